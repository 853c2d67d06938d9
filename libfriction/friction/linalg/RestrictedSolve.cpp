// RestrictedSolve: the reach of a set of rows in a supernodal factor's elimination tree, and
// the two triangular solves over it (RestrictedSolve.hpp).
#include "friction/linalg/RestrictedSolve.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <string>

// BLAS (OpenBLAS at run time), called as CHOLMOD's supernodal solve calls it.
extern "C" {
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
            const int* lda, double* x, const int* incx);
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a,
            const int* lda, const double* x, const int* incx, const double* beta, double* y,
            const int* incy);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc);
}

namespace friction {

using Eigen::Index;

namespace {

int blasInt(long v) {
  if (v > INT_MAX) throw std::runtime_error("restricted solve: a dimension exceeds BLAS's int");
  return static_cast<int>(v);
}

}  // namespace

RestrictedSolve::RestrictedSolve(const SupernodalView& L, const std::vector<Index>& rows) : L_(L) {
  const long n = L.n, nsuper = L.nsuper;
  std::vector<long> nodeOf(static_cast<std::size_t>(n));
  for (long s = 0; s < nsuper; ++s)
    for (long k = L.super[s]; k < L.super[s + 1]; ++k) nodeOf[static_cast<std::size_t>(k)] = s;
  std::vector<long> factorRowOf(static_cast<std::size_t>(n));  // of each row of A
  for (long k = 0; k < n; ++k) factorRowOf[static_cast<std::size_t>(L.perm ? L.perm[k] : k)] = k;
  // Each row's supernode and its ancestors: the parent of a supernode is the supernode of its
  // first row below the diagonal block.
  std::vector<char> in(static_cast<std::size_t>(nsuper), 0);
  for (const Index r : rows) {
    if (r < 0 || r >= n)
      throw std::logic_error("restricted solve: row " + std::to_string(r) + " outside 0 … " +
                             std::to_string(n - 1));
    long s = nodeOf[static_cast<std::size_t>(factorRowOf[static_cast<std::size_t>(r)])];
    while (s >= 0 && !in[static_cast<std::size_t>(s)]) {
      in[static_cast<std::size_t>(s)] = 1;
      const long nscol = L.super[s + 1] - L.super[s], nsrow = L.pi[s + 1] - L.pi[s];
      s = nsrow > nscol ? nodeOf[static_cast<std::size_t>(L.s[L.pi[s] + nscol])] : -1;
    }
  }
  std::vector<long> localOfFactorRow(static_cast<std::size_t>(n), -1);
  double read = 0, all = 0;
  for (long s = 0; s < nsuper; ++s) {
    const long nscol = L.super[s + 1] - L.super[s], nsrow = L.pi[s + 1] - L.pi[s];
    all += static_cast<double>(nsrow) * static_cast<double>(nscol);
    if (!in[static_cast<std::size_t>(s)]) continue;
    read += static_cast<double>(nsrow) * static_cast<double>(nscol);
    nodes_.push_back(s);
    first_.push_back(reached_);
    for (long k = L.super[s]; k < L.super[s + 1]; ++k) {
      localOfFactorRow[static_cast<std::size_t>(k)] = reached_++;
      factorRowOfLocal_.push_back(k);
    }
  }
  share_ = all > 0 ? read / all : 0;
  local_.assign(static_cast<std::size_t>(n), -1);
  for (long k = 0; k < n; ++k)
    local_[static_cast<std::size_t>(L.perm ? L.perm[k] : k)] =
        localOfFactorRow[static_cast<std::size_t>(k)];
  below_.reserve(nodes_.size());
  for (const long s : nodes_) {
    const long nscol = L.super[s + 1] - L.super[s], nsrow = L.pi[s + 1] - L.pi[s];
    std::vector<long> b;
    b.reserve(static_cast<std::size_t>(nsrow - nscol));
    for (long p = L.pi[s] + nscol; p < L.pi[s + 1]; ++p) {
      const long l = localOfFactorRow[static_cast<std::size_t>(L.s[p])];
      // A row below a supernode belongs to one of its ancestors, so it was reached too.
      if (l < 0) throw std::logic_error("restricted solve: a row below a supernode not reached");
      b.push_back(l);
    }
    widest_ = std::max(widest_, nsrow - nscol);
    below_.push_back(std::move(b));
  }
  blasInt(reached_);
}

Eigen::MatrixXd RestrictedSolve::solve(const Eigen::MatrixXd& B) const {
  const long n = L_.n, m = B.cols();
  if (B.rows() != n) throw std::logic_error("restricted solve: right-hand sides of the wrong size");
  for (long c = 0; c < m; ++c)
    for (long i = 0; i < n; ++i)
      if (B(i, c) != 0 && local_[static_cast<std::size_t>(i)] < 0)
        throw std::logic_error("restricted solve: a right-hand side is nonzero at row " +
                               std::to_string(i) + ", outside the rows it was restricted to");
  Eigen::MatrixXd Y(reached_, m);
  for (long l = 0; l < reached_; ++l) {
    const long k = factorRowOfLocal_[static_cast<std::size_t>(l)];
    Y.row(l) = B.row(L_.perm ? L_.perm[k] : k);
  }
  // The rows below a supernode's diagonal block, gathered: `below` × m, leading dimension
  // `below`.
  std::vector<double> E(static_cast<std::size_t>(widest_ * m));
  const int ldy = blasInt(reached_), one = 1, rhs = blasInt(m);
  const double plus = 1.0, minus = -1.0;
  const auto gather = [&](std::size_t t, long below) {
    const std::vector<long>& b = below_[t];
    for (long c = 0; c < m; ++c)
      for (long ii = 0; ii < below; ++ii)
        E[static_cast<std::size_t>(ii + c * below)] = Y(b[static_cast<std::size_t>(ii)], c);
  };
  const auto scatter = [&](std::size_t t, long below) {
    const std::vector<long>& b = below_[t];
    for (long c = 0; c < m; ++c)
      for (long ii = 0; ii < below; ++ii)
        Y(b[static_cast<std::size_t>(ii)], c) = E[static_cast<std::size_t>(ii + c * below)];
  };
  // Reached supernode t: its diagonal block L1 (nscol × nscol) and the block below it L2
  // (below × nscol), both with leading dimension nsrow, and its columns' part y1 of Y.
  struct Supernode {
    int nscol, nsrow, below, ldE;
    const double *L1, *L2;
    double* y1;
  };
  const auto supernode = [&](std::size_t t) {
    const long s = nodes_[t];
    Supernode b;
    b.nscol = blasInt(L_.super[s + 1] - L_.super[s]);
    b.nsrow = blasInt(L_.pi[s + 1] - L_.pi[s]);
    b.below = b.nsrow - b.nscol;
    b.ldE = std::max(1, b.below);
    b.L1 = L_.x + L_.px[s];
    b.L2 = b.L1 + b.nscol;
    b.y1 = Y.data() + first_[t];
    return b;
  };
  // L y = P b, supernode by supernode upward.
  for (std::size_t t = 0; t < nodes_.size(); ++t) {
    const auto [nscol, nsrow, below, ldE, L1, L2, y1] = supernode(t);
    gather(t, below);
    if (m == 1) {
      dtrsv_("L", "N", "N", &nscol, L1, &nsrow, y1, &one);
      dgemv_("N", &below, &nscol, &minus, L2, &nsrow, y1, &one, &plus, E.data(), &one);
    } else {
      dtrsm_("L", "L", "N", "N", &nscol, &rhs, &plus, L1, &nsrow, y1, &ldy);
      if (below > 0)
        dgemm_("N", "N", &below, &rhs, &nscol, &minus, L2, &nsrow, y1, &ldy, &plus, E.data(), &ldE);
    }
    scatter(t, below);
  }
  // Lᵀ x = y, downward.
  for (std::size_t t = nodes_.size(); t-- > 0;) {
    const auto [nscol, nsrow, below, ldE, L1, L2, y1] = supernode(t);
    gather(t, below);
    if (m == 1) {
      dgemv_("C", &below, &nscol, &minus, L2, &nsrow, E.data(), &one, &plus, y1, &one);
      dtrsv_("L", "C", "N", &nscol, L1, &nsrow, y1, &one);
    } else {
      if (below > 0)
        dgemm_("C", "N", &nscol, &rhs, &below, &minus, L2, &nsrow, E.data(), &ldE, &plus, y1, &ldy);
      dtrsm_("L", "L", "C", "N", &nscol, &rhs, &plus, L1, &nsrow, y1, &ldy);
    }
  }
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, m);
  for (long l = 0; l < reached_; ++l) {
    const long k = factorRowOfLocal_[static_cast<std::size_t>(l)];
    X.row(L_.perm ? L_.perm[k] : k) = Y.row(l);
  }
  return X;
}

}  // namespace friction
