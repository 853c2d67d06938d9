// Every optimizer of the selection table on the synthetic control problem: the line-search
// methods never let J rise, and each reaches the friction law (D = 0) or says why not.
#include <catch2/catch.hpp>

#include "SyntheticResponse.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using friction::test::SyntheticResponse;
using Eigen::VectorXd;

namespace {

std::unique_ptr<Optimizer> make(const std::string& type, double alpha, int maxIterations) {
  Dictionary d = Dictionary::parse("type " + type + "; alpha " + std::to_string(alpha) +
                                       "; tolerance 1e-9; maxIterations " +
                                       std::to_string(maxIterations) + ";",
                                   "test");
  return Optimizer::New(d);
}

}  // namespace

TEST_CASE("every optimizer solves the synthetic Coulomb problem", "[control][optimizer]") {
  // α for the fixed-step methods: below 2/L with L ~ ‖S‖² ≈ (n·max w⁻¹)² for this operator.
  for (const std::string type :
       {"armijo", "barzilaiBorwein", "lbfgs", "semismoothNewton", "semismoothNewton; variant krylov"}) {
    DYNAMIC_SECTION(type) {
      SyntheticResponse r(6, 21);
      ControlProblem p(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0, GradientKind::exact);
      auto opt = make(type, type == "armijo" ? 1.0 : 1e-3, 20000);
      VectorXd beta = VectorXd::Zero(6);
      const OptimizerReport rep = opt->minimize(p, beta);
      INFO("iterations " << rep.iterations << ", status " << toString(rep.status));
      CHECK(rep.status == OptimizerStatus::converged);
      CHECK(p.relativeResidual(p.evaluate(beta)) <= 1e-9);
      if (type != "barzilaiBorwein")  // the only non-monotone one
        for (std::size_t k = 1; k < rep.history.size(); ++k)
          CHECK(rep.history[k].J <= rep.history[k - 1].J * (1 + 1e-12));
    }
  }
}

TEST_CASE("all optimizers agree on the solution", "[control][optimizer]") {
  VectorXd reference;
  for (const std::string type :
       {"semismoothNewton", "semismoothNewton; variant krylov", "lbfgs", "armijo"}) {
    SyntheticResponse r(6, 5);
    ControlProblem p(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0, GradientKind::exact);
    VectorXd beta = VectorXd::Zero(6);
    make(type, type == "armijo" ? 1.0 : 1e-3, 20000)->minimize(p, beta);
    if (reference.size() == 0) reference = beta;
    // Converged to ‖D‖ ≤ 1e-9 ‖Σ‖; the slip error is that residual times the condition of
    // S (about 10⁴ here), so 1e-4 relative.
    CHECK((beta - reference).norm() <= 1e-4 * reference.norm());
  }
}
