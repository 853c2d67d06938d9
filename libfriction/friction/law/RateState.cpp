// RateState (RateState.hpp): the regularised rate-and-state law at one node and the solve for
// its slip rate. Every quantity that spans hundreds of decades (e^{ψ/a}, sinh(u/a)) is carried
// in logarithms, so that no finite input overflows on the way to a finite answer.
#include "friction/law/RateState.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace friction {

namespace {

constexpr double kLn2 = 0.69314718055994530942;

/// asinh(e^s) without forming e^s where it would overflow or lose asinh's linear regime:
/// asinh(x) = ln 2x + 1/(4x²) − … (the tail below 1e-18 relative for x > e^20) and
/// asinh(x) = x − x³/6 + … (x³/6 below 1e-18 relative for x < e^−20).
double asinhOfExp(double s) {
  if (s > 20) return s + kLn2;
  if (s < -20) return std::exp(s);
  return std::asinh(std::exp(s));
}

/// ln sinh(x) for x ≥ 0 (−inf at 0).
double lnSinh(double x) {
  if (x > 20) return x - kLn2 + std::log1p(-std::exp(-2 * x));
  return std::log(std::sinh(x));
}

/// ln cosh(x) for x ≥ 0.
double lnCosh(double x) { return x - kLn2 + std::log1p(std::exp(-2 * x)); }

/// X/√(1 + X²) with X = e^s: the factor the regularisation puts on ∂f/∂ln V and ∂f/∂ψ.
double saturation(double s) {
  if (s > 0) return 1 / std::sqrt(1 + std::exp(-2 * s));
  const double X = std::exp(s);
  return X / std::sqrt(1 + X * X);
}

}  // namespace

const char* toString(SlipRateStatus status) {
  switch (status) {
    case SlipRateStatus::converged:
      return "converged";
    case SlipRateStatus::invalidInput:
      return "invalidInput";
    case SlipRateStatus::overflow:
      return "overflow";
    case SlipRateStatus::maxIterations:
      return "maxIterations";
  }
  return "unknown";
}

bool RateState::valid() const {
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  return positive(a) && positive(b) && positive(L) && std::isfinite(f0) && positive(V0) &&
         positive(sigmaBar) && std::isfinite(eta) && eta >= 0;
}

std::string RateState::invalid() const {
  if (valid()) return "";
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  std::ostringstream os;
  if (!positive(a))
    os << "a = " << a << ": expected a finite number > 0";
  else if (!positive(b))
    os << "b = " << b << ": expected a finite number > 0";
  else if (!positive(L))
    os << "L = " << L << ": expected a finite length > 0 [m]";
  else if (!std::isfinite(f0))
    os << "f0 = " << f0 << ": expected a finite number";
  else if (!positive(V0))
    os << "V0 = " << V0 << ": expected a finite slip rate > 0 [m/s]";
  else if (!positive(sigmaBar))
    os << "sigmaBar = " << sigmaBar
       << ": expected a finite effective normal compression > 0 [Pa] (the fault is in tension)";
  else if (!(std::isfinite(eta) && eta >= 0))
    os << "eta = " << eta << ": expected a finite radiation damping >= 0 [Pa s/m]";
  return os.str();
}

// Below, s = ln X with X = (|V|/2V₀) e^{ψ/a}, the argument of asinh, formed as a sum.
double RateState::friction(double V, double psi) const {
  if (V == 0) return 0;
  const double f = a * asinhOfExp(std::log(std::abs(V) / (2 * V0)) + psi / a);
  return V > 0 ? f : -f;
}

double RateState::frictionDerivativeV(double V, double psi) const {
  if (V == 0) return a * std::exp(psi / a - std::log(2 * V0));
  const double s = std::log(std::abs(V) / (2 * V0)) + psi / a;
  return a * saturation(s) / std::abs(V);
}

double RateState::frictionDerivativePsi(double V, double psi) const {
  if (V == 0) return 0;
  const double r = saturation(std::log(std::abs(V) / (2 * V0)) + psi / a);
  return V > 0 ? r : -r;
}

double RateState::stateRate(double V, double psi) const {
  if (evolution == StateEvolution::slip) {
    if (V == 0) return 0;  // |V| ln|V| → 0
    return -(std::abs(V) / L) * (psi - steadyState(V));
  }
  // (b V₀/L) e^{(f₀−ψ)/b} as one exponential: its two factors may over- and underflow.
  return std::exp(std::log(b * V0 / L) + (f0 - psi) / b) - b * std::abs(V) / L;
}

double RateState::steadyState(double V) const { return f0 - b * std::log(std::abs(V) / V0); }

double RateState::steadyStateFriction(double V) const {
  const double s = (1 - b / a) * std::log(std::abs(V) / V0) + f0 / a - kLn2;
  const double f = a * asinhOfExp(s);
  return V < 0 ? -f : f;
}

std::optional<double> RateState::steadyStateSlipRate(double tau) const {
  if (a == b) return std::nullopt;
  const double mu = std::abs(tau) / sigmaBar;
  const double V = V0 * std::exp((a * (lnSinh(mu / a) + kLn2) - f0) / (a - b));
  if (!std::isfinite(V)) return std::nullopt;
  return tau < 0 ? -V : V;
}

std::optional<double> RateState::stateFor(double V, double phi) const {
  const double s = phi - eta * V;
  if (!std::isfinite(V) || !std::isfinite(s) || V == 0 || !(s * V > 0)) return std::nullopt;
  return a * (std::log(2 * V0 / std::abs(V)) + lnSinh(std::abs(s) / (a * sigmaBar)));
}

SlipRate RateState::slipRate(double phi, double psi) const {
  SlipRate r;
  r.V = std::numeric_limits<double>::quiet_NaN();
  // valid(), not invalid(): this runs per node and right-hand side (a message's stream cost a
  // fifth of a BP3 run).
  if (!std::isfinite(phi) || !std::isfinite(psi) || !valid()) return r;
  if (phi == 0) {
    r.V = 0;
    r.status = SlipRateStatus::converged;
    return r;
  }
  const double target = std::abs(phi);
  // V(u) = 2V₀ e^{−ψ/a} sinh(u/a) and dV/du = (2V₀/a) e^{−ψ/a} cosh(u/a), in logarithms.
  const double lnC = std::log(2 * V0) - psi / a;
  auto rate = [&](double u) { return std::exp(lnC + lnSinh(u / a)); };
  auto rateDerivative = [&](double u) { return std::exp(lnC + lnCosh(u / a)) / a; };

  // The root u* lies in (0, hi]: σ̄u ≤ |φ| and ηV ≤ |φ| there. h(hi) ≥ 0, and h convex and
  // increasing, so Newton from hi decreases monotonically to u* without overshooting.
  double lo = 0, hi = target / sigmaBar;
  if (eta > 0) hi = std::min(hi, friction(target / eta, psi));
  double u = hi, V = rate(u);
  if (!std::isfinite(V)) {
    r.status = SlipRateStatus::overflow;
    return r;
  }
  r.status = SlipRateStatus::maxIterations;
  for (r.iterations = 1; r.iterations <= 200; ++r.iterations) {
    const double h = sigmaBar * u + eta * V - target;
    if (h == 0) {
      r.status = SlipRateStatus::converged;
      break;
    }
    (h > 0 ? hi : lo) = u;
    double uNew = u - h / (sigmaBar + eta * rateDerivative(u));
    // Rounding, never the mathematics, can put the Newton iterate outside the bracket.
    if (!(uNew >= lo && uNew <= hi)) uNew = 0.5 * (lo + hi);
    const double VNew = rate(uNew);
    const bool done = std::abs(VNew - V) <= 1e-13 * VNew || hi - lo <= 4e-16 * hi;
    u = uNew;
    V = VNew;
    if (done) {
      r.status = SlipRateStatus::converged;
      break;
    }
  }
  if (r.converged()) r.V = phi > 0 ? V : -V;
  return r;
}

}  // namespace friction
