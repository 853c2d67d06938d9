// Coincident vertices and unlabelled boundary edges: see MeshCheck.hpp.
#include "friction/mesh/MeshCheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "friction/mesh/MeshTopology.hpp"

namespace friction {

std::vector<std::pair<Index, Index>> coincidentPoints(const Mesh& mesh) {
  const Index n = mesh.numPoints();
  // Shortest triangle side at each vertex (infinite for a vertex no triangle uses: such a
  // vertex is not part of the body and is left out).
  std::vector<double> h(n, std::numeric_limits<double>::infinity());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const double l = (mesh.points[a] - mesh.points[b]).norm();
      h[a] = std::min(h[a], l);
      h[b] = std::min(h[b], l);
    }
  double cell = 0;
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(h[v])) cell = std::max(cell, coincidentTolerance * h[v]);
  std::vector<std::pair<Index, Index>> pairs;
  if (!(cell > 0)) return pairs;

  // Grid with cells of the largest tolerance, as a sorted list (one allocation): a
  // coincident pair lies in neighbouring cells. Cell coordinates are clamped so that a huge
  // coordinate cannot overflow.
  const auto cellOf = [&](double x) {
    constexpr double limit = 1e15;
    return static_cast<std::int64_t>(std::max(-limit, std::min(limit, std::floor(x / cell))));
  };
  struct Entry {
    std::int64_t i, j;
    Index v;
    bool operator<(const Entry& o) const {
      return i != o.i ? i < o.i : j != o.j ? j < o.j : v < o.v;
    }
  };
  std::vector<Entry> grid;
  grid.reserve(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(h[v]))
      grid.push_back({cellOf(mesh.points[v].x()), cellOf(mesh.points[v].y()), v});
  std::sort(grid.begin(), grid.end());
  for (const Entry& e : grid)
    for (std::int64_t di = -1; di <= 1; ++di) {
      // Cells (i+di, j-1..j+1) are contiguous in the sorted list.
      auto it = std::lower_bound(grid.begin(), grid.end(), Entry{e.i + di, e.j - 1, -1});
      for (; it != grid.end() && it->i == e.i + di && it->j <= e.j + 1; ++it) {
        const Index v = e.v, w = it->v;
        if (w <= v) continue;
        if ((mesh.points[v] - mesh.points[w]).norm() <= coincidentTolerance * std::min(h[v], h[w]))
          pairs.emplace_back(v, w);
      }
    }
  if (pairs.empty()) return pairs;
  // Vertices joined by a triangle side are a side length apart and so never within the
  // tolerance of each other; a side of (near) zero length is a degenerate triangle, which the
  // readers refuse. Kept as a guard for meshes built in code.
  const auto topology = mesh.topology();
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const std::pair<Index, Index>& p) {
                               return topology->findFacet({p.first, p.second}) >= 0;
                             }),
              pairs.end());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::array<Index, 2>> unlabelledBoundaryEdges(const Mesh& mesh) {
  const auto topology = mesh.topology();
  std::vector<char> labelled(static_cast<std::size_t>(topology->numFacets()), 0);
  for (const auto& e : mesh.edges) {
    const Index f = topology->findFacet({e[0], e[1]});
    if (f >= 0) labelled[f] = 1;
  }
  std::vector<std::array<Index, 2>> out;
  for (Index f = 0; f < topology->numFacets(); ++f) {
    if (!topology->isBoundary(f) || labelled[f]) continue;
    // Local side k is opposite vertex k: the side from vertex k + 1 to k + 2, as the
    // (counter-clockwise) triangle runs.
    const auto [cell, k] = topology->cellOf(f, 0);
    out.push_back(
        {topology->cellVertex(cell, (k + 1) % 3), topology->cellVertex(cell, (k + 2) % 3)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace friction
