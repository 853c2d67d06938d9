// The control layer on blocks of k = 2 tangential components per node (3D faults,
// docs/method.md §7), on a synthetic M-self-adjoint response whose σ_n depends on β (so that
// Coulomb's ρ does too): the exact gradient and Newton's Jacobian against finite differences,
// Newton's solution of Tresca and Coulomb problems with stick and slip nodes, the isotropy of
// the laws (a turned tangent basis turns the slip), the projection onto the disc, and k = 1
// giving the scalar formulas of 2D to the bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
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

constexpr int k = 2;

// Smallest distance of any node from a kink of D (|N| = ρ, or ρ = 0).
double kinkMargin(const ControlState& s, double gamma) {
  double m = 1e300;
  for (Eigen::Index i = 0; i < s.sigmaN.size(); ++i) {
    const Block N = s.tau.segment(k * i, k) - gamma * s.beta.segment(k * i, k);
    m = std::min({m, std::abs(blockNorm(N) - s.rho[i]), std::abs(s.rho[i])});
  }
  return m;
}

struct Counts {
  int stick = 0, slip = 0, open = 0;
};
Counts count(const ControlState& s) {
  Counts c;
  for (const auto& n : s.node) {
    c.stick += n.state == SlipState::stick;
    c.slip += n.state == SlipState::slip;
    c.open += n.state == SlipState::open;
  }
  return c;
}

// A random β away from kinks where some nodes stick and some slip: finite differences across a
// kink measure nothing, and a β where every node is in one state tests only some rows.
VectorXd mixedBeta(ControlProblem& p, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (int attempt = 0; attempt < 20000; ++attempt) {
    const VectorXd beta = VectorXd::NullaryExpr(p.size(), [&] { return scale * u(rng); });
    const ControlState s = p.evaluate(beta);
    const Counts c = count(s);
    if (c.stick > 0 && c.slip > 0 && kinkMargin(s, p.gamma()) > 0.05) return beta;
  }
  FAIL("no β away from kinks with both stick and slip nodes found");
  return {};
}

std::unique_ptr<Optimizer> newton(const std::string& variant, double tolerance) {
  std::ostringstream text;
  text << "type semismoothNewton; variant " << variant << ";"
       << (variant == "condensed" ? " interfaceOperator dualSolves;" : "") << " tolerance "
       << tolerance << "; maxIterations 200;";
  Dictionary d = Dictionary::parse(text.str(), "test");
  auto opt = Optimizer::New(d);
  d.checkAllRead();
  return opt;
}

// The scalar complementarity of 2D as it was before blocks: the reference of the k = 1 check.
struct ScalarNode {
  SlipState state = SlipState::open;
  double D = 0, dPdN = 0, dPdRho = 0;
};
ScalarNode scalarComplementarity(double tau, double beta, double rho, double gamma) {
  ScalarNode c;
  if (rho <= 0) {
    c.D = tau;
    return c;
  }
  const double N = tau - gamma * beta;
  if (std::abs(N) <= rho) {
    c.state = SlipState::stick;
    c.D = gamma * beta;
    c.dPdN = 1;
    return c;
  }
  const double s = N > 0 ? 1.0 : -1.0;
  c.state = SlipState::slip;
  c.D = tau - rho * s;
  c.dPdRho = s;
  return c;
}

// Equal to the last bit, the sign of zero included. NaN equals NaN whatever its sign bit: that
// bit is not a result (a compiler may turn a product by ±1 into a sign flip).
bool sameBits(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("k = 2: the exact gradient matches finite differences of J", "[control][gradient]") {
  struct Law {
    const char* name;
    double mu, cohesion;
    GradientKind kind;
  };
  // The frozen-ρ gradient only for Tresca, where ρ does not depend on β and it is exact.
  const Law laws[] = {{"coulomb exact", 0.4, 0.0, GradientKind::exact},
                      {"coulomb with cohesion, exact", 0.3, 0.5, GradientKind::exact},
                      {"tresca exact", 0.0, 1.5, GradientKind::exact},
                      {"tresca frozen rho", 0.0, 1.5, GradientKind::frozenRho}};
  for (const Law& law : laws)
    for (unsigned seed : {1u, 2u, 3u}) {
      DYNAMIC_SECTION(law.name << ", seed " << seed) {
        const int n = 6;
        SyntheticResponse r(n, seed, k);
        ControlProblem p(r, VectorXd::Constant(n, law.mu), VectorXd::Constant(n, law.cohesion), 2.0,
                         0.1, law.kind);
        REQUIRE(p.size() == k * n);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int check = 0; check < 3; ++check) {
          const VectorXd beta = mixedBeta(p, rng, 0.05);
          const ControlState s = p.evaluate(beta);
          const VectorXd d = VectorXd::NullaryExpr(k * n, [&] { return u(rng); });
          // D is smooth between kinks (N/|N| is not linear in slip, so J is not piecewise
          // quadratic): the central difference errs by O(ε²) ~ 1e-12 relative, and by
          // cancellation ~1e-16 J/ε.
          const double eps = 1e-6;
          const double fd =
              (p.evaluate(beta + eps * d).J - p.evaluate(beta - eps * d).J) / (2 * eps);
          CHECK(p.dot(p.gradient(s), d) == Approx(fd).epsilon(1e-6));
        }
      }
    }
}

TEST_CASE("k = 2: for Coulomb the frozen-rho gradient differs where nodes slip",
          "[control][gradient]") {
  const int n = 6;
  SyntheticResponse r(n, 4, k);
  ControlProblem exact(r, VectorXd::Constant(n, 0.4), VectorXd::Zero(n), 2.0, 0.0,
                       GradientKind::exact);
  ControlProblem frozen(r, VectorXd::Constant(n, 0.4), VectorXd::Zero(n), 2.0, 0.0,
                        GradientKind::frozenRho);
  std::mt19937 rng(4);
  const VectorXd beta = mixedBeta(exact, rng, 0.05);
  const ControlState s = exact.evaluate(beta);
  REQUIRE(count(s).slip > 0);
  // The difference is the dual response to μ (P'_ρ·D) n_Γ: of the size of the gradient.
  const VectorXd g = exact.gradient(s);
  CHECK((g - frozen.gradient(frozen.evaluate(beta))).norm() > 1e-3 * g.norm());
}

TEST_CASE("k = 2: Newton's generalised Jacobian matches finite differences of D",
          "[control][optimizer]") {
  for (unsigned seed : {5u, 6u, 7u}) {
    for (double mu : {0.0, 0.4}) {
      CAPTURE(seed, mu);
      const int n = 6;
      SyntheticResponse r(n, seed, k);
      ControlProblem p(r, VectorXd::Constant(n, mu), VectorXd::Constant(n, mu > 0 ? 0.0 : 1.5), 2.0,
                       0.0, GradientKind::exact);
      const InterfaceOperator op = r.interfaceOperator(InterfaceMethod::dualSolves);
      REQUIRE(op.Stt.rows() == k * n);
      REQUIRE(op.Snt.rows() == n);
      REQUIRE(op.Snt.cols() == k * n);
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> u(-1, 1);
      const VectorXd beta = mixedBeta(p, rng, 0.05);
      const ControlState s = p.evaluate(beta);
      MatrixXd G(k * n, k * n);
      for (Eigen::Index a = 0; a < k * n; ++a)
        for (Eigen::Index b = 0; b < k * n; ++b) G(a, b) = p.jacobianEntry(s, op.Stt, op.Snt, a, b);
      const VectorXd d = VectorXd::NullaryExpr(k * n, [&] { return u(rng); });
      const double eps = 1e-6;
      const VectorXd fd = (p.evaluate(beta + eps * d).D - p.evaluate(beta - eps * d).D) / (2 * eps);
      // O(ε²) truncation of a smooth D and cancellation ~1e-16 |D|/ε: 1e-7 of |G d|.
      CHECK((G * d - fd).norm() <= 1e-7 * fd.norm());
      REQUIRE(fd.norm() > 0);
    }
  }
}

TEST_CASE(
    "k = 2: Newton solves Tresca and Coulomb, slip opposite to tau, |tau| = rho where "
    "nodes slip",
    "[control][optimizer]") {
  struct Problem {
    const char* name;
    double mu, cohesion;
  };
  for (const Problem& law : {Problem{"tresca", 0.0, 3.0}, Problem{"coulomb", 0.8, 0.0}})
    for (const char* variant : {"condensed", "krylov"}) {
      DYNAMIC_SECTION(law.name << ", " << variant) {
        const int n = 10;
        SyntheticResponse r(n, 31, k);
        ControlProblem p(r, VectorXd::Constant(n, law.mu), VectorXd::Constant(n, law.cohesion), 2.0,
                         0.0, GradientKind::exact);
        VectorXd beta = VectorXd::Zero(k * n);
        const OptimizerReport rep = newton(variant, 1e-12)->minimize(p, beta);
        INFO("iterations " << rep.iterations << ", status " << toString(rep.status));
        REQUIRE(rep.status == OptimizerStatus::converged);
        const ControlState s = p.evaluate(beta);
        CHECK(p.relativeResidual(s) <= 1e-12);
        const Counts c = count(s);
        // Both states present: otherwise the check covers one branch of the law only.
        REQUIRE(c.stick > 0);
        REQUIRE(c.slip > 0);
        double largest = 0;
        for (Eigen::Index i = 0; i < n; ++i)
          largest = std::max(largest, beta.segment<2>(k * i).norm());
        for (Eigen::Index i = 0; i < n; ++i) {
          const Eigen::Vector2d b = beta.segment<2>(k * i), t = s.tau.segment<2>(k * i);
          const double scale = std::max(s.rho[i], 1.0);
          if (s.node[i].state == SlipState::stick) {
            CHECK(b.norm() == 0.0);  // β = 0 exactly: Newton sets stick nodes at once
            CHECK(t.norm() <= s.rho[i]);
          } else {
            REQUIRE(s.node[i].state == SlipState::slip);
            CHECK(std::abs(t.norm() - s.rho[i]) <= 1e-10 * scale);
            // β = −c τ with c > 0: antiparallel, up to the residual: γβ = (1 − |N|/ρ)τ +
            // (|N|/ρ)D, so the part of β across τ is below |D|/γ ≈ 1e-11 here, against slips
            // of 1e-3 (bound: 1e-7 of the largest).
            CHECK(b.dot(t) < 0);
            CHECK(std::abs(b.x() * t.y() - b.y() * t.x()) / t.norm() <= 1e-7 * largest);
          }
        }
      }
    }
}

TEST_CASE("k = 2: turning every node's tangent basis turns the slip, |beta| unchanged",
          "[control][optimizer]") {
  // The laws use |τ| and |N| only (isotropic in the tangent plane): a case written in another
  // tangent basis has the same slip vectors, with components in that basis.
  for (double mu : {0.0, 0.8}) {
    CAPTURE(mu);
    const int n = 10;
    const VectorXd m = VectorXd::Constant(n, mu), c = VectorXd::Constant(n, mu > 0 ? 0.0 : 3.0);
    SyntheticResponse r(n, 31, k), turned(n, 31, k);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-M_PI, M_PI);
    std::vector<double> angle(n);
    for (double& a : angle) a = u(rng);
    turned.rotateBases(angle);
    ControlProblem p(r, m, c, 2.0, 0.0, GradientKind::exact);
    ControlProblem q(turned, m, c, 2.0, 0.0, GradientKind::exact);
    VectorXd beta = VectorXd::Zero(k * n), betaTurned = VectorXd::Zero(k * n);
    REQUIRE(newton("condensed", 1e-14)->minimize(p, beta).status == OptimizerStatus::converged);
    REQUIRE(newton("condensed", 1e-14)->minimize(q, betaTurned).status ==
            OptimizerStatus::converged);
    REQUIRE(beta.norm() > 0);
    const VectorXd expected = r.rotation(angle).transpose() * beta;
    int slipping = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double size = beta.segment<2>(k * i).norm();
      slipping += size > 0;
      // Both solved to round-off; the slip inherits it times the condition of S (~10²).
      CHECK(betaTurned.segment<2>(k * i).norm() == Approx(size).epsilon(1e-12).margin(1e-14));
      CHECK((betaTurned.segment<2>(k * i) - expected.segment<2>(k * i)).norm() <=
            1e-12 * beta.norm());
    }
    CHECK(slipping > 0);
    CHECK(slipping < n);
  }
}

TEST_CASE("the projection onto the disc: inside unchanged, outside onto the circle",
          "[control][complementarity]") {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-3, 3);
  int inside = 0, outside = 0, open = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Block tau = Block::NullaryExpr(k, [&] { return u(rng); });
    const double rho = u(rng);
    // β = 0: N = τ, and P_ρ(N) = τ − D.
    const NodeComplementarity c = complementarity(tau, Block::Zero(k), rho, 2.0);
    const Block P = tau - c.D;
    if (rho <= 0) {
      ++open;
      CHECK(P.norm() == 0.0);
      CHECK(c.state == SlipState::open);
    } else if (tau.norm() <= rho) {
      ++inside;
      CHECK(P == tau);
      CHECK(c.state == SlipState::stick);
      CHECK(c.dPdN == BlockMatrix::Identity(k, k));
    } else {
      ++outside;
      CHECK(c.state == SlipState::slip);
      // P is read back as τ − D: round-off of a few operations on numbers of size |τ|.
      const double roundOff = 1e-15 * tau.norm();
      CHECK(P.norm() <= rho + roundOff);
      CHECK((P - rho * tau / tau.norm()).norm() <= roundOff);
      // P'_N = (ρ/|N|)(I − N̂N̂ᵀ): N̂ is its null vector, and P'_ρ = N̂.
      CHECK((c.dPdN * tau).norm() <= 1e-15 * tau.norm());
      CHECK((c.dPdRho - tau / tau.norm()).norm() <= 1e-15);
      CHECK((c.dPdN * c.dPdN - rho / tau.norm() * c.dPdN).norm() <= 1e-15);
    }
  }
  CHECK(inside > 100);
  CHECK(outside > 100);
  CHECK(open > 100);
  // Overflow-safe: the norm of huge and tiny blocks.
  Block big(2), tiny(2);
  big << 3e200, 4e200;
  tiny << 3e-200, 4e-200;
  CHECK(blockNorm(big) == Approx(5e200));
  CHECK(blockNorm(tiny) == Approx(5e-200));
}

TEST_CASE("k = 1: the block complementarity is the scalar formula of 2D, bit for bit",
          "[control][complementarity]") {
  // Every operation on a block of one component must be the scalar one: 2D results stay the
  // same to the last bit (including the signs of zeros and non-finite values).
  const double inf = std::numeric_limits<double>::infinity(),
               nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {
      0.0, -0.0,  1e-300, -1e-300, 1e-170, -3e-170, 0.1,     -0.3,     0.7, -0.7, 1.0, -1.0,
      2.5, -4.75, 1e10,   -3e10,   1e200,  -1e200,  1.7e308, -1.7e308, inf, -inf, nan};
  const std::vector<double> gammas = {2.0, 1e-8, 3e7};
  long compared = 0;
  for (double tau : values)
    for (double beta : values)
      for (double rho : values)
        for (double gamma : gammas) {
          const ScalarNode ref = scalarComplementarity(tau, beta, rho, gamma);
          const NodeComplementarity c =
              complementarity(Block::Constant(1, tau), Block::Constant(1, beta), rho, gamma);
          INFO("tau " << tau << " beta " << beta << " rho " << rho << " gamma " << gamma);
          REQUIRE(c.D.size() == 1);
          CHECK(c.state == ref.state);
          CHECK(sameBits(c.D[0], ref.D));
          CHECK(sameBits(c.dPdN(0, 0), ref.dPdN));
          CHECK(sameBits(c.dPdRho[0], ref.dPdRho));
          ++compared;
        }
  CHECK(compared == 23L * 23 * 23 * 3);
}
