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
#pragma once

#include <string>

#include "friction/fracture/SplitMesh.hpp"

namespace friction {

/// Write atomically (temporary file + rename). precision: significant digits of coordinates.
void writeSplitMesh(const SplitMesh& split, const std::string& path, int precision = 17);

/// Read and validate (counts, index ranges, counter-clockwise triangles, plus/minus copies
/// that are copies of the same node). Errors name file:line and the key.
SplitMesh readSplitMesh(const std::string& path);

}  // namespace friction
