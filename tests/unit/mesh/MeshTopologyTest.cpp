// MeshTopology (MeshTopology.hpp): what the definitions require. Every facet is a set of d
// cell vertices, listed once, ascending, in key order; a facet's cells are the cells that have
// it, with the local number k whose opposite vertex is the cell's vertex k; boundary facets
// are those of one cell; a facet of three cells is reported and the splitter refuses it.
#include <algorithm>
#include <catch2/catch.hpp>
#include <set>

#include "../fracture/TestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/MeshTopology.hpp"

using namespace friction;
using namespace friction::test;

namespace {

// Every facet against the cells, by brute force: facet f of cell c at local k has the cell's
// vertices but vertex k, that vertex is not on it, and it lists (c, k) among its cells.
void checkAgainstCells(const Mesh& m, const MeshTopology& topo) {
  REQUIRE(topo.numCells() == m.numCells());
  REQUIRE(topo.numCells() > 0);
  std::size_t sides = 0;
  for (Index c = 0; c < topo.numCells(); ++c)
    for (int k = 0; k < 3; ++k) {
      const Index f = topo.cellFacet(c, k);
      REQUIRE(f >= 0);
      std::set<Index> expected;
      for (int j = 0; j < 3; ++j)
        if (j != k) expected.insert(m.cell(c)[j]);
      const std::set<Index> got{topo.facetVertex(f, 0), topo.facetVertex(f, 1)};
      CHECK(got == expected);
      CHECK(topo.facetVertex(f, 0) < topo.facetVertex(f, 1));
      CHECK(topo.oppositeVertex(c, k) == m.cell(c)[k]);
      CHECK_FALSE(got.count(topo.oppositeVertex(c, k)));
      bool listed = false;
      for (int i = 0; i < topo.numCellsOf(f); ++i)
        listed |= topo.cellOf(f, i).cell == c && topo.cellOf(f, i).local == k;
      CHECK(listed);
      ++sides;
    }
  // Each (cell, local facet) appears once among the facets' cells.
  std::size_t listedTotal = 0;
  for (Index f = 0; f < topo.numFacets(); ++f) {
    listedTotal += static_cast<std::size_t>(topo.numCellsOf(f));
    for (int i = 1; i < topo.numCellsOf(f); ++i)
      CHECK(topo.cellOf(f, i - 1).cell < topo.cellOf(f, i).cell);
    if (f > 0)  // key order, each key once
      CHECK(std::make_pair(topo.facetVertex(f - 1, 0), topo.facetVertex(f - 1, 1)) <
            std::make_pair(topo.facetVertex(f, 0), topo.facetVertex(f, 1)));
  }
  CHECK(listedTotal == sides);
}

}  // namespace

TEST_CASE("MeshTopology of two triangles: one interior side, four boundary sides", "[mesh]") {
  Mesh m;
  m.source = "square";
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.cellVertices = {0, 1, 2, 0, 2, 3};
  const MeshTopology topo(m);
  REQUIRE(topo.dimension() == 2);
  REQUIRE(topo.numVertices() == 4);
  REQUIRE(topo.numFacets() == 5);
  checkAgainstCells(m, topo);

  // Facets in key order: {0,1} {0,2} {0,3} {1,2} {2,3}; only the diagonal {0,2} is interior.
  const Index diagonal = topo.findFacet({2, 0});
  REQUIRE(diagonal == 1);
  CHECK(topo.findFacet({0, 2}) == diagonal);
  CHECK(topo.numCellsOf(diagonal) == 2);
  CHECK_FALSE(topo.isBoundary(diagonal));
  CHECK(topo.cellOf(diagonal, 0).cell == 0);
  CHECK(topo.cellOf(diagonal, 1).cell == 1);
  // Opposite vertices: 1 in the first triangle, 3 in the second.
  CHECK(topo.oppositeVertex(0, topo.cellOf(diagonal, 0).local) == 1);
  CHECK(topo.oppositeVertex(1, topo.cellOf(diagonal, 1).local) == 3);
  for (const auto& [a, b] : {std::pair<Index, Index>{0, 1}, {1, 2}, {2, 3}, {3, 0}}) {
    const Index f = topo.findFacet({a, b});
    REQUIRE(f >= 0);
    CHECK(topo.isBoundary(f));
    CHECK(topo.numCellsOf(f) == 1);
  }
  CHECK(topo.overSharedFacets().empty());

  // Not a side, a vertex out of range, the wrong number of vertices: no facet.
  CHECK(topo.findFacet({1, 3}) == -1);
  CHECK(topo.findFacet({0, 4}) == -1);
  CHECK(topo.findFacet({-1, 0}) == -1);
  CHECK(topo.findFacet({0, 1, 2}) == -1);
}

TEST_CASE("MeshTopology of a grid: boundary flags are the sides on the square's edges", "[mesh]") {
  const int n = 5;
  const Mesh m = gridMesh(n);
  const MeshTopology topo(m);
  checkAgainstCells(m, topo);
  // 3 · cells = 2 · interior + boundary, and the boundary of the square has 4n sides.
  Index boundary = 0, interior = 0;
  for (Index f = 0; f < topo.numFacets(); ++f) {
    const Vector2 a = m.points[topo.facetVertex(f, 0)].head<2>(),
                  b = m.points[topo.facetVertex(f, 1)].head<2>();
    const bool onSquare = (a.x() == b.x() && (a.x() == 0 || a.x() == 1)) ||
                          (a.y() == b.y() && (a.y() == 0 || a.y() == 1));
    CHECK(topo.isBoundary(f) == onSquare);
    if (topo.isBoundary(f)) {
      ++boundary;
    } else {
      REQUIRE(topo.numCellsOf(f) == 2);
      ++interior;
      // The two cells lie on opposite sides of an interior side: their opposite vertices do.
      const Vector2 d = b - a;
      double side[2];
      for (int i = 0; i < 2; ++i) {
        const auto [cell, local] = topo.cellOf(f, i);
        const Vector2 c = m.points[topo.oppositeVertex(cell, local)].head<2>() - a;
        side[i] = d.x() * c.y() - d.y() * c.x();
      }
      CHECK(side[0] * side[1] < 0);
    }
  }
  CHECK(boundary == 4 * n);
  CHECK(3 * topo.numCells() == 2 * interior + boundary);
  // Every labelled edge of the grid is a boundary side.
  for (Index e = 0; e < m.numFacets(); ++e)
    CHECK(topo.isBoundary(topo.findFacet({m.facetVertex(e, 0), m.facetVertex(e, 1)})));
}

TEST_CASE("MeshTopology reports a side of three triangles, and the splitter refuses it", "[mesh]") {
  Mesh m;
  m.source = "fan.msh";
  m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 2, 0}};
  // The side (0 0)-(1 0) bounds the first two and the third, which overlaps the first.
  m.cellVertices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  m.cellRegion = {0, 0, 0};
  const MeshTopology topo(m);
  checkAgainstCells(m, topo);
  const Index f = topo.findFacet({0, 1});
  REQUIRE(f >= 0);
  CHECK(topo.overSharedFacets() == std::vector<Index>{f});
  REQUIRE(topo.numCellsOf(f) == 3);
  for (int i = 0; i < 3; ++i) CHECK(topo.cellOf(f, i).cell == i);
  CHECK_FALSE(topo.isBoundary(f));

  try {
    splitFractures(m, {});
    FAIL("a side of three triangles was accepted");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("fan.msh") &&
                             Catch::Contains("the edge (0 0)-(1 0) is a side of 3 triangles "
                                             "(at most 2 expected)"));
  }
}

TEST_CASE("MeshTopology of an empty mesh has no cells and no facets", "[mesh]") {
  Mesh m;
  const MeshTopology none(m);
  CHECK(none.numCells() == 0);
  CHECK(none.numFacets() == 0);
  CHECK(none.findFacet({0, 1}) == -1);
  CHECK(none.overSharedFacets().empty());

  m.points = {{0, 0, 0}, {1, 0, 0}};  // points, but no triangle
  const MeshTopology pointsOnly(m);
  CHECK(pointsOnly.numVertices() == 2);
  CHECK(pointsOnly.numFacets() == 0);
  CHECK(pointsOnly.findFacet({0, 1}) == -1);
}

TEST_CASE("MeshTopology refuses a triangle vertex that is not a point, naming the mesh", "[mesh]") {
  Mesh m;
  m.source = "bad.msh";
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.cellVertices = {0, 1, 3};
  CHECK_THROWS_WITH(MeshTopology(m), Catch::Contains("bad.msh") && Catch::Contains("vertex 3"));
}

TEST_CASE("Mesh::topology is built once and rebuilt when the triangles change", "[mesh]") {
  Mesh m = gridMesh(2);
  const auto first = m.topology();
  CHECK(m.topology() == first);  // shared, not rebuilt
  CHECK(first->describes(m));

  // Flip the diagonal of the first grid cell: other sides, so a new topology.
  const Index a = gridNode(2, 0, 0), b = gridNode(2, 1, 0), c = gridNode(2, 1, 1),
              d = gridNode(2, 0, 1);
  std::copy_n(std::array<Index, 3>{a, b, d}.begin(), 3, m.cell(0).begin());
  std::copy_n(std::array<Index, 3>{b, c, d}.begin(), 3, m.cell(1).begin());
  CHECK_FALSE(first->describes(m));
  const auto second = m.topology();
  CHECK(second != first);
  CHECK(second->describes(m));
  CHECK(second->findFacet({b, d}) >= 0);
  CHECK(second->findFacet({a, c}) == -1);
  CHECK(first->findFacet({a, c}) >= 0);  // the old one, still held, is unchanged
}
