// Small structured meshes for the splitting tests: the unit square cut into n x n cells, each
// cell into two counter-clockwise triangles along its (0,0)-(1,1) diagonal. Boundary labels
// 1..4 = bottom, right, top, left (FreeFEM's convention); the caller adds fracture edges.
#pragma once

#include <functional>
#include <numeric>
#include <set>

#include "friction/mesh/Mesh.hpp"

namespace friction::test {

inline Index gridNode(int n, int i, int j) { return j * (n + 1) + i; }

inline Mesh gridMesh(int n) {
  Mesh m;
  m.source = "grid" + std::to_string(n);
  m.format = "test grid";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.points.emplace_back(double(i) / n, double(j) / n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = gridNode(n, i, j), b = gridNode(n, i + 1, j), c = gridNode(n, i + 1, j + 1),
                  d = gridNode(n, i, j + 1);
      m.cellVertices.insert(m.cellVertices.end(), {a, b, c});
      m.cellVertices.insert(m.cellVertices.end(), {a, c, d});
      m.cellRegion.push_back(0);
      m.cellRegion.push_back(0);
    }
  for (int k = 0; k < n; ++k) {
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, k, 0), gridNode(n, k + 1, 0)});
    m.facetLabel.push_back(1);
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, n, k), gridNode(n, n, k + 1)});
    m.facetLabel.push_back(2);
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, k + 1, n), gridNode(n, k, n)});
    m.facetLabel.push_back(3);
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 0, k + 1), gridNode(n, 0, k)});
    m.facetLabel.push_back(4);
  }
  m.labelNames = {{1, "bottom"}, {2, "right"}, {3, "top"}, {4, "left"}};
  return m;
}

/// Horizontal fracture along grid row j from column i0 to i1, with the given label; edges are
/// added in reversed orientation on purpose (FreeFEM's orientation is arbitrary).
inline void addHorizontalFracture(Mesh& m, int n, int j, int i0, int i1, int label,
                                  const std::string& name) {
  for (int i = i0; i < i1; ++i) {
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, i + 1, j), gridNode(n, i, j)});
    m.facetLabel.push_back(label);
  }
  m.labelNames[label] = name;
}

/// Number of groups of triangles connected through shared nodes.
inline int connectedComponents(const Mesh& m) {
  std::vector<int> parent(m.numPoints());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int i) {
    return parent[i] == i ? i : parent[i] = find(parent[i]);
  };
  for (Index t_ = 0; t_ < m.numCells(); ++t_) {
    const auto t = m.cell(t_);
    parent[find(t[0])] = find(t[1]);
    parent[find(t[1])] = find(t[2]);
  }
  std::set<int> roots;
  for (Index t_ = 0; t_ < m.numCells(); ++t_)
    if (const auto t = m.cell(t_); true) roots.insert(find(t[0]));
  return static_cast<int>(roots.size());
}

}  // namespace friction::test
