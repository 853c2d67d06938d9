// Reader for FreeFEM's 2D .msh (what savemesh writes): header "nv nt nbe", nv lines
// "x y label", nt lines "v1 v2 v3 region" (1-based, counter-clockwise), nbe lines
// "v1 v2 label". Internal fracture edges are ordinary lines of the edge list, once each, in
// either direction.
#include <limits>

#include "friction/mesh/MeshReaderDetail.hpp"

namespace friction::detail {

namespace {

class FreeFemParser {
 public:
  explicit FreeFemParser(TextScanner& scanner) : s_(scanner) {}

  Mesh parse() {
    mesh_.source = s_.path();
    mesh_.format = "FreeFEM .msh";
    readHeader();
    readVertices();
    readTriangles();
    readEdges();
    if (s_.next())
      s_.fail("the file goes on after the " + std::to_string(nbe_) +
              " edges announced by the header (line " + std::to_string(headerLine_) + "), found " +
              s_.quotedLine() + ": expected the end of the file; the counts " +
              "nv nt nbe = " + counts() + " disagree with the file");
    numbering_.point.resize(mesh_.points.size());
    for (std::size_t i = 0; i < numbering_.point.size(); ++i)
      numbering_.point[i] = static_cast<long long>(i) + 1;
    finishMesh(s_, mesh_, numbering_);
    return std::move(mesh_);
  }

 private:
  std::string counts() const {
    return std::to_string(nv_) + " " + std::to_string(nt_) + " " + std::to_string(nbe_);
  }

  void readHeader() {
    if (!s_.next())
      s_.fail("the file is empty: expected a FreeFEM header \"nv nt nbe\" or a gmsh $MeshFormat");
    headerLine_ = s_.lineNumber();
    LineFields f = s_.fields();
    if (!f.integer(nv_) || !f.integer(nt_) || !f.integer(nbe_) || !f.done()) {
      std::string hint;
      if (s_.line() == "$MeshFormat")
        hint = " (this is a gmsh file: read it with readMesh or readGmshMesh)";
      else if (s_.line().front() == '$')
        hint = " (a gmsh file must start with $MeshFormat)";
      s_.fail(
          "expected the FreeFEM header \"nv nt nbe\" (numbers of vertices, triangles and "
          "edges), found " +
          s_.quotedLine() + hint);
    }
    constexpr long long maxCount = std::numeric_limits<Index>::max();
    if (nv_ < 3 || nv_ > maxCount)
      s_.fail("the header \"nv nt nbe\" = " + counts() + " announces nv = " + std::to_string(nv_) +
              " vertices: expected at least 3 (and at most " + std::to_string(maxCount) + ")");
    if (nt_ < 1 || nt_ > maxCount)
      s_.fail("the header \"nv nt nbe\" = " + counts() + " announces nt = " + std::to_string(nt_) +
              " triangles: expected a mesh with at least one triangle");
    if (nbe_ < 0 || nbe_ > maxCount)
      s_.fail("the header \"nv nt nbe\" = " + counts() +
              " announces nbe = " + std::to_string(nbe_) + " edges: expected a count of 0 or more");
  }

  // Move to the next data line; a file that ends early says how many items it holds.
  void dataLine(const char* items, long long found, long long announced, const char* syntax) {
    if (s_.next()) return;
    s_.fail("unexpected end of file: the header (line " + std::to_string(headerLine_) +
            ") announces " + std::to_string(announced) + " " + items + ", found " +
            std::to_string(found) + "; expected another line \"" + syntax + "\"");
  }

  [[noreturn]] void syntaxError(const char* item, long long i, long long n, const char* syntax) {
    s_.fail("expected " + std::string(item) + " " + std::to_string(i) + " of " + std::to_string(n) +
            " as \"" + syntax + "\", found " + s_.quotedLine() +
            " (check the counts \"nv nt nbe\" = " + counts() + " in the header at line " +
            std::to_string(headerLine_) + ")");
  }

  // 1-based vertex number in the file to 0-based index.
  Index vertex(long long v, const char* item, long long i) {
    if (v < 1 || v > nv_)
      s_.fail(std::string(item) + " " + std::to_string(i) + " refers to vertex " +
              std::to_string(v) + ": expected a vertex number in 1.." + std::to_string(nv_) +
              " (nv in the header at line " + std::to_string(headerLine_) + ")");
    return static_cast<Index>(v - 1);
  }

  void readVertices() {
    static constexpr const char* syntax = "x y label";
    mesh_.points.reserve(reserveHint(nv_, s_, 6));
    for (long long i = 0; i < nv_; ++i) {
      dataLine("vertices", i, nv_, syntax);
      LineFields f = s_.fields();
      double x, y;
      // The vertex label is read past but not kept: FreeFEM leaves garbage there after
      // adaptmesh, and the edge labels carry the boundary information.
      if (!f.real(x) || !f.real(y) || !f.skip() || !f.done())
        syntaxError("vertex", i + 1, nv_, syntax);
      checkCoordinates(s_, x, y, "vertex", i + 1);
      mesh_.points.emplace_back(x, y, 0.0);
    }
  }

  void readTriangles() {
    static constexpr const char* syntax = "v1 v2 v3 region";
    static const std::string fix =
        "list its vertices counter-clockwise (swap two of them); FreeFEM's savemesh always "
        "writes them counter-clockwise, so the file was written or edited by something else";
    mesh_.cellVertices.reserve(3 * reserveHint(nt_, s_, 8));
    mesh_.cellRegion.reserve(reserveHint(nt_, s_, 8));
    for (long long i = 0; i < nt_; ++i) {
      dataLine("triangles", i, nt_, syntax);
      LineFields f = s_.fields();
      std::array<long long, 3> v;
      int region;
      if (!f.integer(v[0]) || !f.integer(v[1]) || !f.integer(v[2]) ||
          !readLabel(s_, f, region, "region", "triangle", i + 1) || !f.done())
        syntaxError("triangle", i + 1, nt_, syntax);
      std::array<Index, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = vertex(v[k], "triangle", i + 1);
      const TriangleDefect defect = triangleDefect(mesh_.points, t);
      if (defect != TriangleDefect::none)
        failTriangle(s_, s_.lineNumber(), defect, mesh_.points, t, "triangle", i + 1, v, fix);
      mesh_.addCell({t[0], t[1], t[2]}, region);
      numbering_.cellLine.push_back(s_.lineNumber());
    }
  }

  void readEdges() {
    static constexpr const char* syntax = "v1 v2 label";
    mesh_.facetVertices.reserve(2 * reserveHint(nbe_, s_, 6));
    mesh_.facetLabel.reserve(reserveHint(nbe_, s_, 6));
    for (long long i = 0; i < nbe_; ++i) {
      dataLine("edges", i, nbe_, syntax);
      LineFields f = s_.fields();
      std::array<long long, 2> v;
      int label;
      if (!f.integer(v[0]) || !f.integer(v[1]) ||
          !readLabel(s_, f, label, "label", "edge", i + 1) || !f.done())
        syntaxError("edge", i + 1, nbe_, syntax);
      const std::array<Index, 2> e{vertex(v[0], "edge", i + 1), vertex(v[1], "edge", i + 1)};
      checkEdge(s_, s_.lineNumber(), e, "edge", i + 1, v);
      mesh_.addFacet({e[0], e[1]}, label);
      numbering_.facetLine.push_back(s_.lineNumber());
    }
  }

  TextScanner& s_;
  Mesh mesh_;
  FileNumbering numbering_;
  long long nv_ = 0, nt_ = 0, nbe_ = 0;
  int headerLine_ = 0;
};

}  // namespace

Mesh parseFreeFemMesh(TextScanner& scanner) { return FreeFemParser(scanner).parse(); }

}  // namespace friction::detail
