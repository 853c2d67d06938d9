// TimeIntegrator: how the state of a case's faults goes from one time of the case's grid
// (system/controlDict: startTime, deltaT, endTime, or its list of times) to the next,
// run-time selectable in system/frictionSolution (README.md, "Time integration"):
//
//   timeIntegration quasiStatic;        // the default
//
// quasiStatic: at each time of the grid the loads of that time are applied and the control
// problem gives the step's slip increment (docs/method.md §5): friction equilibrium, no
// inertia. A step whose loads equal the previous (converged) step's keeps its solution.
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
  double equilibrium = 0;  ///< ‖K x − b‖/‖b‖ of the step's final primal solve
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
};

/// The quasi-static stepping: one control problem per time of the grid.
class QuasiStatic : public TimeIntegrator {
 public:
  std::string name() const override { return "quasiStatic"; }
  std::string prepare(StepHost& host) override { return host.prepareSolver(); }
  void advance(StepHost& host, StepResult& r, const StepResult* previous) override;

 private:
  StepLoads last_;  ///< the loads of the last step advanced to
};

}  // namespace friction
