// The split mesh on disk: constant/splitMesh, an OpenFOAM-syntax dictionary (so that
// foamDictionary and a text editor can read it) written by splitFractureNodes and read by the
// solver. Layout (all node numbers 0-based, into 'points'):
//
//   source     "constant/mesh/square.msh";  format "FreeFEM .msh";
//   points     N((x y) ...);       origin N(...);   // node of the unsplit mesh per point
//   triangles  N((a b c) ...);     regions N(...);
//   patches    { <name> { label L; edges N((a b) ...); } ... }
//   fractures  { <name> { label L; node N(...); plus N(...); minus N(...); kind N(words);
//                         arclength N(...); normal N((nx ny) ...); tangent N(...); } ... }
//
// 3D (tetrahedra): 'dimension 3;' after 'format' (absent in 2D, which reads as 2), points
// (x y z), 'tetrahedra N((a b c d) ...)' instead of 'triangles', patches with
// 'triangles N((a b c) ...)' instead of 'edges', and per fracture node/plus/minus/kind,
// 'normal N((nx ny nz) ...)' and 'triangles N((a b c) ...)' (by plus copies, oriented so that
// their right-hand normal is n_Γ) instead of arclength/normal/tangent. Fracture nodes in
// ascending node order.
//   madeFrom   { mesh "constant/mesh/square.msh"; meshHash "fnv1a64:…";
//                meshDictHash "fnv1a64:…"; }    // what it was split from (SplitMeshRecord)
#pragma once

#include <string>

#include "friction/fracture/SplitMesh.hpp"

namespace friction {

/// Write atomically (temporary file + rename). precision: significant digits of coordinates.
void writeSplitMesh(const SplitMesh& split, const std::string& path, int precision = 17);

/// Read and validate what the solver relies on: counts, index ranges, counter-clockwise
/// triangles (3D: tetrahedra of positive volume) each listed once, every point used by a cell,
/// the unsplit points first with their copies after them at the same place, patch edges
/// (3D: triangles) that are facets of the mesh, consecutive fracture nodes joined by triangle
/// sides on both copies (3D: fracture triangles that are faces on both copies), plus and
/// minus copies of the same node. Errors name file:line and the key. A missing 'madeFrom'
/// (older files) is read as an empty record: checkSplitMeshCurrent refuses it.
SplitMesh readSplitMesh(const std::string& path);

/// "fnv1a64:" and the FNV-1a 64-bit hash of the file's bytes as 16 hex digits. InputError if
/// the file cannot be read.
std::string fileHash(const std::string& path);

/// Refuse (InputError naming caseDir/constant/splitMesh, what changed, and the command that
/// splits again) a split mesh that was not made from the case's present system/meshDict and
/// mesh file, or that does not record what it was made from.
void checkSplitMeshCurrent(const std::string& caseDir, const SplitMesh& split);

}  // namespace friction
