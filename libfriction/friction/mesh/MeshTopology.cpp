// MeshTopology: see MeshTopology.hpp.
#include "friction/mesh/MeshTopology.hpp"

#include <algorithm>
#include <utility>

#include "friction/core/Assert.hpp"
#include "friction/core/InputError.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

namespace {

std::vector<Index> flatTriangles(const Mesh& mesh) {
  std::vector<Index> cells;
  cells.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) cells.insert(cells.end(), t.begin(), t.end());
  return cells;
}

// A facet seen from one cell, in the bucket of its smallest vertex: the rest of its key, then
// the cell, so that sorting a bucket gives the facets in key order and each facet's cells in
// ascending order.
struct Entry {
  std::array<Index, MeshTopology::maxDimension - 1> rest;
  Index cell;
  int local;
  bool operator<(const Entry& o) const {
    return rest != o.rest ? rest < o.rest : cell != o.cell ? cell < o.cell : local < o.local;
  }
};

// Sort the first n (≤ maxDimension) entries of a key; insertion sort, as std::sort would do for
// so few (and GCC 12 warns about std::sort's unrolled loop on a 3-element array).
void sortKey(std::array<Index, MeshTopology::maxDimension>& key, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && key[j] < key[j - 1]; --j) std::swap(key[j], key[j - 1]);
}

}  // namespace

MeshTopology::MeshTopology(const Mesh& mesh)
    : MeshTopology(2, mesh.numPoints(), flatTriangles(mesh), mesh.source) {}

MeshTopology::MeshTopology(int dimension, Index numVertices, std::vector<Index> cellVertices,
                           const std::string& source)
    : dim_(dimension), numVertices_(numVertices), cells_(std::move(cellVertices)) {
  FRICTION_ASSERT(dim_ >= 1 && dim_ <= maxDimension, "MeshTopology: dimension out of range");
  const int nv = dim_ + 1;  // vertices (and facets) per cell
  FRICTION_ASSERT(cells_.size() % nv == 0, "MeshTopology: cell list of the wrong length");
  const Index nc = numCells();
  for (std::size_t i = 0; i < cells_.size(); ++i)
    if (cells_[i] < 0 || cells_[i] >= numVertices_)
      throw InputError(source, "cell " + std::to_string(i / nv) + " has vertex " +
                                   std::to_string(cells_[i]) +
                                   ", which is not a point of the mesh (expected 0 to " +
                                   std::to_string(numVertices_ - 1) + ")");

  // Key of local facet k of cell c: its vertices (all but vertex k), ascending.
  const auto keyOf = [&](Index c, int k) {
    std::array<Index, maxDimension> key{};
    int n = 0;
    for (int j = 0; j < nv; ++j)
      if (j != k) key[n++] = cells_[at(c, j)];
    sortKey(key, dim_);
    return key;
  };

  // Bucket every (facet, cell) by the facet's smallest vertex (counting sort), then sort the
  // few entries of each bucket.
  std::vector<Index> start(static_cast<std::size_t>(numVertices_) + 1, 0);
  for (Index c = 0; c < nc; ++c)
    for (int k = 0; k < nv; ++k) ++start[keyOf(c, k)[0] + 1];
  for (Index v = 0; v < numVertices_; ++v) start[v + 1] += start[v];
  std::vector<Entry> entries(cells_.size());
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index c = 0; c < nc; ++c)
      for (int k = 0; k < nv; ++k) {
        const auto key = keyOf(c, k);
        Entry& e = entries[fill[key[0]]++];
        e.rest = {};
        std::copy(key.begin() + 1, key.begin() + dim_, e.rest.begin());
        e.cell = c;
        e.local = k;
      }
  }

  cellFacets_.assign(cells_.size(), -1);
  facetCells_.reserve(entries.size());
  facetCellStart_.reserve(entries.size() / 2 + numVertices_ + 1);
  facetVertices_.reserve(entries.size() / 2 * dim_ + dim_);
  firstFacet_.assign(static_cast<std::size_t>(numVertices_) + 1, 0);
  facetCellStart_.push_back(0);
  for (Index v = 0; v < numVertices_; ++v) {
    const auto first = entries.begin() + start[v], last = entries.begin() + start[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last;) {
      auto end = it + 1;
      while (end != last && end->rest == it->rest) ++end;
      const Index f = numFacets();
      facetVertices_.push_back(v);
      facetVertices_.insert(facetVertices_.end(), it->rest.begin(), it->rest.begin() + dim_ - 1);
      for (auto e = it; e != end; ++e) {
        facetCells_.push_back({e->cell, e->local});
        cellFacets_[at(e->cell, e->local)] = f;
      }
      facetCellStart_.push_back(static_cast<Index>(facetCells_.size()));
      if (end - it > 2) overShared_.push_back(f);
      it = end;
    }
    firstFacet_[v + 1] = numFacets();
  }
}

bool MeshTopology::describes(const Mesh& mesh) const {
  if (dim_ != 2 || numVertices_ != mesh.numPoints() || numCells() != mesh.numTriangles())
    return false;
  for (Index c = 0; c < numCells(); ++c)
    for (int k = 0; k < 3; ++k)
      if (cells_[at(c, k)] != mesh.triangles[c][k]) return false;
  return true;
}

Index MeshTopology::findFacet(std::initializer_list<Index> vertices) const {
  if (static_cast<int>(vertices.size()) != dim_) return -1;
  std::array<Index, maxDimension> key{};
  std::copy(vertices.begin(), vertices.end(), key.begin());
  sortKey(key, dim_);
  const Index v = key[0];
  if (v < 0 || v >= numVertices_) return -1;
  // The facets of smallest vertex v are in key order: binary search on the rest of the key.
  Index lo = firstFacet_[v], hi = firstFacet_[v + 1];
  while (lo < hi) {
    const Index mid = lo + (hi - lo) / 2;
    const Index* f = &facetVertices_[static_cast<std::size_t>(mid) * dim_];
    if (std::lexicographical_compare(f + 1, f + dim_, key.begin() + 1, key.begin() + dim_))
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo == firstFacet_[v + 1]) return -1;
  const Index* f = &facetVertices_[static_cast<std::size_t>(lo) * dim_];
  return std::equal(f + 1, f + dim_, key.begin() + 1) ? lo : -1;
}

}  // namespace friction
