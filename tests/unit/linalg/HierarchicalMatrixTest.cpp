// HierarchicalMatrix (linalg/HierarchicalMatrix.hpp): on kernels that decay with distance like
// the fault operator's (a line of points as a 2D fault, a square as a 3D one, several rows and
// columns per point as S has), the compressed matrix is within its tolerance of the dense one
// in the Frobenius norm, the error falls with the tolerance, the storage is a fraction of the
// dense one, the product equals the compressed matrix's, and with no admissible block it is
// the dense matrix exactly.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "friction/linalg/HierarchicalMatrix.hpp"

using namespace friction;
using Eigen::Index;

namespace {

struct Kernel {
  Eigen::MatrixXd points;  // d × p
  std::vector<Index> rowPoint, colPoint;
  Eigen::MatrixXd A;  // the dense matrix
};

/// rowsPer rows and colsPer columns per point; entry (a, b) of points (i, j):
/// (1 + a + 2b) / (|x_i − x_j| + h), h the spacing: smooth away from the diagonal, like the
/// traction at one node caused by slip at another.
Kernel kernel(const Eigen::MatrixXd& points, int rowsPer, int colsPer, double h) {
  Kernel k;
  k.points = points;
  const Index p = points.cols();
  for (Index i = 0; i < p; ++i) {
    for (int a = 0; a < rowsPer; ++a) k.rowPoint.push_back(i);
    for (int b = 0; b < colsPer; ++b) k.colPoint.push_back(i);
  }
  k.A.resize(rowsPer * p, colsPer * p);
  for (Index i = 0; i < p; ++i)
    for (Index j = 0; j < p; ++j) {
      const double r = (points.col(i) - points.col(j)).norm();
      for (int a = 0; a < rowsPer; ++a)
        for (int b = 0; b < colsPer; ++b)
          k.A(rowsPer * i + a, colsPer * j + b) = (1.0 + a + 2.0 * b) / (r + h);
    }
  return k;
}

HierarchicalMatrix compress(const Kernel& k, const HierarchicalSettings& s) {
  const auto source = [&](const std::vector<Index>& rows, const std::vector<Index>& cols,
                          Eigen::MatrixXd& out) {
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < cols.size(); ++j)
        out(static_cast<Index>(i), static_cast<Index>(j)) = k.A(rows[i], cols[j]);
  };
  return HierarchicalMatrix(source, k.points, k.rowPoint, k.colPoint, s);
}

/// Points along a dipping line (2D fault), shuffled so that the tree, not the input order,
/// groups them.
Eigen::MatrixXd linePoints(Index p) {
  Eigen::MatrixXd x(2, p);
  for (Index i = 0; i < p; ++i) {
    const Index q = (i * 7919) % p;  // a permutation (7919 is prime, p below it)
    x(0, q) = 0.5 * static_cast<double>(i);
    x(1, q) = -0.866 * static_cast<double>(i);
  }
  return x;
}

Eigen::MatrixXd squarePoints(Index side) {
  Eigen::MatrixXd x(3, side * side);
  for (Index i = 0; i < side; ++i)
    for (Index j = 0; j < side; ++j)
      x.col(i * side + j) << static_cast<double>(i), 0.0, -static_cast<double>(j);
  return x;
}

}  // namespace

TEST_CASE("HierarchicalMatrix: within its tolerance of the dense matrix, a line of points",
          "[HierarchicalMatrix]") {
  const Kernel k = kernel(linePoints(1500), 2, 1, 1.0);
  double lastError = 1;
  for (const double tol : {1e-4, 1e-6, 1e-9}) {
    HierarchicalSettings s;
    s.tolerance = tol;
    const HierarchicalMatrix H = compress(k, s);
    REQUIRE(H.rows() == k.A.rows());
    REQUIRE(H.cols() == k.A.cols());
    REQUIRE(H.stats().lowRankBlocks > 0);  // something was compressed
    const double error = (H.toDense() - k.A).norm() / k.A.norm();
    CHECK(error <= tol);
    CHECK(error < lastError);
    lastError = error;
    // Storage: a fraction of the dense matrix even at 1e-9 (ranks grow like log(1/tol)).
    CHECK(H.stats().storedEntries < 0.35 * H.stats().denseEntries);
  }
}

TEST_CASE("HierarchicalMatrix: a square of points with three rows and two columns per point",
          "[HierarchicalMatrix]") {
  const Kernel k = kernel(squarePoints(30), 3, 2, 1.0);
  HierarchicalSettings s;
  s.tolerance = 1e-6;
  s.leafSize = 16;
  const HierarchicalMatrix H = compress(k, s);
  REQUIRE(H.stats().lowRankBlocks > 0);
  CHECK((H.toDense() - k.A).norm() <= 1e-6 * k.A.norm());
  CHECK(H.stats().storedEntries < 0.6 * H.stats().denseEntries);
  // The product is the compressed matrix's (every block counted once, in its place).
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(H.cols(), -1.0, 2.0).array().sin();
  Eigen::VectorXd y;
  H.multiply(x, y);
  const Eigen::VectorXd yDense = H.toDense() * x;
  CHECK((y - yDense).norm() <= 1e-13 * yDense.norm());
  CHECK((y - k.A * x).norm() <= 1e-5 * (k.A * x).norm());
}

TEST_CASE("HierarchicalMatrix: with no admissible block it is the dense matrix",
          "[HierarchicalMatrix]") {
  const Kernel k = kernel(linePoints(300), 2, 1, 1.0);
  HierarchicalSettings s;
  s.eta = 0;  // nothing is far enough
  const HierarchicalMatrix H = compress(k, s);
  CHECK(H.stats().lowRankBlocks == 0);
  CHECK(H.stats().denseBlocks > 1);
  CHECK(H.toDense() == k.A);
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(H.cols(), 1.0, 3.0), y;
  H.multiply(x, y);
  CHECK((y - k.A * x).norm() <= 1e-14 * (k.A * x).norm());
}

TEST_CASE("HierarchicalMatrix: zero columns (held nodes) stay zero", "[HierarchicalMatrix]") {
  Kernel k = kernel(linePoints(400), 2, 1, 1.0);
  for (Index j = 0; j < k.A.cols(); j += 3) k.A.col(j).setZero();
  HierarchicalSettings s;
  const HierarchicalMatrix H = compress(k, s);
  const Eigen::MatrixXd D = H.toDense();
  // Exactly zero but for the recompression's round-off (the masked slip never reaches them).
  for (Index j = 0; j < k.A.cols(); j += 3) CHECK(D.col(j).norm() <= 1e-14 * k.A.norm());
  CHECK((D - k.A).norm() <= s.tolerance * k.A.norm());
}
