// Pieces shared by the FreeFEM and gmsh readers (MeshReader.cpp, FreeFemMeshReader.cpp,
// GmshMeshReader.cpp). Private to friction/mesh (not part of the library's interface).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "friction/mesh/Mesh.hpp"
#include "friction/mesh/TextScanner.hpp"

namespace friction::detail {

/// True if a label, region or count read as long long fits the int the Mesh stores.
inline bool fitsInt(long long v) {
  return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}

/// How many items to reserve for a count read from a file: the count, but no more than
/// the file could hold with lines of at least `minLineBytes` (so that a corrupt header cannot
/// make us allocate gigabytes before the truncation is reported).
inline std::size_t reserveHint(long long announced, const TextScanner& scanner,
                               std::size_t minLineBytes) {
  const std::size_t cap = scanner.text().size() / minLineBytes + 1;
  return announced < 0 ? 0 : std::min(static_cast<std::size_t>(announced), cap);
}

/// Parse a FreeFEM / gmsh file whose whole text the scanner holds.
Mesh parseFreeFemMesh(TextScanner& scanner);
Mesh parseGmshMesh(TextScanner& scanner);

/// What is wrong with a triangle, if anything: zero area (relative to its longest edge
/// squared) or clockwise order. Cheap; called for every triangle.
enum class TriangleDefect { none, zeroArea, clockwise };
TriangleDefect triangleDefect(const std::vector<Point>& points,
                              const std::array<Index, 3>& triangle);

/// Throw the InputError for a defective triangle at the scanner's current line. `kind` and
/// `number` name it as the file does ("triangle 7", "element 31"); `fileVertices` are its
/// vertex numbers as written in the file; `clockwiseFix` tells the user how to repair a
/// clockwise triangle with the tool that wrote the file.
[[noreturn]] void failTriangle(const TextScanner& scanner, TriangleDefect defect,
                               const std::vector<Point>& points,
                               const std::array<Index, 3>& triangle, const char* kind,
                               long long number, const std::array<long long, 3>& fileVertices,
                               const std::string& clockwiseFix);

/// Reject an edge whose two ends are the same vertex, at the scanner's current line.
void checkEdge(const TextScanner& scanner, const std::array<Index, 2>& edge, const char* kind,
               long long number, const std::array<long long, 2>& fileVertices);

/// Where each item of a parsed mesh came from, for the whole-mesh checks of finishMesh.
struct FileNumbering {
  std::vector<long long>
      point;                   ///< per vertex, its number in the file (FreeFEM position, gmsh tag)
  std::vector<int> cellLine;   ///< per cell, its line
  std::vector<int> facetLine;  ///< per labelled facet, its line
};

/// The checks that need the whole mesh, each an InputError at the line of the offending
/// item: a triangle listed twice, a side shared by more than two triangles, a labelled edge
/// that is no side of any triangle, an edge listed twice with the same label. Then drops the
/// vertices no triangle uses (renumbering triangles and edges) and lists them in
/// mesh.droppedPoints.
void finishMesh(const TextScanner& scanner, Mesh& mesh, const FileNumbering& numbering);

/// Reject a NaN or Inf coordinate at the scanner's current line.
void checkFinite(const TextScanner& scanner, double x, double y, const char* kind,
                 long long number);

}  // namespace friction::detail
