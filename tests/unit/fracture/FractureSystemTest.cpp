// The finite-element SlipResponse (docs/method.md): the gradient of J against finite
// differences for Coulomb and Tresca, P1 and P2; the M-self-adjointness of the dual map; and
// the known answers that need no optimizer.
#include <catch2/catch.hpp>

#include <random>

#include "TestMeshes.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::test;
using Eigen::VectorXd;

namespace {

// Unit square, horizontal fracture across the width at y = 0.5, bottom clamped, top moved
// by (−0.02, −0.025) as in the paper's benchmark; λ = μ = 1.
struct Benchmark {
  SplitMesh split;
  Material material = Material::fromLame(1.0, 1.0);
  std::unique_ptr<FractureSystem> sys;

  Benchmark(int n, int degree, Vector2 top = Vector2(-0.02, -0.025)) {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, n / 2, 0, n, 5, "fracture");
    split = splitFractures(m, {{"fracture", 5, {}}});
    sys = std::make_unique<FractureSystem>(split, degree, material);
    sys->dirichlet().fixPatch(1, FixedComponents::all);
    sys->dirichlet().fixPatch(3, FixedComponents::all);
    REQUIRE(sys->factor("cholmod") == FactorStatus::ok);
    sys->dirichlet().setPatchValue(1, Vector2(0, 0));
    sys->dirichlet().setPatchValue(3, top);
    sys->setStep(VectorXd::Zero(sys->splitSpace().numDofs()), VectorXd::Zero(sys->size()));
  }
};

double kinkMargin(const ControlState& s, double gamma) {
  double m = 1e300;
  for (Eigen::Index i = 0; i < s.beta.size(); ++i) {
    const double N = s.tau[i] - gamma * s.beta[i];
    m = std::min({m, std::abs(std::abs(N) - s.rho[i]) / (std::abs(s.rho[i]) + 1e-3),
                  std::abs(s.rho[i]) / 1e-3});
  }
  return m;
}

}  // namespace

TEST_CASE("the finite-element gradient of J matches finite differences",
          "[control][gradient][fe]") {
  for (int degree : {1, 2}) {
    for (const char* law : {"coulomb", "tresca"}) {
      DYNAMIC_SECTION("P" << degree << " " << law) {
        Benchmark b(8, degree);
        const Eigen::Index n = b.sys->size();
        const bool coulomb = std::string(law) == "coulomb";
        // μ_f = 0.2 makes the middle slip; Tresca with a threshold of the same size.
        ControlProblem p(*b.sys, VectorXd::Constant(n, coulomb ? 0.2 : 0.0),
                         VectorXd::Constant(n, coulomb ? 0.0 : 0.008), 2.0, 0.0,
                         GradientKind::exact);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1, 1);
        int checked = 0, slipping = 0;
        for (int attempt = 0; attempt < 200 && checked < 3; ++attempt) {
          const VectorXd beta = VectorXd::NullaryExpr(n, [&] { return 0.004 * u(rng); });
          const ControlState s = p.evaluate(beta);
          if (kinkMargin(s, p.gamma()) < 0.02) continue;
          for (const auto& c : s.node) slipping += c.state == SlipState::slip;
          const VectorXd d = VectorXd::NullaryExpr(n, [&] { return u(rng); });
          const double eps = 1e-7;
          const double fd =
              (p.evaluate(beta + eps * d).J - p.evaluate(beta - eps * d).J) / (2 * eps);
          // J is piecewise quadratic and β ± εd stays in one piece: the central difference
          // is exact up to cancellation, ~1e-16 J / ε relative.
          CHECK(p.dot(p.gradient(s), d) == Approx(fd).epsilon(1e-6));
          ++checked;
        }
        CHECK(checked == 3);
        CHECK(slipping > 0);  // the check covered the slip state, where ρ(β) matters
      }
    }
  }
}

TEST_CASE("the dual map is self-adjoint in the M inner product", "[fracture][fe]") {
  for (int degree : {1, 2}) {
    Benchmark b(6, degree);
    const Eigen::Index n = b.sys->size();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const VectorXd a = VectorXd::NullaryExpr(n, [&] { return u(rng); });
    const VectorXd c = VectorXd::NullaryExpr(n, [&] { return u(rng); });
    const VectorXd zero = VectorXd::Zero(n);
    VectorXd Sa, Sc;
    b.sys->dual(a, zero, Sa);
    b.sys->dual(c, zero, Sc);
    const VectorXd& w = b.sys->weights();
    const double lhs = (w.array() * Sa.array() * c.array()).sum();
    const double rhs = (w.array() * a.array() * Sc.array()).sum();
    // Round-off of two back-substitutions, relative to the size of the products.
    CHECK(lhs == Approx(rhs).epsilon(1e-10));
    // And positive: the Steklov–Poincaré map of an elastic body stores energy, ⟨Sa, a⟩_M > 0.
    CHECK((w.array() * Sa.array() * a.array()).sum() > 0);
  }
}

TEST_CASE("zero load gives zero traction and a zero-jump solve equals the unsplit solve",
          "[fracture][fe]") {
  Benchmark zero(8, 1, Vector2(0, 0));
  VectorXd tau, sigmaN;
  zero.sys->primal(VectorXd::Zero(zero.sys->size()), tau, sigmaN);
  CHECK(tau.cwiseAbs().maxCoeff() == 0.0);
  CHECK(sigmaN.cwiseAbs().maxCoeff() == 0.0);

  // With no jump, the split displacement is the unsplit linear solve: each copy of a
  // fracture node carries the unsplit value, so ⁺ and ⁻ agree exactly.
  Benchmark b(8, 1);
  b.sys->primal(VectorXd::Zero(b.sys->size()), tau, sigmaN);
  const VectorXd u = b.sys->lastSplitDisplacement();
  int split = 0;  // nodes with two copies: on a single copy the check below is trivial
  for (const auto& v : b.sys->controlNodes()) {
    split += v.plus != v.minus;
    for (int c = 0; c < 2; ++c) CHECK(u[2 * v.plus + c] == u[2 * v.minus + c]);
  }
  CHECK(split == 9);  // the whole fracture of the 8x8 grid, both ends on the boundary
  // Compression across the fracture (top pushed down) and the horizontal pull of the top
  // give σ_n < 0 and τ ≠ 0 in the middle.
  const Eigen::Index mid = b.sys->size() / 2;
  CHECK(sigmaN[mid] < 0);
  CHECK(tau[mid] != 0);
}
