// SparseFactor: one factorisation of the reduced stiffness matrix, many back-substitutions
// (docs/method.md §4). Backends behind a small interface; the table below lists every backend.
#include "friction/linalg/SparseFactor.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>

#include "friction/core/Assert.hpp"
#include "friction/core/Suggest.hpp"

namespace friction {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// A factorisation backend. factor() returns the backend's own verdict; pivots() gives, per
/// original row i, the pivot of that row in the factor (d of LDLᵀ or l² of LLᵀ), so that the
/// caller can apply one relative test to every backend.
class SparseFactor::Backend {
 public:
  virtual ~Backend() = default;
  virtual FactorStatus factor(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd pivots() const = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const = 0;
};

namespace {

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

/// Eigen's wrapper with access to the CHOLMOD factor, which we need to read the pivots and to
/// check that the analysis succeeded before factorising (Eigen would dereference a null
/// factor after a failed analysis).
class CholmodLlt : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* cholmodFactor() const { return m_cholmodFactor; }
};

class CholmodBackend : public SparseFactor::Backend {
 public:
  CholmodBackend() {
    // Silence CHOLMOD's own printing: "not positive definite" is reported as a status value.
    llt_.cholmod().print = 0;
  }
  FactorStatus factor(const SparseMatrix& A) override {
    llt_.analyzePattern(A);
    if (!llt_.cholmodFactor() || llt_.cholmod().status < 0) return FactorStatus::failed;
    llt_.factorize(A);
    const int status = llt_.cholmod().status;
    if (status == CHOLMOD_NOT_POSDEF || llt_.info() == Eigen::NumericalIssue)
      return FactorStatus::notPositiveDefinite;
    return status < 0 ? FactorStatus::failed : FactorStatus::ok;
  }
  Eigen::VectorXd pivots() const override {
    const cholmod_factor& L = *llt_.cholmodFactor();
    const auto n = static_cast<Eigen::Index>(L.n);
    const double* x = static_cast<const double*>(L.x);
    const int* perm = static_cast<const int*>(L.Perm);
    Eigen::VectorXd inFactorOrder(n);
    if (L.is_super) {
      // Supernode s: columns super[s] .. super[s+1]−1, stored as a dense column-major block
      // of pi[s+1] − pi[s] rows starting at px[s]; its diagonal has stride rows + 1.
      const int* super = static_cast<const int*>(L.super);
      const int* pi = static_cast<const int*>(L.pi);
      const int* px = static_cast<const int*>(L.px);
      for (std::size_t s = 0; s < L.nsuper; ++s) {
        const int nrows = pi[s + 1] - pi[s];
        for (int j = 0; j < super[s + 1] - super[s]; ++j) {
          const double l = x[px[s] + j * (nrows + 1)];
          inFactorOrder[super[s] + j] = l * l;
        }
      }
    } else {
      const int* p = static_cast<const int*>(L.p);
      for (Eigen::Index k = 0; k < n; ++k) {
        const double d = x[p[k]];
        inFactorOrder[k] = L.is_ll ? d * d : d;
      }
    }
    // Row k of the factor is row Perm[k] of A.
    Eigen::VectorXd out(n);
    for (Eigen::Index k = 0; k < n; ++k) out[perm ? perm[k] : k] = inFactorOrder[k];
    return out;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override { return llt_.solve(b); }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const override { return llt_.solve(B); }

 private:
  CholmodLlt llt_;
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
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

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

std::vector<std::string> SparseFactor::backendNames() {
  std::vector<std::string> names;
  for (const auto& entry : kBackends) names.emplace_back(entry.name);
  return names;
}

SparseFactor::SparseFactor(const std::string& backend, const SourceLocation& where)
    : backend_(backend) {
  for (const auto& entry : kBackends)
    if (backend == entry.name) impl_ = entry.make();
  if (!impl_)
    throw InputError(where, "unknown linear solver '" + backend + "'" +
                                suggestionText(backend, backendNames()) +
                                "; valid types are: " + joinWords(backendNames()));
}

SparseFactor::~SparseFactor() = default;
SparseFactor::SparseFactor(SparseFactor&&) noexcept = default;
SparseFactor& SparseFactor::operator=(SparseFactor&&) noexcept = default;

FactorStatus SparseFactor::factor(const SparseMatrix& A) {
  FRICTION_ASSERT(A.rows() == A.cols(), "factor: matrix must be square");
  const auto start = std::chrono::steady_clock::now();
  ++numFactorizations_;
  rows_ = A.rows();
  maxAbsEntry_ = 0.0;
  for (Eigen::Index k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      maxAbsEntry_ = std::isfinite(it.value()) ? std::max(maxAbsEntry_, std::abs(it.value()))
                                               : std::numeric_limits<double>::infinity();
  // A non-finite entry makes every pivot meaningless: no backend is asked.
  if (!std::isfinite(maxAbsEntry_)) {
    status_ = FactorStatus::nonFinite;
    factored_ = false;
    minPivotRatio_ = std::numeric_limits<double>::quiet_NaN();
    factorSeconds_ += secondsSince(start);
    return status_;
  }
  status_ = impl_->factor(A);
  factored_ = true;
  minPivotRatio_ = std::numeric_limits<double>::quiet_NaN();
  if (status_ == FactorStatus::ok && A.rows() > 0) {
    // One relative test for every backend: a pivot that is round-off compared with its
    // diagonal entry means the matrix is singular to working precision.
    const Eigen::VectorXd pivot = impl_->pivots();
    const Eigen::VectorXd diag = A.diagonal();
    double minRatio = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < pivot.size(); ++i) {
      const double ratio = diag[i] > 0.0 ? pivot[i] / diag[i] : -1.0;
      minRatio = std::isnan(ratio) ? -1.0 : std::min(minRatio, ratio);
    }
    minPivotRatio_ = minRatio;
    if (!(minRatio > pivotTolerance_)) status_ = FactorStatus::notPositiveDefinite;
  }
  factorSeconds_ += secondsSince(start);
  return status_;
}

Eigen::VectorXd SparseFactor::solve(const Eigen::VectorXd& b) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(b.size() == rows_, "solve: right-hand side has the wrong size");
  const auto start = std::chrono::steady_clock::now();
  Eigen::VectorXd x = impl_->solve(b);
  ++numSolves_;
  solveSeconds_ += secondsSince(start);
  return x;
}

Eigen::MatrixXd SparseFactor::solve(const Eigen::MatrixXd& B) {
  FRICTION_ASSERT(ok(), "solve without a successful factor()");
  FRICTION_ASSERT(B.rows() == rows_, "solve: right-hand sides have the wrong size");
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd X = impl_->solve(B);
  numSolves_ += static_cast<long>(B.cols());
  solveSeconds_ += secondsSince(start);
  return X;
}

}  // namespace friction
