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
#define FRICTION_DENSE_PRODUCT_TARGETS __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define FRICTION_DENSE_PRODUCT_TARGETS
#endif
FRICTION_DENSE_PRODUCT_TARGETS
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

// The same with A in single precision, eight columns at a time: a float column is half the
// bytes of a double one, so y is read and written once per eight columns to keep its traffic
// below A's (measured at BP5's 1 km size: 10.0–12.3 ms on two threads, against 18.6–21.8 ms for
// the double kernel and 11.6–13.9 ms with four columns at a time; blocks of rows were slower).
// Each row's sum runs over the columns in one fixed order, whatever the rows' split.
FRICTION_DENSE_PRODUCT_TARGETS
void kernelSingle(long m, long n, const float* a, long lda, const double* x, double* y) {
  for (long i = 0; i < m; ++i) y[i] = 0.0;
  long j = 0;
  for (; j + 8 <= n; j += 8) {
    const float* c = a + j * lda;
    const double x0 = x[j], x1 = x[j + 1], x2 = x[j + 2], x3 = x[j + 3], x4 = x[j + 4],
                 x5 = x[j + 5], x6 = x[j + 6], x7 = x[j + 7];
    for (long i = 0; i < m; ++i)
      y[i] += static_cast<double>(c[i]) * x0 + static_cast<double>(c[i + lda]) * x1 +
              static_cast<double>(c[i + 2 * lda]) * x2 + static_cast<double>(c[i + 3 * lda]) * x3 +
              static_cast<double>(c[i + 4 * lda]) * x4 + static_cast<double>(c[i + 5 * lda]) * x5 +
              static_cast<double>(c[i + 6 * lda]) * x6 + static_cast<double>(c[i + 7 * lda]) * x7;
  }
  for (; j < n; ++j) {
    const float* c = a + j * lda;
    const double x0 = x[j];
    for (long i = 0; i < m; ++i) y[i] += static_cast<double>(c[i]) * x0;
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

namespace {

// The threads' split of y = A x (rows in blocks of a multiple of 8: whole cache lines of y and
// of each column), for either kernel.
template <class Entry, class Kernel>
void splitProduct(const Entry* a, long m, long n, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y, Kernel run) {
  y.resize(m);
  if (m == 0) return;
  // x may have a stride (a Ref): the kernel reads a contiguous copy.
  const Eigen::VectorXd xc = x;
  const int threads = m * n >= denseProductThreadedFrom
                          ? static_cast<int>(std::min<long>(denseProductThreads(), m / 64))
                          : 1;
  if (threads <= 1) {
    run(m, n, a, m, xc.data(), y.data());
    return;
  }
  std::vector<long> first(static_cast<std::size_t>(threads) + 1);
  for (int t = 0; t <= threads; ++t)
    first[static_cast<std::size_t>(t)] = t == threads ? m : (m * t / threads) & ~7L;
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads) - 1);
  for (int t = 1; t < threads; ++t) {
    const long r0 = first[static_cast<std::size_t>(t)], r1 = first[static_cast<std::size_t>(t) + 1];
    try {
      pool.emplace_back([&, r0, r1] { run(r1 - r0, n, a + r0, m, xc.data(), y.data() + r0); });
    } catch (const std::system_error&) {  // no thread to be had: this one does the block
      run(r1 - r0, n, a + r0, m, xc.data(), y.data() + r0);
    }
  }
  run(first[1], n, a, m, xc.data(), y.data());
  for (std::thread& th : pool) th.join();
}

}  // namespace

void denseProduct(const Eigen::MatrixXd& A, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y) {
  splitProduct(A.data(), A.rows(), A.cols(), x, y,
               [](long m, long n, const double* a, long lda, const double* xs, double* ys) {
                 kernel(m, n, a, lda, xs, ys);
               });
}

void denseProduct(const Eigen::MatrixXf& A, const Eigen::Ref<const Eigen::VectorXd>& x,
                  Eigen::VectorXd& y) {
  splitProduct(A.data(), A.rows(), A.cols(), x, y,
               [](long m, long n, const float* a, long lda, const double* xs, double* ys) {
                 kernelSingle(m, n, a, lda, xs, ys);
               });
}

std::string describeDenseProduct(long entries) {
  const int threads = entries >= denseProductThreadedFrom ? denseProductThreads() : 1;
  std::ostringstream s;
  s << (vectorised() ? "AVX2+FMA (x86-64-v3)" : "baseline") << " kernel, " << threads
    << (threads == 1 ? " thread" : " threads");
  return s.str();
}

}  // namespace friction
