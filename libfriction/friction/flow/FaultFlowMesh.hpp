// FaultFlowMesh: a fault's own mesh for P1 flow along it (METHOD.md §11, "Computed on the
// fault"): points in space and elements that are segments (2D: the fault is a curve, or a
// network of curves) or triangles (3D: a fault surface), with the P1 mass and stiffness
// matrices of the surface operator ∇_Γ·(κ ∇_Γ ·) and the location of points (wells) on it.
//
// Nodes shared by several curves or surfaces (junctions) are one node: at a junction the
// pressure is one value per physical point, and the flux balances there by assembly.
// Everything is computed from lengths, areas and dot products of edge vectors, so a rigid
// motion of the points changes the matrices only by round-off.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <array>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/core/Types.hpp"

namespace friction {

class FaultFlowMesh;

/// A material coefficient of the flow (storage S, transmissivity κ): a constant, one value per
/// node (interpolated P1), or one per element. On an element the value used is its mean (the
/// mean of its nodes' values for a per-node field): exact for the stiffness of a P1-interpolated
/// κ (its gradient term is constant on the element), second order for the mass.
class FlowCoefficient {
 public:
  enum class Kind { constant, perNode, perElement };

  /// A constant (implicit, so that a number can be passed where a coefficient is expected).
  FlowCoefficient(double constant = 1.0) : constant_(constant) {}  // NOLINT(runtime/explicit)
  static FlowCoefficient perNode(Eigen::VectorXd values);
  static FlowCoefficient perElement(Eigen::VectorXd values);

  Kind kind() const { return kind_; }
  /// The value on element e of mesh.
  double onElement(const FaultFlowMesh& mesh, Index e) const;
  /// Refuses (InputError at `where`, naming `what`) a size that does not match mesh, or a value
  /// that is not finite, or ≤ 0 (allowZero: < 0).
  void check(const FaultFlowMesh& mesh, bool allowZero, const std::string& what,
             const SourceLocation& where) const;

 private:
  Kind kind_ = Kind::constant;
  double constant_ = 1.0;
  Eigen::VectorXd values_;
};

class FaultFlowMesh {
 public:
  using Segment = std::array<Index, 2>;
  using Triangle = std::array<Index, 3>;

  /// A curve (2D fault): `points` [m] (z = 0 in a 2D mesh) and `segments`, pairs of point
  /// indices. Refuses (InputError at `where`) an empty mesh, an index out of range, a segment
  /// of length 0, a point that is not finite or belongs to no segment.
  FaultFlowMesh(std::vector<Point> points, const std::vector<Segment>& segments,
                SourceLocation where = {});
  /// A surface (3D fault): `triangles` of point indices (any orientation). Refuses the same as
  /// above, and triangles of area 0.
  FaultFlowMesh(std::vector<Point> points, const std::vector<Triangle>& triangles,
                SourceLocation where = {});

  /// One fracture curve of a 2D network, its nodes in order along it (each consecutive pair is
  /// a segment), each with a global id (e.g. its node number in the unsplit mesh) and point.
  struct Curve {
    std::vector<long long> id;
    std::vector<Point> points;
  };
  /// The curves' network: nodes with the same id are one node (a junction), whose points must
  /// agree (within 1e-9 of the network's size). curveNodes()[c][i] is then the mesh node of
  /// node i of curve c.
  static FaultFlowMesh fromCurves(const std::vector<Curve>& curves, SourceLocation where = {});
  /// fromCurves: per curve, its nodes' indices in this mesh; otherwise empty.
  const std::vector<std::vector<Index>>& curveNodes() const { return curveNodes_; }

  /// 1 for a curve (segments), 2 for a surface (triangles).
  int elementDimension() const { return nodesPerElement_ - 1; }
  int nodesPerElement() const { return nodesPerElement_; }
  Index numNodes() const { return static_cast<Index>(points_.size()); }
  Index numElements() const { return static_cast<Index>(elements_.size()); }
  const Point& point(Index i) const { return points_[static_cast<std::size_t>(i)]; }
  const std::vector<Point>& points() const { return points_; }
  /// The nodes of element e (the first nodesPerElement() entries; −1 after them).
  const std::array<Index, 3>& element(Index e) const {
    return elements_[static_cast<std::size_t>(e)];
  }
  /// Length (segments) or area (triangles) of element e [m or m²].
  double measure(Index e) const { return measure_[static_cast<std::size_t>(e)]; }
  double totalMeasure() const;
  /// The mean edge length [m] (h of the convergence studies).
  double meanEdgeLength() const;

  /// The nodes on the edge of the fault itself: curve ends (nodes of exactly one segment), or
  /// nodes of triangle edges that belong to one triangle only; ascending.
  std::vector<Index> edgeNodes() const;

  /// ∫ c φ_i dA per node (the lumped mass: row sums of the consistent mass).
  Eigen::VectorXd lumpedMass(const FlowCoefficient& c = 1.0) const;
  /// ∫ c φ_i φ_j dA (c at its element mean).
  Eigen::SparseMatrix<double> consistentMass(const FlowCoefficient& c = 1.0) const;
  /// ∫ κ ∇_Γφ_i·∇_Γφ_j dA: symmetric, rows summing to zero (no-flow edges).
  Eigen::SparseMatrix<double> stiffness(const FlowCoefficient& kappa) const;

  /// The closest point of the mesh to x: its element, the P1 weights of that point in the
  /// element (summing to 1; the first nodesPerElement() entries) and the distance [m].
  struct Location {
    Index element = -1;
    std::array<double, 3> weight{};
    Point closest = Point::Zero();
    double distance = 0.0;
  };
  Location locate(const Point& x) const;
  /// The node nearest to x, and its distance [m] when `distance` is given.
  Index nearestNode(const Point& x, double* distance = nullptr) const;

 private:
  FaultFlowMesh() = default;
  void build(int nodesPerElement, const SourceLocation& where);

  int nodesPerElement_ = 2;
  std::vector<Point> points_;
  std::vector<std::array<Index, 3>> elements_;
  std::vector<double> measure_;
  std::vector<std::vector<Index>> curveNodes_;
};

}  // namespace friction
