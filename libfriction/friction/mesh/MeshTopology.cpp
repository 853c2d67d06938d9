// MeshTopology: see MeshTopology.hpp.
#include "friction/mesh/MeshTopology.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "friction/core/Assert.hpp"
#include "friction/core/InputError.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

namespace {

// A facet seen from one cell, in the bucket of its smallest vertex: the rest of its key
// (packed so that integer order is key order), then the cell and local facet (cell · 4 +
// local), so that sorting a bucket gives the facets in key order and each facet's cells
// ascending. The scatter into buckets is a cache miss per entry on a large mesh, so the entry
// is kept small: one 64-bit word up to triangles (one vertex and cell · 4 + local in 32 bits
// each), two for tetrahedra.
template <int dim>
struct Entry {
  std::uint64_t rest;
  std::uint32_t cellLocal;
  bool operator<(const Entry& o) const {
    return rest != o.rest ? rest < o.rest : cellLocal < o.cellLocal;
  }
  std::uint64_t restKey() const { return rest; }
  Index cell() const { return static_cast<Index>(cellLocal >> 2); }
  int local() const { return static_cast<int>(cellLocal & 3u); }
};
template <>
struct Entry<2> {
  std::uint64_t word;  // rest · 2³² + cell · 4 + local
  Entry() = default;
  Entry(std::uint64_t rest, std::uint32_t cellLocal) : word((rest << 32) | cellLocal) {}
  bool operator<(const Entry& o) const { return word < o.word; }
  std::uint64_t restKey() const { return word >> 32; }
  Index cell() const { return static_cast<Index>((word & 0xffffffffu) >> 2); }
  int local() const { return static_cast<int>(word & 3u); }
};
static_assert(MeshTopology::maxDimension <= 3, "Entry packs at most two vertices and 4 locals");

// Vertices of local facet k of a cell of dim + 1 vertices (all but vertex k), ascending.
template <int dim>
std::array<Index, dim> facetKey(const Index* cell, int k) {
  std::array<Index, dim> key;
  for (int j = 0, n = 0; j <= dim; ++j)
    if (j != k) key[n++] = cell[j];
  for (int i = 1; i < dim; ++i)  // insertion sort of d ≤ 3 numbers
    for (int j = i; j > 0 && key[j] < key[j - 1]; --j) std::swap(key[j], key[j - 1]);
  return key;
}

template <int dim>
std::uint64_t packRest(const std::array<Index, dim>& key) {
  std::uint64_t r = 0;
  for (int j = 1; j < dim; ++j) r = (r << 32) | static_cast<std::uint32_t>(key[j]);
  return r;
}

}  // namespace

MeshTopology::MeshTopology(const Mesh& mesh)
    : MeshTopology(mesh.dim, mesh.numPoints(), mesh.cellVertices, mesh.source) {}

MeshTopology::MeshTopology(int dimension, Index numVertices, std::vector<Index> cellVertices,
                           const std::string& source)
    : dim_(dimension), numVertices_(numVertices), cells_(std::move(cellVertices)) {
  FRICTION_ASSERT(dim_ >= 1 && dim_ <= maxDimension, "MeshTopology: dimension out of range");
  FRICTION_ASSERT(cells_.size() % (dim_ + 1) == 0, "MeshTopology: cell list of the wrong length");
  for (std::size_t i = 0; i < cells_.size(); ++i)
    if (cells_[i] < 0 || cells_[i] >= numVertices_)
      throw InputError(source, "cell " + std::to_string(i / (dim_ + 1)) + " has vertex " +
                                   std::to_string(cells_[i]) +
                                   ", which is not a point of the mesh (expected 0 to " +
                                   std::to_string(numVertices_ - 1) + ")");
  // The build packs cell · 4 + local in 32 bits.
  if (numCells() >= (Index(1) << 30))
    throw InputError(source,
                     "more than 2^30 cells (expected fewer: the mesh topology numbers "
                     "cells in 30 bits)");
  switch (dim_) {  // the dimension is dispatched once; the build is compiled per dimension
    case 1:
      build<1>();
      break;
    case 2:
      build<2>();
      break;
    default:
      build<3>();
  }
}

template <int dim>
void MeshTopology::build() {
  constexpr int nv = dim + 1;  // vertices (and facets) per cell
  const Index nc = numCells();

  // Every (facet, cell) once, in cell order, with the facet's smallest vertex; then bucketed
  // by that vertex (counting sort) and the few entries of each bucket sorted.
  std::vector<Entry<dim>> inCellOrder(cells_.size());
  std::vector<Index> smallest(cells_.size());
  std::vector<Index> start(static_cast<std::size_t>(numVertices_) + 1, 0);
  for (Index c = 0; c < nc; ++c)
    for (int k = 0; k < nv; ++k) {
      const auto key = facetKey<dim>(&cells_[at(c, 0)], k);
      inCellOrder[at(c, k)] = {packRest<dim>(key),
                               (static_cast<std::uint32_t>(c) << 2) | static_cast<unsigned>(k)};
      smallest[at(c, k)] = key[0];
      ++start[key[0] + 1];
    }
  for (Index v = 0; v < numVertices_; ++v) start[v + 1] += start[v];
  std::vector<Entry<dim>> entries(cells_.size());
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < inCellOrder.size(); ++i)
      entries[fill[smallest[i]]++] = inCellOrder[i];
  }
  inCellOrder = {};
  smallest = {};

  facetCells_.resize(entries.size());
  cellFacets_.resize(cells_.size());
  facetCellStart_.reserve(entries.size() / 2 + numVertices_ + 1);
  facetVertices_.reserve((entries.size() / 2 + numVertices_) * dim);
  firstFacet_.assign(static_cast<std::size_t>(numVertices_) + 1, 0);
  facetCellStart_.push_back(0);
  Index f = 0;
  for (Index v = 0; v < numVertices_; ++v) {
    Entry<dim>* const first = entries.data() + start[v];
    Entry<dim>* const last = entries.data() + start[v + 1];
    // A bucket holds the few facets around one vertex: insertion sort.
    for (Entry<dim>* i = first; i != last; ++i)
      for (Entry<dim>* j = i; j != first && *j < *(j - 1); --j) std::swap(*j, *(j - 1));
    for (Entry<dim>* it = first; it != last; ++f) {
      Entry<dim>* end = it + 1;
      while (end != last && end->restKey() == it->restKey()) ++end;
      facetVertices_.push_back(v);
      for (int j = dim - 2; j >= 0; --j)
        facetVertices_.push_back(static_cast<Index>((it->restKey() >> (32 * j)) & 0xffffffffu));
      for (Entry<dim>* e = it; e != end; ++e) {
        // Entries are in facet order, so facet f's cells sit at the same positions.
        facetCells_[static_cast<std::size_t>(e - entries.data())] =
            (static_cast<std::uint32_t>(e->cell()) << 2) | static_cast<unsigned>(e->local());
        cellFacets_[at(e->cell(), e->local())] = f;
      }
      facetCellStart_.push_back(static_cast<Index>(end - entries.data()));
      if (end - it > 2) overShared_.push_back(f);
      it = end;
    }
    firstFacet_[v + 1] = f;
  }
  facetVertices_.shrink_to_fit();
  facetCellStart_.shrink_to_fit();
}

bool MeshTopology::describes(const Mesh& mesh) const {
  return dim_ == mesh.dim && numVertices_ == mesh.numPoints() && cells_ == mesh.cellVertices;
}

Index MeshTopology::findFacet(std::initializer_list<Index> vertices) const {
  if (static_cast<int>(vertices.size()) != dim_) return -1;
  std::array<Index, maxDimension> key{};
  std::copy(vertices.begin(), vertices.end(), key.begin());
  for (int i = 1; i < dim_; ++i)
    for (int j = i; j > 0 && key[j] < key[j - 1]; --j) std::swap(key[j], key[j - 1]);
  if (key[0] < 0 || key[0] >= numVertices_) return -1;
  return findFacetKey(key.data());
}

Index MeshTopology::findFacetKey(const Index* key) const {
  // The facets of smallest vertex key[0] are in key order: binary search on the rest.
  const Index v = key[0];
  Index lo = firstFacet_[v], hi = firstFacet_[v + 1];
  while (lo < hi) {
    const Index mid = lo + (hi - lo) / 2;
    const Index* f = &facetVertices_[static_cast<std::size_t>(mid) * dim_];
    if (std::lexicographical_compare(f + 1, f + dim_, key + 1, key + dim_))
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo == firstFacet_[v + 1]) return -1;
  const Index* f = &facetVertices_[static_cast<std::size_t>(lo) * dim_];
  return std::equal(f + 1, f + dim_, key + 1) ? lo : -1;
}

}  // namespace friction
