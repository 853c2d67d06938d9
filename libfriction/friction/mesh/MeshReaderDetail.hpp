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

/// Parse a FreeFEM / gmsh / Medit file whose whole text the scanner holds.
Mesh parseFreeFemMesh(TextScanner& scanner);
Mesh parseGmshMesh(TextScanner& scanner);
Mesh parseMeditMesh(TextScanner& scanner);

/// What is wrong with a triangle, if anything: zero area (relative to its longest edge
/// squared) or clockwise order. Cheap; called for every triangle.
enum class TriangleDefect { none, zeroArea, clockwise };
TriangleDefect triangleDefect(const std::vector<Point>& points,
                              const std::array<Index, 3>& triangle);

/// Throw the InputError for a defective triangle at `line`. `kind` and
/// `number` name it as the file does ("triangle 7", "element 31"); `fileVertices` are its
/// vertex numbers as written in the file; `clockwiseFix` tells the user how to repair a
/// clockwise triangle with the tool that wrote the file.
[[noreturn]] void failTriangle(const TextScanner& scanner, int line, TriangleDefect defect,
                               const std::vector<Point>& points,
                               const std::array<Index, 3>& triangle, const char* kind,
                               long long number, const std::array<long long, 3>& fileVertices,
                               const std::string& clockwiseFix);

/// What is wrong with a tetrahedron, if anything: zero volume (relative to its longest edge
/// cubed) or negative volume (vertex 3 not on the side of face 0 1 2 that its right-hand
/// normal (x1 − x0) × (x2 − x0) points to).
enum class TetrahedronDefect { none, zeroVolume, negative };
TetrahedronDefect tetrahedronDefect(const std::vector<Point>& points,
                                    const std::array<Index, 4>& tetrahedron);

/// Throw the InputError for a defective tetrahedron at `line`; arguments as failTriangle.
[[noreturn]] void failTetrahedron(const TextScanner& scanner, int line, TetrahedronDefect defect,
                                  const std::vector<Point>& points,
                                  const std::array<Index, 4>& tetrahedron, const char* kind,
                                  long long number, const std::array<long long, 4>& fileVertices,
                                  const std::string& negativeFix);

/// Reject a labelled triangle (3D) with a repeated vertex, at `line`.
void checkTriangleFacet(const TextScanner& scanner, int line, const std::array<Index, 3>& facet,
                        const char* kind, long long number,
                        const std::array<long long, 3>& fileVertices);

/// Reject an edge whose two ends are the same vertex, at `line`.
void checkEdge(const TextScanner& scanner, int line, const std::array<Index, 2>& edge,
               const char* kind, long long number, const std::array<long long, 2>& fileVertices);

/// Where each item of a parsed mesh came from, for the whole-mesh checks of finishMesh.
struct FileNumbering {
  std::vector<long long>
      point;                   ///< per vertex, its number in the file (FreeFEM position, gmsh tag)
  std::vector<int> cellLine;   ///< per cell, its line
  std::vector<int> facetLine;  ///< per labelled facet, its line
};

/// The checks that need the whole mesh, each an InputError at the line of the offending
/// item: a cell listed twice, a facet shared by more than two cells, a labelled facet that is
/// no facet of any cell, a facet listed twice with the same label. Then drops the vertices no
/// cell uses (renumbering cells and facets) and lists them in mesh.droppedPoints.
void finishMesh(const TextScanner& scanner, Mesh& mesh, const FileNumbering& numbering);

/// The last step of finishMesh: drop the vertices no cell uses, renumber, and list them in
/// mesh.droppedPoints.
void dropUnusedPoints(Mesh& mesh, const FileNumbering& numbering);

/// The largest |coordinate| read. A tetrahedron's volume is a sum of six products of three
/// coordinate differences, each up to twice the largest |coordinate|: 48 * (1e100)^3 is far
/// below the largest double (1.8e308), so no area, volume or edge length squared overflows.
constexpr double kMaxCoordinate = 1e100;

/// Reject a NaN or Inf coordinate, or one above kMaxCoordinate in size, at the scanner's
/// current line, naming the item (`kind` `number`: "vertex 3", "node 20").
void checkCoordinates(const TextScanner& scanner, double x, double y, const char* kind,
                      long long number);
void checkCoordinates(const TextScanner& scanner, double x, double y, double z, const char* kind,
                      long long number);

/// The next field as a label or region (the Mesh stores an int): false if there is none or it
/// is not a whole number (the caller reports the syntax); a whole number outside the range of
/// an int is an InputError at the current line: "<item> <number>: <what> 2147483648 is out of
/// range ...".
bool readLabel(const TextScanner& scanner, LineFields& fields, int& value, const char* what,
               const char* item, long long number);

}  // namespace friction::detail
