// Node splitting along fractures (docs/method.md). The rule is topological: around a fracture
// node, the triangles that still share a non-fracture edge through the node form one side.
// Geometry enters only to tell which side is Ω⁺ (SignConventions.hpp).
#include "friction/fracture/SplitMesh.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

#include "friction/fracture/SignConventions.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

namespace {

// Minimal union-find over a few dozen triangles around one node.
struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

// The rule of the splitting, in any dimension: the cells around node v (`cells`, all of them)
// that stay connected through facets that contain v and are not fracture facets
// (fractureOfFacet[facet] >= 0), grouped: one group per copy of v. Keyed by a group's root,
// each group in the order of `cells`.
std::map<int, std::vector<Index>> sidesAround(Index v, const std::vector<Index>& cells,
                                              const MeshTopology& topo,
                                              const std::vector<int>& fractureOfFacet) {
  UnionFind uf(static_cast<int>(cells.size()));
  for (std::size_t p = 0; p < cells.size(); ++p)
    for (int k = 0; k < topo.verticesPerCell(); ++k) {
      if (topo.cellVertex(cells[p], k) == v) continue;  // the facet opposite v lacks it
      const Index side = topo.cellFacet(cells[p], k);
      if (fractureOfFacet[side] >= 0 || topo.numCellsOf(side) != 2) continue;
      const Index c0 = topo.cellOf(side, 0).cell, c1 = topo.cellOf(side, 1).cell;
      const Index other = c0 == cells[p] ? c1 : c0;
      const auto q = std::find(cells.begin(), cells.end(), other) - cells.begin();
      uf.unite(static_cast<int>(p), static_cast<int>(q));
    }
  std::map<int, std::vector<Index>> groups;
  for (std::size_t p = 0; p < cells.size(); ++p)
    groups[uf.find(static_cast<int>(p))].push_back(cells[p]);
  return groups;
}

// The split mesh before any node is split: the mesh's points, cells and names, every node
// its own origin; the patches are added by the caller.
SplitMesh unsplitCopy(const Mesh& mesh) {
  SplitMesh out;
  out.mesh.source = mesh.source;
  out.mesh.format = mesh.format;
  out.mesh.dim = mesh.dim;
  out.mesh.points = mesh.points;
  out.mesh.cellVertices = mesh.cellVertices;
  out.mesh.cellRegion = mesh.cellRegion;
  out.mesh.labelNames = mesh.labelNames;
  out.mesh.regionNames = mesh.regionNames;
  out.origin.resize(mesh.points.size());
  std::iota(out.origin.begin(), out.origin.end(), 0);
  return out;
}

// Split node v: the Ω⁺ copy keeps the node number, the Ω⁻ copy is appended to out's points,
// and the cells of the group on the Ω⁻ side (sideOf < 0, in the order of `groups`) are
// renumbered to it. Returns the Ω⁻ copy.
Index appendMinusCopy(SplitMesh& out, const Mesh& mesh, Index v,
                      const std::map<int, std::vector<Index>>& groups, const int* sideOf) {
  const Index copy = static_cast<Index>(out.mesh.points.size());
  out.mesh.points.push_back(mesh.points[v]);
  out.origin.push_back(v);
  int gi = 0;
  for (const auto& [root, list] : groups) {
    if (sideOf[gi++] < 0)
      for (Index t : list)
        for (Index& x : out.mesh.cell(t))
          if (x == v) x = copy;
  }
  return copy;
}

// The edges (a < b) of the boundary facets of a 3D mesh: where a surface's edge lies on ∂Ω.
std::set<std::pair<Index, Index>> outerBoundaryEdges(const MeshTopology& topo) {
  std::set<std::pair<Index, Index>> edges;
  for (Index f = 0; f < topo.numFacets(); ++f)
    if (topo.isBoundary(f))
      for (int k = 0; k < 3; ++k)
        edges.insert(std::minmax(topo.facetVertex(f, k), topo.facetVertex(f, (k + 1) % 3)));
  return edges;
}

SplitMesh splitSurfaces(const Mesh& mesh, const std::vector<FractureSpec>& specs);

}  // namespace

const char* toString(FractureNodeKind kind) {
  switch (kind) {
    case FractureNodeKind::interior:
      return "interior";
    case FractureNodeKind::boundary:
      return "boundary";
    case FractureNodeKind::tip:
      return "tip";
    case FractureNodeKind::crossing:
      return "crossing";
    case FractureNodeKind::abutting:
      return "abutting";
    case FractureNodeKind::joined:
      return "joined";
  }
  return "?";
}

Index FractureGeometry::numTips() const {
  return static_cast<Index>(std::count(kind.begin(), kind.end(), FractureNodeKind::tip));
}

Index FractureGeometry::numDuplicated() const {
  Index n = 0;
  for (std::size_t i = 0; i < plus.size(); ++i) n += plus[i] != minus[i];
  return n;
}

Index FractureGeometry::numOfKind(FractureNodeKind k) const {
  return static_cast<Index>(std::count(kind.begin(), kind.end(), k));
}

Index FractureGeometry::numGluedTriangles() const {
  // A tip keeps one node (plus == minus); triangles are listed by ⁺ copies, which are the
  // unsplit node numbers.
  std::set<Index> tips;
  for (Index i = 0; i < numNodes(); ++i)
    if (kind[i] == FractureNodeKind::tip) tips.insert(plus[i]);
  Index glued = 0;
  for (const auto& t : triangles)
    if (tips.count(t[0]) && tips.count(t[1]) && tips.count(t[2])) ++glued;
  return glued;
}

double FractureGeometry::area(const std::vector<Point>& points) const {
  double a = 0;
  for (const auto& t : triangles)
    a += 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
  return a;
}

double FractureGeometry::tipLineLength(const Mesh& unsplit) const {
  if (triangles.empty()) return 0.0;
  const auto topology = unsplit.topology();
  const MeshTopology& topo = *topology;
  std::map<std::pair<Index, Index>, int> uses;  // edge of the surface -> its triangles
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  const std::set<std::pair<Index, Index>> outer = outerBoundaryEdges(topo);
  double length = 0;
  for (const auto& [edge, count] : uses)
    if (count == 1 && !outer.count(edge))
      length += (unsplit.points[edge.second] - unsplit.points[edge.first]).norm();
  return length;
}

Index SplitMesh::numOriginalPoints() const {
  Index n = 0;
  for (Index o : origin) n = std::max(n, o + 1);
  return n;
}

SplitMesh splitFractures(const Mesh& mesh, const std::vector<FractureSpec>& specs) {
  if (mesh.dim == 3) return splitSurfaces(mesh, specs);
  const std::string& file = mesh.source;
  const Index nPoints = mesh.numPoints();

  // Triangle sides -> the (at most two) triangles they bound.
  const auto topology = mesh.topology();
  const MeshTopology& topo = *topology;
  if (!topo.overSharedFacets().empty()) {
    const Index f = topo.overSharedFacets().front();
    const Index a = topo.facetVertex(f, 0), b = topo.facetVertex(f, 1);
    throw InputError(file, "the mesh is not a valid 2D triangulation: the edge " +
                               formatPoint(mesh.points[a], mesh.dim) + "-" +
                               formatPoint(mesh.points[b], mesh.dim) + " is a side of " +
                               std::to_string(topo.numCellsOf(f)) +
                               " triangles (at most 2 expected)");
  }

  // Points that coincide with another point (only a split mesh has them).
  auto hasTwin = [&](Index v) {
    for (Index w = 0; w < nPoints; ++w)
      if (w != v && (mesh.points[w].head<2>() - mesh.points[v].head<2>()).norm() <=
                        1e-12 * (1 + mesh.points[v].head<2>().norm()))
        return true;
    return false;
  };

  // 1. Collect each fracture's edges and check each is an interior side of the triangulation.
  std::vector<std::vector<std::array<Index, 2>>> fracEdges(specs.size());
  std::vector<int> fractureOfEdge(static_cast<std::size_t>(topo.numFacets()),
                                  -1);  // side -> fracture
  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    for (Index e = 0; e < mesh.numFacets(); ++e) {
      if (mesh.facetLabel[e] != spec.label) continue;
      const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1);
      const Index side = topo.findFacet({a, b});
      if (side >= 0 && fractureOfEdge[side] >= 0) {
        if (fractureOfEdge[side] == static_cast<int>(f)) continue;  // listed twice in one patch
        throw InputError(spec.where, "fractures '" + specs[fractureOfEdge[side]].name + "' and '" +
                                         spec.name + "' share the edge " +
                                         formatPoint(mesh.points[a], mesh.dim) + "-" +
                                         formatPoint(mesh.points[b], mesh.dim) + " of " + file +
                                         ": a fracture patch must be listed once");
      }
      if (side < 0)
        throw InputError(file, "fracture '" + spec.name + "': its edge " +
                                   formatPoint(mesh.points[a], mesh.dim) + "-" +
                                   formatPoint(mesh.points[b], mesh.dim) +
                                   " is not a side of any triangle");
      if (topo.isBoundary(side)) {
        if (hasTwin(a) || hasTwin(b))
          throw InputError(file, "fracture '" + spec.name + "' is already split in this mesh " +
                                     "(its edge " + formatPoint(mesh.points[a], mesh.dim) + "-" +
                                     formatPoint(mesh.points[b], mesh.dim) +
                                     " bounds one triangle and its nodes have coincident " +
                                     "copies); give splitFractureNodes the unsplit mesh");
        throw InputError(file, "fracture '" + spec.name + "': its edge " +
                                   formatPoint(mesh.points[a], mesh.dim) + "-" +
                                   formatPoint(mesh.points[b], mesh.dim) +
                                   " lies on the outer boundary of the mesh; a fracture must be "
                                   "inside the body (a side of two triangles)");
      }
      fractureOfEdge[side] = static_cast<int>(f);
      fracEdges[f].push_back({a, b});
    }
    if (fracEdges[f].empty())
      throw InputError(spec.where, "fracture '" + spec.name + "' (label " +
                                       std::to_string(spec.label) + ") has no edges in " + file);
  }

  // 2. Node -> incident fracture edges. Edges of several fractures at a node make it a
  //    junction (docs/method.md §4, "Junctions"); one fracture with more than two edges at a
  //    node branches, which a curve cannot: each branch must have its own label.
  std::unordered_map<Index, std::vector<std::pair<int, Index>>> nodeEdges;  // (fracture, other end)
  for (std::size_t f = 0; f < specs.size(); ++f)
    for (const auto& [a, b] : fracEdges[f]) {
      nodeEdges[a].push_back({static_cast<int>(f), b});
      nodeEdges[b].push_back({static_cast<int>(f), a});
    }
  // Edges of fracture f at node v, and the fractures at v.
  auto edgesOfAt = [&](Index v, int f) {
    int c = 0;
    for (const auto& fe : nodeEdges[v]) c += fe.first == f;
    return c;
  };
  auto fracturesAt = [&](Index v) {
    std::vector<int> list;
    for (const auto& fe : nodeEdges[v])
      if (std::find(list.begin(), list.end(), fe.first) == list.end()) list.push_back(fe.first);
    return list;
  };
  for (const auto& [v, list] : nodeEdges)
    for (int f : fracturesAt(v))
      if (edgesOfAt(v, f) > 2)
        throw InputError(
            file, "fracture '" + specs[f].name + "' branches at " +
                      formatPoint(mesh.points[v], mesh.dim) + " (" +
                      std::to_string(edgesOfAt(v, f)) +
                      " of its edges meet there): a fracture is one curve; give each branch its "
                      "own label and list each as a fracture (fractures may meet: junctions)");

  // A curve whose nodes all have two of its edges is closed: refuse before anything else.
  for (std::size_t f = 0; f < specs.size(); ++f) {
    bool hasEnd = false;
    for (const auto& [a, b] : fracEdges[f])
      hasEnd |= edgesOfAt(a, static_cast<int>(f)) == 1 || edgesOfAt(b, static_cast<int>(f)) == 1;
    if (!hasEnd)
      throw InputError(specs[f].where, "fracture '" + specs[f].name +
                                           "' is a closed curve; only open fractures (two ends) "
                                           "are supported");
  }

  // 3. A triangle with all three vertices on one fracture has no node off it: refuse.
  for (Index t = 0; t < mesh.numCells(); ++t) {
    const auto tri = mesh.cell(t);
    auto it = nodeEdges.find(tri[0]);
    if (it == nodeEdges.end()) continue;
    for (int f0 : fracturesAt(tri[0])) {
      bool all = true;
      for (int k = 1; k < 3 && all; ++k) all = nodeEdges.count(tri[k]) && edgesOfAt(tri[k], f0) > 0;
      if (all)
        throw InputError(file, "triangle " + std::to_string(t + 1) + " " +
                                   formatPoint(mesh.points[tri[0]], mesh.dim) + " " +
                                   formatPoint(mesh.points[tri[1]], mesh.dim) + " " +
                                   formatPoint(mesh.points[tri[2]], mesh.dim) +
                                   " has all three vertices on fracture '" + specs[f0].name +
                                   "', so it cannot be assigned to one side; refining the mesh "
                                   "near the fracture (a smaller element size there) removes it");
    }
  }

  // Node -> incident triangles, for the nodes on fractures only.
  std::unordered_map<Index, std::vector<Index>> fan;
  for (Index t = 0; t < mesh.numCells(); ++t)
    for (Index v : mesh.cell(t))
      if (nodeEdges.count(v)) fan[v].push_back(t);

  SplitMesh out = unsplitCopy(mesh);

  // The triangle on the Ω⁺ (plus true) or Ω⁻ side of the fracture edge (v, w), walked from v
  // to w when forward (else from w to v): Ω⁺ is where (x − x_v)·n < 0, n the edge's normal in
  // the walking direction (SignConventions.hpp).
  auto triangleOnSide = [&](Index v, Index w, bool forward, bool plus) -> Index {
    const Index side = topo.findFacet({v, w});
    Vector2 dir = mesh.points[w].head<2>() - mesh.points[v].head<2>();
    if (!forward) dir = -dir;
    for (int c = 0; c < topo.numCellsOf(side); ++c) {
      const Index t = topo.cellOf(side, c).cell;
      for (Index x : mesh.cell(t)) {
        if (x == v || x == w) continue;
        const double s =
            (mesh.points[x].head<2>() - mesh.points[v].head<2>()).dot(normalFromTangent(dir));
        if ((s < 0) == plus) return t;
      }
    }
    return -1;
  };

  // A junction node (edges of several fractures) is split once, into one copy per group of
  // triangles (sector) between consecutive fracture edges; the fractures then take the copies
  // of the sectors at their edges. The first fracture to reach it decides which sector keeps
  // the node's number (its Ω⁺ side); the others' copies are appended in group order.
  struct Sectors {
    std::vector<std::vector<Index>> groups;
    std::vector<Index> copy;  ///< per group
    Index copyOf(Index triangle) const {
      for (std::size_t k = 0; k < groups.size(); ++k)
        if (std::find(groups[k].begin(), groups[k].end(), triangle) != groups[k].end())
          return copy[k];
      return -1;
    }
  };
  std::map<Index, Sectors> junctionSectors;
  auto splitJunction = [&](Index v, Index keepTriangle) -> const Sectors& {
    auto found = junctionSectors.find(v);
    if (found != junctionSectors.end()) return found->second;
    Sectors s;
    for (auto& [root, list] : sidesAround(v, fan[v], topo, fractureOfEdge))
      s.groups.push_back(list);
    s.copy.assign(s.groups.size(), -1);
    for (std::size_t k = 0; k < s.groups.size(); ++k)
      if (std::find(s.groups[k].begin(), s.groups[k].end(), keepTriangle) != s.groups[k].end())
        s.copy[k] = v;
    for (std::size_t k = 0; k < s.groups.size(); ++k) {
      if (s.copy[k] >= 0) continue;
      s.copy[k] = static_cast<Index>(out.mesh.points.size());
      out.mesh.points.push_back(mesh.points[v]);
      out.origin.push_back(v);
      for (Index t : s.groups[k])
        for (Index& x : out.mesh.cell(t))
          if (x == v) x = s.copy[k];
    }
    return junctionSectors.emplace(v, std::move(s)).first->second;
  };

  // 4. Per fracture: order the nodes along the curve, then split each node.
  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    const int fi = static_cast<int>(f);
    // Ends are the nodes with one edge of this fracture.
    std::vector<Index> ends;
    std::vector<Index> nodesOfF;
    for (const auto& [a, b] : fracEdges[f])
      for (Index v : {a, b})
        if (std::find(nodesOfF.begin(), nodesOfF.end(), v) == nodesOfF.end()) nodesOfF.push_back(v);
    for (Index v : nodesOfF)
      if (edgesOfAt(v, fi) == 1) ends.push_back(v);
    auto lexLess = [&](Index a, Index b) {
      const Point &p = mesh.points[a], &q = mesh.points[b];
      return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
    };
    const Index start = *std::min_element(ends.begin(), ends.end(), lexLess);

    FractureGeometry g;
    g.name = spec.name;
    g.label = spec.label;
    Index prev = -1, cur = start;
    while (cur != -1) {
      g.node.push_back(cur);
      Index next = -1;
      for (const auto& fe : nodeEdges[cur])
        if (fe.first == fi && fe.second != prev) next = fe.second;
      prev = cur;
      cur = next;
    }
    if (g.node.size() != nodesOfF.size()) {
      throw InputError(spec.where, "fracture '" + spec.name + "' (label " +
                                       std::to_string(spec.label) +
                                       ") is not one connected curve; give each curve its own "
                                       "label and list each as a fracture");
    }
    const std::size_t n = g.node.size();

    // Split each node: union the triangles of its fan across non-fracture sides.
    g.plus.resize(n);
    g.minus.resize(n);
    g.kind.resize(n);
    // A node joined end to end with another fracture (and nothing else): the tangent there is
    // the chord to that fracture's neighbour, as if the two were one curve.
    std::vector<Index> joinedNeighbour(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
      const Index v = g.node[i];
      const std::vector<int> here = fracturesAt(v);
      if (here.size() > 1) {
        // Junction: the sectors between the fracture edges at v.
        const Index w = g.node[i + 1 < n ? i + 1 : i - 1];
        const bool forward = i + 1 < n;
        const Index left = triangleOnSide(v, w, forward, true),
                    right = triangleOnSide(v, w, forward, false);
        const Sectors& sectors = splitJunction(v, left);
        const std::size_t branches = nodeEdges[v].size(), m = sectors.groups.size();
        g.plus[i] = sectors.copyOf(left);
        g.minus[i] = sectors.copyOf(right);
        const int own = edgesOfAt(v, fi);
        std::string problem;
        if (left < 0 || right < 0 || g.plus[i] < 0 || g.minus[i] < 0 || g.plus[i] == g.minus[i])
          problem =
              "cannot tell the two sides of the fracture apart (folded or inverted "
              "triangles next to it?)";
        else if (m == branches && branches == 2)
          g.kind[i] = FractureNodeKind::joined;
        else if (m == branches)
          g.kind[i] = own == 2 ? FractureNodeKind::crossing : FractureNodeKind::abutting;
        else if (m == branches + 1 && own == 1)
          g.kind[i] = FractureNodeKind::boundary;  // fractures ending on the outer boundary
        else
          problem = "the " + std::to_string(branches) +
                    " fracture edges there cut the triangles "
                    "around it into " +
                    std::to_string(m) + " groups (" + std::to_string(branches) +
                    " expected inside the body, " + std::to_string(branches + 1) +
                    " on its boundary, where every fracture must end); the mesh is not a "
                    "manifold here, or a fracture touches the boundary between its ends";
        if (!problem.empty())
          throw InputError(file, "fracture '" + spec.name + "' at the junction " +
                                     formatPoint(mesh.points[v], mesh.dim) + ": " + problem);
        if (g.kind[i] == FractureNodeKind::joined)
          for (const auto& fe : nodeEdges[v])
            if (fe.first != fi) joinedNeighbour[i] = fe.second;
        continue;
      }

      const std::map<int, std::vector<Index>> groups = sidesAround(v, fan[v], topo, fractureOfEdge);
      if (groups.size() == 1) {
        if (nodeEdges[v].size() != 1)
          throw InputError(file, "fracture '" + spec.name + "' at " +
                                     formatPoint(mesh.points[v], mesh.dim) +
                                     ": the triangles around this node are not separated by "
                                     "the fracture (is the mesh conforming to the fracture?)");
        g.kind[i] = FractureNodeKind::tip;
        g.plus[i] = g.minus[i] = v;
        continue;
      }
      if (groups.size() > 2)
        throw InputError(file, "fracture '" + spec.name + "' at " +
                                   formatPoint(mesh.points[v], mesh.dim) +
                                   ": the fracture cuts the triangles around this node into " +
                                   std::to_string(groups.size()) +
                                   " groups (2 expected); the mesh is not a manifold here");
      g.kind[i] =
          nodeEdges[v].size() == 1 ? FractureNodeKind::boundary : FractureNodeKind::interior;

      // Which group is Ω⁺: take a triangle of the group that has a fracture edge (v, w) and
      // see on which side of that edge its third vertex lies. Ω⁺ is where (x − x_v)·n < 0.
      int sideOf[2] = {0, 0};
      int gi = 0;
      for (const auto& [root, list] : groups) {
        for (Index t : list) {
          const auto tri = mesh.cell(t);
          for (const auto& fe : nodeEdges[v]) {
            const Index w = fe.second;
            if (std::find(tri.begin(), tri.end(), w) == tri.end()) continue;
            Index c = -1;
            for (Index x : tri)
              if (x != v && x != w) c = x;
            // Edge normal of (v, w) in the walking direction of the fracture.
            const bool forward = (i + 1 < n && g.node[i + 1] == w);
            Vector2 dir = mesh.points[w].head<2>() - mesh.points[v].head<2>();
            if (!forward) dir = -dir;
            const double s =
                (mesh.points[c].head<2>() - mesh.points[v].head<2>()).dot(normalFromTangent(dir));
            sideOf[gi] = s < 0 ? +1 : -1;
            break;
          }
          if (sideOf[gi] != 0) break;
        }
        ++gi;
      }
      if (sideOf[0] == 0 || sideOf[1] == 0 || sideOf[0] == sideOf[1])
        throw InputError(file, "fracture '" + spec.name + "' at " +
                                   formatPoint(mesh.points[v], mesh.dim) +
                                   ": cannot tell the two sides of the fracture apart (folded "
                                   "or inverted triangles next to it?)");

      g.plus[i] = v;
      g.minus[i] = appendMinusCopy(out, mesh, v, groups, sideOf);
    }

    // Tangent at a node: the direction of the chord between its neighbours, i.e. the sum
    // of the adjacent edge vectors. This is the length-weighted average of the edge
    // tangents, which is what the lumped (trapezoid) mass of Γ pairs with. At a node joined
    // to another fracture the missing neighbour is that fracture's.
    g.tangent.resize(n);
    g.normal.resize(n);
    g.arclength.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Vector2 a = mesh.points[g.node[i == 0 ? 0 : i - 1]].head<2>();
      Vector2 b = mesh.points[g.node[i + 1 == n ? n - 1 : i + 1]].head<2>();
      if (joinedNeighbour[i] >= 0) (i == 0 ? a : b) = mesh.points[joinedNeighbour[i]].head<2>();
      g.tangent[i] = (b - a).normalized();
      const Vector2 normal = normalFromTangent(g.tangent[i]);
      g.normal[i] = Point(normal.x(), normal.y(), 0.0);
      g.arclength[i] = i == 0 ? 0.0
                              : g.arclength[i - 1] + (mesh.points[g.node[i]].head<2>() -
                                                      mesh.points[g.node[i - 1]].head<2>())
                                                         .norm();
    }
    out.fractures.push_back(std::move(g));
  }

  // 5. Boundary patches follow the copies their triangle uses.
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1);
    const Index side = topo.findFacet({a, b});
    if (side >= 0 && fractureOfEdge[side] >= 0) continue;
    if (side < 0)
      throw InputError(file, "edge " + formatPoint(mesh.points[a], mesh.dim) + "-" +
                                 formatPoint(mesh.points[b], mesh.dim) + " with label " +
                                 std::to_string(mesh.facetLabel[e]) +
                                 " is not a side of any triangle");
    const Index t = topo.cellOf(side, 0).cell;
    const auto orig = mesh.cell(t);
    const auto split = out.mesh.cell(t);
    std::array<Index, 2> ne{a, b};
    for (Index& x : ne)
      for (int k = 0; k < 3; ++k)
        if (orig[k] == x) {
          x = split[k];
          break;
        }
    out.mesh.addFacet({ne[0], ne[1]}, mesh.facetLabel[e]);
  }
  return out;
}

}  // namespace friction

namespace friction {

namespace {

// 3D: fault surfaces of triangles inside a tetrahedral mesh. Same rule as in 2D (one copy per
// group of tetrahedra around a node that stay connected through facets that contain the node
// and are not fracture facets); the surface is checked (manifold, orientable, open, one piece)
// and oriented first, since the sides Ω⁺ and Ω⁻ come from its orientation.
SplitMesh splitSurfaces(const Mesh& mesh, const std::vector<FractureSpec>& specs) {
  const std::string& file = mesh.source;
  const Index nPoints = mesh.numPoints();
  const auto topology = mesh.topology();
  const MeshTopology& topo = *topology;
  auto at = [&](Index v) { return formatPoint(mesh.points[v], 3); };
  auto triangleText = [&](Index a, Index b, Index c) { return at(a) + "-" + at(b) + "-" + at(c); };
  if (!topo.overSharedFacets().empty()) {
    const Index f = topo.overSharedFacets().front();
    throw InputError(file, "the mesh is not a valid 3D tetrahedral mesh: the triangle " +
                               triangleText(topo.facetVertex(f, 0), topo.facetVertex(f, 1),
                                            topo.facetVertex(f, 2)) +
                               " is a face of " + std::to_string(topo.numCellsOf(f)) +
                               " tetrahedra (at most 2 expected)");
  }
  auto entry = [&](const FractureSpec& spec) {
    return "fracture '" + spec.name + "' (label " + std::to_string(spec.label) + ")";
  };
  auto hasTwin = [&](Index v) {
    for (Index w = 0; w < nPoints; ++w)
      if (w != v && (mesh.points[w] - mesh.points[v]).norm() <= 1e-12 * (1 + mesh.points[v].norm()))
        return true;
    return false;
  };

  // 1. Each fracture's triangles: interior facets of the mesh, each of one fracture.
  std::vector<std::vector<std::array<Index, 3>>> tris(specs.size());
  std::vector<int> fractureOfFacet(static_cast<std::size_t>(topo.numFacets()), -1);
  std::vector<int> triangleOfFacet(static_cast<std::size_t>(topo.numFacets()), -1);  // in tris
  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    for (Index e = 0; e < mesh.numFacets(); ++e) {
      if (mesh.facetLabel[e] != spec.label) continue;
      const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1),
                  c = mesh.facetVertex(e, 2);
      const Index side = topo.findFacet({a, b, c});
      if (side >= 0 && fractureOfFacet[side] >= 0) {
        if (fractureOfFacet[side] == static_cast<int>(f)) continue;  // listed twice in one patch
        throw InputError(spec.where, "fractures '" + specs[fractureOfFacet[side]].name + "' and '" +
                                         spec.name + "' share the triangle " +
                                         triangleText(a, b, c) + " of " + file +
                                         ": a fracture patch must be listed once");
      }
      if (side < 0)
        throw InputError(file, entry(spec) + ": its triangle " + triangleText(a, b, c) +
                                   " is not a face of any tetrahedron");
      if (topo.isBoundary(side)) {
        if (hasTwin(a) || hasTwin(b) || hasTwin(c))
          throw InputError(file, entry(spec) + " is already split in this mesh (its triangle " +
                                     triangleText(a, b, c) +
                                     " is a face of one tetrahedron and its nodes have "
                                     "coincident copies); give splitFractureNodes the unsplit "
                                     "mesh");
        throw InputError(file, entry(spec) + ": its triangle " + triangleText(a, b, c) +
                                   " lies on the outer boundary of the mesh; a fracture must be "
                                   "inside the body (a face of two tetrahedra)");
      }
      fractureOfFacet[side] = static_cast<int>(f);
      triangleOfFacet[side] = static_cast<int>(tris[f].size());
      tris[f].push_back({a, b, c});
    }
    if (tris[f].empty()) throw InputError(spec.where, entry(spec) + " has no triangles in " + file);
  }

  // 2. Node -> fractures (in the order listed); a node of two or more lies where fault
  //    surfaces meet (an intersection node, split once into its sectors in step 6).
  std::vector<int> fractureOfNode(static_cast<std::size_t>(nPoints), -1);  // the first one
  std::vector<std::vector<int>> fracturesOfNode(static_cast<std::size_t>(nPoints));
  for (std::size_t f = 0; f < specs.size(); ++f)
    for (const auto& t : tris[f])
      for (Index v : t) {
        auto& list = fracturesOfNode[v];
        if (list.empty() || list.back() != static_cast<int>(f)) list.push_back(static_cast<int>(f));
        if (fractureOfNode[v] < 0) fractureOfNode[v] = static_cast<int>(f);
      }

  // The other fractures at node v than f, quoted: "'a'", "'a' and 'b'", ...
  auto othersNamed = [&](Index v, std::size_t f) {
    std::vector<std::string> names;
    for (int o : fracturesOfNode[v])
      if (o != static_cast<int>(f)) names.push_back("'" + specs[o].name + "'");
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
      text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
    return text;
  };

  // 3. Each surface: manifold, open, orientable, one piece; oriented (SignConventions.hpp).
  auto cross = [&](const std::array<Index, 3>& t) {
    return Point(
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]));
  };
  std::vector<std::map<std::pair<Index, Index>, std::vector<int>>> edgesOf(specs.size());
  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    std::vector<std::array<Index, 3>>& tri = tris[f];
    const int nt = static_cast<int>(tri.size());

    // Edges -> triangles: manifold (at most two per edge), open (some edge of one), one
    // piece (connected through edges).
    auto& edgeTris = edgesOf[f];
    for (int i = 0; i < nt; ++i)
      for (int k = 0; k < 3; ++k)
        edgeTris[std::minmax(tri[i][k], tri[i][(k + 1) % 3])].push_back(i);
    bool open = false;
    for (const auto& [edge, list] : edgeTris) {
      if (list.size() > 2)
        throw InputError(
            file, entry(spec) + " is not a manifold surface: its edge " + at(edge.first) + "-" +
                      at(edge.second) + " is an edge of " + std::to_string(list.size()) +
                      " of its triangles (at most 2 expected; a surface that branches needs a "
                      "label per branch, and surfaces may then meet)");
      open = open || list.size() == 1;
    }
    if (!open)
      throw InputError(spec.where, entry(spec) + " is a closed surface in " + file +
                                       "; only surfaces with an edge (a tip line or an edge "
                                       "on the outer boundary) are supported");

    // Orient the triangles consistently: walk across edges from the first triangle (file
    // orientation); a neighbour must run through the shared edge the other way.
    std::vector<int> flip(nt, -1);                    // 0 as in the file, 1 reversed
    auto runsInFile = [&](int i, Index a, Index b) {  // does triangle i run a -> b in the file?
      for (int k = 0; k < 3; ++k)
        if (tri[i][k] == a && tri[i][(k + 1) % 3] == b) return true;
      return false;
    };
    std::vector<int> stack{0};
    flip[0] = 0;
    int reached = 1;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        // Oriented, i runs a -> b (reversed, b -> a): j must run the other way.
        const Index a = tri[i][k], b = tri[i][(k + 1) % 3];
        for (int j : edgeTris[std::minmax(a, b)]) {
          if (j == i) continue;
          const int want = (runsInFile(j, a, b) == (flip[i] == 0)) ? 1 : 0;
          if (flip[j] < 0) {
            flip[j] = want;
            ++reached;
            stack.push_back(j);
          } else if (flip[j] != want) {
            throw InputError(file, entry(spec) +
                                       " is not an orientable surface (a Moebius strip?): its "
                                       "two sides cannot be told apart; found at the edge " +
                                       at(a) + "-" + at(b));
          }
        }
      }
    }
    if (reached != nt) {
      int other = 0;
      while (flip[other] >= 0) ++other;
      throw InputError(spec.where, entry(spec) + " is made of several pieces in " + file +
                                       " (not joined through triangle edges): one contains " +
                                       at(tri[0][0]) + ", another " + at(tri[other][0]) +
                                       "; give each piece its own label and list each as a "
                                       "fracture");
    }
    for (int i = 0; i < nt; ++i)
      if (flip[i]) std::swap(tri[i][1], tri[i][2]);

    // Global sign (SignConventions.hpp): the area-weighted mean normal's component of
    // largest magnitude is negative (a tie goes to the earlier axis). Where the normals
    // cancel exactly (mean = 0) the orientation of the first triangle in the file is kept.
    Point mean = Point::Zero();
    for (const auto& t : tri) mean += cross(t);
    int axis = 0;
    for (int c = 1; c < 3; ++c)
      if (std::abs(mean[c]) > std::abs(mean[axis])) axis = c;
    if (mean[axis] > 0)
      for (auto& t : tri) std::swap(t[1], t[2]);
  }

  // 4. A tetrahedron with all four vertices on one fracture has no vertex off it.
  for (Index t = 0; t < mesh.numCells(); ++t) {
    const auto tet = mesh.cell(t);
    int f0 = -1;
    for (int f : fracturesOfNode[tet[0]]) {
      bool all = true;
      for (int k = 1; k < 4; ++k)
        all = all && std::find(fracturesOfNode[tet[k]].begin(), fracturesOfNode[tet[k]].end(), f) !=
                         fracturesOfNode[tet[k]].end();
      if (all) {
        f0 = f;
        break;
      }
    }
    if (f0 >= 0)
      throw InputError(file, "tetrahedron " + std::to_string(t + 1) + " " + at(tet[0]) + " " +
                                 at(tet[1]) + " " + at(tet[2]) + " " + at(tet[3]) +
                                 " has all four vertices on " + entry(specs[f0]) +
                                 ", so it cannot be assigned to one side; refining the mesh "
                                 "near the fracture (a smaller element size there) removes it");
  }

  // Node -> incident tetrahedra, for the fracture nodes only.
  std::unordered_map<Index, std::vector<Index>> fan;
  for (Index t = 0; t < mesh.numCells(); ++t)
    for (Index v : mesh.cell(t))
      if (fractureOfNode[v] >= 0) fan[v].push_back(t);

  SplitMesh out = unsplitCopy(mesh);

  // Intersection nodes (on two or more fractures) are split once, into one copy per sector:
  // the groups of tetrahedra around the node once every fault triangle through it is cut. The
  // first fracture at the node decides which sector keeps the node's number (the Ω⁺ side of
  // its first triangle through the node); the other sectors' copies are appended in group
  // order. Each fracture's ⁺ and ⁻ copies there are the sectors on either side of its first
  // triangle through the node.
  std::vector<std::vector<Index>> facetOfTriangle(specs.size());
  for (std::size_t f = 0; f < specs.size(); ++f) facetOfTriangle[f].resize(tris[f].size());
  for (Index side = 0; side < topo.numFacets(); ++side)
    if (fractureOfFacet[side] >= 0)
      facetOfTriangle[fractureOfFacet[side]][triangleOfFacet[side]] = side;
  // The tetrahedra on the Ω⁺ (first) and Ω⁻ side of fracture f's oriented triangle ti; −1 for
  // a side that has none (inverted tetrahedra).
  auto tetsOf = [&](std::size_t f, int ti) {
    const Index side = facetOfTriangle[f][ti];
    const auto& tr = tris[f][ti];
    std::array<Index, 2> pm{-1, -1};
    for (int c = 0; c < 2; ++c) {
      const Index t = topo.cellOf(side, c).cell;
      for (Index x : mesh.cell(t))
        if (x != tr[0] && x != tr[1] && x != tr[2])
          pm[(mesh.points[x] - mesh.points[tr[0]]).dot(cross(tr)) < 0 ? 0 : 1] = t;
    }
    return pm;
  };
  // The nodes where fracture f ends inside the body: on an edge of its own boundary (an edge
  // of one of its triangles) that is not on the outer boundary. A fracture at an intersection
  // node passes through it unless it ends there.
  const std::set<std::pair<Index, Index>> outer = outerBoundaryEdges(topo);
  std::vector<std::set<Index>> endsAt(specs.size());
  for (std::size_t f = 0; f < specs.size(); ++f)
    for (const auto& [edge, list] : edgesOf[f])
      if (list.size() == 1 && !outer.count(edge)) endsAt[f].insert({edge.first, edge.second});
  struct Sectors {
    std::map<Index, std::size_t> groupOf;  ///< tetrahedron -> its sector
    std::vector<Index> copy;               ///< per sector
    Index copyOf(Index tet) const {
      const auto it = groupOf.find(tet);
      return it == groupOf.end() ? Index(-1) : copy[it->second];
    }
  };
  std::map<Index, Sectors> sectorsAt;
  auto splitIntersection = [&](Index v, Index keepTet) -> const Sectors& {
    auto found = sectorsAt.find(v);
    if (found != sectorsAt.end()) return found->second;
    Sectors s;
    for (auto& [root, list] : sidesAround(v, fan[v], topo, fractureOfFacet)) {
      for (Index t : list) s.groupOf[t] = s.copy.size();
      s.copy.push_back(-1);
    }
    const auto keep = s.groupOf.find(keepTet);
    if (keep != s.groupOf.end()) s.copy[keep->second] = v;
    for (std::size_t k = 0; k < s.copy.size(); ++k) {
      if (s.copy[k] >= 0) continue;
      s.copy[k] = static_cast<Index>(out.mesh.points.size());
      out.mesh.points.push_back(mesh.points[v]);
      out.origin.push_back(v);
    }
    for (const auto& [t, k] : s.groupOf)
      for (Index& x : out.mesh.cell(t))
        if (x == v) x = s.copy[k];
    return sectorsAt.emplace(v, std::move(s)).first->second;
  };

  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    const std::vector<std::array<Index, 3>>& tri = tris[f];
    const auto& edgeTris = edgesOf[f];
    // 5. Nodes in ascending order, their normals (sum of the adjacent triangles' cross
    //    products: area-weighted) and whether they lie on the surface's edge.
    FractureGeometry g;
    g.name = spec.name;
    g.label = spec.label;
    std::map<Index, std::size_t> local;
    for (const auto& t : tri)
      for (Index v : t) local.emplace(v, 0);
    for (auto& [v, i] : local) {
      i = g.node.size();
      g.node.push_back(v);
    }
    const std::size_t n = g.node.size();
    g.normal.assign(n, Point::Zero());
    for (const auto& t : tri) {
      const Point c = cross(t);
      for (Index v : t) g.normal[local[v]] += c;
    }
    for (Point& p : g.normal) p.normalize();
    std::vector<char> onEdge(n, 0);
    for (const auto& [edge, list] : edgeTris)
      if (list.size() == 1) onEdge[local[edge.first]] = onEdge[local[edge.second]] = 1;

    // 6. Split each node: union its tetrahedra across facets through it that are not fracture
    //    facets.
    g.plus.resize(n);
    g.minus.resize(n);
    g.kind.resize(n);
    std::map<Index, std::vector<int>> through;  // intersection node -> f's triangles there
    for (int ti = 0; ti < static_cast<int>(tri.size()); ++ti)
      for (Index v : tri[ti])
        if (fracturesOfNode[v].size() > 1) through[v].push_back(ti);
    for (std::size_t i = 0; i < n; ++i) {
      const Index v = g.node[i];
      if (fracturesOfNode[v].size() > 1) {
        // Where fault surfaces meet (README "Intersections (3D)"): f passes through the node
        // (every fault triangle of it there separates two sectors: its jump is free, kind
        // crossing, or boundary on the outer boundary), or it ends there: held (abutting)
        // where another passes, joined where exactly one other ends with it, else abutting.
        const std::vector<int>& mine = through.at(v);
        const std::array<Index, 2> ref = tetsOf(f, mine.front());
        const Sectors& sectors = splitIntersection(v, ref[0]);
        g.plus[i] = sectors.copyOf(ref[0]);
        g.minus[i] = sectors.copyOf(ref[1]);
        if (g.plus[i] < 0 || g.minus[i] < 0)
          throw InputError(file, entry(spec) + " at " + at(v) +
                                     ": cannot tell the two sides of the fracture apart (folded "
                                     "or inverted tetrahedra next to it?)");
        const bool passes = !endsAt[f].count(v);
        if (passes)
          for (int ti : mine) {
            const std::array<Index, 2> pm = tetsOf(f, ti);
            if (pm[0] < 0 || pm[1] < 0 || sectors.copyOf(pm[0]) == sectors.copyOf(pm[1]))
              throw InputError(
                  file, entry(spec) + " at " + at(v) + ", where it meets " + othersNamed(v, f) +
                            ": the fault surfaces there do not cut the tetrahedra around the "
                            "node into sectors on either side of each of its triangles (is the "
                            "mesh conforming to the surfaces where they meet?)");
          }
        bool anotherPasses = false;
        for (int o : fracturesOfNode[v])
          anotherPasses = anotherPasses || (o != static_cast<int>(f) && !endsAt[o].count(v));
        if (g.plus[i] == g.minus[i])
          g.kind[i] = FractureNodeKind::tip;
        else if (passes)
          g.kind[i] = onEdge[i] ? FractureNodeKind::boundary : FractureNodeKind::crossing;
        else if (!anotherPasses && fracturesOfNode[v].size() == 2)
          g.kind[i] = FractureNodeKind::joined;
        else
          g.kind[i] = FractureNodeKind::abutting;
        continue;
      }
      const std::map<int, std::vector<Index>> groups =
          sidesAround(v, fan[v], topo, fractureOfFacet);

      if (groups.size() == 1) {
        if (!onEdge[i])
          throw InputError(file, entry(spec) + " at " + at(v) +
                                     ": the tetrahedra around this node are not separated by "
                                     "the fracture (is the mesh conforming to the fracture?)");
        g.kind[i] = FractureNodeKind::tip;
        g.plus[i] = g.minus[i] = v;
        continue;
      }
      if (groups.size() > 2)
        throw InputError(file, entry(spec) + " at " + at(v) +
                                   ": the fracture cuts the tetrahedra around this node into " +
                                   std::to_string(groups.size()) +
                                   " groups (2 expected); the mesh is not a manifold here");
      g.kind[i] = onEdge[i] ? FractureNodeKind::boundary : FractureNodeKind::interior;

      // Which group is Ω⁺: a tetrahedron of the group with a fracture triangle through v;
      // Ω⁺ is where its fourth vertex lies against the triangle's oriented normal.
      int sideOf[2] = {0, 0};
      int gi = 0;
      for (const auto& [root, list] : groups) {
        for (Index t : list) {
          for (int k = 0; k < 4 && sideOf[gi] == 0; ++k) {
            const Index side = topo.cellFacet(t, k);
            if (fractureOfFacet[side] != static_cast<int>(f) || topo.cellVertex(t, k) == v)
              continue;
            const auto& tr = tri[triangleOfFacet[side]];  // oriented
            const double s =
                (mesh.points[topo.cellVertex(t, k)] - mesh.points[tr[0]]).dot(cross(tr));
            sideOf[gi] = s < 0 ? +1 : -1;
          }
          if (sideOf[gi] != 0) break;
        }
        ++gi;
      }
      if (sideOf[0] == 0 || sideOf[1] == 0 || sideOf[0] == sideOf[1])
        throw InputError(file, entry(spec) + " at " + at(v) +
                                   ": cannot tell the two sides of the fracture apart (folded "
                                   "or inverted tetrahedra next to it?)");

      g.plus[i] = v;
      g.minus[i] = appendMinusCopy(out, mesh, v, groups, sideOf);
    }
    g.triangles = tri;
    out.fractures.push_back(std::move(g));
  }

  // 7. Boundary patches follow the copies their tetrahedron uses.
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const auto fv = mesh.facet(e);
    const Index side = topo.findFacet({fv[0], fv[1], fv[2]});
    if (side >= 0 && fractureOfFacet[side] >= 0) continue;
    if (side < 0)
      throw InputError(file, "triangle " + triangleText(fv[0], fv[1], fv[2]) + " with label " +
                                 std::to_string(mesh.facetLabel[e]) +
                                 " is not a face of any tetrahedron");
    const Index t = topo.cellOf(side, 0).cell;
    const auto orig = mesh.cell(t);
    const auto split = out.mesh.cell(t);
    std::array<Index, 3> ne{fv[0], fv[1], fv[2]};
    for (Index& x : ne)
      for (int k = 0; k < 4; ++k)
        if (orig[k] == x) {
          x = split[k];
          break;
        }
    out.mesh.addFacet({ne[0], ne[1], ne[2]}, mesh.facetLabel[e]);
  }
  return out;
}

}  // namespace

std::string othersAt(const SplitMesh& split, std::size_t f, Index node) {
  std::vector<std::string> names;
  for (std::size_t o = 0; o < split.fractures.size(); ++o) {
    const auto& nodes = split.fractures[o].node;
    if (o != f && std::find(nodes.begin(), nodes.end(), node) != nodes.end())
      names.push_back("'" + split.fractures[o].name + "'");
  }
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return s;
}

std::string IntersectionCurve::kind() const {
  if (onOuterBoundary) return "on the outer boundary";
  if (passing.size() >= 2) return "crossing";
  if (passing.size() == 1) return "abutting";
  // Two ending together act as one surface there (the 2D kind's name); three or more are held.
  return ending.size() == 2 ? "joined" : "ending together";
}

std::vector<IntersectionCurve> intersectionCurves(const SplitMesh& split, const Mesh& unsplit) {
  if (unsplit.dim != 3) return {};
  // Edge -> per fracture, its triangles at the edge.
  std::map<std::pair<Index, Index>, std::map<std::size_t, int>> uses;
  for (std::size_t f = 0; f < split.fractures.size(); ++f)
    for (const auto& t : split.fractures[f].triangles)
      for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])][f];
  const auto topology = unsplit.topology();
  const std::set<std::pair<Index, Index>> outer = outerBoundaryEdges(*topology);
  // The edges of two or more fractures, each with its roles; then joined through shared nodes
  // into curves of equal roles.
  struct Edge {
    std::pair<Index, Index> nodes;
    IntersectionCurve roles;
  };
  std::vector<Edge> edges;
  for (const auto& [edge, count] : uses) {
    if (count.size() < 2) continue;
    Edge e{edge, {}};
    for (const auto& [f, c] : count) (c == 2 ? e.roles.passing : e.roles.ending).push_back(f);
    e.roles.onOuterBoundary = outer.count(edge) > 0;
    edges.push_back(e);
  }
  auto sameRoles = [](const IntersectionCurve& a, const IntersectionCurve& b) {
    return a.passing == b.passing && a.ending == b.ending && a.onOuterBoundary == b.onOuterBoundary;
  };
  UnionFind uf(static_cast<int>(edges.size()));
  std::map<Index, std::vector<int>> edgesAt;
  for (std::size_t k = 0; k < edges.size(); ++k)
    for (Index v : {edges[k].nodes.first, edges[k].nodes.second})
      edgesAt[v].push_back(static_cast<int>(k));
  for (const auto& [v, list] : edgesAt)
    for (std::size_t a = 1; a < list.size(); ++a)
      for (std::size_t b = 0; b < a; ++b)
        if (sameRoles(edges[list[a]].roles, edges[list[b]].roles)) uf.unite(list[a], list[b]);
  std::map<int, IntersectionCurve> byRoot;
  std::map<int, std::map<Index, int>> degree;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const int root = uf.find(static_cast<int>(k));
    IntersectionCurve& c = byRoot.emplace(root, edges[k].roles).first->second;
    const auto [a, b] = edges[k].nodes;
    c.length += (unsplit.points[b] - unsplit.points[a]).norm();
    ++degree[root][a];
    ++degree[root][b];
  }
  std::vector<IntersectionCurve> curves;
  for (auto& [root, c] : byRoot) {
    for (const auto& [v, d] : degree[root]) {
      c.nodes.push_back(v);
      if (d == 1) c.ends.push_back(v);
    }
    curves.push_back(std::move(c));
  }
  std::sort(curves.begin(), curves.end(),
            [](const IntersectionCurve& a, const IntersectionCurve& b) {
              return a.nodes.front() < b.nodes.front();
            });
  return curves;
}

std::vector<std::string> junctionNotes(const SplitMesh& split, std::size_t f) {
  std::vector<std::string> notes;
  const FractureGeometry& g = split.fractures.at(f);
  for (Index i = 0; i < g.numNodes(); ++i) {
    const FractureNodeKind kind = g.kind[i];
    if (kind != FractureNodeKind::crossing && kind != FractureNodeKind::abutting &&
        kind != FractureNodeKind::joined)
      continue;
    std::string what;
    if (kind == FractureNodeKind::crossing)
      what = "passes through";
    else if (kind == FractureNodeKind::abutting)
      what = "ends here, its jump held (state junction)";
    else {
      // A joined node belongs to the first-listed of its two fractures.
      std::size_t owner = f;
      for (std::size_t o = 0; o < f; ++o) {
        const auto& nodes = split.fractures[o].node;
        if (std::find(nodes.begin(), nodes.end(), g.node[i]) != nodes.end()) owner = o;
      }
      what = owner == f ? "joined end to end (one node of both: its row is in this table)"
                        : "joined end to end (one node of both: its row is in '" +
                              split.fractures[owner].name + "')";
    }
    notes.push_back("junction at " + formatPoint(split.mesh.points[g.node[i]], 2) + ": " + what +
                    "; meets " + othersAt(split, f, g.node[i]));
  }
  return notes;
}

namespace {
// The number of fractures with each node (a node of two or more is where they meet).
std::map<Index, int> fractureCount(const SplitMesh& split) {
  std::map<Index, int> count;
  for (const FractureGeometry& g : split.fractures)
    for (Index v : g.node) ++count[v];
  return count;
}
}  // namespace

std::string quotedFractureNames(const SplitMesh& split, const std::vector<std::size_t>& list) {
  std::string text;
  for (std::size_t k = 0; k < list.size(); ++k)
    text += (k == 0                 ? ""
             : k + 1 == list.size() ? " and "
                                    : ", ") +
            ("'" + split.fractures[list[k]].name + "'");
  return text;
}

std::vector<std::string> intersectionNotes(const SplitMesh& split,
                                           const std::vector<IntersectionCurve>& curves,
                                           std::size_t f) {
  std::vector<std::string> notes;
  const FractureGeometry& g = split.fractures.at(f);
  std::map<Index, FractureNodeKind> kindOf;
  for (Index i = 0; i < g.numNodes(); ++i) kindOf[g.node[i]] = g.kind[i];
  const auto quoted = [&](const std::vector<std::size_t>& list) {
    return quotedFractureNames(split, list);
  };
  std::set<Index> onCurves;
  for (const IntersectionCurve& c : curves) {
    onCurves.insert(c.nodes.begin(), c.nodes.end());
    const bool passes = std::count(c.passing.begin(), c.passing.end(), f) > 0;
    if (!passes && !std::count(c.ending.begin(), c.ending.end(), f)) continue;
    std::vector<std::size_t> others;
    for (std::size_t o : c.passing)
      if (o != f) others.push_back(o);
    for (std::size_t o : c.ending)
      if (o != f) others.push_back(o);
    std::sort(others.begin(), others.end());
    std::ostringstream line;
    line << std::setprecision(6) << "intersection (" << c.kind() << ") with " << quoted(others)
         << ", " << c.nodes.size() << " nodes ";
    if (c.ends.empty())
      line << "on a closed curve";
    else
      line << "from " << formatPoint(split.mesh.points[c.ends.front()], 3) << " to "
           << formatPoint(split.mesh.points[c.ends.back()], 3);
    line << ", length " << c.length << ": ";
    int held = 0, joined = 0;
    for (Index v : c.nodes) {
      const auto it = kindOf.find(v);
      if (it == kindOf.end()) continue;
      held += it->second == FractureNodeKind::abutting;
      joined += it->second == FractureNodeKind::joined;
    }
    if (passes)
      line << "passes through";
    else if (c.passing.empty())
      // A joined node is one control node, the first-listed fracture's: its row is there.
      line << "ends together with " << (others.size() == 1 ? "it" : "them") << " (" << joined
           << " nodes joined, their rows "
           << (c.ending.front() == f ? std::string("in this table")
                                     : "in '" + split.fractures[c.ending.front()].name + "'")
           << "; " << held << " held: state junction)";
    else
      line << "ends on " << (c.passing.size() == 1 ? "it" : "them") << ", its jump held at " << held
           << " nodes (state junction)";
    notes.push_back(line.str());
  }
  const std::map<Index, int> count = fractureCount(split);
  for (Index i = 0; i < g.numNodes(); ++i) {
    const Index v = g.node[i];
    if (onCurves.count(v) || count.at(v) < 2) continue;
    const std::string others = othersAt(split, f, v);
    const FractureNodeKind kind = g.kind[i];
    notes.push_back("touches " + others + " at " + formatPoint(split.mesh.points[v], 3) +
                    " (a point only): " +
                    (kind == FractureNodeKind::abutting ? "its jump held (state junction)"
                     : kind == FractureNodeKind::tip    ? "its tip"
                     : kind == FractureNodeKind::joined ? "joined"
                                                        : "passes through"));
  }
  return notes;
}

std::vector<int> intersectionCodes(const SplitMesh& split, std::size_t f) {
  const FractureGeometry& g = split.fractures.at(f);
  std::vector<int> codes(static_cast<std::size_t>(g.numNodes()), 0);
  const std::map<Index, int> count = fractureCount(split);
  for (Index i = 0; i < g.numNodes(); ++i) {
    if (count.at(g.node[i]) < 2) continue;
    const FractureNodeKind kind = g.kind[i];
    codes[i] = kind == FractureNodeKind::abutting ? 2
               : kind == FractureNodeKind::joined ? 3
               : kind == FractureNodeKind::tip    ? 4
                                                  : 1;
  }
  return codes;
}

}  // namespace friction
