// Dense solves through LAPACK: see DenseSolve.hpp.
#include "friction/linalg/DenseSolve.hpp"

#include <vector>

#include "friction/core/Assert.hpp"

extern "C" void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv,
                       double* b, const int* ldb, int* info);

namespace friction {

bool luSolveInPlace(Eigen::MatrixXd& A, Eigen::VectorXd& b) {
  FRICTION_ASSERT(A.rows() == A.cols() && b.size() == A.rows(), "luSolveInPlace: sizes");
  const int n = static_cast<int>(A.rows()), one = 1;
  if (n == 0) return true;
  std::vector<int> pivots(static_cast<std::size_t>(n));
  int info = 0;
  dgesv_(&n, &one, A.data(), &n, pivots.data(), b.data(), &n, &info);
  FRICTION_ASSERT(info >= 0, "dgesv: invalid argument");
  return info == 0;
}

}  // namespace friction
