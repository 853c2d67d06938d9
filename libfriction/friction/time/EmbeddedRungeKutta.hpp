// EmbeddedRungeKutta: an adaptive explicit Runge–Kutta integrator with an embedded error
// estimate, for dy/dt = F(t, y) on Eigen vectors — the time stepping of the quasi-dynamic
// rate-and-state integration (../shared/METHOD.md §12: steps from milliseconds in events to
// years between them) [beyond]. Nothing in it knows about faults.
//
// Pairs (both first-same-as-last: the last stage is F at the new state, so an accepted step
// costs s − 1 evaluations; both advance with the higher order, "local extrapolation"):
//   dormandPrince54     Dormand & Prince (1980), order 5 with an order-4 estimate, 7 stages
//   bogackiShampine32   Bogacki & Shampine (1989), order 3 with an order-2 estimate, 4 stages
//
// Error control: with sc_i = atol_i + rtol_i max(|y_i|, |y_new,i|), the step's error is
//   E = max_i |err_i| / sc_i            (ErrorNorm::max, the default)
//   E = sqrt(mean_i (|err_i| / sc_i)²)   (ErrorNorm::rms)
// and the step is accepted when E ≤ 1. The default is the max norm because on a fault the
// error that matters is local: a nucleating patch of a few nodes among thousands would be
// diluted by an RMS over all of them.
//
// Step size (k = the embedded order + 1): h_new = h · clamp(safety · E^(−α) · E_prev^β,
// minFactor, maxFactor) with the PI controller of Gustafsson (1991) / Söderlind,
// α = 0.7/k, β = 0.4/k (β = 0, α = 1/k: the elementary controller, piController false);
// after a rejection the step is not allowed to grow on the next accepted step. A right-hand
// side that cannot be evaluated (returns false, throws RightHandSideFailure, or gives a
// non-finite derivative) or a non-finite error rejects the step and halves it. Below the
// minimum step the integration stops and says so (status stepTooSmall): it never loops.
//
// Output: integrate(t0, t1, y) lands exactly on t1 (the last step is shortened to reach it);
// an observer sees every accepted step with a dense-output interpolant (cubic Hermite on the
// step's end values and derivatives, which FSAL gives for free: third order, C¹) and can stop
// the integration after that step (events). The integrator keeps its step size and the last
// derivative between calls, so integrating from output time to output time costs what one
// call over the whole interval would.
#pragma once

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

namespace friction {

/// Thrown by a right-hand side that cannot evaluate F(t, y) (e.g. no slip rate balances the
/// stress): the step is rejected and halved. Other exceptions (StopNow) propagate.
class RightHandSideFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// F(t, y) → dydt (resized by the integrator to y's size); false: cannot evaluate here.
using RightHandSide =
    std::function<bool(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt)>;

enum class RungeKuttaScheme { dormandPrince54, bogackiShampine32 };
enum class ErrorNorm { max, rms };

struct RungeKuttaSettings {
  RungeKuttaScheme scheme = RungeKuttaScheme::dormandPrince54;
  /// Tolerances: one value for every component (size 1) or one per component (size n).
  Eigen::VectorXd relTol = Eigen::VectorXd::Constant(1, 1e-6);
  Eigen::VectorXd absTol = Eigen::VectorXd::Constant(1, 1e-9);
  ErrorNorm norm = ErrorNorm::max;
  bool piController = true;
  double safety = 0.9;     ///< factor on the step the error estimate predicts
  double minFactor = 0.2;  ///< smallest and largest change of h from one step to the next
  double maxFactor = 5.0;
  double initialStep = 0;  ///< [time]; 0: chosen from F(t0, y0) (Hairer, Nørsett & Wanner II.4)
  double maxStep = std::numeric_limits<double>::infinity();  ///< [time]
  /// [time] smallest step before stepTooSmall; whatever it is, a step below
  /// 64 ε max(|t|, |t1|) is too small (t + h would not differ from t in its last digits).
  double minStep = 0;
  long maxSteps = 100000000;  ///< accepted + rejected steps per call of integrate
  /// > 0: steps of exactly this size, no error control (every step accepted; order studies).
  double fixedStep = 0;
};

/// One accepted step, as the observer sees it.
struct AcceptedStep {
  double t0, t1;  ///< the step's interval
  const Eigen::VectorXd &y0, &y1, &dydt0, &dydt1;
  double error;  ///< the step's error norm E (≤ 1; 0 with fixedStep)
  /// y(t) for t in [t0, t1] by cubic Hermite interpolation (third order).
  void interpolate(double t, Eigen::VectorXd& y) const;
};

/// Return false to stop the integration at the end of this step (an event).
using StepObserver = std::function<bool(const AcceptedStep&)>;

enum class IntegrationStatus {
  reachedEnd,               ///< t = t1 exactly
  stoppedByObserver,        ///< the observer returned false: t is that step's end
  stepTooSmall,             ///< rejections drove h below the minimum step: t is the last accepted
  initialEvaluationFailed,  ///< F(t0, y0) could not be evaluated: nothing done
  maxSteps,                 ///< RungeKuttaSettings::maxSteps reached
};

/// A word for the log: "reachedEnd", "stoppedByObserver", "stepTooSmall", ….
const char* toString(IntegrationStatus status);

/// Work done; cumulative over the integrator's life (counters()) or per call (report).
struct RungeKuttaCounters {
  long evaluations = 0;        ///< calls of F, failed ones included
  long failedEvaluations = 0;  ///< of those, how many could not evaluate
  long acceptedSteps = 0;
  long rejectedSteps = 0;  ///< by the error test or by a failed evaluation
};

struct IntegrationReport {
  IntegrationStatus status = IntegrationStatus::reachedEnd;
  double t = 0;             ///< where the integration stopped (y is the state there)
  double nextStep = 0;      ///< the step size the controller proposes next
  RungeKuttaCounters work;  ///< this call's work
  bool ok() const {
    return status == IntegrationStatus::reachedEnd ||
           status == IntegrationStatus::stoppedByObserver;
  }
};

class EmbeddedRungeKutta {
 public:
  EmbeddedRungeKutta(RightHandSide rhs, RungeKuttaSettings settings);

  /// "" when the settings are valid, else which one is wrong (for the caller's InputError).
  static std::string invalid(const RungeKuttaSettings& settings);

  /// Advances y from t0 to t1 > t0 (y of size n, the tolerances' size 1 or n); y is the state
  /// at report.t on return (at t1 exactly when reachedEnd). A call whose (t0, y) equal the
  /// previous call's end reuses F there (FSAL) and the step size.
  IntegrationReport integrate(double t0, double t1, Eigen::VectorXd& y,
                              const StepObserver& observer = nullptr);

  /// Forget the previous call's end (F there and the step size): after the state changed
  /// outside the integrator with the same (t, y) bits, which integrate cannot tell.
  void reset();

  const RungeKuttaCounters& counters() const { return total_; }
  const RungeKuttaSettings& settings() const { return settings_; }
  /// The orders of the scheme: the solution's (5 or 3) and the embedded estimate's (4 or 2).
  int order() const;
  int embeddedOrder() const;

 private:
  bool evaluate(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt,
                RungeKuttaCounters& work);
  double errorNorm(const Eigen::VectorXd& err, const Eigen::VectorXd& y0,
                   const Eigen::VectorXd& y1) const;
  double startingStep(double t0, double t1, const Eigen::VectorXd& y0, const Eigen::VectorXd& f0,
                      RungeKuttaCounters& work);

  RightHandSide rhs_;
  RungeKuttaSettings settings_;
  RungeKuttaCounters total_;
  // The end of the previous call: t, y, F there, the proposed step and the last error.
  bool haveLast_ = false;
  double lastT_ = 0, lastStep_ = 0, lastError_ = 1e-4;
  Eigen::VectorXd lastY_, lastF_;
};

}  // namespace friction
