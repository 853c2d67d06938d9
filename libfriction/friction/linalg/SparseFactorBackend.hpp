// SparseFactor's backend interface (internal to linalg/): one class per sparse direct solver,
// listed in the table of SparseFactor.cpp.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "friction/core/LogLines.hpp"
#include "friction/linalg/SparseFactor.hpp"

namespace friction {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// A factorisation backend. factor() returns the backend's own verdict; pivots() gives, per
/// original row i, the pivot of that row in the factor (d of LDLᵀ or l² of LLᵀ), so that the
/// caller can apply one relative test to every backend; a backend that cannot tell them
/// (MUMPS) returns an empty vector and judges definiteness itself.
class SparseFactor::Backend {
 public:
  virtual ~Backend() = default;
  virtual FactorStatus factor(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd pivots() const = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const = 0;
  /// Factor the bordered matrix [A B; Bᵀ C] with the border last and return C − Bᵀ A⁻¹ B in
  /// `schur`; afterwards pivots() and solve() are those of A. Returns false when the backend
  /// cannot (then nothing was changed, `whyNot` says why, and the caller factors A alone).
  virtual bool factorBordered(const SparseMatrix& /*A*/, const SparseMatrix& /*B*/,
                              const SparseMatrix& /*C*/, Eigen::MatrixXd& /*schur*/,
                              FactorStatus& /*status*/, std::string& /*whyNot*/) {
    return false;
  }
  /// Whether A may be each rank's summand of the matrix (setSummedInput).
  virtual bool takesSummands() const { return false; }
  virtual void setSummedInput(bool /*summed*/) {}
  /// Backends that judge their pivots themselves (pivots() empty) take the relative tolerance
  /// here, before factor().
  virtual void setPivotTolerance(double /*tolerance*/) {}
  /// Backends that take a fill-reducing ordering (SparseFactor::takesOrdering): the one of the
  /// next analyses, never Ordering::automatic (SparseFactor resolves it), and what chose it
  /// (FactorAnalysis::orderingChoice).
  virtual bool takesOrdering() const { return false; }
  /// mumps: a low-rank or out-of-core factor (SparseFactor::setMumpsMemory); false: not taken.
  virtual bool setMumpsMemory(const MumpsMemory& /*memory*/) { return false; }
  virtual void setOrdering(Ordering /*ordering*/, const std::string& /*choice*/) {}
  /// Iterative backends (amg): the displacement component of each unknown (0 … count − 1),
  /// for a vector multigrid hierarchy, and the relative residual its solves stop at. Direct
  /// backends ignore both.
  virtual void setComponents(const std::vector<int>& /*components*/, int /*count*/) {}
  virtual void setIterativeTolerance(double /*tolerance*/) {}
  /// The ordering and size of the last analysis, as far as the backend knows them.
  virtual FactorAnalysis analysis() const { return {}; }
  /// What factor(A) would take, from its ordering and a symbolic analysis alone
  /// (SparseFactor::predict); the ordering is kept for the next factorisation of A's pattern.
  /// False: the backend cannot tell (or failed to).
  virtual bool predict(const SparseMatrix& /*A*/, FactorAnalysis& /*predicted*/) { return false; }
  /// Solves restricted to `rows` (SparseFactor::restrictSolves): what one restricted solve
  /// visits, a negative share where this backend solves whole (then solveRestricted() is
  /// solve()).
  virtual SolveReach restrictTo(const std::vector<Eigen::Index>& /*rows*/) { return {}; }
  virtual Eigen::MatrixXd solveRestricted(const Eigen::MatrixXd& B) const { return solve(B); }
  /// Told each phase of a factorisation as it ends (SparseFactor::setPhaseReport); a backend
  /// that reports none is reported whole by SparseFactor.
  PhaseReport onPhase;
  int phasesReported = 0;

 protected:
  void reportPhase(const std::string& phase, double seconds) {
    ++phasesReported;
    if (onPhase) onPhase(phase, seconds);
  }
};

/// METIS's nested-dissection order of the symmetric A (its lower triangle's pattern), by
/// CHOLMOD: order[k] is the row eliminated k-th. False if CHOLMOD could not order (or A is empty).
bool metisOrdering(const SparseMatrix& A, std::vector<long>& order);

#ifdef FRICTION_WITH_HYPRE
/// hypre's BoomerAMG with conjugate gradients (linalg/AmgBackend.cpp): one rank.
std::unique_ptr<SparseFactor::Backend> makeAmgBackend();
#endif

#ifdef FRICTION_WITH_MUMPS
/// MUMPS (linalg/MumpsBackend.cpp): shared by the ranks of a run.
std::unique_ptr<SparseFactor::Backend> makeMumpsBackend();
#endif

}  // namespace friction
