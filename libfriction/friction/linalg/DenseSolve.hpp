// Dense linear systems through LAPACK (OpenBLAS's at run time: blocked, threaded, and built
// for the machine's vector units, where Eigen's own kernels are compiled for baseline SSE2).
// Used where a dense system on the fracture is the largest piece of work of an iteration:
// the condensed Newton's generalised Jacobian (docs/method.md §4).
#pragma once

#include <Eigen/Core>

namespace friction {

/// Solve A x = b by LU with partial pivoting (LAPACK dgesv). A is overwritten by its
/// factors and b by x. Returns false when A is exactly singular (a zero pivot); then b is
/// left undefined.
bool luSolveInPlace(Eigen::MatrixXd& A, Eigen::VectorXd& b);

}  // namespace friction
