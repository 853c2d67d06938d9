// Splitting mesh nodes along fractures (docs/method.md): every node on a fracture gets one copy
// per group of its cells (triangles in 2D, tetrahedra in 3D) that stay connected once the mesh
// is cut along the fracture facets (edges in 2D, triangles in 3D). A tip inside the body (a
// point in 2D, the tip line of a fault surface in 3D) therefore stays single (the jump
// vanishes there); a node where a fracture reaches the outer boundary is duplicated. Signs:
// SignConventions.hpp.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/core/Types.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

/// Which patch of the mesh is a fracture, and where the user said so (for messages).
struct FractureSpec {
  std::string name;
  int label = 0;
  SourceLocation where;
};

/// How a fracture node relates to the rest of the mesh.
enum class FractureNodeKind {
  interior,  ///< inside the fracture (2D: between two fracture edges): duplicated
  boundary,  ///< on the fracture's edge (2D: an end) where it meets the outer boundary:
             ///< duplicated
  tip,       ///< on the fracture's edge inside the body (2D: an end; 3D: the tip line):
             ///< single (plus == minus)
  // 2D junctions (docs/method.md §4, "Junctions"): a node where several fractures meet has
  // one copy per sector between consecutive fracture edges; plus and minus are the copies of
  // the sectors at the fracture's edge towards its next node (its previous one at its last
  // node). 3D intersection nodes (fault surfaces that meet along curves) likewise: one copy
  // per sector of the tetrahedra around the node, plus and minus those on either side of the
  // fracture's first triangle through the node; the kinds below apply per node.
  crossing,  ///< the fracture passes through a junction: its jump there is free, and the
             ///< sectors on each side of it move with its Ω⁺ (Ω⁻) copy
  abutting,  ///< the fracture ends on a junction where three or more fracture edges meet:
             ///< its jump there is held at zero (the fractures that pass through the node
             ///< carry the jumps; with none, every jump there is held)
  joined     ///< the fracture ends where exactly one other fracture ends, inside the body:
             ///< the two act as one curve there (one jump, the first-listed fracture's law)
};
const char* toString(FractureNodeKind kind);

/// One fracture of the split mesh; every per-node array has one entry per fracture node. Node
/// order: 2D, along the curve (arclength order, SignConventions.hpp); 3D, by ascending node
/// number of the unsplit mesh. The Ω⁺ copy keeps the unsplit node number (plus == node), except
/// at 2D junctions, where one sector keeps it (FractureNodeKind).
struct FractureGeometry {
  std::string name;
  int label = 0;
  std::vector<Index> node;       ///< node number in the unsplit mesh
  std::vector<Index> plus;       ///< copy used by cells in Ω⁺ (split-mesh node number)
  std::vector<Index> minus;      ///< copy used by cells in Ω⁻ (== plus at tips)
  std::vector<Point> normal;     ///< unit n_Γ, from Ω⁺ to Ω⁻ (z = 0 in 2D)
  std::vector<Vector2> tangent;  ///< 2D: unit t_Γ, along growing arclength; 3D: empty
  /// 2D: s, from 0 at the first node [length units of the mesh]; 3D: empty (no curve to
  /// walk).
  std::vector<double> arclength;
  std::vector<FractureNodeKind> kind;
  /// 3D: the fracture's triangles, by unsplit node numbers (== their Ω⁺ copies), ordered so
  /// that the right-hand normal (b − a) × (c − a) is n_Γ. 2D: empty (the edges join
  /// consecutive nodes).
  std::vector<std::array<Index, 3>> triangles;

  Index numNodes() const { return static_cast<Index>(node.size()); }
  /// 2D: the length of the curve; 3D: 0 (see area() and tipLineLength()).
  double length() const { return arclength.empty() ? 0.0 : arclength.back(); }
  Index numTips() const;
  Index numDuplicated() const;
  Index numOfKind(FractureNodeKind kind) const;
  /// 3D: the area of the triangles (points: the mesh's or the split mesh's, whose first
  /// points are the unsplit ones). 0 in 2D.
  double area(const std::vector<Point>& points) const;
  /// 3D: the length of the tip line: the edges of the surface's own boundary (edges of one of
  /// its triangles) that are not edges of a boundary face of the unsplit mesh. 0 in 2D.
  double tipLineLength(const Mesh& unsplit) const;
  /// 3D: triangles whose three vertices are all tips (on the tip line). Their two sides keep
  /// the same nodes, so they carry no jump: the fault is one cell wide there and cannot slip
  /// (refine across it). 0 in 2D.
  Index numGluedTriangles() const;
};

/// What a split mesh was made from, so that the solver can refuse one made from another mesh
/// or meshDict than the case has now (constant/splitMesh, key 'madeFrom'). Hashes are
/// FNV-1a 64-bit of the files' bytes (SplitMeshIO.hpp, fileHash); empty in a split mesh
/// written before the record existed.
struct SplitMeshRecord {
  std::string mesh;          ///< the mesh file, relative to the case folder (meshDict's 'mesh')
  std::string meshHash;      ///< hash of the mesh file
  std::string meshDictHash;  ///< hash of system/meshDict
  bool empty() const { return meshHash.empty() && meshDictHash.empty(); }
};

/// A mesh whose fracture nodes are split. mesh.points holds the unsplit points first (the Ω⁺
/// copy keeps the original number) and the Ω⁻ copies after them (by fracture, then in the
/// fracture's node order); mesh.facetVertices holds the boundary patches only (fracture facets
/// live in `fractures`), renumbered to the copies their cell uses.
struct SplitMesh {
  Mesh mesh;
  std::vector<Index> origin;  ///< per split-mesh node, its node number in the unsplit mesh
  std::vector<FractureGeometry> fractures;
  SplitMeshRecord madeFrom;  ///< set by splitFractureNodes, not by splitFractures

  /// Number of nodes of the unsplit mesh.
  Index numOriginalPoints() const;
};

/// 3D: a curve where fault surfaces meet: a connected set of edges of fault triangles, each an
/// edge of the same fractures in the same roles. README "Intersections (3D)".
struct IntersectionCurve {
  std::vector<std::size_t> passing;  ///< fractures with two triangles at each of its edges
  std::vector<std::size_t> ending;   ///< fractures with one (their own edge runs along it)
  bool onOuterBoundary = false;      ///< its edges lie on the outer boundary of the mesh
  std::vector<Index> nodes;          ///< unsplit node numbers, ascending
  std::vector<Index> ends;           ///< nodes on one of its edges only (none: a closed curve)
  double length = 0;                 ///< [length units of the mesh]
  /// crossing (two or more pass), abutting (one passes, the others end on it), joined (none
  /// passes, two end: one surface cut along the curve), ending together (none passes, three or
  /// more end: all held), on the outer boundary (its edges lie there).
  std::string kind() const;
};

/// 3D: the curves where the split mesh's fault surfaces meet, ordered by their smallest node;
/// unsplit: the mesh that was split (for the outer boundary). Empty in 2D.
std::vector<IntersectionCurve> intersectionCurves(const SplitMesh& split, const Mesh& unsplit);

/// Split the mesh along the given fractures. Refuses, with an InputError naming the mesh file
/// (and the FractureSpec's location where it helps):
/// * both dimensions: a fracture with no facets; a cell whose vertices all lie on one
///   fracture; a fracture facet that is not a facet of two cells (already split, or on the
///   outer boundary);
/// * 2D: a fracture with more than two of its own edges at a node (branches need labels of
///   their own); a fracture made of several disjoint curves or of a closed curve; a junction
///   whose edges do not cut the triangles around it into one sector per edge (inside the
///   body) or one more (on its boundary, where every fracture must end there). Fractures
///   that meet are split at the junction (FractureNodeKind crossing, abutting, joined);
/// * 3D: a non-manifold surface (an edge of
///   more than two of its triangles); a non-orientable one; a closed one; one made of several
///   pieces (not joined through edges); an intersection node where a fracture passing through
///   it does not separate the tetrahedra on either side of each of its triangles there.
///   Surfaces that meet are split at their intersection nodes (FractureNodeKind crossing,
///   abutting, joined, and boundary where one passes through on the outer boundary); a line
///   where two end together (joined) may reach the outer boundary.
SplitMesh splitFractures(const Mesh& mesh, const std::vector<FractureSpec>& fractures);

/// The fractures other than f that have unsplit node `node`, quoted and listed in their
/// order: "'a'", "'a' and 'b'", "'a', 'b' and 'c'"; empty if none.
std::string othersAt(const SplitMesh& split, std::size_t f, Index node);

/// 2D: one line per junction node of fracture f (kinds crossing, abutting, joined) saying
/// where it is, what the fracture does there and which fractures it meets, e.g.
/// "junction at (0 0): passes through; meets 'branch'". For the fracture tables' comments.
std::vector<std::string> junctionNotes(const SplitMesh& split, std::size_t f);

/// "'a'", "'a' and 'b'", "'a', 'b' and 'c'": the fractures of `list` by name, for messages.
std::string quotedFractureNames(const SplitMesh& split, const std::vector<std::size_t>& list);

/// 3D: one line per intersection curve of fracture f (intersectionCurves) saying its kind, the
/// other fractures on it, where it runs and what f does there, e.g. "intersection (abutting)
/// with 'main', 5 nodes from (0.75 0.2 0.5) to (0.75 0.8 0.5), length 0.6: ends on it, its
/// jump held at 3 nodes (state junction)"; then one line per node where f touches another
/// fracture without a common edge. For the fracture tables' comments; `curves`: those of the
/// split mesh.
std::vector<std::string> intersectionNotes(const SplitMesh& split,
                                           const std::vector<IntersectionCurve>& curves,
                                           std::size_t f);

/// 3D: per node of fracture f (its order), what it does where fault surfaces meet, for the
/// .vtp's point array `intersection`: 0 not on another fracture, 1 passes through (crossing,
/// or boundary there), 2 ends on another (abutting: held, state junction), 3 ends together
/// with another (joined), 4 its tip line touches another (tip).
std::vector<int> intersectionCodes(const SplitMesh& split, std::size_t f);

}  // namespace friction
