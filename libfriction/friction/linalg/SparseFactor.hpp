// SparseFactor: "factor once, solve many" for the symmetric positive definite reduced
// stiffness matrix (docs/method.md §4: every primal and dual solve of a run reuses one factor).
//
// Backends, chosen by name:
//   cholmod         CHOLMOD supernodal LLᵀ (SuiteSparse) through Eigen's CholmodSupernodalLLT;
//                   fill-reducing ordering chosen by setOrdering() (AMD, METIS or NESDIS, one
//                   of them, or CHOLMOD's own strategy). The default.
//   simplicialLDLT  Eigen's SimplicialLDLT with AMD ordering: no external library; slower on
//                   large 2D problems, kept as a fallback and a cross-check.
//   amg             conjugate gradients preconditioned by hypre's BoomerAMG, set up once: no
//                   factor, so memory linear in the unknowns; every solve is an iteration to a
//                   relative residual (setIterativeTolerance); shared by the ranks of an MPI
//                   run like mumps. Only in builds with FRICTION_HYPRE (README "The largest 3D
//                   models").
//   mumps           MUMPS (multifrontal LDLᵀ, symmetric mode) shared by the ranks of an MPI run
//                   (frictionSolver -parallel); with one rank, the same solver serially. Only
//                   in builds with FRICTION_MUMPS (README "Running in parallel").
// Both read the lower triangle of the matrix, so full and lower storage are both fine.
//
// A failed factorisation is a value (FactorStatus), not an exception or a crash: the caller
// logs it and stops the run cleanly.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/core/LogLines.hpp"

namespace friction {

enum class FactorStatus {
  ok,                   ///< factor is usable
  notPositiveDefinite,  ///< a pivot was ≤ 0 or negligible: the matrix is singular (e.g. a
                        ///< rigid-body mode left unfixed) or indefinite
  failed,               ///< the backend failed otherwise (out of memory, bad input)
  nonFinite             ///< an entry of the matrix is inf or NaN (overflow: see maxAbsEntry)
};

/// "ok", "notPositiveDefinite", "failed", "nonFinite".
const char* toString(FactorStatus status);

/// The fill-reducing ordering of the cholmod backend (system/frictionSolution, key `ordering`;
/// README "The ordering of the factorisation"). cholmodDefault is CHOLMOD's own strategy: it
/// orders by AMD and, where AMD's factor looks costly (≥ 500 flops per entry and ≥ 5 × A's
/// entries), orders by METIS as well and keeps the smaller factor: two orderings per run.
/// amd, metis and nesdis (CHOLMOD's nested dissection) order once; automatic picks one of
/// them by dimension and size (automaticOrdering()).
enum class Ordering { automatic, amd, metis, nesdis, cholmodDefault };

/// The key's words, in the enum's order: "auto", "amd", "metis", "nesdis", "cholmodDefault".
const std::vector<std::string>& orderingNames();
/// The word of an ordering (orderingNames()).
const std::string& toString(Ordering ordering);
/// The ordering of a word of orderingNames() (checked by the caller: asserts otherwise).
Ordering orderingNamed(const std::string& name);
/// What `auto` orders by, for a matrix of `unknowns` rows from a `dimension`-D mesh. Chosen by
/// measurement (utilities/frictionStudy/orderingBenchmark.sh, README): never amd, metis or
/// nesdis against each other at run time.
Ordering automaticOrdering(int dimension, Eigen::Index unknowns);

/// The mumps backend's ways to a factor smaller than the full-rank one in memory
/// (system/frictionSolution keys `lowRank`, `outOfCore`, `outOfCoreDir`; README "Running in
/// parallel").
struct MumpsMemory {
  /// Block low-rank factor (MUMPS's BLR, ICNTL(35) = 2) with this dropping tolerance (CNTL(7):
  /// blocks of the fronts are truncated where the pivots of their rank-revealing QR fall below
  /// it, in MUMPS's scaled matrix, whose entries are at most 1). 0: the full-rank factor.
  double lowRank = 0;
  /// Out-of-core factor (ICNTL(22) = 1): MUMPS writes the factor's full-rank blocks to files in
  /// this folder (OOC_TMPDIR) and deletes them when the factor is freed. Empty: in core.
  std::string outOfCoreDir;
  /// With outOfCoreDir: out of core only where MUMPS's estimate of the in-core factorisation
  /// (after the analysis: INFOG(17), or INFOG(37) with lowRank; all ranks together) exceeds
  /// outOfCoreAbove bytes, or, with outOfCoreAbove ≤ 0, the memory available when the
  /// factorisation starts (MemAvailable in /proc/meminfo; rank 0's figure).
  bool outOfCoreAuto = false;
  double outOfCoreAbove = 0;
  bool any() const { return lowRank > 0 || !outOfCoreDir.empty(); }
};

/// Where SparseFactor::restrictSolves() found the rows' reach: the share of the factor's
/// values and the supernodes a restricted solve visits. share < 0: the backend solves whole.
struct SolveReach {
  double share = -1;
  long supernodes = 0, ofSupernodes = 0;
};

/// What the last analysis of a sparse Cholesky factorisation chose and will cost (for the log:
/// at 10⁶ unknowns in 3D the factor, not the control loop, sets the time and the memory).
struct FactorAnalysis {
  std::string ordering;  ///< fill-reducing ordering, e.g. "METIS" (empty: unknown)
  /// What chose it, for the log: "auto: 2D" (Ordering::automatic, with the reason), "ordering
  /// metis" (the case's key), "cholmodDefault" (CHOLMOD's strategy); empty for backends that
  /// take no ordering.
  std::string orderingChoice;
  /// Vertices of the graph the ordering ordered: A's groups of equal columns (a node's
  /// displacement components, SparseFactor.cpp indistinguishableColumns); 0 when it ordered
  /// A's own graph (cholmodDefault) or is unknown.
  double orderedGroups = 0;
  /// mumps, outOfCore auto: what it chose and why, for the log (empty: not asked).
  std::string outOfCoreChoice;
  double entries = 0;  ///< nonzeros of the factor L (0: unknown)
  double bytes = 0;    ///< memory of L's values, padding of dense blocks included (0: unknown)
  double flops = 0;    ///< floating-point operations of the numeric factorisation (0: unknown)
  // Wall time of the phases [s] (0: unknown): the ordering and the symbolic analysis (with a
  // border: A's ordering, then the bordered matrix's analysis), the numeric factorisation,
  // and the dense work that turns the border's block into the complement. orderingSeconds is
  // the part of analysisSeconds spent ordering A (0: unknown).
  double analysisSeconds = 0;
  double orderingSeconds = 0;
  double numericSeconds = 0;
  double complementSeconds = 0;
  // Distributed backends (mumps): the ranks that share the factor, and the memory the
  // factorisation used on the rank that used most and on all of them together [bytes] (0:
  // unknown).
  int ranks = 1;
  double rankMemoryMax = 0;
  double memoryTotal = 0;
  // mumps with MumpsMemory: the dropping tolerance of a low-rank factor (0: full rank), the
  // entries the full-rank factor would have had (then `entries` is what the low-rank one
  // keeps, MUMPS's INFOG(35) against INFOG(29)), the flops it spent (RINFOG(14); `flops` stays
  // the full-rank count), and, out of core, the folder and the bytes of factor written there
  // (RINFOG(16)).
  double lowRank = 0;
  double fullRankEntries = 0;
  double lowRankFlops = 0;
  std::string outOfCoreDir;
  double outOfCoreBytes = 0;
  /// What MUMPS's analysis estimated the factorisation would take in all ranks [bytes] (0:
  /// unknown): in core (INFOG(17)), out of core (INFOG(27)), and with the low-rank factor in
  /// core or out of core (INFOG(37) or INFOG(39); MUMPS assumes 60 % of the entries kept).
  double estimatedInCore = 0;
  double estimatedOutOfCore = 0;
  double estimatedLowRank = 0;
  /// Why the backend failed, where it says (mumps: out of memory, the out-of-core folder; amg:
  /// CG's tolerance not reached, a singular matrix).
  std::string problem;
  /// Iterative backends (amg): what was set up and what its check solve measured, for the log
  /// (empty for direct backends); the check's forward error ‖x − r‖/‖r‖; and, so far in the
  /// run, the solves, their CG iterations, those that stopped short of the tolerance and the
  /// largest relative residual any solve ended with.
  std::string iterativeNote;
  double iterativeForwardError = 0;
  long iterativeSolves = 0;
  long iterativeIterations = 0;
  long iterativeUnconverged = 0;
  double iterativeWorstResidual = 0;
};

/// The memory this machine has for a new allocation [bytes]: MemAvailable of /proc/meminfo
/// (infinite where it cannot be read: then nothing is chosen for lack of memory).
double availableMemory();

class SparseFactor {
 public:
  /// Select the backend by name (see backendNames()). Throws InputError naming `where`
  /// (the dictionary entry that chose it, if any) and listing the valid names on a typo.
  explicit SparseFactor(const std::string& backend = "cholmod", const SourceLocation& where = {});
  ~SparseFactor();
  SparseFactor(SparseFactor&&) noexcept;
  SparseFactor& operator=(SparseFactor&&) noexcept;
  SparseFactor(const SparseFactor&) = delete;
  SparseFactor& operator=(const SparseFactor&) = delete;

  /// Valid backend names, in the order of the table in SparseFactor.cpp.
  static std::vector<std::string> backendNames();
  /// Throws InputError naming `where` if `backend` is a known solver this build lacks (mumps
  /// without FRICTION_MUMPS), saying how to get it; anything else passes.
  static void requireInBuild(const std::string& backend, const SourceLocation& where);
  const std::string& backend() const { return backend_; }

  /// The fill-reducing ordering of the next factorisations; `dimension` (2 or 3) is the
  /// mesh's, which Ordering::automatic needs. Only a backend that takesOrdering() accepts
  /// another than Ordering::automatic (asserted: the case refuses the key first).
  void setOrdering(Ordering ordering, int dimension);
  Ordering ordering() const { return ordering_; }
  /// Whether the backend orders as setOrdering() says (cholmod); the others have their own
  /// (simplicialLDLT: AMD, mumps: METIS).
  bool takesOrdering() const;

  /// Analyse and factor the symmetric matrix A (its lower triangle is read). Besides the
  /// backend's own check, every pivot d_k (D of LDLᵀ, or L_kk² of LLᵀ) must exceed
  /// pivotTolerance() · A_kk in the factor's ordering; otherwise the status is
  /// notPositiveDefinite. That catches singular matrices whose last pivot is round-off.
  FactorStatus factor(const Eigen::SparseMatrix<double>& A);
  FactorStatus status() const { return status_; }
  /// Whether the last factor() succeeded, i.e. solve() may be called.
  bool ok() const { return status_ == FactorStatus::ok && factored_; }

  /// Relative pivot tolerance (default 1e-10). A pivot d_k ≤ tolerance · A_kk is taken as
  /// round-off, i.e. the matrix as singular. Measured on unit-square elasticity meshes up to
  /// 256 × 256 cells (P1, P2, ν up to 0.4999): reduced matrices with the rigid modes fixed
  /// have d_k / A_kk ≥ 5e-5, while the full (singular) K leaves round-off pivots of
  /// magnitude 1e-16 … 4e-6, of either sign. So this is a safety net behind the backend's
  /// own (sign) check, not a proof of definiteness.
  double pivotTolerance() const { return pivotTolerance_; }
  void setPivotTolerance(double tolerance) { pivotTolerance_ = tolerance; }
  /// Smallest d_k / A_kk of the last factorisation (diagnostics: a tiny value warns of a
  /// nearly singular problem even when the status is ok). NaN before the first factor(), and
  /// with a backend that does not report its pivots (mumps: it detects null and negative
  /// pivots itself, against pivotTolerance() · max |A_ij|).
  double minPivotRatio() const { return minPivotRatio_; }
  /// Largest |A_ij| of the last factorisation's matrix (inf when an entry overflowed or is
  /// NaN): tells overflow and bad scaling (E in Pa near 1e300) apart from singularity.
  double maxAbsEntry() const { return maxAbsEntry_; }

  /// What factor(A) would take, before any numeric work (linearSolver auto, README "Which
  /// linear solver"): the fill-reducing ordering the next factor() would use, then CHOLMOD's
  /// symbolic analysis of A in that order. `entries` and `flops` are CHOLMOD's counts;
  /// `bytes` is 8 bytes per entry times predictedPadding, the zeros the supernodes' dense
  /// blocks let in. The ordering is kept: the next factor() or factorWithSchur() of a matrix
  /// with A's pattern does not order again. Only a backend that takesOrdering() (cholmod)
  /// predicts, and not with Ordering::cholmodDefault (it orders inside its analysis); false
  /// otherwise or when CHOLMOD failed.
  bool predict(const Eigen::SparseMatrix<double>& A, FactorAnalysis& predicted);
  /// The factor's bytes per 8-byte entry (supernodal padding) that predict() assumes: measured
  /// 1.22–1.23 in 3D (P1, 2.8–4.9·10⁵ unknowns, METIS; the log's "entries in the factor"
  /// against its GB), rounded up.
  static constexpr double predictedPadding = 1.25;

  /// Factor A as factor(A) does, and with it the Schur complement of the bordered matrix
  ///     [ A   B ]
  ///     [ Bᵀ  C ]        (A: n×n, B: n×m sparse, C: m×m symmetric, lower triangle read),
  /// i.e. the dense m×m matrix C − Bᵀ A⁻¹ B (docs/method.md §4: with B the lifting of the
  /// jumps and C their split stiffness this is M·S, the interface operator). The cholmod
  /// backend factors the bordered matrix once, with the border ordered last, so that the
  /// complement is a by-product of the factorisation: no back-substitution is spent on it.
  /// Other backends (and CHOLMOD when it cannot keep the border last) factor A alone and
  /// form the complement from blocks of right-hand sides (m back-substitutions, counted in
  /// numSolves()); schurSolves() says which happened. solve() solves with A either way.
  FactorStatus factorWithSchur(const Eigen::SparseMatrix<double>& A,
                               const Eigen::SparseMatrix<double>& B,
                               const Eigen::SparseMatrix<double>& C);
  /// The complement of the last factorWithSchur() (empty after factor()).
  const Eigen::MatrixXd& schurComplement() const { return schur_; }
  /// Back-substitutions the last complement cost (0 when it came from the factorisation).
  long schurSolves() const { return schurSolves_; }
  /// Why the last complement came from blocks of solves although the backend has a bordered
  /// factorisation (e.g. "its factor would exceed 2³¹ entries"); empty otherwise.
  const std::string& schurFallbackReason() const { return schurFallbackReason_; }
  /// The ordering and size of the last factor (of the bordered matrix when it was bordered).
  const FactorAnalysis& analysis() const { return analysis_; }
  /// Wall time [s] of the blocked solves of the last complement (0 when it came from the
  /// factorisation: its cost is then part of factorSeconds()).
  double schurSeconds() const { return schurSeconds_; }
  /// C − Bᵀ A⁻¹ B from the current factor by blocks of right-hand sides (m
  /// back-substitutions): the generic way, and the cross-check of the bordered one.
  Eigen::MatrixXd schurBySolves(const Eigen::SparseMatrix<double>& B,
                                const Eigen::SparseMatrix<double>& C);

  /// x = A⁻¹ b (one back-substitution). Requires ok() (debug assert). An Eigen expression
  /// must be evaluated first (VectorXd(expr)): both overloads would accept it.
  Eigen::VectorXd solve(const Eigen::VectorXd& b);
  /// X = A⁻¹ B, one back-substitution per column.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B);

  /// Solves whose right-hand sides vanish outside `rows` and whose solutions are read on `rows`
  /// only (a fault's band of unknowns: docs/method.md §4, "Solves restricted to the fault's
  /// reach"). With a supernodal cholmod factor of A alone, solveRestricted() then visits only
  /// the supernodes those rows reach in the elimination tree (linalg/RestrictedSolve.hpp): the
  /// same answer on `rows`, to the bit. Returns what such a solve visits, with a negative
  /// share where the backend solves whole (mumps, amg, a bordered or simplicial factor):
  /// solveRestricted() is then solve(). Holds until the next factor().
  SolveReach restrictSolves(const std::vector<Eigen::Index>& rows);
  /// X = A⁻¹ B on the rows of restrictSolves() (elsewhere zero, or the whole solve's values
  /// where the backend solves whole). B must vanish outside the rows' reach (a caller's
  /// mistake otherwise: std::logic_error). One back-substitution per column, counted in
  /// numSolves().
  Eigen::MatrixXd solveRestricted(const Eigen::MatrixXd& B);
  Eigen::VectorXd solveRestricted(const Eigen::VectorXd& b);

  /// The displacement component (0 … count − 1) of each row of the next matrices, and the
  /// relative residual at which an iterative backend's solves stop (amg; ignored by the direct
  /// ones). Whether the backend is iterative: iterative().
  void setComponents(const std::vector<int>& components, int count);
  void setIterativeTolerance(double tolerance);
  bool iterative() const { return backend_ == "amg"; }
  /// The analysis with the iterative backend's counts so far (solves, iterations).
  FactorAnalysis currentAnalysis() const;

  /// MUMPS's low-rank or out-of-core factor for the next factorisations (mumps only: asserted;
  /// the case refuses the keys for the other solvers).
  void setMumpsMemory(const MumpsMemory& memory);

  /// Whether the backend takes each rank's summand of the matrix (its own cells' entries; the
  /// distributed engine, README "Running in parallel"): mumps and amg.
  bool takesSummands() const;
  /// With true, the A given to factor() and factorWithSchur() on each rank is that rank's
  /// summand of the matrix (the matrix is their sum); B and C stay whole on every rank. Only
  /// for a backend that takesSummands(); every rank must call factor() alike.
  void setSummedOverRanks(bool summed);
  bool summedOverRanks() const { return summed_; }

  /// Told each phase of the factorisations as it ends (ordering and analysis, numeric
  /// factorisation, the complement), for a log that says what a long setup is doing.
  void setPhaseReport(PhaseReport report);

  /// Order of the factored matrix (0 before the first factor()).
  Eigen::Index rows() const { return rows_; }
  /// Number of factor() calls (successful or not).
  long numFactorizations() const { return numFactorizations_; }
  /// Number of right-hand sides solved for (a k-column solve counts k).
  long numSolves() const { return numSolves_; }
  /// Wall time spent in factor() [s], all calls; and in solve() [s].
  double factorSeconds() const { return factorSeconds_; }
  double solveSeconds() const { return solveSeconds_; }

  /// The backend interface (defined in SparseFactor.cpp).
  class Backend;

 private:
  std::string backend_;
  std::unique_ptr<Backend> impl_;
  FactorStatus status_ = FactorStatus::failed;
  bool factored_ = false;
  Eigen::Index rows_ = 0;
  double pivotTolerance_ = 1e-10;
  bool summed_ = false;
  Ordering ordering_ = Ordering::automatic;
  int dimension_ = 2;
  double minPivotRatio_ = std::numeric_limits<double>::quiet_NaN();
  double maxAbsEntry_ = 0.0;
  long numFactorizations_ = 0;
  long numSolves_ = 0;
  double factorSeconds_ = 0.0;
  double solveSeconds_ = 0.0;
  Eigen::MatrixXd schur_;
  long schurSolves_ = 0;
  double schurSeconds_ = 0.0;
  std::string schurFallbackReason_;
  FactorAnalysis analysis_;
  PhaseReport phaseReport_;

  // factor() and factorWithSchur(): A alone, or bordered by B and C where the backend can.
  FactorStatus factorImpl(const Eigen::SparseMatrix<double>& A,
                          const Eigen::SparseMatrix<double>* B,
                          const Eigen::SparseMatrix<double>* C);
  // The ordering of the next analysis, `auto` resolved for A's size (factor(), predict()).
  void passOrdering(Eigen::Index rows);
  // Runs `solve` (a back-substitution of `columns` right-hand sides), counting and timing it.
  template <class Solve>
  auto counted(Eigen::Index columns, Solve&& solve);
  // The pivot test on the first rows_ rows.
  FactorStatus judgePivots(const Eigen::SparseMatrix<double>& A);
};

}  // namespace friction
