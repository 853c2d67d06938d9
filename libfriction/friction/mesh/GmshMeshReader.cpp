// Reader for gmsh ASCII .msh, versions 2.2 and 4.1: $MeshFormat, $PhysicalNames, $Entities
// (4.1), $Nodes, $Elements; other sections are skipped. The mesh is 3D when it has
// tetrahedra (type 4), else 2D. In 2D, line elements (type 1) become edges labelled by their
// physical curve and triangles (type 2) take their physical surface as region; in 3D,
// triangles become faces labelled by their physical surface, tetrahedra take their physical
// volume as region and lines are ignored. Points (type 15) are ignored (their nodes, used by
// no cell, are dropped with every other unused node: see finishMesh); anything else is an
// error. Node tags may be arbitrary (non-contiguous, in any order); nodes are numbered 0, 1,
// ... in file order.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "friction/core/Assert.hpp"
#include "friction/mesh/MeshReaderDetail.hpp"

namespace friction::detail {

namespace {

std::string formatNumber(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

const char* elementTypeName(long long type) {
  switch (type) {
    case 1:
      return "2-node line";
    case 2:
      return "3-node triangle";
    case 3:
      return "4-node quadrangle";
    case 4:
      return "4-node tetrahedron";
    case 5:
      return "8-node hexahedron";
    case 6:
      return "6-node prism";
    case 7:
      return "5-node pyramid";
    case 8:
      return "3-node second-order line";
    case 9:
      return "6-node second-order triangle";
    case 10:
      return "9-node second-order quadrangle";
    case 11:
      return "10-node second-order tetrahedron";
    case 15:
      return "1-node point";
    case 16:
      return "8-node second-order quadrangle";
    case 20:
      return "9-node third-order triangle";
    case 21:
      return "10-node third-order triangle";
    case 26:
      return "4-node third-order line";
    default:
      return "element";
  }
}

// Tells what to do about an element type the solver does not take.
std::string elementTypeAdvice(long long type) {
  const bool highOrder = (type >= 8 && type <= 14) || (type >= 16 && type <= 31);
  if (highOrder)
    return "P2 nodes are built from the P1 mesh: mesh with order 1 (gmsh -order 1, or "
           "Mesh.ElementOrder = 1)";
  if (type == 3)
    return "the solver takes triangles only: do not recombine (no Recombine Surface, "
           "Mesh.RecombineAll = 0)";
  if (type >= 5 && type <= 7)
    return "the solver takes tetrahedra only in 3D: do not recombine volumes or extrude them "
           "with Recombine (hexahedra, prisms, pyramids)";
  return "mesh with gmsh -2 (or -3) -order 1 and no recombination";
}

// Node tag -> 0-based index. Tags are usually dense (1..n) and then a vector is fastest;
// sparse tags (e.g. 10^9-based) fall back to a sorted table and binary search.
class NodeMap {
 public:
  /// Build from tags in file order; `lines` gives each tag's line for duplicate messages.
  void build(const TextScanner& s, const std::vector<long long>& tags,
             const std::vector<int>& lines) {
    long long maxTag = 0;
    for (long long t : tags) maxTag = std::max(maxTag, t);
    const long long n = static_cast<long long>(tags.size());
    dense_ = maxTag <= 4 * n + 1024;
    if (dense_) {
      index_.assign(static_cast<std::size_t>(maxTag) + 1, -1);
      for (long long i = 0; i < n; ++i) {
        Index& slot = index_[tags[i]];
        if (slot >= 0) duplicate(s, tags[i], lines[slot], lines[i]);
        slot = static_cast<Index>(i);
      }
    } else {
      sorted_.resize(n);
      for (long long i = 0; i < n; ++i) sorted_[i] = {tags[i], static_cast<Index>(i)};
      std::sort(sorted_.begin(), sorted_.end());
      for (long long i = 1; i < n; ++i)
        if (sorted_[i].first == sorted_[i - 1].first)
          duplicate(s, sorted_[i].first, lines[sorted_[i - 1].second], lines[sorted_[i].second]);
    }
  }

  /// Index of a tag, or -1 if no node has it.
  Index find(long long tag) const {
    if (dense_) return tag >= 0 && tag < static_cast<long long>(index_.size()) ? index_[tag] : -1;
    auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(tag, Index(-1)));
    return it != sorted_.end() && it->first == tag ? it->second : -1;
  }

 private:
  [[noreturn]] static void duplicate(const TextScanner& s, long long tag, int firstLine,
                                     int secondLine) {
    s.failAt(std::max(firstLine, secondLine),
             "node tag " + std::to_string(tag) + " is defined twice (lines " +
                 std::to_string(std::min(firstLine, secondLine)) + " and " +
                 std::to_string(std::max(firstLine, secondLine)) +
                 "): expected each node tag once in $Nodes");
  }

  bool dense_ = true;
  std::vector<Index> index_;
  std::vector<std::pair<long long, Index>> sorted_;
};

class GmshParser {
 public:
  explicit GmshParser(TextScanner& scanner) : s_(scanner) {}

  Mesh parse() {
    mesh_.source = s_.path();
    if (!s_.next()) s_.fail("the file is empty: expected a gmsh mesh starting with $MeshFormat");
    if (s_.line() != "$MeshFormat")
      s_.fail("expected $MeshFormat (the first line of a gmsh .msh file), found " +
              s_.quotedLine());
    readMeshFormat();
    while (s_.next()) {
      const std::string_view l = s_.line();
      if (l.front() != '$')
        s_.fail("expected the start of a section such as $Nodes or $Elements, found " +
                s_.quotedLine());
      if (l == "$PhysicalNames") {
        once(physicalNamesLine_);
        readPhysicalNames();
      } else if (l == "$Entities" && version_ == 41) {
        once(entitiesLine_);
        readEntities();
      } else if (l == "$Nodes") {
        once(nodesLine_);
        version_ == 41 ? readNodes41() : readNodes22();
        nodeMap_.build(s_, nodeTags_, nodeLines_);
      } else if (l == "$Elements") {
        once(elementsLine_);
        if (!nodesLine_) s_.fail("$Elements comes before $Nodes: expected $Nodes first");
        version_ == 41 ? readElements41() : readElements22();
      } else if (l == "$PartitionedEntities") {
        s_.fail(
            "partitioned meshes are not supported: expected a mesh saved without "
            "partitions (no -part, or Mesh.NbPartitions = 0)");
      } else if (l.substr(0, 4) == "$End" || l == "$MeshFormat") {
        s_.fail("unexpected " + s_.quotedLine() +
                ": expected the start of a section such as $Nodes or $Elements");
      } else {
        skipSection();
      }
    }
    if (!nodesLine_) s_.fail("the file has no $Nodes section: expected $Nodes and $Elements");
    if (!elementsLine_) s_.fail("the file has no $Elements section: expected $Elements");
    buildMesh();
    if (mesh_.cellRegion.empty())
      s_.failAt(elementsLine_,
                "$Elements holds no 3-node triangles (type 2): expected a 2D mesh (gmsh -2) "
                "whose surfaces are in physical groups (or Mesh.SaveAll = 1), or 4-node "
                "tetrahedra (type 4) for a 3D mesh (gmsh -3) whose volumes are in physical "
                "groups");
    numbering_.point = nodeTags_;
    finishMesh(s_, mesh_, numbering_);
    return std::move(mesh_);
  }

 private:
  // ---- sections and lines -----------------------------------------------------------

  void once(int& sectionLine) {
    if (sectionLine)
      s_.fail("a second " + s_.quotedLine() + " section (the first is at line " +
              std::to_string(sectionLine) + "): expected each section once");
    sectionLine = s_.lineNumber();
  }

  // The tracked section opened at `openLine` (every section but $MeshFormat is tracked).
  std::string sectionName(int openLine) const {
    return std::string(openLine == nodesLine_           ? "$Nodes"
                       : openLine == elementsLine_      ? "$Elements"
                       : openLine == entitiesLine_      ? "$Entities"
                       : openLine == physicalNamesLine_ ? "$PhysicalNames"
                                                        : "$MeshFormat");
  }

  // Move to the next line of a section's data, which must not be the section's end yet.
  // Called for every line: the message is only built on failure.
  void dataLine(int openLine, const char* items, long long found, long long announced,
                const char* syntax) {
    const bool more = s_.next();
    if (more && s_.line().front() != '$') return;
    const std::string where =
        sectionName(openLine) + " (opened at line " + std::to_string(openLine) + ")";
    const std::string counts = "it announces " + std::to_string(announced) + " " + items +
                               ", found " + std::to_string(found) + "; expected another line \"" +
                               syntax + "\"";
    if (!more) s_.fail("unexpected end of file in " + where + ": " + counts);
    s_.fail(s_.quotedLine() + " ends " + where + " early: " + counts);
  }

  [[noreturn]] void syntaxError(const std::string& item, const char* syntax) {
    s_.fail("expected " + item + " as \"" + syntax + "\", found " + s_.quotedLine());
  }

  void expectEnd(int openLine, const std::string& after) {
    const std::string section = sectionName(openLine);
    const std::string end = "$End" + section.substr(1);
    if (!s_.next())
      s_.fail("missing " + end + ": the file ends inside " + section + " (opened at line " +
              std::to_string(openLine) + ")");
    if (s_.line() != end)
      s_.fail("expected " + end + " to close " + section + " (opened at line " +
              std::to_string(openLine) + ") after " + after + ", found " + s_.quotedLine());
  }

  void skipSection() {
    const int openLine = s_.lineNumber();
    const std::string name(s_.line());
    const std::string end = "$End" + name.substr(1);
    while (s_.next())
      if (s_.line() == end) return;
    s_.fail("missing " + end + ": the file ends inside " + name + " (opened at line " +
            std::to_string(openLine) + ")");
  }

  long long count(const char* syntax, const std::string& what) {
    if (!s_.next()) s_.fail("unexpected end of file: expected " + what + " \"" + syntax + "\"");
    LineFields f = s_.fields();
    long long n;
    if (!f.integer(n) || !f.done() || n < 0 || n > std::numeric_limits<Index>::max())
      syntaxError(what, syntax);
    return n;
  }

  // ---- $MeshFormat, $PhysicalNames, $Entities -----------------------------------------

  void readMeshFormat() {
    const int openLine = s_.lineNumber();
    static constexpr const char* syntax = "version file-type data-size";
    if (!s_.next()) s_.fail("missing $EndMeshFormat: the file ends inside $MeshFormat");
    LineFields f = s_.fields();
    std::string_view version;
    long long fileType, dataSize;
    if (!f.token(version) || !f.integer(fileType) || !f.integer(dataSize) || !f.done())
      syntaxError("the $MeshFormat line", syntax);
    if (version == "2.2") {
      version_ = 22;
      mesh_.format = "gmsh .msh 2.2";
    } else if (version == "4.1") {
      version_ = 41;
      mesh_.format = "gmsh .msh 4.1";
    } else {
      s_.fail("gmsh format version " + std::string(version) +
              " is not supported: expected 2.2 or 4.1 (gmsh -format msh41 or -format msh22)");
    }
    if (fileType != 0)
      s_.fail("this is a binary gmsh file (file-type " + std::to_string(fileType) +
              " in $MeshFormat): expected an ASCII file (file-type 0); mesh it again without -bin "
              "(gmsh -3 -format msh41 for a volume mesh, gmsh -2 for a 2D one), or with "
              "Mesh.Binary = 0 in the .geo");
    const int formatLine = openLine;
    if (!s_.next())
      s_.fail("missing $EndMeshFormat: the file ends inside $MeshFormat (opened at line " +
              std::to_string(formatLine) + ")");
    if (s_.line() != "$EndMeshFormat")
      s_.fail("expected $EndMeshFormat to close $MeshFormat (opened at line " +
              std::to_string(formatLine) + ") after \"" + syntax + "\", found " + s_.quotedLine());
  }

  void readPhysicalNames() {
    const int openLine = physicalNamesLine_;
    static constexpr const char* syntax = "dimension tag \"name\"";
    const long long n = count("numPhysicalNames", "the number of physical names");
    for (long long i = 0; i < n; ++i) {
      dataLine(openLine, "physical names", i, n, syntax);
      LineFields f = s_.fields();
      long long dim;
      int tag;
      if (!f.integer(dim) || !readLabel(s_, f, tag, "tag", "physical name", i + 1))
        syntaxError("physical name " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      const std::string_view q = f.rest();
      if (q.size() < 2 || q.front() != '"' || q.back() != '"')
        syntaxError("physical name " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      const std::string name(q.substr(1, q.size() - 2));
      // Labels or regions once the mesh's dimension is known (buildMesh).
      if (dim >= 1 && dim <= 3) names_[dim][tag] = name;
    }
    expectEnd(openLine, "the " + std::to_string(n) + " names it announces");
  }

  // One line of $Entities: the physical tags of a point, curve, surface or volume.
  std::vector<int> readEntity(int dim, long long i, long long n, long long& tag) {
    static const char* syntaxes[] = {
        "tag x y z numPhysicalTags physicalTags...",
        "tag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTags... numBoundingPoints "
        "pointTags...",
        "tag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTags... numBoundingCurves "
        "curveTags...",
        "tag minX minY minZ maxX maxY maxZ numPhysicalTags physicalTags... numBoundingSurfaces "
        "surfaceTags..."};
    static const char* kinds[] = {"points", "curves", "surfaces", "volumes"};
    dataLine(entitiesLine_, kinds[dim], i, n, syntaxes[dim]);
    const auto bad = [&] {
      syntaxError(std::string(kinds[dim]).substr(0, std::string(kinds[dim]).size() - 1) + " " +
                      std::to_string(i + 1) + " of " + std::to_string(n),
                  syntaxes[dim]);
    };
    LineFields f = s_.fields();
    double box;
    if (!f.integer(tag)) bad();
    for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
      if (!f.real(box)) bad();
    long long numPhysical, numBounding, t;
    if (!f.integer(numPhysical) || numPhysical < 0) bad();
    std::vector<int> physical;
    static const char* items[] = {"point", "curve", "surface", "volume"};
    for (long long k = 0; k < numPhysical; ++k) {
      int label;
      if (!readLabel(s_, f, label, "physical tag", items[dim], i + 1)) bad();
      physical.push_back(label);
    }
    if (dim > 0) {
      if (!f.integer(numBounding) || numBounding < 0) bad();
      for (long long k = 0; k < numBounding; ++k)
        if (!f.integer(t)) bad();
    }
    if (!f.done()) bad();
    return physical;
  }

  void readEntities() {
    static constexpr const char* syntax = "numPoints numCurves numSurfaces numVolumes";
    if (!s_.next()) s_.fail("unexpected end of file: expected \"" + std::string(syntax) + "\"");
    if (s_.line().front() == '$') syntaxError("the $Entities header", syntax);
    LineFields f = s_.fields();
    long long n[4];
    for (long long& c : n)
      if (!f.integer(c) || c < 0) syntaxError("the $Entities header", syntax);
    if (!f.done()) syntaxError("the $Entities header", syntax);
    for (int dim = 0; dim < 4; ++dim)
      for (long long i = 0; i < n[dim]; ++i) {
        long long tag;
        std::vector<int> physical = readEntity(dim, i, n[dim], tag);
        if (dim >= 1) entityPhysical_[dim][tag] = std::move(physical);
      }
    expectEnd(entitiesLine_,
              "the " + std::to_string(n[0] + n[1] + n[2] + n[3]) + " entities it announces");
  }

  // ---- $Nodes ------------------------------------------------------------------------

  void addNode(long long tag, int line) {
    if (tag < 1) s_.failAt(line, "node tag " + std::to_string(tag) + ": expected a tag >= 1");
    nodeTags_.push_back(tag);
    nodeLines_.push_back(line);
  }

  // Coordinates of node i, which must be the next point (nodes are numbered in file order).
  void setCoordinates(std::size_t i, double x, double y, double z, int line) {
    FRICTION_ASSERT(i == mesh_.points.size(), "node coordinates out of order");
    checkCoordinates(s_, x, y, z, "node", nodeTags_[i]);
    mesh_.points.emplace_back(x, y, z);
    scale_ = std::max({scale_, std::abs(x), std::abs(y)});
    if (std::abs(z) > maxAbsZ_) {
      maxAbsZ_ = std::abs(z);
      maxAbsZValue_ = z;
      maxAbsZNode_ = i;
      maxAbsZLine_ = line;
    }
  }

  // gmsh writes 2D meshes in the plane z = 0; a nonzero z (beyond round-off) means a 3D or
  // rotated geometry whose projection would be wrong. Then z is set to 0 (the 2D convention).
  void checkPlanar() {
    if (maxAbsZ_ <= 1e-10 * scale_) {
      for (Point& p : mesh_.points) p.z() = 0;
      return;
    }
    s_.failAt(maxAbsZLine_, "node " + std::to_string(nodeTags_[maxAbsZNode_]) +
                                " has z = " + formatNumber(maxAbsZValue_) +
                                ": expected a 2D mesh in the plane z = 0 (|z| <= 1e-10 "
                                "times the largest |x|, |y|)");
  }

  void readNodes22() {
    static constexpr const char* syntax = "tag x y z";
    const long long n = count("numNodes", "the number of nodes");
    nodeTags_.reserve(reserveHint(n, s_, 8));
    nodeLines_.reserve(reserveHint(n, s_, 8));
    mesh_.points.reserve(reserveHint(n, s_, 8));
    for (long long i = 0; i < n; ++i) {
      dataLine(nodesLine_, "nodes", i, n, syntax);
      LineFields f = s_.fields();
      long long tag;
      double x, y, z;
      if (!f.integer(tag) || !f.real(x) || !f.real(y) || !f.real(z) || !f.done())
        syntaxError("node " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      addNode(tag, s_.lineNumber());
      setCoordinates(i, x, y, z, s_.lineNumber());
    }
    expectEnd(nodesLine_, "the " + std::to_string(n) + " nodes it announces");
  }

  void readNodes41() {
    static constexpr const char* headerSyntax = "numEntityBlocks numNodes minNodeTag maxNodeTag";
    static constexpr const char* blockSyntax = "entityDim entityTag parametric numNodesInBlock";
    if (!s_.next())
      s_.fail("unexpected end of file: expected \"" + std::string(headerSyntax) + "\"");
    const int headerLine = s_.lineNumber();
    LineFields f = s_.fields();
    long long numBlocks, numNodes, minTag, maxTag;
    if (s_.line().front() == '$' || !f.integer(numBlocks) || !f.integer(numNodes) ||
        !f.integer(minTag) || !f.integer(maxTag) || !f.done() || numBlocks < 0 || numNodes < 0 ||
        numNodes > std::numeric_limits<Index>::max())
      syntaxError("the $Nodes header", headerSyntax);
    nodeTags_.reserve(reserveHint(numNodes, s_, 8));
    nodeLines_.reserve(reserveHint(numNodes, s_, 8));
    mesh_.points.reserve(reserveHint(numNodes, s_, 8));
    long long total = 0;
    for (long long b = 0; b < numBlocks; ++b) {
      dataLine(nodesLine_, "node blocks", b, numBlocks, blockSyntax);
      const int blockLine = s_.lineNumber();
      LineFields bf = s_.fields();
      long long dim, entity, parametric, count;
      if (!bf.integer(dim) || !bf.integer(entity) || !bf.integer(parametric) ||
          !bf.integer(count) || !bf.done() || count < 0)
        syntaxError("node block " + std::to_string(b + 1) + " of " + std::to_string(numBlocks),
                    blockSyntax);
      if (total + count > std::numeric_limits<Index>::max())
        s_.fail("too many nodes: expected at most " +
                std::to_string(std::numeric_limits<Index>::max()));
      const std::string where = " (node block at line " + std::to_string(blockLine) + ")";
      // The tags first, then the coordinates, each one per line.
      const std::size_t first = nodeTags_.size();
      for (long long k = 0; k < count; ++k) {
        dataLine(nodesLine_, "nodes", total + k, std::max(numNodes, total + count), "nodeTag");
        LineFields tf = s_.fields();
        long long tag;
        if (!tf.integer(tag) || !tf.done())
          syntaxError(
              "the tag of node " + std::to_string(k + 1) + " of " + std::to_string(count) + where,
              "nodeTag");
        addNode(tag, s_.lineNumber());
      }
      for (long long k = 0; k < count; ++k) {
        dataLine(nodesLine_, "node coordinates", total + k, std::max(numNodes, total + count),
                 "x y z");
        LineFields cf = s_.fields();
        double x, y, z;
        // Parametric nodes add u (and v) after z; they are not needed.
        if (!cf.real(x) || !cf.real(y) || !cf.real(z) || (parametric == 0 && !cf.done()))
          syntaxError("the coordinates of node " + std::to_string(k + 1) + " of " +
                          std::to_string(count) + where,
                      parametric ? "x y z u [v]" : "x y z");
        setCoordinates(first + k, x, y, z, s_.lineNumber());
      }
      total += count;
    }
    if (total != numNodes)
      s_.failAt(headerLine, "the $Nodes header announces " + std::to_string(numNodes) +
                                " nodes, but its " + std::to_string(numBlocks) + " blocks hold " +
                                std::to_string(total) + ": expected the counts to agree");
    expectEnd(nodesLine_, "the " + std::to_string(numBlocks) + " node blocks it announces");
  }

  // ---- $Elements ---------------------------------------------------------------------

  Index node(long long tag, long long element) {
    const Index i = nodeMap_.find(tag);
    if (i < 0)
      s_.fail("element " + std::to_string(element) + " refers to node " + std::to_string(tag) +
              ", which $Nodes (line " + std::to_string(nodesLine_) +
              ") does not define: expected the tag of a node in $Nodes");
    return i;
  }

  [[noreturn]] void unsupportedType(long long type) {
    s_.fail("element type " + std::to_string(type) + " (" + elementTypeName(type) +
            ") is not supported: expected 2-node lines (type 1), 3-node triangles (type 2), "
            "4-node tetrahedra (type 4) or points (type 15). " +
            elementTypeAdvice(type));
  }

  static std::string clockwiseFix(long long surface) {
    const std::string tag = surface > 0 ? std::to_string(surface) : "<tag>";
    return "in gmsh reverse the orientation of surface " + tag + " (Reverse Surface{" + tag +
           "}; in the .geo, or gmsh::model::mesh::reverse), so that it faces +z";
  }

  // The elements are kept as read until the dimension is known (a triangle is a cell of a 2D
  // mesh, a labelled face of a 3D one), then checked and stored in file order by buildMesh.
  struct RawElement {
    long long tag;
    long long entity;  ///< elementary tag, 0 if the file gives none
    std::array<Index, 4> node;
    int line;
    int type;      ///< 1, 2 or 4
    int physical;  ///< 2.2: the physical tag (0 if none)
    int block;     ///< 4.1: the element block (blocks_), else -1
  };
  struct Block {
    std::vector<int> physical;
    int line;
  };

  void addRaw(int type, long long tag, long long entity, const std::array<long long, 4>& v,
              int physical, int block) {
    RawElement e{tag, entity, {}, s_.lineNumber(), type, physical, block};
    const int n = type == 1 ? 2 : type == 2 ? 3 : 4;
    for (int k = 0; k < n; ++k) e.node[k] = node(v[k], tag);
    elements_.push_back(e);
  }

  std::array<long long, 4> fileNodes(const RawElement& e) const {
    std::array<long long, 4> v{};
    for (int k = 0; k < 4; ++k) v[k] = nodeTags_[e.node[k]];
    return v;
  }

  void addFacet(const RawElement& e, int label) {
    const auto v = fileNodes(e);
    if (mesh_.dim == 2) {
      const std::array<Index, 2> edge{e.node[0], e.node[1]};
      checkEdge(s_, e.line, edge, "element", e.tag, {v[0], v[1]});
      mesh_.addFacet({edge[0], edge[1]}, label);
    } else {
      const std::array<Index, 3> t{e.node[0], e.node[1], e.node[2]};
      checkTriangleFacet(s_, e.line, t, "element", e.tag, {v[0], v[1], v[2]});
      mesh_.addFacet({t[0], t[1], t[2]}, label);
    }
    numbering_.facetLine.push_back(e.line);
  }

  void addCell(const RawElement& e, int region) {
    const auto v = fileNodes(e);
    if (mesh_.dim == 2) {
      const std::array<Index, 3> t{e.node[0], e.node[1], e.node[2]};
      const TriangleDefect defect = triangleDefect(mesh_.points, t);
      if (defect != TriangleDefect::none)
        failTriangle(s_, e.line, defect, mesh_.points, t, "element", e.tag, {v[0], v[1], v[2]},
                     clockwiseFix(e.entity));
      mesh_.addCell({t[0], t[1], t[2]}, region);
    } else {
      const TetrahedronDefect defect = tetrahedronDefect(mesh_.points, e.node);
      if (defect != TetrahedronDefect::none)
        failTetrahedron(s_, e.line, defect, mesh_.points, e.node, "element", e.tag, v,
                        "gmsh writes them so: the file was written or edited by something "
                        "else; swap two vertices of the element");
      mesh_.addCell({e.node[0], e.node[1], e.node[2], e.node[3]}, region);
    }
    numbering_.cellLine.push_back(e.line);
  }

  [[noreturn]] void twoRegions(int line, long long entity, long long a, long long b,
                               const std::string& where) {
    const bool volume = mesh_.dim == 3;
    s_.failAt(line, std::string(volume ? "volume " : "surface ") + std::to_string(entity) +
                        " is in two physical " + (volume ? "volumes" : "surfaces") + " (" +
                        std::to_string(a) + " and " + std::to_string(b) + where +
                        "): expected each " + (volume ? "volume" : "surface") +
                        " in at most one physical " + (volume ? "volume" : "surface") +
                        ", since a " + cellName(mesh_.dim) + " has one region");
  }

  // The mesh from the raw elements: the dimension is the highest of its cells' (3 with
  // tetrahedra); cells and labelled facets in file order.
  void buildMesh() {
    const bool tetrahedra = std::any_of(elements_.begin(), elements_.end(),
                                        [](const RawElement& e) { return e.type == 4; });
    mesh_.dim = tetrahedra ? 3 : 2;
    mesh_.labelNames = names_[mesh_.dim - 1];
    mesh_.regionNames = names_[mesh_.dim];
    if (mesh_.dim == 2) checkPlanar();
    const int facetType = mesh_.dim == 2 ? 1 : 2, cellType = mesh_.dim == 2 ? 2 : 4;
    std::size_t numCells = 0;
    for (const RawElement& e : elements_) numCells += e.type == cellType;
    mesh_.cellVertices.reserve(numCells * (mesh_.dim + 1));
    mesh_.cellRegion.reserve(numCells);
    numbering_.cellLine.reserve(numCells);
    // gmsh 2.2 writes an element once per physical group of its entity; a cell can only
    // have one region.
    std::unordered_map<long long, long long> entityRegion;  // elementary tag -> physical
    for (const RawElement& e : elements_) {
      const std::vector<int>* physical = e.block >= 0 ? &blocks_[e.block].physical : nullptr;
      if (e.type == facetType) {
        // One facet per physical group, like gmsh's own 2.2 output.
        if (!physical)
          addFacet(e, e.physical);
        else if (physical->empty())
          addFacet(e, 0);
        else
          for (int label : *physical) addFacet(e, label);
      } else if (e.type == cellType) {
        int region = e.physical;
        if (physical) {
          if (physical->size() > 1)
            twoRegions(blocks_[e.block].line, e.entity, (*physical)[0], (*physical)[1],
                       " in $Entities at line " + std::to_string(entitiesLine_));
          region = physical->empty() ? 0 : (*physical)[0];
        } else if (e.entity != 0) {
          const auto [it, inserted] = entityRegion.emplace(e.entity, e.physical);
          if (!inserted && it->second != e.physical)
            twoRegions(e.line, e.entity, it->second, e.physical, "");
        }
        addCell(e, region);
      }
      // Else a line element of a 3D mesh (an edge of a physical curve): not needed.
    }
    elements_ = {};
  }

  void readElements22() {
    static constexpr const char* syntax = "tag type numTags tags... nodes...";
    const long long n = count("numElements", "the number of elements");
    elements_.reserve(reserveHint(n, s_, 16));
    for (long long i = 0; i < n; ++i) {
      dataLine(elementsLine_, "elements", i, n, syntax);
      LineFields f = s_.fields();
      long long tag, type, numTags;
      if (!f.integer(tag) || !f.integer(type) || !f.integer(numTags) || numTags < 0)
        syntaxError("element " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      if (type == 15) continue;
      if (type != 1 && type != 2 && type != 4) unsupportedType(type);
      int physical = 0;
      long long elementary = 0, t;
      for (long long k = 0; k < numTags; ++k) {
        // The first tag is the physical group: the label or region, an int.
        if (k == 0 ? !readLabel(s_, f, physical, "physical tag", "element", tag) : !f.integer(t))
          syntaxError("element " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
        if (k == 1) elementary = t;
      }
      std::array<long long, 4> v{};
      const int numNodes = type == 1 ? 2 : type == 2 ? 3 : 4;
      for (int k = 0; k < numNodes; ++k)
        if (!f.integer(v[k]))
          syntaxError("element " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      if (!f.done())
        syntaxError("element " + std::to_string(i + 1) + " of " + std::to_string(n), syntax);
      addRaw(static_cast<int>(type), tag, numTags >= 2 ? elementary : 0, v, physical, -1);
    }
    expectEnd(elementsLine_, "the " + std::to_string(n) + " elements it announces");
  }

  // Physical tags of the entity an element block belongs to (none without $Entities).
  const std::vector<int>& physicalTags(long long dim, long long entity) {
    static const std::vector<int> none;
    if (!entitiesLine_) return none;
    const auto& table = entityPhysical_[dim];
    auto it = table.find(entity);
    if (it == table.end())
      s_.fail("element block of " +
              std::string(dim == 1   ? "curve "
                          : dim == 2 ? "surface "
                                     : "volume ") +
              std::to_string(entity) + ": $Entities (line " + std::to_string(entitiesLine_) +
              ") lists no such entity: expected the entity of every element block in $Entities");
    return it->second;
  }

  void readElements41() {
    static constexpr const char* headerSyntax =
        "numEntityBlocks numElements minElementTag maxElementTag";
    static constexpr const char* blockSyntax = "entityDim entityTag elementType numElementsInBlock";
    if (!s_.next())
      s_.fail("unexpected end of file: expected \"" + std::string(headerSyntax) + "\"");
    const int headerLine = s_.lineNumber();
    LineFields f = s_.fields();
    long long numBlocks, numElements, minTag, maxTag;
    if (s_.line().front() == '$' || !f.integer(numBlocks) || !f.integer(numElements) ||
        !f.integer(minTag) || !f.integer(maxTag) || !f.done() || numBlocks < 0 || numElements < 0)
      syntaxError("the $Elements header", headerSyntax);
    // An upper bound (points count too).
    elements_.reserve(reserveHint(numElements, s_, 8));
    long long total = 0;
    for (long long b = 0; b < numBlocks; ++b) {
      dataLine(elementsLine_, "element blocks", b, numBlocks, blockSyntax);
      const int blockLine = s_.lineNumber();
      LineFields bf = s_.fields();
      long long dim, entity, type, count;
      if (!bf.integer(dim) || !bf.integer(entity) || !bf.integer(type) || !bf.integer(count) ||
          !bf.done() || count < 0)
        syntaxError("element block " + std::to_string(b + 1) + " of " + std::to_string(numBlocks),
                    blockSyntax);
      if (type != 1 && type != 2 && type != 4 && type != 15) unsupportedType(type);
      const long long typeDim = type == 1 ? 1 : type == 2 ? 2 : type == 4 ? 3 : 0;
      if (dim != typeDim)
        s_.fail("element block of type " + std::to_string(type) + " (" + elementTypeName(type) +
                ") on an entity of dimension " + std::to_string(dim) + ": expected dimension " +
                std::to_string(typeDim));
      const int block = static_cast<int>(blocks_.size());
      if (type != 15) blocks_.push_back({physicalTags(dim, entity), blockLine});
      const int numNodes = type == 1 ? 2 : type == 2 ? 3 : type == 4 ? 4 : 1;
      const char* syntax = type == 1   ? "elementTag node node"
                           : type == 2 ? "elementTag node node node"
                           : type == 4 ? "elementTag node node node node"
                                       : "elementTag node";
      const std::string where = " (element block at line " + std::to_string(blockLine) + ")";
      for (long long k = 0; k < count; ++k) {
        dataLine(elementsLine_, "elements", total + k, std::max(numElements, total + count),
                 syntax);
        LineFields ef = s_.fields();
        long long tag;
        std::array<long long, 4> v{};
        bool ok = ef.integer(tag);
        for (int j = 0; j < numNodes && ok; ++j) ok = ef.integer(v[j]);
        if (!ok || !ef.done())
          syntaxError("element " + std::to_string(k + 1) + " of " + std::to_string(count) + where,
                      syntax);
        if (type != 15) addRaw(static_cast<int>(type), tag, entity, v, 0, block);
      }
      total += count;
    }
    if (total != numElements)
      s_.failAt(headerLine, "the $Elements header announces " + std::to_string(numElements) +
                                " elements, but its " + std::to_string(numBlocks) +
                                " blocks hold " + std::to_string(total) +
                                ": expected the counts to agree");
    expectEnd(elementsLine_, "the " + std::to_string(numBlocks) + " element blocks it announces");
  }

  TextScanner& s_;
  Mesh mesh_;
  FileNumbering numbering_;
  int version_ = 0;  // 22 or 41
  int physicalNamesLine_ = 0, entitiesLine_ = 0, nodesLine_ = 0, elementsLine_ = 0;
  std::unordered_map<long long, std::vector<int>> entityPhysical_[4];  // per entity dimension
  std::map<int, std::string> names_[4];  // physical names per dimension
  std::vector<RawElement> elements_;
  std::vector<Block> blocks_;
  std::vector<long long> nodeTags_;
  std::vector<int> nodeLines_;
  NodeMap nodeMap_;
  double scale_ = 0, maxAbsZ_ = 0, maxAbsZValue_ = 0;
  std::size_t maxAbsZNode_ = 0;
  int maxAbsZLine_ = 0;
};

}  // namespace

Mesh parseGmshMesh(TextScanner& scanner) { return GmshParser(scanner).parse(); }

}  // namespace friction::detail
