// FrictionCase: a case folder run by frictionSolver, deal.II-style (setup, factor, run):
// read and validate every dictionary before any work, build the FractureSystem on the split
// mesh, factor once, then the quasi-static time loop — per step apply the loads, solve the
// control problem for the slip increment β, accumulate s_{n+1} = s_n + β, write the time
// folder when due (atomically), one log line.
//
// Dictionaries (see README.md, "Case reference"):
//   system/controlDict             TimeControl
//   system/frictionSolution        element order, linear solver, control-problem settings
//   constant/mechanicalProperties  E, ν (or λ, μ), planeStress, bodyForce
//   constant/fractureProperties    per fracture: law and its parameters
//   constant/effects               optional: bodyForce, initialStress, fracturePressure,
//                                  faultPressure, porePressure (Effect.hpp)
//   constant/splitMesh             from splitFractureNodes
//   0/D                            boundary conditions (BoundaryConditions.hpp)
#pragma once

#include <functional>
#include <iosfwd>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/case/BoundaryConditions.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/core/AtomicFile.hpp"
#include "friction/core/LogLines.hpp"
#include "friction/core/OutputError.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fe/MaterialMap.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/law/FrictionLaw.hpp"
#include "friction/law/RateState.hpp"
#include "friction/output/FieldWriter.hpp"
#include "friction/output/VtkWriter.hpp"
#include "friction/time/TimeControl.hpp"
#include "friction/time/TimeIntegrator.hpp"

namespace friction {

class Dictionary;
class FaultSeries;

/// A connected part of the split mesh (cells joined through shared split-mesh nodes, so the
/// two sides of a fracture are different parts) that touches no Dirichlet patch.
struct FloatingPart {
  int dim = 2;
  int cells = 0;                       ///< triangles (2D) or tetrahedra (3D)
  Point point = Point::Zero();         ///< centroid of the part's cell nearest its centre
  bool heldThroughFracture = false;    ///< joined to a held part in the unsplit mesh
  std::vector<std::string> fractures;  ///< fractures on its boundary
  /// "around (x, y), N triangles" (2D) or "around (x, y, z), N tetrahedra" (3D)
  std::string describe() const;
};

class FrictionCase : private StepHost {
 public:
  /// Reads and validates every dictionary and the split mesh (InputError on any problem).
  /// `given`: fields the program running the case hands to its effects (GivenField.hpp; the
  /// FreeFEM plug-in's pressure); each must be taken by an effect whose entry asks for it
  /// (InputError naming constant/effects and what to add otherwise).
  explicit FrictionCase(const std::string& caseDir, const GivenFields& given = {});
  /// elementOrder of caseDir/system/frictionSolution (1 or 2; InputError as the constructor
  /// gives it), before the case is read as a whole: the FreeFEM plug-in's frictionOrder.
  static int elementOrder(const std::string& caseDir);
  ~FrictionCase() override;

  /// Before any work: time folders after startTime from an earlier run are refused
  /// (InputError naming them and both ways out) unless startFrom is latestTime, or
  /// `overwrite` (frictionSolver -overwrite), which removes the earlier run's outputs first:
  /// time folders after startTime, its VTK files and postProcessing/convergence.dat. A folder
  /// the solver did not write (TimeFolder::notWrittenBySolver) is never removed: `overwrite`
  /// refuses it (InputError naming it and the file). `overwriteHint`: how the caller asks for
  /// `overwrite`, for the messages. run() calls it (without overwrite) if the caller did not.
  void prepareOutput(bool overwrite, std::ostream& log,
                     const std::string& overwriteHint = "frictionSolver -overwrite");
  /// Build the spaces, fix the Dirichlet dofs, assemble and factor once. Returns the status.
  FactorStatus setup(std::ostream& log);
  /// The time loop. Returns the step results (also logged). With startFrom latestTime it
  /// continues from the newest complete time folder (its uniform/frictionState) at its time,
  /// after dropping what a killed run wrote beyond it, so that the outputs end as an
  /// uninterrupted run's. Refused (InputError): a restart folder whose name is not the time
  /// its state records (a copied or renamed folder), and folders after it that the solver did
  /// not write. With endTime at or before the saved time nothing is computed or rewritten.
  std::vector<StepResult> run(std::ostream& log);
  /// Why run() stopped before endTime ("" if it reached it): stopAt or a signal.
  const std::string& stoppedEarly() const { return stoppedEarly_; }
  /// After a run stopped early: how to continue it, from which time (the last written), and
  /// what is computed again.
  std::string continuation() const;

  /// Why the factorisation failed, in the user's terms: overflow of the matrix entries (the
  /// case's units), parts of the mesh that nothing holds, or conditioning (the worst
  /// triangle). Call after setup() returned a status other than ok.
  std::string factorFailureDiagnosis() const;
  /// Parts of the split mesh that touch no Dirichlet patch (set by setup()).
  const std::vector<FloatingPart>& floatingParts() const { return floating_; }

  /// Print the active models and settings (the log's first lines).
  void printSettings(std::ostream& log) const;
  /// Wall time since the case began to be read [s]: the clock of the log's "[12.3 s]".
  double secondsSinceStart() const { return sinceStart_.seconds(); }
  /// A setup phase's log line, "Setup: <phase>: <seconds> s [<since start> s]", flushed.
  void logPhase(std::ostream& log, const std::string& phase, double seconds) const;

  FractureSystem& system() { return *system_; }
  const SplitMesh& splitMesh() const { return split_; }
  const TimeControl& time() const { return *time_; }
  /// Accumulated slip [m], k components per control node (SlipResponse.hpp).
  const Eigen::VectorXd& slip() const { return slip_; }
  const ControlState& lastState() const { return last_; }
  /// Fracture f's table for the last step computed: the rows <time>/fractures/<name>.dat
  /// holds (FieldWriter.hpp), at full precision. For callers that keep the results in memory
  /// (the FreeFEM plug-in).
  std::vector<FractureRow> fractureRows(std::size_t f) const;

 private:
  struct FractureSettings {
    std::string name;
    std::unique_ptr<FrictionLaw> law;
    bool unilateral = false;  ///< contact unilateral: the faces may open
  };

  // StepHost: what the time integrator (timeIntegrator_) reaches of the case.
  std::string prepareSolver() override;
  StepLoads loadsAt(double t) override;
  void solveStep(const StepLoads& loads, double t, StepResult& r) override;
  void keepSolution(const StepLoads& loads) override;
  bool restoreStep(const StepLoads& loads, StepResult& r) override;
  double stateTime() const override { return lastTime_; }
  // The control problem of a step under `loads` at time t from the accumulated slip
  // `startSlip` (the system's step, traction offsets, pressure, openings, weakening), handed
  // to `use`: solveStep() and restoreStep() build it alike.
  void withStepProblem(const StepLoads& loads, double t, const Eigen::VectorXd& startSlip,
                       const Eigen::VectorXd& startPath,
                       const std::function<void(ControlProblem&)>& use);
  const InterfaceOperator& faultOperator() override;
  void tractionsAt(const StepLoads& loads, double t, Eigen::VectorXd& tau,
                   Eigen::VectorXd& sigmaN) override;
  RateStateFault rateStateFault() override;
  bool wantsRateSamples() const override;
  void rateSample(const RateSample& sample) override;
  void finishRateStep(const StepLoads& loads, double t, const Eigen::VectorXd& slip,
                      const Eigen::VectorXd& V, StepResult& r) override;
  /// Rate-and-state faults at the run's start: ψ₀ per node from the law's initialSlipRate
  /// under the stresses of startTime (RateState::stateFor); InputError naming the node where
  /// that slip rate cannot be (the shear too small for it).
  void initialiseRateState();

  void writeTimeFolder(const StepResult& r, const Eigen::VectorXd& beta, long step);
  /// Fracture f's rows for the control β (and the state of the last step); rowOfNode, if
  /// given, maps each row's control node to its row.
  std::vector<FractureRow> fractureRows(std::size_t f, const Eigen::VectorXd& beta,
                                        std::map<Index, Index>* rowOfNode) const;
  /// 3D: fracture f's comment lines on where it meets other fault surfaces (intersectionNotes,
  /// SplitMesh.hpp), made on the first call for every fracture.
  const std::vector<std::string>& intersectionNotes3D(std::size_t f);
  std::vector<std::vector<std::string>> intersectionNotes_;
  /// Control node k's state in the last step: stick, slip, open or tip.
  std::string nodeState(Eigen::Index k) const;
  /// Where the nodes of fractures whose friction weakens slip in the last step, per fracture
  /// (2D: the arclength span; 3D: area, centre, extent); "" when none slips.
  std::string patchOfWeakeningSlip() const;
  /// What the effects add at time t to the stress C:ε(u) of cell `cell` at x to make the
  /// total stress [Pa] (Effect::stressOffset summed), or nothing: false when no effect gives
  /// one. The .vtu's stress and the tables' values at tips add the same.
  bool hasStressOffset() const;
  Eigen::Matrix3d stressOffset(Index cell, const Point& x, double t) const;
  /// The total stress [Pa] of the body at tip (or junction end) k for the split displacement
  /// u at time t: the mean over the split-mesh cells that hold the node (every copy of it,
  /// all sides) of C:ε(u) plus stressOffset(). Under a uniform stress it is the traction the
  /// other nodes recover; at a crack tip it grows under refinement, as the stress there does.
  Eigen::Matrix3d tipStress(std::size_t k, const Eigen::VectorXd& u, double t) const;
  /// Per control node: the cells of the split space that hold it, for tips and junction ends
  /// (tipStress); empty for the other nodes. Set by finishSetup().
  std::vector<std::vector<Index>> tipCells_;
  double lastTime_ = 0;     ///< the time of the last step computed (fractureRows())
  double lastWritten_ = 0;  ///< the last time folder written (or the start's time)
  /// Judge the state to be written (last_, the primal solve just done): non-finite values
  /// make the step diverged; a residual above the tolerance makes a 'converged' step
  /// inaccurate; a slip larger than the body gets a diagnosis. Sets r's status and note.
  void judgeStep(StepResult& r) const;
  void findFloatingParts();
  // The keys lowRank, outOfCore and outOfCoreDir of system/frictionSolution.
  void readMumpsMemory(const Dictionary& sol);
  /// Log, once per run each, a note where the answer is most likely a case typed wrong: every
  /// node of a fracture open, a displacement beyond the body's size.
  void sanityNotes(std::ostream& log);
  std::vector<char> allOpenNoted_;
  bool largeDisplacementNoted_ = false;
  /// The components ("x", "y", "z") that no fixedDisplacement patch fixes: the body can
  /// translate along them.
  std::vector<std::string> freeComponents() const;
  /// Whether the body can move without strain: a part that nothing holds (floating_), or a
  /// free component. K is then singular, whatever a factorisation's pivots say.
  bool canMoveRigidly() const;
  /// What setup() does after the factorisation: the friction coefficients and cohesion per
  /// node, γ, the optimiser's scale, and the log of it all.
  void finishSetup(FactorStatus status, std::ostream& log);
  /// Mean length of the fracture edges [m] (0 without fractures): the h of γ's default.
  double meanFractureEdge() const;
  Eigen::VectorXd loadVector(double t) const;
  /// The step line's load fields at t (README.md, "frictionSolver"): the largest prescribed
  /// displacement and traction where 0/D gives any, the mean fluid pressure on the fractures
  /// where an effect gives one.
  std::string loadFields(double t, const Eigen::VectorXd& pressure) const;
  /// Effective fluid pressure per control node at t [Pa] (zero without fracturePressure).
  Eigen::VectorXd fracturePressure(double t) const;

  Stopwatch sinceStart_;  ///< started before anything is read
  std::string caseDir_;
  std::unique_ptr<TimeControl> time_;
  SplitMesh split_;
  std::unique_ptr<MaterialMap> materials_;
  /// The E of γ's and the gradient step's scale-free defaults [Pa]: the material's E, or with
  /// several materials the largest E among the cells that touch a fracture (the stiffest rock
  /// the fractures load; the largest E of all without fractures).
  double youngScale_ = 0;
  std::vector<std::unique_ptr<Effect>> effects_;
  std::vector<std::string> skippedEffects_;  ///< listed but 'active no'
  std::unique_ptr<BoundaryConditions> bcs_;
  std::vector<FractureSettings> fractures_;
  int order_ = 1;
  std::string linearSolver_ = "cholmod";
  /// linearSolver auto (the default): linearSolver_ is chosen in setup() (chooseLinearSolver);
  /// the bytes of CHOLMOD's predicted factor above which it takes the iterative solver (key
  /// iterativeAbove; ≤ 0: 80 % of the memory available then); the choice and why, for the log.
  bool linearSolverAuto_ = false;
  double iterativeAbove_ = 0;
  std::string linearSolverChoice_;
  Ordering ordering_ = Ordering::automatic;  ///< the key `ordering` (cholmod only)
  /// The keys `lowRank`, `outOfCore`, `outOfCoreDir` (mumps only).
  MumpsMemory mumpsMemory_;
  double iterativeTolerance_ = 1e-10;  ///< linearSolver amg: CG's relative residual
  /// linearSolver amg: the solves that stopped short of the tolerance, as of the last step
  /// judged (judgeStep marks a step with more inaccurate).
  mutable long iterativeUnconvergedSeen_ = 0;
  std::string outOfCoreNote_;  // why outOfCore auto cannot leave the core, for the log
  // linearSolver auto: the solver for an assembled system (setup()), and the one a restart
  // finds in the newest complete time folder's state (empty: none recorded).
  void chooseLinearSolver();
  std::string recordedLinearSolver() const;
  double gamma_ = 0, gammaRelative_ = 1, zeta_ = 0;
  bool gammaAbsolute_ = false, warmStart_ = false;
  /// Where gamma and gammaNormal were given (absolute values are checked against E/h once h is
  /// known, in setup()).
  SourceLocation gammaLocation_, gammaNLocation_;
  /// Fractures that open (docs/method.md §4, "Fractures that open"): any fracture with contact
  /// unilateral; γ_n and how it was given (gammaNormal, gammaNormalRelative, or γ's own value).
  bool opening_ = false;
  double gammaN_ = 0, gammaNRelative_ = 0;
  enum class GammaNGiven {
    sameAsGamma,
    absolute,
    relative
  } gammaNGiven_ = GammaNGiven::sameAsGamma;
  Eigen::VectorXd unilateral_;  ///< per control node: 1 where its fracture may open
  GradientKind gradient_ = GradientKind::exact;
  std::unique_ptr<Optimizer> optimizer_;
  /// system/frictionSolution's timeIntegration (TimeIntegrator.hpp).
  std::unique_ptr<TimeIntegrator> timeIntegrator_;

  std::unique_ptr<FractureSystem> system_;
  Eigen::VectorXd mu_, cohesion_, slip_;
  /// Friction that weakens with slip (law slipWeakening on some fracture): per control node
  /// its weakening and cohesion (WeakeningSettings), and the laws' state, the slip path δ [m]
  /// of every node (written in uniform/frictionState, restarted from it).
  /// Rate-and-state faults (law rateState, timeIntegration quasiDynamic): per control node
  /// the law (σ̄ set when used), its initial slip rate, and the state ψ (written in
  /// uniform/frictionState, restarted from it); the last slip rates [m/s] (k per node).
  bool rateState_ = false, psiKnown_ = false;
  std::vector<RateState> rateLaws_;
  Eigen::VectorXd initialSlipRate_, psi_, slipRate_;
  /// Nodes of fractures with law creep: 1 where the slip rate is imposed (n), and that rate on
  /// the node's tangent basis (k·n) [m/s].
  Eigen::VectorXd imposed_, imposedRate_;
  /// system/controlDict's faultOutput: SEAS-layout series of a quasiDynamic run (or none).
  std::unique_ptr<FaultSeries> faultSeries_;
  /// Its surface stations: G = ∂u/∂β at them (2 per station × k·n, buildSurfaceResponse), and
  /// u there at the last two tractionsAt (the integration interval's ends).
  Eigen::MatrixXd surfaceResponse_;
  struct SurfaceAt {
    double time = 0;
    Eigen::VectorXd u;
  };
  SurfaceAt surfaceAt_[2];
  void buildSurfaceResponse(std::ostream& log);
  bool weakening_ = false;
  /// The log line of what the optimizer chose by the case (Optimizer::chooseFor), or "".
  std::string optimizerChoice_;
  WeakeningSettings weakeningSettings_;
  Eigen::VectorXd slipPath_;
  ControlState last_;
  Eigen::VectorXd pressure_;  ///< p of the last step, per control node
  /// Some effect gives a fluid pressure on the fractures: tables and VTK carry p and σ'_n.
  bool hasPressure_ = false;
  /// With a fluid pressure: σ'_n and |τ| of the initial state per control node [Pa] (the
  /// in-situ stress and p_f at startTime), which ΔCFS is measured against.
  Eigen::VectorXd initialSigmaNEffective_, initialTauNorm_;
  /// Control of the last step (warm start, restart): the slip increment, then with openings
  /// the opening g per node [m] (a state: the faces' separation at the end of that step).
  Eigen::VectorXd lastBeta_;
  /// The evaluation last_ holds (quasiStatic): the time of its step, the accumulated slip at
  /// that step's start and its control β (solveStep). A time folder's state records it, and a
  /// restart makes it again bit for bit where its first step reuses it (restoreStep); the
  /// solves that costs are not the step's own (restoreSolves_).
  struct Evaluation {
    double time = 0;
    Eigen::VectorXd slip, beta;
    Eigen::VectorXd path;  ///< law slipWeakening: the slip path δ at the step's start
    /// law slipWeakening: Newton's patch stiffness of the step (its status line and file)
    double tangentStiffness = std::numeric_limits<double>::quiet_NaN();
    long stiffnessComponents = 0;
  };
  std::optional<Evaluation> evaluated_, restore_;
  long restoreSolves_ = 0;
  bool restartedFromFolder_ = false;
  std::string stoppedEarly_;
  std::vector<FloatingPart> floating_;
  /// setup()'s verdict on the factorisation: the backend's, or notPositiveDefinite where the
  /// body can move rigidly (canMoveRigidly()).
  FactorStatus factorStatus_ = FactorStatus::failed;
  double diameter_ = 0;                  ///< diagonal of the mesh's bounding box [m]
  std::unique_ptr<VtkSeries> vtk_;       ///< ParaView files, when controlDict's writeVTK is on
  std::unique_ptr<AppendFile> history_;  ///< postProcessing/convergence.dat
  /// postProcessing/history_<name>.dat per fracture: the rupture's size, slip and moment per
  /// step (historyLine()).
  std::vector<std::unique_ptr<AppendFile>> fractureHistories_;
  std::vector<double> shearModulus_;  ///< per fracture: G of the rock around it [Pa]
  std::string historyHeader() const;
  /// Fracture f's line of its history file for the step just solved (time t).
  std::string historyLine(std::size_t f, double t) const;
  bool outputPrepared_ = false;
  std::string overwriteHint_ = "frictionSolver -overwrite";  ///< for the messages
  /// Restart: read the state of the newest complete time folder, trim the outputs after it;
  /// returns the first step to compute.
  long restart(std::ostream& log);
  /// Keep of the outputs around the time folders (VTK files and .pvd entries, convergence.dat
  /// lines) only the times whose name `keep` accepts; remove temporary files and folders of
  /// killed writes. `fresh`: start convergence.dat anew. Not fresh (a restart), the VTK series
  /// goes on under the name of the earlier times' files when the case folder was renamed (the
  /// log says so).
  /// `limit`: the restart's time (the fault outputs keep their rows up to it).
  void trimOutputs(const std::function<bool(const std::string&)>& keep, bool fresh,
                   std::ostream& log, double limit = 0);
};

}  // namespace friction
