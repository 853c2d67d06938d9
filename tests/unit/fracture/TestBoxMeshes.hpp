// Small structured tetrahedral meshes for the 3D splitting tests: the unit cube cut into n³
// cubes, each into the 6 Kuhn tetrahedra (the paths from its corner (0,0,0) to (1,1,1) along
// the axes in every order), so that every grid plane is a union of tetrahedron faces. Boundary
// labels 1..6 = x = 0, x = 1, y = 0, y = 1, z = 0, z = 1; the caller adds fault triangles.
#pragma once

#include <algorithm>
#include <array>
#include <string>

#include <Eigen/Geometry>

#include "friction/mesh/Mesh.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction::test {

inline Index boxNode(int n, int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; }

inline Mesh boxMesh(int n) {
  Mesh m;
  m.source = "box" + std::to_string(n);
  m.format = "test box";
  m.dim = 3;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.points.emplace_back(double(i) / n, double(j) / n, double(k) / n);
  std::array<int, 3> order{0, 1, 2};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::sort(order.begin(), order.end());
        do {
          std::array<int, 3> c{i, j, k};
          std::array<Index, 4> tet;
          tet[0] = boxNode(n, c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[order[s]];
            tet[s + 1] = boxNode(n, c[0], c[1], c[2]);
          }
          const Point& a = m.points[tet[0]];
          if ((m.points[tet[1]] - a).cross(m.points[tet[2]] - a).dot(m.points[tet[3]] - a) < 0)
            std::swap(tet[2], tet[3]);
          m.addCell({tet[0], tet[1], tet[2], tet[3]});
        } while (std::next_permutation(order.begin(), order.end()));
      }
  MeshTopology topo(m);
  for (Index f = 0; f < topo.numFacets(); ++f) {
    if (!topo.isBoundary(f)) continue;
    const Point c = (m.points[topo.facetVertex(f, 0)] + m.points[topo.facetVertex(f, 1)] +
                     m.points[topo.facetVertex(f, 2)]) /
                    3;
    int label = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (c[axis] < 1e-12) label = 2 * axis + 1;
      if (c[axis] > 1 - 1e-12) label = 2 * axis + 2;
    }
    m.addFacet({topo.facetVertex(f, 0), topo.facetVertex(f, 1), topo.facetVertex(f, 2)}, label);
  }
  m.labelNames = {{1, "xmin"}, {2, "xmax"}, {3, "ymin"}, {4, "ymax"}, {5, "zmin"}, {6, "zmax"}};
  return m;
}

/// The grid squares [a0, a1) × [b0, b1) of the plane {x_axis = level} (in-plane axes u < v in
/// their natural order) as triangles with the given label, each square along the diagonal of
/// the Kuhn tetrahedra; `flip` alternates the triangles' orientation (the file's orientation is
/// arbitrary).
inline void addPlaneFault(Mesh& m, int n, int axis, int level, int a0, int a1, int b0, int b1,
                          int label, const std::string& name) {
  const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
  auto node = [&](int a, int b) {
    std::array<int, 3> c{};
    c[axis] = level;
    c[u] = a;
    c[v] = b;
    return boxNode(n, c[0], c[1], c[2]);
  };
  bool flip = false;
  for (int a = a0; a < a1; ++a)
    for (int b = b0; b < b1; ++b) {
      const Index p = node(a, b), q = node(a + 1, b), r = node(a + 1, b + 1), s = node(a, b + 1);
      if (flip) {
        m.addFacet({p, r, q}, label);
        m.addFacet({p, r, s}, label);
      } else {
        m.addFacet({p, q, r}, label);
        m.addFacet({p, s, r}, label);
      }
      flip = !flip;
    }
  m.labelNames[label] = name;
}

}  // namespace friction::test
