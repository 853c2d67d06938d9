// Fault flow meshes for the flow tests: a straight line in 2D, a structured triangulated square
// in 3D, and the discrete error norms the convergence tests use.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "friction/flow/FaultFlowMesh.hpp"

namespace friction::test {

/// Segments of length h on the x axis from −L to L (2n + 1 nodes, node n at the origin).
inline FaultFlowMesh lineMesh(double L, int n) {
  std::vector<Point> points;
  std::vector<FaultFlowMesh::Segment> segments;
  for (int i = 0; i <= 2 * n; ++i) points.emplace_back(-L + L * i / n, 0.0, 0.0);
  for (int i = 0; i < 2 * n; ++i) segments.push_back({i, i + 1});
  return FaultFlowMesh(points, segments);
}

/// The square [−L, L]² in the plane z = 0, 2n × 2n squares each cut along one diagonal (the
/// P1 stiffness is then the 5-point Laplacian); node (2n + 1)·n + n at the origin.
inline FaultFlowMesh squareMesh(double L, int n) {
  const int m = 2 * n + 1;
  std::vector<Point> points;
  std::vector<FaultFlowMesh::Triangle> triangles;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) points.emplace_back(-L + L * i / n, -L + L * j / n, 0.0);
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < m; ++i) {
      const int a = j * m + i, b = a + 1, c = a + m + 1, d = a + m;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  return FaultFlowMesh(points, triangles);
}

/// Errors of p against exact(x) over the nodes where keep(x) holds: the largest and the
/// lumped-mass L2 norm, both relative to the exact values' own norms there.
struct RelativeError {
  double max = 0.0;
  double l2 = 0.0;
  int nodes = 0;
};
inline RelativeError relativeError(const FaultFlowMesh& mesh, const Eigen::VectorXd& p,
                                   const std::function<double(const Point&)>& exact,
                                   const std::function<bool(const Point&)>& keep) {
  const Eigen::VectorXd m = mesh.lumpedMass();
  double eMax = 0.0, xMax = 0.0, e2 = 0.0, x2 = 0.0;
  RelativeError r;
  for (Index i = 0; i < mesh.numNodes(); ++i) {
    if (!keep(mesh.point(i))) continue;
    const double x = exact(mesh.point(i)), e = p[i] - x;
    eMax = std::max(eMax, std::abs(e));
    xMax = std::max(xMax, std::abs(x));
    e2 += m[i] * e * e;
    x2 += m[i] * x * x;
    ++r.nodes;
  }
  r.max = eMax / xMax;
  r.l2 = std::sqrt(e2 / x2);
  return r;
}

}  // namespace friction::test
