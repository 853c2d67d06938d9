// RestrictedSolve: back-substitutions with a supernodal Cholesky factor, L Lᵀ = P A Pᵀ, for
// right-hand sides that vanish outside a set F of rows and solutions read on F only — the
// fault's products of Newton's krylov variant and its probes (docs/method.md §4, "Solves
// restricted to the fault's reach").
//
// Row k of L y = P b depends only on the rows of its descendants in the elimination tree, and
// row k of Lᵀ x = y only on its ancestors'. So with b zero outside F, y is zero outside the
// rows F's rows reach upward (their ancestors, R), and x on R needs y and x on R alone: both
// triangular solves may skip every supernode outside R. On a fault in a 3D body R holds the
// separators above the fault and the subdomains the fault crosses; what share of the factor
// that is, is measured, not assumed (share(), logged by the caller).
//
// Each supernode is processed with the same BLAS calls as the whole supernodal solve (dtrsv
// and dgemv for one right-hand side, dtrsm and dgemm for several), so the solution on R is the
// whole solve's, to the bit where the BLAS is deterministic (the unit test checks it).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace friction {

/// A supernodal LLᵀ factor as CHOLMOD stores it (64-bit indices): supernode s holds the
/// factor's columns super[s] … super[s+1]−1 as a dense column-major block of pi[s+1] − pi[s]
/// rows (their indices s[pi[s]] …, the block's own columns first) at x + px[s]. Row k of the
/// factor is row perm[k] of A (perm null: the identity).
struct SupernodalView {
  long n = 0, nsuper = 0;
  const long* super = nullptr;
  const long* pi = nullptr;
  const long* px = nullptr;
  const long* s = nullptr;
  const long* perm = nullptr;
  const double* x = nullptr;
};

class RestrictedSolve {
 public:
  /// The reach of `rows` (rows of A, each in 0 … n−1) in L's elimination tree. The view's
  /// arrays must outlive this object and not change.
  RestrictedSolve(const SupernodalView& L, const std::vector<Eigen::Index>& rows);

  /// Share of the factor's stored values one solve reads (0 … 1).
  double share() const { return share_; }
  Eigen::Index reachedSupernodes() const { return static_cast<Eigen::Index>(nodes_.size()); }
  Eigen::Index reachedRows() const { return reached_; }
  /// Whether row i of A lies in the reach (a right-hand side may be nonzero there).
  bool reaches(Eigen::Index i) const { return local_[static_cast<std::size_t>(i)] >= 0; }

  /// X = A⁻¹ B on the reached rows, zero elsewhere. B (n × m) must vanish outside the reach:
  /// an entry there throws std::logic_error (a caller's mistake, never the data's).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

 private:
  SupernodalView L_;
  std::vector<long> nodes_;  // the reached supernodes, ascending
  // Per row of A: its position among the reached rows (in the factor's order), or −1.
  std::vector<long> local_;
  // Per reached supernode, the positions of its rows below the diagonal block.
  std::vector<std::vector<long>> below_;
  std::vector<long> first_;             // per reached supernode, its first column's position
  std::vector<long> factorRowOfLocal_;  // the factor's row of each reached position
  long reached_ = 0;
  long widest_ = 0;  // the most rows below a reached supernode's diagonal block
  double share_ = 0;
};

}  // namespace friction
