// constant/splitMesh writer and reader: see SplitMeshIO.hpp.
#include "friction/fracture/SplitMeshIO.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>

#include "friction/core/Assert.hpp"
#include "friction/core/InputFile.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/dict/Tokenizer.hpp"
#include "friction/fracture/SignConventions.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

namespace {

namespace fs = std::filesystem;

template <typename T>
std::vector<int> toInts(const std::vector<T>& v) {
  return std::vector<int>(v.begin(), v.end());
}

// Appended to every consistency error: the file is the utility's output, so the repair is
// to make it again.
const char* const resplit =
    " (constant/splitMesh is written by splitFractureNodes: split again with "
    "splitFractureNodes -case <case> -overwrite)";

// One entry per fracture node in every list of a fracture's entry (`sizes`: key -> length).
void requireOnePerNode(const Dictionary& f, std::size_t n,
                       const std::map<std::string, std::size_t>& sizes) {
  for (const auto& [key, size] : sizes)
    if (size != n)
      f.fail(key, "key '" + key + "': " + std::to_string(size) +
                      " entries, expected one per fracture node (" + std::to_string(n) + ")");
}

// Fracture node i's copies: both copies of its node, and the same node exactly at tips.
void requireCopies(const Dictionary& f, const SplitMesh& s, const FractureGeometry& g,
                   std::size_t i) {
  if (s.origin[g.plus[i]] != g.node[i] || s.origin[g.minus[i]] != g.node[i])
    f.fail("plus", "fracture node " + std::to_string(i) +
                       ": 'plus' and 'minus' must be copies of 'node' (see 'origin')");
  if ((g.plus[i] == g.minus[i]) != (g.kind[i] == FractureNodeKind::tip))
    f.fail("kind", "fracture node " + std::to_string(i) + ": exactly the tips have plus == minus");
}

// The 3D part of a fracture's entry (after node, plus, minus, kind): unit normals and the
// triangles, each a face of the split mesh through its plus copies and through its minus
// copies (the two lips of the cut).
template <class IsFace>
void readSurface(const Dictionary& f, FractureGeometry& g, const SplitMesh& s,
                 const IsFace& isFace) {
  g.normal = f.getPointList("normal");
  const std::size_t n = g.node.size();
  requireOnePerNode(f, n,
                    {{"plus", g.plus.size()},
                     {"minus", g.minus.size()},
                     {"kind", g.kind.size()},
                     {"normal", g.normal.size()}});
  // Triangles are listed by unsplit node numbers, which are the plus copies away from
  // intersection nodes (where fault surfaces meet, every copy is a sector's: any may be plus).
  // A node there has a kind of its own, or more copies than its sides (a tip or a node on
  // the outer boundary where another fracture passes).
  std::map<Index, std::vector<Index>> copies;  // fracture node -> its copies
  for (std::size_t i = 0; i < n; ++i) copies[g.node[i]];
  for (Index c = 0; c < static_cast<Index>(s.origin.size()); ++c) {
    const auto it = copies.find(s.origin[c]);
    if (it != copies.end()) it->second.push_back(c);
  }
  std::vector<char> meets(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    meets[i] = g.kind[i] == FractureNodeKind::crossing || g.kind[i] == FractureNodeKind::abutting ||
               g.kind[i] == FractureNodeKind::joined ||
               copies[g.node[i]].size() > (g.kind[i] == FractureNodeKind::tip ? 1u : 2u);
  const auto copiesOf = [&](std::size_t i) {  // of fracture node i
    return meets[i] ? copies.at(g.node[i]) : std::vector<Index>{g.plus[i], g.minus[i]};
  };
  std::map<Index, std::size_t> local;  // plus copy (node at intersections) -> fracture node
  for (std::size_t i = 0; i < n; ++i) {
    requireCopies(f, s, g, i);
    if (!(std::abs(g.normal[i].norm() - 1) <= 1e-9))
      f.fail("normal", "fracture node " + std::to_string(i) + ": 'normal' must be a unit vector" +
                           std::string(resplit));
    if (!local.emplace(meets[i] ? g.node[i] : g.plus[i], i).second)
      f.fail("node",
             "fracture node " + std::to_string(i) + ": listed twice" + std::string(resplit));
  }
  if (n < 3) f.fail("node", "key 'node': expected at least three fracture nodes (one triangle)");
  for (const auto& t : f.getIntTupleList<3>("triangles")) {
    std::array<std::size_t, 3> k{};
    for (int j = 0; j < 3; ++j) {
      const auto it = local.find(static_cast<Index>(t[j]));
      if (it == local.end())
        f.fail("triangles", "key 'triangles': " + std::to_string(t[j]) +
                                " is not the plus copy of a node of this fracture" +
                                std::string(resplit));
      k[j] = it->second;
    }
    // At an intersection node the triangle's lips use the copies of the sectors beside it,
    // not necessarily the node's plus and minus: some copies of its nodes must make a face.
    bool lips = true;
    if (meets[k[0]] || meets[k[1]] || meets[k[2]]) {
      int faces = 0;
      for (Index a : copiesOf(k[0]))
        for (Index b : copiesOf(k[1]))
          for (Index c : copiesOf(k[2])) faces += isFace(a, b, c);
      lips = faces >= 1;
    } else {
      lips = isFace(g.plus[k[0]], g.plus[k[1]], g.plus[k[2]]) &&
             isFace(g.minus[k[0]], g.minus[k[1]], g.minus[k[2]]);
    }
    if (!lips)
      f.fail("triangles", "key 'triangles': (" + std::to_string(t[0]) + " " + std::to_string(t[1]) +
                              " " + std::to_string(t[2]) +
                              "): its 'plus' and its 'minus' copies must each be a face of a "
                              "tetrahedron (the two sides of the cut)" +
                              std::string(resplit));
    g.triangles.push_back({meets[k[0]] ? g.node[k[0]] : g.plus[k[0]],
                           meets[k[1]] ? g.node[k[1]] : g.plus[k[1]],
                           meets[k[2]] ? g.node[k[2]] : g.plus[k[2]]});
  }
  if (g.triangles.empty()) f.fail("triangles", "key 'triangles': expected at least one triangle");
}

}  // namespace

void writeSplitMesh(const SplitMesh& split, const std::string& path, int precision) {
  const Mesh& m = split.mesh;
  DictionaryWriter w("dictionary", "splitMesh",
                     "written by splitFractureNodes; node numbers are 0-based");
  w.setPrecision(precision);
  w.entryString("source", m.source);
  w.entryString("format", m.format);
  FRICTION_ASSERT(m.dim == 2 || m.dim == 3, "writeSplitMesh: a mesh is 2D or 3D");
  const bool is3D = m.dim == 3;
  if (is3D) {
    // A 2D file has no 'dimension' (2 when absent), so that it reads as before.
    w.entry("dimension", 3);
    w.entry("points", m.points);
  } else {
    std::vector<Vector2> points;
    points.reserve(m.points.size());
    for (const Point& p : m.points) points.push_back(p.head<2>());
    w.entry("points", points);
  }
  w.entry("origin", toInts(split.origin));
  if (is3D) {
    std::vector<std::array<int, 4>> tets;
    tets.reserve(m.cellRegion.size());
    for (Index t = 0; t < m.numCells(); ++t)
      tets.push_back(
          {m.cellVertex(t, 0), m.cellVertex(t, 1), m.cellVertex(t, 2), m.cellVertex(t, 3)});
    w.entry("tetrahedra", tets);
  } else {
    std::vector<std::array<int, 3>> tris;
    tris.reserve(m.cellRegion.size());
    for (Index t = 0; t < m.numCells(); ++t)
      tris.push_back({m.cellVertex(t, 0), m.cellVertex(t, 1), m.cellVertex(t, 2)});
    w.entry("triangles", tris);
  }
  w.entry("regions", m.cellRegion);
  // [beyond] The regions' names (constant/mechanicalProperties may key materials by them),
  // written only when the cells lie in several regions: a one-region mesh needs no name to
  // take one material, and its split mesh stays as it was. Optional on reading. A name that is
  // no dictionary word, or that two regions share, is left out (region<N> reaches it).
  if (!m.regionNames.empty() &&
      std::adjacent_find(m.cellRegion.begin(), m.cellRegion.end(), std::not_equal_to<int>()) !=
          m.cellRegion.end()) {
    std::map<std::string, int> uses;
    for (const auto& entry : m.regionNames) ++uses[entry.second];
    w.beginDict("regionNames");
    for (const auto& [number, name] : m.regionNames)
      if (detail::isSafeWord(name) && uses[name] == 1) w.entry(name, number);
    w.endDict();
  }

  w.beginDict("patches");
  for (const auto& [label, name] : m.labelNames) {
    const bool isFracture =
        std::any_of(split.fractures.begin(), split.fractures.end(),
                    [&, l = label](const FractureGeometry& g) { return g.label == l; });
    if (isFracture) continue;  // its facets live in 'fractures'
    w.beginDict(name);
    w.entry("label", label);
    if (is3D) {
      std::vector<std::array<int, 3>> triangles;
      for (Index e = 0; e < m.numFacets(); ++e)
        if (m.facetLabel[e] == label)
          triangles.push_back({m.facetVertex(e, 0), m.facetVertex(e, 1), m.facetVertex(e, 2)});
      w.entry("triangles", triangles);
    } else {
      std::vector<std::array<int, 2>> edges;
      for (Index e = 0; e < m.numFacets(); ++e)
        if (m.facetLabel[e] == label) edges.push_back({m.facetVertex(e, 0), m.facetVertex(e, 1)});
      w.entry("edges", edges);
    }
    w.endDict();
  }
  w.endDict();

  w.beginDict("fractures");
  for (const FractureGeometry& g : split.fractures) {
    w.beginDict(g.name);
    w.entry("label", g.label);
    w.entry("node", toInts(g.node));
    w.entry("plus", toInts(g.plus));
    w.entry("minus", toInts(g.minus));
    std::vector<std::string> kinds;
    for (FractureNodeKind k : g.kind) kinds.push_back(toString(k));
    w.entryWords("kind", kinds);
    if (is3D) {
      w.entry("normal", g.normal);
      std::vector<std::array<int, 3>> triangles;
      for (const auto& t : g.triangles) triangles.push_back({t[0], t[1], t[2]});
      w.entry("triangles", triangles);
    } else {
      w.entry("arclength", g.arclength);
      std::vector<Vector2> normal;
      for (const Point& p : g.normal) normal.push_back(p.head<2>());
      w.entry("normal", normal);
      w.entry("tangent", g.tangent);
    }
    w.endDict();
  }
  w.endDict();

  if (!split.madeFrom.empty()) {
    w.beginDict("madeFrom");
    w.entryString("mesh", split.madeFrom.mesh);
    w.entryString("meshHash", split.madeFrom.meshHash);
    w.entryString("meshDictHash", split.madeFrom.meshDictHash);
    w.endDict();
  }
  w.writeAtomic(path);
}

SplitMesh readSplitMesh(const std::string& path) {
  const Dictionary dict = Dictionary::read(path, DictionaryLimits::dataFile());
  SplitMesh s;
  Mesh& m = s.mesh;
  m.source = dict.getWord("source");
  m.format = dict.getWord("format");
  m.dim = 2;
  if (dict.found("dimension")) {
    const long d = dict.getInt("dimension", Bounds::nonNegative());
    if (d != 2 && d != 3)
      dict.fail("dimension", "key 'dimension': " + std::to_string(d) + " (expected 2 or 3)");
    m.dim = static_cast<int>(d);
  }
  const bool is3D = m.dim == 3;
  const char* const cellKey = is3D ? "tetrahedra" : "triangles";
  const std::string cell = cellName(m.dim);
  if (is3D)
    m.points = dict.getPointList("points");
  else
    for (const Vector2& p : dict.getVectorList("points")) m.points.emplace_back(p.x(), p.y(), 0.0);
  const Index nPoints = m.numPoints();

  auto checkIndex = [&](const Dictionary& d, const std::string& key, long i) -> Index {
    if (i < 0 || i >= nPoints)
      d.fail(key, "key '" + key + "': node number " + std::to_string(i) +
                      " out of range (expected 0 to " + std::to_string(nPoints - 1) + ")");
    return static_cast<Index>(i);
  };

  for (long o : dict.getIntList("origin")) s.origin.push_back(checkIndex(dict, "origin", o));
  if (static_cast<Index>(s.origin.size()) != nPoints)
    dict.fail("origin", "key 'origin': " + std::to_string(s.origin.size()) +
                            " entries, expected one per point (" + std::to_string(nPoints) + ")");

  // The unsplit points come first (origin[i] == i), their copies after them.
  Index numOriginal = 0;
  while (numOriginal < nPoints && s.origin[numOriginal] == numOriginal) ++numOriginal;
  for (Index i = numOriginal; i < nPoints; ++i)
    if (s.origin[i] >= numOriginal)
      dict.fail("origin", "key 'origin': point " + std::to_string(i) + " is a copy of point " +
                              std::to_string(s.origin[i]) +
                              ", expected a copy of one of the unsplit points 0 to " +
                              std::to_string(numOriginal - 1) +
                              " (the unsplit points come first, each its own origin)" + resplit);

  auto addCell = [&](std::initializer_list<long> t) {
    for (long v : t) m.cellVertices.push_back(checkIndex(dict, cellKey, v));
    const double measure = m.signedMeasure(m.numCells() - 1);
    const std::string which =
        "key '" + std::string(cellKey) + "': " + cell + " " + std::to_string(m.numCells() - 1);
    if (!std::isfinite(measure))
      dict.fail(cellKey, which + " has " + (is3D ? "a volume" : "an area") +
                             " that is not a finite number (coordinates too large in "
                             "'points'?)");
    if (!(measure > 0))
      dict.fail(cellKey, which + (is3D ? " is inverted or degenerate (expected a positive "
                                         "volume)"
                                       : " is clockwise or degenerate (expected "
                                         "counter-clockwise)"));
  };
  if (is3D)
    for (const auto& t : dict.getIntTupleList<4>("tetrahedra")) addCell({t[0], t[1], t[2], t[3]});
  else
    for (const auto& t : dict.getIntTupleList<3>("triangles")) addCell({t[0], t[1], t[2]});
  if (m.cellVertices.empty())
    dict.fail(cellKey, "key '" + std::string(cellKey) + "': expected at least one " + cell);
  {
    const int nv = m.verticesPerCell();
    std::vector<std::pair<std::array<Index, 4>, Index>> sorted;
    for (Index t = 0; t < m.numCells(); ++t) {
      std::array<Index, 4> k{-1, -1, -1, -1};
      for (int j = 0; j < nv; ++j) k[j] = m.cellVertex(t, j);
      // Insertion sort of the nv ≤ 4 vertices: std::sort on them made GCC 12 warn
      // (-Warray-bounds, about its 16-element insertion threshold: a false positive).
      for (int a = 1; a < nv; ++a)
        for (int b = a; b > 0 && k[b] < k[b - 1]; --b) std::swap(k[b], k[b - 1]);
      sorted.emplace_back(k, t);
    }
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i].first == sorted[i - 1].first)
        dict.fail(cellKey, "key '" + std::string(cellKey) + "': " + cell + "s " +
                               std::to_string(sorted[i - 1].second) + " and " +
                               std::to_string(sorted[i].second) + " have the same vertices " +
                               "(expected each " + cell + " once)" + resplit);
  }
  // A point no triangle uses would be a node without stiffness (and no row in the
  // split-to-unsplit map the solver builds cell by cell).
  std::vector<char> used(nPoints, 0);
  for (Index v : m.cellVertices) used[v] = 1;
  for (Index i = 0; i < nPoints; ++i)
    if (!used[i])
      dict.fail("points", "key 'points': point " + std::to_string(i) + " is used by no " + cell +
                              " (expected every point to be a vertex of a " + cell + ")" + resplit);
  // Built here once, kept by the mesh for the solver (boundary conditions, FE spaces).
  const auto topology = m.topology();
  const auto isSide = [&](Index a, Index b) { return topology->findFacet({a, b}) >= 0; };
  const auto isFace = [&](Index a, Index b, Index c) {
    return topology->findFacet({a, b, c}) >= 0;
  };
  for (long r : dict.getIntList("regions")) m.cellRegion.push_back(static_cast<int>(r));
  if (static_cast<Index>(m.cellRegion.size()) != m.numCells())
    dict.fail("regions", "key 'regions': " + std::to_string(m.cellRegion.size()) +
                             " entries, expected one per " + cell + " (" +
                             std::to_string(m.numCells()) + ")");
  if (const Dictionary* names = dict.findDict("regionNames"))
    for (const std::string& name : names->keys())
      m.regionNames[static_cast<int>(names->getInt(name, Bounds::nonNegative()))] = name;

  const Dictionary& patches = dict.subDict("patches");
  for (const std::string& name : patches.keys()) {
    const Dictionary& p = patches.subDict(name);
    const int label = static_cast<int>(p.getInt("label", Bounds::nonNegative()));
    m.labelNames[label] = name;
    if (is3D) {
      for (const auto& e : p.getIntTupleList<3>("triangles")) {
        const Index a = checkIndex(p, "triangles", e[0]), b = checkIndex(p, "triangles", e[1]),
                    c = checkIndex(p, "triangles", e[2]);
        m.addFacet({a, b, c}, label);
        if (!isFace(a, b, c))
          p.fail("triangles", "key 'triangles': the triangle (" + std::to_string(e[0]) + " " +
                                  std::to_string(e[1]) + " " + std::to_string(e[2]) +
                                  ") is not a face of any tetrahedron (expected the patch's "
                                  "triangles to be tetrahedron faces)" +
                                  resplit);
      }
      continue;
    }
    for (const auto& e : p.getIntTupleList<2>("edges")) {
      const Index a = checkIndex(p, "edges", e[0]), b = checkIndex(p, "edges", e[1]);
      m.addFacet({a, b}, label);
      if (!isSide(a, b))
        p.fail("edges", "key 'edges': the edge (" + std::to_string(e[0]) + " " +
                            std::to_string(e[1]) +
                            ") is not a side of any triangle (expected the patch's edges to be "
                            "triangle sides)" +
                            resplit);
    }
  }

  const Dictionary& fractures = dict.subDict("fractures");
  for (const std::string& name : fractures.keys()) {
    const Dictionary& f = fractures.subDict(name);
    FractureGeometry g;
    g.name = name;
    g.label = static_cast<int>(f.getInt("label", Bounds::nonNegative()));
    m.labelNames[g.label] = name;
    for (long i : f.getIntList("node")) g.node.push_back(checkIndex(f, "node", i));
    for (long i : f.getIntList("plus")) g.plus.push_back(checkIndex(f, "plus", i));
    for (long i : f.getIntList("minus")) g.minus.push_back(checkIndex(f, "minus", i));
    for (const std::string& k : f.getWordList("kind")) {
      if (k == "interior")
        g.kind.push_back(FractureNodeKind::interior);
      else if (k == "boundary")
        g.kind.push_back(FractureNodeKind::boundary);
      else if (k == "tip")
        g.kind.push_back(FractureNodeKind::tip);
      else if (k == "crossing")
        g.kind.push_back(FractureNodeKind::crossing);
      else if (k == "abutting")
        g.kind.push_back(FractureNodeKind::abutting);
      else if (k == "joined")
        g.kind.push_back(FractureNodeKind::joined);
      else
        f.fail("kind", "key 'kind': '" + k +
                           "' is not a node kind (expected interior, boundary, tip, crossing, "
                           "abutting or joined)");
    }
    const std::size_t n = g.node.size();
    if (is3D) {
      readSurface(f, g, s, isFace);
      s.fractures.push_back(std::move(g));
      continue;
    }
    g.arclength = f.getScalarList("arclength");
    for (const Vector2& v : f.getVectorList("normal")) g.normal.emplace_back(v.x(), v.y(), 0.0);
    g.tangent = f.getVectorList("tangent");
    requireOnePerNode(f, n,
                      {{"plus", g.plus.size()},
                       {"minus", g.minus.size()},
                       {"kind", g.kind.size()},
                       {"arclength", g.arclength.size()},
                       {"normal", g.normal.size()},
                       {"tangent", g.tangent.size()}});
    for (std::size_t i = 0; i < n; ++i) {
      requireCopies(f, s, g, i);
      // The solver takes the frame as written: it must be one (SignConventions.hpp).
      const double tol = 1e-9;
      if (!(std::abs(g.tangent[i].norm() - 1) <= tol) ||
          !(std::abs(g.normal[i].norm() - 1) <= tol) ||
          !((g.normal[i].head<2>() - normalFromTangent(g.tangent[i])).norm() <= tol))
        f.fail("normal", "fracture node " + std::to_string(i) +
                             ": 'normal' and 'tangent' must be unit vectors with normal = "
                             "(t_y, -t_x) (SignConventions.hpp)" +
                             std::string(resplit));
      if (!std::isfinite(g.arclength[i]) ||
          (i == 0 ? g.arclength[i] != 0 : !(g.arclength[i] > g.arclength[i - 1])))
        f.fail("arclength", "fracture node " + std::to_string(i) +
                                ": 'arclength' must start at 0 and grow along the fracture" +
                                std::string(resplit));
      // At a crossing the copies are those of the sectors towards the next node.
      if (i > 0 && g.kind[i] != FractureNodeKind::crossing &&
          (!isSide(g.plus[i - 1], g.plus[i]) || !isSide(g.minus[i - 1], g.minus[i])))
        f.fail("plus", "fracture nodes " + std::to_string(i - 1) + " and " + std::to_string(i) +
                           ": their 'plus' and 'minus' copies must be joined by triangle sides "
                           "(consecutive nodes along the fracture)" +
                           std::string(resplit));
    }
    if (n < 2) f.fail("node", "key 'node': expected at least two fracture nodes (one edge)");
    s.fractures.push_back(std::move(g));
  }
  if (const Dictionary* made = dict.findDict("madeFrom")) {
    s.madeFrom.mesh = made->getWord("mesh");
    s.madeFrom.meshHash = made->getWord("meshHash");
    s.madeFrom.meshDictHash = made->getWord("meshDictHash");
    made->checkAllRead();
  }
  dict.checkAllRead();
  return s;
}

std::string fileHash(const std::string& path) {
  // Streamed, not read whole: the mesh may be large. Regular files only (InputFile.hpp).
  const InputFileHandle f = openInputFile(path, InputFileRole{});
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
  unsigned char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0)
    for (std::size_t i = 0; i < n; ++i) {
      h ^= buffer[i];
      h *= 1099511628211ull;  // FNV prime
    }
  if (std::ferror(f.get()))
    throw InputError(path, std::string("cannot read: ") + std::strerror(errno));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return std::string("fnv1a64:") + hex;
}

void checkSplitMeshCurrent(const std::string& caseDir, const SplitMesh& split) {
  const std::string splitPath = (fs::path(caseDir) / "constant" / "splitMesh").string();
  const std::string redo = ". Split the mesh again: splitFractureNodes -case " + caseDir +
                           " -overwrite (then run frictionSolver again)";
  const SplitMeshRecord& made = split.madeFrom;
  if (made.empty())
    throw InputError(splitPath,
                     "does not record which mesh and system/meshDict it was made "
                     "from (written by an older splitFractureNodes), so it may be "
                     "stale" +
                         redo);
  const std::string dictPath = (fs::path(caseDir) / "system" / "meshDict").string();
  if (!fs::exists(dictPath))
    throw InputError(splitPath, "was made from " + dictPath + ", which no longer exists" + redo);
  if (fileHash(dictPath) != made.meshDictHash)
    throw InputError(splitPath, "is stale: " + dictPath +
                                    " changed after the mesh was split (its hash is not the "
                                    "recorded " +
                                    made.meshDictHash + ")" + redo);
  const std::string meshPath = (fs::path(caseDir) / made.mesh).lexically_normal().string();
  if (!fs::exists(meshPath))
    throw InputError(splitPath,
                     "was made from the mesh file " + meshPath + ", which no longer exists" + redo);
  if (fileHash(meshPath) != made.meshHash)
    throw InputError(splitPath, "is stale: the mesh file " + meshPath +
                                    " changed after it was split (e.g. ./Allmesh ran after "
                                    "splitFractureNodes; its hash is not the recorded " +
                                    made.meshHash + ")" + redo);
}

}  // namespace friction
