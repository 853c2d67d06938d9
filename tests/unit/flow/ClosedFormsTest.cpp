// Closed forms of METHOD.md §11 (flow/ClosedForms.hpp): E₁ against reference values, and each
// pressure form against its equation (finite differences of ∂p/∂t − α∇²p away from the
// source) and its source (the flux it injects), the BP6 form against the rate form under the
// mapping q₀/(βφ) = Q₀/S, and superposition of schedules (StepSchedule).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>

#include "friction/flow/ClosedForms.hpp"

using namespace friction;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Central second differences of a smooth function of size ~1 with step d lose ~eps/d² to
// round-off and gain ~d² f''''/12 of truncation; d = 1e-3 balances the two near 1e-7 relative.
// (f(x+d) − f(x−d))/2d likewise, d = 1e-5: truncation and round-off ~1e-10.
double secondDerivative(const std::function<double(double)>& f, double x, double d) {
  return (f(x + d) - 2.0 * f(x) + f(x - d)) / (d * d);
}
double derivative(const std::function<double(double)>& f, double x, double d) {
  return (f(x + d) - f(x - d)) / (2.0 * d);
}

}  // namespace

TEST_CASE("flow E1 matches reference values to full double precision", "[flow][closedForms]") {
  // Reference values: mpmath 1.3 (mp.dps = 30), rounded to 20 digits. Tolerance 4 ulp: the
  // implementation measured ≤ 2.2 ulp on 6000 points of [1e-12, 630] (ClosedForms.cpp).
  // (E₁(1) = 0.21938393439552027368; the value 0.21938393439552062 sometimes quoted is 12
  // ulp away and is not met.)
  struct Case {
    double x, e1;
  };
  const Case cases[] = {{1e-10, 22.448635265138923980},     {1e-3, 6.3315393641361493320},
                        {0.01, 4.0379295765381138318},      {0.1, 1.8229239584193906661},
                        {0.5, 0.55977359477616081175},      {0.999, 0.21975218202294454081},
                        {1.0, 0.21938393439552027368},      {1.001, 0.21901642252746885568},
                        {2.0, 0.048900510708061119567},     {5.0, 0.0011482955912753257973},
                        {10.0, 4.1569689296853242774e-6},   {50.0, 3.7832640295504590187e-24},
                        {100.0, 3.6835977616820321802e-46}, {700.0, 1.4065187662340329228e-307}};
  for (const Case& c : cases) {
    CAPTURE(c.x);
    const double e = exponentialIntegralE1(c.x);
    REQUIRE(std::abs(e - c.e1) <= 4.0 * std::numeric_limits<double>::epsilon() * c.e1);
  }
  REQUIRE(exponentialIntegralE1(0.0) == std::numeric_limits<double>::infinity());
  REQUIRE(exponentialIntegralE1(800.0) == 0.0);
  REQUIRE_THROWS_AS(exponentialIntegralE1(-1.0), std::domain_error);
  REQUIRE_THROWS_AS(exponentialIntegralE1(std::nan("")), std::domain_error);
  // Continuity across the switch from series to fraction at x = 1: E₁' = −e^{−x}/x.
  const double below = exponentialIntegralE1(std::nextafter(1.0, 0.0));
  const double above = exponentialIntegralE1(std::nextafter(1.0, 2.0));
  REQUIRE(std::abs(below - above) <= 1e-15);
}

TEST_CASE("flow step schedule values, integrals and step-ons", "[flow][closedForms]") {
  const StepSchedule s({1.0, 2.0, 4.0}, {3.0, -1.0, 0.0});
  REQUIRE(s.value(0.5) == 0.0);
  REQUIRE(s.value(1.0) == 3.0);  // right-continuous
  REQUIRE(s.valueBefore(1.0) == 0.0);
  REQUIRE(s.value(3.0) == -1.0);
  REQUIRE(s.valueBefore(4.0) == -1.0);
  REQUIRE(s.value(9.0) == 0.0);
  REQUIRE(s.integral(0.0, 10.0) == 3.0 - 2.0);
  REQUIRE(s.integral(1.5, 2.5) == 1.5 - 0.5);
  REQUIRE(s.integral(5.0, 6.0) == 0.0);
  const auto steps = s.steps();
  REQUIRE(steps.size() == 3);
  REQUIRE(steps[1].first == 2.0);
  REQUIRE(steps[1].second == -4.0);
  REQUIRE(s.changesIn(1.0, 1.5));
  REQUIRE(!s.changesIn(1.0 + 1e-9, 2.0));
  REQUIRE(StepSchedule::constant(2.0, 1.0).value(1.0) == 2.0);
  // Bad schedules name the entry.
  REQUIRE_THROWS_WITH(StepSchedule({1.0, 1.0}, {1.0, 2.0}, {"wells", 7}),
                      Catch::Contains("wells:7") && Catch::Contains("increase strictly"));
  REQUIRE_THROWS_WITH(StepSchedule({1.0}, {1.0, 2.0}), Catch::Contains("one value per time"));
  REQUIRE_THROWS_WITH(StepSchedule({}, {}), Catch::Contains("at least one"));
  REQUIRE_THROWS_WITH(StepSchedule({0.0}, {std::nan("")}), Catch::Contains("finite"));
}

TEST_CASE("flow 2D held-pressure form solves the diffusion equation", "[flow][closedForms]") {
  const double alpha = 0.3, dp = 2.0, s0 = 0.7;
  // Away from the source: ∂p/∂t = α ∂²p/∂s², at several (s, t).
  for (double s : {-1.3, 0.2, 1.0, 2.5})
    for (double t : {0.4, 1.0, 3.0}) {
      CAPTURE(s, t);
      const double pt =
          derivative([&](double x) { return heldPressure2d(s, s0, x, dp, alpha); }, t, 1e-5);
      const double pss =
          secondDerivative([&](double x) { return heldPressure2d(x, s0, t, dp, alpha); }, s, 1e-3);
      // Both sides are O(0.1–1); the differences are accurate to ~1e-7 (see above).
      REQUIRE(std::abs(pt - alpha * pss) <= 1e-6);
    }
  // The held value at the source, nothing before t = 0.
  REQUIRE(heldPressure2d(s0, s0, 1.0, dp, alpha) == dp);
  REQUIRE(heldPressure2d(s0 + 1.0, s0, 0.0, dp, alpha) == 0.0);
  // A schedule: on at 0, to 0 at t₁: afterwards the two step-ons cancel at the source.
  const StepSchedule on({0.0, 1.0}, {dp, 0.0});
  REQUIRE(heldPressure2d(s0, s0, 2.0, on, alpha) == 0.0);
  REQUIRE(heldPressure2d(s0 + 1.0, s0, 2.0, on, alpha) ==
          Approx(heldPressure2d(s0 + 1.0, s0, 2.0, dp, alpha) -
                 heldPressure2d(s0 + 1.0, s0, 1.0, dp, alpha))
              .epsilon(1e-15));
  REQUIRE_THROWS_AS(heldPressure2d(0.0, 0.0, 1.0, 1.0, 0.0), InputError);
}

TEST_CASE("flow 2D flux form (BP6) solves the diffusion equation and injects its flux",
          "[flow][closedForms]") {
  // BP6's parameters: α = 0.1 m²/s, β = 1e-8 1/Pa, φ = 0.1, q₀ = 1.25e-6 m/s, t_off = 100 d.
  const double alpha = 0.1, betaPhi = 1e-9, q0 = 1.25e-6, tOff = 100.0 * 86400.0;
  const auto p = [&](double s, double t) { return bp6Pressure2d(s, t, q0, betaPhi, alpha, tOff); };
  // Scale: q₀/(βφ√α)·√t ≈ 4e3·√t Pa, ~4 MPa at 10 days.
  for (double s : {-300.0, 50.0, 400.0, 1500.0})
    for (double t : {1e5, 5e6, 9e6, 2e7}) {  // before and after t_off
      CAPTURE(s, t);
      const double scale = std::abs(p(0.0, t));
      const double pt = derivative([&](double x) { return p(s, x); }, t, 1e-5 * t);
      const double pss = secondDerivative([&](double x) { return p(x, t); }, s, 1e-3 * 400.0);
      // Relative to p/t, the natural size of both terms: FD error ~1e-6 of it.
      REQUIRE(std::abs(pt - alpha * pss) <= 1e-5 * scale / t);
    }
  // Flux at the injection point, before t_off: −αβφ ∂p/∂s(0±) = ±q₀/2 (each side half).
  for (double t : {1e4, 1e6, 5e6}) {
    CAPTURE(t);
    const double d = 1e-6 * std::sqrt(alpha * t);
    // One-sided second-order differences from s = 0 (the kink): error O(d²/(αt)) ~1e-12.
    const double right = (-3.0 * p(0.0, t) + 4.0 * p(d, t) - p(2.0 * d, t)) / (2.0 * d);
    const double left = (3.0 * p(0.0, t) - 4.0 * p(-d, t) + p(-2.0 * d, t)) / (2.0 * d);
    REQUIRE(-alpha * betaPhi * right == Approx(q0 / 2).epsilon(1e-6));
    REQUIRE(-alpha * betaPhi * left == Approx(-q0 / 2).epsilon(1e-6));
  }
  // The same form in this library's terms: S = βφ, Q₀ = q₀, a schedule on at 0, off at t_off.
  const StepSchedule rate({0.0, tOff}, {q0, 0.0});
  for (double s : {0.0, 300.0})
    for (double t : {1e6, 2e7}) {
      CAPTURE(s, t);
      REQUIRE(ratePressure2d(s, 0.0, t, rate, betaPhi, alpha) == Approx(p(s, t)).epsilon(1e-14));
    }
  // Long after shut-in the pressure decays back (towards 0).
  REQUIRE(p(0.0, 1e9) < 0.1 * p(0.0, tOff));
  REQUIRE(p(0.0, -1.0) == 0.0);
}

TEST_CASE("flow 3D rate form solves the radial diffusion equation and injects Q",
          "[flow][closedForms]") {
  const double Q = 0.02, kappa = 3e-9, alpha = 0.05;
  const auto p = [&](double r, double t) { return ratePressure3d(r, t, Q, kappa, alpha); };
  for (double r : {0.5, 2.0, 10.0})
    for (double t : {10.0, 100.0, 1000.0}) {
      CAPTURE(r, t);
      const double scale = Q / (4.0 * kPi * kappa);
      const double pt = derivative([&](double x) { return p(r, x); }, t, 1e-5 * t);
      // The length over which p varies: r, √(αt), or 2αt/r where e^{−r²/4αt} dominates; a
      // step of 1e-4 of it keeps truncation (~1e-8) above round-off (~1e-8).
      const double d = 1e-4 * std::min({r, std::sqrt(alpha * t), 2.0 * alpha * t / r});
      const double prr = secondDerivative([&](double x) { return p(x, t); }, r, d);
      const double pr = derivative([&](double x) { return p(x, t); }, r, 0.1 * d);
      // Near the well p_rr and p_r/r (~scale/r²) nearly cancel and dwarf p_t: the bound is
      // relative to the largest term; FD error ~1e-7 of it (see secondDerivative).
      const double size = std::max(std::abs(pt), alpha * std::max(std::abs(prr), std::abs(pr / r)));
      REQUIRE(std::abs(pt - alpha * (prr + pr / r)) <= 1e-6 * size);
      REQUIRE(scale > 0.0);
    }
  // Flux through a small circle: −2πr κ ∂p/∂r = Q e^{−r²/4αt} → Q.
  const double t = 100.0, r = 1e-4;
  const double pr = derivative([&](double x) { return p(x, t); }, r, 1e-3 * r);
  REQUIRE(-2.0 * kPi * r * kappa * pr == Approx(Q).epsilon(1e-6));
  // Superposition: a shut-in at t₁ is the step-on minus a delayed one.
  const StepSchedule shutIn({0.0, 50.0}, {Q, 0.0});
  REQUIRE(ratePressure3d(2.0, 80.0, shutIn, kappa, alpha) ==
          Approx(p(2.0, 80.0) - p(2.0, 30.0)).epsilon(1e-14));
  REQUIRE(p(2.0, 0.0) == 0.0);
  REQUIRE_THROWS_WITH(ratePressure3d(1.0, 1.0, Q, -1.0, alpha), Catch::Contains("kappa"));
}
