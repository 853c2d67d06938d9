// LagrangeSpace: continuous vector-valued Lagrange P1 or P2 on a simplex mesh, triangles (2D)
// or tetrahedra (3D) (the discrete displacement space of docs/method.md §4, §7). Elements are
// affine: P2 nodes sit at the midpoints of straight edges.
//
// Numbering:
// * nodes: the mesh points first (node i is mesh point i), then, for P2, one node per
//   distinct cell edge at its midpoint, in the order of the edges' keys (a, b), a < b. Edges
//   are keyed by their two node numbers, never by coordinates, so on a mesh whose fracture
//   nodes were duplicated the edges (a⁺, b⁺) and (a⁻, b⁻) are different edges with different
//   midpoint nodes. In 2D the edges are the facets of the mesh's topology; in 3D they are not
//   facets, and the space builds its own edge table (sorted, like the topology's facets).
// * local nodes of a cell: Simplex.hpp's order (P2 triangle: v0, v1, v2, mid(v0,v1),
//   mid(v1,v2), mid(v2,v0); P2 tetrahedron: VTK_QUADRATIC_TETRA order).
// * nodes of a labelled facet (a, b) / (a, b, c): P1 its vertices; P2 (a, mid, b) in 2D,
//   (a, b, c, mid(a,b), mid(b,c), mid(c,a)) in 3D (Simplex.hpp's facet order).
// * dofs interleaved: dof(node, component) = d · node + component (0 = x, 1 = y, 2 = z).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "friction/core/Types.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

class MeshTopology;

/// Up to ten node numbers (a cell's, a facet's or an edge's), by value: no heap allocation.
struct NodeList {
  std::array<Index, 10> node{};
  int size = 0;

  Index operator[](int i) const { return node[static_cast<std::size_t>(i)]; }
  const Index* begin() const { return node.data(); }
  const Index* end() const { return node.data() + size; }
};

class LagrangeSpace {
 public:
  /// Build the space of the given degree (1 or 2) on `mesh` (2D or 3D). The space keeps a
  /// reference to the mesh, which must outlive it. Throws InputError (naming mesh.source) if
  /// a labelled mesh facet is not a facet of any cell.
  LagrangeSpace(const Mesh& mesh, int degree);

  const Mesh& mesh() const { return *mesh_; }
  /// The mesh's dimension d: components per node.
  int dim() const { return dim_; }
  /// Polynomial degree: 1 or 2.
  int degree() const { return degree_; }

  Index numNodes() const { return static_cast<Index>(points_.size()); }
  Index numDofs() const { return dim_ * numNodes(); }
  Index numCells() const { return mesh_->numCells(); }
  /// Nodes per cell: d + 1 (P1); 6 (P2 triangle) or 10 (P2 tetrahedron).
  int nodesPerCell() const { return degree_ == 1 ? dim_ + 1 : (dim_ + 1) * (dim_ + 2) / 2; }
  /// Nodes per labelled facet: d (P1); 3 (P2 edge) or 6 (P2 triangle).
  int nodesPerFacet() const { return degree_ == 1 ? dim_ : dim_ * (dim_ + 1) / 2; }
  /// Nodes per edge: 2 (P1) or 3 (P2).
  int nodesPerEdge() const { return degree_ + 1; }
  /// Number of distinct cell edges of the mesh.
  Index numEdges() const;

  /// Global dof of component `component` (0 = x, 1 = y, 2 = z) of `node`.
  Index dof(Index node, int component) const { return dim_ * node + component; }

  /// Position of a node [m] (z = 0 in 2D).
  const Point& point(Index node) const { return points_[static_cast<std::size_t>(node)]; }
  /// x and y of a node [m], for 2D code.
  Vector2 coordinate(Index node) const { return point(node).head<2>(); }

  /// Nodes of a cell in local order (see the file comment).
  NodeList cellNodes(Index cell) const;

  /// Nodes of the cell edge (a, b), from a to b: {a, b} (P1) or {a, mid, b} (P2).
  /// (a, b) must be a cell edge (debug assert); see midpointNode to test that.
  NodeList edgeNodes(Index a, Index b) const;

  /// Midpoint node of the edge (a, b) for P2, or −1 if (a, b) is not a cell edge.
  /// For P1 returns −1 for every pair.
  Index midpointNode(Index a, Index b) const;

  /// Whether (a, b), in either orientation, is an edge of some cell.
  bool isEdge(Index a, Index b) const { return findEdge(a, b) >= 0; }

  /// Nodes of a facet given by its d vertices (a cell facet, in any orientation), in the facet
  /// order of the file comment.
  NodeList facetNodes(const Index* vertices) const;
  /// Nodes of the mesh's labelled facet f.
  NodeList labelledFacetNodes(Index f) const;

  /// The mesh's labelled facets with this label (indices into the mesh's facet list).
  std::vector<Index> labelledFacets(int label) const;
  /// 2D: the labelled mesh edges with this label, as node pairs in file orientation.
  std::vector<std::array<Index, 2>> labelledEdges(int label) const;

  /// All nodes (vertices and, for P2, midpoints) on the facets with this label, sorted,
  /// without repeats. Empty if the label has no facets.
  std::vector<Index> patchNodes(int label) const;

 private:
  /// Index of the edge {a, b} in the edge table, or −1.
  Index findEdge(Index a, Index b) const;
  /// 3D: the edge table (edges keyed (a, b), a < b, in key order) and each cell's six edges.
  void buildEdgeTable();

  const Mesh* mesh_;
  int dim_;
  int degree_;
  std::vector<Point> points_;
  /// Local-to-global node map, nodesPerCell() entries per cell.
  std::vector<Index> cellNodes_;
  /// The mesh's topology. In 2D edge k is its facet k (ordered by (a, b), a < b) and has
  /// midpoint node numPoints + k.
  std::shared_ptr<const MeshTopology> topology_;
  /// 3D edge table: the edges of smallest vertex a are k in [edgeStart_[a], edgeStart_[a+1]),
  /// with larger vertex edgeOther_[k], ascending; edge k has midpoint node numPoints + k.
  std::vector<Index> edgeStart_;
  std::vector<Index> edgeOther_;
  /// 3D: the edge of each cell's local edge e (SimplexNodes<3>::edges order), 6 per cell.
  std::vector<Index> cellEdges_;
};

}  // namespace friction
