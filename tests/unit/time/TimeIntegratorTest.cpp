// The selection of the time integrator (system/frictionSolution's timeIntegration) and the
// quasi-static stepping's rule for steps whose loads did not change (TimeIntegrator.hpp), on
// a host that records what the integrator asks of it: no case, no solve.
#include <catch2/catch.hpp>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/time/TimeIntegrator.hpp"

using namespace friction;

namespace {

// Loads that are a function of the time the test chooses; records the calls.
struct RecordingHost : StepHost {
  std::vector<std::string> calls;
  std::function<double(double)> scale = [](double t) { return t; };
  std::string prepareSolver() override {
    calls.push_back("prepare");
    return "S";
  }
  StepLoads loadsAt(double t) override {
    calls.push_back("loads");
    StepLoads l;
    l.load = Eigen::VectorXd::Constant(3, scale(t));
    l.dirichlet = Eigen::VectorXd::Zero(2);
    l.pressure = Eigen::VectorXd::Zero(1);
    return l;
  }
  void solveStep(const StepLoads&, double, StepResult& r) override {
    calls.push_back("solve");
    r.report.status = OptimizerStatus::converged;
    r.relResidual = 1e-9;
  }
  void keepSolution(const StepLoads&) override { calls.push_back("keep"); }
  // The quasi-static stepping asks nothing of these.
  double stateTime() const override { return 0; }
  const InterfaceOperator& faultOperator() override { throw std::logic_error("not used"); }
  void tractionsAt(const StepLoads&, double, Eigen::VectorXd&, Eigen::VectorXd&) override {
    calls.push_back("tractions");
  }
  RateStateFault rateStateFault() override { return {}; }
  void finishRateStep(const StepLoads&, double, const Eigen::VectorXd&, const Eigen::VectorXd&,
                      StepResult&) override {
    calls.push_back("finishRate");
  }
};

std::unique_ptr<TimeIntegrator> select(const std::string& text) {
  return TimeIntegrator::New(Dictionary::parse(text, "system/frictionSolution"));
}

}  // namespace

TEST_CASE("time integration: quasiStatic by default and by name, others refused", "[unit][time]") {
  CHECK(select("elementOrder 1;")->name() == "quasiStatic");
  CHECK(select("timeIntegration quasiStatic;")->name() == "quasiStatic");
  try {
    select("timeIntegration quasistatic;");
    FAIL("an unknown integrator was accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("system/frictionSolution") != std::string::npos);
    CHECK(what.find("timeIntegration") != std::string::npos);
    CHECK(what.find("quasiStatic") != std::string::npos);  // the way forward
  }
  CHECK_FALSE(TimeIntegrator::names().empty());
}

TEST_CASE("quasi-static stepping: a step solves unless its loads equal a converged step's",
          "[unit][time]") {
  RecordingHost host;
  // Loads 1, 2, 2, 2, 3 at the times 1 … 5.
  host.scale = [](double t) { return t < 2 ? 1.0 : t < 4.5 ? 2.0 : 3.0; };
  QuasiStatic q;
  CHECK(q.prepare(host) == "S");
  std::vector<StepResult> results;
  for (int k = 1; k <= 5; ++k) {
    StepResult r;
    r.time = k;
    q.advance(host, r, results.empty() ? nullptr : &results.back());
    results.push_back(r);
  }
  const std::vector<std::string> expected = {"prepare", "loads", "solve", "loads", "solve", "loads",
                                             "keep",    "loads", "keep",  "loads", "solve"};
  CHECK(host.calls == expected);
  CHECK_FALSE(results[1].reused);
  CHECK(results[2].reused);
  CHECK(results[2].relResidual == results[1].relResidual);
  CHECK(results[4].report.status == OptimizerStatus::converged);

  // A step that did not converge is not kept: the next one with the same loads solves again.
  RecordingHost failing;
  failing.scale = [](double) { return 1.0; };
  QuasiStatic q2;
  StepResult first;
  first.time = 1;
  q2.advance(failing, first, nullptr);
  first.report.status = OptimizerStatus::maxIterations;
  StepResult second;
  second.time = 2;
  q2.advance(failing, second, &first);
  CHECK_FALSE(second.reused);
  CHECK(failing.calls.back() == "solve");
}
