// Every optimizer of the selection table on the synthetic control problem: the line-search
// methods never let J rise, and each reaches the friction law (D = 0) or says why not.
#include <catch2/catch.hpp>

#include <algorithm>

#include "SyntheticResponse.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using Eigen::VectorXd;
using friction::test::SyntheticResponse;

namespace {

// Every optimizer of the selection table with every variant it has: a new optimizer is tested
// by the loops below without a line here; only a variant key needs one.
std::vector<std::string> allSettings() {
  std::vector<std::string> settings;
  for (const std::string& type : Optimizer::names()) {
    settings.push_back(type);
    if (type == "semismoothNewton") settings.push_back(type + "; variant krylov");
  }
  return settings;
}

constexpr int maxIterations = 100000;

std::string typeOf(const std::string& setting) { return setting.substr(0, setting.find(';')); }

// α for the gradient methods: steepestDescent's fixed step must stay below 2/L, L the largest
// curvature of J (~ ‖S_tt‖² ≈ 10⁴ here: 1.3e-4 already diverges on seed 5), so 1e-4; the
// others use α as a first trial (Armijo backtracks from 1). Newton reads no α. The gradient
// methods converge linearly, with a rate set by the condition of S² (~10²): up to 4·10⁴
// iterations to reach 1e-9 (measured), hence the iteration limit of the tests.
std::unique_ptr<Optimizer> make(const std::string& setting, int iterationLimit) {
  const std::string type = typeOf(setting);
  const std::string alpha = type == "semismoothNewton"  ? ""
                            : type == "armijo"          ? "alpha 1;"
                            : type == "steepestDescent" ? "alpha 1e-4;"
                                                        : "alpha 1e-3;";
  Dictionary d =
      Dictionary::parse("type " + setting + "; " + alpha + " tolerance 1e-9; maxIterations " +
                            std::to_string(iterationLimit) + ";",
                        "test");
  auto opt = Optimizer::New(d);
  d.checkAllRead();  // every key above is one the optimizer reads: no setting silently ignored
  return opt;
}

}  // namespace

namespace {
// The case's facts for SemismoothNewton::chooseFor.
friction::CaseFacts facts(Eigen::Index nodes, int dim, Eigen::Index dofs, const std::string& why,
                          int order = 1, const std::string& iterative = "") {
  friction::CaseFacts f;
  f.fractureNodes = nodes;
  f.dimension = dim;
  f.dofs = dofs;
  f.needsDenseS = why;
  f.elementOrder = order;
  f.iterativeSolver = iterative;
  return f;
}
}  // namespace

TEST_CASE("the optimizer table lists the paper's methods and the project's own",
          "[control][optimizer]") {
  // The loops below run over this table: were it empty, they would pass without a test.
  const std::vector<std::string> names = Optimizer::names();
  for (const char* expected :
       {"steepestDescent", "armijo", "barzilaiBorwein", "lbfgs", "semismoothNewton"})
    CHECK(std::find(names.begin(), names.end(), expected) != names.end());
}

TEST_CASE("every optimizer solves the synthetic Coulomb problem", "[control][optimizer]") {
  const std::vector<std::string> settings = allSettings();
  REQUIRE(settings.size() > Optimizer::names().size());  // the variants are in too
  for (const std::string& setting : settings) {
    DYNAMIC_SECTION(setting) {
      SyntheticResponse r(6, 21);
      ControlProblem p(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0,
                       GradientKind::exact);
      auto opt = make(setting, maxIterations);
      VectorXd beta = VectorXd::Zero(6);
      const OptimizerReport rep = opt->minimize(p, beta);
      INFO("iterations " << rep.iterations << ", status " << toString(rep.status));
      CHECK(opt->name() == typeOf(setting));
      CHECK(rep.status == OptimizerStatus::converged);
      CHECK(p.relativeResidual(p.evaluate(beta)) <= 1e-9);
      // The problem is not solved at the start: the optimizer had to move (some node slips).
      CHECK(rep.iterations > 0);
      CHECK(beta.norm() > 0);
      REQUIRE_FALSE(rep.history.empty());
      if (typeOf(setting) != "barzilaiBorwein")  // the only non-monotone one
        for (std::size_t k = 1; k < rep.history.size(); ++k)
          CHECK(rep.history[k].J <= rep.history[k - 1].J * (1 + 1e-12));
    }
  }
}

TEST_CASE("all optimizers agree on the solution", "[control][optimizer]") {
  const auto solve = [](const std::string& setting) {
    SyntheticResponse r(6, 5);
    ControlProblem p(r, VectorXd::Constant(6, 0.4), VectorXd::Zero(6), 2.0, 0.0,
                     GradientKind::exact);
    VectorXd beta = VectorXd::Zero(6);
    CHECK(make(setting, maxIterations)->minimize(p, beta).status == OptimizerStatus::converged);
    return beta;
  };
  // The reference: Newton, which solves D = 0 to round-off.
  const VectorXd reference = solve("semismoothNewton");
  REQUIRE(reference.norm() > 0);  // agreeing on β = 0 (nothing slips) would prove little
  for (const std::string& setting : allSettings()) {
    INFO(setting);
    const VectorXd beta = solve(setting);
    // Converged to ‖D‖ ≤ 1e-9 ‖Σ‖; the slip error is that residual times the condition of
    // S (about 10⁴ here), so 1e-4 relative.
    CHECK((beta - reference).norm() <= 1e-4 * reference.norm());
  }
}

TEST_CASE("krylov variant: the state Newton tracks without solving is a fresh solve's",
          "[control][optimizer]") {
  // The krylov variant makes no solve for its trial states: τ(β + t·dir) = τ(β) + t·S dir,
  // with S dir summed from its GMRES products, and later Newton iterations reuse the step's
  // earlier products (Optimizer.cpp, gmres). A wrong weight or a reused product outside the
  // active set would leave its last recorded residual different from a fresh solve's.
  for (const int k : {1, 2}) {
    DYNAMIC_SECTION("k = " << k) {
      const int n = 80;
      SyntheticResponse r(n, 13, k);
      ControlProblem p(r, VectorXd::Constant(n, 0.6), VectorXd::Zero(n), 2.0, 0.0,
                       GradientKind::exact);
      auto opt = make("semismoothNewton; variant krylov", 100);
      VectorXd beta = VectorXd::Zero(k * n);
      const OptimizerReport rep = opt->minimize(p, beta);
      INFO(rep.note);
      REQUIRE(rep.status == OptimizerStatus::converged);
      REQUIRE(rep.iterations >= 2);  // later iterations had earlier products to reuse
      const ControlState fresh = p.evaluate(beta);
      int stick = 0, slip = 0;
      for (const auto& c : fresh.node) (c.state == SlipState::stick ? stick : slip) += 1;
      CHECK(stick > 0);  // both states: the active set is a proper subset of the nodes
      CHECK(slip > 0);
      const double tracked = rep.history.back().relResidual, solved = p.relativeResidual(fresh);
      INFO("tracked " << tracked << ", fresh " << solved);
      CHECK(solved <= 1e-9);
      // Round-off of a few sums of S-products against one product: 1e-13 of ‖Σ‖.
      CHECK(std::abs(tracked - solved) <= 1e-13);
    }
  }
}

TEST_CASE("krylov variant: an iteration past its kept products gets S dir from a product",
          "[control][optimizer]") {
  // SemismoothNewton::setKeptProductsForTests: with one product kept per Newton iteration, an
  // iteration whose GMRES makes more gets S dir from one product of its own instead of the
  // sum of its products' S. The tracked state must still be a fresh solve's, and the answer
  // the same to Newton's tolerance; it costs products (S dir's own, and fewer kept products
  // for later iterations to reuse).
  struct Restore {
    ~Restore() { SemismoothNewton::setKeptProductsForTests(0); }
  } restore;
  const int n = 80, k = 2;
  std::vector<VectorXd> betas;
  std::vector<long> duals;
  std::vector<int> iterations;
  for (const int cap : {0, 1}) {
    SemismoothNewton::setKeptProductsForTests(cap);
    SyntheticResponse r(n, 13, k);
    ControlProblem p(r, VectorXd::Constant(n, 0.6), VectorXd::Zero(n), 2.0, 0.0,
                     GradientKind::exact);
    auto opt = make("semismoothNewton; variant krylov", 100);
    VectorXd beta = VectorXd::Zero(k * n);
    const long before = r.dualCalls;
    const OptimizerReport rep = opt->minimize(p, beta);
    INFO("cap " << cap << ": " << rep.note);
    REQUIRE(rep.status == OptimizerStatus::converged);
    duals.push_back(r.dualCalls - before);
    const ControlState fresh = p.evaluate(beta);
    CHECK(std::abs(rep.history.back().relResidual - p.relativeResidual(fresh)) <= 1e-13);
    betas.push_back(beta);
    iterations.push_back(rep.iterations);
  }
  REQUIRE(betas[0].norm() > 0);
  INFO("iterations " << iterations[0] << " and " << iterations[1] << ", products " << duals[0]
                     << " and " << duals[1]);
  // Both stop at |D|/|Σ| ≤ 1e-9 (make()'s tolerance) on the same problem; S is well
  // conditioned here (its eigenvalues within a factor of about 10²), so the slips agree to
  // about 1e-7.
  CHECK((betas[1] - betas[0]).norm() <= 1e-6 * betas[0].norm());
  CHECK(duals[1] > duals[0]);
}

TEST_CASE("semismoothNewton reads interfaceOperator, and refuses it for the krylov variant",
          "[control][optimizer]") {
  // The key decides whether the case factors the bordered matrix (docs/method.md §4).
  auto read = [](const std::string& text) {
    Dictionary d = Dictionary::parse(text, "frictionSolution");
    auto opt = Optimizer::New(d);
    d.checkAllRead();
    return opt;
  };
  CHECK(read("type semismoothNewton;")->wantsInterfaceOperator());
  CHECK(read("type semismoothNewton; interfaceOperator factorisation;")->wantsInterfaceOperator());
  for (const char* how : {"blockSolves", "dualSolves"}) {
    auto opt = read(std::string("type semismoothNewton; interfaceOperator ") + how + ";");
    CHECK_FALSE(opt->wantsInterfaceOperator());
    const auto* newton = dynamic_cast<const SemismoothNewton*>(opt.get());
    REQUIRE(newton != nullptr);
    CHECK(toString(newton->interfaceMethod()) == std::string(how));
  }
  CHECK_FALSE(read("type semismoothNewton; variant krylov;")->wantsInterfaceOperator());
  CHECK_FALSE(read("type lbfgs;")->wantsInterfaceOperator());
  // With krylov the key has no meaning: refused, naming the key and the reason.
  CHECK_THROWS_WITH(read("type semismoothNewton; variant krylov; interfaceOperator dualSolves;"),
                    Catch::Contains("interfaceOperator") && Catch::Contains("condensed only"));
  // A misspelt choice lists the valid ones.
  CHECK_THROWS_WITH(read("type semismoothNewton; interfaceOperator factorization;"),
                    Catch::Contains("factorisation") && Catch::Contains("blockSolves"));
}

TEST_CASE("semismoothNewton variant auto: krylov from the case's threshold, unless S is needed",
          "[control][optimizer]") {
  // The default variant is auto: condensed until the case's facts are known (so that unit uses
  // and small cases run as before), then krylov for fractures of at least krylovFromNodes(d,
  // dofs) control nodes that need no dense S. The log line names the choice, the node count and
  // the threshold, and what needs S when that overrides the size.
  auto read = [](const std::string& text) {
    Dictionary d = Dictionary::parse(text, "frictionSolution");
    auto opt = Optimizer::New(d);
    d.checkAllRead();
    return opt;
  };
  auto variantOf = [](const Optimizer& o) {
    const auto* newton = dynamic_cast<const SemismoothNewton*>(&o);
    REQUIRE(newton != nullptr);
    return newton->variant();
  };
  using V = SemismoothNewton::Variant;
  // The measurements the thresholds rest on (README "Newton's variant by fault size"): the
  // variant found faster on each side of the threshold. 3D: krylov at 4 178 nodes in 312 180
  // dofs, 2 387 in 46 446 and 10 299 in 316 251; condensed at 2 387 in 678 102 and at 273 (the
  // committed penny, 9 660). 2D (with products on the fault's reach): condensed at 513 nodes,
  // krylov at 1 025, 2 049 and 5 001.
  CHECK(SemismoothNewton::krylovFromNodes(3, 312180) <= 4178);
  CHECK(SemismoothNewton::krylovFromNodes(3, 46446) <= 2387);
  CHECK(SemismoothNewton::krylovFromNodes(3, 316251) <= 10299);
  CHECK(SemismoothNewton::krylovFromNodes(3, 678102) > 2387);
  CHECK(SemismoothNewton::krylovFromNodes(3, 9660) > 273);
  CHECK(SemismoothNewton::krylovFromNodes(2, 86720) > 513);
  CHECK(SemismoothNewton::krylovFromNodes(2, 159286) <= 1025);
  CHECK(SemismoothNewton::krylovFromNodes(2, 300950) <= 2049);
  CHECK(SemismoothNewton::krylovFromNodes(2, 701946) <= 5001);
  // A larger body makes each back-substitution dearer: the threshold grows with the dofs.
  CHECK(SemismoothNewton::krylovFromNodes(3, 10'000'000) >
        SemismoothNewton::krylovFromNodes(3, 1'000'000));
  for (const auto& [dim, dofs] :
       {std::pair<int, Eigen::Index>{2, 300950}, {3, 9660}, {3, 312180}, {3, 678102}}) {
    CAPTURE(dim, dofs);
    const Eigen::Index t = SemismoothNewton::krylovFromNodes(dim, dofs);
    REQUIRE(t > 1);
    const std::string at3D = dim == 3 ? " at " + std::to_string(dofs) + " dofs" : "";
    for (const char* text : {"type semismoothNewton;", "type semismoothNewton; variant auto;"}) {
      CAPTURE(text);
      auto below = read(text), at = read(text);
      // Before the choice: condensed, S from the factorisation.
      CHECK(variantOf(*at) == V::condensed);
      CHECK(at->wantsInterfaceOperator());
      CHECK(at->handlesOpening());
      CHECK(at->handlesWeakening());
      const std::string lineBelow = below->chooseFor(facts(t - 1, dim, dofs, ""));
      CHECK(variantOf(*below) == V::condensed);
      CHECK(below->wantsInterfaceOperator());
      CHECK(lineBelow == "Newton variant: condensed (variant auto: " + std::to_string(t - 1) +
                             " fracture control nodes < " + std::to_string(t) + ", the " +
                             std::to_string(dim) + "D threshold for krylov" + at3D + ")");
      const std::string lineAt = at->chooseFor(facts(t, dim, dofs, ""));
      CHECK(variantOf(*at) == V::krylov);
      CHECK_FALSE(at->wantsInterfaceOperator());
      CHECK_FALSE(at->handlesOpening());
      CHECK(lineAt == "Newton variant: krylov (variant auto: " + std::to_string(t) +
                          " fracture control nodes >= " + std::to_string(t) + ", the " +
                          std::to_string(dim) + "D threshold for krylov" + at3D + ")");
      // Chosen once: another call changes nothing and says nothing.
      CHECK(at->chooseFor(facts(1, dim, dofs, "")).empty());
      CHECK(variantOf(*at) == V::krylov);
      for (const char* why : {"fractures that open (contact unilateral)", "law slipWeakening",
                              "timeIntegration quasiDynamic"}) {
        auto o = read(text);
        const std::string line = o->chooseFor(facts(10 * t, dim, dofs, why));
        CHECK(variantOf(*o) == V::condensed);
        CHECK(o->wantsInterfaceOperator());
        CHECK_THAT(line, Catch::StartsWith("Newton variant: condensed") &&
                             Catch::EndsWith(std::string("; condensed all the same: the dense S is "
                                                         "needed for ") +
                                             why + ")"));
      }
      // An iterative linear solver (amg): krylov at any size, for it has no factor to take S
      // from; condensed still where the dense S is needed.
      auto it = read(text);
      const std::string lineIt = it->chooseFor(facts(t - 1, dim, dofs, "", 1, "amg"));
      CHECK(variantOf(*it) == V::krylov);
      CHECK_THAT(lineIt,
                 Catch::StartsWith("Newton variant: krylov") &&
                     Catch::Contains("< " + std::to_string(t)) &&
                     Catch::EndsWith("; krylov all the same: linear solver amg has no "
                                     "factor, so S would cost one solve per jump unknown)"));
      // Nearly incompressible rock: krylov all the same, with a note on its preconditioner.
      auto soft = read(text);
      CaseFacts nu = facts(t, dim, dofs, "");
      nu.maxPoissonRatio = 0.49;
      const std::string lineNu = soft->chooseFor(nu);
      CHECK(variantOf(*soft) == V::krylov);
      CHECK_THAT(lineNu, Catch::EndsWith("; note: at nu 0.49 krylov's probed preconditioner is "
                                         "weak (thousands of GMRES products per Newton iteration "
                                         "measured at nu 0.49); variant condensed is robust there "
                                         "where its dense S fits)"));
      CHECK(lineAt.find("note:") == std::string::npos);
      auto itOpen = read(text);
      itOpen->chooseFor(facts(1, dim, dofs, "fractures that open (contact unilateral)", 1, "amg"));
      CHECK(variantOf(*itOpen) == V::condensed);
      // P2: krylov in 2D; in 3D condensed, its probed preconditioner does not hold there.
      auto p2 = read(text);
      const std::string lineP2 = p2->chooseFor(facts(10 * t, dim, dofs, "", 2));
      if (dim == 2) {
        CHECK(variantOf(*p2) == V::krylov);
      } else {
        CHECK(variantOf(*p2) == V::condensed);
        CHECK_THAT(lineP2, Catch::EndsWith("; condensed all the same: krylov's probed "
                                           "preconditioner does not hold for P2 faults in 3D)"));
      }
    }
    // A variant given, or the condensed variant's own key: nothing left to choose.
    for (const char* text :
         {"type semismoothNewton; variant condensed;",
          "type semismoothNewton; interfaceOperator blockSolves;",
          "type semismoothNewton; variant auto; interfaceOperator dualSolves;"}) {
      auto o = read(text);
      CHECK(o->chooseFor(facts(10 * t, dim, dofs, "")).empty());
      CHECK(variantOf(*o) == V::condensed);
    }
    auto k = read("type semismoothNewton; variant krylov;");
    CHECK(k->chooseFor(facts(1, dim, dofs, "law slipWeakening")).empty());
    CHECK(variantOf(*k) == V::krylov);
    CHECK(read("type lbfgs;")->chooseFor(facts(10 * t, dim, dofs, "")).empty());
  }
  // The krylov variant's keys with auto: refused, naming the key and the way out.
  for (const char* key : {"preconditioner probing;", "probingDistance 2;"})
    CHECK_THROWS_WITH(
        read(std::string("type semismoothNewton; ") + key),
        Catch::Contains("variant krylov only") && Catch::Contains("set 'variant krylov;'"));
  CHECK_THROWS_WITH(
      read("type semismoothNewton; variant automatic;"),
      Catch::Contains("auto") && Catch::Contains("condensed") && Catch::Contains("krylov"));
}
