// Readers for FreeFEM 2D .msh, Medit .mesh (FreeFEM's savemesh of a 3D mesh3) and gmsh
// ASCII .msh (2.2 and 4.1, 2D or 3D). The format is told from the content ($MeshFormat opens
// a gmsh file, MeshVersionFormatted a Medit file), not from the file name. A mesh is 3D when
// it has tetrahedra (then its labelled facets are triangles), else 2D.
//
// Every error is an InputError naming file:line and what was expected: a path that is no
// regular file (a FIFO, a device, a folder: InputFile.hpp), truncated files, counts that
// disagree, indices out of range, labels and regions out of the range of an int, NaN/Inf
// coordinates or coordinates so large that areas and volumes overflow, zero-area or clockwise
// triangles, zero-volume or negative tetrahedra, cells listed twice, facets of more than two
// cells, labelled facets that are no facet of a cell or are listed twice with one label,
// unsupported element types, non-planar (z != 0) nodes of a 2D gmsh mesh, binary files.
// Vertices that no cell uses are dropped (the rest renumbered) and listed in
// Mesh::droppedPoints.
#pragma once

#include <cstdint>
#include <string>

#include "friction/mesh/Mesh.hpp"

namespace friction {

/// The largest mesh file read (its text is held whole while it is parsed).
constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t{4} << 30;

/// Read a mesh, telling FreeFEM, Medit and gmsh apart by content.
Mesh readMesh(const std::string& path);

/// Medit .mesh in 3D as FreeFEM's savemesh writes it: MeshVersionFormatted, Dimension 3,
/// Vertices ("x y z label"), Tetrahedra ("v1 v2 v3 v4 region"), Triangles ("v1 v2 v3 label"),
/// End; 1-based. Other sections (Edges, Corners, ...) are skipped.
Mesh readMeditMesh(const std::string& path);

/// FreeFEM 2D .msh: "nv nt nbe"; nv lines "x y label"; nt lines "v1 v2 v3 region" (1-based);
/// nbe lines "v1 v2 label".
Mesh readFreeFemMesh(const std::string& path);

/// gmsh ASCII .msh, version 2.2 or 4.1: nodes, 2-node lines (type 1), 3-node triangles
/// (type 2), 4-node tetrahedra (type 4), points (type 15, ignored), physical groups and their
/// names. With tetrahedra the mesh is 3D: triangles are its labelled facets (physical
/// surfaces) and lines are ignored.
Mesh readGmshMesh(const std::string& path);

}  // namespace friction
