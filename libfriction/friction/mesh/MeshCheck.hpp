// Checks of a read mesh that no file syntax can express: vertices at the same place that
// share no edge (a hidden internal cut) and boundary facets (edges in 2D, triangles in 3D)
// that carry no label. Both are legal meshes that the solver would treat as traction-free
// boundaries, so the case must say that it means them (system/meshDict:
// allowCoincidentNodes, defaultPatch). And the sizes of the cells, for the summary. (Facets
// of more than two cells are refused by the readers and listed by MeshTopology.)
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "friction/mesh/Mesh.hpp"

namespace friction {

/// Relative tolerance of coincidentPoints: two vertices closer than this times the shortest
/// triangle side at either of them coincide. Vertices that share a side are at least one
/// side length apart, so no valid mesh comes near; a hidden cut has them at distance 0 (or
/// round-off of the coordinates, ~1e-16 relative).
inline constexpr double coincidentTolerance = 1e-6;

/// Pairs (a < b) of vertices used by cells that lie within coincidentTolerance times the
/// shorter local edge length of each other without being joined by a cell edge, ordered
/// by a. Expected cost O(n): a sorted grid.
std::vector<std::pair<Index, Index>> coincidentPoints(const Mesh& mesh);

/// Facets that bound one cell (the outer boundary, or the lips of a cut) and appear in no
/// labelled facet of the mesh, mesh.dim vertices each (flat), in lexicographic order of
/// their vertex lists, oriented with the body inside: a triangle side counter-clockwise as its
/// triangle runs (the body on the left), a tetrahedron face with its right-hand normal
/// pointing out of the body.
std::vector<Index> unlabelledBoundaryFacets(const Mesh& mesh);

/// Sizes of the cells of a mesh (areas in 2D, volumes in 3D), for summaries.
struct CellSizes {
  double total = 0;     ///< the mesh's area or volume
  double smallest = 0;  ///< the smallest cell's (0 for a mesh without cells)
  double largest = 0;
  Index smallestCell = -1, largestCell = -1;
};
CellSizes cellSizes(const Mesh& mesh);

}  // namespace friction
