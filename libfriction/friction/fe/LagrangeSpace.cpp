// LagrangeSpace: node and dof numbering of continuous P1 / P2 (docs/method.md §4, §7). See the
// header for the numbering conventions.
#include "friction/fe/LagrangeSpace.hpp"

#include <algorithm>
#include <string>

#include "friction/core/Assert.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fe/Simplex.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

LagrangeSpace::LagrangeSpace(const Mesh& mesh, int degree)
    : mesh_(&mesh), dim_(mesh.dim), degree_(degree) {
  FRICTION_ASSERT(degree == 1 || degree == 2, "Lagrange degree must be 1 or 2");
  FRICTION_ASSERT(dim_ == 2 || dim_ == 3, "Lagrange spaces on triangles or tetrahedra");
  const Index np = mesh.numPoints();
  const Index nc = mesh.numCells();

  topology_ = mesh.topology();
  if (dim_ == 3) buildEdgeTable();

  // Node positions: mesh points, then edge midpoints in edge order. In 2D z stays 0 and x, y
  // are the same sums as on 2-vectors.
  points_.reserve(np + (degree_ == 2 ? numEdges() : 0));
  points_.insert(points_.end(), mesh.points.begin(), mesh.points.end());
  if (degree_ == 2) {
    if (dim_ == 2) {
      for (Index f = 0; f < topology_->numFacets(); ++f)
        points_.push_back(0.5 * (mesh.points[topology_->facetVertex(f, 0)] +
                                 mesh.points[topology_->facetVertex(f, 1)]));
    } else {
      for (Index a = 0; a < np; ++a)
        for (Index k = edgeStart_[a]; k < edgeStart_[a + 1]; ++k)
          points_.push_back(0.5 * (mesh.points[a] + mesh.points[edgeOther_[k]]));
    }
  }

  const int npc = nodesPerCell();
  cellNodes_.resize(static_cast<std::size_t>(npc) * nc);
  for (Index c = 0; c < nc; ++c) {
    const auto t = mesh.cell(c);
    Index* out = &cellNodes_[static_cast<std::size_t>(npc) * c];
    for (int i = 0; i <= dim_; ++i) out[i] = t[i];
    if (degree_ != 2) continue;
    if (dim_ == 2) {
      // Midpoint of local edge (v_e, v_e+1): the facet opposite vertex e + 2.
      for (int e = 0; e < 3; ++e) out[3 + e] = np + topology_->cellFacet(c, (e + 2) % 3);
    } else {
      for (int e = 0; e < 6; ++e) out[4 + e] = np + cellEdges_[static_cast<std::size_t>(6) * c + e];
    }
  }
  if (degree_ == 1 || dim_ == 2) std::vector<Index>().swap(cellEdges_);

  // A labelled facet that no cell has would get no midpoints and no stiffness: the mesh is
  // inconsistent, and the user must hear about it now rather than see a singular matrix.
  for (Index i = 0; i < mesh.numFacets(); ++i) {
    const auto f = mesh.facet(i);
    bool inRange = true;
    for (Index v : f) inRange = inRange && v >= 0 && v < np;
    const bool found = inRange && (dim_ == 2 ? topology_->findFacet({f[0], f[1]})
                                             : topology_->findFacet({f[0], f[1], f[2]})) >= 0;
    if (!found) {
      std::string nodes;
      for (Index v : f) nodes += (nodes.empty() ? "" : ", ") + std::to_string(v);
      throw InputError(mesh.source, std::string("labelled ") + facetName(dim_) + " " +
                                        std::to_string(i) + " (nodes " + nodes + ", label " +
                                        std::to_string(mesh.facetLabel[i]) + ") is not a " +
                                        (dim_ == 2 ? "side" : "face") + " of any " +
                                        cellName(dim_));
    }
  }
}

void LagrangeSpace::buildEdgeTable() {
  // Every (edge, cell, local edge) once, bucketed by the edge's smaller vertex (counting
  // sort), each small bucket sorted by the larger vertex: O(N) plus a short sort per vertex,
  // as MeshTopology builds the facets.
  constexpr int ne = SimplexNodes<3>::numEdges;
  const Index np = mesh_->numPoints(), nc = mesh_->numCells();
  struct Entry {
    Index other;
    Index slot;  // 6 · cell + local edge
    bool operator<(const Entry& o) const {
      return other != o.other ? other < o.other : slot < o.slot;
    }
  };
  std::vector<Index> start(static_cast<std::size_t>(np) + 1, 0);
  for (Index c = 0; c < nc; ++c)
    for (const auto& e : SimplexNodes<3>::edges)
      ++start[std::min(mesh_->cellVertex(c, e[0]), mesh_->cellVertex(c, e[1])) + 1];
  for (Index v = 0; v < np; ++v) start[v + 1] += start[v];
  std::vector<Entry> entries(static_cast<std::size_t>(start[np]));
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index c = 0; c < nc; ++c)
      for (int k = 0; k < ne; ++k) {
        const Index a = mesh_->cellVertex(c, SimplexNodes<3>::edges[k][0]);
        const Index b = mesh_->cellVertex(c, SimplexNodes<3>::edges[k][1]);
        entries[fill[std::min(a, b)]++] = {std::max(a, b), ne * c + k};
      }
  }
  cellEdges_.resize(static_cast<std::size_t>(ne) * nc);
  edgeStart_.assign(static_cast<std::size_t>(np) + 1, 0);
  edgeOther_.clear();
  for (Index v = 0; v < np; ++v) {
    Entry* const first = entries.data() + start[v];
    Entry* const last = entries.data() + start[v + 1];
    std::sort(first, last);
    for (Entry* it = first; it != last; ++it) {
      if (it == first || it->other != (it - 1)->other) edgeOther_.push_back(it->other);
      cellEdges_[it->slot] = static_cast<Index>(edgeOther_.size()) - 1;
    }
    edgeStart_[v + 1] = static_cast<Index>(edgeOther_.size());
  }
  edgeOther_.shrink_to_fit();
}

Index LagrangeSpace::numEdges() const {
  return dim_ == 2 ? topology_->numFacets() : static_cast<Index>(edgeOther_.size());
}

Index LagrangeSpace::findEdge(Index a, Index b) const {
  if (dim_ == 2) return topology_->findFacet({a, b});
  if (a > b) std::swap(a, b);
  if (a < 0 || b >= mesh_->numPoints()) return -1;
  const auto first = edgeOther_.begin() + edgeStart_[a];
  const auto last = edgeOther_.begin() + edgeStart_[a + 1];
  const auto it = std::lower_bound(first, last, b);
  return it != last && *it == b ? static_cast<Index>(it - edgeOther_.begin()) : -1;
}

NodeList LagrangeSpace::cellNodes(Index cell) const {
  NodeList list;
  list.size = nodesPerCell();
  const Index* in = &cellNodes_[static_cast<std::size_t>(list.size) * cell];
  std::copy(in, in + list.size, list.node.begin());
  return list;
}

Index LagrangeSpace::midpointNode(Index a, Index b) const {
  if (degree_ != 2) return -1;
  const Index k = findEdge(a, b);
  return k < 0 ? -1 : mesh_->numPoints() + k;
}

NodeList LagrangeSpace::edgeNodes(Index a, Index b) const {
  FRICTION_ASSERT(isEdge(a, b), "edgeNodes: (a, b) is not a cell edge");
  NodeList list;
  if (degree_ == 1) {
    list.node[0] = a;
    list.node[1] = b;
    list.size = 2;
  } else {
    list.node[0] = a;
    list.node[1] = midpointNode(a, b);
    list.node[2] = b;
    list.size = 3;
  }
  return list;
}

NodeList LagrangeSpace::facetNodes(const Index* v) const {
  if (dim_ == 2) return edgeNodes(v[0], v[1]);
  NodeList list;
  for (int i = 0; i < 3; ++i) list.node[i] = v[i];
  list.size = 3;
  if (degree_ == 2) {
    for (int e = 0; e < 3; ++e) {
      list.node[3 + e] = midpointNode(v[e], v[(e + 1) % 3]);
      FRICTION_ASSERT(list.node[3 + e] >= 0, "facetNodes: a side of the facet is not an edge");
    }
    list.size = 6;
  }
  return list;
}

NodeList LagrangeSpace::labelledFacetNodes(Index f) const {
  return facetNodes(&mesh_->facetVertices[static_cast<std::size_t>(f) * dim_]);
}

std::vector<Index> LagrangeSpace::labelledFacets(int label) const {
  std::vector<Index> out;
  for (Index i = 0; i < mesh_->numFacets(); ++i)
    if (mesh_->facetLabel[i] == label) out.push_back(i);
  return out;
}

std::vector<std::array<Index, 2>> LagrangeSpace::labelledEdges(int label) const {
  FRICTION_ASSERT(dim_ == 2, "labelledEdges: the labelled facets are edges in 2D only");
  std::vector<std::array<Index, 2>> out;
  for (Index i : labelledFacets(label))
    out.push_back({mesh_->facetVertex(i, 0), mesh_->facetVertex(i, 1)});
  return out;
}

std::vector<Index> LagrangeSpace::patchNodes(int label) const {
  std::vector<Index> nodes;
  for (Index f : labelledFacets(label))
    for (Index n : labelledFacetNodes(f)) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace friction
