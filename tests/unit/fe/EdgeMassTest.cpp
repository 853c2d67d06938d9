// Boundary-edge mass (fe/ElasticityAssembler.hpp), the M of the traction recovery (53):
// lumped weights sum to edge lengths; Simpson weights integrate quadratics exactly along an
// edge; the consistent mass has the lumped weights as row sums and integrates products of
// discrete functions exactly.
#include <catch2/catch.hpp>
#include <cmath>

#include "FeTestMeshes.hpp"
#include "friction/fe/ElasticityAssembler.hpp"

using namespace friction;

namespace {

double edgeLength(const LagrangeSpace& V, const std::array<Index, 2>& e) {
  return (V.coordinate(e[1]) - V.coordinate(e[0])).norm();
}

}  // namespace

TEST_CASE("fe lumped edge mass sums to the edge lengths", "[fe][edgeMass]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  // Boundary nodes are moved along their sides, so the edges have different lengths.
  const Mesh mesh = test::unitSquareMesh(5, 0.6);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromLame(1.0, 1.0);
  const ElasticityAssembler assembler(V, material);
  // Sums of a few lengths of order 0.2: round-off ~1e-16; 1e-14 is a margin of ~100.
  for (int label = 1; label <= 4; ++label) {
    const auto edges = V.labelledEdges(label);
    const Eigen::VectorXd m = assembler.lumpedEdgeMass(edges);
    REQUIRE(m.size() == V.numNodes());
    REQUIRE(m.sum() == Approx(1.0).margin(1e-14));  // each side of the unit square
    // Per edge: the weights of its own nodes, taken alone, sum to its length.
    for (const auto& e : edges) {
      const Eigen::VectorXd me = assembler.lumpedEdgeMass({e});
      double s = 0.0;
      for (Index n : V.edgeNodes(e[0], e[1])) s += me[n];
      REQUIRE(s == Approx(edgeLength(V, e)).margin(1e-15));
      REQUIRE(me.sum() == Approx(edgeLength(V, e)).margin(1e-15));
    }
    // Off the patch every weight is zero; on it every weight is positive.
    const auto nodes = V.patchNodes(label);
    REQUIRE((m.array() > 0.0).count() == static_cast<Eigen::Index>(nodes.size()));
    for (Index n : nodes) REQUIRE(m[n] > 0.0);
  }
  // An interior set of edges (the cell diagonals of the first row) works the same way.
  std::vector<std::array<Index, 2>> diagonals;
  for (int i = 0; i < 5; ++i) diagonals.push_back({mesh.cell(2 * i)[0], mesh.cell(2 * i)[2]});
  double total = 0.0;
  for (const auto& e : diagonals) total += edgeLength(V, e);
  REQUIRE(assembler.lumpedEdgeMass(diagonals).sum() == Approx(total).margin(1e-14));
  // Consistent mass: its row sums are the lumped weights (∫ φ_i = Σ_j ∫ φ_i φ_j since
  // Σ_j φ_j = 1), and it is symmetric.
  const auto bottom = V.labelledEdges(1);
  const Eigen::SparseMatrix<double> M = assembler.consistentEdgeMass(bottom);
  const Eigen::VectorXd rowSums = M * Eigen::VectorXd::Ones(V.numNodes());
  REQUIRE((rowSums - assembler.lumpedEdgeMass(bottom)).cwiseAbs().maxCoeff() <= 1e-15);
  REQUIRE((Eigen::MatrixXd(M) - Eigen::MatrixXd(M).transpose()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("fe Simpson edge weights integrate quadratics exactly", "[fe][edgeMass]") {
  const Mesh mesh = test::unitSquareMesh(5, 0.6);
  const Material material = Material::fromLame(1.0, 1.0);
  // f = x² − 3xy + 2 on the bottom (y = 0) has ∫_0^1 f dx = 1/3 + 2; on the left (x = 0)
  // f = 2 gives 2. On any straight edge f is a quadratic in the arclength.
  auto f = [](const Vector2& x) { return x.x() * x.x() - 3.0 * x.x() * x.y() + 2.0; };
  auto integrate = [&](const LagrangeSpace& V, const std::vector<std::array<Index, 2>>& edges) {
    const Eigen::VectorXd w = ElasticityAssembler(V, material).lumpedEdgeMass(edges);
    double s = 0.0;
    for (Index n = 0; n < V.numNodes(); ++n) s += w[n] * f(V.coordinate(n));
    return s;
  };
  const LagrangeSpace p2(mesh, 2), p1(mesh, 1);
  // Round-off on a sum of ~10 terms of order 1: 1e-14 is a margin of ~50.
  REQUIRE(integrate(p2, p2.labelledEdges(1)) == Approx(1.0 / 3 + 2.0).margin(1e-14));
  REQUIRE(integrate(p2, p2.labelledEdges(4)) == Approx(2.0).margin(1e-14));
  // A slanted edge: from a = (0, 0) to b, f(a + s(b − a)) integrated exactly by Simpson.
  const std::array<Index, 2> diag{mesh.cell(0)[0], mesh.cell(0)[2]};
  const Vector2 a = mesh.points[diag[0]].head<2>(), b = mesh.points[diag[1]].head<2>();
  const Vector2 d = b - a;
  // ∫_0^1 f(a + s d) |d| ds for f = x² − 3xy + 2, a = 0: (d_x² − 3 d_x d_y)/3 + 2.
  REQUIRE(a.norm() == 0.0);
  const double exactDiag = d.norm() * ((d.x() * d.x() - 3.0 * d.x() * d.y()) / 3.0 + 2.0);
  REQUIRE(integrate(p2, {diag}) == Approx(exactDiag).margin(1e-15));
  // Trapezoid weights (P1) do not integrate x² exactly on the perturbed bottom side: the
  // Simpson check above is therefore not trivially satisfied by any weights.
  REQUIRE(std::abs(integrate(p1, p1.labelledEdges(1)) - (1.0 / 3 + 2.0)) > 1e-3);

  // Consistent P2 mass: vᵀ M v = ∫ v² exactly for v = x² interpolated (x² is in P2):
  // ∫_0^1 x⁴ dx = 1/5 on the bottom.
  const Eigen::SparseMatrix<double> M =
      ElasticityAssembler(p2, material).consistentEdgeMass(p2.labelledEdges(1));
  Eigen::VectorXd v(p2.numNodes());
  for (Index n = 0; n < p2.numNodes(); ++n) v[n] = std::pow(p2.coordinate(n).x(), 2);
  REQUIRE(v.dot(M * v) == Approx(0.2).margin(1e-14));
}

TEST_CASE("fe edge mass on the two sides of a split fracture", "[fe][edgeMass]") {
  // The + and − copies of the fracture each get their own weights, at their own nodes.
  const Mesh mesh = test::splitFourTriangleMesh();
  const LagrangeSpace V(mesh, 2);
  const ElasticityAssembler assembler(V, Material::fromLame(1.0, 1.0));
  const Eigen::VectorXd plus = assembler.lumpedEdgeMass({{2, 3}});
  const Eigen::VectorXd minus = assembler.lumpedEdgeMass({{7, 6}});
  // Exact: 1/6, 4/6, 1/6 times length 1, one rounding each.
  REQUIRE(plus[2] == Approx(1.0 / 6).margin(1e-16));
  REQUIRE(plus[V.midpointNode(2, 3)] == Approx(4.0 / 6).margin(1e-16));
  REQUIRE(plus[6] == 0.0);
  REQUIRE(plus[V.midpointNode(6, 7)] == 0.0);
  REQUIRE(minus[V.midpointNode(6, 7)] == Approx(4.0 / 6).margin(1e-16));
  REQUIRE(minus[7] == Approx(1.0 / 6).margin(1e-16));
  REQUIRE(minus[3] == 0.0);
}
