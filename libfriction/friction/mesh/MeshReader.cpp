// readMesh and the checks the mesh formats share: loading the file, telling FreeFEM .msh,
// Medit .mesh and gmsh apart by content, rejecting degenerate or wrongly oriented cells and
// collapsed facets, and the whole-mesh checks. The format parsers are in
// FreeFemMeshReader.cpp, MeditMeshReader.cpp and GmshMeshReader.cpp.
#include "friction/mesh/MeshReader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>

#include <Eigen/Geometry>

#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/mesh/MeshReaderDetail.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

namespace {

// The whole file in one string: one read, no per-line I/O (a 500k-node mesh is ~50 MB). Only a
// regular file: a FIFO or a device would block or never end (InputFile.hpp).
std::string loadFile(const std::string& path) {
  InputFileRole role;
  role.what = "the mesh file: FreeFEM .msh, Medit .mesh or gmsh .msh";
  role.maxBytes = kMaxMeshFileBytes;
  return readInputFile(path, role);
}

// Whether the first word of the file (after a byte-order mark and white space) is `tag`.
bool startsWith(const std::string& text, const std::string& tag) {
  std::size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (text.compare(i, tag.size(), tag) != 0) return false;
  const std::size_t after = i + tag.size();
  return after == text.size() || std::isspace(static_cast<unsigned char>(text[after]));
}

bool isGmsh(const std::string& text) { return startsWith(text, "$MeshFormat"); }
bool isMedit(const std::string& text) { return startsWith(text, "MeshVersionFormatted"); }

// NUL bytes do not occur in text meshes; catching them here gives a clearer message than
// "expected nv nt nbe, found <garbage>".
void rejectBinary(const std::string& path, const std::string& text) {
  const std::size_t head = std::min<std::size_t>(text.size(), 4096);
  const auto* nul = static_cast<const char*>(std::memchr(text.data(), '\0', head));
  if (!nul) return;
  const int line = 1 + static_cast<int>(std::count(text.data(), nul, '\n'));
  throw InputError(SourceLocation{path, line},
                   "this is a binary file: expected a text mesh (FreeFEM .msh, or gmsh .msh "
                   "written as ASCII: gmsh -format msh41 without -bin, with -3 for a volume mesh "
                   "or -2 for a 2D one)");
}

}  // namespace

Mesh readMesh(const std::string& path) {
  std::string text = loadFile(path);
  const bool gmsh = isGmsh(text), medit = !gmsh && isMedit(text);
  if (!gmsh) rejectBinary(path, text);
  TextScanner scanner(path, std::move(text));
  if (gmsh) return detail::parseGmshMesh(scanner);
  return medit ? detail::parseMeditMesh(scanner) : detail::parseFreeFemMesh(scanner);
}

Mesh readMeditMesh(const std::string& path) {
  std::string text = loadFile(path);
  rejectBinary(path, text);
  TextScanner scanner(path, std::move(text));
  return detail::parseMeditMesh(scanner);
}

Mesh readFreeFemMesh(const std::string& path) {
  std::string text = loadFile(path);
  rejectBinary(path, text);
  TextScanner scanner(path, std::move(text));
  return detail::parseFreeFemMesh(scanner);
}

Mesh readGmshMesh(const std::string& path) {
  TextScanner scanner(path, loadFile(path));
  return detail::parseGmshMesh(scanner);
}

namespace detail {

TriangleDefect triangleDefect(const std::vector<Point>& points, const std::array<Index, 3>& t) {
  const Vector2 ab = points[t[1]].head<2>() - points[t[0]].head<2>();
  const Vector2 bc = points[t[2]].head<2>() - points[t[1]].head<2>();
  const Vector2 ac = points[t[2]].head<2>() - points[t[0]].head<2>();
  const double area = 0.5 * (ab.x() * ac.y() - ab.y() * ac.x());
  const double longest2 = std::max({ab.squaredNorm(), bc.squaredNorm(), ac.squaredNorm()});
  // Relative to the longest edge so that the test is independent of the mesh's units; 1e-12
  // is far below any usable triangle's shape ratio and far above round-off (~1e-16).
  // Written as !(… > …) so that an area that is not a number (coordinates whose differences
  // overflow double) is refused too.
  if (!(std::abs(area) > 1e-12 * longest2)) return TriangleDefect::zeroArea;
  return area < 0 ? TriangleDefect::clockwise : TriangleDefect::none;
}

void failTriangle(const TextScanner& scanner, int line, TriangleDefect defect,
                  const std::vector<Point>& points, const std::array<Index, 3>& t, const char* kind,
                  long long number, const std::array<long long, 3>& fileVertices,
                  const std::string& clockwiseFix) {
  const Vector2 a = points[t[0]].head<2>(), b = points[t[1]].head<2>(), c = points[t[2]].head<2>();
  const double area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  std::ostringstream s;
  s.precision(6);
  s << kind << " " << number << " (vertices " << fileVertices[0] << " " << fileVertices[1] << " "
    << fileVertices[2] << " at (" << a.x() << ", " << a.y() << "), (" << b.x() << ", " << b.y()
    << "), (" << c.x() << ", " << c.y() << ")) ";
  if (defect == TriangleDefect::zeroArea && !std::isfinite(area))
    s << "has an area that is not a finite number (" << area
      << "): the differences of its coordinates overflow double; rescale the mesh";
  else if (defect == TriangleDefect::zeroArea)
    s << "has zero area (" << area
      << "): expected a triangle whose area is more than 1e-12 times its longest edge squared; "
         "remesh or remove it";
  else
    s << "is clockwise (signed area " << area << "): expected counter-clockwise triangles; "
      << clockwiseFix;
  scanner.failAt(line, s.str());
}

TetrahedronDefect tetrahedronDefect(const std::vector<Point>& points,
                                    const std::array<Index, 4>& t) {
  const Point& x0 = points[t[0]];
  const Point a = points[t[1]] - x0, b = points[t[2]] - x0, c = points[t[3]] - x0;
  const double sixVolume = a.cross(b).dot(c);
  double longest2 = std::max({a.squaredNorm(), b.squaredNorm(), c.squaredNorm()});
  for (int i = 1; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest2 = std::max(longest2, (points[t[j]] - points[t[i]]).squaredNorm());
  // As for triangles: relative to the longest edge cubed, far below any usable shape. Written
  // so that a volume that overflows (NaN) is refused too.
  if (!(std::abs(sixVolume) > 1e-12 * longest2 * std::sqrt(longest2)))
    return TetrahedronDefect::zeroVolume;
  return sixVolume < 0 ? TetrahedronDefect::negative : TetrahedronDefect::none;
}

void failTetrahedron(const TextScanner& scanner, int line, TetrahedronDefect defect,
                     const std::vector<Point>& points, const std::array<Index, 4>& t,
                     const char* kind, long long number,
                     const std::array<long long, 4>& fileVertices, const std::string& negativeFix) {
  const Point& x0 = points[t[0]];
  const double volume = (points[t[1]] - x0).cross(points[t[2]] - x0).dot(points[t[3]] - x0) / 6.0;
  std::ostringstream s;
  s.precision(6);
  s << kind << " " << number << " (vertices " << fileVertices[0] << " " << fileVertices[1] << " "
    << fileVertices[2] << " " << fileVertices[3] << " at ";
  for (int k = 0; k < 4; ++k) s << (k ? ", " : "") << formatPoint(points[t[k]], 3);
  s << ") ";
  if (defect == TetrahedronDefect::zeroVolume)
    s << "has zero volume (" << volume
      << "): expected a tetrahedron whose volume is more than 1e-12 times its longest edge "
         "cubed; remesh or remove it";
  else
    s << "has negative volume (signed volume " << volume
      << "): expected tetrahedra of positive volume (the fourth vertex on the side of the first "
         "three where (x1 - x0) x (x2 - x0) points); "
      << negativeFix;
  scanner.failAt(line, s.str());
}

void checkTriangleFacet(const TextScanner& scanner, int line, const std::array<Index, 3>& f,
                        const char* kind, long long number,
                        const std::array<long long, 3>& fileVertices) {
  if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2]) return;
  scanner.failAt(line, std::string(kind) + " " + std::to_string(number) +
                           " is a triangle with a repeated vertex (" +
                           std::to_string(fileVertices[0]) + " " + std::to_string(fileVertices[1]) +
                           " " + std::to_string(fileVertices[2]) +
                           "): expected three different vertices");
}

void checkEdge(const TextScanner& scanner, int line, const std::array<Index, 2>& edge,
               const char* kind, long long number, const std::array<long long, 2>& fileVertices) {
  if (edge[0] != edge[1]) return;
  scanner.failAt(line, std::string(kind) + " " + std::to_string(number) + " joins vertex " +
                           std::to_string(fileVertices[0]) + " to itself (" +
                           std::to_string(fileVertices[0]) + " " + std::to_string(fileVertices[1]) +
                           "): expected an edge between two different vertices");
}

namespace {

// finishMesh's checks for tetrahedra and labelled triangles, on the topology of the cells
// (the vertex numbers are in range: the parsers checked them).
void checkMesh3(const TextScanner& scanner, const Mesh& mesh, const FileNumbering& numbering) {
  const auto vertexText = [&](Index v) {
    return std::to_string(numbering.point[v]) + " " + formatPoint(mesh.points[v], 3);
  };
  const MeshTopology topology(3, mesh.numPoints(), mesh.cellVertices, mesh.source);
  const auto sorted = [&](Index c) {
    std::array<Index, 4> k{mesh.cellVertex(c, 0), mesh.cellVertex(c, 1), mesh.cellVertex(c, 2),
                           mesh.cellVertex(c, 3)};
    std::sort(k.begin(), k.end());
    return k;
  };
  // A tetrahedron listed twice shares every face with its copy: look for it first (it would
  // otherwise be reported as a face of three tetrahedra).
  for (Index f = 0; f < topology.numFacets(); ++f) {
    const int n = topology.numCellsOf(f);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const Index a = topology.cellOf(f, i).cell, b = topology.cellOf(f, j).cell;
        if (sorted(a) != sorted(b)) continue;
        const auto v = sorted(a);
        scanner.failAt(numbering.cellLine[b],
                       "the tetrahedron with vertices " + std::to_string(numbering.point[v[0]]) +
                           " " + std::to_string(numbering.point[v[1]]) + " " +
                           std::to_string(numbering.point[v[2]]) + " " +
                           std::to_string(numbering.point[v[3]]) + " is listed twice (lines " +
                           std::to_string(numbering.cellLine[a]) + " and " +
                           std::to_string(numbering.cellLine[b]) +
                           "): expected each tetrahedron once");
      }
  }
  if (!topology.overSharedFacets().empty()) {
    const Index f = topology.overSharedFacets().front();
    const Index third = topology.cellOf(f, 2).cell;
    scanner.failAt(numbering.cellLine[third],
                   "the face with vertices " + vertexText(topology.facetVertex(f, 0)) + ", " +
                       vertexText(topology.facetVertex(f, 1)) + " and " +
                       vertexText(topology.facetVertex(f, 2)) +
                       " is a face of a third tetrahedron here (the others are at lines " +
                       std::to_string(numbering.cellLine[topology.cellOf(f, 0).cell]) + " and " +
                       std::to_string(numbering.cellLine[topology.cellOf(f, 1).cell]) +
                       "): expected a 3D tetrahedral mesh, where a face bounds at most two "
                       "tetrahedra (overlapping or folded tetrahedra?)");
  }
  // Labelled triangles: faces of the mesh, each label once per face.
  std::vector<std::pair<std::pair<Index, int>, Index>> keys;
  keys.reserve(mesh.facetLabel.size());
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1), c = mesh.facetVertex(e, 2);
    const Index f = topology.findFacet({a, b, c});
    if (f < 0)
      scanner.failAt(numbering.facetLine[e],
                     "the triangle with vertices " + vertexText(a) + ", " + vertexText(b) +
                         " and " + vertexText(c) + " (label " + std::to_string(mesh.facetLabel[e]) +
                         ") is not a face of any tetrahedron: expected labelled triangles on the "
                         "mesh (the boundary, or a surface embedded in the volume, e.g. gmsh's "
                         "Surface{s} In Volume{v})");
    keys.push_back({{f, mesh.facetLabel[e]}, e});
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) {
      const Index e = keys[i].second;
      const int first = numbering.facetLine[keys[i - 1].second], second = numbering.facetLine[e];
      scanner.failAt(
          std::max(first, second),
          "the triangle with vertices " + vertexText(mesh.facetVertex(e, 0)) + ", " +
              vertexText(mesh.facetVertex(e, 1)) + " and " + vertexText(mesh.facetVertex(e, 2)) +
              " is listed twice with label " + std::to_string(mesh.facetLabel[e]) + " (lines " +
              std::to_string(std::min(first, second)) + " and " +
              std::to_string(std::max(first, second)) + "): expected each triangle once per label");
    }
}

}  // namespace

void finishMesh(const TextScanner& scanner, Mesh& mesh, const FileNumbering& numbering) {
  const auto vertexText = [&](Index v) {
    return std::to_string(numbering.point[v]) + " " + formatPoint(mesh.points[v], mesh.dim);
  };
  if (mesh.dim == 3) {
    checkMesh3(scanner, mesh, numbering);
    dropUnusedPoints(mesh, numbering);
    return;
  }

  // Vertex -> its triangles (compressed rows): the side checks below walk one vertex's fan,
  // a few triangles, with no sorting or hashing of all sides.
  std::vector<Index> fanStart(mesh.points.size() + 1, 0);
  for (Index v : mesh.cellVertices) ++fanStart[v + 1];
  for (std::size_t v = 0; v < mesh.points.size(); ++v) fanStart[v + 1] += fanStart[v];
  std::vector<Index> fan(fanStart.back());
  {
    std::vector<Index> next(fanStart.begin(), fanStart.end() - 1);
    for (Index t = 0; t < mesh.numCells(); ++t)
      for (Index v : mesh.cell(t)) fan[next[v]++] = t;  // ascending t within each fan
  }
  const auto hasVertex = [&](Index t, Index v) {
    const auto tri = mesh.cell(t);
    return tri[0] == v || tri[1] == v || tri[2] == v;
  };
  const auto sortedVertices = [&](Index t) {
    std::array<Index, 3> k{mesh.cellVertex(t, 0), mesh.cellVertex(t, 1), mesh.cellVertex(t, 2)};
    std::sort(k.begin(), k.end());
    return k;
  };

  // Per side, the triangles that have it, in file order. A triangle listed twice doubles its
  // stiffness and hides as a valid mesh (each of its sides then has two triangles, as inside
  // the body); it shares every side with its copy, so the side walk finds it.
  for (Index t = 0; t < mesh.numCells(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.cellVertex(t, k), b = mesh.cellVertex(t, (k + 1) % 3);
      Index with[3];
      int count = 0;
      for (Index i = fanStart[a]; i < fanStart[a + 1] && count < 3; ++i)
        if (hasVertex(fan[i], b)) with[count++] = fan[i];
      if (count >= 2 && with[1] == t && sortedVertices(with[0]) == sortedVertices(t)) {
        const auto v = sortedVertices(t);
        scanner.failAt(numbering.cellLine[t],
                       "the triangle with vertices " + std::to_string(numbering.point[v[0]]) + " " +
                           std::to_string(numbering.point[v[1]]) + " " +
                           std::to_string(numbering.point[v[2]]) + " is listed twice (lines " +
                           std::to_string(numbering.cellLine[with[0]]) + " and " +
                           std::to_string(numbering.cellLine[t]) +
                           "): expected each triangle once");
      }
      if (count == 3 && with[2] == t)
        scanner.failAt(numbering.cellLine[t],
                       "the side from vertex " + vertexText(a) + " to vertex " + vertexText(b) +
                           " is a side of a third triangle here (the others are at lines " +
                           std::to_string(numbering.cellLine[with[0]]) + " and " +
                           std::to_string(numbering.cellLine[with[1]]) +
                           "): expected a 2D triangulation, where a side bounds at most two "
                           "triangles (overlapping or folded triangles?)");
    }
  const auto isSide = [&](Index a, Index b) {
    for (Index i = fanStart[a]; i < fanStart[a + 1]; ++i)
      if (hasVertex(fan[i], b)) return true;
    return false;
  };

  // Labelled edges: sides of the triangulation, each label once per side.
  std::vector<std::pair<std::pair<std::uint64_t, int>, Index>> edgeKeys;
  edgeKeys.reserve(mesh.facetLabel.size());
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1);
    if (!isSide(a, b))
      scanner.failAt(numbering.facetLine[e],
                     "the edge from vertex " + vertexText(a) + " to vertex " + vertexText(b) +
                         " (label " + std::to_string(mesh.facetLabel[e]) +
                         ") is not a side of any triangle: expected labelled edges on the "
                         "triangulation (the boundary, or a curve embedded in the surface, e.g. "
                         "gmsh's Curve{c} In Surface{s})");
    edgeKeys.push_back({{sideKey(a, b), mesh.facetLabel[e]}, e});
  }
  // An edge listed twice with one label would carry its boundary load twice.
  std::sort(edgeKeys.begin(), edgeKeys.end());
  for (std::size_t i = 1; i < edgeKeys.size(); ++i)
    if (edgeKeys[i].first == edgeKeys[i - 1].first) {
      const Index e = edgeKeys[i].second;
      const int first = numbering.facetLine[edgeKeys[i - 1].second];
      const int second = numbering.facetLine[e];
      scanner.failAt(std::max(first, second),
                     "the edge from vertex " + vertexText(mesh.facetVertex(e, 0)) + " to vertex " +
                         vertexText(mesh.facetVertex(e, 1)) + " is listed twice with label " +
                         std::to_string(mesh.facetLabel[e]) + " (lines " +
                         std::to_string(std::min(first, second)) + " and " +
                         std::to_string(std::max(first, second)) +
                         "): expected each edge once per label");
    }

  dropUnusedPoints(mesh, numbering);
}

void dropUnusedPoints(Mesh& mesh, const FileNumbering& numbering) {
  // Vertices no cell uses carry no stiffness: the solver's matrices would have empty rows
  // for them. Drop them and renumber.
  std::vector<Index> newNumber(mesh.points.size(), -1);
  for (Index v : mesh.cellVertices) newNumber[v] = 0;
  Index next = 0;
  std::vector<Point> kept;
  kept.reserve(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (newNumber[v] < 0) {
      mesh.droppedPoints.push_back({numbering.point[v], mesh.points[v]});
      continue;
    }
    newNumber[v] = next++;
    kept.push_back(mesh.points[v]);
  }
  if (mesh.droppedPoints.empty()) return;
  mesh.points = std::move(kept);
  for (Index& v : mesh.cellVertices) v = newNumber[v];
  // Every labelled facet is a facet of a cell (checked above), so its vertices are kept.
  for (Index& v : mesh.facetVertices) v = newNumber[v];
}

namespace {

// One coordinate: finite, and small enough that areas and volumes do not overflow.
void checkCoordinate(const TextScanner& scanner, double c, char axis, const char* kind,
                     long long number) {
  if (!std::isfinite(c))
    scanner.fail(std::string(kind) + " " + std::to_string(number) + " has coordinate " + axis +
                 " that is not a finite number (NaN or Inf): expected finite coordinates");
  if (std::abs(c) > kMaxCoordinate)
    scanner.fail(std::string(kind) + " " + std::to_string(number) + " has coordinate " + axis +
                 " = " + formatNumber(c) +
                 ", too large: the areas and volumes computed from it would overflow a double; "
                 "expected |x|, |y|, |z| <= 1e100 (rescale the mesh, e.g. to metres)");
}

}  // namespace

void checkCoordinates(const TextScanner& scanner, double x, double y, const char* kind,
                      long long number) {
  checkCoordinate(scanner, x, 'x', kind, number);
  checkCoordinate(scanner, y, 'y', kind, number);
}

void checkCoordinates(const TextScanner& scanner, double x, double y, double z, const char* kind,
                      long long number) {
  checkCoordinates(scanner, x, y, kind, number);
  checkCoordinate(scanner, z, 'z', kind, number);
}

bool readLabel(const TextScanner& scanner, LineFields& fields, int& value, const char* what,
               const char* item, long long number) {
  long long v = 0;
  bool overflow = false;
  std::string_view text;
  if (!fields.integer(v, overflow, text) && !overflow) return false;
  if (overflow || !fitsInt(v))
    scanner.fail(std::string(item) + " " + std::to_string(number) + ": " + what + " " +
                 (overflow ? std::string(text) : std::to_string(v)) +
                 " is out of range: expected a whole number from " +
                 std::to_string(std::numeric_limits<int>::min()) + " to " +
                 std::to_string(std::numeric_limits<int>::max()) +
                 " (labels and regions are stored as int)");
  value = static_cast<int>(v);
  return true;
}

}  // namespace detail

}  // namespace friction
