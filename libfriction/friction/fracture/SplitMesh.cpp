// Node splitting along fractures (docs/method.md). The rule is topological: around a fracture
// node, the triangles that still share a non-fracture edge through the node form one side.
// Geometry enters only to tell which side is Ω⁺ (SignConventions.hpp).
#include "friction/fracture/SplitMesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
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

}  // namespace

const char* toString(FractureNodeKind kind) {
  switch (kind) {
    case FractureNodeKind::interior:
      return "interior";
    case FractureNodeKind::boundary:
      return "boundary";
    case FractureNodeKind::tip:
      return "tip";
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

Index SplitMesh::numOriginalPoints() const {
  Index n = 0;
  for (Index o : origin) n = std::max(n, o + 1);
  return n;
}

SplitMesh splitFractures(const Mesh& mesh, const std::vector<FractureSpec>& specs) {
  const std::string& file = mesh.source;
  const Index nPoints = mesh.numPoints();
  if (mesh.dim != 2)
    throw InputError(file,
                     "the mesh is 3D (tetrahedra): splitting fracture nodes of a 3D mesh "
                     "is not supported yet; expected a 2D triangle mesh");

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

  // 2. Node -> incident fracture edges; more than two, or two fractures meeting, is a junction.
  std::unordered_map<Index, std::vector<std::pair<int, Index>>> nodeEdges;  // (fracture, other end)
  for (std::size_t f = 0; f < specs.size(); ++f)
    for (const auto& [a, b] : fracEdges[f]) {
      nodeEdges[a].push_back({static_cast<int>(f), b});
      nodeEdges[b].push_back({static_cast<int>(f), a});
    }
  for (const auto& [v, list] : nodeEdges) {
    bool mixed = false;
    for (const auto& fe : list) mixed |= fe.first != list.front().first;
    if (mixed)
      throw InputError(
          file,
          "fractures '" + specs[list[0].first].name + "' and '" + specs[list[1].first].name +
              "' meet at " + formatPoint(mesh.points[v], mesh.dim) +
              ": junctions of fractures are not supported (mesh them so that they do not meet)");
    if (list.size() > 2)
      throw InputError(
          file,
          "fracture '" + specs[list[0].first].name + "' branches at " +
              formatPoint(mesh.points[v], mesh.dim) + " (" + std::to_string(list.size()) +
              " fracture edges meet there): junctions of fractures are not supported (give each "
              "branch its own label and keep them apart)");
  }

  // A curve whose nodes all have two fracture edges is closed: refuse before anything else.
  for (std::size_t f = 0; f < specs.size(); ++f) {
    bool hasEnd = false;
    for (const auto& [a, b] : fracEdges[f])
      hasEnd |= nodeEdges[a].size() == 1 || nodeEdges[b].size() == 1;
    if (!hasEnd)
      throw InputError(specs[f].where, "fracture '" + specs[f].name +
                                           "' is a closed curve; only open fractures (two ends) "
                                           "are supported");
  }

  // 3. A triangle with all three vertices on one fracture has no node off it: refuse.
  for (Index t = 0; t < mesh.numCells(); ++t) {
    const auto tri = mesh.cell(t);
    int f0 = -2;
    bool all = true;
    for (int k = 0; k < 3 && all; ++k) {
      auto it = nodeEdges.find(tri[k]);
      if (it == nodeEdges.end()) {
        all = false;
        break;
      }
      const int f = it->second.front().first;
      if (f0 != -2 && f != f0) all = false;
      f0 = f;
    }
    if (all)
      throw InputError(file, "triangle " + std::to_string(t + 1) + " " +
                                 formatPoint(mesh.points[tri[0]], mesh.dim) + " " +
                                 formatPoint(mesh.points[tri[1]], mesh.dim) + " " +
                                 formatPoint(mesh.points[tri[2]], mesh.dim) +
                                 " has all three vertices on fracture '" + specs[f0].name +
                                 "', so it cannot be assigned to one side; refining the mesh "
                                 "near the fracture (a smaller element size there) removes it");
  }

  // Node -> incident triangles, for the nodes on fractures only.
  std::unordered_map<Index, std::vector<Index>> fan;
  for (Index t = 0; t < mesh.numCells(); ++t)
    for (Index v : mesh.cell(t))
      if (nodeEdges.count(v)) fan[v].push_back(t);

  SplitMesh out;
  out.mesh.source = mesh.source;
  out.mesh.format = mesh.format;
  out.mesh.dim = mesh.dim;
  out.mesh.points = mesh.points;
  out.mesh.cellVertices = mesh.cellVertices;
  out.mesh.cellRegion = mesh.cellRegion;
  out.mesh.labelNames = mesh.labelNames;
  out.mesh.regionNames = mesh.regionNames;
  out.origin.resize(nPoints);
  std::iota(out.origin.begin(), out.origin.end(), 0);

  // 4. Per fracture: order the nodes along the curve, then split each node.
  for (std::size_t f = 0; f < specs.size(); ++f) {
    const FractureSpec& spec = specs[f];
    // Ends are the nodes with one fracture edge. A curve whose nodes all have two is closed.
    std::vector<Index> ends;
    std::vector<Index> nodesOfF;
    for (const auto& [a, b] : fracEdges[f])
      for (Index v : {a, b})
        if (std::find(nodesOfF.begin(), nodesOfF.end(), v) == nodesOfF.end()) nodesOfF.push_back(v);
    for (Index v : nodesOfF)
      if (nodeEdges[v].size() == 1) ends.push_back(v);
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
        if (fe.second != prev) next = fe.second;
      prev = cur;
      cur = next;
    }
    if (g.node.size() != nodesOfF.size()) {
      throw InputError(spec.where, "fracture '" + spec.name + "' (label " +
                                       std::to_string(spec.label) +
                                       ") is not one connected curve; give each curve its own "
                                       "label and list each as a fracture");
    }

    // Tangent at a node: the direction of the chord between its neighbours, i.e. the sum
    // of the adjacent edge vectors. This is the length-weighted average of the edge
    // tangents, which is what the lumped (trapezoid) mass of Γ pairs with.
    const std::size_t n = g.node.size();
    g.tangent.resize(n);
    g.normal.resize(n);
    g.arclength.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Vector2 a = mesh.points[g.node[i == 0 ? 0 : i - 1]].head<2>();
      const Vector2 b = mesh.points[g.node[i + 1 == n ? n - 1 : i + 1]].head<2>();
      g.tangent[i] = (b - a).normalized();
      g.normal[i] = normalFromTangent(g.tangent[i]);
      g.arclength[i] = i == 0 ? 0.0
                              : g.arclength[i - 1] + (mesh.points[g.node[i]].head<2>() -
                                                      mesh.points[g.node[i - 1]].head<2>())
                                                         .norm();
    }

    // Split each node: union the triangles of its fan across non-fracture sides.
    g.plus.resize(n);
    g.minus.resize(n);
    g.kind.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Index v = g.node[i];
      const std::vector<Index>& tris = fan[v];
      UnionFind uf(static_cast<int>(tris.size()));
      for (std::size_t p = 0; p < tris.size(); ++p)
        for (Index w : mesh.cell(tris[p])) {
          if (w == v) continue;
          const Index side = topo.findFacet({v, w});
          if (fractureOfEdge[side] >= 0 || topo.numCellsOf(side) != 2) continue;
          const Index t0 = topo.cellOf(side, 0).cell, t1 = topo.cellOf(side, 1).cell;
          const Index other = t0 == tris[p] ? t1 : t0;
          const auto q = std::find(tris.begin(), tris.end(), other) - tris.begin();
          uf.unite(static_cast<int>(p), static_cast<int>(q));
        }
      std::map<int, std::vector<Index>> groups;  // root -> triangles of one side
      for (std::size_t p = 0; p < tris.size(); ++p)
        groups[uf.find(static_cast<int>(p))].push_back(tris[p]);

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

      // The Ω⁺ copy keeps the node number; the Ω⁻ copy is appended.
      const Index copy = static_cast<Index>(out.mesh.points.size());
      out.mesh.points.push_back(mesh.points[v]);
      out.origin.push_back(v);
      gi = 0;
      for (const auto& [root, list] : groups) {
        if (sideOf[gi++] < 0)
          for (Index t : list)
            for (Index& x : out.mesh.cell(t))
              if (x == v) x = copy;
      }
      g.plus[i] = v;
      g.minus[i] = copy;
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
