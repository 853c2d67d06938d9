// Patch tests (docs/method.md §10): a displacement field in the element space, imposed through
// boundary data, is reproduced exactly inside a distorted mesh. Linear fields for P1 and P2
// (Dirichlet on the whole boundary, and Dirichlet + tractions of the constant stress), a
// quadratic field with its constant body force for P2.
#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "FeTestMeshes.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

/// u(x) = u0 + G x with a non-symmetric gradient (strain and rotation) [m].
const Vector2 kU0(1.0e-3, -2.0e-3);
Eigen::Matrix2d linearGradient() {
  Eigen::Matrix2d G;
  G << 2.0e-3, -1.0e-3, 0.5e-3, 3.0e-3;
  return G;
}
Vector2 linearField(const Vector2& x) { return kU0 + linearGradient() * x; }

/// Largest nodal difference between the discrete solution and a field, over all nodes.
double maxNodalError(const LagrangeSpace& V, const Eigen::VectorXd& u,
                     const std::function<Vector2(const Vector2&)>& exact) {
  double err = 0.0;
  for (Index n = 0; n < V.numNodes(); ++n)
    err = std::max(err, (u.segment<2>(2 * n) - exact(V.coordinate(n))).cwiseAbs().maxCoeff());
  return err;
}

/// Solve K u = F with the given fixed patches, all prescribed by `exact`.
Eigen::VectorXd solveWith(const LagrangeSpace& V, const Eigen::SparseMatrix<double>& K,
                          const Eigen::VectorXd& F, const std::vector<int>& dirichletLabels,
                          const std::function<Vector2(const Vector2&)>& exact) {
  DirichletConditions bc(V);
  for (int label : dirichletLabels) {
    REQUIRE(bc.fixPatch(label, FixedComponents::all) > 0);
    bc.setPatchValue(label, test::planar(exact));
  }
  const ReducedSystem reduced(K, bc);
  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  return reduced.expand(factor.solve(reduced.rhs(F, bc)), bc);
}

// Tolerance for all patch tests: |u| ~ 5e-3 m; the error of a direct solve is about
// eps · cond(K_ff) · |u| with cond(K_ff) ≲ 1e3 on these 6 × 6 meshes, i.e. ≲ 1e-15 m.
// 1e-14 m leaves a margin of 10 while a wrong element (e.g. a sign or a missing μ term)
// gives errors of order 1e-4 m.
constexpr double kTol = 1e-14;

}  // namespace

TEST_CASE("fe patch test linear field with Dirichlet on the whole boundary", "[fe][patch]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::unitSquareMesh(6, 0.5);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromYoungPoisson(1.0, 0.3);
  const ElasticityAssembler assembler(V, material);
  const Eigen::SparseMatrix<double> K = assembler.stiffness();
  const Eigen::VectorXd u =
      solveWith(V, K, Eigen::VectorXd::Zero(V.numDofs()), {1, 2, 3, 4}, linearField);
  REQUIRE(maxNodalError(V, u, linearField) <= kTol);
  // The recovered stress is the constant stress of the field, in every cell. Stress
  // tolerance: kTol / h · E · (a few) = 1e-14 · 6 · 3 ≈ 2e-13 Pa.
  const Eigen::Matrix2d G = linearGradient();
  const Eigen::Matrix2d sigma = material.stress(0.5 * (G + G.transpose()));
  for (Index c = 0; c < V.numCells(); ++c) {
    const auto& t = mesh.cell(c);
    const Vector2 centroid =
        (mesh.points[t[0]].head<2>() + mesh.points[t[1]].head<2>() + mesh.points[t[2]].head<2>()) /
        3.0;
    REQUIRE((assembler.stress(u, c, centroid) - sigma).cwiseAbs().maxCoeff() <= 2e-13);
    REQUIRE((assembler.displacementGradient(u, c, Vector2(mesh.points[t[1]].head<2>())) - G)
                .cwiseAbs()
                .maxCoeff() <= 2e-13);
  }
}

TEST_CASE("fe patch test linear field with tractions of the constant stress", "[fe][patch]") {
  const int degree = GENERATE(1, 2);
  const bool planeStress = GENERATE(false, true);
  CAPTURE(degree, planeStress);
  const Mesh mesh = test::unitSquareMesh(6, 0.5);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromYoungPoisson(1.0, 0.25, planeStress);
  const ElasticityAssembler assembler(V, material);
  const Eigen::Matrix2d G = linearGradient();
  const Eigen::Matrix2d sigma = material.stress(0.5 * (G + G.transpose()));
  // Left side prescribed; bottom, right and top loaded by g = σ n (outward normals).
  Eigen::VectorXd F = assembler.traction(1, Vector2(sigma * Vector2(0, -1)));
  F += assembler.traction(2, Vector2(sigma * Vector2(1, 0)));
  F += assembler.traction(
      3, test::planar([&](const Vector2&) { return Vector2(sigma * Vector2(0, 1)); }));
  const Eigen::VectorXd u = solveWith(V, assembler.stiffness(), F, {4}, linearField);
  REQUIRE(maxNodalError(V, u, linearField) <= kTol);
  // And the traction load must matter: without it the answer is far off.
  const Eigen::VectorXd u0 =
      solveWith(V, assembler.stiffness(), Eigen::VectorXd::Zero(V.numDofs()), {4}, linearField);
  REQUIRE(maxNodalError(V, u0, linearField) > 1e-4);
}

TEST_CASE("fe patch test quadratic field with constant body force for P2", "[fe][patch]") {
  // u = (x² + xy, y² − 2xy) · 1e-3: −div σ = −(λ+μ) ∇(div u) − μ Δu is constant.
  const Material material = Material::fromLame(0.7, 1.3);
  const double lam = material.lambda(), mu = material.mu();
  auto exact = [](const Vector2& x) {
    return Vector2(1e-3 * (x.x() * x.x() + x.x() * x.y()),
                   1e-3 * (x.y() * x.y() - 2.0 * x.x() * x.y()));
  };
  // div u = 1e-3 (2x + y + 2y − 2x) = 3e-3 y → ∇div = (0, 3e-3); Δu = 1e-3 (2, 2).
  const Vector2 f = -(lam + mu) * Vector2(0.0, 3e-3) - mu * Vector2(2e-3, 2e-3);
  const Mesh mesh = test::unitSquareMesh(6, 0.5);
  const LagrangeSpace V(mesh, 2);
  const ElasticityAssembler assembler(V, material);
  const Eigen::VectorXd u =
      solveWith(V, assembler.stiffness(), assembler.bodyForce(f), {1, 2, 3, 4}, exact);
  REQUIRE(maxNodalError(V, u, exact) <= kTol);
  // P1 cannot represent it: the same test on P1 must fail (so it can).
  const LagrangeSpace V1(mesh, 1);
  const ElasticityAssembler assembler1(V1, material);
  const Eigen::VectorXd u1 =
      solveWith(V1, assembler1.stiffness(), assembler1.bodyForce(f), {1, 2, 3, 4}, exact);
  REQUIRE(maxNodalError(V1, u1, exact) > 1e-7);
}
