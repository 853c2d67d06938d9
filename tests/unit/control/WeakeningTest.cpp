// Slip-weakening friction in the control problem (ControlProblem.hpp, WeakeningSettings):
// μ(δ) and its slope, the Jacobian dD/dβ that Newton builds and the gradient of J against
// finite differences, on the synthetic response of GradientTest.cpp; and the reduction to
// Coulomb when μ_d = μ_s.
#include <catch2/catch.hpp>

#include <random>

#include "SyntheticResponse.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/law/Weakening.hpp"

using namespace friction;
using Eigen::VectorXd;
using friction::test::SyntheticResponse;

namespace {

WeakeningSettings settings(int n, Weakening form, double muS, double muD, double dc,
                           const VectorXd& pathStart) {
  WeakeningSettings w;
  w.nodes.assign(static_cast<std::size_t>(n), WeakeningNode{form, muS, muD, dc});
  w.pathStart = pathStart;
  w.cohesion = VectorXd::Zero(n);
  w.pressure = VectorXd::Zero(n);
  return w;
}

// Distance of node states from the kinks of D with weakening: |N| = ρ, ρ = 0, β_i = 0 (the
// path's |β|) and δ = D_c (the linear law's corner), each relative to its scale.
bool awayFromKinks(const ControlState& s, const ControlProblem& p, const WeakeningSettings& w,
                   double dc) {
  const Eigen::Index n = p.numNodes(), k = p.blockSize();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Block tau = s.tau.segment(k * i, k), beta = s.beta.segment(k * i, k);
    const double N = blockNorm(tau - p.gamma() * beta);
    if (std::abs(N - s.rho[i]) < 0.05 || std::abs(s.rho[i]) < 0.05) return false;
    if (blockNorm(beta) < 1e-3) return false;
    if (std::abs(w.pathStart[i] + blockNorm(beta) - dc) < 1e-3) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("slip-weakening: mu(delta) and its slope, linear and exponential", "[unit][control]") {
  const WeakeningNode lin{Weakening::linear, 0.6, 0.36, 2e-3};
  CHECK(lin.mu(0) == Approx(0.6));
  CHECK(lin.mu(1e-3) == Approx(0.48));
  CHECK(lin.mu(2e-3) == Approx(0.36));
  CHECK(lin.mu(5e-3) == Approx(0.36));
  CHECK(lin.slope(1e-3) == Approx(-120.0));
  CHECK(lin.slope(3e-3) == 0.0);
  const WeakeningNode ex{Weakening::exponential, 0.6, 0.36, 2e-3};
  CHECK(ex.mu(0) == Approx(0.6));
  CHECK(ex.mu(2e-3) == Approx(0.36 + 0.24 * std::exp(-1.0)));
  for (const WeakeningNode& w : {lin, ex})
    for (double d : {1e-4, 7e-4, 1.5e-3, 4e-3}) {
      const double e = 1e-8;
      CHECK(w.slope(d) == Approx((w.mu(d + e) - w.mu(d - e)) / (2 * e)).margin(1e-6));
    }
  const WeakeningNode none{Weakening::none, 0.5, 0.5, 1};
  CHECK(none.mu(10) == 0.5);
  CHECK(none.slope(10) == 0.0);
}

TEST_CASE("slip-weakening: Newton's Jacobian and the gradient match finite differences",
          "[unit][control]") {
  for (int k : {1, 2})
    for (Weakening form : {Weakening::linear, Weakening::exponential})
      for (unsigned seed : {1u, 2u, 3u}) {
        SyntheticResponse r(6, seed, k);
        const int n = 6;
        std::uniform_real_distribution<double> u(-1, 1);
        const double dc = 0.8;
        const VectorXd path = VectorXd::NullaryExpr(n, [&] { return 0.4 + 0.3 * u(r.rng()); });
        const WeakeningSettings w = settings(n, form, 0.6, 0.2, dc, path);
        ControlProblem p(r, VectorXd::Constant(n, 0.6), VectorXd::Zero(n), 2.0, 0.0,
                         GradientKind::exact, nullptr, &w);
        bool found = false;
        for (int attempt = 0; attempt < 2000 && !found; ++attempt) {
          const VectorXd beta = VectorXd::NullaryExpr(k * n, [&] { return 0.5 * u(r.rng()); });
          const ControlState s = p.evaluate(beta);
          int slipping = 0;
          for (const auto& c : s.node) slipping += c.state == SlipState::slip;
          if (slipping == 0 || !awayFromKinks(s, p, w, dc)) continue;
          found = true;
          // ρ really weakens: the state's μ is below μ_s where a node has slid.
          CHECK(s.mu.minCoeff() < 0.6);
          const double eps = 1e-7;
          for (Eigen::Index col = 0; col < k * n; ++col) {
            VectorXd e = VectorXd::Zero(k * n);
            e[col] = eps;
            const VectorXd dD = (p.evaluate(beta + e).D - p.evaluate(beta - e).D) / (2 * eps);
            for (Eigen::Index row = 0; row < k * n; ++row) {
              INFO("k " << k << " seed " << seed << " row " << row << " col " << col);
              CHECK(p.jacobianEntry(s, r.Stt(), r.Snt(), row, col) ==
                    Approx(dD[row]).margin(1e-5 * (1 + std::abs(dD[row]))));
            }
          }
          const VectorXd d = VectorXd::NullaryExpr(k * n, [&] { return u(r.rng()); });
          const double Jp = p.evaluate(beta + eps * d).J, Jm = p.evaluate(beta - eps * d).J;
          CHECK(p.dot(p.gradient(s), d) == Approx((Jp - Jm) / (2 * eps)).epsilon(1e-5));
        }
        CHECK(found);
      }
}

TEST_CASE("slip-weakening with mu_d = mu_s is Coulomb", "[unit][control]") {
  SyntheticResponse r(6, 7, 2);
  const int n = 6;
  const WeakeningSettings w = settings(n, Weakening::linear, 0.5, 0.5, 1e-3, VectorXd::Zero(n));
  ControlProblem weak(r, VectorXd::Constant(n, 0.5), VectorXd::Zero(n), 2.0, 0.0,
                      GradientKind::exact, nullptr, &w);
  ControlProblem coulomb(r, VectorXd::Constant(n, 0.5), VectorXd::Zero(n), 2.0, 0.0,
                         GradientKind::exact);
  std::uniform_real_distribution<double> u(-1, 1);
  const VectorXd beta = VectorXd::NullaryExpr(2 * n, [&] { return 0.5 * u(r.rng()); });
  const ControlState a = weak.evaluate(beta), b = coulomb.evaluate(beta);
  CHECK((a.D - b.D).norm() <= 1e-12 * (1 + b.D.norm()));
  CHECK((weak.gradient(a) - coulomb.gradient(b)).norm() <=
        1e-12 * (1 + coulomb.gradient(b).norm()));
}
