// MumpsBackend: the "mumps" linear solver — MUMPS's multifrontal LDLᵀ (symmetric mode,
// SYM = 2), shared by the ranks of an MPI run (docs/method.md §4 "The distributed engine").
//
// Each rank hands MUMPS its entries (distributed assembled input, ICNTL(18) = 3): with
// setSummedInput(true) the matrix is the sum of the ranks' A (each assembled its own cells,
// README "Running in parallel"), otherwise every rank holds the whole A and gives a share of its
// columns. MUMPS then factors and solves across the ranks, in the order rank 0 computes (METIS
// by CHOLMOD, on the gathered pattern). Right-hand sides and solutions are centralised on rank
// 0 and the solution is broadcast, so that every rank continues with the same numbers.
//
// The interface operator: MUMPS's Schur complement (ICNTL(19) = 1) on the jump unknowns of
// the bordered matrix [A B; Bᵀ C], ordered last — the same "by-product of the one
// factorisation" as the cholmod backend's, but distributed. Solves with A afterwards use
// ICNTL(26) = 0, which solves the interior problem A x = b with the same factor. (PETSc's
// interface to MUMPS refuses Schur complements on more than one rank, which is why this calls
// MUMPS directly.)
//
// A smaller factor (MumpsMemory, system/frictionSolution keys lowRank and outOfCore): MUMPS's
// block low-rank factorisation (ICNTL(35) = 2, the factors kept low-rank for the solves too,
// CNTL(7) the dropping tolerance) and its out-of-core factorisation (ICNTL(22) = 1: the
// factor's full-rank blocks written to files, in a folder of our own made for the run inside
// the given one and removed, empty, after MUMPS has deleted its files). The Schur complement
// works with both: MUMPS keeps the Schur block itself full-rank and dense (measured on
// cases/pennyCrack, README "Running in parallel").
// Compiled only in builds with FRICTION_WITH_MUMPS (other builds skip the file).
#ifdef FRICTION_WITH_MUMPS
#include <dmumps_c.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "friction/core/Assert.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/linalg/SparseFactorBackend.hpp"

namespace friction {

namespace {

// MUMPS's 1-based control arrays, with the manual's numbering.
#define ICNTL(I) icntl[(I)-1]
#define CNTL(I) cntl[(I)-1]
#define INFOG(I) infog[(I)-1]
#define RINFOG(I) rinfog[(I)-1]

const char* mumpsOrderingName(int ordering) {
  switch (ordering) {
    case 0:
      return "AMD";
    case 1:
      return "METIS (by CHOLMOD)";
    case 2:
      return "AMF";
    case 3:
      return "SCOTCH";
    case 4:
      return "PORD";
    case 5:
      return "METIS";
    case 6:
      return "QAMD";
    default:
      return "";
  }
}

class MumpsBackend : public SparseFactor::Backend {
 public:
  MumpsBackend() {
    parallel::ensureInitialized();
    id_.comm_fortran = static_cast<MUMPS_INT>(parallel::fortranCommunicator());
    id_.par = 1;  // rank 0 works too
    // Symmetric (LDLᵀ), not MUMPS's SPD mode: only this mode detects null pivots (ICNTL(24)).
    // Measured: the stiffness of a free body bordered by jumps factored "fine" with SYM = 1,
    // round-off pivots and all; with SYM = 2 its three rigid modes are three null pivots. On
    // an SPD matrix every pivot passes the threshold test, so the factor is the same work.
    id_.sym = 2;
    id_.job = -1;
    dmumps_c(&id_);
    live_ = id_.INFOG(1) >= 0;
  }
  ~MumpsBackend() override {
    if (live_ && parallel::running()) {
      id_.job = -2;  // frees the factor and deletes its out-of-core files
      dmumps_c(&id_);
    }
    // Our folder, empty now: rmdir removes nothing else (it fails on a folder with files).
    if (!oocFolder_.empty()) ::rmdir(oocFolder_.c_str());
  }
  MumpsBackend(const MumpsBackend&) = delete;
  MumpsBackend& operator=(const MumpsBackend&) = delete;

  void setPivotTolerance(double tolerance) override { tolerance_ = tolerance; }
  bool setMumpsMemory(const MumpsMemory& memory) override {
    memory_ = memory;
    return true;
  }
  bool takesSummands() const override { return true; }
  void setSummedInput(bool summed) override { summed_ = summed; }

  FactorStatus factor(const SparseMatrix& A) override {
    schurSize_ = 0;
    return run(A, nullptr, nullptr, nullptr);
  }

  bool factorBordered(const SparseMatrix& A, const SparseMatrix& B, const SparseMatrix& C,
                      Eigen::MatrixXd& schur, FactorStatus& status, std::string& whyNot) override {
    schurSize_ = static_cast<MUMPS_INT>(B.cols());
    status = run(A, &B, &C, &schur);
    if (status == FactorStatus::failed && !problem_.empty()) {
      // Let the caller try A alone (and the complement by solves): say why.
      whyNot = "MUMPS could not factor the bordered matrix: " + problem_;
      schurSize_ = 0;
      return false;
    }
    return true;
  }

  Eigen::VectorXd pivots() const override { return {}; }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    return solveColumns(Eigen::MatrixXd(b)).col(0);
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return solveColumns(B); }

  FactorAnalysis analysis() const override { return analysis_; }

 private:
  // Entries of the lower triangle of [A B; Bᵀ C] (1-based), this rank's share: the columns of
  // a contiguous range chosen so that the ranks get about as many entries each. A summed A
  // (each rank's own cells) goes whole from every rank, MUMPS adds the ranks' entries; B and C,
  // whole on every rank, are shared out by columns.
  void shareEntries(const SparseMatrix& A, const SparseMatrix* B, const SparseMatrix* C) {
    const Eigen::Index n = A.rows(), m = B ? B->cols() : 0;
    // Column j's entries: A's lower part, then B's row j as (n + a, j); C's lower part after.
    const Eigen::SparseMatrix<double, Eigen::RowMajor> Brows =
        B ? Eigen::SparseMatrix<double, Eigen::RowMajor>(*B)
          : Eigen::SparseMatrix<double, Eigen::RowMajor>();
    std::vector<long> count(static_cast<std::size_t>(n + m), 0);
    long total = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!summed_)
        for (SparseMatrix::InnerIterator it(A, j); it; ++it) count[j] += it.row() >= j;
      if (B) count[j] += Brows.outerIndexPtr()[j + 1] - Brows.outerIndexPtr()[j];
      total += count[j];
    }
    for (Eigen::Index a = 0; a < m; ++a) {
      for (SparseMatrix::InnerIterator it(*C, a); it; ++it) count[n + a] += it.row() >= a;
      total += count[n + a];
    }
    const int ranks = parallel::size(), me = parallel::rank();
    const long from = total * me / ranks, to = total * (me + 1) / ranks;
    rows_.clear();
    cols_.clear();
    values_.clear();
    long seen = 0;
    const auto add = [&](Eigen::Index i, Eigen::Index j, double v) {
      rows_.push_back(static_cast<MUMPS_INT>(i + 1));
      cols_.push_back(static_cast<MUMPS_INT>(j + 1));
      values_.push_back(v);
    };
    for (Eigen::Index j = 0; j < n + m; ++j) {
      // A column belongs to the rank whose range holds its first entry.
      const bool mine = seen >= from && seen < to;
      seen += count[j];
      if (j < n && (mine || summed_))
        for (SparseMatrix::InnerIterator it(A, j); it; ++it)
          if (it.row() >= j) add(it.row(), j, it.value());
      if (!mine) continue;
      if (j < n) {
        if (B)
          for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Brows, j); it; ++it)
            add(n + it.col(), j, it.value());
      } else {
        for (SparseMatrix::InnerIterator it(*C, j - n); it; ++it)
          if (it.row() >= j - n) add(n + it.row(), j, it.value());
      }
    }
  }

  // The factorisation; what went wrong, if anything, in analysis().problem.
  FactorStatus run(const SparseMatrix& A, const SparseMatrix* B, const SparseMatrix* C,
                   Eigen::MatrixXd* schur) {
    const FactorStatus status = runPhases(A, B, C, schur);
    analysis_.problem = problem_;
    return status;
  }

  FactorStatus runPhases(const SparseMatrix& A, const SparseMatrix* B, const SparseMatrix* C,
                         Eigen::MatrixXd* schur) {
    problem_.clear();
    analysis_ = {};
    if (!live_) {
      problem_ = "MUMPS did not start";
      return FactorStatus::failed;
    }
    n_ = static_cast<MUMPS_INT>(A.rows());
    const MUMPS_INT m = B ? static_cast<MUMPS_INT>(B->cols()) : 0;
    shareEntries(A, B, C);
    // Silent: the log reports what matters.
    id_.ICNTL(1) = -1;
    id_.ICNTL(2) = -1;
    id_.ICNTL(3) = -1;
    id_.ICNTL(4) = 0;
    id_.ICNTL(18) = 3;  // distributed assembled input
    perm_.clear();
    // The ordering: METIS's nested dissection of A, computed on rank 0 by CHOLMOD (linked
    // anyway), with the border after it, given to MUMPS (ICNTL(7) = 1). MUMPS's own choice is
    // worse here: with a Schur complement it takes AMD whatever ICNTL(7) asks (METIS, SCOTCH
    // and PORD tried), which on cases/pennyCrack at h = a/8 made 8.9e7 factor entries and
    // 3.1e11 flops, against 5.0e7 and 9.1e10 with this order (CHOLMOD's own: 4.7e7, 8.7e10).
    // A summed A: rank 0 orders the pattern of the whole (the ranks' patterns gathered there for
    // the analysis, then freed).
    SparseMatrix whole;
    if (summed_) whole = gatherPattern(A);
    if (parallel::isMaster() && metisOrder(summed_ ? whole : A, m, perm_)) {
      id_.ICNTL(7) = 1;
      id_.perm_in = perm_.data();
    } else {
      id_.ICNTL(7) = 7;  // MUMPS's automatic choice
      id_.perm_in = nullptr;
    }
    whole = SparseMatrix();
    int given = id_.ICNTL(7);
    parallel::broadcast(&given, 1);
    id_.ICNTL(7) = given;
    if (!lowRankAndOutOfCore()) return FactorStatus::failed;
    id_.ICNTL(24) = 1;         // detect null pivots: a singular matrix is a status, not a factor
    id_.CNTL(3) = tolerance_;  // null below tolerance · max |A_ij| (relative, CNTL(3) > 0)
    id_.n = n_ + m;
    id_.nnz_loc = static_cast<MUMPS_INT8>(rows_.size());
    id_.irn_loc = rows_.data();
    id_.jcn_loc = cols_.data();
    id_.a_loc = values_.data();
    schurVars_.clear();
    schurValues_.clear();
    if (m > 0) {
      for (MUMPS_INT a = 0; a < m; ++a) schurVars_.push_back(n_ + a + 1);
      id_.ICNTL(19) = 1;  // the complement, centralised on rank 0
      id_.size_schur = m;
      id_.listvar_schur = schurVars_.data();
      if (parallel::isMaster()) schurValues_.assign(static_cast<std::size_t>(m) * m, 0.0);
      id_.schur = parallel::isMaster() ? schurValues_.data() : nullptr;
    } else {
      id_.ICNTL(19) = 0;
      id_.size_schur = 0;
      id_.listvar_schur = nullptr;
      id_.schur = nullptr;
    }
    // Analysis, then the numeric factorisation; MUMPS's workspace estimate may be short:
    // grow it (ICNTL(14), percent) and factor again.
    double clock = wallClock();
    id_.job = 1;
    dmumps_c(&id_);
    analysis_.analysisSeconds = wallClock() - clock;
    if (id_.INFOG(1) < 0) return verdict();
    reportPhase("ordering and analysis (MUMPS)", analysis_.analysisSeconds);
    if (!chooseOutOfCore()) return FactorStatus::failed;
    clock = wallClock();
    id_.ICNTL(14) = 30;
    for (int attempt = 0; attempt < 4; ++attempt) {
      id_.job = 2;
      dmumps_c(&id_);
      const int e = id_.INFOG(1);
      if (e != -8 && e != -9 && e != -14 && e != -15 && e != -17 && e != -20) break;
      id_.ICNTL(14) *= 3;
    }
    analysis_.numericSeconds = wallClock() - clock;
    const FactorStatus status = verdict();
    record();
    if (status == FactorStatus::ok)
      reportPhase("numeric factorisation (MUMPS)", analysis_.numericSeconds);
    if (status == FactorStatus::ok && schur) {
      clock = wallClock();
      Eigen::MatrixXd S(m, m);
      if (parallel::isMaster()) S = Eigen::Map<Eigen::MatrixXd>(schurValues_.data(), m, m);
      parallel::broadcast(S.data(), static_cast<long>(S.size()));
      schurValues_ = std::vector<double>();
      // A symmetric Schur complement comes back as its lower triangle by rows (ICNTL(19) =
      // 1), i.e. the upper triangle of this column-major view; the rest of the buffer is
      // not part of it (measured: on a 3D fault with 627 jump unknowns MUMPS leaves other
      // numbers there). Mirror the upper triangle.
      S.triangularView<Eigen::StrictlyLower>() = S.transpose();
      schur->swap(S);
      analysis_.complementSeconds = wallClock() - clock;
      reportPhase("interface operator S, the complement of the " + std::to_string(m) +
                      " jump unknowns (MUMPS)",
                  analysis_.complementSeconds);
    }
    return status;
  }

  // MumpsMemory's controls, set before the analysis (MUMPS prepares the low-rank clustering
  // there). Out of core: a folder of this run's own inside the given one, made at the first
  // factorisation (one per rank: each writes its own files). False, with problem_ set, if the
  // folder cannot be made.
  bool lowRankAndOutOfCore() {
    id_.ICNTL(35) = memory_.lowRank > 0 ? 2 : 0;  // 2: low-rank factors for the solves too
    id_.CNTL(7) = memory_.lowRank;
    const bool now = !memory_.outOfCoreDir.empty() && !memory_.outOfCoreAuto;
    id_.ICNTL(22) = now ? 1 : 0;
    return !now || outOfCoreFolder();
  }

  // outOfCore auto, after the analysis: out of core where MUMPS's in-core estimate exceeds the
  // limit (MumpsMemory). MUMPS reads ICNTL(22) and the folder at the factorisation. Every rank
  // takes rank 0's verdict. False, with problem_ set, if the folder cannot be made.
  bool chooseOutOfCore() {
    if (!memory_.outOfCoreAuto || memory_.outOfCoreDir.empty()) return true;
    // INFOG(17), INFOG(37): the in-core estimates [MB] summed over the ranks.
    const double estimate = 1e6 * (memory_.lowRank > 0 ? id_.INFOG(37) : id_.INFOG(17));
    double limit = memory_.outOfCoreAbove > 0 ? memory_.outOfCoreAbove : availableMemory();
    parallel::broadcast(&limit, 1);
    const bool outOfCore = estimate > limit;
    std::ostringstream why;
    why << std::setprecision(3) << "outOfCore auto: " << (outOfCore ? "out of core" : "in core")
        << ", MUMPS's in-core estimate " << estimate / 1e9 << " GB " << (outOfCore ? "> " : "<= ")
        << limit / 1e9 << " GB"
        << (memory_.outOfCoreAbove > 0 ? " (outOfCoreAbove)" : " available");
    analysis_.outOfCoreChoice = why.str();
    id_.ICNTL(22) = outOfCore ? 1 : 0;
    return !outOfCore || outOfCoreFolder();
  }

  bool outOfCoreFolder() {
    int failed = 0;
    if (oocFolder_.empty()) {
      std::string name = memory_.outOfCoreDir + "/mumpsOutOfCore.XXXXXX";
      if (name.size() >= sizeof(id_.ooc_tmpdir) || !::mkdtemp(name.data())) {
        problem_ = "cannot make a folder for the out-of-core factor in '" + memory_.outOfCoreDir +
                   "': " +
                   (name.size() >= sizeof(id_.ooc_tmpdir) ? std::string("path too long for MUMPS")
                                                          : std::strerror(errno));
        failed = 1;
      } else {
        oocFolder_ = name;
      }
    }
    // Every rank goes on to the analysis, or none does (it is collective).
    if (parallel::maxOverRanks(failed) > 0) {
      if (problem_.empty()) problem_ = "another rank could not make its out-of-core folder";
      return false;
    }
    std::snprintf(id_.ooc_tmpdir, sizeof(id_.ooc_tmpdir), "%s", oocFolder_.c_str());
    std::snprintf(id_.ooc_prefix, sizeof(id_.ooc_prefix), "%s", "factor");
    return true;
  }

  // The pattern of the sum of the ranks' A (lower triangle, values 1) on rank 0; empty on the
  // others. Collective.
  static SparseMatrix gatherPattern(const SparseMatrix& A) {
    std::vector<int> mine;
    for (Eigen::Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j)
          mine.insert(mine.end(), {static_cast<int>(it.row()), static_cast<int>(j)});
    const std::vector<int> all = parallel::gatherOnMaster(mine);
    std::vector<int>().swap(mine);
    SparseMatrix P(A.rows(), A.cols());
    if (!parallel::isMaster()) return P;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(all.size() / 2);
    for (std::size_t k = 0; k + 1 < all.size(); k += 2) t.emplace_back(all[k], all[k + 1], 1.0);
    P.setFromTriplets(t.begin(), t.end());
    return P;
  }

  // perm[i] = position (1-based) of unknown i in the elimination order: METIS on A's pattern,
  // then the m border unknowns in their order. False if it could not order.
  static bool metisOrder(const SparseMatrix& A, MUMPS_INT m, std::vector<MUMPS_INT>& perm) {
    std::vector<long> order;
    if (!metisOrdering(A, order)) return false;
    const Eigen::Index n = A.rows();
    perm.assign(static_cast<std::size_t>(n + m), 0);
    for (Eigen::Index k = 0; k < n; ++k) perm[order[k]] = static_cast<MUMPS_INT>(k + 1);
    for (MUMPS_INT a = 0; a < m; ++a) perm[n + a] = static_cast<MUMPS_INT>(n + a + 1);
    return true;
  }

  FactorStatus verdict() {
    const int e = id_.INFOG(1);
    if (e == -10) return FactorStatus::notPositiveDefinite;  // numerically singular
    if (e < 0) {
      problem_ = e == -13 ? "out of memory (INFOG(1) = -13)"
                 : e <= -90 && e >= -99 && !oocFolder_.empty()
                     ? "the out-of-core factor could not be written to " + oocFolder_ +
                           " (disk full or not writable? INFOG(1) = " + std::to_string(e) + ")"
                     : "error INFOG(1) = " + std::to_string(e) +
                           ", INFOG(2) = " + std::to_string(id_.INFOG(2));
      return FactorStatus::failed;
    }
    if (id_.job == 1) return FactorStatus::ok;
    // A negative pivot (INFOG(12)) means A is indefinite, a null one (INFOG(28), below
    // pivotTolerance · max |A_ij|) that it is singular to round-off.
    if (id_.INFOG(12) > 0 || id_.INFOG(28) > 0) return FactorStatus::notPositiveDefinite;
    return FactorStatus::ok;
  }

  void record() {
    analysis_.ordering = mumpsOrderingName(id_.INFOG(7));
    // INFOG(29): entries of the factors (negative: millions).
    const double entries = id_.INFOG(29) >= 0 ? id_.INFOG(29) : -1e6 * id_.INFOG(29);
    analysis_.entries = entries;
    analysis_.bytes = 8.0 * entries;
    analysis_.flops = id_.RINFOG(3);
    analysis_.ranks = parallel::size();
    // INFOG(21), INFOG(22): memory the factorisation used [MB], the largest rank's and all.
    analysis_.rankMemoryMax = 1e6 * id_.INFOG(21);
    analysis_.memoryTotal = 1e6 * id_.INFOG(22);
    analysis_.estimatedInCore = 1e6 * id_.INFOG(17);
    analysis_.estimatedOutOfCore = 1e6 * id_.INFOG(27);
    if (memory_.lowRank > 0)
      analysis_.estimatedLowRank = 1e6 * (oocFolder_.empty() ? id_.INFOG(37) : id_.INFOG(39));
    if (memory_.lowRank > 0) {
      // INFOG(35): the entries the low-rank factor keeps; INFOG(29) those of the full-rank one.
      analysis_.lowRank = memory_.lowRank;
      analysis_.fullRankEntries = entries;
      analysis_.entries = id_.INFOG(35) >= 0 ? id_.INFOG(35) : -1e6 * id_.INFOG(35);
      analysis_.bytes = 8.0 * analysis_.entries;
      analysis_.lowRankFlops = id_.RINFOG(14);
    }
    if (!oocFolder_.empty()) {
      analysis_.outOfCoreDir = oocFolder_;
      analysis_.outOfCoreBytes = 1e6 * id_.RINFOG(16);  // [MB] written by all ranks
    }
  }

  // Every rank calls it with the same B; rank 0's solution reaches all of them.
  Eigen::MatrixXd solveColumns(const Eigen::MatrixXd& B) const {
    const Eigen::Index n = n_, k = B.cols(), N = n_ + schurSize_;
    FRICTION_ASSERT(B.rows() == n, "mumps solve: right-hand side of the wrong size");
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(N, k);
    if (parallel::isMaster()) X.topRows(n) = B;
    id_.ICNTL(20) = 0;  // dense right-hand sides on rank 0
    id_.ICNTL(21) = 0;  // solution there too
    id_.ICNTL(26) = 0;  // with a Schur complement: the interior problem A x = b only
    id_.nrhs = static_cast<MUMPS_INT>(k);
    id_.lrhs = static_cast<MUMPS_INT>(N);
    id_.rhs = parallel::isMaster() ? X.data() : nullptr;
    id_.job = 3;
    dmumps_c(&id_);
    FRICTION_ASSERT(id_.INFOG(1) >= 0, "MUMPS solve failed");
    Eigen::MatrixXd out = X.topRows(n);
    parallel::broadcast(out.data(), static_cast<long>(out.size()));
    return out;
  }

  static double wallClock() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  mutable DMUMPS_STRUC_C id_{};
  bool live_ = false;
  double tolerance_ = 1e-10;
  bool summed_ = false;
  MUMPS_INT n_ = 0, schurSize_ = 0;
  std::vector<MUMPS_INT> rows_, cols_, schurVars_, perm_;
  std::vector<double> values_, schurValues_;
  std::string problem_;
  FactorAnalysis analysis_;
  MumpsMemory memory_;
  std::string oocFolder_;  // this run's folder of out-of-core files (empty: in core)
};

}  // namespace

std::unique_ptr<SparseFactor::Backend> makeMumpsBackend() {
  return std::unique_ptr<SparseFactor::Backend>(new MumpsBackend);
}

}  // namespace friction
#endif  // FRICTION_WITH_MUMPS
