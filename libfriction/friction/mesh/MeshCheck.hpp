// Checks of a read mesh that no file syntax can express: vertices at the same place that
// share no edge (a hidden internal cut) and boundary edges that carry no label. Both are
// legal triangulations that the solver would treat as traction-free boundaries, so the
// case must say that it means them (system/meshDict: allowCoincidentNodes, defaultPatch).
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

}  // namespace friction
