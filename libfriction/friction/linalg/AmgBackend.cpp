// AmgBackend: the "amg" linear solver — conjugate gradients preconditioned by one V-cycle of
// hypre's BoomerAMG, set up once per factorisation and reused by every solve (README "The
// largest 3D models: linearSolver amg"; docs/method.md §4).
//
// What it is for: a direct factor of a 3D body grows as n^{4/3} in memory and n² in flops, so
// this 24 GiB machine factors about 1.3·10⁶ unknowns at most, out of core. The multigrid
// hierarchy and CG's vectors grow as n: bodies of several million unknowns fit. What it costs:
// every solve is an iteration (tens of V-cycles) instead of a back-substitution, and its answer
// is exact only to the tolerance. It holds no factor, so S cannot come from a factorisation:
// the optimizer's krylov variant, which asks only for solves, is the one that fits it (variant
// auto takes it; the condensed variant forms S by one solve per jump unknown).
//
// The hierarchy is that of a vector problem (BoomerAMG's "unknown approach": coarsening and
// interpolation within each displacement component, setComponents()); HMIS coarsening, ext+i
// interpolation with at most 4 entries per row, symmetric hybrid Gauss–Seidel smoothing, so the
// V-cycle is a symmetric preconditioner and CG applies. These are hypre's recommendations for
// 3D elasticity-like problems; they were measured here against the classical ones (README).
//
// The check in factor(): b = A r for a fixed pseudo-random r (1 plus noise in [−0.5, 0.5]),
// then the solve of A x = b. A matrix with rigid translations in its null space (a body
// nothing holds) still gives CG a consistent right-hand side but an x that differs from r by
// about r's mean, so ‖x − r‖/‖r‖ > 10⁻³ is a singular matrix (notPositiveDefinite), as is a
// diagonal entry ≤ 0; a CG that does not reach its tolerance is `failed`. This is weaker than
// a factor's pivots (an indefinite matrix with a positive diagonal can pass it): the case
// checks the mesh and its patches for rigid motions besides (FrictionCase::canMoveRigidly). The
// forward error of that check is what the solves cost in accuracy, and the log says it.
//
// On several ranks (frictionSolver -parallel) the ranks share the rows in contiguous blocks:
// each rank hands hypre its summand (its own cells' entries, SparseFactor::setSummedOverRanks)
// and hypre adds them; right-hand sides are whole on every rank (each sets its rows) and every
// rank gets the whole solution back. One rank runs on MPI_COMM_SELF. Compiled only in builds
// with FRICTION_WITH_HYPRE (others skip the file).
#ifdef FRICTION_WITH_HYPRE
#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <HYPRE_parcsr_mv.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "friction/core/Assert.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/linalg/SparseFactorBackend.hpp"

namespace friction {

namespace {

// first_ is MPI_Allgatherv's displacements (int): hypre's ints must be ints (Debian's are).
static_assert(sizeof(HYPRE_Int) == sizeof(int), "hypre built with 64-bit HYPRE_Int");

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class AmgBackend final : public SparseFactor::Backend {
 public:
  AmgBackend() {
    parallel::ensureInitialized();
    static const bool started = [] {
      HYPRE_Init();
      return true;
    }();
    (void)started;
  }
  ~AmgBackend() override { release(); }
  AmgBackend(const AmgBackend&) = delete;
  AmgBackend& operator=(const AmgBackend&) = delete;

  void setComponents(const std::vector<int>& components, int count) override {
    components_ = components;
    componentCount_ = count;
  }
  void setIterativeTolerance(double tolerance) override { tolerance_ = tolerance; }

  bool takesSummands() const override { return true; }
  void setSummedInput(bool summed) override { summed_ = summed; }

  FactorStatus factor(const SparseMatrix& A) override {
    release();
    analysis_ = FactorAnalysis{};
    analysis_.ordering = "none (BoomerAMG + CG)";
    const auto start = std::chrono::steady_clock::now();
    n_ = static_cast<HYPRE_Int>(A.rows());
    if (A.rows() == 0) return FactorStatus::ok;
    // The ranks share the rows in contiguous blocks; one rank holds them all.
    ranks_ = parallel::size();
    comm_ = ranks_ > 1 ? MPI_COMM_WORLD : MPI_COMM_SELF;
    first_.assign(static_cast<std::size_t>(ranks_ + 1), 0);
    for (int q = 0; q <= ranks_; ++q)
      first_[static_cast<std::size_t>(q)] =
          static_cast<HYPRE_Int>(static_cast<long long>(n_) * q / ranks_);
    const int me = parallel::rank();
    lo_ = first_[static_cast<std::size_t>(me)];
    hi_ = first_[static_cast<std::size_t>(me) + 1];  // one past the last
    rankCounts_.resize(static_cast<std::size_t>(ranks_));
    for (int q = 0; q < ranks_; ++q)
      rankCounts_[static_cast<std::size_t>(q)] =
          first_[static_cast<std::size_t>(q) + 1] - first_[static_cast<std::size_t>(q)];
    ownRows_.resize(static_cast<std::size_t>(hi_ - lo_));
    for (HYPRE_Int i = lo_; i < hi_; ++i) ownRows_[static_cast<std::size_t>(i - lo_)] = i;
    // The whole symmetric matrix from its lower triangle (full storage gives the same): each
    // rank adds its entries (its summand, or, with the whole matrix on every rank, its own
    // rows'); hypre sends those of other ranks' rows to them when it assembles.
    std::vector<std::vector<std::pair<HYPRE_Int, double>>> rows(static_cast<std::size_t>(n_));
    int nonFinite = 0;
    for (Eigen::Index c = 0; c < A.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
        const auto r = static_cast<HYPRE_Int>(it.row()), k = static_cast<HYPRE_Int>(it.col());
        if (r < k) continue;
        if (!std::isfinite(it.value())) nonFinite = 1;
        const auto mine = [&](HYPRE_Int row) { return summed_ || (row >= lo_ && row < hi_); };
        if (mine(r)) rows[static_cast<std::size_t>(r)].emplace_back(k, it.value());
        if (r != k && mine(k)) rows[static_cast<std::size_t>(k)].emplace_back(r, it.value());
      }
    if (parallel::maxOverRanks(nonFinite) != 0) return FactorStatus::nonFinite;
    HYPRE_IJMatrixCreate(comm_, lo_, hi_ - 1, lo_, hi_ - 1, &ij_);
    HYPRE_IJMatrixSetObjectType(ij_, HYPRE_PARCSR);
    // Room per own row: its entries here, twice that where other ranks add to it.
    std::vector<HYPRE_Int> sizes(static_cast<std::size_t>(hi_ - lo_));
    for (HYPRE_Int r = lo_; r < hi_; ++r)
      sizes[static_cast<std::size_t>(r - lo_)] =
          static_cast<HYPRE_Int>(rows[static_cast<std::size_t>(r)].size()) * (summed_ ? 2 : 1) + 1;
    HYPRE_IJMatrixSetRowSizes(ij_, sizes.data());
    HYPRE_IJMatrixInitialize(ij_);
    std::vector<HYPRE_BigInt> cols;
    std::vector<double> values;
    for (HYPRE_Int r = 0; r < n_; ++r) {
      auto& row = rows[static_cast<std::size_t>(r)];
      if (row.empty()) continue;
      cols.clear();
      values.clear();
      for (const auto& [k, v] : row) {
        cols.push_back(k);
        values.push_back(v);
      }
      HYPRE_Int count = static_cast<HYPRE_Int>(row.size());
      HYPRE_BigInt at = r;
      HYPRE_IJMatrixAddToValues(ij_, 1, &count, &at, cols.data(), values.data());
      std::vector<std::pair<HYPRE_Int, double>>().swap(row);
    }
    HYPRE_IJMatrixAssemble(ij_);
    HYPRE_IJMatrixGetObject(ij_, reinterpret_cast<void**>(&A_));
    // A positive definite matrix has a positive diagonal (the assembled one: a rank's summand
    // alone may lack a row's cells).
    double nonzeros = 0, smallest = std::numeric_limits<double>::infinity();
    HYPRE_Int smallestRow = -1;
    for (HYPRE_Int r = lo_; r < hi_; ++r) {
      HYPRE_Int size = 0;
      HYPRE_BigInt* rowCols = nullptr;
      HYPRE_Complex* rowValues = nullptr;
      HYPRE_ParCSRMatrixGetRow(A_, r, &size, &rowCols, &rowValues);
      nonzeros += size;
      double diagonal = 0;
      for (HYPRE_Int q = 0; q < size; ++q)
        if (rowCols[q] == r) diagonal = rowValues[q];
      HYPRE_ParCSRMatrixRestoreRow(A_, r, &size, &rowCols, &rowValues);
      if (diagonal < smallest) smallest = diagonal, smallestRow = r;
    }
    nonzeros = parallel::sumOverRanks(nonzeros);
    if (parallel::maxOverRanks(smallest > 0 ? 0 : 1) != 0) {
      analysis_.problem =
          "a diagonal entry is not positive" +
          (smallestRow >= 0 && !(smallest > 0)
               ? " (row " + std::to_string(smallestRow) + ": " + formatted(smallest) + ")"
               : std::string()) +
          ": the matrix is not positive definite";
      return FactorStatus::notPositiveDefinite;
    }
    b_ = makeVector();
    x_ = makeVector();
    r_ = makeVector();

    HYPRE_BoomerAMGCreate(&amg_);
    HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
    HYPRE_BoomerAMGSetCoarsenType(amg_, 10);  // HMIS
    HYPRE_BoomerAMGSetInterpType(amg_, 6);    // extended+i
    HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
    HYPRE_BoomerAMGSetAggNumLevels(amg_, 1);  // aggressive coarsening on the finest level
    HYPRE_BoomerAMGSetStrongThreshold(amg_, componentCount_ == 3 ? 0.5 : 0.25);
    HYPRE_BoomerAMGSetRelaxType(amg_, 6);  // symmetric hybrid Gauss–Seidel
    HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
    HYPRE_BoomerAMGSetTol(amg_, 0.0);
    HYPRE_BoomerAMGSetMaxIter(amg_, 1);
    if (componentCount_ > 1 && static_cast<HYPRE_Int>(components_.size()) == n_) {
      HYPRE_BoomerAMGSetNumFunctions(amg_, componentCount_);
      // hypre takes the array and frees it with the solver.
      const auto own = static_cast<std::size_t>(hi_ - lo_);
      auto* dofFunc = static_cast<HYPRE_Int*>(std::malloc(sizeof(HYPRE_Int) * own));
      for (std::size_t i = 0; i < own; ++i)
        dofFunc[i] = components_[static_cast<std::size_t>(lo_) + i];
      HYPRE_BoomerAMGSetDofFunc(amg_, dofFunc);
    }
    HYPRE_ParCSRPCGCreate(comm_, &pcg_);
    HYPRE_PCGSetTol(pcg_, tolerance_);
    HYPRE_PCGSetMaxIter(pcg_, maxIterations_);
    HYPRE_PCGSetTwoNorm(pcg_, 1);
    HYPRE_PCGSetPrintLevel(pcg_, 0);
    HYPRE_PCGSetPrecond(pcg_, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg_);
    HYPRE_ParCSRPCGSetup(pcg_, A_, bPar(), xPar());
    const double setupSeconds = secondsSince(start);
    reportPhase("BoomerAMG setup", setupSeconds);

    // The check: b = A r, x = A⁻¹ b, against r. r is 1 plus noise, so that a null space of
    // rigid translations (a part nothing holds) takes a large share of it.
    Eigen::VectorXd r(n_);
    std::mt19937_64 random(20261128);
    std::uniform_real_distribution<double> uniform(0.5, 1.5);
    for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = uniform(random);
    setOwn(x_, r);
    HYPRE_ParCSRMatrixMatvec(1.0, A_, xPar(), 0.0, bPar());
    const Eigen::VectorXd Ar = gathered(b_);
    const auto checkStart = std::chrono::steady_clock::now();
    bool converged = false;
    const Eigen::VectorXd x = solveOne(Ar, converged);
    const double forward = (x - r).norm() / r.norm();
    const double checkSeconds = secondsSince(checkStart);
    reportPhase("the check solve", checkSeconds);
    analysis_.analysisSeconds = setupSeconds;
    analysis_.numericSeconds = checkSeconds;
    std::ostringstream note;
    note.precision(3);
    note << "Linear solver amg: BoomerAMG ("
         << (componentCount_ > 1 ? std::to_string(componentCount_) + " displacement components"
                                 : std::string("scalar"))
         << ", " << nonzeros << " nonzeros) set up in " << setupSeconds
         << " s; CG to a relative residual of " << tolerance_ << ": the check solve A x = A r took "
         << lastIterations_ << " iterations (" << checkSeconds << " s), forward error |x - r|/|r| "
         << forward;
    analysis_.iterativeNote = note.str();
    analysis_.iterativeForwardError = forward;
    // x off r: a rigid translation in A's null space, whether CG stopped at its tolerance (the
    // right-hand side is consistent) or stalled.
    if (!(forward <= 1e-3)) {
      analysis_.problem = "the check solve A x = A r returned x off r by " + formatted(forward) +
                          " (relative; CG stopped after " + std::to_string(lastIterations_) +
                          " iterations at a relative residual of " + formatted(lastResidual_) +
                          "): the matrix is singular (a part of the body nothing holds)";
      return FactorStatus::notPositiveDefinite;
    }
    if (!converged) {
      analysis_.problem = "CG did not reach its tolerance " + formatted(tolerance_) +
                          ": it stopped after " + std::to_string(lastIterations_) +
                          " iterations (at most " + std::to_string(maxIterations_) +
                          ") at a relative residual |b - A x|/|b| of " + formatted(lastResidual_) +
                          "; double precision reaches about 1e-16 times the condition number: "
                          "loosen iterativeTolerance";
      return FactorStatus::failed;
    }
    return FactorStatus::ok;
  }

  Eigen::VectorXd pivots() const override { return {}; }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    bool converged = false;
    Eigen::VectorXd x = solveOne(b, converged);
    if (!converged) ++unconverged_;
    return x;
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override {
    Eigen::MatrixXd X(B.rows(), B.cols());
    for (Eigen::Index c = 0; c < B.cols(); ++c) X.col(c) = solve(Eigen::VectorXd(B.col(c)));
    return X;
  }

  FactorAnalysis analysis() const override {
    FactorAnalysis a = analysis_;
    a.iterativeSolves = solves_;
    a.iterativeIterations = iterations_;
    a.iterativeUnconverged = unconverged_;
    a.iterativeWorstResidual = worstResidual_;
    return a;
  }

 private:
  static std::string formatted(double value) {
    std::ostringstream s;
    s.precision(3);
    s << value;
    return s.str();
  }

  HYPRE_IJVector makeVector() const {
    HYPRE_IJVector v;
    HYPRE_IJVectorCreate(comm_, lo_, hi_ - 1, &v);
    HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v);
    HYPRE_IJVectorAssemble(v);
    return v;
  }
  HYPRE_ParVector bPar() const { return parOf(b_); }
  HYPRE_ParVector xPar() const { return parOf(x_); }
  static HYPRE_ParVector parOf(HYPRE_IJVector v) {
    HYPRE_ParVector p;
    HYPRE_IJVectorGetObject(v, reinterpret_cast<void**>(&p));
    return p;
  }

  // This rank's rows of a whole vector into v.
  void setOwn(HYPRE_IJVector v, const Eigen::VectorXd& whole) const {
    HYPRE_IJVectorSetValues(v, hi_ - lo_, ownRows_.data(), whole.data() + lo_);
  }
  // The whole vector, every rank's rows of v, on every rank.
  Eigen::VectorXd gathered(HYPRE_IJVector v) const {
    Eigen::VectorXd whole(n_);
    HYPRE_IJVectorGetValues(v, hi_ - lo_, ownRows_.data(), whole.data() + lo_);
    if (ranks_ > 1)
      MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, whole.data(), rankCounts_.data(),
                     first_.data(), MPI_DOUBLE, comm_);
    return whole;
  }

  Eigen::VectorXd solveOne(const Eigen::VectorXd& b, bool& converged) const {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    converged = true;
    if (n_ == 0) return x;
    const double bNorm = b.norm();
    if (bNorm == 0) return x;
    setOwn(b_, b);
    setOwn(x_, x);
    HYPRE_ParCSRPCGSolve(pcg_, A_, bPar(), xPar());
    HYPRE_ClearAllErrors();  // "did not converge" is read below, not kept as hypre's error
    x = gathered(x_);
    HYPRE_Int iterations = 0, done = 0;
    HYPRE_PCGGetNumIterations(pcg_, &iterations);
    HYPRE_PCGGetConverged(pcg_, &done);
    // The true residual ‖b − A x‖/‖b‖, not CG's recursively updated one, which keeps falling
    // below what double precision can hold (measured: 1e-30 "reached" on the penny crack).
    HYPRE_ParVectorCopy(bPar(), parOf(r_));
    HYPRE_ParCSRMatrixMatvec(-1.0, A_, xPar(), 1.0, parOf(r_));
    double rr = 0;
    HYPRE_ParVectorInnerProd(parOf(r_), parOf(r_), &rr);
    const double residual = std::sqrt(rr) / bNorm;
    lastIterations_ = iterations;
    lastResidual_ = residual;
    ++solves_;
    iterations_ += iterations;
    if (residual > worstResidual_) worstResidual_ = residual;
    // Its stop and the true residual within 10 × the tolerance (the two differ by round-off).
    converged = done != 0 && residual <= 10 * tolerance_;
    return x;
  }

  void release() {
    if (pcg_) HYPRE_ParCSRPCGDestroy(pcg_);
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    if (b_) HYPRE_IJVectorDestroy(b_);
    if (x_) HYPRE_IJVectorDestroy(x_);
    if (r_) HYPRE_IJVectorDestroy(r_);
    if (ij_) HYPRE_IJMatrixDestroy(ij_);
    pcg_ = amg_ = nullptr;
    b_ = x_ = r_ = nullptr;
    ij_ = nullptr;
    A_ = nullptr;
  }

  bool summed_ = false;
  int ranks_ = 1;
  MPI_Comm comm_ = MPI_COMM_SELF;
  std::vector<HYPRE_Int> first_;       // first_[q]: the first row of rank q; first_[ranks_] = n_
  HYPRE_Int lo_ = 0, hi_ = 0;          // this rank's rows [lo_, hi_)
  std::vector<int> rankCounts_;        // rows per rank (MPI_Allgatherv)
  std::vector<HYPRE_BigInt> ownRows_;  // lo_, …, hi_ − 1
  std::vector<int> components_;
  int componentCount_ = 1;
  double tolerance_ = 1e-10;
  int maxIterations_ = 1000;
  HYPRE_Int n_ = 0;
  HYPRE_IJMatrix ij_ = nullptr;
  HYPRE_ParCSRMatrix A_ = nullptr;
  HYPRE_IJVector b_ = nullptr, x_ = nullptr, r_ = nullptr;
  HYPRE_Solver amg_ = nullptr, pcg_ = nullptr;
  FactorAnalysis analysis_;
  mutable long solves_ = 0;
  mutable long iterations_ = 0;
  mutable long unconverged_ = 0;
  mutable double worstResidual_ = 0;
  mutable int lastIterations_ = 0;
  mutable double lastResidual_ = 0;
};

}  // namespace

std::unique_ptr<SparseFactor::Backend> makeAmgBackend() {
  return std::unique_ptr<SparseFactor::Backend>(new AmgBackend);
}

}  // namespace friction
#endif
