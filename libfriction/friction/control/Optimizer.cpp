// Optimizers of the control problem (docs/method.md §4) and their selection table.
#include "friction/control/Optimizer.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "friction/control/KrylovPreconditioner.hpp"
#include "friction/core/Assert.hpp"
#include "friction/core/StopRequest.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/linalg/DenseSolve.hpp"

namespace friction {

const char* toString(OptimizerStatus s) {
  switch (s) {
    case OptimizerStatus::converged:
      return "converged";
    case OptimizerStatus::maxIterations:
      return "maxIterations";
    case OptimizerStatus::diverged:
      return "diverged";
    case OptimizerStatus::stalled:
      return "stalled";
    case OptimizerStatus::inaccurate:
      return "inaccurate";
    case OptimizerStatus::nucleation:
      return "nucleation";
  }
  return "?";
}

namespace {

struct OptimizerEntry {
  const char* name;
  std::unique_ptr<Optimizer> (*make)(const Dictionary&);
};

// The one table of optimizers: adding one is one line here.
const OptimizerEntry optimizerTable[] = {
    // The paper's α = 2·10⁻⁴ is alphaRelative 2 in the paper's scaling (λ = μ = 1,
    // h = 1/40: (h/E)² = 10⁻⁴); it diverges on the inclined crack, so the default is 1,
    // stable on every case of the project (README.md).
    {"steepestDescent",
     [](const Dictionary&) -> std::unique_ptr<Optimizer> {
       return std::make_unique<SteepestDescent>();
     }},
    {"armijo",
     [](const Dictionary& d) -> std::unique_ptr<Optimizer> {
       return std::make_unique<Armijo>(d.getScalarOr("armijoC", 1e-4, {0, 1, true, true}),
                                       static_cast<int>(d.getIntOr("maxBacktracks", 60, {1, 200})));
     }},
    {"barzilaiBorwein",
     [](const Dictionary&) -> std::unique_ptr<Optimizer> {
       return std::make_unique<BarzilaiBorwein>();
     }},
    {"lbfgs",
     [](const Dictionary& d) -> std::unique_ptr<Optimizer> {
       return std::make_unique<Lbfgs>(static_cast<int>(d.getIntOr("memory", 10, {1, 100})),
                                      static_cast<int>(d.getIntOr("maxBacktracks", 60, {1, 200})));
     }},
    {"semismoothNewton",
     [](const Dictionary& d) -> std::unique_ptr<Optimizer> {
       const std::string variant =
           d.getChoiceOr("variant", {"auto", "condensed", "krylov"}, "auto");
       const bool krylov = variant == "krylov";
       // How the condensed variant forms S; the Krylov variant never forms it. Given with
       // variant auto, it asks for the condensed variant (as before auto was the default).
       if (krylov && d.found("interfaceOperator"))
         throw InputError(d.location("interfaceOperator"),
                          "'interfaceOperator' applies to variant condensed only: the krylov "
                          "variant does not form S");
       const bool automatic = variant == "auto" && !d.found("interfaceOperator");
       for (const char* key : {"preconditioner", "probingDistance"})
         if (automatic && d.found(key))
           throw InputError(d.location(key),
                            std::string("'") + key +
                                "' applies to variant krylov only: set 'variant krylov;' (the "
                                "default, variant auto, chooses by the fracture's size and may "
                                "choose condensed)");
       const std::string how =
           krylov ? "factorisation"
                  : d.getChoiceOr("interfaceOperator",
                                  {"factorisation", "blockSolves", "dualSolves"}, "factorisation");
       // The krylov variant's preconditioner (KrylovPreconditioner.hpp).
       for (const char* key : {"preconditioner", "probingDistance"})
         if (!krylov && d.found(key))
           throw InputError(d.location(key), std::string("'") + key +
                                                 "' applies to variant krylov only: the "
                                                 "condensed variant solves with the dense S");
       const std::string pre =
           krylov      ? d.getChoiceOr("preconditioner", {"none", "blockDiagonal", "probing"},
                                       "probing")
           : automatic ? "probing"  // what auto runs if it chooses krylov
                       : "none";
       if (pre != "probing" && d.found("probingDistance"))
         throw InputError(d.location("probingDistance"),
                          "'probingDistance' applies to preconditioner probing only");
       const int distance = static_cast<int>(d.getIntOr("probingDistance", 1, {1, 20}));
       return std::make_unique<SemismoothNewton>(
           static_cast<int>(d.getIntOr("maxBacktracks", 30, {1, 200})),
           krylov      ? SemismoothNewton::Variant::krylov
           : automatic ? SemismoothNewton::Variant::automatic
                       : SemismoothNewton::Variant::condensed,
           how == "blockSolves"  ? InterfaceMethod::blockSolves
           : how == "dualSolves" ? InterfaceMethod::dualSolves
                                 : InterfaceMethod::factorisation,
           pre == "blockDiagonal" ? KrylovPreconditioning::blockDiagonal
           : pre == "probing"     ? KrylovPreconditioning::probing
                                  : KrylovPreconditioning::none,
           distance);
     }},
};

}  // namespace

std::vector<std::string> Optimizer::names() {
  std::vector<std::string> n;
  for (const auto& e : optimizerTable) n.push_back(e.name);
  return n;
}

std::unique_ptr<Optimizer> Optimizer::New(const Dictionary& dict) {
  const std::string type = dict.getChoice("type", names());
  std::unique_ptr<Optimizer> opt;
  for (const auto& e : optimizerTable)
    if (type == e.name) opt = e.make(dict);
  if (type != "semismoothNewton") {
    if (dict.alternative({{"alpha"}, {"alphaRelative"}}, 1) == 0)
      opt->setStep(dict.getScalar("alpha", Bounds::positive()), false);
    else
      opt->setStep(dict.getScalarOr("alphaRelative",
                                    type == "armijo"            ? 10.0
                                    : type == "steepestDescent" ? 1.0
                                                                : 2.0,
                                    Bounds::positive()),
                   true);
  }
  StopRule s;
  s.on = dict.getChoiceOr("stopOn", {"residual", "step"}, "residual") == "step"
             ? StopRule::On::step
             : StopRule::On::residual;
  s.tolerance = dict.getScalarOr("tolerance", s.tolerance, Bounds::positive());
  s.maxIterations = static_cast<int>(dict.getIntOr("maxIterations", s.maxIterations, {0, 1e9}));
  opt->setStopRule(s);
  return opt;
}

IterationRecord Optimizer::record(ControlProblem& p, const ControlState& s, int k,
                                  double stepNorm) const {
  return {k, s.J, p.relativeResidual(s), stepNorm};
}

bool Optimizer::converged(ControlProblem& p, const ControlState& s, double stepNorm) const {
  const double rel = p.relativeResidual(s);
  if (rel == 0) return true;  // the friction law holds exactly (e.g. zero load)
  if (stop_.on == StopRule::On::step) return stepNorm >= 0 && stepNorm <= stop_.tolerance;
  return rel <= stop_.tolerance;
}

OptimizerReport SteepestDescent::minimize(ControlProblem& p, Eigen::VectorXd& beta) {
  OptimizerReport r;
  ControlState s = p.evaluate(beta);
  r.history.push_back(record(p, s, 0, -1));
  const double J0 = s.J;
  for (int k = 1; k <= stop_.maxIterations; ++k) {
    if (converged(p, s, k == 1 ? -1 : r.history.back().stepNorm)) {
      r.status = OptimizerStatus::converged;
      break;
    }
    const Eigen::VectorXd g = p.gradient(s);
    const Eigen::VectorXd next = s.beta - alpha() * g;
    const double step = p.norm(next - s.beta);
    s = p.evaluate(next);
    r.iterations = k;
    r.history.push_back(record(p, s, k, step));
    // A fixed step that makes J grow a thousandfold is not going to come back.
    if (!std::isfinite(s.J) || s.J > 1e3 * std::max(J0, 1e-300)) {
      r.status = OptimizerStatus::diverged;
      break;
    }
  }
  if (r.status != OptimizerStatus::diverged && converged(p, s, r.history.back().stepNorm))
    r.status = OptimizerStatus::converged;
  beta = s.beta;
  return r;
}

OptimizerReport Armijo::minimize(ControlProblem& p, Eigen::VectorXd& beta) {
  OptimizerReport r;
  ControlState s = p.evaluate(beta);
  r.history.push_back(record(p, s, 0, -1));
  double alpha = this->alpha();
  double lastStep = -1;
  for (int k = 1; k <= stop_.maxIterations; ++k) {
    if (converged(p, s, lastStep)) {
      r.status = OptimizerStatus::converged;
      break;
    }
    const Eigen::VectorXd g = p.gradient(s);
    const double g2 = p.dot(g, g);
    if (g2 == 0) {  // stationary but not converged: a kink
      r.status = OptimizerStatus::stalled;
      beta = s.beta;
      return r;
    }
    bool accepted = false;
    for (int b = 0; b < maxBacktracks_; ++b) {
      const Eigen::VectorXd next = s.beta - alpha * g;
      ControlState trial = p.evaluate(next);
      // Strictly lower J as well: once c·α·‖g‖² is below J's round-off, an equal J would pass
      // the Armijo test and the iteration would stand still until maxIterations.
      if (std::isfinite(trial.J) && trial.J < s.J && trial.J <= s.J - c_ * alpha * g2) {
        lastStep = p.norm(trial.beta - s.beta);
        s = std::move(trial);
        accepted = true;
        break;
      }
      alpha *= 0.5;
    }
    r.iterations = k;
    if (!accepted) {
      // No decrease along −g down to tiny steps: J is at a kink or at round-off level.
      r.status = OptimizerStatus::stalled;
      r.history.push_back(record(p, s, k, 0));
      beta = s.beta;
      if (converged(p, s, 0)) r.status = OptimizerStatus::converged;
      return r;
    }
    r.history.push_back(record(p, s, k, lastStep));
    alpha *= 2;  // let the step grow back after a backtrack
  }
  if (converged(p, s, lastStep)) r.status = OptimizerStatus::converged;
  beta = s.beta;
  return r;
}

OptimizerReport BarzilaiBorwein::minimize(ControlProblem& p, Eigen::VectorXd& beta) {
  // BB steps with a non-monotone safeguard (Grippo–Lampariello–Lucidi): a step is accepted
  // when J falls below the largest of the last 10 values by c α ‖g‖²; otherwise α is halved.
  // J is only piecewise smooth, where pure BB steps may cycle; the safeguard keeps the
  // method's speed on smooth stretches and makes it converge on kinks.
  OptimizerReport r;
  ControlState s = p.evaluate(beta);
  r.history.push_back(record(p, s, 0, -1));
  Eigen::VectorXd g = p.gradient(s), gOld, betaOld;
  std::vector<double> recent{s.J};
  double alpha = this->alpha(), lastStep = -1;
  for (int k = 1; k <= stop_.maxIterations; ++k) {
    if (converged(p, s, lastStep)) {
      r.status = OptimizerStatus::converged;
      break;
    }
    if (k > 1) {
      const Eigen::VectorXd sv = s.beta - betaOld, y = g - gOld;
      const double sy = p.dot(sv, y);
      alpha = sy > 0 ? p.dot(sv, sv) / sy : this->alpha();
    }
    const double g2 = p.dot(g, g);
    const double reference = *std::max_element(recent.begin(), recent.end());
    bool accepted = false;
    for (int b = 0; b < 60; ++b, alpha *= 0.5) {
      ControlState trial = p.evaluate(s.beta - alpha * g);
      if (std::isfinite(trial.J) && trial.J <= reference - 1e-4 * alpha * g2) {
        betaOld = s.beta;
        gOld = g;
        s = std::move(trial);
        accepted = true;
        break;
      }
    }
    r.iterations = k;
    if (!accepted) {
      r.history.push_back(record(p, s, k, 0));
      r.status = converged(p, s, 0) ? OptimizerStatus::converged : OptimizerStatus::stalled;
      beta = s.beta;
      return r;
    }
    lastStep = p.norm(s.beta - betaOld);
    r.history.push_back(record(p, s, k, lastStep));
    recent.push_back(s.J);
    if (recent.size() > 10) recent.erase(recent.begin());
    g = p.gradient(s);
  }
  if (converged(p, s, lastStep)) r.status = OptimizerStatus::converged;
  beta = s.beta;
  return r;
}

OptimizerReport Lbfgs::minimize(ControlProblem& p, Eigen::VectorXd& beta) {
  OptimizerReport r;
  ControlState s = p.evaluate(beta);
  r.history.push_back(record(p, s, 0, -1));
  Eigen::VectorXd g = p.gradient(s);
  std::vector<Eigen::VectorXd> S, Y;
  std::vector<double> rho;
  double lastStep = -1;
  for (int k = 1; k <= stop_.maxIterations; ++k) {
    if (converged(p, s, lastStep)) {
      r.status = OptimizerStatus::converged;
      break;
    }
    // Two-loop recursion in the M inner product.
    Eigen::VectorXd q = g;
    std::vector<double> a(S.size());
    for (int i = static_cast<int>(S.size()) - 1; i >= 0; --i) {
      a[i] = rho[i] * p.dot(S[i], q);
      q -= a[i] * Y[i];
    }
    double scale = alpha();
    if (!S.empty()) scale = p.dot(S.back(), Y.back()) / p.dot(Y.back(), Y.back());
    Eigen::VectorXd d = scale * q;
    for (std::size_t i = 0; i < S.size(); ++i) {
      const double b = rho[i] * p.dot(Y[i], d);
      d += (a[i] - b) * S[i];
    }
    d = -d;
    double slope = p.dot(g, d);
    if (!(slope < 0)) {  // not a descent direction (a kink, or stale pairs): restart
      d = -alpha() * g;
      slope = p.dot(g, d);
      S.clear(), Y.clear(), rho.clear();
    }
    if (slope == 0) {
      r.status = OptimizerStatus::stalled;
      break;
    }
    double t = 1;
    bool accepted = false;
    for (int b = 0; b < maxBacktracks_; ++b, t *= 0.5) {
      ControlState trial = p.evaluate(s.beta + t * d);
      if (std::isfinite(trial.J) && trial.J < s.J && trial.J <= s.J + 1e-4 * t * slope) {
        const Eigen::VectorXd gNew = p.gradient(trial);
        const Eigen::VectorXd sv = trial.beta - s.beta, y = gNew - g;
        const double sy = p.dot(sv, y);
        if (sy > 1e-14 * p.norm(sv) * p.norm(y)) {  // keep the curvature pairs positive
          S.push_back(sv), Y.push_back(y), rho.push_back(1 / sy);
          if (static_cast<int>(S.size()) > memory_)
            S.erase(S.begin()), Y.erase(Y.begin()), rho.erase(rho.begin());
        }
        lastStep = p.norm(sv);
        s = std::move(trial);
        g = gNew;
        accepted = true;
        break;
      }
    }
    r.iterations = k;
    r.history.push_back(record(p, s, k, accepted ? lastStep : 0));
    if (!accepted) {
      r.status = converged(p, s, 0) ? OptimizerStatus::converged : OptimizerStatus::stalled;
      beta = s.beta;
      return r;
    }
  }
  if (converged(p, s, lastStep)) r.status = OptimizerStatus::converged;
  beta = s.beta;
  return r;
}

namespace {

/// GMRES's restart length: the Arnoldi basis holds at most this many vectors (and as many
/// preconditioned ones, flexible GMRES), which the krylov variant's memory count reads.
constexpr Eigen::Index gmresRestart = 60;

// SemismoothNewton::setKeptProductsForTests: 0, or the tests' smaller cap.
int keptProductsOverride = 0;

// Restarted GMRES for a small nonsymmetric system A x = b given by its action; x starts at 0.
// With a right preconditioner M (x = M u, GMRES on A M u = b) the residual it judges is still
// b − A x. Stops at ‖b − A x‖ ≤ tol ‖b‖ or after maxProducts products with A; `products`
// returns how many it made.
//
// A recycled space U (columns) with its products AU = A U known costs no product: GMRES then
// minimises over span U as well (GCRO with a fixed space, de Sturler 1999): AU = Q R, each
// cycle starts from x + U R⁻¹ Qᵀ r and runs Arnoldi on (I − Q Qᵀ) A M. Columns of AU that
// depend on the others (pivots below 1e-7 of the largest) are left out.
//
// The products' arguments z_j = M v_j are kept (flexible GMRES), so that
// x = Σ_j weights[j] z_j + U recycledWeights over the vectors given to A0, in the order they
// were given: a caller that keeps what else each product yields (S z_j) has it for x without
// another product. A restart's residual product gets weight 0.
struct GmresAnswer {
  Eigen::VectorXd x;
  std::vector<double> weights;
  Eigen::VectorXd recycledWeights;
  bool reached = true;  ///< ‖b − A x‖ ≤ tol ‖b‖ (false: stopped at maxProducts)
};

GmresAnswer gmres(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& A0,
                  const Eigen::VectorXd& b, double tol, int maxProducts, int& products,
                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& M = nullptr,
                  const Eigen::MatrixXd& U = Eigen::MatrixXd(),
                  const Eigen::MatrixXd& AU = Eigen::MatrixXd(),
                  int restart = static_cast<int>(gmresRestart)) {
  const Eigen::Index n = b.size();
  GmresAnswer out{Eigen::VectorXd::Zero(n), {}, Eigen::VectorXd::Zero(U.cols())};
  Eigen::VectorXd& x = out.x;
  const double bnorm = b.norm();
  products = 0;
  if (bnorm == 0) return out;
  const auto A = [&](const Eigen::VectorXd& z) {
    ++products;
    out.weights.push_back(0.0);
    return A0(z);
  };
  // The recycled space's orthonormal basis Q of A U, its R and which columns of U it keeps.
  Eigen::MatrixXd Q(n, 0), R(0, 0);
  std::vector<Eigen::Index> kept;
  if (U.cols() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(AU.rows(), AU.cols());
    qr.setThreshold(1e-7);
    qr.compute(AU);
    const Eigen::Index r = qr.rank();
    Q = qr.householderQ() * Eigen::MatrixXd::Identity(n, r);
    R = qr.matrixR().topLeftCorner(r, r).triangularView<Eigen::Upper>();
    for (Eigen::Index j = 0; j < r; ++j) kept.push_back(qr.colsPermutation().indices()[j]);
  }
  // x += U R⁻¹ c: the recycled part of a cycle's answer.
  const auto addRecycled = [&](const Eigen::VectorXd& c) {
    const Eigen::VectorXd w = R.triangularView<Eigen::Upper>().solve(c);
    for (std::size_t j = 0; j < kept.size(); ++j) {
      x += w[j] * U.col(kept[j]);
      out.recycledWeights[kept[j]] += w[j];
    }
  };
  bool first = true;
  out.reached = false;
  while (products < maxProducts) {
    Eigen::VectorXd r = first ? b : Eigen::VectorXd(b - A(x));
    first = false;
    if (Q.cols() > 0) {  // the best answer in span U first: r ⊥ A U after it
      const Eigen::VectorXd c = Q.transpose() * r;
      addRecycled(c);
      r -= Q * c;
    }
    const double beta0 = r.norm();
    if (beta0 <= tol * bnorm) {
      out.reached = true;
      break;
    }
    const int m = std::min<int>(restart, static_cast<int>(n));
    Eigen::MatrixXd V(n, m + 1), Z(n, m), H = Eigen::MatrixXd::Zero(m + 1, m);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(Q.cols(), m);  // Qᵀ A z_j
    std::vector<std::size_t> at(m);                          // which product each column of Z is
    Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs(m), sn(m);
    V.col(0) = r / beta0;
    g[0] = beta0;
    int k = 0;
    for (; k < m && products < maxProducts; ++k) {
      Z.col(k) = M ? M(V.col(k)) : Eigen::VectorXd(V.col(k));
      at[k] = out.weights.size();
      Eigen::VectorXd w = A(Z.col(k));
      for (Eigen::Index i = 0; i < Q.cols(); ++i) {  // (I − Q Qᵀ) A z_j
        B(i, k) = w.dot(Q.col(i));
        w -= B(i, k) * Q.col(i);
      }
      for (int i = 0; i <= k; ++i) {  // modified Gram–Schmidt
        H(i, k) = w.dot(V.col(i));
        w -= H(i, k) * V.col(i);
      }
      H(k + 1, k) = w.norm();
      if (H(k + 1, k) > 0) V.col(k + 1) = w / H(k + 1, k);
      for (int i = 0; i < k; ++i) {  // apply the earlier rotations
        const double t = cs[i] * H(i, k) + sn[i] * H(i + 1, k);
        H(i + 1, k) = -sn[i] * H(i, k) + cs[i] * H(i + 1, k);
        H(i, k) = t;
      }
      const double d = std::hypot(H(k, k), H(k + 1, k));
      cs[k] = d > 0 ? H(k, k) / d : 1;
      sn[k] = d > 0 ? H(k + 1, k) / d : 0;
      H(k, k) = d;
      H(k + 1, k) = 0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::abs(g[k + 1]) <= tol * bnorm || H(k, k) == 0) {
        ++k;
        break;
      }
    }
    const Eigen::VectorXd y = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    x += Z.leftCols(k) * y;
    for (int j = 0; j < k; ++j) out.weights[at[j]] += y[j];
    if (Q.cols() > 0) addRecycled(-B.leftCols(k) * y);  // keeps b − A x ⊥ A U
    if (std::abs(g[k]) <= tol * bnorm) {
      out.reached = true;
      break;
    }
  }
  return out;
}

// Puts the case's γ back however minimize() leaves (Newton may iterate with its own).
struct RestoreGamma {
  ControlProblem& p;
  double gamma;
  ~RestoreGamma() { p.setGamma(gamma); }
};

std::string newtonGammaNote(double gammaNewton, double gammaCase) {
  std::ostringstream note;
  note << std::setprecision(3) << "Newton's gamma " << gammaNewton << " Pa/m: the case's is "
       << (gammaCase < gammaNewton ? "< 1e-2" : "> 10") << " x the interface stiffness";
  return note.str();
}

}  // namespace

bool SemismoothNewton::lineSearch(ControlProblem& p, ControlState& s,
                                  const std::function<ControlState(double)>& trialAt,
                                  double& lastStep, std::vector<int>& states) {
  // Backtracking on the merit ½‖D‖²_M; counts active-set changes for the cycling report.
  const double merit = 0.5 * p.dot(s.D, s.D);
  double t = 1;
  for (int b = 0; b < maxBacktracks_; ++b, t *= 0.5) {
    ControlState trial = trialAt(t);
    if (0.5 * p.dot(trial.D, trial.D) <= (1 - 1e-4 * t) * merit) {
      lastStep = p.norm(trial.beta - s.beta);
      // A node's stick/slip/open state, and with openings whether its faces touch.
      std::vector<int> now;
      for (const auto& c : trial.node) now.push_back(static_cast<int>(c.state));
      for (const char c : trial.contact) now.push_back(c);
      if (!states.empty() && now != states) ++activeSetChanges_;
      states = std::move(now);
      s = std::move(trial);
      return true;
    }
  }
  return false;
}

OptimizerReport& SemismoothNewton::finish(ControlProblem& p, const ControlState& s, double lastStep,
                                          OptimizerReport& r, Eigen::VectorXd& beta) {
  if (r.status != OptimizerStatus::stalled && converged(p, s, lastStep))
    r.status = OptimizerStatus::converged;
  // An active set that keeps changing without the residual closing is cycling: say so
  // instead of looping silently.
  if (r.status != OptimizerStatus::converged && activeSetChanges_ > 2)
    r.note = "active set changed " + std::to_string(activeSetChanges_) +
             " times without converging (cycling between " +
             (p.hasOpening() ? "stick, slip, open and closed)" : "stick and slip)");
  beta = s.beta;
  return r;
}

// Variant auto's thresholds, from the wall time of whole runs against the same mesh's linear
// solve (README "Newton's variant by fault size"; P1, Newton to 1e-10, this 2-core machine).
// What decides is which extra work is larger: condensed's dense S (the border's fill, the
// complement, Newton's LU on it) grows like (k·n)³, krylov's ~50–90 back-substitutions (GMRES
// products, trial points, the probing block) like the factor, ~dofs^(4/3) in 3D.
//  * 3D, the penny crack: even at 1 002 nodes in 24 003 dofs (3.6 s against 3.9 s,
//    interfaceBenchmark.sh); krylov 4x faster at 2 387 nodes in 46 446 dofs (6.1 s against
//    24.1 s) and 2.6x at 4 178 nodes in 312 180 dofs (99 s against 256 s, pennyBenchmark.sh);
//    condensed faster at 2 387 nodes in 678 102 dofs (263 s, 1.07x the linear solve, against
//    ~80 single back-substitutions of 1.3–2.7 s each). Even where n ∝ dofs^(4/9), through the
//    1 002-node point: n ≥ 11.3 dofs^(4/9) (3 130 nodes at 312 180 dofs, 4 410 at 678 102),
//    and never below 1 000 nodes, where the dense S costs a fraction of a second.
//  * 2D, the inclined crack (interfaceBenchmark.sh; one family of meshes, the dofs growing
//    with the crack). Measured first with whole back-substitutions and before the krylov
//    variant's solve cuts: condensed faster at 2 049 nodes (8.1 s against 16.8 s), krylov at
//    5 001 (31 s against 59 s), so 3 000. Measured again 2026-11-29 with its products solved on
//    the fault's reach (2.5x cheaper in 2D): condensed faster at 513 nodes (1.45 s against
//    1.54 s), krylov at 1 025 (3.0–3.7 s against 4.0–4.3 s), 1 537 (4.7–4.9 s against
//    5.3–6.2 s), 2 049 (6.4–6.6 s against 7.1–8.4 s), 3 073 (11.6–12.3 s against 15.1 s) and
//    4 097 (14.7–16.5 s against 27.4 s): even between 513 and 1 025 nodes.
constexpr Eigen::Index krylovFromNodes2D = 1000;
constexpr double krylovNodeScale3D = 11.3;  // n ≥ scale · dofs^(4/9) in 3D
constexpr Eigen::Index krylovFromNodesMin3D = 1000;
// From this ν on, variant auto's line warns that krylov's probed preconditioner is weak.
constexpr double krylovWeakPoisson = 0.45;

Eigen::Index SemismoothNewton::krylovFromNodes(int dimension, Eigen::Index dofs) {
  if (dimension != 3) return krylovFromNodes2D;
  const double n = krylovNodeScale3D * std::pow(static_cast<double>(dofs), 4.0 / 9.0);
  return std::max(krylovFromNodesMin3D, static_cast<Eigen::Index>(std::ceil(n)));
}

std::string SemismoothNewton::chooseFor(const CaseFacts& facts) {
  if (!automatic_) return "";
  automatic_ = false;  // chosen once: a second call changes nothing
  const Eigen::Index threshold = krylovFromNodes(facts.dimension, facts.dofs);
  // An iterative linear solver has no factor to take S from: forming it costs one solve per
  // jump unknown, krylov's products a few dozen, whatever the size.
  const bool iterative = !facts.iterativeSolver.empty();
  const bool large = iterative || facts.fractureNodes >= threshold;
  // P2 in 3D: the tractions come from the consistent mass of the fault's triangles
  // (FractureSystem::buildRecovery), which spreads S beyond the probed neighbourhood, and the
  // probing preconditioner no longer holds: on the 1 038-node P2 penny (75 657 dofs) GMRES took
  // 1 400 products for 10⁻³ in the first Newton iteration, and the step ran > 10 min where
  // condensed takes 2 s (README "Newton's variant by fault size").
  const bool krylovFits = facts.dimension == 2 || facts.elementOrder == 1;
  variant_ =
      large && krylovFits && facts.needsDenseS.empty() ? Variant::krylov : Variant::condensed;
  std::ostringstream line;
  line << "Newton variant: " << (variant_ == Variant::krylov ? "krylov" : "condensed")
       << " (variant auto: " << facts.fractureNodes << " fracture control nodes "
       << (facts.fractureNodes >= threshold ? ">= " : "< ") << threshold << ", the "
       << facts.dimension << "D threshold for krylov";
  if (facts.dimension == 3) line << " at " << facts.dofs << " dofs";
  if (iterative && facts.fractureNodes < threshold && variant_ == Variant::krylov)
    line << "; krylov all the same: linear solver " << facts.iterativeSolver
         << " has no factor, so S would cost one solve per jump unknown";
  if (large && !facts.needsDenseS.empty())
    line << "; condensed all the same: the dense S is needed for " << facts.needsDenseS;
  else if (large && !krylovFits)
    line << "; condensed all the same: krylov's probed preconditioner does not hold for P2 "
            "faults in 3D";
  // Measured on the committed penny at ν = 0.49: 1 776 GMRES products in one Newton iteration
  // (cholmod and amg alike), against 3–8 at ν = 0.25 (README "The largest 3D models").
  if (variant_ == Variant::krylov && facts.maxPoissonRatio >= krylovWeakPoisson)
    line << "; note: at nu " << facts.maxPoissonRatio
         << " krylov's probed preconditioner is weak (thousands of GMRES products per Newton "
            "iteration measured at nu 0.49); variant condensed is robust there where its dense "
            "S fits";
  line << ")";
  return line.str();
}

std::string SemismoothNewton::prepare(SlipResponse& resp, bool withOpening) {
  // The krylov variant's probing needs a ControlProblem: it stays in the first step.
  if (variant_ != Variant::condensed || resp.size() == 0) return "";
  S_ = resp.interfaceOperator(interfaceMethod_, withOpening);
  cachedFor_ = &resp;
  std::ostringstream s;
  s << "Newton's interface operator in the fractures' frame (S_tt " << S_.Stt.rows() << " x "
    << S_.Stt.cols() << (withOpening ? ", with the openings' rows and columns" : "") << ", from "
    << (S_.method == InterfaceMethod::factorisation ? "the factorisation's complement"
        : S_.method == InterfaceMethod::blockSolves ? "blocks of back-substitutions"
                                                    : "one dual solve per node")
    << ")";
  return s.str();
}

void SemismoothNewton::tangentStiffness(ControlProblem& p, const ControlState& s,
                                        OptimizerReport& r) const {
  // The slipping nodes' free components: stick nodes are held (β = 0 there), so the patch's
  // stability is that of G restricted to the slipping ones.
  const Eigen::Index n = p.numNodes(), k = p.blockSize();
  const Eigen::VectorXd& w = p.response().weights();
  std::vector<Eigen::Index> slipping;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (p.freeMask()[i] == 0 || s.node[static_cast<std::size_t>(i)].state != SlipState::slip)
      continue;
    for (Eigen::Index c = 0; c < k; ++c)
      if (p.componentMask()[k * i + c] != 0) slipping.push_back(k * i + c);
  }
  const Eigen::Index m = static_cast<Eigen::Index>(slipping.size());
  r.stiffnessComponents = m;
  if (m == 0) return;
  // W·G is symmetric where G is S_tt alone (M·S is); its symmetric part's smallest eigenvalue
  // decides whether a slip perturbation on the patch is resisted (> 0) or runs away (≤ 0).
  Eigen::MatrixXd A(m, m);
  double scale = 0;
  for (Eigen::Index a = 0; a < m; ++a) {
    const double wa = w[slipping[static_cast<std::size_t>(a)] / k];
    for (Eigen::Index b = 0; b < m; ++b)
      A(a, b) = wa * p.jacobianEntry(s, S_.Stt, S_.Snt, slipping[a], slipping[b]);
    scale += wa * S_.Stt(slipping[a], slipping[a]);
  }
  const Eigen::MatrixXd sym = 0.5 * (A + A.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(sym, Eigen::EigenvaluesOnly);
  scale /= static_cast<double>(m);
  r.tangentStiffness = eig.eigenvalues()[0] / (scale > 0 ? scale : 1.0);
}

OptimizerReport SemismoothNewton::minimize(ControlProblem& p, Eigen::VectorXd& beta) {
  if (variant_ == Variant::krylov) return minimizeKrylov(p, beta);
  SlipResponse& resp = p.response();
  const Eigen::Index n = p.numNodes(), k = p.blockSize(), size = p.size();
  const Eigen::VectorXd& mask = resp.freeMask();
  long setupSolves = 0;
  const bool opening = p.hasOpening();
  const Eigen::Index kn = k * n;
  if (cachedFor_ != &resp || S_.Stt.rows() != kn || (opening && S_.Snn.rows() != n)) {
    // Once per run: S depends only on the mesh and the Dirichlet patches.
    S_ = resp.interfaceOperator(interfaceMethod_, opening);
    setupSolves = S_.solves;
    cachedFor_ = &resp;
  }

  OptimizerReport r;
  r.setupSolves = setupSolves;
  activeSetChanges_ = 0;
  // One primal solve gives the affine maps' offsets; the rest is dense.
  const ControlState s0 = p.evaluate(Eigen::VectorXd::Zero(size));
  const Eigen::VectorXd tau0 = s0.tau, sigma0 = s0.sigmaN;
  auto stateAt = [&](const Eigen::VectorXd& b) {
    const Eigen::VectorXd bm = b.cwiseProduct(p.componentMask());
    if (!opening) return p.stateFrom(bm, tau0 + S_.Stt * bm, sigma0 + S_.Snt * bm);
    const auto bt = bm.head(kn), g = bm.tail(n);
    return p.stateFrom(bm, tau0 + S_.Stt * bt + S_.Stn * g, sigma0 + S_.Snt * bt + S_.Snn * g);
  };

  // In 3D (k ≥ 2) the slip's direction enters D through N̂ = (τ − γβ)/|τ − γβ|, whose
  // linearisation holds only while γ|Δβ| is small against |N| − ρ: with γ far below the
  // interface stiffness (the diagonal of S_tt), Newton's steps along the slip's direction
  // overshoot and the line search cuts them to nothing (measured: gammaRelative 1e-5 on the
  // fault in a cube, J falling 1 % an iteration over 100). D = 0 does not depend on γ (only
  // the path does), so Newton then iterates with γ_N = the mean diagonal of S_tt and checks
  // the stop rule with the case's γ before it stops. With k = 1 there is no such direction:
  // 2D iterates with the case's γ, as always.
  const double gammaCase = p.gamma();
  const double gammaNewton = newtonGamma(p, S_.Stt.diagonal());
  // Openings: the same for γ_n, from the other side. With γ_n far above the normal interface
  // stiffness (−the diagonal of S_nn: opening the faces compresses them), a node that a step
  // opened and whose faces must close again keeps σ'_n + γ_n g > 0 for the smallest g > 0: it
  // is classed open, Newton drives its σ'_n to 0 with a g < 0, the next iterate classes it
  // closed, and so on (measured on a tilted penny whose pressure drops, warm-started, the
  // stiffness 0.93 E/h: gammaNormalRelative 1e2, 1e3, 1e5 cycled for 100 iterations, 1e1 took
  // 15 against 9 from 1e-5 to 1). D = 0 does not depend on γ_n (g = 0 in contact): Newton then
  // iterates with γ_n = that stiffness (mean over the nodes) and judges the stop with the
  // case's γ_n.
  const double gammaNCase = opening ? p.openingSettings().gammaN : 0;
  double gammaNNewton = gammaNCase;
  if (opening) {
    double diagonal = 0;
    int count = 0;
    for (Eigen::Index i = 0; i < n; ++i)
      if (p.componentMask()[kn + i] != 0 && S_.Snn(i, i) < 0) diagonal -= S_.Snn(i, i), ++count;
    if (count > 0 && gammaNCase > 10 * diagonal / count) gammaNNewton = diagonal / count;
  }
  struct RestoreGammas {
    ControlProblem& p;
    double gamma, gammaN;
    bool opening;
    ~RestoreGammas() {
      p.setGamma(gamma);
      if (opening) p.setGammaNormal(gammaN);
    }
  } restore{p, gammaCase, gammaNCase, opening};
  p.setGamma(gammaNewton);
  if (opening) p.setGammaNormal(gammaNNewton);
  if (gammaNewton != gammaCase) r.note = newtonGammaNote(gammaNewton, gammaCase);
  if (gammaNNewton != gammaNCase) {
    std::ostringstream note;
    note << std::setprecision(3) << "Newton's gammaNormal " << gammaNNewton
         << " Pa/m: the case's is > 10 x the normal interface stiffness";
    r.note += (r.note.empty() ? "" : "; ") + note.str();
  }
  const auto caseGammas = [&] {
    return p.gamma() == gammaCase && (!opening || p.openingSettings().gammaN == gammaNCase);
  };
  const auto useCaseGammas = [&] {
    p.setGamma(gammaCase);
    if (opening) p.setGammaNormal(gammaNCase);
  };
  ControlState s = stateAt(beta);
  r.history.push_back(record(p, s, 0, -1));
  double lastStep = -1;
  std::vector<int> states;
  for (int it = 1; it <= stop_.maxIterations; ++it) {
    if (converged(p, s, lastStep)) {
      if (caseGammas()) {
        r.status = OptimizerStatus::converged;
        break;
      }
      // The same β with the case's γ and γ_n: converged there too, or Newton goes on with them.
      useCaseGammas();
      s = stateAt(s.beta);
      if (converged(p, s, lastStep)) {
        r.status = OptimizerStatus::converged;
        break;
      }
    }
    // Generalised Jacobian on the free nodes. Stick rows read γ δ_i = −γ β_i: they give
    // δ_i = −β_i exactly (β = 0 at once), so only the other nodes' components enter the
    // linear solve.
    std::vector<Eigen::Index> active;  // components k·i + c of the slip and open nodes
    Eigen::VectorXd dir = Eigen::VectorXd::Zero(size);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (mask[i] == 0) continue;
      for (Eigen::Index c = 0; c < k; ++c) {
        if (p.componentMask()[k * i + c] == 0) continue;  // held by a roller: β stays 0
        if (s.node[i].state == SlipState::stick)
          dir[k * i + c] = -s.beta[k * i + c];
        else
          active.push_back(k * i + c);
      }
    }
    // Openings: a node in contact reads −γ_n δg = γ_n g, so g = 0 at once, like a stick row;
    // an open node's g is an unknown of the linear solve.
    for (Eigen::Index i = 0; opening && i < n; ++i) {
      if (p.componentMask()[kn + i] == 0) continue;
      if (s.contact[i])
        dir[kn + i] = -s.beta[kn + i];
      else
        active.push_back(kn + i);
    }
    const auto entry = [&](Eigen::Index row, Eigen::Index col) {
      return opening ? p.jacobianEntryWithOpening(s, S_, row, col)
                     : p.jacobianEntry(s, S_.Stt, S_.Snt, row, col);
    };
    const Eigen::Index m = static_cast<Eigen::Index>(active.size());
    if (m > 0) {
      Eigen::MatrixXd G(m, m);
      Eigen::VectorXd rhs(m);
      for (Eigen::Index a = 0; a < m; ++a) {
        for (Eigen::Index b = 0; b < m; ++b) G(a, b) = entry(active[a], active[b]);
        // Move the known stick increments to the right-hand side.
        double known = 0;
        for (Eigen::Index j = 0; j < size; ++j)
          if (dir[j] != 0) known += entry(active[a], j) * dir[j];
        rhs[a] = -s.D[active[a]] - known;
      }
      // LAPACK's LU: at thousands of slipping nodes this is the iteration's whole cost.
      const bool solved = luSolveInPlace(G, rhs);
      for (Eigen::Index a = 0; a < m; ++a)
        dir[active[a]] = solved ? rhs[a] : std::numeric_limits<double>::quiet_NaN();
    }
    if (!dir.allFinite()) {
      r.status = OptimizerStatus::stalled;
      r.note += std::string(r.note.empty() ? "" : "; ") +
                "the Newton system on the non-stick nodes is singular";
      break;
    }
    const bool accepted = lineSearch(
        p, s, [&](double t) { return stateAt(s.beta + t * dir); }, lastStep, states);
    r.iterations = it;
    r.history.push_back(record(p, s, it, accepted ? lastStep : 0));
    if (!accepted) {
      r.status = converged(p, s, 0) ? OptimizerStatus::converged : OptimizerStatus::stalled;
      break;
    }
  }
  // What is written and judged is the state with the case's γ and γ_n.
  if (!caseGammas()) {
    useCaseGammas();
    s = stateAt(s.beta);
    if (r.status == OptimizerStatus::converged && !converged(p, s, 0))
      r.status = OptimizerStatus::maxIterations;
  }
  if (p.weakens()) tangentStiffness(p, s, r);
  return finish(p, s, lastStep, r, beta);
}

void SemismoothNewton::setKeptProductsForTests(int count) {
  keptProductsOverride = std::max(count, 0);
}

OptimizerReport SemismoothNewton::minimizeKrylov(ControlProblem& p, Eigen::VectorXd& beta) {
  FRICTION_ASSERT(!p.hasOpening(), "the krylov variant is refused for fractures that open");
  SlipResponse& resp = p.response();
  const Eigen::Index n = p.numNodes(), k = p.blockSize(), size = p.size();
  const Eigen::VectorXd& mask = resp.freeMask();
  OptimizerReport r;
  if (cachedFor_ != &resp || diagonal_.size() != k * n) {
    // Once per run, like the condensed S: the probed S depends only on the mesh and the
    // Dirichlet patches.
    const std::vector<std::vector<Eigen::Index>> graph = resp.nodeGraph();
    krylovPreconditioner_.reset();
    diagonal_ = Eigen::VectorXd::Zero(k * n);
    if (static_cast<Eigen::Index>(graph.size()) == n) {
      if (preconditioner_ != KrylovPreconditioning::none) {
        const int distance =
            preconditioner_ == KrylovPreconditioning::blockDiagonal ? 0 : probingDistance_;
        ProbedInterfaceOperator op =
            probeInterfaceOperator(resp, graph, distance, probingSeparation(distance));
        r.setupSolves = op.solves;
        diagonal_ = Eigen::VectorXd(op.Stt.diagonal());
        krylovPreconditioner_ = std::make_shared<KrylovPreconditioner>(std::move(op));
      } else if (k >= 2) {
        // k solves: the nodes of one colour 5 hops apart, where a neighbour's share is small.
        diagonal_ = sampledDiagonal(resp, graph, 5, r.setupSolves);
      }
    }
    cachedFor_ = &resp;
  }
  activeSetChanges_ = 0;
  // Newton's own γ in 3D, as the condensed variant (minimize()): the interface stiffness
  // from the probed (or sampled) diagonal of S_tt.
  const double gammaCase = p.gamma(), gammaNewton = newtonGamma(p, diagonal_);
  RestoreGamma restore{p, gammaCase};
  p.setGamma(gammaNewton);
  if (gammaNewton != gammaCase) r.note = newtonGammaNote(gammaNewton, gammaCase);
  // States at another γ without a solve: D from the tractions already known.
  const auto atGamma = [&p](const ControlState& s) { return p.stateFrom(s.beta, s.tau, s.sigmaN); };
  ControlState s = p.evaluate(beta);
  r.history.push_back(record(p, s, 0, -1));
  double lastStep = -1;
  std::vector<int> states;
  std::vector<int> products;  // GMRES products per Newton iteration, for the log
  std::vector<int> capped;    // Newton iterations whose GMRES stopped at its limit
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  // S v: one dual solve gives S_tt v (k·n) and S_nt v (n).
  struct Image {
    Eigen::VectorXd t, sn;
  };
  const auto image = [&](const Eigen::VectorXd& v) {
    throwIfStopNow();  // a second SIGINT/SIGTERM abandons the step between two solves
    Image Sv;
    resp.dual(v, zero, Sv.t, &Sv.sn);
    return Sv;
  };
  // This step's GMRES products so far: vector (k·n) and S of it, the newest last. Later
  // Newton iterations reuse them without a solve (S is one matrix for the whole step). Not
  // kept across steps: a restarted run would start without them and write other round-off
  // than the uninterrupted run (measured gain across steps: 140 → 126 back-substitutions on
  // cases/strikeSlipFault's 8 steps, not worth a restart that is not byte for byte).
  struct Kept {
    Eigen::VectorXd z;
    Image Sz;
  };
  std::deque<Kept> recycled;
  constexpr std::size_t maxRecycled = 60;
  // An iteration's own products kept to sum S dir from: GMRES's restart length (more products
  // than that, and S dir costs one product instead; setKeptProductsForTests()).
  const std::size_t maxCalls = keptProductsOverride > 0
                                   ? static_cast<std::size_t>(keptProductsOverride)
                                   : static_cast<std::size_t>(gmresRestart);
  double heldKept = 0, heldGmres = 0;  // the largest of an iteration, for the log
  for (int it = 1; it <= stop_.maxIterations; ++it) {
    if (converged(p, s, lastStep)) {
      if (p.gamma() == gammaCase) {
        r.status = OptimizerStatus::converged;
        break;
      }
      p.setGamma(gammaCase);
      s = atGamma(s);
      if (converged(p, s, lastStep)) {
        r.status = OptimizerStatus::converged;
        break;
      }
    }
    // G v on the free nodes from S v = (S_tt v, S_nt v), which one dual solve gives. Row r of
    // node i: ((I − P'_N) S_tt v)_r + μ P'_ρ,r (S_nt v)_i + γ (P'_N v)_r, summed in the order
    // of the scalar expression.
    auto applyG = [&](const Eigen::VectorXd& v, const Image& Sv) {
      Eigen::VectorXd out(size);
      for (Eigen::Index i = 0; i < n; ++i) {
        const NodeComplementarity& c = s.node[i];
        for (Eigen::Index row = 0; row < k; ++row) {
          if (mask[i] == 0) {
            out[k * i + row] = 0.0;
            continue;
          }
          double a = ((row == 0 ? 1.0 : 0.0) - c.dPdN(row, 0)) * Sv.t[k * i];
          double g = p.gamma() * c.dPdN(row, 0) * v[k * i];
          for (Eigen::Index j = 1; j < k; ++j) {
            a += ((row == j ? 1.0 : 0.0) - c.dPdN(row, j)) * Sv.t[k * i + j];
            g += p.gamma() * c.dPdN(row, j) * v[k * i + j];
          }
          out[k * i + row] = a + p.mu()[i] * c.dPdRho[row] * Sv.sn[i] + g;
        }
      }
      return out;
    };
    Eigen::VectorXd dir = Eigen::VectorXd::Zero(size);
    std::vector<Eigen::Index> active;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (mask[i] == 0) continue;
      for (Eigen::Index c = 0; c < k; ++c) {
        if (p.componentMask()[k * i + c] == 0) continue;  // held by a roller: β stays 0
        if (s.node[i].state == SlipState::stick)
          dir[k * i + c] = -s.beta[k * i + c];  // β = 0 at once on the stick nodes
        else
          active.push_back(k * i + c);
      }
    }
    // S dir, summed from the dual solves made for it: the line search's trial states then
    // need no solve (S is linear: τ(β + t dir) = τ(β) + t S dir).
    Image Sdir{Eigen::VectorXd::Zero(size), Eigen::VectorXd::Zero(n)};
    const Eigen::Index m = static_cast<Eigen::Index>(active.size());
    int made = 0;
    Eigen::VectorXd rhsFull = -s.D;
    if (dir.squaredNorm() > 0) {
      Sdir = image(dir);
      rhsFull -= applyG(dir, Sdir);
    }
    if (m > 0) {
      Eigen::VectorXd rhs(m);
      for (Eigen::Index a = 0; a < m; ++a) rhs[a] = rhsFull[active[a]];
      // This step's earlier products whose vectors live on these active components: GMRES
      // gets them as a recycled space, their G-products from S already known.
      std::vector<char> isActive(size, 0);
      for (const Eigen::Index c : active) isActive[c] = 1;
      std::vector<const Kept*> usable;
      for (const Kept& kp : recycled) {
        bool inside = true;
        for (Eigen::Index c = 0; c < size && inside; ++c) inside = isActive[c] || kp.z[c] == 0;
        if (inside) usable.push_back(&kp);
      }
      const Eigen::Index p0 = static_cast<Eigen::Index>(usable.size());
      Eigen::MatrixXd U(m, p0), AU(m, p0);
      for (Eigen::Index j = 0; j < p0; ++j) {
        const Eigen::VectorXd Gu = applyG(usable[j]->z, usable[j]->Sz);
        for (Eigen::Index a = 0; a < m; ++a) {
          U(a, j) = usable[j]->z[active[a]];
          AU(a, j) = Gu[active[a]];
        }
      }
      std::vector<Kept> calls;  // the first maxCalls products' vectors and S of them
      bool dropped = false;     // a later product was not kept: S dir from a product of its own
      auto applyActive = [&](const Eigen::VectorXd& vA) {
        Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
        for (Eigen::Index a = 0; a < m; ++a) v[active[a]] = vA[a];
        Image Sv = image(v);
        const Eigen::VectorXd Gv = applyG(v, Sv);
        if (calls.size() < maxCalls)
          calls.push_back({std::move(v), std::move(Sv)});
        else
          dropped = true;
        Eigen::VectorXd out(m);
        for (Eigen::Index a = 0; a < m; ++a) out[a] = Gv[active[a]];
        return out;
      };
      std::function<Eigen::VectorXd(const Eigen::VectorXd&)> precondition;
      if (krylovPreconditioner_ && krylovPreconditioner_->factor(p, s, active))
        precondition = [this](const Eigen::VectorXd& v) { return krylovPreconditioner_->apply(v); };
      // Inexact Newton: solve as accurately as the current residual warrants (η ≤ ‖D‖/‖Σ‖,
      // at most 1e-3), and no more accurately than the stop rule needs: the step leaves about
      // η‖D‖, so with the residual rule η = 0.1 · tolerance / (‖D‖/‖Σ‖) stops at the next
      // iterate with a margin of 10 (the last iteration's products fall by about half).
      const double rel = p.relativeResidual(s);
      double eta = std::max(1e-10, std::min(1e-3, rel));
      if (stop_.on == StopRule::On::residual && rel > 0)
        eta = std::max(eta, std::min(0.1, 0.1 * stop_.tolerance / rel));
      const GmresAnswer delta =
          gmres(applyActive, rhs, eta, static_cast<int>(std::min<Eigen::Index>(4 * m, 2000)), made,
                precondition, U, AU);
      if (!delta.reached) capped.push_back(it);
      // What this iteration held for the fault, counted from the arrays' sizes: the step's
      // products (vector, S_tt and S_nt of it) and GMRES's (its basis V, Z of the restart
      // length, the recycled U, A U and their basis Q).
      const double kept = static_cast<double>(recycled.size() + calls.size()) *
                          static_cast<double>(2 * size + n) * sizeof(double);
      const double basis =
          static_cast<double>(2 * std::min<Eigen::Index>(gmresRestart, m) + 1 + 3 * p0) *
          static_cast<double>(m) * sizeof(double);
      if (kept + basis > heldKept + heldGmres) heldKept = kept, heldGmres = basis;
      for (Eigen::Index a = 0; a < m; ++a) dir[active[a]] = delta.x[a];
      if (dropped) {
        Sdir = image(dir);  // the whole direction's, stick part included
      } else {
        for (std::size_t j = 0; j < calls.size(); ++j) {
          if (delta.weights[j] == 0) continue;
          Sdir.t += delta.weights[j] * calls[j].Sz.t;
          Sdir.sn += delta.weights[j] * calls[j].Sz.sn;
        }
        for (Eigen::Index j = 0; j < p0; ++j) {
          if (delta.recycledWeights[j] == 0) continue;
          Sdir.t += delta.recycledWeights[j] * usable[j]->Sz.t;
          Sdir.sn += delta.recycledWeights[j] * usable[j]->Sz.sn;
        }
      }
      for (Kept& kp : calls) recycled.push_back(std::move(kp));
      while (recycled.size() > maxRecycled) recycled.pop_front();
    }
    products.push_back(made);
    const auto trialAt = [&](double t) {
      return p.stateFrom(s.beta + t * dir, s.tau + t * Sdir.t, s.sigmaN + t * Sdir.sn);
    };
    const bool accepted = lineSearch(p, s, trialAt, lastStep, states);
    r.iterations = it;
    r.history.push_back(record(p, s, it, accepted ? lastStep : 0));
    if (!accepted) {
      r.status = converged(p, s, 0) ? OptimizerStatus::converged : OptimizerStatus::stalled;
      break;
    }
  }
  // What is written and judged is the state with the case's γ.
  if (p.gamma() != gammaCase) {
    p.setGamma(gammaCase);
    s = atGamma(s);
    if (r.status == OptimizerStatus::converged && !converged(p, s, 0))
      r.status = OptimizerStatus::maxIterations;
  }
  finish(p, s, lastStep, r, beta);
  // The cost of each Newton iteration in dual solves (deterministic: tests assert it).
  if (!products.empty()) {
    std::ostringstream note;
    // The fault's memory beyond the body's solver (issue 29's bytes per fault node).
    const double probed = krylovPreconditioner_ ? krylovPreconditioner_->probedBytes() : 0.0,
                 lu = krylovPreconditioner_ ? krylovPreconditioner_->largestFactorBytes() : 0.0,
                 held = probed + lu + heldKept + heldGmres;
    note << std::setprecision(3) << "fault operator " << held / 1e6 << " MB counted, "
         << held / 1e3 / static_cast<double>(n) << " kB per fault node (probed S " << probed / 1e6
         << ", its LU " << lu / 1e6 << ", products kept " << heldKept / 1e6 << ", GMRES "
         << heldGmres / 1e6 << "); ";
    note << "GMRES products per Newton iteration:";
    for (const int c : products) note << " " << c;
    // A GMRES that stopped at its limit short of its tolerance: the preconditioner does not
    // hold for this fault, and the step costs hundreds of back-substitutions per iteration.
    if (!capped.empty()) {
      note << "; GMRES stopped at its limit short of its tolerance in Newton iteration";
      note << (capped.size() > 1 ? "s" : "");
      for (const int i : capped) note << " " << i;
      note << ": variant condensed solves this fault directly";
    }
    r.note += (r.note.empty() ? "" : "; ") + note.str();
  }
  return r;
}

}  // namespace friction
