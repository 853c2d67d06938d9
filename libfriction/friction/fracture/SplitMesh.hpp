// Splitting mesh nodes along fractures (docs/method.md): every node on a fracture gets one copy
// per group of its triangles that stay connected once the mesh is cut along the fracture
// edges. A tip inside the body therefore stays single (the jump vanishes there); a node
// where a fracture reaches the outer boundary is duplicated. Signs: SignConventions.hpp.
#pragma once

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
  interior,  ///< between two fracture edges: duplicated
  boundary,  ///< an end of the fracture on the outer boundary: duplicated
  tip        ///< an end inside the body: single (plus == minus)
};
const char* toString(FractureNodeKind kind);

/// One fracture of the split mesh; every array has one entry per fracture node, in
/// arclength order.
struct FractureGeometry {
  std::string name;
  int label = 0;
  std::vector<Index> node;        ///< node number in the unsplit mesh
  std::vector<Index> plus;        ///< copy used by triangles in Ω⁺ (split-mesh node number)
  std::vector<Index> minus;       ///< copy used by triangles in Ω⁻ (== plus at tips)
  std::vector<Vector2> normal;    ///< unit n_Γ, from Ω⁺ to Ω⁻
  std::vector<Vector2> tangent;   ///< unit t_Γ, along growing arclength
  std::vector<double> arclength;  ///< s, from 0 at the first node [length units of the mesh]
  std::vector<FractureNodeKind> kind;

  Index numNodes() const { return static_cast<Index>(node.size()); }
  double length() const { return arclength.empty() ? 0.0 : arclength.back(); }
  Index numTips() const;
  Index numDuplicated() const;
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
/// copy keeps the original number) and the Ω⁻ copies after them; mesh.facetVertices holds the
/// boundary patches only (fracture edges live in `fractures`), renumbered to the copies their
/// triangle uses.
struct SplitMesh {
  Mesh mesh;
  std::vector<Index> origin;  ///< per split-mesh node, its node number in the unsplit mesh
  std::vector<FractureGeometry> fractures;
  SplitMeshRecord madeFrom;  ///< set by splitFractureNodes, not by splitFractures

  /// Number of nodes of the unsplit mesh.
  Index numOriginalPoints() const;
};

/// Split the mesh along the given fractures. Refuses, with an InputError naming the mesh file
/// (and the FractureSpec's location where it helps): a fracture with no edges; branching
/// edges or fractures that meet (junctions are not supported); a fracture made of several
/// disjoint curves or of a closed curve; a triangle whose three vertices all lie on one
/// fracture; a fracture edge that is not a side of two triangles (already split, or on the
/// outer boundary).
SplitMesh splitFractures(const Mesh& mesh, const std::vector<FractureSpec>& fractures);

}  // namespace friction
