// Coincident vertices and unlabelled boundary edges: see MeshCheck.hpp.
#include "friction/mesh/MeshCheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace friction {

namespace {

std::uint64_t sideKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace

std::vector<std::pair<Index, Index>> coincidentPoints(const Mesh& mesh) {
  const Index n = mesh.numPoints();
  // Shortest triangle side at each vertex (infinite for a vertex no triangle uses: such a
  // vertex is not part of the body and is left out).
  std::vector<double> h(n, std::numeric_limits<double>::infinity());
  std::unordered_set<std::uint64_t> sides;
  sides.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const double l = (mesh.points[a] - mesh.points[b]).norm();
      h[a] = std::min(h[a], l);
      h[b] = std::min(h[b], l);
      sides.insert(sideKey(a, b));
    }
  double cell = 0;
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(h[v])) cell = std::max(cell, coincidentTolerance * h[v]);
  std::vector<std::pair<Index, Index>> pairs;
  if (!(cell > 0)) return pairs;

  // Hash grid with cells of the largest tolerance: a coincident pair lies in neighbouring
  // cells. Cell coordinates are clamped so that a huge coordinate cannot overflow.
  const auto cellOf = [&](double x) {
    const double c = std::floor(x / cell);
    constexpr double limit = 1e15;
    return static_cast<std::int64_t>(std::max(-limit, std::min(limit, c)));
  };
  const auto cellKey = [](std::int64_t i, std::int64_t j) {
    return static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(j);
  };
  std::unordered_map<std::uint64_t, std::vector<Index>> grid;
  grid.reserve(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(h[v]))
      grid[cellKey(cellOf(mesh.points[v].x()), cellOf(mesh.points[v].y()))].push_back(v);
  for (Index v = 0; v < n; ++v) {
    if (!std::isfinite(h[v])) continue;
    const std::int64_t ci = cellOf(mesh.points[v].x()), cj = cellOf(mesh.points[v].y());
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        auto it = grid.find(cellKey(ci + di, cj + dj));
        if (it == grid.end()) continue;
        for (Index w : it->second) {
          if (w <= v) continue;
          const double tol = coincidentTolerance * std::min(h[v], h[w]);
          if ((mesh.points[v] - mesh.points[w]).norm() <= tol && !sides.count(sideKey(v, w)))
            pairs.emplace_back(v, w);
        }
      }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());  // hash collisions
  return pairs;
}

std::vector<std::array<Index, 2>> unlabelledBoundaryEdges(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, std::pair<int, std::array<Index, 2>>> sides;
  sides.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      auto& s = sides[sideKey(t[k], t[(k + 1) % 3])];
      ++s.first;
      s.second = {t[k], t[(k + 1) % 3]};
    }
  std::unordered_set<std::uint64_t> labelled;
  for (const auto& e : mesh.edges) labelled.insert(sideKey(e[0], e[1]));
  std::vector<std::array<Index, 2>> out;
  for (const auto& [key, s] : sides)
    if (s.first == 1 && !labelled.count(key)) out.push_back(s.second);
  // Hash order is not reproducible across libraries: sort for stable summaries.
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace friction
