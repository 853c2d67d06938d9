// DirichletConditions and ReducedSystem (fe/DirichletConditions.hpp): the reduced system is
// K_ff u_f = f_f − K_fd u_d; new Dirichlet values only change the right-hand side, so one
// factorisation serves every time step (docs/method.md §4).
#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "FeTestMeshes.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

TEST_CASE("fe Dirichlet conditions fix components per patch", "[fe][dirichlet]") {
  const Mesh mesh = test::unitSquareMesh(4);
  const LagrangeSpace V(mesh, 2);
  DirichletConditions bc(V);
  REQUIRE(bc.numFixed() == 0);
  REQUIRE(bc.fixPatch(1, FixedComponents::y) == 9);  // 5 vertices + 4 midpoints
  REQUIRE(bc.fixPatch(4, FixedComponents::x) == 9);
  REQUIRE(bc.fixPatch(42, FixedComponents::all) == 0);  // no such label: caller reports it
  REQUIRE(bc.numFixed() == 18);
  REQUIRE(bc.numFree() + bc.numFixed() == V.numDofs());
  const Index corner = 0;  // on bottom and left: both components fixed
  REQUIRE(bc.isFixed(V.dof(corner, 0)));
  REQUIRE(bc.isFixed(V.dof(corner, 1)));
  const Index bottomMid = V.midpointNode(1, 2);
  REQUIRE(bc.isFixed(V.dof(bottomMid, 1)));
  REQUIRE_FALSE(bc.isFixed(V.dof(bottomMid, 0)));
  for (Index k = 0; k < bc.numFree(); ++k) REQUIRE(bc.reducedIndex(bc.freeDofs()[k]) == k);
  for (Index d : bc.fixedDofs()) REQUIRE(bc.reducedIndex(d) == -1);
  // Values go only to the components each patch fixes: the corner keeps bottom's y and
  // left's x, whatever the order of the calls.
  bc.setPatchValue(1, Vector2(7.0, 0.25));
  bc.setPatchValue(4, Vector2(-0.5, 9.0));
  REQUIRE(bc.values()[V.dof(corner, 0)] == -0.5);
  REQUIRE(bc.values()[V.dof(corner, 1)] == 0.25);
  REQUIRE(bc.values()[V.dof(bottomMid, 0)] == 0.0);
}

TEST_CASE("fe reduced system factors once and follows changing Dirichlet values",
          "[fe][dirichlet]") {
  const Mesh mesh = test::unitSquareMesh(5, 0.4);
  const LagrangeSpace V(mesh, 2);
  const Material material = Material::fromYoungPoisson(3.0, 0.2);
  const ElasticityAssembler assembler(V, material);
  const Eigen::SparseMatrix<double> K = assembler.stiffness();
  DirichletConditions bc(V);
  bc.fixPatch(4, FixedComponents::all);
  bc.fixPatch(2, FixedComponents::x);
  const ReducedSystem reduced(K, bc);
  REQUIRE(reduced.matrix().rows() == bc.numFree());
  REQUIRE(reduced.coupling().cols() == bc.numFixed());

  // The reduced blocks are exactly the corresponding blocks of K.
  const Eigen::MatrixXd Kd(K);
  const Eigen::MatrixXd Kff(reduced.matrix()), Kfd(reduced.coupling());
  for (Index i = 0; i < bc.numFree(); ++i) {
    for (Index j = 0; j < bc.numFree(); ++j)
      REQUIRE(Kff(i, j) == Kd(bc.freeDofs()[i], bc.freeDofs()[j]));
    for (Index j = 0; j < bc.numFixed(); ++j)
      REQUIRE(Kfd(i, j) == Kd(bc.freeDofs()[i], bc.fixedDofs()[j]));
  }

  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  const Eigen::VectorXd F = assembler.bodyForce(Vector2(0.1, -0.3));
  // Three "time steps" with growing Dirichlet values; each solution satisfies the full
  // equations at the free dofs and carries the prescribed values at the fixed ones.
  for (int step = 1; step <= 3; ++step) {
    bc.setPatchValue(4, Vector2(0.0, 0.01 * step));
    bc.setPatchValue(
        2, test::planar([step](const Vector2& x) { return Vector2(-0.02 * step * x.y(), 0.0); }));
    const Eigen::VectorXd u = reduced.expand(factor.solve(reduced.rhs(F, bc)), bc);
    for (Index d : bc.fixedDofs()) REQUIRE(u[d] == bc.values()[d]);
    const Eigen::VectorXd residual = K * u - F;
    // Residual at free dofs: eps · |K| · |u| · (terms per row ~ 40) ≈ 1e-16 · 10 · 0.1 · 40;
    // 1e-12 leaves a margin of ~100. Non-zero residual at fixed dofs = reactions.
    double worst = 0.0;
    for (Index d : bc.freeDofs()) worst = std::max(worst, std::abs(residual[d]));
    CAPTURE(step);
    REQUIRE(worst <= 1e-12);
  }
  REQUIRE(factor.numFactorizations() == 1);
  REQUIRE(factor.numSolves() == 3);
}
