// LagrangeSpace: node and dof numbering of continuous P1 / P2 (docs/method.md §4). See the header
// for the numbering conventions.
#include "friction/fe/LagrangeSpace.hpp"

#include <algorithm>
#include <string>

#include "friction/core/Assert.hpp"
#include "friction/core/InputError.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

LagrangeSpace::LagrangeSpace(const Mesh& mesh, int degree) : mesh_(&mesh), degree_(degree) {
  FRICTION_ASSERT(degree == 1 || degree == 2, "Lagrange degree must be 1 or 2");
  if (mesh.dim != 2)
    throw InputError(mesh.source,
                     "the mesh is 3D (tetrahedra): finite elements on a 3D mesh "
                     "are not supported yet; expected a 2D triangle mesh");
  const Index np = mesh.numPoints();
  const Index nt = mesh.numCells();

  // Edges are the facets of the mesh's (shared) topology, numbered in key order (a, b), a < b.
  topology_ = mesh.topology();

  // Node coordinates: mesh points, then edge midpoints in edge order.
  coordinates_.reserve(np + (degree_ == 2 ? topology_->numFacets() : 0));
  for (const Point& p : mesh.points) coordinates_.push_back(p.head<2>());
  if (degree_ == 2) {
    for (Index f = 0; f < topology_->numFacets(); ++f)
      coordinates_.push_back(0.5 * (mesh.points[topology_->facetVertex(f, 0)].head<2>() +
                                    mesh.points[topology_->facetVertex(f, 1)].head<2>()));
  }

  const int npc = nodesPerCell();
  cellNodes_.resize(static_cast<std::size_t>(npc) * nt);
  for (Index c = 0; c < nt; ++c) {
    const auto t = mesh.cell(c);
    Index* out = &cellNodes_[static_cast<std::size_t>(npc) * c];
    out[0] = t[0];
    out[1] = t[1];
    out[2] = t[2];
    // Midpoint of local edge (v_e, v_e+1): the facet opposite vertex e + 2.
    if (degree_ == 2)
      for (int e = 0; e < 3; ++e) out[3 + e] = np + topology_->cellFacet(c, (e + 2) % 3);
  }

  // A labelled edge that no triangle has would get no midpoint and no stiffness: the mesh is
  // inconsistent, and the user must hear about it now rather than see a singular matrix.
  for (Index i = 0; i < mesh.numFacets(); ++i) {
    const auto e = mesh.facet(i);
    const bool inRange = e[0] >= 0 && e[0] < np && e[1] >= 0 && e[1] < np;
    if (!inRange || findEdge(e[0], e[1]) < 0)
      throw InputError(mesh.source, "labelled edge " + std::to_string(i) + " (nodes " +
                                        std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                                        ", label " + std::to_string(mesh.facetLabel[i]) +
                                        ") is not a side of any triangle");
  }
}

Index LagrangeSpace::numEdges() const { return topology_->numFacets(); }

Index LagrangeSpace::findEdge(Index a, Index b) const { return topology_->findFacet({a, b}); }

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
  FRICTION_ASSERT(isEdge(a, b), "edgeNodes: (a, b) is not a triangle side");
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

std::vector<std::array<Index, 2>> LagrangeSpace::labelledEdges(int label) const {
  std::vector<std::array<Index, 2>> out;
  for (Index i = 0; i < mesh_->numFacets(); ++i)
    if (mesh_->facetLabel[i] == label)
      out.push_back({mesh_->facetVertex(i, 0), mesh_->facetVertex(i, 1)});
  return out;
}

std::vector<Index> LagrangeSpace::patchNodes(int label) const {
  std::vector<Index> nodes;
  for (const auto& e : labelledEdges(label))
    for (Index n : edgeNodes(e[0], e[1])) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace friction
