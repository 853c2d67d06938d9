// DenseProduct: the vectorised, threaded y = A x (DenseProduct.hpp).
#include "friction/linalg/DenseProduct.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <system_error>
#include <thread>
#include <vector>

#include "friction/core/Parallel.hpp"

namespace friction {

namespace {

// y[0:m) = A[0:m, 0:n) x, A column-major with leading dimension lda. Four columns at a time:
// y is read and written once per four columns of A, and each row's sum runs over the columns
// in one fixed order. Plain loops, no templates or inline functions of other headers, so the
// AVX2 clone cannot leak into code shared with the rest of the program.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define FRICTION_DENSE_PRODUCT_CLONES 1
// x86-64-v3: AVX2 and FMA (the comma of "avx2,fma" would make two clones, and the AVX2 one
// would take no FMA).
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void kernel(long m, long n, const double* a, long lda, const double* x, double* y) {
  for (long i = 0; i < m; ++i) y[i] = 0.0;
  long j = 0;
  for (; j + 4 <= n; j += 4) {
    const double* a0 = a + j * lda;
    const double* a1 = a0 + lda;
    const double* a2 = a1 + lda;
    const double* a3 = a2 + lda;
    const double x0 = x[j], x1 = x[j + 1], x2 = x[j + 2], x3 = x[j + 3];
    for (long i = 0; i < m; ++i) y[i] += a0[i] * x0 + a1[i] * x1 + a2[i] * x2 + a3[i] * x3;
  }
  for (; j < n; ++j) {
    const double* a0 = a + j * lda;
    const double x0 = x[j];
    for (long i = 0; i < m; ++i) y[i] += a0[i] * x0;
  }
}

int overridden = 0;

int ruleThreads() {
  if (parallel::size() > 1) return 1;
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && v >= 1) return static_cast<int>(std::min<long>(v, 64));
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return std::clamp(static_cast<int>(hw), 1, denseProductMaxThreads);
}

bool vectorised() {
#ifdef FRICTION_DENSE_PRODUCT_CLONES
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3");
#else
  return false;
#endif
}

}  // namespace

int denseProductThreads() { return overridden > 0 ? overridden : ruleThreads(); }

void setDenseProductThreads(int n) { overridden = std::max(n, 0); }

void denseProduct(const Eigen::MatrixXd& A, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y) {
  const long m = A.rows(), n = A.cols();
  y.resize(m);
  if (m == 0) return;
  // x may have a stride (a Ref): the kernel reads a contiguous copy.
  const Eigen::VectorXd xc = x;
  const int threads = m * n >= denseProductThreadedFrom
                          ? static_cast<int>(std::min<long>(denseProductThreads(), m / 64))
                          : 1;
  if (threads <= 1) {
    kernel(m, n, A.data(), m, xc.data(), y.data());
    return;
  }
  // Row blocks of a multiple of 8 rows (whole cache lines of y and of each column).
  std::vector<long> first(static_cast<std::size_t>(threads) + 1);
  for (int t = 0; t <= threads; ++t)
    first[static_cast<std::size_t>(t)] = t == threads ? m : (m * t / threads) & ~7L;
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads) - 1);
  for (int t = 1; t < threads; ++t) {
    const long r0 = first[static_cast<std::size_t>(t)], r1 = first[static_cast<std::size_t>(t) + 1];
    try {
      pool.emplace_back(
          [&, r0, r1] { kernel(r1 - r0, n, A.data() + r0, m, xc.data(), y.data() + r0); });
    } catch (const std::system_error&) {  // no thread to be had: this one does the block
      kernel(r1 - r0, n, A.data() + r0, m, xc.data(), y.data() + r0);
    }
  }
  kernel(first[1], n, A.data(), m, xc.data(), y.data());
  for (std::thread& th : pool) th.join();
}

std::string describeDenseProduct(long entries) {
  const int threads = entries >= denseProductThreadedFrom ? denseProductThreads() : 1;
  std::ostringstream s;
  s << (vectorised() ? "AVX2+FMA (x86-64-v3)" : "baseline") << " kernel, " << threads
    << (threads == 1 ? " thread" : " threads");
  return s.str();
}

}  // namespace friction
