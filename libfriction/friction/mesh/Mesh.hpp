// Mesh: a 2D triangle mesh with labelled line elements (boundary patches and internal
// fracture edges), as read from FreeFEM or gmsh. Node numbers are 0-based and contiguous.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "friction/core/Types.hpp"

namespace friction {

class MeshTopology;

struct Mesh {
  /// File the mesh was read from, and its format ("FreeFEM .msh", "gmsh .msh 2.2",
  /// "gmsh .msh 4.1"); for messages and summaries.
  std::string source;
  std::string format;

  std::vector<Vector2> points;
  /// Triangles, counter-clockwise (positive area); readers reject clockwise ones.
  std::vector<std::array<Index, 3>> triangles;
  /// Region number per triangle (FreeFEM region / gmsh physical surface tag, 0 if none).
  std::vector<int> triangleRegion;

  /// Labelled line elements: boundary edges and internal (fracture) edges, in file order
  /// and orientation. An edge in two physical groups appears twice (one per label).
  std::vector<std::array<Index, 2>> edges;
  /// Label per edge (FreeFEM edge label / gmsh physical curve tag, 0 if none).
  std::vector<int> edgeLabel;

  /// Names of labels where the file gives them (gmsh $PhysicalNames of dimension 1).
  std::map<int, std::string> labelNames;
  /// Names of regions where the file gives them (gmsh $PhysicalNames of dimension 2).
  std::map<int, std::string> regionNames;

  /// A vertex of the file that no triangle uses: the readers drop it (and renumber), since
  /// it would be a node without stiffness. gmsh writes one per `Physical Point` that is not
  /// embedded in a surface. Kept for the split summary.
  struct DroppedPoint {
    long long number;  ///< as the file numbers it (FreeFEM: 1-based position; gmsh: node tag)
    Vector2 x;
  };
  std::vector<DroppedPoint> droppedPoints;

  Index numPoints() const { return static_cast<Index>(points.size()); }
  Index numTriangles() const { return static_cast<Index>(triangles.size()); }

  /// Signed area of triangle t (positive for counter-clockwise).
  double signedArea(Index t) const;
  /// Sum of triangle areas.
  double totalArea() const;

  /// The adjacency of the triangles (MeshTopology.hpp), built on the first call and kept, so
  /// that every user of this mesh shares one. Rebuilt if the triangles or the number of
  /// points changed since (checked on each call, O(number of triangles)): keep the pointer
  /// rather than calling this per lookup. Not thread-safe.
  std::shared_ptr<const MeshTopology> topology() const;

 private:
  mutable std::shared_ptr<const MeshTopology> topology_;
};

/// "(x y)" with 6 significant digits: how messages and summaries name a point.
std::string formatPoint(const Vector2& p);

/// One key per side {a, b} of the mesh, whatever its orientation (for hashing sides).
std::uint64_t sideKey(Index a, Index b);

}  // namespace friction
