// The control layer with openings (docs/method.md §4, "Fractures that open"), on the synthetic
// M-self-adjoint response, for k = 1 and 2: the exact gradient of J and Newton's Jacobian
// against finite differences where some nodes are in contact (sticking and slipping) and
// some open, and Newton's solution satisfying g ≥ 0, σ'_n ≤ 0, g σ'_n = 0 and the friction law.
#include <catch2/catch.hpp>

#include <random>
#include <sstream>

#include "SyntheticResponse.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using friction::test::SyntheticResponse;

namespace {

/// n nodes, k components; σ_n offsets spread over −4 … +2 and a pressure 0.5, so that some
/// nodes are pulled open; the last node's fracture may not open.
struct Setup {
  int n, k;
  SyntheticResponse r;
  OpeningSettings open;
  Setup(int n_, int k_, unsigned seed) : n(n_), k(k_), r(n_, seed, k_) {
    r.shiftSigmaN(VectorXd::LinSpaced(n, 0.0, 4.0));
    open.unilateral = VectorXd::Ones(n);
    open.unilateral[n - 1] = 0;
    open.pressure = VectorXd::Constant(n, 0.5);
    open.gammaN = 3.0;
  }
};

/// Smallest distance from a kink of D: |N| = ρ, ρ = 0, or σ'_n + γ_n g = 0.
double kinkMargin(const ControlProblem& p, const ControlState& s) {
  const Eigen::Index n = p.numNodes(), k = p.blockSize();
  double m = 1e300;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Block N = s.tau.segment(k * i, k) - p.gamma() * s.beta.segment(k * i, k);
    if (s.rho[i] != 0) m = std::min({m, std::abs(blockNorm(N) - s.rho[i]), std::abs(s.rho[i])});
    if (p.componentMask()[k * n + i] != 0)
      m = std::min(m, std::abs(s.sigmaN[i] + p.openingSettings().pressure[i] +
                               p.openingSettings().gammaN * s.beta[k * n + i]));
  }
  return m;
}

/// A random control away from kinks with nodes in contact and open: finite differences
/// across a kink measure nothing.
VectorXd mixedControl(ControlProblem& p, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Index n = p.numNodes(), k = p.blockSize();
  for (int attempt = 0; attempt < 20000; ++attempt) {
    VectorXd x = VectorXd::NullaryExpr(p.size(), [&] { return 0.05 * u(rng); });
    for (Eigen::Index i = 0; i < n; ++i) x[k * n + i] = std::abs(x[k * n + i]) * 4;
    const ControlState s = p.evaluate(x);
    int open = 0, contact = 0, slip = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (p.componentMask()[k * n + i] == 0) continue;
      (s.contact[i] ? contact : open)++;
      slip += s.contact[i] && s.node[i].state == SlipState::slip;
    }
    if (open > 0 && contact > 0 && slip > 0 && kinkMargin(p, s) > 0.02) return x;
  }
  FAIL("no control away from kinks with open, closed and slipping nodes found");
  return {};
}

}  // namespace

TEST_CASE("openings: the exact gradient matches finite differences of J", "[control][opening]") {
  for (int k : {1, 2})
    for (unsigned seed : {11u, 12u, 13u}) {
      DYNAMIC_SECTION("k = " << k << ", seed " << seed) {
        Setup c(8, k, seed);
        ControlProblem p(c.r, VectorXd::Constant(c.n, 0.4), VectorXd::Constant(c.n, 0.2), 2.0, 0.1,
                         GradientKind::exact, &c.open);
        REQUIRE(p.size() == k * c.n + c.n);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int check = 0; check < 3; ++check) {
          const VectorXd x = mixedControl(p, rng);
          const ControlState s = p.evaluate(x);
          const VectorXd d = VectorXd::NullaryExpr(p.size(), [&] { return u(rng); });
          // Central differences of a D smooth between kinks: O(ε²) and ~1e-16 J/ε.
          const double eps = 1e-6;
          const double fd = (p.evaluate(x + eps * d).J - p.evaluate(x - eps * d).J) / (2 * eps);
          CHECK(p.dot(p.gradient(s), d) == Approx(fd).epsilon(1e-6));
        }
      }
    }
}

TEST_CASE("openings: Newton's Jacobian matches finite differences of D", "[control][opening]") {
  for (int k : {1, 2})
    for (unsigned seed : {21u, 22u}) {
      CAPTURE(k, seed);
      Setup c(8, k, seed);
      ControlProblem p(c.r, VectorXd::Constant(c.n, 0.4), VectorXd::Zero(c.n), 2.0, 0.0,
                       GradientKind::exact, &c.open);
      const InterfaceOperator op = c.r.interfaceOperator(InterfaceMethod::dualSolves, true);
      REQUIRE(op.Stn.rows() == k * c.n);
      REQUIRE(op.Snn.rows() == c.n);
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> u(-1, 1);
      const VectorXd x = mixedControl(p, rng);
      const ControlState s = p.evaluate(x);
      const Eigen::Index m = p.size();
      MatrixXd G(m, m);
      for (Eigen::Index a = 0; a < m; ++a)
        for (Eigen::Index b = 0; b < m; ++b) G(a, b) = p.jacobianEntryWithOpening(s, op, a, b);
      const VectorXd d =
          VectorXd::NullaryExpr(m, [&] { return u(rng); }).cwiseProduct(p.componentMask());
      const double eps = 1e-6;
      const VectorXd fd = (p.evaluate(x + eps * d).D - p.evaluate(x - eps * d).D) / (2 * eps);
      REQUIRE(fd.norm() > 0);
      CHECK((G * d - fd).norm() <= 1e-7 * fd.norm());
    }
}

TEST_CASE("openings: Newton solves contact with friction node by node", "[control][opening]") {
  for (int k : {1, 2}) {
    CAPTURE(k);
    Setup c(10, k, 31);
    c.r.shiftSigmaN(VectorXd::LinSpaced(c.n, 0.0, 8.0));  // the last nodes well in tension
    ControlProblem p(c.r, VectorXd::Constant(c.n, 0.8), VectorXd::Zero(c.n), 2.0, 0.0,
                     GradientKind::exact, &c.open);
    Dictionary d = Dictionary::parse(
        "type semismoothNewton; interfaceOperator dualSolves; tolerance 1e-12; maxIterations "
        "200;",
        "test");
    auto newton = Optimizer::New(d);
    VectorXd x = VectorXd::Zero(p.size());
    const OptimizerReport rep = newton->minimize(p, x);
    INFO("iterations " << rep.iterations << ", status " << toString(rep.status));
    REQUIRE(rep.status == OptimizerStatus::converged);
    const ControlState s = p.evaluate(x);
    CHECK(p.relativeResidual(s) <= 1e-12);
    int open = 0, closed = 0;
    const Eigen::Index n = c.n, kn = k * n;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double g = x[kn + i], effective = s.sigmaN[i] + c.open.pressure[i];
      if (c.open.unilateral[i] == 0) {
        CHECK(g == 0);  // may not open: its component is held
        continue;
      }
      CHECK(g >= 0);
      if (s.contact[i]) {
        ++closed;
        CHECK(g == 0);  // Newton sets a closed node's g = 0 exactly
        CHECK(effective <= 1e-12);
        CHECK(blockNorm(s.tau.segment(k * i, k)) <= s.rho[i] * (1 + 1e-10));
      } else {
        ++open;
        CHECK(std::abs(effective) <= 1e-10);
        CHECK(blockNorm(s.tau.segment(k * i, k)) <= 1e-10);
      }
    }
    // Both kinds, or half of the checks test nothing.
    CHECK(open > 0);
    CHECK(closed > 0);
  }
}
