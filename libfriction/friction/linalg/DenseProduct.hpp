// DenseProduct: y = A x for a large dense column-major A (the quasi-dynamic right-hand side's
// S, read once per Runge–Kutta stage): a kernel compiled for the processor's vector units
// and rows shared between threads; A in double or stored in single precision.
#pragma once

#include <Eigen/Core>
#include <string>

namespace friction {

/// y = A x. The kernel is compiled twice, for x86-64-v3 (AVX2 with FMA) and for the baseline, and
/// the program takes the one its processor runs when it loads (Eigen's own kernels are compiled for
/// the baseline SSE2 only). Where A has at least denseProductThreadedFrom entries its rows are
/// split between denseProductThreads() threads. Every row is summed in the same order whatever the
/// split, so the result does not depend on the number of threads.
void denseProduct(const Eigen::MatrixXd& A, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y);

/// y = A x with A stored in single precision: each entry is widened to double before its
/// multiply-add and the sums run in double, so y differs from the double product of the same
/// matrix only by A's rounding to float (about 6e-8 of each entry). Half the bytes to read:
/// where the product is bound by memory bandwidth, about half the time.
void denseProduct(const Eigen::MatrixXf& A, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y);

/// A matrix of this many entries or more (8 MB) is multiplied on several threads: below it a
/// thread's start costs more than it saves.
inline constexpr long denseProductThreadedFrom = 1L << 20;

/// The threads the products use: 1 in a run on several ranks (each rank has its core);
/// otherwise OMP_NUM_THREADS where it is set to a positive integer, else the processor's
/// hardware threads, at most denseProductMaxThreads (the product is bound by memory
/// bandwidth: two threads take it most of the way).
int denseProductThreads();
inline constexpr int denseProductMaxThreads = 4;

/// Overrides denseProductThreads() (n >= 1), or restores its rule (n = 0). For tests.
void setDenseProductThreads(int n);

/// What the products run on, for the log: "AVX2+FMA (x86-64-v3) kernel, 2 threads".
std::string describeDenseProduct(long entries);

}  // namespace friction
