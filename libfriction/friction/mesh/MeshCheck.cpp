// Coincident vertices, unlabelled boundary facets, cell sizes: see MeshCheck.hpp.
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
  // Distances in 2D read x and y only (results stay those of the 2D code, byte for byte).
  const auto distance = [&](Index a, Index b) {
    return mesh.dim == 2 ? (mesh.points[a].head<2>() - mesh.points[b].head<2>()).norm()
                         : (mesh.points[a] - mesh.points[b]).norm();
  };
  const int nv = mesh.verticesPerCell();
  for (Index c = 0; c < mesh.numCells(); ++c) {
    const auto t = mesh.cell(c);
    for (int i = 0; i < nv; ++i)
      for (int j = i + 1; j < nv; ++j) {
        const Index a = t[i], b = t[j];
        const double l = distance(a, b);
        h[a] = std::min(h[a], l);
        h[b] = std::min(h[b], l);
      }
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
    std::int64_t i, j, k;  // k = 0 in 2D
    Index v;
    bool operator<(const Entry& o) const {
      return i != o.i ? i < o.i : j != o.j ? j < o.j : k != o.k ? k < o.k : v < o.v;
    }
  };
  std::vector<Entry> grid;
  grid.reserve(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v)
    if (std::isfinite(h[v]))
      grid.push_back({cellOf(mesh.points[v].x()), cellOf(mesh.points[v].y()),
                      mesh.dim == 3 ? cellOf(mesh.points[v].z()) : 0, v});
  std::sort(grid.begin(), grid.end());
  const auto near = [&](const Entry& e, std::int64_t i, std::int64_t j, std::int64_t k0,
                        std::int64_t k1) {
    // Cells (i, j, k0..k1) are contiguous in the sorted list.
    auto it = std::lower_bound(grid.begin(), grid.end(), Entry{i, j, k0, -1});
    for (; it != grid.end() && it->i == i && it->j == j && it->k <= k1; ++it) {
      const Index v = e.v, w = it->v;
      if (w <= v) continue;
      if (distance(v, w) <= coincidentTolerance * std::min(h[v], h[w])) pairs.emplace_back(v, w);
    }
  };
  for (const Entry& e : grid)
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        if (mesh.dim == 3)
          near(e, e.i + di, e.j + dj, e.k - 1, e.k + 1);
        else
          near(e, e.i + di, e.j + dj, 0, 0);
      }
  if (pairs.empty()) return pairs;
  // Vertices of one cell are an edge length apart and so never within the tolerance of each
  // other; an edge of (near) zero length is a degenerate cell, which the readers refuse. Kept
  // as a guard for meshes built in code.
  std::vector<std::uint64_t> joined;
  {
    std::vector<char> inPair(static_cast<std::size_t>(n), 0);
    for (const auto& [a, b] : pairs) inPair[a] = inPair[b] = 1;
    for (Index c = 0; c < mesh.numCells(); ++c) {
      const auto t = mesh.cell(c);
      for (int i = 0; i < nv; ++i)
        for (int j = i + 1; j < nv; ++j)
          if (inPair[t[i]] && inPair[t[j]]) joined.push_back(sideKey(t[i], t[j]));
    }
    std::sort(joined.begin(), joined.end());
  }
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const std::pair<Index, Index>& p) {
                               return std::binary_search(joined.begin(), joined.end(),
                                                         sideKey(p.first, p.second));
                             }),
              pairs.end());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<Index> unlabelledBoundaryFacets(const Mesh& mesh) {
  const auto topology = mesh.topology();
  std::vector<char> labelled(static_cast<std::size_t>(topology->numFacets()), 0);
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const auto v = mesh.facet(e);
    const Index f =
        mesh.dim == 2 ? topology->findFacet({v[0], v[1]}) : topology->findFacet({v[0], v[1], v[2]});
    if (f >= 0) labelled[f] = 1;
  }
  // Local facet k is opposite vertex k; these vertex orders run it with the cell on the left
  // (2D: counter-clockwise) or with the normal by the right-hand rule pointing out (3D).
  static constexpr int outward2[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  static constexpr int outward3[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<std::vector<Index>> out;
  for (Index f = 0; f < topology->numFacets(); ++f) {
    if (!topology->isBoundary(f) || labelled[f]) continue;
    const auto [cell, k] = topology->cellOf(f, 0);
    std::vector<Index> v;
    for (int j = 0; j < mesh.dim; ++j)
      v.push_back(topology->cellVertex(cell, mesh.dim == 2 ? outward2[k][j] : outward3[k][j]));
    out.push_back(std::move(v));
  }
  std::sort(out.begin(), out.end());
  std::vector<Index> flat;
  for (const auto& v : out) flat.insert(flat.end(), v.begin(), v.end());
  return flat;
}

CellSizes cellSizes(const Mesh& mesh) {
  CellSizes s;
  for (Index c = 0; c < mesh.numCells(); ++c) {
    const double m = std::abs(mesh.signedMeasure(c));
    s.total += m;
    if (s.smallestCell < 0 || m < s.smallest) s.smallest = m, s.smallestCell = c;
    if (s.largestCell < 0 || m > s.largest) s.largest = m, s.largestCell = c;
  }
  return s;
}

}  // namespace friction
