// Meshes for the finite-element tests, built in code: the unit square cut into n × n cells,
// each cell into two counter-clockwise triangles along its (0,0)-(1,1) diagonal, boundary
// labels 1..4 = bottom, right, top, left. Optionally distorted: interior nodes moved by up to
// `amount`·h/2 in each direction, boundary nodes (not corners) moved along their side, by a
// fixed pseudo-random sequence so that every run sees the same mesh.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction::test {

/// A 2D field as the assembler's VectorField (z ignored on the way in, 0 on the way out).
inline VectorField planar(std::function<Vector2(const Vector2&)> f) {
  return [f](const Point& p) {
    const Vector2 v = f(p.head<2>());
    return Point(v.x(), v.y(), 0.0);
  };
}

/// Deterministic value in [−0.5, 0.5] for node k (a hash, not a random generator, so that
/// the meshes do not depend on the standard library's engines).
inline double jitter(int k, int salt) {
  unsigned h = static_cast<unsigned>(k) * 2654435761u ^ (static_cast<unsigned>(salt) * 40503u);
  h ^= h >> 13;
  h *= 1274126177u;
  h ^= h >> 16;
  return (h % 100000u) / 100000.0 - 0.5;
}

inline Mesh unitSquareMesh(int n, double amount = 0.0) {
  Mesh m;
  m.source = "unitSquare" + std::to_string(n);
  m.format = "test grid";
  const double h = 1.0 / n;
  auto node = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = i * h, y = j * h;
      const int k = node(i, j);
      const bool bx = (i == 0 || i == n), by = (j == 0 || j == n);
      if (!bx) x += amount * h * jitter(k, 1);
      if (!by) y += amount * h * jitter(k, 2);
      m.points.emplace_back(x, y, 0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      m.cellVertices.insert(m.cellVertices.end(), {a, b, c});
      m.cellVertices.insert(m.cellVertices.end(), {a, c, d});
      m.cellRegion.push_back(0);
      m.cellRegion.push_back(0);
    }
  for (int k = 0; k < n; ++k) {
    m.facetVertices.insert(m.facetVertices.end(), {node(k, 0), node(k + 1, 0)});
    m.facetLabel.push_back(1);
    m.facetVertices.insert(m.facetVertices.end(), {node(n, k), node(n, k + 1)});
    m.facetLabel.push_back(2);
    m.facetVertices.insert(m.facetVertices.end(), {node(k + 1, n), node(k, n)});
    m.facetLabel.push_back(3);
    m.facetVertices.insert(m.facetVertices.end(), {node(0, k + 1), node(0, k)});
    m.facetLabel.push_back(4);
  }
  m.labelNames = {{1, "bottom"}, {2, "right"}, {3, "top"}, {4, "left"}};
  for (Index t_ = 0; t_ < m.numCells(); ++t_) {
    const auto t = m.cell(t_);
    const Vector2 e1 = (m.points[t[1]] - m.points[t[0]]).head<2>(),
                  e2 = (m.points[t[2]] - m.points[t[0]]).head<2>();
    if (e1.x() * e2.y() - e1.y() * e2.x() <= 0.0)
      throw std::logic_error("unitSquareMesh: distortion inverted a triangle");
  }
  return m;
}

/// Two unit squares stacked, [0,1] × [0,1], split along y = 1/2 into two halves that share no
/// node: the top half uses nodes 2 = (0, ½)⁺ and 3 = (1, ½)⁺, the bottom half their coincident
/// copies 6 and 7 — what splitting a fracture along y = ½ produces. Four triangles.
inline Mesh splitFourTriangleMesh() {
  Mesh m;
  m.source = "splitFourTriangles";
  m.format = "test mesh";
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 0.5, 0}, {1, 0.5, 0},
              {0, 1, 0}, {1, 1, 0}, {0, 0.5, 0}, {1, 0.5, 0}};
  m.cellVertices = {0, 1, 7, 0, 7, 6, 2, 3, 5, 2, 5, 4};
  m.cellRegion = {2, 2, 1, 1};
  m.facetVertices = {0, 1, 1, 7, 3, 5, 5, 4, 4, 2, 6, 0};
  m.facetLabel = {1, 2, 2, 3, 4, 4};
  return m;
}

/// The unit cube cut into n³ cubes, each into the 6 tetrahedra of its Kuhn (Freudenthal)
/// triangulation (all around the cube's (0,0,0)-(1,1,1) diagonal), every one positively
/// oriented; boundary triangles labelled 1..6 = x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
/// Interior nodes optionally moved by up to `amount`·h/2 in each direction (deterministic).
inline Mesh unitCubeMesh(int n, double amount = 0.0) {
  Mesh m;
  m.dim = 3;
  m.source = "unitCube" + std::to_string(n);
  m.format = "test grid";
  const double h = 1.0 / n;
  auto node = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Point x(i * h, j * h, k * h);
        const bool inside = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        if (inside)
          for (int c = 0; c < 3; ++c) x[c] += amount * h * jitter(node(i, j, k), c + 1);
        m.points.push_back(x);
      }
  const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perm) {
          // The path from the cube's corner (i, j, k) to the opposite one, one axis at a time.
          int at[3] = {i, j, k};
          Index v[4];
          v[0] = node(at[0], at[1], at[2]);
          for (int s = 0; s < 3; ++s) {
            ++at[p[s]];
            v[s + 1] = node(at[0], at[1], at[2]);
          }
          m.addCell({v[0], v[1], v[2], v[3]});
          if (m.signedMeasure(m.numCells() - 1) < 0.0)
            std::swap(m.cell(m.numCells() - 1)[2], m.cell(m.numCells() - 1)[3]);
          if (!(m.signedMeasure(m.numCells() - 1) > 0.0))
            throw std::logic_error("unitCubeMesh: a tetrahedron is not positively oriented");
        }
  // Boundary triangles: the facets of one cell whose three vertices lie on one cube face.
  auto face = [&](Index a, Index b, Index c) {
    const Point& x = m.points[a];
    const Point& y = m.points[b];
    const Point& z = m.points[c];
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        if (x[axis] == side && y[axis] == side && z[axis] == side) return 1 + 2 * axis + side;
    return 0;
  };
  const Index nc = m.numCells();
  for (Index c = 0; c < nc; ++c)
    for (int skip = 0; skip < 4; ++skip) {
      Index f[3];
      for (int q = 0, r = 0; q < 4; ++q)
        if (q != skip) f[r++] = m.cellVertex(c, q);
      if (const int label = face(f[0], f[1], f[2])) m.addFacet({f[0], f[1], f[2]}, label);
    }
  m.labelNames = {{1, "x0"}, {2, "x1"}, {3, "y0"}, {4, "y1"}, {5, "z0"}, {6, "z1"}};
  return m;
}

}  // namespace friction::test
