// The fault's P1 flow mesh (flow/FaultFlowMesh.hpp): masses integrate what they must, the
// stiffness is symmetric with zero row sums and vanishes on linear functions at interior nodes
// (the patch test, on an uneven curve and an inclined triangulated plane), points are located
// with weights that reproduce them, junctions of curves share one node, bad input is refused.
#include <catch2/catch.hpp>
#include <cmath>

#include "FlowTestMeshes.hpp"

using namespace friction;

namespace {

// A rotation taking the plane z = 0 to an inclined one (axis (1, 2, 3), 0.7 rad) and a shift.
Point moved(const Point& x) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  return R * x + Point(10.0, -3.0, 2.0);
}

FaultFlowMesh movedSquare(double L, int n) {
  const FaultFlowMesh flat = test::squareMesh(L, n);
  std::vector<Point> points;
  for (const Point& p : flat.points()) points.push_back(moved(p));
  std::vector<FaultFlowMesh::Triangle> triangles;
  for (Index e = 0; e < flat.numElements(); ++e)
    triangles.push_back({flat.element(e)[0], flat.element(e)[1], flat.element(e)[2]});
  return FaultFlowMesh(points, triangles);
}

bool isInterior(const FaultFlowMesh& mesh, Index i) {
  const auto edge = mesh.edgeNodes();
  return !std::binary_search(edge.begin(), edge.end(), i);
}

}  // namespace

TEST_CASE("flow mesh on a curve: masses, stiffness and the patch test", "[flow][flowMesh]") {
  // An uneven polyline in the plane (a bent fault), nodes at uneven spacing.
  std::vector<Point> points;
  std::vector<FaultFlowMesh::Segment> segments;
  double s = 0.0;
  std::vector<double> arclength;
  for (int i = 0; i < 12; ++i) {
    const double angle = 0.3 * (i >= 6);
    const double h = 0.1 + 0.05 * (i % 3);
    if (i > 0) {
      points.push_back(points.back() + h * Point(std::cos(angle), std::sin(angle), 0.0));
      s += h;
    } else {
      points.emplace_back(1.0, 2.0, 0.0);
    }
    arclength.push_back(s);
    if (i > 0) segments.push_back({i - 1, i});
  }
  const FaultFlowMesh mesh(points, segments);
  REQUIRE(mesh.elementDimension() == 1);
  // Sums of ~12 lengths of 0.1: round-off ~1e-16; bound 1e-14.
  REQUIRE(mesh.lumpedMass().sum() == Approx(s).margin(1e-14));
  REQUIRE(mesh.totalMeasure() == Approx(s).margin(1e-14));
  const Eigen::SparseMatrix<double> M = mesh.consistentMass(2.0);
  REQUIRE((M * Eigen::VectorXd::Ones(12) - mesh.lumpedMass(2.0)).cwiseAbs().maxCoeff() <= 1e-15);
  // ∫ s ds = s²/2 from the consistent mass (exact for P1 functions).
  Eigen::VectorXd sv = Eigen::Map<Eigen::VectorXd>(arclength.data(), 12);
  REQUIRE((mesh.consistentMass() * sv).sum() == Approx(s * s / 2).margin(1e-14));
  // Stiffness: symmetric, rows sum to 0, and A·(linear in arclength) vanishes inside.
  const Eigen::SparseMatrix<double> A = mesh.stiffness(FlowCoefficient::perNode(sv.array() + 1.0));
  const Eigen::MatrixXd Ad(A);
  REQUIRE((Ad - Ad.transpose()).cwiseAbs().maxCoeff() == 0.0);
  REQUIRE((Ad * Eigen::VectorXd::Ones(12)).cwiseAbs().maxCoeff() <= 1e-13);
  // Constant κ: A·(linear in arclength) vanishes inside (a varying κ adds ∂κ/∂s there).
  const Eigen::VectorXd As = mesh.stiffness(2.0) * sv;
  for (int i = 1; i < 11; ++i) REQUIRE(std::abs(As[i]) <= 1e-12);  // entries ~κ/h ~ 20
  // At the ends the flux κ ∂s/∂s = κ leaves (−) and enters (+).
  REQUIRE(As[0] == Approx(-2.0).epsilon(1e-12));
  REQUIRE(As[11] == Approx(2.0).epsilon(1e-12));
  REQUIRE(mesh.edgeNodes() == std::vector<Index>{0, 11});
}

TEST_CASE("flow mesh on an inclined plane: masses, stiffness and the patch test",
          "[flow][flowMesh]") {
  const int n = 4;
  const FaultFlowMesh mesh = movedSquare(1.5, n);
  REQUIRE(mesh.elementDimension() == 2);
  const double area = 9.0;
  REQUIRE(mesh.lumpedMass().sum() == Approx(area).epsilon(1e-14));
  REQUIRE(mesh.edgeNodes().size() == static_cast<std::size_t>(8 * n));
  // Per-element coefficient: the mass is Σ c_e |T_e|.
  Eigen::VectorXd c(mesh.numElements());
  for (Index e = 0; e < mesh.numElements(); ++e) c[e] = 1.0 + e % 5;
  double expected = 0.0;
  for (Index e = 0; e < mesh.numElements(); ++e) expected += c[e] * mesh.measure(e);
  const Eigen::SparseMatrix<double> M = mesh.consistentMass(FlowCoefficient::perElement(c));
  REQUIRE(Eigen::VectorXd(M * Eigen::VectorXd::Ones(mesh.numNodes())).sum() ==
          Approx(expected).epsilon(1e-14));
  const Eigen::MatrixXd A(mesh.stiffness(FlowCoefficient::perElement(c)));
  REQUIRE((A - A.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * A.cwiseAbs().maxCoeff());
  REQUIRE((A * Eigen::VectorXd::Ones(mesh.numNodes())).cwiseAbs().maxCoeff() <= 1e-13);
  // A linear function of x, y, z (its gradient along the plane is what acts): with κ
  // constant, A·f vanishes at interior nodes (the P1 patch test).
  Eigen::VectorXd f(mesh.numNodes());
  for (Index i = 0; i < mesh.numNodes(); ++i) f[i] = Point(0.3, -1.2, 2.0).dot(mesh.point(i)) + 4.0;
  const double kappa = 2.5;
  const Eigen::VectorXd Af = mesh.stiffness(kappa) * f;
  int interior = 0;
  for (Index i = 0; i < mesh.numNodes(); ++i)
    if (isInterior(mesh, i)) {
      REQUIRE(std::abs(Af[i]) <= 1e-12);
      ++interior;
    }
  REQUIRE(interior == (2 * n - 1) * (2 * n - 1));
  // The P1 Dirichlet energy of a linear function: fᵀAf = κ |∇_Γ f|² |Γ|; ∇_Γ f is the
  // in-plane part of (0.3, −1.2, 2), whose squared norm is the full one minus the normal's.
  const Point g(0.3, -1.2, 2.0);
  const Point normal =
      (mesh.point(1) - mesh.point(0)).cross(mesh.point(2 * n + 1) - mesh.point(0)).normalized();
  const double g2 = g.squaredNorm() - std::pow(g.dot(normal), 2);
  REQUIRE(f.dot(Af) == Approx(kappa * g2 * area).epsilon(1e-12));
}

TEST_CASE("flow mesh locates points with weights that reproduce them", "[flow][flowMesh]") {
  const FaultFlowMesh plane = movedSquare(1.0, 2);
  // Above an interior point of a triangle: the closest point is the foot, at the height.
  const Point normal =
      (plane.point(1) - plane.point(0)).cross(plane.point(5) - plane.point(0)).normalized();
  const Point foot = moved(Point(0.3, -0.2, 0.0));
  const auto at = plane.locate(foot + 0.25 * normal);
  REQUIRE(at.distance == Approx(0.25).epsilon(1e-12));
  REQUIRE((at.closest - foot).norm() <= 1e-12);
  Point rebuilt = Point::Zero();
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    REQUIRE(at.weight[k] >= 0.0);
    rebuilt += at.weight[k] * plane.point(plane.element(at.element)[k]);
    sum += at.weight[k];
  }
  REQUIRE(sum == Approx(1.0).epsilon(1e-15));
  REQUIRE((rebuilt - foot).norm() <= 1e-12);
  // Beyond a corner of the square: the corner itself.
  const auto corner = plane.locate(moved(Point(1.5, 1.5, 0.0)));
  REQUIRE((corner.closest - moved(Point(1.0, 1.0, 0.0))).norm() <= 1e-12);
  REQUIRE(corner.distance == Approx(std::sqrt(0.5)).epsilon(1e-12));
  double d = 0.0;
  REQUIRE(plane.nearestNode(moved(Point(0.45, 0.05, 0.1)), &d) == 2 * 5 + 3);  // node (0.5, 0)
  REQUIRE(d == Approx(std::sqrt(0.05 * 0.05 + 0.05 * 0.05 + 0.01)).epsilon(1e-12));
  // On a curve: a point off a segment.
  const FaultFlowMesh line = test::lineMesh(1.0, 2);
  const auto s = line.locate(Point(0.2, 0.3, 0.0));
  REQUIRE(s.distance == Approx(0.3).epsilon(1e-15));
  REQUIRE(s.weight[0] + s.weight[1] == Approx(1.0).epsilon(1e-15));
  REQUIRE((s.closest - Point(0.2, 0.0, 0.0)).norm() <= 1e-15);
}

TEST_CASE("flow mesh of curves that meet: one node per junction", "[flow][flowMesh]") {
  // Three arms from the origin (id 0), the third listed towards it.
  std::vector<FaultFlowMesh::Curve> curves(3);
  for (int c = 0; c < 3; ++c) {
    const double angle = 2.0 * 3.14159265358979 * c / 3.0;
    const Point dir(std::cos(angle), std::sin(angle), 0.0);
    for (int i = 0; i <= 4; ++i) {
      curves[c].id.push_back(i == 0 ? 0 : 100 * (c + 1) + i);
      curves[c].points.push_back(0.25 * i * dir);
    }
  }
  std::reverse(curves[2].id.begin(), curves[2].id.end());
  std::reverse(curves[2].points.begin(), curves[2].points.end());
  const FaultFlowMesh mesh = FaultFlowMesh::fromCurves(curves);
  REQUIRE(mesh.numNodes() == 13);
  REQUIRE(mesh.numElements() == 12);
  const Index junction = mesh.curveNodes()[0][0];
  REQUIRE(mesh.curveNodes()[1][0] == junction);
  REQUIRE(mesh.curveNodes()[2][4] == junction);
  // The junction is not an edge of the network; the three far ends are.
  REQUIRE(mesh.edgeNodes().size() == 3);
  REQUIRE(isInterior(mesh, junction));
  // Stiffness row of the junction: the three arms' 1/h each.
  const Eigen::SparseMatrix<double> A = mesh.stiffness(1.0);
  REQUIRE(A.coeff(junction, junction) == Approx(3.0 / 0.25).epsilon(1e-14));
  // A point that disagrees with the one first met under its id is refused.
  curves[1].points[0] = Point(1e-3, 0.0, 0.0);
  REQUIRE_THROWS_WITH(FaultFlowMesh::fromCurves(curves, {"constant/faults", 3}),
                      Catch::Contains("constant/faults:3") && Catch::Contains("curve 1") &&
                          Catch::Contains("node id 0"));
}

TEST_CASE("flow mesh refuses bad input", "[flow][flowMesh]") {
  const std::vector<Point> p = {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0)};
  REQUIRE_THROWS_WITH(FaultFlowMesh(p, std::vector<FaultFlowMesh::Segment>{{0, 1}, {1, 3}}),
                      Catch::Contains("segment 1") && Catch::Contains("out of range"));
  REQUIRE_THROWS_WITH(FaultFlowMesh(p, std::vector<FaultFlowMesh::Segment>{{0, 1}, {1, 1}}),
                      Catch::Contains("segment 1 has length 0"));
  REQUIRE_THROWS_WITH(FaultFlowMesh(p, std::vector<FaultFlowMesh::Segment>{{0, 1}}),
                      Catch::Contains("point 2") && Catch::Contains("belongs to no segment"));
  REQUIRE_THROWS_WITH(FaultFlowMesh(p, std::vector<FaultFlowMesh::Segment>{}),
                      Catch::Contains("at least one segment"));
  REQUIRE_THROWS_WITH(FaultFlowMesh(p, std::vector<FaultFlowMesh::Triangle>{{0, 1, 2}}),
                      Catch::Contains("triangle 0 has area 0"));
  const FaultFlowMesh line = test::lineMesh(1.0, 2);
  REQUIRE_THROWS_WITH(
      FlowCoefficient::perNode(Eigen::VectorXd::Ones(3)).check(line, false, "S", {}),
      Catch::Contains("one value per node (5), got 3"));
  Eigen::VectorXd v = Eigen::VectorXd::Ones(4);
  v[2] = -1.0;
  REQUIRE_THROWS_WITH(FlowCoefficient::perElement(v).check(line, true, "kappa", {"f", 2}),
                      Catch::Contains("f:2") && Catch::Contains("element 2 has -1"));
}
