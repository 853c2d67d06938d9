// Optimizer: minimises J(β) of one time step (docs/method.md §4). Run-time selectable by name
// from one table in Optimizer.cpp.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "friction/control/ControlProblem.hpp"

namespace friction {

class Dictionary;

/// How a step's iteration ended (a value the caller acts on, never a silent pass).
enum class OptimizerStatus {
  converged,      ///< the stop rule holds
  maxIterations,  ///< the iteration limit came first
  diverged,       ///< J grew without bound (fixed step too large)
  stalled,        ///< the line search found no decrease (J at a kink or at round-off)
  /// The iteration met the stop rule on its own evaluations, but the state re-evaluated for
  /// output (one more primal solve) misses the tolerance: round-off of an ill-conditioned
  /// system (ν close to 0.5, slivers) is larger than the tolerance asks. Set by the caller
  /// that judges the written state (FrictionCase), never by an optimizer.
  inaccurate,
  /// Friction that weakens with slip: no stable quasi-static equilibrium near the previous
  /// step's (the slipping patch's tangent stiffness is ≤ 0, or Newton found no equilibrium
  /// while weakening nodes slip): an instability nucleates. Set by FrictionCase.
  nucleation
};
const char* toString(OptimizerStatus s);

/// One line of the convergence history.
struct IterationRecord {
  int iteration = 0;
  double J = 0;
  double relResidual = 0;  ///< ‖D‖_M / ‖Σ‖_M (ControlProblem::relativeResidual)
  double stepNorm = 0;     ///< ‖β^{k+1} − β^k‖_M
};

struct OptimizerReport {
  OptimizerStatus status = OptimizerStatus::maxIterations;
  int iterations = 0;
  /// A diagnosis for the log when the status is not 'converged' (e.g. active-set cycling).
  std::string note;
  std::vector<IterationRecord> history;
  /// Back-substitutions spent on operators built once per run (Newton's condensed S), not
  /// on this step: a restarted run builds them again, and its steps must read the same.
  long setupSolves = 0;
  /// With friction that weakens (ControlProblem::weakens) and an optimizer that holds S: the
  /// smallest eigenvalue of the symmetric part of W·G on the slipping nodes' components (G the
  /// Jacobian dD/dβ at the answer, W the nodes' weights), over the mean of W·diag(S_tt) there:
  /// the slipping patch's tangent stiffness, relative. ≤ 0: the equilibrium is unstable (the
  /// weakening outruns the rock's stiffness: nucleation). NaN when not computed (no weakening,
  /// or no node slips).
  double tangentStiffness = std::numeric_limits<double>::quiet_NaN();
  /// The number of slipping components it was computed on.
  long stiffnessComponents = 0;
};

/// What an optimizer may choose by before the factorisation (SemismoothNewton's variant auto):
/// facts of the case alone — never timings — so that a restart and every rank of a parallel
/// run choose alike.
struct CaseFacts {
  Eigen::Index fractureNodes = 0;  ///< control nodes of all fractures (SlipResponse::size())
  int dimension = 2;               ///< of the mesh
  Eigen::Index dofs = 0;           ///< displacement unknowns of the (unsplit) mesh
  /// Why the case needs the dense S (fractures that open, weakening friction, quasiDynamic
  /// time integration), for the log; empty when it does not.
  std::string needsDenseS;
  int elementOrder = 1;  ///< 1 (P1) or 2 (P2)
  /// The linear solver when it is iterative (amg: no factor, every solve an iteration), for
  /// the log; empty for a direct one. Krylov then needs far fewer solves than forming S.
  std::string iterativeSolver;
  /// The largest Poisson ratio of the rock: krylov's probed preconditioner weakens as ν → ½.
  double maxPoissonRatio = 0;
};

/// Settings every optimizer shares (keys of the case's 'solver' dictionary).
struct StopRule {
  enum class On { residual, step };
  On on = On::residual;  ///< residual: ‖D‖_M ≤ tol ‖Σ‖_M; step: ‖Δβ‖_M ≤ tol (paper)
  double tolerance = 1e-6;  ///< relative (residual) or in m·√m (step, the paper's L²(Γ) norm)
  int maxIterations = 2000;
};

class Optimizer {
 public:
  virtual ~Optimizer() = default;

  /// Names in the selection table, for messages, -listModels and the README.
  static std::vector<std::string> names();
  /// Reads 'type' (and the type's own keys plus the StopRule keys) from dict.
  static std::unique_ptr<Optimizer> New(const Dictionary& dict);

  /// True when the optimizer uses the interface operator S formed by the factorisation
  /// (then the caller factors the bordered matrix: docs/method.md §4).
  virtual bool wantsInterfaceOperator() const { return false; }
  /// False where the optimizer cannot take fractures that open (the opening control of
  /// docs/method.md §4, "Fractures that open"); the case refuses that combination.
  virtual bool handlesOpening() const { return true; }
  /// Friction that weakens with slip (slipWeakening): only an optimizer that can tell a lost
  /// equilibrium from slow convergence (OptimizerReport::tangentStiffness) takes it.
  virtual bool handlesWeakening() const { return false; }
  /// Make the choices left to the case (SemismoothNewton's variant auto) from its facts; call
  /// once, before the factorisation (wantsInterfaceOperator() depends on it). Returns one line
  /// for the log saying what was chosen and why, or "" when nothing was left to choose.
  virtual std::string chooseFor(const CaseFacts& /*facts*/) { return ""; }
  /// The interface operator S the optimizer holds (formed by prepare()), or nullptr.
  virtual const InterfaceOperator* heldOperator() const { return nullptr; }

  /// Build what the optimizer forms once per run (Newton's condensed S in the fractures'
  /// frame) now, before the first step, so that the log says what it costs when it is done
  /// instead of hiding it in the first step. Returns what was built, for the log ("" for
  /// nothing). The back-substitutions it spends are the caller's to count.
  virtual std::string prepare(SlipResponse& /*response*/, bool /*withOpening*/) { return ""; }
  /// Minimise from beta (in: start, out: result).
  virtual OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) = 0;
  virtual std::string name() const = 0;

  const StopRule& stopRule() const { return stop_; }
  void setStopRule(const StopRule& s) { stop_ = s; }

  /// The step α [m/Pa] of the gradient methods: given absolutely ('alpha') or relative to
  /// the problem's own scale ('alphaRelative' × (h/E)², with h the spacing of the fracture
  /// nodes and E Young's modulus: the Hessian of J grows like (E/h)², so this keeps a step
  /// stable across units and meshes). The caller sets the scale once it knows h and E.
  void setStepScale(double hOverESquared) { stepScale_ = hOverESquared; }
  void setStep(double alpha, bool relative) { alpha_ = alpha, alphaRelative_ = relative; }
  double alpha() const { return alphaRelative_ ? alpha_ * stepScale_ : alpha_; }
  bool alphaIsRelative() const { return alphaRelative_; }

 protected:
  /// True when the stop rule holds at state s (stepNorm: of the step that led to s).
  bool converged(ControlProblem& p, const ControlState& s, double stepNorm) const;
  IterationRecord record(ControlProblem& p, const ControlState& s, int k, double stepNorm) const;

  StopRule stop_;
  double alpha_ = 1, stepScale_ = 1;
  bool alphaRelative_ = true;
};

/// The paper's (54): β ← β − α g with a fixed step α [m/Pa].
class SteepestDescent : public Optimizer {
 public:
  SteepestDescent() = default;
  OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) override;
  std::string name() const override { return "steepestDescent"; }
};

/// Steepest descent with Armijo backtracking (paper §4.2): accept α when
/// J(β − αg) ≤ J(β) − c α ‖g‖²_M, else halve α; the next step starts from 2α.
class Armijo : public Optimizer {
 public:
  Armijo(double c, int maxBacktracks) : c_(c), maxBacktracks_(maxBacktracks) {}
  OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) override;
  std::string name() const override { return "armijo"; }

 private:
  double c_;
  int maxBacktracks_;
};

/// [beyond] Barzilai–Borwein steepest descent on J: β ← β − α_k g with the BB1 step
/// α_k = ⟨s, s⟩_M / ⟨s, y⟩_M (s, y the last changes of β and g), safeguarded by a
/// non-monotone line search (J may rise above the previous value, never above the largest of
/// the last ten); a non-positive curvature ⟨s, y⟩ falls back to the first step α0.
class BarzilaiBorwein : public Optimizer {
 public:
  BarzilaiBorwein() = default;
  OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) override;
  std::string name() const override { return "barzilaiBorwein"; }
};

/// [beyond] L-BFGS on J in the M inner product, with backtracking (Armijo) on J along the
/// quasi-Newton direction; 'memory' pairs (default 10). A direction that is not a descent
/// direction is replaced by −g.
class Lbfgs : public Optimizer {
 public:
  Lbfgs(int memory, int maxBacktracks) : memory_(memory), maxBacktracks_(maxBacktracks) {}
  OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) override;
  std::string name() const override { return "lbfgs"; }

 private:
  int memory_;
  int maxBacktracks_;
};

class KrylovPreconditioner;

/// The right preconditioner of the krylov variant's GMRES (KrylovPreconditioner.hpp):
/// `none`; `blockDiagonal`, the k × k blocks of the probed S on each node; `probing`, the
/// probed S on node pairs within probingDistance hops.
enum class KrylovPreconditioning { none, blockDiagonal, probing };

/// [beyond] Semismooth Newton on D(β) = 0 (docs/method.md §4), condensed variant: the interface
/// operators S_tt and S_nt are assembled densely once per run (one dual solve per fracture
/// node and tangential component, reused by every step, since they depend only on the mesh
/// and the Dirichlet patches); then every iteration is dense work on Γ alone. The generalised
/// Jacobian has, by node state, k × k blocks G = (I − P'_N) S_tt + γ P'_N + μ P'_ρ S_nt; stick
/// nodes get β = 0 at once, the other nodes' components form the linear system. Globalised by
/// backtracking on the merit ½‖D‖²_M. Solves D = 0, the minimiser of J when ζ = 0 (with ζ > 0 it
/// still solves the friction law exactly).
///
/// How S is formed (key interfaceOperator): `factorisation` (default) takes it from the one
/// factorisation, as the Schur complement of the stiffness in the variables (free dofs,
/// jumps) with the jumps ordered last — no back-substitution; `blockSolves` from blocks of
/// right-hand sides (one per jump dof); `dualSolves` one dual solve per node (the reference).
///
/// Variant `krylov` (matrix-free): no S is assembled; each Newton system is solved by GMRES
/// whose every product with S is one dual back-substitution, and each trial point is one
/// primal solve — for fractures with many nodes, where n dual solves per run cost too much.
/// Its GMRES is right-preconditioned (key preconditioner, KrylovPreconditioning) by the sparse
/// Jacobian of S probed once per run (KrylovPreconditioner.hpp); in 3D it iterates with
/// Newton's own γ as the condensed variant does, the interface stiffness read from the probed
/// (or sampled) diagonal of S_tt.
///
/// Variant `auto` (the key's default; `automatic` here) is condensed until chooseFor() picks
/// by the case: krylov where the fractures have at least krylovFromNodes(dimension, dofs)
/// control nodes and nothing needs the dense S, condensed otherwise.
class SemismoothNewton : public Optimizer {
 public:
  enum class Variant { condensed, krylov, automatic };
  /// The fewest fracture control nodes from which variant auto takes krylov, in a
  /// `dimension`-D mesh of `dofs` unknowns (measured: Optimizer.cpp, README "Newton's variant
  /// by fault size").
  static Eigen::Index krylovFromNodes(int dimension, Eigen::Index dofs);
  SemismoothNewton(int maxBacktracks, Variant variant = Variant::condensed,
                   InterfaceMethod interfaceMethod = InterfaceMethod::factorisation,
                   KrylovPreconditioning preconditioner = KrylovPreconditioning::none,
                   int probingDistance = 1)
      : maxBacktracks_(maxBacktracks),
        variant_(variant == Variant::automatic ? Variant::condensed : variant),
        automatic_(variant == Variant::automatic),
        interfaceMethod_(interfaceMethod),
        preconditioner_(preconditioner),
        probingDistance_(probingDistance) {}
  std::string prepare(SlipResponse& response, bool withOpening) override;
  std::string chooseFor(const CaseFacts& facts) override;
  /// The variant minimize() runs (condensed while auto has not chosen).
  Variant variant() const { return variant_; }
  const InterfaceOperator* heldOperator() const override {
    return variant_ == Variant::condensed && cachedFor_ ? &S_ : nullptr;
  }
  OptimizerReport minimize(ControlProblem& problem, Eigen::VectorXd& beta) override;
  std::string name() const override { return "semismoothNewton"; }
  /// The krylov variant keeps at most this many of a Newton iteration's GMRES products (the
  /// vector and S of it: 5n doubles each in 3D) to sum S dir from; an iteration that makes more
  /// gets S dir from one more product instead. With the step's recycled products (at most 60)
  /// and GMRES's basis of the restart length, this bounds what the variant holds besides the
  /// preconditioner's LU by a constant times n, however many products a fault's GMRES needs
  /// (README, "The fault operator's memory, counted"). Set smaller by tests (0: the default).
  static void setKeptProductsForTests(int count);
  /// Active-set changes over the last call's iterations (a cycling diagnostic).
  int activeSetChanges() const { return activeSetChanges_; }
  bool wantsInterfaceOperator() const override {
    return variant_ == Variant::condensed && interfaceMethod_ == InterfaceMethod::factorisation;
  }
  InterfaceMethod interfaceMethod() const { return interfaceMethod_; }
  /// The krylov variant's products carry no normal rows yet.
  bool handlesOpening() const override { return variant_ == Variant::condensed; }
  /// The condensed variant holds S, so it can judge the slipping patch's stability.
  bool handlesWeakening() const override { return variant_ == Variant::condensed; }

 private:
  OptimizerReport minimizeKrylov(ControlProblem& problem, Eigen::VectorXd& beta);
  /// OptimizerReport::tangentStiffness of the answer s (condensed: S_ is at hand).
  void tangentStiffness(ControlProblem& p, const ControlState& s, OptimizerReport& r) const;
  /// Backtracking from s along the trial states trialAt(t), t = 1, 1/2, …
  bool lineSearch(ControlProblem& p, ControlState& s,
                  const std::function<ControlState(double)>& trialAt, double& lastStep,
                  std::vector<int>& states);
  OptimizerReport& finish(ControlProblem& p, const ControlState& s, double lastStep,
                          OptimizerReport& r, Eigen::VectorXd& beta);

  int maxBacktracks_;
  Variant variant_;  // condensed or krylov: what runs
  bool automatic_;   // variant auto: chooseFor() may still set variant_
  InterfaceMethod interfaceMethod_;
  int activeSetChanges_ = 0;
  InterfaceOperator S_;  // cached for the run
  const SlipResponse* cachedFor_ = nullptr;
  KrylovPreconditioning preconditioner_;
  int probingDistance_;
  std::shared_ptr<KrylovPreconditioner> krylovPreconditioner_;  // cached for the run
  Eigen::VectorXd diagonal_;  // S_tt's diagonal, probed or sampled (zero where not known)
};

}  // namespace friction
