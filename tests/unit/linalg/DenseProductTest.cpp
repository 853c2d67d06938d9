// denseProduct (linalg/DenseProduct.hpp): y = A x equals Eigen's product to round-off on
// shapes that leave a remainder of columns (not a multiple of four) and of rows (not a
// multiple of eight), reads a strided x, handles empty matrices, and gives the same bytes on
// 1, 2, 3 and 4 threads (each row summed in one order whatever the split).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "friction/linalg/DenseProduct.hpp"

using namespace friction;

namespace {

struct ThreadsRestored {
  ~ThreadsRestored() { setDenseProductThreads(0); }
};

}  // namespace

TEST_CASE("denseProduct: Eigen's product to round-off, the same bytes on any number of threads",
          "[linalg][denseProduct]") {
  ThreadsRestored restore;
  // Large enough to be threaded (>= denseProductThreadedFrom entries), odd in both shapes.
  const Eigen::Index m = 1541, n = 1031;
  REQUIRE(m * n >= denseProductThreadedFrom);
  Eigen::MatrixXd A(m, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < m; ++i)
      A(i, j) = 1.0 / (1.0 + std::abs(static_cast<double>(i) / m - static_cast<double>(j) / n)) *
                (((i + 3 * j) % 7) - 3.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -2.0, 3.0).array().sin();
  const Eigen::VectorXd reference = A * x;
  REQUIRE(reference.norm() > 0);

  Eigen::VectorXd one;
  setDenseProductThreads(1);
  denseProduct(A, x, one);
  REQUIRE(one.size() == m);
  // Summed in another order (four columns at a time, fused multiply-adds where the processor
  // has them): round-off of a sum of n terms, far below 1e-13 of the result.
  CHECK((one - reference).norm() / reference.norm() < 1e-13);
  for (int threads : {2, 3, 4}) {
    setDenseProductThreads(threads);
    REQUIRE(denseProductThreads() == threads);
    Eigen::VectorXd y;
    denseProduct(A, x, y);
    REQUIRE(y.size() == m);
    CHECK(std::memcmp(y.data(), one.data(), sizeof(double) * static_cast<std::size_t>(m)) == 0);
  }
  // Fewer entries than the threshold: one thread, the same kernel.
  const Eigen::MatrixXd small = A.topLeftCorner(37, 13);
  Eigen::VectorXd ySmall;
  denseProduct(small, x.head(13), ySmall);
  CHECK((ySmall - small * x.head(13)).norm() <= 1e-13 * (small * x.head(13)).norm());
  CHECK(describeDenseProduct(small.size()).find("1 thread") != std::string::npos);
  setDenseProductThreads(2);
  CHECK(describeDenseProduct(A.size()).find("2 threads") != std::string::npos);
}

TEST_CASE("denseProduct: a strided x, and empty shapes", "[linalg][denseProduct]") {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(5, 3);
  A << 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15;
  Eigen::MatrixXd X(3, 2);
  X << 1, -1, 2, -2, 3, -3;
  Eigen::VectorXd y;
  denseProduct(A, X.row(1).transpose(), y);  // a row of X: stride 3
  REQUIRE(y.size() == 5);
  CHECK((y - A * X.row(1).transpose()).norm() == 0.0);  // small integers: exact
  denseProduct(A, X.col(0), y);
  CHECK((y - A * X.col(0)).norm() == 0.0);
  const Eigen::MatrixXd none(0, 3);
  denseProduct(none, X.col(0), y);
  CHECK(y.size() == 0);
  const Eigen::MatrixXd noColumns(4, 0);
  denseProduct(noColumns, Eigen::VectorXd(), y);
  REQUIRE(y.size() == 4);
  CHECK(y.isZero(0.0));
}

TEST_CASE("denseProduct: A stored in single precision, summed in double",
          "[linalg][denseProduct]") {
  ThreadsRestored restore;
  const Eigen::Index m = 1541, n = 1031;  // threaded, odd in both shapes
  REQUIRE(m * n >= denseProductThreadedFrom);
  Eigen::MatrixXd A(m, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < m; ++i)
      A(i, j) = 1e10 / (1.0 + std::abs(static_cast<double>(i) / m - static_cast<double>(j) / n)) *
                (((i + 3 * j) % 7) - 3.0 + 1e-3 * std::sin(static_cast<double>(i + j)));
  const Eigen::MatrixXf Af = A.cast<float>();
  const Eigen::MatrixXd rounded = Af.cast<double>();
  REQUIRE((rounded - A).norm() > 0);  // the rounding is there to be seen
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -2.0, 3.0).array().sin();
  Eigen::VectorXd ySingle, yRounded;
  setDenseProductThreads(1);
  denseProduct(Af, x, ySingle);
  denseProduct(rounded, x, yRounded);
  REQUIRE(ySingle.size() == m);
  // The same products and sums as the double kernel on the rounded matrix: only A's rounding
  // separates it from the double product, never the sums (which a float sum would spoil at
  // 1e-7 of the largest term, here about 1e-5 of y's norm).
  CHECK((ySingle - yRounded).norm() <= 1e-13 * yRounded.norm());
  const Eigen::VectorXd exact = A * x;
  // Each entry rounded by at most 2^-24 of itself: |y − y_single| ≤ 2^-24 |A| |x| row by row.
  const Eigen::VectorXd bound = A.cwiseAbs() * x.cwiseAbs() * std::ldexp(1.0, -24);
  for (Eigen::Index i = 0; i < m; ++i)
    REQUIRE(std::abs(ySingle[i] - exact[i]) <= bound[i] * (1 + 1e-6) + 1e-12 * exact.norm());
  for (int threads : {2, 3}) {
    setDenseProductThreads(threads);
    Eigen::VectorXd y;
    denseProduct(Af, x, y);
    CHECK(std::memcmp(y.data(), ySingle.data(), sizeof(double) * static_cast<std::size_t>(m)) == 0);
  }
}

// Not in the default run (hidden tag): what the product costs at the sizes of SEAS BP5's
// right-hand side (moved nodes ns, rows 3·ns, columns 2·ns; 4 141 moved nodes at 1 km cells),
// Eigen's own product against denseProduct on one thread and on denseProductThreads(), each
// the best of several alternated repetitions in this one run (the machine is shared):
//   build/tests/unitTests "[denseProductBenchmark]"
TEST_CASE("denseProduct: cost against Eigen's product at BP5's sizes",
          "[.][denseProductBenchmark]") {
  ThreadsRestored restore;
  const int threads = denseProductThreads();
  std::printf("%8s %8s %8s %12s %12s %12s %12s %8s %8s %8s\n", "ns", "rows", "cols", "Eigen [ms]",
              "1 thread", "threads", "single", "x (1)", "x (all)", "x single");
  for (const Eigen::Index ns : {1071, 2142, 4141}) {
    const Eigen::Index m = 3 * ns, n = 2 * ns;
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(m, n);
    const Eigen::VectorXd x = Eigen::VectorXd::Random(n);
    const Eigen::MatrixXf Af = A.cast<float>();
    Eigen::VectorXd y0(m), y1, y2, y3;
    double eigen = 1e300, one = 1e300, all = 1e300, single = 1e300;
    const auto seconds = [](auto&& f) {
      const auto c0 = std::chrono::steady_clock::now();
      f();
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    };
    for (int rep = 0; rep < 7; ++rep) {
      eigen = std::min(eigen, seconds([&] { y0.noalias() = A * x; }));
      setDenseProductThreads(1);
      one = std::min(one, seconds([&] { denseProduct(A, x, y1); }));
      setDenseProductThreads(threads);
      all = std::min(all, seconds([&] { denseProduct(A, x, y2); }));
      single = std::min(single, seconds([&] { denseProduct(Af, x, y3); }));
    }
    REQUIRE((y1 - y0).norm() <= 1e-12 * y0.norm());
    REQUIRE(y1 == y2);
    REQUIRE((y3 - y0).norm() <= 1e-6 * y0.norm());
    std::printf("%8ld %8ld %8ld %12.2f %12.2f %9.2f (%d) %12.2f %8.2f %8.2f %8.2f\n",
                static_cast<long>(ns), static_cast<long>(m), static_cast<long>(n), 1e3 * eigen,
                1e3 * one, 1e3 * all, threads, 1e3 * single, eigen / one, eigen / all,
                eigen / single);
  }
}
