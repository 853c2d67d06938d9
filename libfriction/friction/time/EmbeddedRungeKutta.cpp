// EmbeddedRungeKutta (EmbeddedRungeKutta.hpp): the Butcher tableaux of the two pairs, the step
// loop with its error test and PI step-size controller, the starting step and the Hermite
// dense output.
#include "friction/time/EmbeddedRungeKutta.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace friction {

namespace {

/// An explicit pair, first same as last: a(s−1, ·) = b and c(s−1) = 1.
struct Tableau {
  int stages, order, embedded;
  std::vector<double> c;
  std::vector<std::vector<double>> a;  ///< a[i][j], j < i
  std::vector<double> b;               ///< weights of the solution (order `order`)
  std::vector<double> e;               ///< b − b̂, b̂ the weights of the embedded solution
};

// Dormand & Prince (1980), Table 2 ("RK5(4)7M"): the 5th-order solution is propagated.
const Tableau& dormandPrince() {
  static const Tableau t = [] {
    Tableau d;
    d.stages = 7;
    d.order = 5;
    d.embedded = 4;
    d.c = {0, 1. / 5, 3. / 10, 4. / 5, 8. / 9, 1, 1};
    d.a = {{},
           {1. / 5},
           {3. / 40, 9. / 40},
           {44. / 45, -56. / 15, 32. / 9},
           {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729},
           {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656},
           {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
    d.b = {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84, 0};
    const std::vector<double> bHat = {5179. / 57600,    0,           7571. / 16695, 393. / 640,
                                      -92097. / 339200, 187. / 2100, 1. / 40};
    for (int i = 0; i < d.stages; ++i) d.e.push_back(d.b[i] - bHat[i]);
    return d;
  }();
  return t;
}

// Bogacki & Shampine (1989): the 3rd-order solution is propagated.
const Tableau& bogackiShampine() {
  static const Tableau t = [] {
    Tableau d;
    d.stages = 4;
    d.order = 3;
    d.embedded = 2;
    d.c = {0, 1. / 2, 3. / 4, 1};
    d.a = {{}, {1. / 2}, {0, 3. / 4}, {2. / 9, 1. / 3, 4. / 9}};
    d.b = {2. / 9, 1. / 3, 4. / 9, 0};
    const std::vector<double> bHat = {7. / 24, 1. / 4, 1. / 3, 1. / 8};
    for (int i = 0; i < d.stages; ++i) d.e.push_back(d.b[i] - bHat[i]);
    return d;
  }();
  return t;
}

const Tableau& tableau(RungeKuttaScheme s) {
  return s == RungeKuttaScheme::dormandPrince54 ? dormandPrince() : bogackiShampine();
}

double component(const Eigen::VectorXd& v, Eigen::Index i) { return v.size() == 1 ? v(0) : v(i); }

void add(RungeKuttaCounters& to, const RungeKuttaCounters& w) {
  to.evaluations += w.evaluations;
  to.failedEvaluations += w.failedEvaluations;
  to.acceptedSteps += w.acceptedSteps;
  to.rejectedSteps += w.rejectedSteps;
}

}  // namespace

const char* toString(IntegrationStatus status) {
  switch (status) {
    case IntegrationStatus::reachedEnd:
      return "reachedEnd";
    case IntegrationStatus::stoppedByObserver:
      return "stoppedByObserver";
    case IntegrationStatus::stepTooSmall:
      return "stepTooSmall";
    case IntegrationStatus::initialEvaluationFailed:
      return "initialEvaluationFailed";
    case IntegrationStatus::maxSteps:
      return "maxSteps";
  }
  return "unknown";
}

void AcceptedStep::interpolate(double t, Eigen::VectorXd& y) const {
  const double h = t1 - t0, s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
  y = (2 * s3 - 3 * s2 + 1) * y0 + (-2 * s3 + 3 * s2) * y1 + (h * (s3 - 2 * s2 + s)) * dydt0 +
      (h * (s3 - s2)) * dydt1;
}

std::string EmbeddedRungeKutta::invalid(const RungeKuttaSettings& s) {
  std::ostringstream os;
  auto tolerances = [&](const Eigen::VectorXd& v, const char* name) {
    if (v.size() == 0)
      os << name << ": expected one value or one per component";
    else if (!v.allFinite() || (v.array() < 0).any())
      os << name << ": expected finite values >= 0";
    return os.tellp() == 0;
  };
  if (!tolerances(s.relTol, "relTol") || !tolerances(s.absTol, "absTol")) return os.str();
  if (s.relTol.size() > 1 && s.absTol.size() > 1 && s.relTol.size() != s.absTol.size())
    os << "relTol and absTol: " << s.relTol.size() << " and " << s.absTol.size()
       << " components, expected the same number (or one value)";
  else if (!(s.safety > 0 && s.safety <= 1))
    os << "safety = " << s.safety << ": expected (0, 1]";
  else if (!(s.minFactor > 0 && s.minFactor < 1))
    os << "minFactor = " << s.minFactor << ": expected (0, 1)";
  else if (!(s.maxFactor > 1 && std::isfinite(s.maxFactor)))
    os << "maxFactor = " << s.maxFactor << ": expected a finite number > 1";
  else if (!(s.initialStep >= 0 && std::isfinite(s.initialStep)))
    os << "initialStep = " << s.initialStep << ": expected a finite number >= 0";
  else if (!(s.maxStep > 0))
    os << "maxStep = " << s.maxStep << ": expected > 0";
  else if (!(s.minStep >= 0 && s.minStep < s.maxStep))
    os << "minStep = " << s.minStep << ": expected >= 0 and below maxStep";
  else if (!(s.maxSteps > 0))
    os << "maxSteps = " << s.maxSteps << ": expected > 0";
  else if (!(s.fixedStep >= 0 && std::isfinite(s.fixedStep)))
    os << "fixedStep = " << s.fixedStep << ": expected a finite number >= 0";
  return os.str();
}

EmbeddedRungeKutta::EmbeddedRungeKutta(RightHandSide rhs, RungeKuttaSettings settings)
    : rhs_(std::move(rhs)), settings_(std::move(settings)) {
  const std::string why = invalid(settings_);
  if (!why.empty()) throw std::invalid_argument("EmbeddedRungeKutta: " + why);
}

int EmbeddedRungeKutta::order() const { return tableau(settings_.scheme).order; }
int EmbeddedRungeKutta::embeddedOrder() const { return tableau(settings_.scheme).embedded; }

void EmbeddedRungeKutta::reset() { haveLast_ = false; }

bool EmbeddedRungeKutta::evaluate(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt,
                                  RungeKuttaCounters& work) {
  ++work.evaluations;
  dydt.resize(y.size());
  bool ok = false;
  try {
    ok = rhs_(t, y, dydt);
  } catch (const RightHandSideFailure&) {
    ok = false;
  }
  ok = ok && dydt.size() == y.size() && dydt.allFinite();
  if (!ok) ++work.failedEvaluations;
  return ok;
}

double EmbeddedRungeKutta::errorNorm(const Eigen::VectorXd& err, const Eigen::VectorXd& y0,
                                     const Eigen::VectorXd& y1) const {
  double maxRatio = 0, sumSquares = 0;
  for (Eigen::Index i = 0; i < err.size(); ++i) {
    const double scale =
        component(settings_.absTol, i) +
        component(settings_.relTol, i) * std::max(std::abs(y0(i)), std::abs(y1(i)));
    // A component with no tolerance at all (both 0 at y = 0) must be exact.
    const double r = err(i) == 0 ? 0.0
                     : scale > 0 ? std::abs(err(i)) / scale
                                 : std::numeric_limits<double>::infinity();
    maxRatio = std::max(maxRatio, r);
    sumSquares += r * r;
    if (std::isnan(r)) return r;
  }
  if (settings_.norm == ErrorNorm::max || err.size() == 0) return maxRatio;
  return std::sqrt(sumSquares / static_cast<double>(err.size()));
}

// Hairer, Nørsett & Wanner, Solving ODEs I, II.4: h such that an Euler step changes y by ~1 %
// of its tolerance-scaled size, refined by the second derivative estimated from one Euler step.
// [beyond] Where y or F is (near) zero Hairer's fallback 1e-6 assumes time of order one; here
// it is 1e-6 of the interval, so that a fault at rest over years does not start at a µs.
double EmbeddedRungeKutta::startingStep(double t0, double t1, const Eigen::VectorXd& y0,
                                        const Eigen::VectorXd& f0, RungeKuttaCounters& work) {
  const double span = t1 - t0, small = 1e-6 * span;
  const double d0 = errorNorm(y0, y0, y0), d1 = errorNorm(f0, y0, y0);
  double h0 = (d0 < 1e-5 || d1 < 1e-5 || !std::isfinite(d0 / d1)) ? small : 0.01 * d0 / d1;
  h0 = std::min({h0, span, settings_.maxStep});
  Eigen::VectorXd y1 = y0 + h0 * f0, f1;
  if (!evaluate(t0 + h0, y1, f1, work)) return 0.1 * h0;
  const double d2 = errorNorm(f1 - f0, y0, y0) / h0, d = std::max(d1, d2);
  const int p = tableau(settings_.scheme).order;
  const double h1 = d <= 1e-15 ? std::max(small, 1e-3 * h0) : std::pow(0.01 / d, 1.0 / (p + 1));
  return std::min({100 * h0, h1, settings_.maxStep});
}

IntegrationReport EmbeddedRungeKutta::integrate(double t0, double t1, Eigen::VectorXd& y,
                                                const StepObserver& observer) {
  const Tableau& T = tableau(settings_.scheme);
  const Eigen::Index n = y.size();
  if ((settings_.relTol.size() > 1 && settings_.relTol.size() != n) ||
      (settings_.absTol.size() > 1 && settings_.absTol.size() != n))
    throw std::invalid_argument(
        "EmbeddedRungeKutta: tolerances for " +
        std::to_string(std::max(settings_.relTol.size(), settings_.absTol.size())) +
        " components, the state has " + std::to_string(n));
  if (!(t1 >= t0)) throw std::invalid_argument("EmbeddedRungeKutta: t1 before t0");

  IntegrationReport report;
  report.t = t0;
  if (t1 == t0) return report;  // nothing to do, and the step size of the last call is kept
  RungeKuttaCounters& work = report.work;
  std::vector<Eigen::VectorXd> k(T.stages, Eigen::VectorXd(n));
  double h, errorPrevious;
  if (haveLast_ && lastT_ == t0 && lastY_.size() == n && lastY_ == y && lastStep_ > 0) {
    k[0] = lastF_;
    h = lastStep_;
    errorPrevious = lastError_;
  } else {
    haveLast_ = false;
    if (!evaluate(t0, y, k[0], work)) {
      report.status = IntegrationStatus::initialEvaluationFailed;
      add(total_, work);
      return report;
    }
    errorPrevious = 1e-4;
    h = settings_.initialStep > 0 ? settings_.initialStep : startingStep(t0, t1, y, k[0], work);
  }
  if (!(h > 0 && std::isfinite(h))) h = 1e-6 * (t1 - t0);  // F overflowed in startingStep
  const bool fixed = settings_.fixedStep > 0;
  if (fixed) h = settings_.fixedStep;

  // The controller's exponents: k = embedded order + 1 (the estimate is O(h^k)).
  const double kOrder = T.embedded + 1;
  const double alpha = settings_.piController ? 0.7 / kOrder : 1.0 / kOrder;
  const double beta = settings_.piController ? 0.4 / kOrder : 0.0;

  double t = t0;
  bool rejectedBefore = false;
  Eigen::VectorXd yStage(n), yNew(n), err(n);
  while (t < t1) {
    if (work.acceptedSteps + work.rejectedSteps >= settings_.maxSteps) {
      report.status = IntegrationStatus::maxSteps;
      break;
    }
    const double minStep = std::max(settings_.minStep, 64 * std::numeric_limits<double>::epsilon() *
                                                           std::max(std::abs(t), std::abs(t1)));
    h = std::min(h, settings_.maxStep);
    const double hWanted = h;
    // Land on t1 exactly; stretch by up to 1 %, and share what is left between two equal
    // steps when it is less than two, rather than leave a sliver of a last step.
    const bool last = t1 - t <= 1.01 * h;
    if (last)
      h = t1 - t;
    else if (!fixed && t1 - t < 2 * h)
      h = 0.5 * (t1 - t);
    const double tNew = last ? t1 : t + h;

    bool evaluated = true;
    for (int i = 1; i < T.stages && evaluated; ++i) {
      yStage = y;
      for (int j = 0; j < i; ++j)
        if (T.a[i][j] != 0) yStage += (h * T.a[i][j]) * k[j];
      evaluated = evaluate(i == T.stages - 1 ? tNew : t + T.c[i] * h, yStage, k[i], work);
    }
    double E = std::numeric_limits<double>::quiet_NaN();
    if (evaluated) {
      yNew = yStage;  // first same as last: the last stage's state is the solution
      err.setZero();
      for (int j = 0; j < T.stages; ++j)
        if (T.e[j] != 0) err += (h * T.e[j]) * k[j];
      E = fixed ? 0.0 : errorNorm(err, y, yNew);
      if (!yNew.allFinite()) E = std::numeric_limits<double>::quiet_NaN();
    }
    if (!(E <= 1)) {
      ++work.rejectedSteps;
      rejectedBefore = true;
      // A failed evaluation or a non-finite error says nothing of the step size: halve it.
      const double factor =
          std::isfinite(E) && evaluated
              ? std::max(settings_.minFactor, settings_.safety * std::pow(E, -1.0 / kOrder))
              : 0.5;
      h *= factor;
      if (fixed || h < minStep) {
        report.status = IntegrationStatus::stepTooSmall;
        break;
      }
      continue;
    }

    double factor =
        settings_.safety * std::pow(std::max(E, 1e-10), -alpha) * std::pow(errorPrevious, beta);
    factor = std::clamp(factor, settings_.minFactor, settings_.maxFactor);
    if (rejectedBefore) factor = std::min(factor, 1.0);
    double hNext = fixed ? settings_.fixedStep : h * factor;
    // A step shortened to land on t1 should not shrink the next call's first step.
    if (last && !fixed && factor >= 1) hNext = std::max(hNext, hWanted);
    errorPrevious = std::max(E, 1e-4);

    ++work.acceptedSteps;
    bool goOn = true;
    if (observer) goOn = observer(AcceptedStep{t, tNew, y, yNew, k[0], k[T.stages - 1], E});
    std::swap(y, yNew);
    std::swap(k[0], k[T.stages - 1]);
    t = tNew;
    h = hNext;
    rejectedBefore = false;
    if (!goOn) {
      report.status = IntegrationStatus::stoppedByObserver;
      break;
    }
  }
  report.t = t;
  report.nextStep = h;
  haveLast_ = true;
  lastT_ = t;
  lastY_ = y;
  lastF_ = k[0];
  lastStep_ = h;
  lastError_ = errorPrevious;
  add(total_, work);
  return report;
}

}  // namespace friction
