// Reader for Medit .mesh in 3D, as FreeFEM's savemesh writes a mesh3: "MeshVersionFormatted
// n", "Dimension 3", then sections each opened by a keyword line and a count line: Vertices
// ("x y z label"), Tetrahedra ("v1 v2 v3 v4 region"), Triangles ("v1 v2 v3 label": boundary
// faces and internal fracture faces), "End". Vertex numbers are 1-based. Other sections with
// a count and one line per item (Edges, Corners, Ridges, Normals, ...) are skipped; cells
// other than tetrahedra are refused. Lines starting with '#' are comments.
#include <cctype>
#include <cmath>
#include <limits>

#include "friction/mesh/MeshReaderDetail.hpp"

namespace friction::detail {

namespace {

class MeditParser {
 public:
  explicit MeditParser(TextScanner& scanner) : s_(scanner) {}

  Mesh parse() {
    mesh_.source = s_.path();
    mesh_.format = "Medit .mesh";
    mesh_.dim = 3;
    readHeader();
    bool ended = false;
    while (!ended && nextLine()) {
      const std::string_view keyword = s_.line();
      if (keyword == "End")
        ended = true;
      else if (keyword == "Vertices")
        readVertices();
      else if (keyword == "Tetrahedra")
        readTetrahedra();
      else if (keyword == "Triangles")
        readTriangles();
      else if (keyword == "Hexahedra" || keyword == "Prisms" || keyword == "Pyramids" ||
               keyword == "Quadrilaterals")
        s_.fail("section " + s_.quotedLine() +
                " is not supported: expected a mesh of tetrahedra with triangle faces (FreeFEM "
                "mesh3, or gmsh -3 without recombination)");
      else
        skipSection();
    }
    if (!ended)
      s_.fail(
          "the file ends without \"End\": expected \"End\" after the last section "
          "(truncated file?)");
    if (!verticesLine_) s_.failAt(0, "no Vertices section: expected Vertices and Tetrahedra");
    if (mesh_.cellRegion.empty())
      s_.failAt(0,
                "no tetrahedra (no Tetrahedra section, or an empty one): expected a 3D mesh of "
                "tetrahedra (FreeFEM's savemesh of a mesh3)");
    numbering_.point.resize(mesh_.points.size());
    for (std::size_t i = 0; i < numbering_.point.size(); ++i)
      numbering_.point[i] = static_cast<long long>(i) + 1;
    finishMesh(s_, mesh_, numbering_);
    return std::move(mesh_);
  }

 private:
  // The next line that is not a comment; false at the end of the file.
  bool nextLine() {
    while (s_.next())
      if (s_.line().front() != '#') return true;
    return false;
  }

  void readHeader() {
    if (!nextLine()) s_.fail("the file is empty: expected \"MeshVersionFormatted 1\" or 2");
    LineFields f = s_.fields();
    std::string_view word;
    long long version;
    if (!f.token(word) || word != "MeshVersionFormatted" || !f.integer(version) || !f.done())
      s_.fail("expected \"MeshVersionFormatted 1\" or 2 (the first line of a Medit .mesh), found " +
              s_.quotedLine());
    if (version != 1 && version != 2)
      s_.fail("MeshVersionFormatted " + std::to_string(version) +
              ": expected 1 or 2 (an ASCII Medit file; version 3 and binary .meshb are not "
              "supported)");
    if (!nextLine()) s_.fail("unexpected end of file: expected \"Dimension 3\"");
    f = s_.fields();
    long long dim;
    if (!f.token(word) || word != "Dimension")
      s_.fail("expected \"Dimension 3\", found " + s_.quotedLine());
    if (f.done()) {  // "Dimension" and the number on separate lines
      if (!nextLine()) s_.fail("unexpected end of file: expected the dimension (3)");
      f = s_.fields();
    }
    if (!f.integer(dim) || !f.done()) s_.fail("expected \"Dimension 3\", found " + s_.quotedLine());
    if (dim != 3)
      s_.fail("Dimension " + std::to_string(dim) +
              ": expected 3 (Medit .mesh is read for 3D meshes; write 2D FreeFEM meshes with "
              "savemesh(Th, \"file.msh\"))");
  }

  // The count line after a section keyword.
  long long count(const std::string& section) {
    const int keywordLine = s_.lineNumber();
    if (!nextLine())
      s_.fail("unexpected end of file after " + section + " (line " + std::to_string(keywordLine) +
              "): expected the number of items");
    LineFields f = s_.fields();
    long long n;
    if (!f.integer(n) || !f.done() || n < 0 || n > std::numeric_limits<Index>::max())
      s_.fail("expected the number of " + section + " after the keyword at line " +
              std::to_string(keywordLine) + ", found " + s_.quotedLine());
    return n;
  }

  void dataLine(const std::string& section, long long found, long long announced,
                const char* syntax) {
    if (nextLine()) return;
    s_.fail("unexpected end of file in " + section + " (announced " + std::to_string(announced) +
            ", found " + std::to_string(found) + "): expected another line \"" + syntax + "\"");
  }

  [[noreturn]] void syntaxError(const char* item, long long i, long long n, const char* syntax) {
    s_.fail("expected " + std::string(item) + " " + std::to_string(i) + " of " + std::to_string(n) +
            " as \"" + syntax + "\", found " + s_.quotedLine());
  }

  Index vertex(long long v, const char* item, long long i) {
    if (!verticesLine_)
      s_.fail(std::string(item) + " " + std::to_string(i) +
              " comes before the Vertices section: expected Vertices first");
    const long long nv = static_cast<long long>(mesh_.points.size());
    if (v < 1 || v > nv)
      s_.fail(std::string(item) + " " + std::to_string(i) + " refers to vertex " +
              std::to_string(v) + ": expected a vertex number in 1.." + std::to_string(nv) +
              " (Vertices at line " + std::to_string(verticesLine_) + ")");
    return static_cast<Index>(v - 1);
  }

  void once(int& sectionLine, const char* name) {
    if (sectionLine)
      s_.fail(std::string("a second ") + name + " section (the first is at line " +
              std::to_string(sectionLine) + "): expected each section once");
    sectionLine = s_.lineNumber();
  }

  void readVertices() {
    once(verticesLine_, "Vertices");
    static constexpr const char* syntax = "x y z label";
    const long long n = count("Vertices");
    mesh_.points.reserve(reserveHint(n, s_, 8));
    for (long long i = 0; i < n; ++i) {
      dataLine("Vertices", i, n, syntax);
      LineFields f = s_.fields();
      double x, y, z;
      // The vertex label is not kept: the triangle labels carry the boundary information.
      if (!f.real(x) || !f.real(y) || !f.real(z) || !f.skip() || !f.done())
        syntaxError("vertex", i + 1, n, syntax);
      checkCoordinates(s_, x, y, z, "vertex", i + 1);
      mesh_.points.emplace_back(x, y, z);
    }
  }

  void readTetrahedra() {
    once(tetrahedraLine_, "Tetrahedra");
    static constexpr const char* syntax = "v1 v2 v3 v4 region";
    const long long n = count("Tetrahedra");
    mesh_.cellVertices.reserve(4 * reserveHint(n, s_, 10));
    mesh_.cellRegion.reserve(reserveHint(n, s_, 10));
    for (long long i = 0; i < n; ++i) {
      dataLine("Tetrahedra", i, n, syntax);
      LineFields f = s_.fields();
      std::array<long long, 4> v;
      int region;
      if (!f.integer(v[0]) || !f.integer(v[1]) || !f.integer(v[2]) || !f.integer(v[3]) ||
          !readLabel(s_, f, region, "region", "tetrahedron", i + 1) || !f.done())
        syntaxError("tetrahedron", i + 1, n, syntax);
      std::array<Index, 4> t;
      for (int k = 0; k < 4; ++k) t[k] = vertex(v[k], "tetrahedron", i + 1);
      const TetrahedronDefect defect = tetrahedronDefect(mesh_.points, t);
      if (defect != TetrahedronDefect::none)
        failTetrahedron(s_, s_.lineNumber(), defect, mesh_.points, t, "tetrahedron", i + 1, v,
                        "FreeFEM writes them so: the file was written or edited by something "
                        "else; swap two of its vertices");
      mesh_.addCell({t[0], t[1], t[2], t[3]}, region);
      numbering_.cellLine.push_back(s_.lineNumber());
    }
  }

  void readTriangles() {
    once(trianglesLine_, "Triangles");
    static constexpr const char* syntax = "v1 v2 v3 label";
    const long long n = count("Triangles");
    mesh_.facetVertices.reserve(3 * reserveHint(n, s_, 8));
    mesh_.facetLabel.reserve(reserveHint(n, s_, 8));
    for (long long i = 0; i < n; ++i) {
      dataLine("Triangles", i, n, syntax);
      LineFields f = s_.fields();
      std::array<long long, 3> v;
      int label;
      if (!f.integer(v[0]) || !f.integer(v[1]) || !f.integer(v[2]) ||
          !readLabel(s_, f, label, "label", "triangle", i + 1) || !f.done())
        syntaxError("triangle", i + 1, n, syntax);
      std::array<Index, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = vertex(v[k], "triangle", i + 1);
      checkTriangleFacet(s_, s_.lineNumber(), t, "triangle", i + 1, v);
      mesh_.addFacet({t[0], t[1], t[2]}, label);
      numbering_.facetLine.push_back(s_.lineNumber());
    }
  }

  // A section this reader does not need: its count, then one line per item.
  void skipSection() {
    const std::string name(s_.line());
    if (name.find_first_of(" \t") != std::string::npos ||
        !std::isalpha(static_cast<unsigned char>(name.front())))
      s_.fail("expected a section keyword (Vertices, Tetrahedra, Triangles, ... or End), found " +
              s_.quotedLine());
    const long long n = count(name);
    for (long long i = 0; i < n; ++i) dataLine(name, i, n, "one item");
  }

  TextScanner& s_;
  Mesh mesh_;
  FileNumbering numbering_;
  int verticesLine_ = 0, tetrahedraLine_ = 0, trianglesLine_ = 0;
};

}  // namespace

Mesh parseMeditMesh(TextScanner& scanner) { return MeditParser(scanner).parse(); }

}  // namespace friction::detail
