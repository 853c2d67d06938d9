// constant/splitMesh writer and reader: see SplitMeshIO.hpp.
#include "friction/fracture/SplitMeshIO.hpp"

#include <algorithm>
#include <map>

#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"

namespace friction {

namespace {

template <typename T>
std::vector<int> toInts(const std::vector<T>& v) {
  return std::vector<int>(v.begin(), v.end());
}

}  // namespace

void writeSplitMesh(const SplitMesh& split, const std::string& path, int precision) {
  const Mesh& m = split.mesh;
  DictionaryWriter w("dictionary", "splitMesh",
                     "written by splitFractureNodes; node numbers are 0-based");
  w.setPrecision(precision);
  w.entryString("source", m.source);
  w.entryString("format", m.format);
  w.entry("points", m.points);
  w.entry("origin", toInts(split.origin));
  std::vector<std::array<int, 3>> tris(m.triangles.begin(), m.triangles.end());
  w.entry("triangles", tris);
  w.entry("regions", m.triangleRegion);

  w.beginDict("patches");
  for (const auto& [label, name] : m.labelNames) {
    std::vector<std::array<int, 2>> edges;
    for (std::size_t e = 0; e < m.edges.size(); ++e)
      if (m.edgeLabel[e] == label) edges.push_back({m.edges[e][0], m.edges[e][1]});
    const bool isFracture =
        std::any_of(split.fractures.begin(), split.fractures.end(),
                    [&, l = label](const FractureGeometry& g) { return g.label == l; });
    if (isFracture) continue;  // its edges live in 'fractures'
    w.beginDict(name);
    w.entry("label", label);
    w.entry("edges", edges);
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
    w.entry("arclength", g.arclength);
    w.entry("normal", g.normal);
    w.entry("tangent", g.tangent);
    w.endDict();
  }
  w.endDict();
  w.writeAtomic(path);
}

SplitMesh readSplitMesh(const std::string& path) {
  const Dictionary dict = Dictionary::read(path);
  SplitMesh s;
  Mesh& m = s.mesh;
  m.source = dict.getWord("source");
  m.format = dict.getWord("format");
  m.points = dict.getVectorList("points");
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

  for (const auto& t : dict.getIntTupleList<3>("triangles")) {
    m.triangles.push_back({checkIndex(dict, "triangles", t[0]), checkIndex(dict, "triangles", t[1]),
                           checkIndex(dict, "triangles", t[2])});
    if (m.signedArea(m.numTriangles() - 1) <= 0)
      dict.fail("triangles", "key 'triangles': triangle " + std::to_string(m.numTriangles() - 1) +
                                 " is clockwise or degenerate (expected counter-clockwise)");
  }
  for (long r : dict.getIntList("regions")) m.triangleRegion.push_back(static_cast<int>(r));
  if (m.triangleRegion.size() != m.triangles.size())
    dict.fail("regions", "key 'regions': " + std::to_string(m.triangleRegion.size()) +
                             " entries, expected one per triangle (" +
                             std::to_string(m.triangles.size()) + ")");

  const Dictionary& patches = dict.subDict("patches");
  for (const std::string& name : patches.keys()) {
    const Dictionary& p = patches.subDict(name);
    const int label = static_cast<int>(p.getInt("label", Bounds::nonNegative()));
    m.labelNames[label] = name;
    for (const auto& e : p.getIntTupleList<2>("edges")) {
      m.edges.push_back({checkIndex(p, "edges", e[0]), checkIndex(p, "edges", e[1])});
      m.edgeLabel.push_back(label);
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
      if (k == "interior") g.kind.push_back(FractureNodeKind::interior);
      else if (k == "boundary") g.kind.push_back(FractureNodeKind::boundary);
      else if (k == "tip") g.kind.push_back(FractureNodeKind::tip);
      else f.fail("kind", "key 'kind': '" + k + "' is not a node kind (expected interior, "
                          "boundary or tip)");
    }
    g.arclength = f.getScalarList("arclength");
    g.normal = f.getVectorList("normal");
    g.tangent = f.getVectorList("tangent");
    const std::size_t n = g.node.size();
    for (const auto& [key, size] :
         std::map<std::string, std::size_t>{{"plus", g.plus.size()}, {"minus", g.minus.size()},
                                            {"kind", g.kind.size()},
                                            {"arclength", g.arclength.size()},
                                            {"normal", g.normal.size()},
                                            {"tangent", g.tangent.size()}})
      if (size != n)
        f.fail(key, "key '" + key + "': " + std::to_string(size) +
                        " entries, expected one per fracture node (" + std::to_string(n) + ")");
    for (std::size_t i = 0; i < n; ++i) {
      if (s.origin[g.plus[i]] != g.node[i] || s.origin[g.minus[i]] != g.node[i])
        f.fail("plus", "fracture node " + std::to_string(i) +
                           ": 'plus' and 'minus' must be copies of 'node' (see 'origin')");
      if ((g.plus[i] == g.minus[i]) != (g.kind[i] == FractureNodeKind::tip))
        f.fail("kind", "fracture node " + std::to_string(i) +
                           ": exactly the tips have plus == minus");
    }
    s.fractures.push_back(std::move(g));
  }
  dict.checkAllRead();
  return s;
}

}  // namespace friction
