// 3D linear elasticity on tetrahedra, end to end in the FE layer (docs/method.md §6, §7): the
// space's numbering on tetrahedra, the rigid modes in K's null space, patch tests, a
// manufactured solution's convergence rates for P1 and P2, the P2 triangle's lumped mass, and
// a cube under uniaxial stress. Meshes: the unit cube's Kuhn triangulation (FeTestMeshes.hpp).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/Simplex.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

const double kPi = std::acos(-1.0);

double maxAbs(const Eigen::SparseMatrix<double>& K) {
  double m = 0.0;
  for (int k = 0; k < K.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it)
      m = std::max(m, std::abs(it.value()));
  return m;
}

/// Nodal vector of a displacement field u(x).
Eigen::VectorXd interpolate(const LagrangeSpace& V, const VectorField& u) {
  Eigen::VectorXd v(V.numDofs());
  for (Index n = 0; n < V.numNodes(); ++n) {
    const Point value = u(V.point(n));
    for (int c = 0; c < 3; ++c) v[V.dof(n, c)] = value[c];
  }
  return v;
}

/// Solve K u = F with every component fixed on `dirichletLabels`, prescribed by `exact`.
Eigen::VectorXd solveWith(const ElasticityAssembler& assembler, const Eigen::VectorXd& F,
                          const std::vector<int>& dirichletLabels, const VectorField& exact) {
  DirichletConditions bc(assembler.space());
  for (int label : dirichletLabels) {
    REQUIRE(bc.fixPatch(label, FixedComponents::all) > 0);
    bc.setPatchValue(label, exact);
  }
  const ReducedSystem reduced(assembler.stiffness(), bc);
  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  return reduced.expand(factor.solve(reduced.rhs(F, bc)), bc);
}

double maxNodalError(const LagrangeSpace& V, const Eigen::VectorXd& u, const VectorField& exact) {
  return (u - interpolate(V, exact)).cwiseAbs().maxCoeff();
}

// A linear field u = u0 + G x with a non-symmetric G (strain and rotation), |u| ~ 5e-3 m.
const Point kU0(1.0e-3, -2.0e-3, 0.5e-3);
Eigen::Matrix3d linearGradient() {
  Eigen::Matrix3d G;
  G << 1.0e-3, 2.5e-3, -0.7e-3, -1.5e-3, 0.5e-3, 1.2e-3, 0.3e-3, -0.9e-3, 2.0e-3;
  return G;
}
Point linearField(const Point& x) { return kU0 + linearGradient() * x; }

// Patch-test tolerance: |u| ≲ 5e-3 m; a direct solve's error is about eps · cond(K_ff) · |u|
// with cond(K_ff) ≲ 1e3 on these meshes (≲ 1e-15 m). 1e-14 m leaves a margin of 10, while a
// wrong element (a sign, a missing μ term, a misplaced mid-edge node) is off by ~1e-4 m.
constexpr double kTol = 1e-14;

}  // namespace

TEST_CASE("fe 3D space numbers P1 and P2 nodes on tetrahedra", "[fe][3d]") {
  const int n = 2;
  const Mesh mesh = test::unitCubeMesh(n, 0.3);
  const LagrangeSpace V1(mesh, 1), V2(mesh, 2);
  REQUIRE(V1.dim() == 3);
  REQUIRE(V1.numNodes() == mesh.numPoints());
  REQUIRE(V1.nodesPerCell() == 4);
  REQUIRE(V2.nodesPerCell() == 10);
  // Euler's relation for a triangulated ball: V − E + F − T = 1 with T = 6n³, boundary
  // triangles 12n², F = (4T + 12n²)/2, so E = (n + 1)³ + 6n³ + 6n² − 1.
  const Index edges = (n + 1) * (n + 1) * (n + 1) + 6 * n * n * n + 6 * n * n - 1;
  REQUIRE(V2.numEdges() == edges);
  REQUIRE(V2.numNodes() == mesh.numPoints() + edges);
  REQUIRE(V2.numDofs() == 3 * V2.numNodes());
  REQUIRE(V2.dof(7, 2) == 23);
  // Every P2 node of every cell sits where Simplex.hpp's local order puts it, and an edge's
  // midpoint node is the same seen from either end and from every cell.
  std::vector<int> seen(static_cast<std::size_t>(V2.numNodes()), 0);
  for (Index c = 0; c < V2.numCells(); ++c) {
    const NodeList nodes = V2.cellNodes(c);
    REQUIRE(nodes.size == 10);
    for (int i = 0; i < 4; ++i) REQUIRE(nodes[i] == mesh.cellVertex(c, i));
    for (int e = 0; e < 6; ++e) {
      const Index a = nodes[SimplexNodes<3>::edges[e][0]], b = nodes[SimplexNodes<3>::edges[e][1]];
      const Index mid = nodes[4 + e];
      REQUIRE(mid >= mesh.numPoints());
      REQUIRE(V2.midpointNode(a, b) == mid);
      REQUIRE(V2.midpointNode(b, a) == mid);
      REQUIRE((V2.point(mid) - 0.5 * (mesh.points[a] + mesh.points[b])).norm() == 0.0);
    }
    for (Index node : nodes) seen[node] = 1;
  }
  // No node without a cell, no P1 midpoints, no edge between far corners.
  REQUIRE(std::count(seen.begin(), seen.end(), 1) == V2.numNodes());
  REQUIRE(V1.midpointNode(mesh.cellVertex(0, 0), mesh.cellVertex(0, 1)) == -1);
  // Kuhn cubes: the cube's diagonal and the face diagonals through (0,0,0) of the first
  // cube are edges, the other face diagonal is not (node (i, j, k) = 9k + 3j + i for n = 2).
  REQUIRE(V2.isEdge(0, 13));
  REQUIRE(V2.isEdge(4, 0));
  REQUIRE(V2.midpointNode(0, 13) >= mesh.numPoints());
  REQUIRE_FALSE(V2.isEdge(1, 3));
  REQUIRE(V2.midpointNode(1, 3) == -1);
  // Facet nodes in Simplex's facet order; patch nodes of the face x = 0.
  const std::vector<Index> x0 = V2.labelledFacets(1);
  REQUIRE(x0.size() == static_cast<std::size_t>(2 * n * n));
  for (Index f : x0) {
    const NodeList nodes = V2.labelledFacetNodes(f);
    REQUIRE(nodes.size == 6);
    for (int e = 0; e < 3; ++e)
      REQUIRE((V2.point(nodes[3 + e]) - 0.5 * (V2.point(nodes[e]) + V2.point(nodes[(e + 1) % 3])))
                  .norm() == 0.0);
  }
  for (const LagrangeSpace* V : {&V1, &V2}) {
    const std::vector<Index> patch = V->patchNodes(1);
    const int perSide = V->degree() * n + 1;
    REQUIRE(patch.size() == static_cast<std::size_t>(perSide * perSide));
    for (Index node : patch) REQUIRE(V->point(node).x() == 0.0);
  }
}

TEST_CASE("fe 3D space refuses a labelled triangle that is no tetrahedron's face", "[fe][3d]") {
  Mesh mesh = test::unitCubeMesh(1);
  mesh.addFacet({1, 2, 4}, 9);  // (1,0,0), (0,1,0), (0,0,1): cuts through the cube
  try {
    const LagrangeSpace V(mesh, 1);
    FAIL("no error for a triangle that is not a face");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("unitCube1") &&
                             Catch::Contains("labelled triangle 12 (nodes 1, 2, 4, label 9) "
                                             "is not a face of any tetrahedron"));
  }
}

TEST_CASE("fe 3D Dirichlet conditions fix the named components", "[fe][3d]") {
  const Mesh mesh = test::unitCubeMesh(1);
  const LagrangeSpace V(mesh, 2);
  DirichletConditions bc(V);
  REQUIRE(bc.numDofs() == V.numDofs());
  REQUIRE(bc.fixPatch(5, FixedComponents::z) == 9);  // z = 0: 4 vertices, 5 midpoints
  REQUIRE(bc.numFixed() == 9);
  bc.fixPatch(1, FixedComponents::x | FixedComponents::y);
  bc.setPatchValue(5, Point(1.0, 2.0, 3.0));
  bc.setPatchValue(1, Point(4.0, 5.0, 6.0));
  const Index corner = 0;  // (0, 0, 0): on both patches
  REQUIRE(bc.isFixed(V.dof(corner, 0)));
  REQUIRE(bc.isFixed(V.dof(corner, 1)));
  REQUIRE(bc.isFixed(V.dof(corner, 2)));
  REQUIRE(bc.values()[V.dof(corner, 0)] == 4.0);
  REQUIRE(bc.values()[V.dof(corner, 2)] == 3.0);
  const Index farCorner = mesh.numPoints() - 1;  // (1, 1, 1): on neither
  for (int c = 0; c < 3; ++c) REQUIRE_FALSE(bc.isFixed(V.dof(farCorner, c)));
  const Index onX0Only = 6;  // (0, 1, 1)
  REQUIRE(bc.isFixed(V.dof(onX0Only, 1)));
  REQUIRE_FALSE(bc.isFixed(V.dof(onX0Only, 2)));
  REQUIRE(bc.values()[V.dof(onX0Only, 1)] == 5.0);
  REQUIRE(bc.values()[V.dof(onX0Only, 2)] == 0.0);
}

TEST_CASE("fe 3D stiffness is symmetric and annihilates exactly the rigid modes", "[fe][3d]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::unitCubeMesh(2, 0.4);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromYoungPoisson(2.0, 0.3);
  const ElasticityAssembler assembler(V, material);
  const Eigen::SparseMatrix<double> K = assembler.stiffness();
  REQUIRE(K.rows() == V.numDofs());
  const double scale = maxAbs(K);
  REQUIRE(scale > 0.0);
  // Symmetric to round-off: ke(i r, j s) and ke(j s, i r) are the same products in another
  // order, so they may differ in the last bit only.
  const Eigen::SparseMatrix<double> Kt = K.transpose();
  REQUIRE(maxAbs(K - Kt) <= 1e-15 * scale);
  // Rigid modes (|r| ≤ ~1 on the unit cube): K r sums ~30 entries of size ≤ |K| per row, so
  // round-off is ~30 eps |K|; 1e-13 |K| allows that with margin, while any missing or wrong
  // term of the element law leaves O(|K|).
  std::vector<VectorField> modes;
  for (int c = 0; c < 3; ++c) modes.push_back([c](const Point&) { return Point(Point::Unit(c)); });
  for (int c = 0; c < 3; ++c)
    modes.push_back([c](const Point& x) { return Point(Point::Unit(c).cross(x)); });
  for (const auto& r : modes)
    REQUIRE((K * interpolate(V, r)).cwiseAbs().maxCoeff() <= 1e-13 * scale);
  // A pure strain is not in the null space (the check above can fail).
  const Eigen::VectorXd strain = interpolate(V, [](const Point& x) { return Point(x.x(), 0, 0); });
  REQUIRE((K * strain).cwiseAbs().maxCoeff() > 1e-3 * scale);
}

TEST_CASE("fe 3D patch test: a linear field with Dirichlet data on the whole boundary",
          "[fe][3d][patch]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::unitCubeMesh(3, 0.4);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromYoungPoisson(1.0, 0.3);
  const ElasticityAssembler assembler(V, material);
  const Eigen::VectorXd u =
      solveWith(assembler, Eigen::VectorXd::Zero(V.numDofs()), {1, 2, 3, 4, 5, 6}, linearField);
  REQUIRE(maxNodalError(V, u, linearField) <= kTol);
  // The interior has free nodes (else the check proves nothing).
  REQUIRE(V.numNodes() > static_cast<Index>(V.patchNodes(1).size()) * 3);
  // Constant stress at every cell, from Hooke's law of the exact gradient.
  const Eigen::Matrix3d G = linearGradient();
  const Eigen::Matrix3d sigma = material.stress3d(0.5 * (G + G.transpose()));
  for (Index c = 0; c < V.numCells(); ++c) {
    Point centroid = Point::Zero();
    for (Index v : mesh.cell(c)) centroid += 0.25 * mesh.points[v];
    REQUIRE((assembler.stress(u, c, centroid) - sigma).cwiseAbs().maxCoeff() <= 1e-12);
    REQUIRE((assembler.displacement(u, c, centroid) - linearField(centroid)).norm() <= kTol);
  }
}

TEST_CASE("fe 3D patch test: constant stress from tractions on three faces", "[fe][3d][patch]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::unitCubeMesh(3, 0.4);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromLame(0.7, 1.3);
  const ElasticityAssembler assembler(V, material);
  const Eigen::Matrix3d G = linearGradient();
  const Eigen::Matrix3d sigma = material.stress3d(0.5 * (G + G.transpose()));
  // Traction σ n on x = 1, y = 1 (constant) and z = 1 (as a field), Dirichlet on the others.
  Eigen::VectorXd F = assembler.traction(2, Point(sigma * Point::UnitX()));
  F += assembler.traction(4, Point(sigma * Point::UnitY()));
  F += assembler.traction(6,
                          VectorField([&](const Point&) { return Point(sigma * Point::UnitZ()); }));
  const Eigen::VectorXd u = solveWith(assembler, F, {1, 3, 5}, linearField);
  REQUIRE(maxNodalError(V, u, linearField) <= kTol);
  // The tractions matter: without them the answer is far off.
  const Eigen::VectorXd u0 =
      solveWith(assembler, Eigen::VectorXd::Zero(V.numDofs()), {1, 3, 5}, linearField);
  REQUIRE(maxNodalError(V, u0, linearField) > 1e-4);
}

TEST_CASE("fe 3D cube under uniaxial stress gives Hooke's strains", "[fe][3d]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::unitCubeMesh(2, 0.4);
  const LagrangeSpace V(mesh, degree);
  const double E = 3.0e9, nu = 0.25, s = 1.0e6;
  const Material material = Material::fromYoungPoisson(E, nu);
  const ElasticityAssembler assembler(V, material);
  // Rollers on x = 0, y = 0, z = 0 (normal component only), σ_xx = s pulling on x = 1.
  DirichletConditions bc(V);
  REQUIRE(bc.fixPatch(1, FixedComponents::x) > 0);
  REQUIRE(bc.fixPatch(3, FixedComponents::y) > 0);
  REQUIRE(bc.fixPatch(5, FixedComponents::z) > 0);
  const ReducedSystem reduced(assembler.stiffness(), bc);
  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  const Eigen::VectorXd F = assembler.traction(2, Point(s, 0.0, 0.0));
  const Eigen::VectorXd u = reduced.expand(factor.solve(reduced.rhs(F, bc)), bc);
  // ε_xx = s/E ~ 3e-4 and ε_yy = ε_zz = −ν s/E; a direct solve leaves ~1e-16 relative.
  const double exx = s / E, eyy = -nu * s / E;
  for (Index c = 0; c < V.numCells(); ++c) {
    Point centroid = Point::Zero();
    for (Index v : mesh.cell(c)) centroid += 0.25 * mesh.points[v];
    const Eigen::Matrix3d eps = assembler.strain(u, c, centroid);
    REQUIRE(std::abs(eps(0, 0) - exx) <= 1e-12 * exx);
    REQUIRE(std::abs(eps(1, 1) - eyy) <= 1e-12 * exx);
    REQUIRE(std::abs(eps(2, 2) - eyy) <= 1e-12 * exx);
    REQUIRE(std::abs(eps(0, 1)) + std::abs(eps(0, 2)) + std::abs(eps(1, 2)) <= 1e-12 * exx);
    const Eigen::Matrix3d sigma = assembler.stress(u, c, centroid);
    REQUIRE(std::abs(sigma(0, 0) - s) <= 1e-9 * s);
    REQUIRE(std::abs(sigma(1, 1)) + std::abs(sigma(2, 2)) <= 1e-9 * s);
  }
}

TEST_CASE("fe 3D lumped P2 triangle mass is positive, A/12 and A/4, and sums to the area",
          "[fe][3d]") {
  const Mesh mesh = test::unitCubeMesh(2, 0.4);
  const LagrangeSpace V(mesh, 2);
  const ElasticityAssembler assembler(V, Material::fromYoungPoisson(1.0, 0.3));
  // One slanted interior face (the jitter moves interior nodes off the grid planes).
  const std::vector<Index> face = {mesh.cellVertex(20, 1), mesh.cellVertex(20, 2),
                                   mesh.cellVertex(20, 3)};
  const Point& a = mesh.points[face[0]];
  const double area = 0.5 * (mesh.points[face[1]] - a).cross(mesh.points[face[2]] - a).norm();
  const Eigen::VectorXd m = assembler.lumpedFacetMass(face);
  const NodeList nodes = V.facetNodes(face.data());
  REQUIRE(nodes.size == 6);
  for (int i = 0; i < 6; ++i)
    REQUIRE(std::abs(m[nodes[i]] - (i < 3 ? area / 12 : area / 4)) <= 1e-15 * area);
  REQUIRE(std::abs(m.sum() - area) <= 1e-15 * area);
  // The whole face x = 1 (area 1): positive at every node of the patch, zero elsewhere.
  std::vector<Index> x1;
  for (Index f : V.labelledFacets(2))
    for (int k = 0; k < 3; ++k) x1.push_back(mesh.facetVertex(f, k));
  REQUIRE_FALSE(x1.empty());
  const Eigen::VectorXd mx = assembler.lumpedFacetMass(x1);
  const std::vector<Index> patch = V.patchNodes(2);
  for (Index n : patch) REQUIRE(mx[n] > 0.0);
  REQUIRE((mx.array() > 0.0).count() == static_cast<Eigen::Index>(patch.size()));
  REQUIRE(std::abs(mx.sum() - 1.0) <= 1e-14);
  // The consistent mass integrates products of quadratics exactly: xᵀ M y = ∫ y z dA = 1/4
  // on x = 1, and its entries sum to the area.
  const Eigen::SparseMatrix<double> M = assembler.consistentFacetMass(x1);
  Eigen::VectorXd y(V.numNodes()), z(V.numNodes());
  for (Index n = 0; n < V.numNodes(); ++n) {
    y[n] = V.point(n).y();
    z[n] = V.point(n).z();
  }
  REQUIRE(std::abs(y.dot(M * z) - 0.25) <= 1e-14);
  REQUIRE(
      std::abs(Eigen::VectorXd::Ones(V.numNodes()).dot(M * Eigen::VectorXd::Ones(V.numNodes())) -
               1.0) <= 1e-14);
}

namespace {

// Manufactured solution u = (sin πx sin πy sin πz, x² y³ z, cos πx · y z²), Dirichlet data on
// all six faces, on n = 2 … 16 (P1) and 1 … 8 (P2) cubes per side; the orders print with
//   build/tests/unitTests "fe 3D manufactured*"
Point exactU(const Point& p) {
  const double x = p.x(), y = p.y(), z = p.z();
  return Point(std::sin(kPi * x) * std::sin(kPi * y) * std::sin(kPi * z), x * x * y * y * y * z,
               std::cos(kPi * x) * y * z * z);
}

Eigen::Matrix3d exactGradient(const Point& p) {
  const double x = p.x(), y = p.y(), z = p.z();
  const double sx = std::sin(kPi * x), sy = std::sin(kPi * y), sz = std::sin(kPi * z);
  const double cx = std::cos(kPi * x), cy = std::cos(kPi * y), cz = std::cos(kPi * z);
  Eigen::Matrix3d G;
  G << kPi * cx * sy * sz, kPi * sx * cy * sz, kPi * sx * sy * cz,      //
      2 * x * y * y * y * z, 3 * x * x * y * y * z, x * x * y * y * y,  //
      -kPi * sx * y * z * z, cx * z * z, 2 * cx * y * z;
  return G;
}

/// f = −div σ = −(λ + μ) ∇(div u) − μ Δu.
Point bodyForce(const Material& m, const Point& p) {
  const double x = p.x(), y = p.y(), z = p.z(), lam = m.lambda(), mu = m.mu(), pi2 = kPi * kPi;
  const double sx = std::sin(kPi * x), sy = std::sin(kPi * y), sz = std::sin(kPi * z);
  const double cx = std::cos(kPi * x), cy = std::cos(kPi * y), cz = std::cos(kPi * z);
  // div u = π cx sy sz + 3 x² y² z + 2 cx y z
  const Point gradDiv(-pi2 * sx * sy * sz + 6 * x * y * y * z - 2 * kPi * sx * y * z,
                      pi2 * cx * cy * sz + 6 * x * x * y * z + 2 * cx * z,
                      pi2 * cx * sy * cz + 3 * x * x * y * y + 2 * cx * y);
  const Point laplace(-3 * pi2 * sx * sy * sz, 2 * y * y * y * z + 6 * x * x * y * z,
                      -pi2 * cx * y * z * z + 2 * cx * y);
  return -(lam + mu) * gradDiv - mu * laplace;
}

ErrorNorms solveManufactured(int n, int degree, const Material& material) {
  const Mesh mesh = test::unitCubeMesh(n);
  const LagrangeSpace V(mesh, degree);
  const ElasticityAssembler assembler(V, material);
  const Eigen::VectorXd F =
      assembler.bodyForce([&](const Point& x) { return bodyForce(material, x); });
  const Eigen::VectorXd u = solveWith(assembler, F, {1, 2, 3, 4, 5, 6}, exactU);
  return assembler.errorNorms(u, exactU, exactGradient);
}

}  // namespace

TEST_CASE("fe 3D manufactured solution converges at the optimal rates", "[fe][3d][convergence]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Material material = Material::fromYoungPoisson(1.0, 0.3);
  const std::vector<int> sizes =
      degree == 1 ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{1, 2, 4, 8};
  std::vector<ErrorNorms> errors;
  for (int n : sizes) errors.push_back(solveManufactured(n, degree, material));
  for (std::size_t k = 1; k < sizes.size(); ++k) {
    const double l2 = std::log2(errors[k - 1].l2 / errors[k].l2);
    const double h1 = std::log2(errors[k - 1].h1Seminorm / errors[k].h1Seminorm);
    std::printf("3D P%d n = %d -> %d: L2 %.3e order %.2f, H1 %.3e order %.2f\n", degree,
                sizes[k - 1], sizes[k], errors[k].l2, l2, errors[k].h1Seminorm, h1);
    CAPTURE(sizes[k], l2, h1);
    // The orders approach the asymptotic ones from below (measured on the last pair: P1 1.92
    // and 0.99, P2 3.03 and 1.93); the meshes stay coarse to keep the test at ~2 s, so the
    // last pair is allowed 0.2 below the optimal order (a lost order is 1 below) and 0.3
    // above (more would mean the error norm, not the solution, is wrong).
    if (k + 1 == sizes.size()) {
      CHECK(l2 >= degree + 1 - 0.2);
      CHECK(l2 <= degree + 1 + 0.3);
      CHECK(h1 >= degree - 0.2);
      CHECK(h1 <= degree + 0.3);
    }
  }
}
