// HierarchicalMatrix: a dense matrix whose rows and columns belong to points in space, stored
// as a hierarchical matrix (H-matrix): blocks coupling well-separated groups of points as
// low-rank products U Vᵀ, the others as they are (docs/method.md, "The fault operator
// compressed").
//
// Why: the interface operator S behaves like a boundary-integral kernel (the traction at one
// fault node caused by slip at another decays with their distance), so the blocks coupling
// distant patches of the fault are numerically of low rank. Stored this way, a product S x
// costs about (rows + cols) · r · log(points) operations instead of rows · cols: the
// right-hand side of the quasi-dynamic integration is that product, evaluated 10⁵–10⁶ times
// in a cycle simulation.
//
// Construction:
//   * cluster tree: the points split in two at the median of their bounding box's longest
//     side, recursively, down to `leafSize` points;
//   * block tree: a pair of clusters (τ, σ) is admissible (compressed) when
//     min(diam τ, diam σ) ≤ eta · dist(τ, σ) (bounding boxes), refined while not; a pair
//     with a leaf cluster that is not admissible is stored dense;
//   * an admissible block is compressed by adaptive cross approximation with full pivoting
//     on the block (its entries are given: this class compresses a matrix that exists,
//     block by block), until the residual's Frobenius norm is at most `tolerance` times the
//     block's; the factors are then recompressed (QR of each, SVD of the small core) to the
//     smallest rank within the same bound. A block whose rank would store more numbers
//     than the block is kept dense.
// So ‖S − H‖_F ≤ tolerance · ‖S‖_F, block by block: each block of H is within `tolerance`
// of the same block of S, far and near alike.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace friction {

struct HierarchicalSettings {
  double tolerance = 1e-8;  ///< relative Frobenius error of every compressed block
  double eta = 2.0;         ///< admissibility: min(diam τ, diam σ) ≤ eta · dist(τ, σ)
  int leafSize = 32;        ///< at most this many points per leaf cluster
};

/// What the compression made (for the log and the studies).
struct HierarchicalStats {
  long denseBlocks = 0, lowRankBlocks = 0;
  int maxRank = 0;
  double meanRank = 0;       ///< over the low-rank blocks
  double storedEntries = 0;  ///< numbers stored (dense entries + (m + n) r per low-rank block)
  double denseEntries = 0;   ///< rows · cols
  double seconds = 0;        ///< wall time of the compression
  /// "H-matrix 3358 x 1679: 412 low-rank blocks (rank ≤ 17, mean 9.1), 150 dense; 6.2 % of
  /// the dense entries (3.5 MB), compressed in 0.21 s".
  std::string describe(long rows, long cols) const;
};

class HierarchicalMatrix {
 public:
  /// The block of the matrix at the given (original) row and column indices, into out
  /// (rows.size() × cols.size()).
  using BlockSource =
      std::function<void(const std::vector<Eigen::Index>& rows,
                         const std::vector<Eigen::Index>& cols, Eigen::MatrixXd& out)>;

  HierarchicalMatrix() = default;
  /// Compress the rows × cols matrix given by `source`. points: d × p coordinates [m];
  /// rowPoint[i], colPoint[j]: the point row i and column j belong to (0 … p − 1).
  HierarchicalMatrix(const BlockSource& source, const Eigen::MatrixXd& points,
                     const std::vector<Eigen::Index>& rowPoint,
                     const std::vector<Eigen::Index>& colPoint,
                     const HierarchicalSettings& settings);

  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return cols_; }
  /// y = H x (x: cols(), y: rows()).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  /// The whole matrix H, dense (for tests and error measurements).
  Eigen::MatrixXd toDense() const;
  const HierarchicalStats& stats() const { return stats_; }

 private:
  struct Cluster {
    Eigen::Index rowBegin = 0, rowEnd = 0, colBegin = 0, colEnd = 0;  ///< permuted ranges
    Eigen::Index pointBegin = 0, pointEnd = 0;
    Eigen::VectorXd lo, hi;  ///< bounding box
    int child[2] = {-1, -1};
  };
  struct Block {
    Eigen::Index row0, rows, col0, cols;  ///< permuted ranges
    Eigen::MatrixXd dense;                ///< dense block, or
    Eigen::MatrixXd U, V;                 ///< the low-rank block U Vᵀ
    bool lowRank = false;
  };

  int buildClusters(const Eigen::MatrixXd& points, std::vector<Eigen::Index>& order,
                    Eigen::Index begin, Eigen::Index end, int leafSize);
  void buildBlocks(int tau, int sigma, const BlockSource& source,
                   const HierarchicalSettings& settings);
  bool admissible(const Cluster& a, const Cluster& b, double eta) const;

  Eigen::Index rows_ = 0, cols_ = 0;
  std::vector<Eigen::Index> rowPerm_, colPerm_;  ///< permuted position → original index
  std::vector<Cluster> clusters_;
  std::vector<Block> blocks_;
  HierarchicalStats stats_;
};

}  // namespace friction
