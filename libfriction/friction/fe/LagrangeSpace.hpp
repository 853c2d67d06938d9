// LagrangeSpace: continuous vector-valued Lagrange P1 or P2 on a triangle mesh (the
// discrete displacement space of docs/method.md §4). Elements are affine: P2 nodes sit at the
// midpoints of straight edges.
//
// Numbering:
// * nodes: the mesh points first (node i is mesh point i), then, for P2, one node per
//   distinct triangle edge at its midpoint. Edges are keyed by their two node numbers, never
//   by coordinates, so on a mesh whose fracture nodes were duplicated the edges (a⁺, b⁺) and
//   (a⁻, b⁻) are different edges with different midpoint nodes.
// * local nodes of a triangle (v0, v1, v2): P1 → v0, v1, v2; P2 → v0, v1, v2, mid(v0,v1),
//   mid(v1,v2), mid(v2,v0) (gmsh / VTK order; FreeFEM orders midpoints differently).
// * dofs interleaved: dof(node, component) = 2 · node + component (component 0 = x, 1 = y).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "friction/core/Types.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

class MeshTopology;

/// Up to six node numbers (a cell's or an edge's), by value: no heap allocation.
struct NodeList {
  std::array<Index, 6> node{};
  int size = 0;

  Index operator[](int i) const { return node[static_cast<std::size_t>(i)]; }
  const Index* begin() const { return node.data(); }
  const Index* end() const { return node.data() + size; }
};

class LagrangeSpace {
 public:
  /// Build the space of the given degree (1 or 2) on `mesh`. The space keeps a reference to
  /// the mesh, which must outlive it. Throws InputError (naming mesh.source) if a labelled
  /// mesh edge is not a side of any triangle.
  LagrangeSpace(const Mesh& mesh, int degree);

  const Mesh& mesh() const { return *mesh_; }
  /// Polynomial degree: 1 or 2.
  int degree() const { return degree_; }

  Index numNodes() const { return static_cast<Index>(coordinates_.size()); }
  Index numDofs() const { return 2 * numNodes(); }
  Index numCells() const { return mesh_->numCells(); }
  /// Nodes per triangle: 3 (P1) or 6 (P2).
  int nodesPerCell() const { return degree_ == 1 ? 3 : 6; }
  /// Nodes per edge: 2 (P1) or 3 (P2).
  int nodesPerEdge() const { return degree_ + 1; }
  /// Number of distinct triangle edges of the mesh.
  Index numEdges() const;

  /// Global dof of component `component` (0 = x, 1 = y) of `node`.
  static Index dof(Index node, int component) { return 2 * node + component; }

  /// Coordinates of a node [m].
  const Vector2& coordinate(Index node) const {
    return coordinates_[static_cast<std::size_t>(node)];
  }
  const std::vector<Vector2>& coordinates() const { return coordinates_; }

  /// Nodes of a triangle in local order (see the file comment).
  NodeList cellNodes(Index cell) const;

  /// Nodes of the triangle side (a, b), from a to b: {a, b} (P1) or {a, mid, b} (P2).
  /// (a, b) must be a side of a triangle (debug assert); see midpointNode to test that.
  NodeList edgeNodes(Index a, Index b) const;

  /// Midpoint node of the side (a, b) for P2, or −1 if (a, b) is not a triangle side.
  /// For P1 returns −1 for every pair.
  Index midpointNode(Index a, Index b) const;

  /// Whether (a, b), in either orientation, is a side of some triangle.
  bool isEdge(Index a, Index b) const { return findEdge(a, b) >= 0; }

  /// The labelled mesh edges with this label, as node pairs in file orientation.
  std::vector<std::array<Index, 2>> labelledEdges(int label) const;

  /// All nodes (vertices and, for P2, midpoints) on the edges with this label, sorted,
  /// without repeats. Empty if the label has no edges.
  std::vector<Index> patchNodes(int label) const;

 private:
  /// Index of the edge {a, b} in the edge table, or −1.
  Index findEdge(Index a, Index b) const;

  const Mesh* mesh_;
  int degree_;
  std::vector<Vector2> coordinates_;
  /// Local-to-global node map, nodesPerCell() entries per cell.
  std::vector<Index> cellNodes_;
  /// The mesh's topology; edge k is its facet k (ordered by (a, b), a < b) and has midpoint
  /// node numPoints + k. Edges are facets in 2D only: P2 on tetrahedra needs an edge table.
  std::shared_ptr<const MeshTopology> topology_;
};

}  // namespace friction
