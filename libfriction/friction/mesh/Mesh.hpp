// Mesh: a simplex mesh whose dimension is a run-time fact (as MFEM's Mesh::Dimension()):
// 2D triangles with labelled line elements, or 3D tetrahedra with labelled triangles; the
// labelled facets are boundary patches and internal fracture facets. As read from FreeFEM
// (.msh in 2D, Medit .mesh in 3D) or gmsh. Node numbers are 0-based and contiguous.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "friction/core/Types.hpp"

namespace friction {

class MeshTopology;

/// A view of `size()` consecutive vertex numbers (one cell or facet of a Mesh). Not
/// assignable, so that `mesh.cell(c) = {...}` does not compile (it would change nothing).
template <class T>
struct VertexSpan {
  VertexSpan(T* data, int size) : first(data), count(size) {}
  VertexSpan(const VertexSpan&) = default;
  VertexSpan& operator=(const VertexSpan&) = delete;
  T* const first;
  const int count;
  T* begin() const { return first; }
  T* end() const { return first + count; }
  T& operator[](int k) const { return first[k]; }
  int size() const { return count; }
};

struct Mesh {
  /// File the mesh was read from, and its format ("FreeFEM .msh", "Medit .mesh",
  /// "gmsh .msh 2.2", "gmsh .msh 4.1"); for messages and summaries.
  std::string source;
  std::string format;

  /// 2: triangles and labelled edges; 3: tetrahedra and labelled triangles.
  int dim = 2;

  /// Coordinates; z = 0 in 2D.
  std::vector<Point> points;
  /// dim + 1 vertices per cell: triangles counter-clockwise (positive area), tetrahedra of
  /// positive volume; the readers reject the other orientation.
  std::vector<Index> cellVertices;
  /// Region per cell (FreeFEM region, gmsh physical surface (2D) or volume (3D) tag, 0 if
  /// none).
  std::vector<int> cellRegion;

  /// Labelled facets, dim vertices each: boundary patches and internal (fracture) facets, in
  /// file order and orientation. A facet in two physical groups appears twice (one per label).
  std::vector<Index> facetVertices;
  /// Label per facet (FreeFEM label, gmsh physical curve (2D) or surface (3D) tag, 0 if none).
  std::vector<int> facetLabel;

  /// Names of labels where the file gives them (gmsh $PhysicalNames of dimension dim − 1).
  std::map<int, std::string> labelNames;
  /// Names of regions where the file gives them (gmsh $PhysicalNames of dimension dim).
  std::map<int, std::string> regionNames;

  /// A vertex of the file that no cell uses: the readers drop it (and renumber), since it
  /// would be a node without stiffness. gmsh writes one per `Physical Point` that is not
  /// embedded in a surface or volume. Kept for the split summary.
  struct DroppedPoint {
    long long number;  ///< as the file numbers it (FreeFEM: 1-based position; gmsh: node tag)
    Point x;
  };
  std::vector<DroppedPoint> droppedPoints;

  int verticesPerCell() const { return dim + 1; }
  int verticesPerFacet() const { return dim; }
  Index numPoints() const { return static_cast<Index>(points.size()); }
  Index numCells() const { return static_cast<Index>(cellVertices.size()) / (dim + 1); }
  Index numFacets() const { return static_cast<Index>(facetLabel.size()); }

  /// Vertex k (0..dim) of cell c, and all of them.
  Index cellVertex(Index c, int k) const {
    return cellVertices[static_cast<std::size_t>(c) * (dim + 1) + k];
  }
  VertexSpan<const Index> cell(Index c) const {
    return {cellVertices.data() + static_cast<std::size_t>(c) * (dim + 1), dim + 1};
  }
  VertexSpan<Index> cell(Index c) {
    return {cellVertices.data() + static_cast<std::size_t>(c) * (dim + 1), dim + 1};
  }
  /// Vertex k (0..dim − 1) of labelled facet f, and all of them.
  Index facetVertex(Index f, int k) const {
    return facetVertices[static_cast<std::size_t>(f) * dim + k];
  }
  VertexSpan<const Index> facet(Index f) const {
    return {facetVertices.data() + static_cast<std::size_t>(f) * dim, dim};
  }
  VertexSpan<Index> facet(Index f) {
    return {facetVertices.data() + static_cast<std::size_t>(f) * dim, dim};
  }

  /// Append a cell (dim + 1 vertices) with its region, or a labelled facet (dim vertices).
  void addCell(std::initializer_list<Index> vertices, int region = 0);
  void addFacet(std::initializer_list<Index> vertices, int label);

  /// Signed area (2D, positive counter-clockwise) or volume (3D, positive for the required
  /// orientation) of cell c.
  double signedMeasure(Index c) const;
  /// Sum of the cells' areas (2D) or volumes (3D).
  double totalMeasure() const;

  /// The adjacency of the cells (MeshTopology.hpp), built on the first call and kept, so
  /// that every user of this mesh shares one. Rebuilt if the dimension, the cells or the
  /// number of points changed since (checked on each call, O(number of cells)): keep the
  /// pointer rather than calling this per lookup. Not thread-safe.
  std::shared_ptr<const MeshTopology> topology() const;

 private:
  mutable std::shared_ptr<const MeshTopology> topology_;
};

/// "(x y)" in 2D, "(x y z)" in 3D, with 6 significant digits: how messages and summaries
/// name a point.
std::string formatPoint(const Point& p, int dim);

/// What a cell and a labelled facet are called in messages: "triangle" / "edge" in 2D,
/// "tetrahedron" / "triangle" in 3D.
const char* cellName(int dim);
const char* facetName(int dim);

/// One key per side {a, b} of the mesh, whatever its orientation (for hashing sides).
std::uint64_t sideKey(Index a, Index b);

}  // namespace friction
