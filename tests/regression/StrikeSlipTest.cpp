// cases/strikeSlipFault on its coarse test mesh (./Allmesh -nFault 10 -nSide 8 -nLayers 5):
// a vertical fault striking 30° east of north in a block under gravity, a lithostatic
// in-situ stress and north-south shortening, Coulomb friction with cohesion. The fault is
// stuck under the first step and slips from the ground surface downwards as the load grows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "CaseRunner.hpp"

using namespace friction::regression;

namespace {

// The case's numbers (cases/strikeSlipFault: constant/*, 0/D, system/controlDict).
constexpr double kE = 30e9;                // [Pa]
constexpr double kMu = 0.6;                // friction coefficient
constexpr double kCohesion = 2e6;          // [Pa]
constexpr double kHorizontalGrad = 19620;  // k0 rho g [Pa/m]
constexpr double kPushPerStep = 0.3;       // north face displacement per unit time [m]
constexpr double kWidth = 2000;            // north-south extent of the block [m]
constexpr int kSteps = 8;
const double kPi = std::acos(-1.0);
const double kStrike = kPi / 6;  // from north (y) towards east (x)

double norm2(double a, double b) { return std::sqrt(a * a + b * b); }

/// The slip vector of row i in x y z.
std::array<double, 3> slipVector(const Table& t, std::size_t i) {
  return {t.at(i, "slipX"), t.at(i, "slipY"), t.at(i, "slipZ")};
}

}  // namespace

TEST_CASE(
    "strikeSlipFault: stuck first, then Coulomb slip spreading down from the surface, "
    "horizontal and left-lateral, normal stress growing with depth",
    "[regression][3d]") {
  Case c("strikeSlipFault", "strikeSlipFault");
  c.remesh("-nFault 10 -nSide 8 -nLayers 5");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);  // every step converged
  std::vector<Table> steps;
  for (int k = 1; k <= kSteps; ++k) steps.push_back(c.namedTable(std::to_string(k), "fault"));
  for (const Table& t : steps) {
    REQUIRE(t.rows.size() == steps[0].rows.size());
    REQUIRE(!t.comments.empty());
    CHECK(t.comments[0].rfind("# status converged", 0) == 0);
  }
  const Table& first = steps.front();
  const Table& last = steps.back();
  const std::array<double, 3> strike{std::sin(kStrike), std::cos(kStrike), 0.0};

  {
    // The first step is the bonded homogeneous state: in-situ stress plus uniaxial shortening, so
    // gravity is balanced and nothing slips. Under the first step no node slips, so the block
    // deforms homogeneously: σ_yy = −E ε with ε = 0.3/2000 (the east face and the ground surface
    // are free), and the lithostatic σ⁰ adds k0 ρ g z to σ_n; were gravity not balanced by σ⁰'s
    // divergence, the block would settle under its weight and σ_n, τ would differ from this.
    const double s = kE * kPushPerStep / kWidth;  // |σ_yy| [Pa]
    const double n = std::sin(kStrike), t = std::cos(kStrike);
    int checked = 0;
    for (std::size_t i = 0; i < first.rows.size(); ++i) {
      INFO("row " << i << " at z = " << first.at(i, "z") << ", state " << first.state[i]);
      CHECK(first.at(i, "slipMagnitude") == 0.0);
      if (first.state[i] == "tip") continue;
      CHECK(first.state[i] == "stick");
      const double sigmaN = kHorizontalGrad * first.at(i, "z") - s * n * n;
      CHECK(first.at(i, "sigmaN") == Approx(sigmaN).margin(1e-6 * s));
      CHECK(first.at(i, "tauMagnitude") == Approx(s * n * t).margin(1e-6 * s));
      ++checked;
    }
    CHECK(checked >= 30);
  }

  {
    // Every node sticks before slip starts; then the slipping area and the slip grow with the load.
    int start = -1;
    for (int k = 0; k < kSteps && start < 0; ++k)
      if (std::count(steps[k].state.begin(), steps[k].state.end(), "slip") > 0) start = k;
    // The cohesion holds the surface until |σ_yy| (0.433 − 0.6·0.25) > 2 MPa, t > 1.57.
    REQUIRE(start == 1);
    for (int k = 0; k < start; ++k)
      for (std::size_t i = 0; i < steps[k].rows.size(); ++i) {
        CHECK(steps[k].at(i, "slipMagnitude") == 0.0);
        CHECK(steps[k].state[i] != "slip");
      }
    for (int k = start; k + 1 < kSteps; ++k) {
      const Table& a = steps[k];
      const Table& b = steps[k + 1];
      CHECK(std::count(b.state.begin(), b.state.end(), "slip") >=
            std::count(a.state.begin(), a.state.end(), "slip"));
      int growing = 0;
      for (std::size_t i = 0; i < a.rows.size(); ++i) {
        REQUIRE(b.at(i, "x") == a.at(i, "x"));
        REQUIRE(b.at(i, "z") == a.at(i, "z"));
        if (a.at(i, "slipMagnitude") == 0.0) continue;
        INFO("step " << k + 2 << ", row " << i << " at z = " << a.at(i, "z"));
        // Each further 0.3 m of shortening adds more than 1 cm of slip at every node that
        // slipped already (measured: at least 1.35 cm); 1 mm is the margin asserted.
        const auto sa = slipVector(a, i), sb = slipVector(b, i);
        double along = 0;
        for (int d = 0; d < 3; ++d) along += (sb[d] - sa[d]) * strike[d];
        CHECK(along > 1e-3);
        CHECK(b.at(i, "slipMagnitude") > a.at(i, "slipMagnitude"));
        ++growing;
      }
      CHECK(growing > 0);
    }
    // By the last step the slip has reached below mid-depth (slip front at 800 m here).
    double deepest = 0;
    for (std::size_t i = 0; i < last.rows.size(); ++i)
      if (last.state[i] == "slip") deepest = std::min(deepest, last.at(i, "z"));
    CHECK(deepest <= -500);
  }

  {
    // Coulomb with cohesion node by node, the slip horizontal, along strike and left-lateral.
    // The fault is vertical with n_Γ pointing west-north-west, so Ω⁺ is its east side and
    // the slip [[u]] = u(east) − u(west). North-south shortening moves the east side
    // north-north-east along the fault relative to the west side (a left-lateral,
    // sinistral fault): slip · strike > 0.
    REQUIRE(last.comments.size() >= 2);
    CHECK(last.comments[1].rfind("# frame n (-0.8660254038 0.5 0) ", 0) == 0);
    int slipping = 0;
    double sumZ = 0, sumSlip = 0;
    for (std::size_t i = 0; i < last.rows.size(); ++i) {
      if (last.state[i] == "tip") continue;
      INFO("row " << i << " at (" << last.at(i, "x") << ", " << last.at(i, "y") << ", "
                  << last.at(i, "z") << "), state " << last.state[i]);
      const double sigmaN = last.at(i, "sigmaN");
      REQUIRE(sigmaN < 0);
      const double bound = kCohesion - kMu * sigmaN;
      const double tau = norm2(last.at(i, "tau1"), last.at(i, "tau2"));
      // The solver stops at ‖D‖ ≤ 1e-10 ‖Σ‖ and the table has ten digits: 1e-7 of the bound.
      if (last.state[i] == "stick") {
        CHECK(tau <= bound * (1 + 1e-7));
        continue;
      }
      REQUIRE(last.state[i] == "slip");
      ++slipping;
      CHECK(tau == Approx(bound).epsilon(1e-7));
      const auto s = slipVector(last, i);
      const double magnitude = last.at(i, "slipMagnitude");
      REQUIRE(magnitude > 0);
      const double along = s[0] * strike[0] + s[1] * strike[1] + s[2] * strike[2];
      CHECK(along > 0);
      // Mostly horizontal: the vertical part is largest next to the tip lines at the
      // surface (measured 13 % of |slip| there), 2 % of the total.
      CHECK(std::abs(s[2]) <= 0.25 * magnitude);
      sumZ += std::abs(s[2]);
      sumSlip += magnitude;
      // The step's slip increment is opposite to τ (docs/method.md, sign conventions; measured
      // cosine −1 to 1e-15; the accumulated slip turns by up to 3.4° over the steps).
      const double b1 = last.at(i, "slipIncrement1"), b2 = last.at(i, "slipIncrement2");
      REQUIRE(norm2(b1, b2) > 0);
      const double cosine =
          (b1 * last.at(i, "tau1") + b2 * last.at(i, "tau2")) / (norm2(b1, b2) * tau);
      CHECK(cosine == Approx(-1).margin(1e-9));
    }
    REQUIRE(slipping >= 20);
    CHECK(sumZ <= 0.05 * sumSlip);
  }

  {
    // With gravity the normal stress and the resistance grow with depth, the slip shrinks with it.
    // Per depth level (the extruded mesh has its fault nodes on horizontal rows): the mean
    // σ_n of its non-tip nodes and the largest slip.
    std::map<double, std::pair<double, int>> sigma;  // z → (sum σ_n, count)
    std::map<double, double> slip;                   // z → max |slip|
    for (std::size_t i = 0; i < last.rows.size(); ++i) {
      const double z = last.at(i, "z");
      slip[z] = std::max(slip[z], last.at(i, "slipMagnitude"));
      if (last.state[i] == "tip") continue;
      sigma[z].first += last.at(i, "sigmaN");
      ++sigma[z].second;
    }
    REQUIRE(sigma.size() == 6);  // five layers
    bool bottom = true;
    double previousSigma = 0, previousSlip = 0, previousZ = 0;
    for (const auto& [z, sum] : sigma) {  // from the bottom up
      INFO("z = " << z);
      const double meanSigma = sum.first / sum.second;
      if (!bottom) {
        // σ_n rises (less compression) from one level to the next up by about k0 ρ g Δz.
        CHECK(meanSigma > previousSigma);
        CHECK(meanSigma - previousSigma == Approx(kHorizontalGrad * (z - previousZ)).epsilon(0.1));
        CHECK(slip[z] >= previousSlip);
      }
      bottom = false;
      previousSigma = meanSigma;
      previousSlip = slip[z];
      previousZ = z;
    }
    // The surface slips most; the bottom row lies on the roller patch, whose jump is held.
    CHECK(slip.rbegin()->second > 0.1);
    CHECK(slip.begin()->second == 0.0);
  }
}
