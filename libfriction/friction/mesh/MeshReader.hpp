// Readers for FreeFEM 2D .msh and gmsh ASCII .msh (2.2 and 4.1). The format is told from
// the content ($MeshFormat opens a gmsh file), not from the file name.
//
// Every error is an InputError naming file:line and what was expected: truncated files,
// counts that disagree, indices out of range, NaN/Inf coordinates, zero-area or clockwise
// triangles, triangles listed twice, sides of more than two triangles, labelled edges that
// are no side of a triangle or are listed twice with one label, unsupported element types,
// non-planar (z != 0) gmsh nodes, binary gmsh files. Vertices that no triangle uses are
// dropped (the rest renumbered) and listed in Mesh::droppedPoints.
#pragma once

#include <string>

#include "friction/mesh/Mesh.hpp"

namespace friction {

/// Read a mesh, telling FreeFEM from gmsh by content.
Mesh readMesh(const std::string& path);

/// FreeFEM 2D .msh: "nv nt nbe"; nv lines "x y label"; nt lines "v1 v2 v3 region" (1-based);
/// nbe lines "v1 v2 label".
Mesh readFreeFemMesh(const std::string& path);

/// gmsh ASCII .msh, version 2.2 or 4.1: nodes, 2-node lines (type 1), 3-node triangles
/// (type 2), points (type 15, ignored), physical groups and their names.
Mesh readGmshMesh(const std::string& path);

}  // namespace friction
