// Coincident vertices and unlabelled boundary edges: see MeshCheck.hpp.
#include "friction/mesh/MeshCheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_set>

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
  std::unordered_set<std::uint64_t> candidates;
  for (const auto& [v, w] : pairs) candidates.insert(sideKey(v, w));
  std::unordered_set<std::uint64_t> joined;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = sideKey(t[k], t[(k + 1) % 3]);
      if (candidates.count(key)) joined.insert(key);
    }
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const std::pair<Index, Index>& p) {
                               return joined.count(sideKey(p.first, p.second)) > 0;
                             }),
              pairs.end());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::array<Index, 2>> unlabelledBoundaryEdges(const Mesh& mesh) {
  // Sorting beats hashing here: one allocation for all sides.
  struct Side {
    std::uint64_t key;
    std::array<Index, 2> edge;
    bool operator<(const Side& o) const { return key < o.key; }
  };
  std::vector<Side> sides;
  sides.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      sides.push_back({sideKey(t[k], t[(k + 1) % 3]), {t[k], t[(k + 1) % 3]}});
  std::sort(sides.begin(), sides.end());
  std::vector<std::uint64_t> labelled;
  labelled.reserve(mesh.edges.size());
  for (const auto& e : mesh.edges) labelled.push_back(sideKey(e[0], e[1]));
  std::sort(labelled.begin(), labelled.end());
  std::vector<std::array<Index, 2>> out;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    if (j == i + 1 && !std::binary_search(labelled.begin(), labelled.end(), sides[i].key))
      out.push_back(sides[i].edge);
    i = j;
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace friction
