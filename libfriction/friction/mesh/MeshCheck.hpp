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

/// Pairs (a < b) of vertices used by triangles that lie within coincidentTolerance times the
/// shorter local side length of each other without being joined by a triangle side, ordered
/// by a. Expected cost O(n): a hash grid.
std::vector<std::pair<Index, Index>> coincidentPoints(const Mesh& mesh);

/// Triangle sides that bound one triangle (the outer boundary, or the lips of a cut) and
/// appear in no labelled edge of the mesh, oriented as in their triangle (counter-clockwise:
/// the body on the left).
std::vector<std::array<Index, 2>> unlabelledBoundaryEdges(const Mesh& mesh);

}  // namespace friction
