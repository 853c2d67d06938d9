// The adaptive embedded Runge–Kutta integrator (EmbeddedRungeKutta.hpp) on problems with exact
// solutions: accuracy at the requested tolerance, the observed order of both pairs, landing
// on t1 exactly, the work counted (FSAL), rejections on a fast transient, and failures that
// are reported instead of looping.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "friction/time/EmbeddedRungeKutta.hpp"

using namespace friction;

namespace {

RungeKuttaSettings tolerances(double rtol, double atol,
                              RungeKuttaScheme scheme = RungeKuttaScheme::dormandPrince54) {
  RungeKuttaSettings s;
  s.scheme = scheme;
  s.relTol = Eigen::VectorXd::Constant(1, rtol);
  s.absTol = Eigen::VectorXd::Constant(1, atol);
  return s;
}

// y_i' = −λ_i y_i, y_i(0) = 1.
const Eigen::Vector3d kRates(0.5, 1.0, 2.0);
bool decay(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  dydt = -kRates.cwiseProduct(y);
  return true;
}

// x'' = −ω² x as (x, x'), x(0) = 1, x'(0) = 0: x = cos ωt.
constexpr double kOmega = 2.0;
bool oscillator(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  dydt(0) = y(1);
  dydt(1) = -kOmega * kOmega * y(0);
  return true;
}
Eigen::VectorXd oscillatorExact(double t) {
  Eigen::VectorXd y(2);
  y << std::cos(kOmega * t), -kOmega * std::sin(kOmega * t);
  return y;
}

// Global error of the oscillator at t = 2 with fixed steps h.
double fixedStepError(RungeKuttaScheme scheme, double h) {
  RungeKuttaSettings s = tolerances(1e-6, 1e-9, scheme);
  s.fixedStep = h;
  EmbeddedRungeKutta rk(oscillator, s);
  Eigen::VectorXd y = oscillatorExact(0);
  const IntegrationReport r = rk.integrate(0, 2, y);
  REQUIRE(r.status == IntegrationStatus::reachedEnd);
  return (y - oscillatorExact(2)).cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("EmbeddedRungeKutta: exponential decay within the requested tolerance", "[unit][time]") {
  for (auto scheme : {RungeKuttaScheme::dormandPrince54, RungeKuttaScheme::bogackiShampine32}) {
    for (double rtol : {1e-4, 1e-7, 1e-10}) {
      EmbeddedRungeKutta rk(decay, tolerances(rtol, 1e-14, scheme));
      Eigen::VectorXd y = Eigen::VectorXd::Ones(3);
      const IntegrationReport r = rk.integrate(0, 5, y);
      REQUIRE(r.status == IntegrationStatus::reachedEnd);
      REQUIRE(r.t == 5);
      // Each step's error is held below rtol |y| (the estimate is that of the embedded,
      // lower-order solution: the propagated one is more accurate still). Decay damps the
      // absolute errors of earlier steps but not the relative ones, which add up over the
      // steps: measured 0.7 rtol (DP, ≤ 340 steps) and 8.5 rtol (BS, ≤ 8 000 steps) on the
      // fastest component (e^−10 at t = 5); the bound 20 rtol holds for every rtol here.
      for (int i = 0; i < 3; ++i) {
        const double exact = std::exp(-kRates(i) * 5);
        CHECK(std::abs(y(i) - exact) <= 20 * rtol * exact);
      }
      CHECK(r.work.acceptedSteps > 0);
    }
  }
}

TEST_CASE("EmbeddedRungeKutta: harmonic oscillator, error proportional to the tolerance",
          "[unit][time]") {
  // Five periods. The oscillator does not damp errors: they add up over the steps, so the
  // global error is bounded by a multiple of rtol (50 × here), and a 100 times smaller tolerance
  // must give a markedly smaller error (> 20 times: with local extrapolation the error per unit
  // time is proportional to the tolerance, not to its 4/5th power).
  const double t1 = 5 * 2 * M_PI / kOmega;
  std::vector<double> errors;
  for (double rtol : {1e-6, 1e-8}) {
    EmbeddedRungeKutta rk(oscillator, tolerances(rtol, rtol));
    Eigen::VectorXd y = oscillatorExact(0);
    const IntegrationReport r = rk.integrate(0, t1, y);
    REQUIRE(r.status == IntegrationStatus::reachedEnd);
    const double e = (y - oscillatorExact(t1)).cwiseAbs().maxCoeff();
    CHECK(e <= 50 * rtol * kOmega);
    errors.push_back(e);
  }
  CHECK(errors[1] < errors[0] / 20);
}

TEST_CASE("EmbeddedRungeKutta: observed orders 5 and 3 with fixed steps", "[unit][time]") {
  // Halving h divides the global error by 2^p. The least-squares slope of log₂ e against
  // log₂ h over h = 0.1 … 0.0125 is within 0.25 of p: the errors (3.6e-7 … 1.6e-11 for DP,
  // 1.7e-3 … 3.9e-6 for BS) are far above rounding, and the single ratios wander by ±0.35
  // around p (the error at t = 2 is a phase error whose constant oscillates), which the fit
  // over four steps smooths (measured 4.84 and 2.93).
  struct Case {
    RungeKuttaScheme scheme;
    int order;
  };
  for (const Case c :
       {Case{RungeKuttaScheme::dormandPrince54, 5}, Case{RungeKuttaScheme::bogackiShampine32, 3}}) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int m = 4;
    for (int i = 0; i < m; ++i) {
      const double x = std::log2(0.1 / (1 << i)),
                   e = std::log2(fixedStepError(c.scheme, 0.1 / (1 << i)));
      sx += x;
      sy += e;
      sxx += x * x;
      sxy += x * e;
    }
    const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    CHECK(slope == Approx(c.order).margin(0.25));
  }
}

TEST_CASE("EmbeddedRungeKutta: lands on t1 exactly and continues across calls", "[unit][time]") {
  EmbeddedRungeKutta whole(oscillator, tolerances(1e-9, 1e-12));
  Eigen::VectorXd yWhole = oscillatorExact(0);
  REQUIRE(whole.integrate(0, 3, yWhole).status == IntegrationStatus::reachedEnd);

  // Output times that are no multiple of any step: every call ends on its t1 to the bit,
  // only the first evaluates F at its start (the others reuse it: first same as last).
  EmbeddedRungeKutta piecewise(oscillator, tolerances(1e-9, 1e-12));
  Eigen::VectorXd y = oscillatorExact(0);
  double t = 0;
  for (int i = 1; i <= 30; ++i) {
    const double tNext = 0.1 * i;
    const IntegrationReport r = piecewise.integrate(t, tNext, y);
    REQUIRE(r.status == IntegrationStatus::reachedEnd);
    REQUIRE(r.t == tNext);
    t = tNext;
  }
  const long perStep = 6;  // Dormand–Prince: 7 stages, the first reused
  const RungeKuttaCounters& w = piecewise.counters();
  CHECK(w.evaluations ==
        1 + 1 /* the starting step's trial */ + perStep * (w.acceptedSteps + w.rejectedSteps));
  // The same accuracy as one call over the whole interval.
  CHECK((y - oscillatorExact(3)).cwiseAbs().maxCoeff() <= 1e-7);
  CHECK((yWhole - oscillatorExact(3)).cwiseAbs().maxCoeff() <= 1e-7);
  // The short calls cost at most two extra steps per output time (an interval holds a whole
  // number of steps, and the controller's step carries over): measured 201 against 170.
  CHECK(w.acceptedSteps <= whole.counters().acceptedSteps + 60);
}

TEST_CASE("EmbeddedRungeKutta: a fast transient rejects steps and is still accurate",
          "[unit][time]") {
  // y' = −λ (y − cos t), y(0) = 0, λ = 50: y approaches cos t within ~1/λ, after which an
  // explicit method's step is limited by stability (h λ ≲ 3.3 for Dormand–Prince); an initial
  // step of 1 is far too long, so the controller must reject before it finds the right size.
  const double lambda = 50;
  auto rhs = [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt(0) = -lambda * (y(0) - std::cos(t));
    return true;
  };
  auto exact = [&](double t) {
    const double l2 = lambda * lambda;
    return (l2 * std::cos(t) + lambda * std::sin(t)) / (l2 + 1) -
           l2 / (l2 + 1) * std::exp(-lambda * t);
  };
  RungeKuttaSettings s = tolerances(1e-8, 1e-10);
  s.initialStep = 1;
  EmbeddedRungeKutta rk(rhs, s);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(1);
  const IntegrationReport r = rk.integrate(0, 4, y);
  REQUIRE(r.status == IntegrationStatus::reachedEnd);
  CHECK(r.work.rejectedSteps > 0);
  CHECK(r.work.failedEvaluations == 0);
  CHECK(r.work.evaluations == 1 + 6 * (r.work.acceptedSteps + r.work.rejectedSteps));
  CHECK(std::abs(y(0) - exact(4)) <= 1e-7);
}

TEST_CASE("EmbeddedRungeKutta: a right-hand side that fails is reported, never looped on",
          "[unit][time]") {
  RungeKuttaSettings s = tolerances(1e-8, 1e-10);
  SECTION("always fails: nothing done") {
    EmbeddedRungeKutta rk([](double, const Eigen::VectorXd&, Eigen::VectorXd&) { return false; },
                          s);
    Eigen::VectorXd y = Eigen::VectorXd::Ones(2);
    const IntegrationReport r = rk.integrate(0, 1, y);
    CHECK(r.status == IntegrationStatus::initialEvaluationFailed);
    CHECK(!r.ok());
    CHECK(r.work.evaluations == 1);
    CHECK(r.t == 0);
    CHECK(y == Eigen::VectorXd::Ones(2));
  }
  SECTION("fails beyond t = 0.5 (throws): halved down to the minimum step, stops there") {
    auto rhs = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
      if (t > 0.5) throw RightHandSideFailure("no slip rate");
      dydt = -y;
      return true;
    };
    EmbeddedRungeKutta rk(rhs, s);
    Eigen::VectorXd y = Eigen::VectorXd::Ones(1);
    const IntegrationReport r = rk.integrate(0, 1, y);
    CHECK(r.status == IntegrationStatus::stepTooSmall);
    CHECK(r.t <= 0.5);
    CHECK(r.t > 0.5 - 1e-12);  // it got as close as the minimum step allows
    CHECK(y(0) == Approx(std::exp(-r.t)).epsilon(1e-7));
    CHECK(r.work.rejectedSteps > 0);
    CHECK(r.work.failedEvaluations > 0);
    CHECK(r.work.rejectedSteps < 200);  // halvings from h ~ 0.1 to 64 ε: ~50 per approach
  }
  SECTION("non-finite derivatives count as failures") {
    auto rhs = [](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) {
      dydt(0) = t > 0.25 ? std::nan("") : 1.0;
      return true;
    };
    EmbeddedRungeKutta rk(rhs, s);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(1);
    const IntegrationReport r = rk.integrate(0, 1, y);
    CHECK(r.status == IntegrationStatus::stepTooSmall);
    CHECK(y.allFinite());
  }
  SECTION("other exceptions propagate (a stop request must not be taken for a bad step)") {
    auto rhs = [](double, const Eigen::VectorXd&, Eigen::VectorXd&) -> bool {
      throw std::logic_error("bug");
    };
    EmbeddedRungeKutta rk(rhs, s);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(1);
    CHECK_THROWS_AS(rk.integrate(0, 1, y), std::logic_error);
  }
  SECTION("maxSteps") {
    s.maxSteps = 5;
    EmbeddedRungeKutta rk(oscillator, s);
    Eigen::VectorXd y = oscillatorExact(0);
    const IntegrationReport r = rk.integrate(0, 100, y);
    CHECK(r.status == IntegrationStatus::maxSteps);
    CHECK(r.work.acceptedSteps + r.work.rejectedSteps == 5);
  }
}

TEST_CASE("EmbeddedRungeKutta: the observer's dense output and a stop at an event",
          "[unit][time]") {
  EmbeddedRungeKutta rk(oscillator, tolerances(1e-10, 1e-12));
  Eigen::VectorXd y = oscillatorExact(0), yi;
  double crossing = -1, maxInterpolationError = 0;
  int steps = 0;
  auto observer = [&](const AcceptedStep& s) {
    ++steps;
    s.interpolate(s.t0, yi);
    REQUIRE(yi == s.y0);
    s.interpolate(0.5 * (s.t0 + s.t1), yi);
    maxInterpolationError = std::max(
        maxInterpolationError, (yi - oscillatorExact(0.5 * (s.t0 + s.t1))).cwiseAbs().maxCoeff());
    if (s.y0(0) > 0 && s.y1(0) <= 0) {  // cos 2t falls through 0 at t = π/4
      double lo = s.t0, hi = s.t1;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        s.interpolate(mid, yi);
        (yi(0) > 0 ? lo : hi) = mid;
      }
      crossing = lo;
      return false;
    }
    return true;
  };
  const IntegrationReport r = rk.integrate(0, 10, y, observer);
  REQUIRE(r.status == IntegrationStatus::stoppedByObserver);
  CHECK(r.t > M_PI / 4);
  CHECK(r.t < 10);
  CHECK(r.work.acceptedSteps == steps);
  // Cubic Hermite: error ~ h⁴ max|x''''|/384 with the steps this tolerance takes (h ~ 0.05).
  CHECK(maxInterpolationError < 1e-7);
  CHECK(crossing == Approx(M_PI / 4).margin(1e-7));
}

TEST_CASE("EmbeddedRungeKutta: invalid settings are named", "[unit][time]") {
  RungeKuttaSettings s;
  s.relTol = Eigen::VectorXd::Constant(1, -1);
  CHECK_THAT(EmbeddedRungeKutta::invalid(s), Catch::Contains("relTol"));
  s = RungeKuttaSettings();
  s.safety = 1.5;
  CHECK_THAT(EmbeddedRungeKutta::invalid(s), Catch::Contains("safety"));
  CHECK_THROWS_AS(EmbeddedRungeKutta(decay, s), std::invalid_argument);
  CHECK(EmbeddedRungeKutta::invalid(RungeKuttaSettings()).empty());
}
