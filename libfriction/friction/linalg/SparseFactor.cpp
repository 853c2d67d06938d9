// SparseFactor: one factorisation of the reduced stiffness matrix, many back-substitutions
// (docs/method.md §4). Backends behind a small interface; the table below lists every backend.
#include "friction/linalg/SparseFactor.hpp"

#include <dlfcn.h>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <type_traits>

#include "friction/core/Assert.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/linalg/RestrictedSolve.hpp"
#include "friction/linalg/SparseFactorBackend.hpp"

// LAPACK (OpenBLAS's at run time, as for CHOLMOD): U Uᵀ in place of an upper triangular U.
extern "C" void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);

namespace friction {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class SimplicialLdltBackend : public SparseFactor::Backend {
 public:
  FactorStatus factor(const SparseMatrix& A) override {
    ldlt_.compute(A);
    // Eigen reports NumericalIssue only for an exactly zero pivot; small and negative pivots
    // are judged by the caller from pivots().
    if (ldlt_.info() == Eigen::NumericalIssue) return FactorStatus::notPositiveDefinite;
    return ldlt_.info() == Eigen::Success ? FactorStatus::ok : FactorStatus::failed;
  }
  Eigen::VectorXd pivots() const override {
    // P A Pᵀ = L D Lᵀ and row i of A is row P.indices()[i] of the permuted matrix.
    const Eigen::VectorXd d = ldlt_.vectorD();
    const auto& p = ldlt_.permutationP().indices();
    Eigen::VectorXd out(d.size());
    for (Eigen::Index i = 0; i < d.size(); ++i) out[i] = d[p[i]];
    return out;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return ldlt_.solve(b); }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return ldlt_.solve(B); }

 private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
};

// CHOLMOD is called with 64-bit indices (its cholmod_l_ functions): with 32-bit ones a factor
// is limited to 2³¹ stored values (16 GB), and the bordered factor of a 3D penny of 849 360
// unknowns (1.77e9 entries, more with the supernodes' padding) failed with them.
using CholmodIndex = SuiteSparse_long;
using CholmodMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, CholmodIndex>;

/// Eigen's wrapper with access to the CHOLMOD factor, which we need to read the pivots and to
/// check that the analysis succeeded before factorising (Eigen would dereference a null
/// factor after a failed analysis).
class CholmodLlt : public Eigen::CholmodSupernodalLLT<CholmodMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* cholmodFactor() const { return m_cholmodFactor; }
  /// The symbolic analysis of A (lower triangle read) in the order `perm` (postordered on
  /// top, as CHOLMOD's own orderings are), in place of analyzePattern's own ordering.
  void analyzeGiven(const CholmodMatrix& A, CholmodIndex* perm) {
    release();
    cholmod_common& cm = cholmod();
    cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    cm.postorder = 1;
    m_cholmodFactor = cholmod_l_analyze_p(&view, perm, nullptr, 0, &cm);
    this->m_isInitialized = true;
    this->m_info = Eigen::Success;
    m_analysisIsOk = true;
    m_factorizationIsOk = false;
  }
  /// Release the factor (or the analysis) held: the bordered path needs only its ordering.
  void release() {
    if (m_cholmodFactor) cholmod_l_free_factor(&m_cholmodFactor, &cholmod());
    m_cholmodFactor = nullptr;
    m_analysisIsOk = m_factorizationIsOk = false;
  }
};

// Pivots of a CHOLMOD factor (d of LDLᵀ, l² of LLᵀ) for the first `rows` original rows. Row k
// of the factor is row perm[k] of the matrix: L's own permutation, unless `perm` is given (a
// factor of a matrix that was permuted before CHOLMOD saw it).
Eigen::VectorXd cholmodPivots(const cholmod_factor& L, Eigen::Index rows,
                              const CholmodIndex* perm = nullptr) {
  using I = CholmodIndex;
  const auto n = static_cast<Eigen::Index>(L.n);
  const double* x = static_cast<const double*>(L.x);
  if (!perm) perm = static_cast<const I*>(L.Perm);
  Eigen::VectorXd inFactorOrder(n);
  if (L.is_super) {
    // Supernode s: columns super[s] .. super[s+1]−1, stored as a dense column-major block
    // of pi[s+1] − pi[s] rows starting at px[s]; its diagonal has stride rows + 1.
    const I* super = static_cast<const I*>(L.super);
    const I* pi = static_cast<const I*>(L.pi);
    const I* px = static_cast<const I*>(L.px);
    for (std::size_t s = 0; s < L.nsuper; ++s) {
      const I nrows = pi[s + 1] - pi[s];
      for (I j = 0; j < super[s + 1] - super[s]; ++j) {
        const double l = x[px[s] + j * (nrows + 1)];
        inFactorOrder[super[s] + j] = l * l;
      }
    }
  } else {
    const I* p = static_cast<const I*>(L.p);
    for (Eigen::Index k = 0; k < n; ++k) {
      const double d = x[p[k]];
      inFactorOrder[k] = L.is_ll ? d * d : d;
    }
  }
  // Row k of the factor is row Perm[k] of the factored matrix.
  Eigen::VectorXd out(rows);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index row = perm ? perm[k] : k;
    if (row < rows) out[row] = inFactorOrder[k];
  }
  return out;
}

// A fingerprint of A's pattern (its size and, column by column, its row indices; FNV-1a): the
// ordering predict() keeps is for this pattern only.
std::uint64_t patternKey(const Eigen::SparseMatrix<double>& A) {
  std::uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](std::uint64_t v) {
    h ^= v;
    h *= 1099511628211ull;
  };
  mix(static_cast<std::uint64_t>(A.rows()));
  mix(static_cast<std::uint64_t>(A.cols()));
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    mix(static_cast<std::uint64_t>(j) << 32);
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      mix(static_cast<std::uint64_t>(it.row()));
  }
  return h;
}

// A square compressed column-major matrix as CHOLMOD sees it, lower triangle read: values x
// (REAL), or its pattern alone (x null).
cholmod_sparse lowerView(std::size_t n, std::size_t nnz, CholmodIndex* p, CholmodIndex* i,
                         double* x, bool sorted) {
  cholmod_sparse c{};
  c.nrow = c.ncol = n;
  c.nzmax = nnz;
  c.p = p;
  c.i = i;
  c.x = x;
  c.stype = -1;
  c.itype = CHOLMOD_LONG;
  c.xtype = x ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  c.dtype = CHOLMOD_DOUBLE;
  c.sorted = sorted ? 1 : 0;
  c.packed = 1;
  return c;
}

cholmod_sparse viewLower(const CholmodMatrix& A) {
  return lowerView(static_cast<std::size_t>(A.cols()), static_cast<std::size_t>(A.nonZeros()),
                   const_cast<CholmodIndex*>(A.outerIndexPtr()),
                   const_cast<CholmodIndex*>(A.innerIndexPtr()), const_cast<double*>(A.valuePtr()),
                   true);
}

// The lower triangle of A with CHOLMOD's indices, written in compressed form directly (the
// rows of a column stay in A's order).
CholmodMatrix lowerTriangle(const Eigen::SparseMatrix<double>& A) {
  using I = CholmodIndex;
  const I n = A.cols();
  CholmodMatrix lower(A.rows(), n);
  I nnz = 0;
  for (I j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) nnz += it.row() >= j;
  lower.resizeNonZeros(nnz);
  I* outer = lower.outerIndexPtr();
  I* inner = lower.innerIndexPtr();
  double* value = lower.valuePtr();
  I pos = 0;
  for (I j = 0; j < n; ++j) {
    outer[j] = pos;
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (it.row() >= j) inner[pos] = it.row(), value[pos++] = it.value();
  }
  outer[n] = pos;
  return lower;
}

// The columns of a symmetric matrix grouped by their pattern. Columns with the same rows —
// the d displacement components of a node in a finite-element stiffness — are
// indistinguishable to a fill-reducing ordering, so it can order the graph of the groups
// instead: a d-th of the vertices and about a d²-th of the edges, where its time goes (AMD and
// METIS find such vertices themselves, but only after reading the whole graph; measured in the
// README, "The ordering"). A group's columns are then consecutive in the ordering.
struct ColumnGroups {
  std::vector<CholmodIndex> first;    ///< group g: members[first[g]] … members[first[g+1]−1]
  std::vector<CholmodIndex> members;  ///< the columns, group after group, ascending in each
  std::vector<CholmodIndex> of;       ///< each column's group
  CholmodIndex count() const { return static_cast<CholmodIndex>(first.size()) - 1; }
};

// Groups of equal columns of A (both triangles stored, rows sorted in each column). Two
// equal columns that hold their diagonal hold each other, so a column's candidates are its
// own rows: one pass over the pattern, with a hash to skip most comparisons. A column whose
// rows are not sorted stays alone (the ordering is then that of A's own graph there).
ColumnGroups indistinguishableColumns(const Eigen::SparseMatrix<double>& A) {
  using I = CholmodIndex;
  const I n = A.cols();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int* nnz = A.innerNonZeroPtr();  // null when compressed
  auto end = [&](I j) { return nnz ? outer[j] + nnz[j] : outer[j + 1]; };
  std::vector<std::uint64_t> hash(static_cast<std::size_t>(n));
  for (I j = 0; j < n; ++j) {
    std::uint64_t h = 0;
    bool sorted = true;
    for (int p = outer[j]; p < end(j); ++p) {
      std::uint64_t x = static_cast<std::uint64_t>(inner[p]) + 0x9e3779b97f4a7c15ULL;
      x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;  // splitmix64's finaliser
      x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
      h += x ^ (x >> 31);
      if (p > outer[j] && inner[p] <= inner[p - 1]) sorted = false;
    }
    // An unsorted column gets a hash of its own index: no other column matches it.
    hash[j] = sorted ? h : ~static_cast<std::uint64_t>(j) * 0x9e3779b97f4a7c15ULL;
  }
  ColumnGroups g;
  g.of.assign(static_cast<std::size_t>(n), -1);
  g.members.reserve(static_cast<std::size_t>(n));
  g.first.reserve(static_cast<std::size_t>(n) + 1);
  auto same = [&](I j, I k) {
    if (hash[j] != hash[k] || end(j) - outer[j] != end(k) - outer[k]) return false;
    return std::equal(inner + outer[j], inner + end(j), inner + outer[k]);
  };
  g.first.push_back(0);
  for (I j = 0; j < n; ++j) {
    if (g.of[j] >= 0) continue;
    const I group = g.count();
    g.of[j] = group;
    g.members.push_back(j);
    for (int p = outer[j]; p < end(j); ++p) {
      const I k = inner[p];
      if (k > j && g.of[k] < 0 && same(j, k)) {
        g.of[k] = group;
        g.members.push_back(k);
      }
    }
    g.first.push_back(static_cast<I>(g.members.size()));
  }
  return g;
}

// The lower triangle of the graph of the groups, as a pattern: column g holds the groups of
// the rows of g's first column that are ≥ g (its own included).
struct GroupGraph {
  std::vector<CholmodIndex> p, i;
  cholmod_sparse view() {
    return lowerView(p.size() - 1, i.size(), p.data(), i.data(), nullptr, false);
  }
};

GroupGraph groupGraph(const Eigen::SparseMatrix<double>& A, const ColumnGroups& groups) {
  using I = CholmodIndex;
  const I G = groups.count();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int* nnz = A.innerNonZeroPtr();
  GroupGraph graph;
  graph.p.reserve(static_cast<std::size_t>(G) + 1);
  std::vector<I> mark(static_cast<std::size_t>(G), -1);
  graph.p.push_back(0);
  for (I g = 0; g < G; ++g) {
    const I j = groups.members[groups.first[g]];
    const int last = nnz ? outer[j] + nnz[j] : outer[j + 1];
    for (int q = outer[j]; q < last; ++q) {
      const I h = groups.of[inner[q]];
      if (h >= g && mark[h] != g) {
        mark[h] = g;
        graph.i.push_back(h);
      }
    }
    graph.p.push_back(static_cast<I>(graph.i.size()));
  }
  return graph;
}

cholmod_dense viewDense(Eigen::MatrixXd& X) {
  cholmod_dense d{};
  d.nrow = static_cast<std::size_t>(X.rows());
  d.ncol = static_cast<std::size_t>(X.cols());
  d.nzmax = d.nrow * d.ncol;
  d.d = d.nrow;
  d.x = X.data();
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

// Why CHOLMOD stopped, in a user's words (cholmod_common::status).
std::string cholmodProblem(int status) {
  switch (status) {
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "the factor is too large for CHOLMOD's integer type";
    case CHOLMOD_NOT_POSDEF:
      return "not positive definite";
    default:
      return "CHOLMOD status " + std::to_string(status);
  }
}

const char* cholmodOrderingName(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL:
      return "natural";
    case CHOLMOD_GIVEN:
      return "given";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    case CHOLMOD_COLAMD:
      return "COLAMD";
    case CHOLMOD_POSTORDERED:
      return "natural, postordered";
    default:
      return "unknown";
  }
}

class CholmodBackend : public SparseFactor::Backend {
 public:
  CholmodBackend() {
    // Silence CHOLMOD's own printing: "not positive definite" is reported as a status value.
    llt_.cholmod().print = 0;
  }
  ~CholmodBackend() override { freeBordered(); }
  CholmodBackend(const CholmodBackend&) = delete;
  CholmodBackend& operator=(const CholmodBackend&) = delete;

  bool takesOrdering() const override { return true; }
  void setOrdering(Ordering ordering, const std::string& choice) override {
    FRICTION_ASSERT(ordering != Ordering::automatic, "cholmod: the ordering must be resolved");
    ordering_ = ordering;
    choice_ = choice;
  }

  FactorStatus factor(const SparseMatrix& A32) override {
    freeBordered();
    analysis_ = {};
    const CholmodMatrix A = A32;
    auto clock = std::chrono::steady_clock::now();
    if (ordering_ == Ordering::cholmodDefault) {
      applyOrdering();
      llt_.analyzePattern(A);
      recordAnalysis(llt_.cholmodFactor());
    } else {
      std::vector<CholmodIndex> perm;
      int orderingA = -1;
      if (!groupedOrdering(A32, perm, orderingA)) return FactorStatus::failed;
      analysis_.orderingSeconds = secondsSince(clock);
      llt_.analyzeGiven(A, perm.data());
      recordAnalysis(llt_.cholmodFactor(), orderingA);
    }
    const double analysisSeconds = secondsSince(clock);
    if (!llt_.cholmodFactor() || llt_.cholmod().status < 0) return FactorStatus::failed;
    reportPhase(orderingPhase(), analysisSeconds);
    clock = std::chrono::steady_clock::now();
    llt_.factorize(A);
    analysis_.analysisSeconds = analysisSeconds;
    analysis_.numericSeconds = secondsSince(clock);
    reportPhase(numericPhase(), analysis_.numericSeconds);
    const int status = llt_.cholmod().status;
    if (status == CHOLMOD_NOT_POSDEF || llt_.info() == Eigen::NumericalIssue)
      return FactorStatus::notPositiveDefinite;
    return status < 0 ? FactorStatus::failed : FactorStatus::ok;
  }
  Eigen::VectorXd pivots() const override {
    return bordered_ ? cholmodPivots(*bordered_, rows_, borderedPerm_.data())
                     : cholmodPivots(*llt_.cholmodFactor(),
                                     static_cast<Eigen::Index>(llt_.cholmodFactor()->n));
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    if (!bordered_) return Eigen::VectorXd(llt_.solve(b));
    Eigen::MatrixXd B = b;
    return solveBordered(B).col(0);
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override {
    return bordered_ ? solveBordered(B) : Eigen::MatrixXd(llt_.solve(B));
  }
  SolveReach restrictTo(const std::vector<Eigen::Index>& rows) override {
    restricted_.reset();
    const cholmod_factor* L = llt_.cholmodFactor();
    if (bordered_ || !L || !L->is_super || L->xtype != CHOLMOD_REAL || rows.empty()) return {};
    static_assert(std::is_same_v<CholmodIndex, long>, "SupernodalView reads 64-bit longs");
    SupernodalView view;
    view.n = static_cast<long>(L->n);
    view.nsuper = static_cast<long>(L->nsuper);
    view.super = static_cast<const long*>(L->super);
    view.pi = static_cast<const long*>(L->pi);
    view.px = static_cast<const long*>(L->px);
    view.s = static_cast<const long*>(L->s);
    view.x = static_cast<const double*>(L->x);
    view.perm = L->ordering == CHOLMOD_NATURAL ? nullptr : static_cast<const long*>(L->Perm);
    restricted_ = std::make_unique<RestrictedSolve>(view, rows);
    return {restricted_->share(), static_cast<long>(restricted_->reachedSupernodes()), view.nsuper};
  }
  Eigen::MatrixXd solveRestricted(const Eigen::MatrixXd& B) const override {
    return restricted_ ? restricted_->solve(B) : solve(B);
  }

  // The bordered matrix is ordered as CHOLMOD orders A alone, then the border: the leading
  // block of its factor is then A's factor, and the trailing block L₂₂ satisfies
  // L₂₂ L₂₂ᵀ = C − Bᵀ A⁻¹ B. C is shifted by σ I (σ = the largest diagonal entry of C)
  // before factoring, and σ taken off again, because the complement itself may be only
  // semi-definite (a part held only by a fracture can move rigidly with the jump).
  //
  // The bordered matrix is written already permuted, and CHOLMOD analyses and factors it in
  // its natural order: given a permutation instead, CHOLMOD permutes (transposes) the matrix
  // twice for the analysis, twice more for the supernodes and twice with the values in the
  // numeric factorisation, which at 10⁶ unknowns in 2D took longer than AMD itself. The
  // symbolic and numeric factors are those of the same permuted matrix, so the factor is the
  // same, bit for bit; only the permutation is applied here (solveBordered, pivots).
  bool factorBordered(const SparseMatrix& A32, const SparseMatrix& B, const SparseMatrix& C,
                      Eigen::MatrixXd& schur, FactorStatus& status, std::string& whyNot) override {
    freeBordered();
    analysis_ = {};
    using I = CholmodIndex;
    cholmod_common& cm = llt_.cholmod();
    const I n = A32.rows(), m = B.cols();
    // 1. A's own fill-reducing ordering, chosen exactly as factor() chooses it (the same
    //    permutation, postorder included): on the graph of A's groups of equal columns
    //    (groupedOrdering), or with cholmodDefault CHOLMOD's strategy on A itself. Only the
    //    ordering is kept, so the analysis is simplicial: CHOLMOD orders and postorders before
    //    its supernodal analysis, which here would be thrown away (step 3 analyses the
    //    bordered matrix). CHOLMOD reads A's lower triangle only: the upper one is not copied.
    std::vector<I>& perm = borderedPerm_;
    perm.assign(static_cast<std::size_t>(n + m), 0);
    int orderingA = -1;
    llt_.release();  // a factor of an earlier factor(): at 10⁶ unknowns in 3D memory counts
    auto clock = std::chrono::steady_clock::now();
    if (ordering_ != Ordering::cholmodDefault) {
      std::vector<I> permA;
      if (!groupedOrdering(A32, permA, orderingA)) {
        status = FactorStatus::failed;
        return true;
      }
      std::copy(permA.begin(), permA.end(), perm.begin());
      for (I a = 0; a < m; ++a) perm[n + a] = n + a;
    } else {
      CholmodMatrix Alower = lowerTriangle(A32);
      cholmod_sparse viewA = viewLower(Alower);
      applyOrdering();
      const int supernodal = cm.supernodal;
      cm.supernodal = CHOLMOD_SIMPLICIAL;
      cholmod_factor* LA = cholmod_l_analyze(&viewA, &cm);
      cm.supernodal = supernodal;
      recordAnalysis(LA);
      if (!LA || cm.status < 0) {
        if (LA) cholmod_l_free_factor(&LA, &cm);
        status = FactorStatus::failed;
        return true;
      }
      orderingA = LA->ordering;
      const I* permA = static_cast<const I*>(LA->Perm);
      for (I i = 0; i < n; ++i) perm[i] = permA ? permA[i] : i;
      for (I a = 0; a < m; ++a) perm[n + a] = n + a;
      cholmod_l_free_factor(&LA, &cm);
    }
    const double orderingSeconds = secondsSince(clock);

    // 2. The bordered matrix in the order perm, lower triangle: row and column k are row and
    //    column perm[k] of [A B; Bᵀ C + σ I]. A's entry (i, j) moves to (max, min) of their
    //    new indices; B(j, a) to row n + a of column j's new index; C stays last.
    double sigma = 0;
    for (I a = 0; a < m; ++a) sigma = std::max(sigma, C.coeff(a, a));
    if (!(sigma > 0)) sigma = 1;
    std::vector<I> inverse(static_cast<std::size_t>(n));
    for (I k = 0; k < n; ++k) inverse[perm[k]] = k;
    const Eigen::SparseMatrix<double, Eigen::RowMajor> Brows = B;  // row j: the a with B(j, a)
    Eigen::SparseMatrix<double> Clower = C.triangularView<Eigen::Lower>();
    for (I a = 0; a < m; ++a) Clower.coeffRef(a, a) += sigma;
    Clower.makeCompressed();
    CholmodMatrix Ab(n + m, n + m);
    I* outer = Ab.outerIndexPtr();
    // Count the entries of each new column, then place them (next: each column's free slot).
    // A's lower triangle is read in place (rows ≥ the column), in A's order within a column.
    std::fill(outer, outer + n + m + 1, I(0));
    const int* aOuter = A32.outerIndexPtr();
    const int* aNnz = A32.innerNonZeroPtr();  // null when compressed
    const int* aInner = A32.innerIndexPtr();
    const double* aValue = A32.valuePtr();
    auto aEnd = [&](I j) { return aNnz ? aOuter[j] + aNnz[j] : aOuter[j + 1]; };
    for (I j = 0; j < n; ++j) {
      const I cj = inverse[j];
      for (I p = aOuter[j]; p < aEnd(j); ++p)
        if (aInner[p] >= j) ++outer[std::min(inverse[aInner[p]], cj) + 1];
      outer[cj + 1] += Brows.outerIndexPtr()[j + 1] - Brows.outerIndexPtr()[j];
    }
    for (I a = 0; a < m; ++a)
      outer[n + a + 1] = Clower.outerIndexPtr()[a + 1] - Clower.outerIndexPtr()[a];
    for (I k = 0; k < n + m; ++k) outer[k + 1] += outer[k];
    Ab.resizeNonZeros(outer[n + m]);
    I* inner = Ab.innerIndexPtr();
    double* value = Ab.valuePtr();
    std::vector<I> next(outer, outer + n + m);
    for (I j = 0; j < n; ++j) {
      const I cj = inverse[j];
      for (I p = aOuter[j]; p < aEnd(j); ++p) {
        if (aInner[p] < j) continue;
        const I ri = inverse[aInner[p]];
        const I q = next[std::min(ri, cj)]++;
        inner[q] = std::max(ri, cj);
        value[q] = aValue[p];
      }
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Brows, j); it; ++it) {
        const I q = next[cj]++;
        inner[q] = n + it.col();
        value[q] = it.value();
      }
    }
    for (I a = 0; a < m; ++a)
      for (SparseMatrix::InnerIterator it(Clower, a); it; ++it) {
        const I q = next[n + a]++;
        inner[q] = n + it.row();
        value[q] = it.value();
      }
    FRICTION_ASSERT(n + m == 0 || next[n + m - 1] == outer[n + m], "bordered matrix: entry count");
    std::vector<I>().swap(next);
    std::vector<I>().swap(inverse);
    cholmod_sparse view = viewLower(Ab);
    view.sorted = 0;  // a column's rows come in A's order, not the new one

    // 3. Symbolic analysis in that (natural) order, not postordered (a postorder could move a
    //    part of the body that no fracture touches behind the border).
    const int nmethods = cm.nmethods, ordering = cm.method[0].ordering, postorder = cm.postorder;
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_NATURAL;
    cm.postorder = 0;
    cholmod_factor* L = cholmod_l_analyze(&view, &cm);
    cm.nmethods = nmethods;
    cm.method[0].ordering = ordering;
    cm.postorder = postorder;
    if (!L || cm.status < 0) {
      whyNot = "the bordered analysis failed: " + cholmodProblem(cm.status);
      if (L) cholmod_l_free_factor(&L, &cm);
      return false;
    }
    if (!L->is_super) {
      whyNot = "CHOLMOD chose a simplicial factor for the bordered matrix";
      cholmod_l_free_factor(&L, &cm);
      return false;
    }
    recordAnalysis(L, orderingA);
    analysis_.orderingSeconds = orderingSeconds;

    // 4. Numeric factorisation. A pivot failure in A's columns is A's (the caller reports
    //    it); one in the border should not happen with the shift: fall back.
    const double analysisSeconds = secondsSince(clock);
    reportPhase(orderingPhase(), analysisSeconds);
    clock = std::chrono::steady_clock::now();
    cholmod_l_factorize(&view, L, &cm);
    const double numericSeconds = secondsSince(clock);
    if (cm.status >= 0 && cm.status != CHOLMOD_NOT_POSDEF)
      reportPhase(numericPhase(), numericSeconds);
    clock = std::chrono::steady_clock::now();
    CholmodMatrix().swap(Ab);  // the factor holds everything now
    if (cm.status == CHOLMOD_NOT_POSDEF) {
      const bool inA = L->minor < static_cast<std::size_t>(n);
      cholmod_l_free_factor(&L, &cm);
      if (!inA) {
        whyNot = "a pivot of the shifted jump block was not positive";
        return false;
      }
      status = FactorStatus::notPositiveDefinite;
      return true;
    }
    if (cm.status < 0) {
      // Out of memory with the border: A alone may still fit (then its complement comes
      // from blocks of solves).
      whyNot = "the bordered factorisation failed: " + cholmodProblem(cm.status);
      cholmod_l_free_factor(&L, &cm);
      return false;
    }

    // 5. L₂₂ from the supernodes whose columns reach into the border, written reversed:
    //    U = J L₂₂ J with J the reversal (U(m−1−r, m−1−c) = L₂₂(r, c)) is upper triangular.
    Eigen::MatrixXd U = Eigen::MatrixXd::Zero(m, m);
    const I* super = static_cast<const I*>(L->super);
    const I* pi = static_cast<const I*>(L->pi);
    const I* px = static_cast<const I*>(L->px);
    const I* Ls = static_cast<const I*>(L->s);
    const double* Lx = static_cast<const double*>(L->x);
    for (std::size_t s = 0; s < L->nsuper; ++s) {
      const I k1 = super[s], k2 = super[s + 1];
      if (k2 <= n) continue;
      const I nrows = pi[s + 1] - pi[s];
      const I* rows = Ls + pi[s];
      const double* X = Lx + px[s];
      for (I jj = std::max(k1, n) - k1; jj < k2 - k1; ++jj)
        for (I ii = jj; ii < nrows; ++ii)
          U(m - 1 - (rows[ii] - n), m - 1 - (k1 + jj - n)) = X[ii + jj * nrows];
    }
    // 6. The complement: L₂₂ L₂₂ᵀ − σ I.
    //    LAPACK's dlauum forms U Uᵀ for an upper triangular U in m³/3 operations (blocked,
    //    threaded), a third of a general product and far faster than Eigen's at m in the
    //    thousands, where this is the largest dense operation of the run; J (U Uᵀ) J = L₂₂ L₂₂ᵀ.
    int info = 0;
    const int m32 = static_cast<int>(m);
    dlauum_("U", &m32, U.data(), &m32, &info);
    FRICTION_ASSERT(info == 0, "dlauum failed");
    U.triangularView<Eigen::StrictlyLower>() = U.transpose();
    // J X J of a column-major square matrix is its storage read backwards: in place.
    std::reverse(U.data(), U.data() + U.size());
    schur.swap(U);
    schur.diagonal().array() -= sigma;
    analysis_.analysisSeconds = analysisSeconds;
    analysis_.numericSeconds = numericSeconds;
    analysis_.complementSeconds = secondsSince(clock);
    reportPhase("interface operator S, the complement of the " + std::to_string(m) +
                    " jump unknowns (dense, LAPACK)",
                analysis_.complementSeconds);
    bordered_ = L;
    rows_ = n;
    status = FactorStatus::ok;
    return true;
  }

  FactorAnalysis analysis() const override { return analysis_; }

  // The ordering factor() would use, then a simplicial symbolic analysis of A's lower pattern
  // in it: CHOLMOD counts the factor's entries and flops from the elimination tree and the
  // column counts, without building the factor's structure (memory O(n) beyond the pattern).
  bool predict(const SparseMatrix& A, FactorAnalysis& predicted) override {
    using I = CholmodIndex;
    analysis_ = {};
    auto clock = std::chrono::steady_clock::now();
    std::vector<I> perm;
    int orderingA = -1;
    kept_ = {};
    if (!groupedOrdering(A, perm, orderingA)) return false;
    const double orderingSeconds = secondsSince(clock);
    const double groups = analysis_.orderedGroups;
    // A's lower triangle as a pattern with CHOLMOD's 64-bit indices (no values).
    const I n = A.rows();
    std::vector<I> colStart(static_cast<std::size_t>(n + 1), 0), rows;
    for (I j = 0; j < n; ++j) {
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) rows.push_back(it.row());
      colStart[j + 1] = static_cast<I>(rows.size());
    }
    cholmod_sparse view = lowerView(static_cast<std::size_t>(n), rows.size(), colStart.data(),
                                    rows.data(), nullptr, false);
    cholmod_common& cm = llt_.cholmod();
    const int supernodal = cm.supernodal, nmethods = cm.nmethods, method = cm.method[0].ordering;
    cm.supernodal = CHOLMOD_SIMPLICIAL;
    cm.nmethods = 1;
    cm.method[0].ordering = CHOLMOD_GIVEN;
    cholmod_factor* L = cholmod_l_analyze_p(&view, perm.data(), nullptr, 0, &cm);
    cm.supernodal = supernodal;
    cm.nmethods = nmethods;
    cm.method[0].ordering = method;
    const bool ok = L && cm.status >= 0;
    if (L) cholmod_l_free_factor(&L, &cm);
    if (!ok) return false;
    analysis_.ordering = orderingA >= 0 ? cholmodOrderingName(orderingA) : "";
    analysis_.orderedGroups = groups;
    analysis_.entries = cm.lnz > 0 ? cm.lnz : 0;
    analysis_.flops = cm.fl > 0 ? cm.fl : 0;
    analysis_.bytes = 8.0 * analysis_.entries * SparseFactor::predictedPadding;
    analysis_.orderingSeconds = orderingSeconds;
    analysis_.analysisSeconds = secondsSince(clock);
    // Kept for the factorisation of this pattern: ordering is most of the analysis's time.
    kept_.key = patternKey(A);
    kept_.ordering = ordering_;
    kept_.perm = std::move(perm);
    kept_.cholmodOrdering = orderingA;
    kept_.groups = groups;
    predicted = analysis_;
    return true;
  }

 private:
  // A's fill-reducing ordering (ordering_, not cholmodDefault), postordered, computed on the
  // graph of A's groups of equal columns (indistinguishableColumns) and expanded to its
  // columns. The analysis is simplicial and thrown away: only the permutation is kept. False
  // if CHOLMOD failed (its status is in the common block). The ordering predict() kept, when
  // A has its pattern and the ordering is the same, is taken instead (once: a new factor of
  // the same pattern later orders again, as it always has).
  bool groupedOrdering(const SparseMatrix& A, std::vector<CholmodIndex>& perm, int& ordering) {
    using I = CholmodIndex;
    cholmod_common& cm = llt_.cholmod();
    if (!kept_.perm.empty()) {
      const Kept kept = std::move(kept_);
      kept_ = {};
      if (kept.ordering == ordering_ && kept.key == patternKey(A)) {
        perm = kept.perm;
        ordering = kept.cholmodOrdering;
        analysis_.orderedGroups = kept.groups;
        analysis_.orderingChoice = choice_ + ", ordered once for the prediction";
        return true;
      }
    }
    const ColumnGroups groups = indistinguishableColumns(A);
    GroupGraph graph = groupGraph(A, groups);
    cholmod_sparse view = graph.view();
    applyOrdering();
    const int supernodal = cm.supernodal;
    cm.supernodal = CHOLMOD_SIMPLICIAL;
    std::vector<I> permG;
    cholmod_factor* L = nullptr;
    bool amdDone = false;
    if (ordering_ == Ordering::amd) {
      // AMD alone: its order is already a postorder of its elimination tree.
      permG.resize(static_cast<std::size_t>(groups.count()));
      amdDone = cholmod_l_amd(&view, nullptr, 0, permG.data(), &cm) != 0;
    } else {
      L = cholmod_l_analyze(&view, &cm);
    }
    cm.supernodal = supernodal;
    if (L) {
      recordAnalysis(L);
      if (cm.status < 0) {
        cholmod_l_free_factor(&L, &cm);
        return false;
      }
      ordering = L->ordering;
      const I* p = static_cast<const I*>(L->Perm);
      permG.resize(static_cast<std::size_t>(groups.count()));
      for (I k = 0; k < groups.count(); ++k) permG[k] = p ? p[k] : k;
      cholmod_l_free_factor(&L, &cm);
    } else if (amdDone) {
      ordering = CHOLMOD_AMD;
      analysis_.orderingChoice = choice_;
    } else {
      return false;
    }
    perm.resize(groups.members.size());
    std::size_t pos = 0;
    for (const I g : permG)
      for (I q = groups.first[g]; q < groups.first[g + 1]; ++q) perm[pos++] = groups.members[q];
    analysis_.orderedGroups = static_cast<double>(groups.count());
    return true;
  }

  // The analysis CHOLMOD just made (its common block holds the last one's counts); the
  // ordering is L's own unless given (a bordered factor's is "given": A's is the one chosen).
  void recordAnalysis(const cholmod_factor* L, int ordering = -2) {
    const cholmod_common& cm = llt_.cholmod();
    if (ordering == -2) {
      ordering = L ? L->ordering : -1;
      // CHOLMOD's strategy says whether it ordered twice (it calls METIS only then).
      analysis_.orderingChoice = ordering_ != Ordering::cholmodDefault ? choice_
                                 : cm.called_nd ? choice_ + ", AMD then METIS tried"
                                                : choice_ + ", AMD only tried";
    }
    analysis_.ordering = ordering >= 0 ? cholmodOrderingName(ordering) : "";
    analysis_.entries = cm.lnz > 0 ? cm.lnz : 0;
    analysis_.flops = cm.fl > 0 ? cm.fl : 0;
    // A supernodal factor stores its supernodes as dense blocks, with the zeros that
    // amalgamation let in: that, not the entry count, is the memory.
    analysis_.bytes = L ? 8.0 * static_cast<double>(L->is_super ? L->xsize : L->nzmax) : 0;
  }

  std::string orderingPhase() const {
    std::ostringstream s;
    s << std::setprecision(3) << "ordering and analysis ("
      << (analysis_.ordering.empty() ? "CHOLMOD" : analysis_.ordering) << ", "
      << analysis_.orderingChoice;
    if (analysis_.orderingSeconds > 0) {
      s << "; ordering A " << analysis_.orderingSeconds << " s";
      if (analysis_.orderedGroups > 0)
        s << " on its " << static_cast<long long>(analysis_.orderedGroups)
          << " groups of equal columns";
    }
    s << "; " << analysis_.entries << " entries in the factor, " << analysis_.bytes / 1e9 << " GB)";
    return s.str();
  }

  // CHOLMOD's parameters for ordering_, before each analysis of A: one method, or CHOLMOD's
  // strategy (nmethods 0). A weighted postorder follows in every case, as by default.
  void applyOrdering() {
    cholmod_common& cm = llt_.cholmod();
    cm.postorder = 1;
    if (ordering_ == Ordering::cholmodDefault) {
      cm.nmethods = 0;
      return;
    }
    cm.nmethods = 1;
    cm.method[0].ordering = ordering_ == Ordering::amd     ? CHOLMOD_AMD
                            : ordering_ == Ordering::metis ? CHOLMOD_METIS
                                                           : CHOLMOD_NESDIS;
  }
  std::string numericPhase() const {
    std::ostringstream s;
    s << std::setprecision(3) << "numeric factorisation (CHOLMOD, " << analysis_.flops << " flops)";
    return s.str();
  }

  void freeBordered() {
    restricted_.reset();  // its view of the factor ends with the factor
    if (bordered_) cholmod_l_free_factor(&bordered_, &llt_.cholmod());
    bordered_ = nullptr;
  }

  // A⁻¹ B with the bordered factor: forward substitution through the border, the border's
  // part set to zero, backward substitution; the border's unknowns then come out zero and
  // the leading ones are A⁻¹ B (L₁₁ L₁₁ᵀ = A in the leading block). The factor is of the
  // permuted matrix: row k of it is row perm[k] of A (k < n; the border is last).
  Eigen::MatrixXd solveBordered(const Eigen::MatrixXd& B) const {
    cholmod_common& cm = llt_.cholmod();
    const Eigen::Index n = rows_, N = static_cast<Eigen::Index>(bordered_->n);
    const CholmodIndex* perm = borderedPerm_.data();
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(N, B.cols());
    for (Eigen::Index c = 0; c < B.cols(); ++c)
      for (Eigen::Index k = 0; k < n; ++k) X(k, c) = B(perm[k], c);
    cholmod_dense view = viewDense(X);
    cholmod_dense* z = cholmod_l_solve(CHOLMOD_L, bordered_, &view, &cm);
    if (z) {
      // The border is last in the factor's order: rows n … N−1 of the permuted vector.
      double* zx = static_cast<double*>(z->x);
      for (std::size_t c = 0; c < z->ncol; ++c)
        for (std::size_t r = static_cast<std::size_t>(n); r < z->nrow; ++r) zx[r + c * z->d] = 0;
    }
    cholmod_dense* w = z ? cholmod_l_solve(CHOLMOD_Lt, bordered_, z, &cm) : nullptr;
    cholmod_l_free_dense(&z, &cm);
    FRICTION_ASSERT(w != nullptr, "CHOLMOD solve with the bordered factor failed");
    Eigen::MatrixXd out(n, B.cols());
    const double* wx = static_cast<const double*>(w->x);
    for (Eigen::Index c = 0; c < B.cols(); ++c)
      for (Eigen::Index k = 0; k < n; ++k)
        out(perm[k], c) = wx[k + c * static_cast<Eigen::Index>(w->d)];
    cholmod_l_free_dense(&w, &cm);
    return out;
  }

  // The ordering of the last predict(), for the factorisation of the same pattern.
  struct Kept {
    std::uint64_t key = 0;
    Ordering ordering = Ordering::automatic;
    std::vector<CholmodIndex> perm;
    int cholmodOrdering = -1;
    double groups = 0;
  };
  Kept kept_;
  mutable CholmodLlt llt_;
  Ordering ordering_ = Ordering::amd;
  std::string choice_ = "ordering amd";
  cholmod_factor* bordered_ = nullptr;
  std::vector<CholmodIndex> borderedPerm_;       // the bordered factor's order (factorBordered)
  std::unique_ptr<RestrictedSolve> restricted_;  // restrictTo()'s reach in llt_'s factor
  Eigen::Index rows_ = 0;
  FactorAnalysis analysis_;
};

struct BackendEntry {
  const char* name;
  std::unique_ptr<SparseFactor::Backend> (*make)();
};

/// Every backend, one line each; the first is the default.
const BackendEntry kBackends[] = {
    {"cholmod", [] { return std::unique_ptr<SparseFactor::Backend>(new CholmodBackend); }},
    {"simplicialLDLT",
     [] { return std::unique_ptr<SparseFactor::Backend>(new SimplicialLdltBackend); }},
#ifdef FRICTION_WITH_MUMPS
    {"mumps", makeMumpsBackend},
#endif
#ifdef FRICTION_WITH_HYPRE
    {"amg", makeAmgBackend},
#endif
};

// One BLAS thread for a single right-hand side. A back-substitution with one vector is
// matrix–vector work (dtrsv, dgemv): OpenBLAS's threads gain no wall time on it but their
// busy-waiting doubled the CPU time on a 2-core machine. Factorisations and blocks of
// right-hand sides (matrix–matrix work) keep every thread. Found at run time, so that any
// other BLAS works unchanged.
class SingleBlasThread {
 public:
  SingleBlasThread() {
    if (set_ && get_) {
      saved_ = get_();
      if (saved_ > 1) set_(1);
    }
  }
  ~SingleBlasThread() {
    if (set_ && saved_ > 1) set_(saved_);
  }
  SingleBlasThread(const SingleBlasThread&) = delete;
  SingleBlasThread& operator=(const SingleBlasThread&) = delete;

 private:
  using Set = void (*)(int);
  using Get = int (*)();
  static inline const Set set_ =
      reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  static inline const Get get_ =
      reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  int saved_ = 1;
};

}  // namespace

bool metisOrdering(const SparseMatrix& A, std::vector<long>& order) {
  if (A.rows() == 0) return false;
  // On the graph of A's groups of equal columns, as CHOLMOD's orderings (groupedOrdering).
  const ColumnGroups groups = indistinguishableColumns(A);
  GroupGraph graph = groupGraph(A, groups);
  cholmod_sparse view = graph.view();
  cholmod_common cm;
  cholmod_l_start(&cm);
  cm.print = 0;
  std::vector<CholmodIndex> perm(static_cast<std::size_t>(groups.count()));
  const bool ok = cholmod_l_metis(&view, nullptr, 0, 1, perm.data(), &cm) != 0;
  cholmod_l_finish(&cm);
  order.clear();
  order.reserve(groups.members.size());
  for (const CholmodIndex g : perm)
    for (CholmodIndex q = groups.first[g]; q < groups.first[g + 1]; ++q)
      order.push_back(groups.members[q]);
  return ok;
}

double availableMemory() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return 1024.0 * kb;
  return std::numeric_limits<double>::infinity();
}

const char* toString(FactorStatus status) {
  switch (status) {
    case FactorStatus::ok:
      return "ok";
    case FactorStatus::notPositiveDefinite:
      return "notPositiveDefinite";
    case FactorStatus::failed:
      return "failed";
    case FactorStatus::nonFinite:
      return "nonFinite";
  }
  return "unknown";
}

const std::vector<std::string>& orderingNames() {
  static const std::vector<std::string> names = {"auto", "amd", "metis", "nesdis",
                                                 "cholmodDefault"};
  return names;
}

const std::string& toString(Ordering ordering) {
  return orderingNames()[static_cast<std::size_t>(ordering)];
}

Ordering orderingNamed(const std::string& name) {
  const auto& names = orderingNames();
  const auto it = std::find(names.begin(), names.end(), name);
  FRICTION_ASSERT(it != names.end(), "unknown ordering name");
  return static_cast<Ordering>(it - names.begin());
}

Ordering automaticOrdering(int dimension, Eigen::Index unknowns) {
  // Measured (orderingBenchmark.sh, README "The ordering"), the bordered factor of the
  // default run, on a 2-core machine shared with other jobs. 2D, 10⁴ to 10⁶ unknowns, P1 and
  // P2: METIS and NESDIS save 35–65 % of AMD's flops but take 3–5× its time to order, so
  // ordering plus numeric factorisation is shorter with AMD up to 2.4·10⁵ unknowns and
  // about even at 10⁶, while AMD's ordering and analysis take 19–65 % of its numeric
  // factorisation (the least at 10⁶) against 80–200 % for theirs; CHOLMOD's own strategy ordered
  // twice at 10⁶. 3D (P1, 2.4·10⁴ and 5·10⁴ unknowns): METIS halves AMD's flops for an ordering of
  // a few % of the factorisation. No size in the measured range changes the choice. Measured
  // again on the graph of the groups of equal columns (at 10⁶ in 2D): AMD 0.6–0.8 s to order,
  // METIS 3.5–4.9 s and NESDIS 4.7–6.6 s for 40–50 % of AMD's flops; whole runs still even.
  (void)unknowns;
  return dimension == 2 ? Ordering::amd : Ordering::metis;
}

std::vector<std::string> SparseFactor::backendNames() {
  std::vector<std::string> names;
  for (const auto& entry : kBackends) names.emplace_back(entry.name);
  return names;
}

void SparseFactor::requireInBuild(const std::string& backend, const SourceLocation& where) {
#ifndef FRICTION_WITH_MUMPS
  if (backend == "mumps")
    throw InputError(where,
                     "linear solver 'mumps' is not in this build: configure with "
                     "-DFRICTION_MUMPS=ON and MUMPS and MPI installed (libmumps-dev, "
                     "mpi-default-dev); valid types are: " +
                         joinWords(backendNames()));
#endif
#ifndef FRICTION_WITH_HYPRE
  if (backend == "amg")
    throw InputError(where,
                     "linear solver 'amg' is not in this build: configure with "
                     "-DFRICTION_HYPRE=ON and hypre and MPI installed (libhypre-dev, "
                     "mpi-default-dev); valid types are: " +
                         joinWords(backendNames()));
#endif
  (void)backend;
  (void)where;
}

SparseFactor::SparseFactor(const std::string& backend, const SourceLocation& where)
    : backend_(backend) {
  for (const auto& entry : kBackends)
    if (backend == entry.name) impl_ = entry.make();
  requireInBuild(backend, where);
  if (!impl_)
    throw InputError(where, "unknown linear solver '" + backend + "'" +
                                suggestionText(backend, backendNames()) +
                                "; valid types are: " + joinWords(backendNames()));
}

SparseFactor::~SparseFactor() = default;
SparseFactor::SparseFactor(SparseFactor&&) noexcept = default;
SparseFactor& SparseFactor::operator=(SparseFactor&&) noexcept = default;

FactorStatus SparseFactor::factor(const SparseMatrix& A) { return factorImpl(A, nullptr, nullptr); }

void SparseFactor::setComponents(const std::vector<int>& components, int count) {
  impl_->setComponents(components, count);
}

void SparseFactor::setIterativeTolerance(double tolerance) {
  impl_->setIterativeTolerance(tolerance);
}

FactorAnalysis SparseFactor::currentAnalysis() const {
  FactorAnalysis a = analysis_;
  if (!iterative()) return a;
  const FactorAnalysis now = impl_->analysis();
  a.iterativeSolves = now.iterativeSolves;
  a.iterativeIterations = now.iterativeIterations;
  a.iterativeUnconverged = now.iterativeUnconverged;
  a.iterativeWorstResidual = now.iterativeWorstResidual;
  return a;
}

void SparseFactor::setPhaseReport(PhaseReport report) { phaseReport_ = std::move(report); }

void SparseFactor::setOrdering(Ordering ordering, int dimension) {
  FRICTION_ASSERT(ordering == Ordering::automatic || takesOrdering(),
                  "this backend has its own ordering");
  ordering_ = ordering;
  dimension_ = dimension;
}

bool SparseFactor::takesOrdering() const { return impl_->takesOrdering(); }

bool SparseFactor::takesSummands() const { return impl_->takesSummands(); }

void SparseFactor::setMumpsMemory(const MumpsMemory& memory) {
  const bool taken = impl_->setMumpsMemory(memory);
  FRICTION_ASSERT(taken || !memory.any(), "a low-rank or out-of-core factor needs mumps");
  (void)taken;
}

void SparseFactor::setSummedOverRanks(bool summed) {
  FRICTION_ASSERT(!summed || takesSummands(), "this backend needs the whole matrix");
  summed_ = summed;
  impl_->setSummedInput(summed);
}

FactorStatus SparseFactor::factorImpl(const SparseMatrix& A, const SparseMatrix* B,
                                      const SparseMatrix* C) {
  FRICTION_ASSERT(A.rows() == A.cols(), "factor: matrix must be square");
  const auto start = std::chrono::steady_clock::now();
  ++numFactorizations_;
  rows_ = A.rows();
  schur_.resize(0, 0);
  schurSolves_ = 0;
  schurSeconds_ = 0;
  schurFallbackReason_.clear();
  analysis_ = {};
  maxAbsEntry_ = 0.0;
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      maxAbsEntry_ = std::isfinite(it.value()) ? std::max(maxAbsEntry_, std::abs(it.value()))
                                               : std::numeric_limits<double>::infinity();
  // A non-finite entry makes every pivot meaningless: no backend is asked.
  // Each rank's summand: the verdict must be every rank's (an overflow on one is on all).
  if (summed_) maxAbsEntry_ = parallel::maxOverRanks(maxAbsEntry_);
  if (!std::isfinite(maxAbsEntry_)) {
    status_ = FactorStatus::nonFinite;
    factored_ = false;
    minPivotRatio_ = std::numeric_limits<double>::quiet_NaN();
    factorSeconds_ += secondsSince(start);
    return status_;
  }
  // The bordered factorisation where the backend has one (and the border is finite: a
  // non-finite border is left to the blocked solves, whose results then say so).
  impl_->setPivotTolerance(pivotTolerance_);
  passOrdering(A.rows());
  impl_->onPhase = phaseReport_;
  impl_->phasesReported = 0;
  bool bordered = false;
  if (B && C) {
    bool finite = true;
    for (const SparseMatrix* M : {B, C})
      for (Eigen::Index k = 0; k < M->outerSize(); ++k)
        for (SparseMatrix::InnerIterator it(*M, k); it; ++it) finite &= std::isfinite(it.value());
    bordered = finite && impl_->factorBordered(A, *B, *C, schur_, status_, schurFallbackReason_);
  }
  if (!bordered) status_ = impl_->factor(A);
  // A backend that does not tell its phases: the factorisation as one.
  if (impl_->phasesReported == 0 && phaseReport_ && status_ == FactorStatus::ok)
    phaseReport_("factorisation (" + backend_ + ")", secondsSince(start));
  analysis_ = impl_->analysis();
  factored_ = true;
  status_ = judgePivots(A);
  if (status_ != FactorStatus::ok) schur_.resize(0, 0);
  factorSeconds_ += secondsSince(start);
  return status_;
}

void SparseFactor::passOrdering(Eigen::Index rows) {
  if (!impl_->takesOrdering()) return;
  // `auto` is resolved here, once per factorisation, by the rule of automaticOrdering(): one
  // ordering, not several tried.
  if (ordering_ == Ordering::automatic)
    impl_->setOrdering(
        automaticOrdering(dimension_, rows),
        "auto, " + std::to_string(dimension_) + "D, " + std::to_string(rows) + " unknowns");
  else
    impl_->setOrdering(ordering_, ordering_ == Ordering::cholmodDefault
                                      ? toString(ordering_)
                                      : "ordering " + toString(ordering_));
}

bool SparseFactor::predict(const SparseMatrix& A, FactorAnalysis& predicted) {
  FRICTION_ASSERT(A.rows() == A.cols(), "predict: matrix must be square");
  if (!impl_->takesOrdering() || ordering_ == Ordering::cholmodDefault || A.rows() == 0)
    return false;
  passOrdering(A.rows());
  return impl_->predict(A, predicted);
}

FactorStatus SparseFactor::judgePivots(const SparseMatrix& A) {
  minPivotRatio_ = std::numeric_limits<double>::quiet_NaN();
  if (status_ == FactorStatus::ok && A.rows() > 0) {
    // One relative test for every backend: a pivot that is round-off compared with its
    // diagonal entry means the matrix is singular to working precision.
    const Eigen::VectorXd pivot = impl_->pivots();
    if (pivot.size() == 0) return status_;  // the backend judged them (mumps)
    const Eigen::VectorXd diag = A.diagonal();
    double minRatio = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < pivot.size(); ++i) {
      const double ratio = diag[i] > 0.0 ? pivot[i] / diag[i] : -1.0;
      minRatio = std::isnan(ratio) ? -1.0 : std::min(minRatio, ratio);
    }
    minPivotRatio_ = minRatio;
    if (!(minRatio > pivotTolerance_)) status_ = FactorStatus::notPositiveDefinite;
  }
  return status_;
}

FactorStatus SparseFactor::factorWithSchur(const SparseMatrix& A, const SparseMatrix& B,
                                           const SparseMatrix& C) {
  FRICTION_ASSERT(B.rows() == A.rows() && C.rows() == B.cols() && C.cols() == B.cols(),
                  "factorWithSchur: the border does not fit the matrix");
  if (B.cols() == 0) return factor(A);
  factorImpl(A, &B, &C);
  // Backends without a bordered factorisation: the complement by blocks of solves.
  if (status_ == FactorStatus::ok && schur_.size() == 0) {
    const auto start = std::chrono::steady_clock::now();
    const long solves0 = numSolves_;
    schur_ = schurBySolves(B, C);
    schurSolves_ = numSolves_ - solves0;
    schurSeconds_ = secondsSince(start);
    if (phaseReport_)
      phaseReport_("interface operator S, the complement of the " + std::to_string(B.cols()) +
                       " jump unknowns by " + std::to_string(schurSolves_) + " back-substitutions",
                   schurSeconds_);
  }
  return status_;
}

Eigen::MatrixXd SparseFactor::schurBySolves(const SparseMatrix& B, const SparseMatrix& C) {
  FRICTION_ASSERT(ok(), "schurBySolves without a successful factor()");
  const Eigen::Index m = B.cols();
  Eigen::MatrixXd S = Eigen::MatrixXd(C);
  // Blocks of right-hand sides: CHOLMOD's supernodal solve then works with matrix–matrix
  // kernels. 64 columns keep the dense block of a 10⁶-unknown mesh at 0.5 GB.
  const Eigen::Index block = 64;
  for (Eigen::Index c0 = 0; c0 < m; c0 += block) {
    const Eigen::Index nc = std::min(block, m - c0);
    const Eigen::MatrixXd X = solve(Eigen::MatrixXd(B.middleCols(c0, nc)));
    S.middleCols(c0, nc) -= B.transpose() * X;
  }
  // Symmetric in exact arithmetic; make it so to round-off.
  return 0.5 * (S + S.transpose());
}

// One back-substitution per column of what `solve` returns, counted and timed.
template <class Solve>
auto SparseFactor::counted(Eigen::Index columns, Solve&& solve) {
  const auto start = std::chrono::steady_clock::now();
  auto X = solve();
  numSolves_ += static_cast<long>(columns);
  solveSeconds_ += secondsSince(start);
  return X;
}

Eigen::VectorXd SparseFactor::solve(const Eigen::VectorXd& b) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(b.size() == rows_, "solve: right-hand side has the wrong size");
  const SingleBlasThread oneThread;
  return counted(1, [&] { return impl_->solve(b); });
}

Eigen::MatrixXd SparseFactor::solve(const Eigen::MatrixXd& B) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(B.rows() == rows_, "solve: right-hand sides have the wrong size");
  return counted(B.cols(), [&] { return impl_->solve(B); });
}

SolveReach SparseFactor::restrictSolves(const std::vector<Eigen::Index>& rows) {
  FRICTION_ASSERT(ok(), "restrictSolves without a successful factor()");
  return impl_->restrictTo(rows);
}

Eigen::VectorXd SparseFactor::solveRestricted(const Eigen::VectorXd& b) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(b.size() == rows_, "solve: right-hand side has the wrong size");
  const SingleBlasThread oneThread;
  return counted(
      1, [&] { return Eigen::VectorXd(impl_->solveRestricted(Eigen::MatrixXd(b)).col(0)); });
}

Eigen::MatrixXd SparseFactor::solveRestricted(const Eigen::MatrixXd& B) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(B.rows() == rows_, "solve: right-hand sides have the wrong size");
  return counted(B.cols(), [&] { return impl_->solveRestricted(B); });
}

}  // namespace friction
