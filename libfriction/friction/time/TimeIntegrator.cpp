// TimeIntegrator: the selection table and the quasi-static stepping (TimeIntegrator.hpp).
#include "friction/time/TimeIntegrator.hpp"

#include <functional>

#include "friction/dict/Dictionary.hpp"
#include "friction/time/QuasiDynamic.hpp"

namespace friction {

namespace {

struct IntegratorEntry {
  const char* name;
  std::function<std::unique_ptr<TimeIntegrator>(const Dictionary*)> make;
};

const std::vector<IntegratorEntry>& integratorTable() {
  static const std::vector<IntegratorEntry> table = {
      {"quasiStatic", [](const Dictionary*) { return std::make_unique<QuasiStatic>(); }},
      {"quasiDynamic",
       [](const Dictionary* d) -> std::unique_ptr<TimeIntegrator> {
         return std::make_unique<QuasiDynamic>(d);
       }},
  };
  return table;
}

}  // namespace

std::vector<std::string> TimeIntegrator::names() {
  std::vector<std::string> n;
  for (const auto& e : integratorTable()) n.push_back(e.name);
  return n;
}

std::unique_ptr<TimeIntegrator> TimeIntegrator::New(const Dictionary& frictionSolution) {
  // A word, or a sub-dictionary with its 'type' and the integrator's settings.
  const Dictionary* settings = nullptr;
  std::string type = "quasiStatic";
  if (frictionSolution.isDict("timeIntegration")) {
    settings = &frictionSolution.subDict("timeIntegration");
    type = settings->getChoice("type", names());
  } else {
    type = frictionSolution.getChoiceOr("timeIntegration", names(), "quasiStatic");
  }
  for (const auto& e : integratorTable())
    if (type == e.name) {
      auto integrator = e.make(settings);
      if (settings) settings->checkAllRead();
      return integrator;
    }
  return nullptr;  // getChoiceOr accepts only the table's names
}

void QuasiStatic::restarted(StepHost& host) {
  // The loads of the restart's time, as the step of that time had them (effects with a state
  // are at that time already: advancing them there changes nothing).
  last_ = host.loadsAt(host.stateTime());
  restartPending_ = true;
}

void QuasiStatic::advance(StepHost& host, StepResult& r, const StepResult* previous) {
  StepLoads loads = host.loadsAt(r.time);
  // A restart's first step: the step before it is the one the restart's state file records,
  // made again bit for bit, so that a step with its loads is reused as in the uninterrupted
  // run (and not solved again from β = 0, which writes other round-off).
  StepResult restored;
  if (!previous && restartPending_ && loads == last_ && host.restoreStep(loads, restored))
    previous = &restored;
  restartPending_ = false;
  // Only what changed is recomputed: a step whose loads equal the previous step's has the
  // previous (converged) solution, with β = 0.
  if (previous && loads == last_ && previous->report.status == OptimizerStatus::converged) {
    r.reused = true;
    r.report.status = OptimizerStatus::converged;
    r.relResidual = previous->relResidual;
    r.equilibrium = previous->equilibrium;
    r.report.tangentStiffness = previous->report.tangentStiffness;
    r.report.stiffnessComponents = previous->report.stiffnessComponents;
    host.keepSolution(loads);
  } else {
    host.solveStep(loads, r.time, r);
  }
  last_ = std::move(loads);
}

}  // namespace friction
