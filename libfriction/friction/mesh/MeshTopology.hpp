// MeshTopology: the adjacency of a simplex mesh (cells, facets, facet → cells, boundary
// facets), built once per mesh and shared by the splitter, the mesh checks, the boundary
// conditions and the FE space (Mesh::topology()). The dimension d is a run-time fact: a cell
// has d + 1 vertices and d + 1 facets of d vertices each (triangles and their sides in 2D;
// tetrahedra and their triangles in 3D).
//
// Conventions:
// * local facet k of a cell is the facet opposite its local vertex k (the other d vertices),
//   so the opposite vertex of (cell, k) is vertex k of the cell;
// * a facet is keyed by its vertices in ascending order, and facets are numbered in
//   lexicographic order of their keys;
// * the cells of a facet are listed in ascending cell order: two inside the body, one on the
//   boundary of the body (or on a lip of a cut), more where the mesh is not a manifold
//   (overSharedFacets; the readers refuse such meshes, and so does the splitter).
//
// Built by sorting, not hashing: every (facet key, cell, local facet) is bucketed by its
// smallest vertex and each small bucket is sorted, O(N) plus a few-element sort per vertex.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "friction/core/Types.hpp"

namespace friction {

struct Mesh;

class MeshTopology {
 public:
  /// Largest dimension the tables hold (a facet of a tetrahedron has 3 vertices).
  static constexpr int maxDimension = 3;

  /// One side of a facet: the cell and the facet's local number in it.
  struct CellFacet {
    Index cell;
    int local;
  };

  /// The topology of the cells of a mesh (mesh.cellVertices, dimension mesh.dim, vertices
  /// 0..numPoints − 1). Throws InputError naming mesh.source if a cell has a vertex that is
  /// not a point of the mesh (the readers never make one).
  explicit MeshTopology(const Mesh& mesh);

  /// The topology of `cellVertices.size() / (dimension + 1)` cells of dimension + 1 vertices
  /// each (vertices 0..numVertices − 1). Throws InputError naming `source` on a vertex out
  /// of range.
  MeshTopology(int dimension, Index numVertices, std::vector<Index> cellVertices,
               const std::string& source);

  /// Whether this is the topology of the mesh as it is now (same points count, same cells).
  bool describes(const Mesh& mesh) const;

  int dimension() const { return dim_; }
  Index numVertices() const { return numVertices_; }
  Index numCells() const { return static_cast<Index>(cells_.size()) / (dim_ + 1); }
  Index numFacets() const { return static_cast<Index>(facetCellStart_.size()) - 1; }
  /// Vertices (and facets) per cell: d + 1.
  int verticesPerCell() const { return dim_ + 1; }
  /// Vertices per facet: d.
  int verticesPerFacet() const { return dim_; }

  /// Vertex k (0..d) of a cell, as the mesh lists it.
  Index cellVertex(Index cell, int k) const { return cells_[at(cell, k)]; }
  /// The facet opposite local vertex k of a cell.
  Index cellFacet(Index cell, int k) const { return cellFacets_[at(cell, k)]; }
  /// The vertex of the cell that is not on its local facet k (vertex k).
  Index oppositeVertex(Index cell, int k) const { return cellVertex(cell, k); }

  /// Vertex k (0..d − 1) of a facet; ascending in k.
  Index facetVertex(Index facet, int k) const {
    return facetVertices_[static_cast<std::size_t>(facet) * dim_ + k];
  }
  /// Number of cells that have this facet: 1 on the boundary, 2 inside, more where the mesh
  /// is not a manifold.
  int numCellsOf(Index facet) const {
    return static_cast<int>(facetCellStart_[facet + 1] - facetCellStart_[facet]);
  }
  /// The i-th cell of a facet (ascending cell order) and the facet's local number there.
  CellFacet cellOf(Index facet, int i) const {
    const std::uint32_t cl = facetCells_[facetCellStart_[facet] + i];
    return {static_cast<Index>(cl >> 2), static_cast<int>(cl & 3u)};
  }
  /// A facet of exactly one cell: on the boundary of the body (outer boundary or a lip).
  bool isBoundary(Index facet) const { return numCellsOf(facet) == 1; }

  /// The facet with these d vertices (any order), or −1 if no cell has it (also for a
  /// vertex out of range or a wrong number of vertices).
  Index findFacet(std::initializer_list<Index> vertices) const;

  /// Facets of more than two cells, ascending: empty for a mesh of a manifold.
  const std::vector<Index>& overSharedFacets() const { return overShared_; }

 private:
  template <int dim>
  void build();
  /// findFacet for a sorted key (key[0] in range).
  Index findFacetKey(const Index* key) const;

  std::size_t at(Index cell, int k) const {
    return static_cast<std::size_t>(cell) * (dim_ + 1) + k;
  }

  int dim_ = 2;
  Index numVertices_ = 0;
  std::vector<Index> cells_;               ///< d + 1 vertices per cell
  std::vector<Index> cellFacets_;          ///< d + 1 facets per cell (facet k opposite vertex k)
  std::vector<Index> facetVertices_;       ///< d ascending vertices per facet
  std::vector<Index> facetCellStart_;      ///< facet f's cells: facetCells_[start[f], start[f+1])
  std::vector<std::uint32_t> facetCells_;  ///< cell · 4 + local (half the memory of CellFacet)
  /// Facets whose smallest vertex is v: [firstFacet_[v], firstFacet_[v + 1]).
  std::vector<Index> firstFacet_;
  std::vector<Index> overShared_;
};

}  // namespace friction
