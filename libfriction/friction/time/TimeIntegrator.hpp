// TimeIntegrator: how the state of a case's faults goes from one time of the case's grid
// (system/controlDict: startTime, deltaT, endTime, or its list of times) to the next,
// run-time selectable in system/frictionSolution (README.md, "Time integration"):
//
//   timeIntegration quasiStatic;        // the default
//   timeIntegration { type quasiDynamic; relativeTolerance 1e-8; }   // rate-and-state faults
//
// quasiStatic: at each time of the grid the loads of that time are applied and the control
// problem gives the step's slip increment (docs/method.md §5): friction equilibrium, no
// inertia. A step whose loads equal the previous (converged) step's keeps its solution.
//
// quasiDynamic (QuasiDynamic.hpp): rate-and-state faults (law rateState) integrated in time on
// the fault alone, τ from the interface operator S, radiation damping, an adaptive embedded
// Runge–Kutta method between the times of the grid (docs/method.md §3).
//
// What every integrator shares stays with the case's driver (FrictionCase::run): restart,
// the stop requests, the time folders and histories, the log's step lines. An integrator
// reaches the case only through StepHost, so that a new one (quasi-dynamic rate-and-state,
// docs/method.md §12 in ../shared) is a new class here and a row of the table in
// TimeIntegrator.cpp, and nothing in the driver.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/control/Optimizer.hpp"

namespace friction {

class Dictionary;

/// Outcome of one time step.
struct StepResult {
  double time = 0;
  OptimizerReport report;
  long backSubstitutions = 0;
  double J = 0, relResidual = 0, maxExcessST = 0, lastStepNorm = 0;
  double equilibrium = 0;   ///< ‖K x − b‖/‖b‖ of the step's final primal solve
  double maxSlipRate = -1;  ///< quasiDynamic: the largest |V| at the step's end [m/s] (< 0: none)
  /// quasiDynamic: the largest |V| over the step's interval, at the integration's steps [m/s]
  double peakSlipRate = -1;
  bool written = false;
  bool reused = false;     ///< loads unchanged since the previous step: its solution reused
  bool nonFinite = false;  ///< the results overflowed: the step is diverged and not written
};

/// The loads of one time, as far as they decide a step's answer: the load vector on the split
/// space [N], the Dirichlet values [m] and the fluid pressure per control node [Pa].
struct StepLoads {
  Eigen::VectorXd load, dirichlet, pressure;
  bool operator==(const StepLoads& o) const {
    return load == o.load && dirichlet == o.dirichlet && pressure == o.pressure;
  }
};

struct InterfaceOperator;
struct RateState;
struct RateSample;
class DictionaryWriter;

/// What a quasi-dynamic integrator advances on the faults (StepHost::rateStateFault): per
/// control node its law, and the case's state, k slip components and one ψ per node.
struct RateStateFault {
  int k = 1;                                     ///< tangential components per node
  const std::vector<RateState>* laws = nullptr;  ///< per node (σ̄ set per evaluation)
  const Eigen::VectorXd* slip = nullptr;         ///< k·n, the slip at the step's start [m]
  Eigen::VectorXd* psi = nullptr;                ///< n, the state ψ (–), advanced in place
  Eigen::VectorXd componentMask;                 ///< k·n: 1 where a slip component is free
  /// n: 1 at nodes whose slip rate is imposed (law creep; their law and ψ are unused), and
  /// that rate (k·n) [m/s].
  const Eigen::VectorXd* imposed = nullptr;
  const Eigen::VectorXd* imposedRate = nullptr;
  Eigen::MatrixXd positions;  ///< 3 × n: the nodes' positions [m] (z = 0 in 2D)
};

/// What the case offers a time integrator (FrictionCase implements it).
class StepHost {
 public:
  virtual ~StepHost() = default;
  /// Form what the case's optimizer forms once per run (Newton's condensed S); returns what
  /// it formed, for the log ("" when nothing). StopNow propagates.
  virtual std::string prepareSolver() = 0;
  /// The loads of time t, set on the system (Dirichlet values), after the effects with a state
  /// of their own advanced to t.
  virtual StepLoads loadsAt(double t) = 0;
  /// Solve the control problem under `loads` at time t: the case's last state becomes its
  /// solution; sets r.report and r.relResidual. StopNow (a second signal) propagates.
  virtual void solveStep(const StepLoads& loads, double t, StepResult& r) = 0;
  /// The step keeps the previous step's solution under `loads`: no slip increment, the
  /// openings stay.
  virtual void keepSolution(const StepLoads& loads) = 0;
  /// After a restart, for a first step whose loads are those of the restart's time: makes
  /// the case's last state the one the step of that time ended with, bit for bit (the
  /// evaluation its state file records), and fills r (status, residual, equilibrium) as that
  /// step's own result; then keepSolution() reuses it as the uninterrupted run did. False
  /// where the state file records no such evaluation (the step did not converge, or the
  /// folder is older): the step is then solved.
  virtual bool restoreStep(const StepLoads& /*loads*/, StepResult& /*r*/) { return false; }

  // For integrators of rate-and-state faults (quasiDynamic):
  /// The time the case's state is at (startTime, a restart's time, or the last step's).
  virtual double stateTime() const = 0;
  /// The interface operator S (prepareSolver() formed it).
  virtual const InterfaceOperator& faultOperator() = 0;
  /// The tractions at the control nodes under `loads` at time t with the slip at the step's
  /// start (no increment): τ (k·n) and σ_n (n) [Pa]. One back-substitution.
  virtual void tractionsAt(const StepLoads& loads, double t, Eigen::VectorXd& tau,
                           Eigen::VectorXd& sigmaN) = 0;
  virtual RateStateFault rateStateFault() = 0;
  /// Ends a step that moved the slip to `slip` (k·n) at slip rates V (k·n) [m/s] under `loads`
  /// at time t: the case's last state becomes that slip's (one back-substitution); sets
  /// r.relResidual.
  virtual void finishRateStep(const StepLoads& loads, double t, const Eigen::VectorXd& slip,
                              const Eigen::VectorXd& V, StepResult& r) = 0;
  /// Whether the case samples the integration's accepted steps (its faultOutput); then the
  /// integrator passes each of them, and the state at each interval's start, to rateSample.
  virtual bool wantsRateSamples() const { return false; }
  virtual void rateSample(const RateSample& /*sample*/) {}
};

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  /// The names in the selection table (messages, the README).
  static std::vector<std::string> names();
  /// Reads 'timeIntegration' of system/frictionSolution (default quasiStatic).
  static std::unique_ptr<TimeIntegrator> New(const Dictionary& frictionSolution);

  virtual std::string name() const = 0;
  /// Once per run, before its first step (after a restart's state is read): forms what the
  /// steps share; returns what it formed, for the log ("" when nothing).
  virtual std::string prepare(StepHost& host) = 0;
  /// From the previous step's time to r.time: fills r (status, residual, reuse) and leaves
  /// the case's last state at r.time. `previous`: the step before, computed in this run
  /// (nullptr for the run's first step).
  virtual void advance(StepHost& host, StepResult& r, const StepResult* previous) = 0;
  /// A restarted run, before its first step: the case's state is that of host.stateTime().
  virtual void restarted(StepHost& /*host*/) {}
  /// Whether the integrator has a state of its own to restart from (written under
  /// 'integrator' in uniform/frictionState).
  virtual bool hasState() const { return false; }
  virtual void writeState(DictionaryWriter& /*out*/) const {}
  virtual void readState(const Dictionary& /*in*/) {}
  /// Rate-and-state faults: the one integrator that takes them.
  virtual bool takesRateState() const { return false; }
  /// For the log's settings line ("" when there is nothing to add to the name).
  virtual std::string describe() const { return ""; }
  /// What the run's integration cost, for the log's last lines ("" when nothing to add).
  virtual std::string summary() const { return ""; }
  /// The balance residual |D|/|Sigma| a step's written state is judged against, given the
  /// control's tolerance; and, when a state exceeds it, why and what to do ("": the control's
  /// own reasons). An integrator whose tractions carry an error of their own (a compressed
  /// S) widens the bound to that error and says so.
  virtual double balanceTolerance(double controlTolerance) const { return controlTolerance; }
  virtual std::string balanceNote() const { return ""; }
};

/// The quasi-static stepping: one control problem per time of the grid.
class QuasiStatic : public TimeIntegrator {
 public:
  std::string name() const override { return "quasiStatic"; }
  std::string prepare(StepHost& host) override { return host.prepareSolver(); }
  void advance(StepHost& host, StepResult& r, const StepResult* previous) override;
  void restarted(StepHost& host) override;

 private:
  StepLoads last_;  ///< the loads of the last step advanced to
  /// A restart's first step may reuse the state of the restart's time (StepHost::restoreStep).
  bool restartPending_ = false;
};

}  // namespace friction
