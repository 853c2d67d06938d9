// The control problem's gradient against finite differences of J (docs/method.md §4), on a
// synthetic affine response with the structure of the real one: S_tt = M⁻¹A with A symmetric
// positive definite (so M S_tt is symmetric), and S_tn = M⁻¹ S_ntᵀ M (the adjoint in the M
// inner product). The finite-element version of this test is in tests/unit/fracture.
#include <catch2/catch.hpp>

#include <random>

#include "SyntheticResponse.hpp"
#include "friction/control/ControlProblem.hpp"

using namespace friction;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using friction::test::SyntheticResponse;

namespace {

// Smallest distance of any node from a kink of D (|N| = ρ, or ρ = 0), relative to ρ's scale.
double kinkMargin(const ControlState& s, double gamma) {
  double m = 1e300;
  for (Eigen::Index i = 0; i < s.beta.size(); ++i) {
    const double N = s.tau[i] - gamma * s.beta[i];
    m = std::min({m, std::abs(std::abs(N) - s.rho[i]), std::abs(s.rho[i])});
  }
  return m;
}

// The complementarity of one k = 1 node.
NodeComplementarity complementarity(double tau, double beta, double rho, double gamma) {
  return friction::complementarity(Block::Constant(1, tau), Block::Constant(1, beta), rho, gamma);
}

struct FdCheck {
  double analytic, numeric;
  int slipping;
};

FdCheck directionalDerivative(ControlProblem& p, SyntheticResponse& r, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Index n = p.size();
  for (int attempt = 0; attempt < 1000; ++attempt) {
    VectorXd beta = VectorXd::NullaryExpr(n, [&] { return scale * u(r.rng()); });
    const ControlState s = p.evaluate(beta);
    if (kinkMargin(s, p.gamma()) < 0.05) continue;  // FD across a kink measures nothing
    int slipping = 0, sticking = 0;
    for (const auto& c : s.node) {
      slipping += c.state == SlipState::slip;
      sticking += c.state == SlipState::stick;
    }
    // Both branches of D (and of ρ(β) for Coulomb) in one check: a β where every node sticks
    // would test only the trivial rows of the gradient.
    if (slipping == 0 || sticking == 0) continue;
    const VectorXd d = VectorXd::NullaryExpr(n, [&] { return u(r.rng()); });
    // J is piecewise quadratic in β: central differences are exact up to round-off as long as
    // β ± εd stays inside one piece, which the margin above guarantees for ε = 1e-6.
    const double eps = 1e-6;
    const double Jp = p.evaluate(beta + eps * d).J, Jm = p.evaluate(beta - eps * d).J;
    return {p.dot(p.gradient(s), d), (Jp - Jm) / (2 * eps), slipping};
  }
  FAIL("no β away from kinks with both stick and slip nodes found");
  return {};
}

}  // namespace

TEST_CASE("the exact gradient matches finite differences of J, Coulomb and Tresca",
          "[control][gradient]") {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    SyntheticResponse r(6, seed);
    const int n = 6;
    SECTION("coulomb, seed " + std::to_string(seed)) {
      ControlProblem p(r, VectorXd::Constant(n, 0.4), VectorXd::Zero(n), 2.0, 0.1,
                       GradientKind::exact);
      const FdCheck c = directionalDerivative(p, r, 0.5);
      // Relative agreement to 1e-6: the FD is exact for a piecewise quadratic up to
      // cancellation error ~ 1e-16 · J / ε.
      CHECK(c.analytic == Approx(c.numeric).epsilon(1e-6));
    }
    SECTION("tresca, seed " + std::to_string(seed)) {
      ControlProblem p(r, VectorXd::Zero(n), VectorXd::Constant(n, 1.0), 2.0, 0.0,
                       GradientKind::exact);
      const FdCheck c = directionalDerivative(p, r, 0.5);
      CHECK(c.analytic == Approx(c.numeric).epsilon(1e-6));
    }
    SECTION("tresca with the paper's frozen-rho gradient, seed " + std::to_string(seed)) {
      // With μ = 0, ρ does not depend on β: the paper's gradient is exact for Tresca.
      ControlProblem p(r, VectorXd::Zero(n), VectorXd::Constant(n, 1.0), 2.0, 0.0,
                       GradientKind::frozenRho);
      const FdCheck c = directionalDerivative(p, r, 0.5);
      CHECK(c.analytic == Approx(c.numeric).epsilon(1e-6));
    }
  }
}

TEST_CASE("for Coulomb the frozen-rho gradient is not the gradient of J where nodes slip",
          "[control][gradient]") {
  SyntheticResponse r(6, 11);
  ControlProblem exact(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0,
                       GradientKind::exact);
  ControlProblem frozen(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0,
                        GradientKind::frozenRho);
  int tested = 0;
  for (int i = 0; i < 20 && tested < 3; ++i) {
    const FdCheck e = directionalDerivative(exact, r, 0.5);
    if (e.slipping == 0) continue;
    ++tested;
    CHECK(e.analytic == Approx(e.numeric).epsilon(1e-6));
  }
  REQUIRE(tested > 0);
  // Same β for both: the frozen gradient differs by the dual response to μ P'_ρ D n_Γ.
  VectorXd beta = VectorXd::Constant(6, 0.3);
  const ControlState s = exact.evaluate(beta);
  int slipping = 0;
  for (const auto& c : s.node) slipping += c.state == SlipState::slip;
  // Without a slipping node the two gradients agree and the check below says nothing.
  REQUIRE(slipping > 0);
  CHECK((exact.gradient(s) - frozen.gradient(frozen.evaluate(beta))).norm() > 1e-8);
}

TEST_CASE("D vanishes exactly on the Coulomb conditions, slip opposite to tau",
          "[control][complementarity]") {
  const double gamma = 2.0, rho = 1.0;
  // Stick: |τ| < ρ and β = 0.
  CHECK(complementarity(0.5, 0.0, rho, gamma).D[0] == 0.0);
  CHECK(complementarity(0.5, 0.0, rho, gamma).state == SlipState::stick);
  // Stick with slip is not a solution.
  CHECK(complementarity(0.5, 0.1, rho, gamma).D[0] != 0.0);
  // Slip: |τ| = ρ and β opposite to τ.
  CHECK(complementarity(1.0, -0.3, rho, gamma).D[0] == 0.0);
  CHECK(complementarity(-1.0, 0.3, rho, gamma).D[0] == 0.0);
  CHECK(complementarity(1.0, -0.3, rho, gamma).state == SlipState::slip);
  // Slip along τ is not a solution.
  CHECK(complementarity(1.0, 0.3, rho, gamma).D[0] != 0.0);
  // Over the bound is not a solution.
  CHECK(complementarity(1.5, 0.0, rho, gamma).D[0] != 0.0);
  // Open (ρ ≤ 0): only τ = 0 is a solution, whatever β.
  CHECK(complementarity(0.0, 0.7, -0.1, gamma).D[0] == 0.0);
  CHECK(complementarity(0.2, 0.7, 0.0, gamma).D[0] == 0.2);
}
