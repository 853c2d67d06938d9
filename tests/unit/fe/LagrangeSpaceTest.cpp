// LagrangeSpace (fe/LagrangeSpace.hpp): node numbering of P1 and P2, edge lookup, and the
// duplicated-node case of a split fracture (docs/method.md §4).
#include <catch2/catch.hpp>
#include <set>

#include "FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fe/LagrangeSpace.hpp"

using namespace friction;

TEST_CASE("fe LagrangeSpace numbers P1 and P2 nodes on a grid", "[fe][space]") {
  const int n = 3;
  const Mesh mesh = test::unitSquareMesh(n, 0.3);
  const LagrangeSpace p1(mesh, 1);
  REQUIRE(p1.numNodes() == (n + 1) * (n + 1));
  REQUIRE(p1.numDofs() == 2 * p1.numNodes());
  REQUIRE(p1.cellNodes(4).size == 3);
  REQUIRE(p1.midpointNode(0, 1) == -1);

  const LagrangeSpace p2(mesh, 2);
  // Edges of a structured grid: horizontal n(n+1), vertical n(n+1), diagonals n².
  const Index numEdges = 2 * n * (n + 1) + n * n;
  REQUIRE(p2.numEdges() == numEdges);
  REQUIRE(p2.numNodes() == (n + 1) * (n + 1) + numEdges);
  for (Index c = 0; c < p2.numCells(); ++c) {
    const NodeList nodes = p2.cellNodes(c);
    REQUIRE(nodes.size == 6);
    // Vertices keep the mesh numbers; midpoints in the order (0,1), (1,2), (2,0).
    const auto& t = mesh.cell(c);
    for (int i = 0; i < 3; ++i) REQUIRE(nodes[i] == t[i]);
    const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int e = 0; e < 3; ++e) {
      const Vector2 mid =
          0.5 * (mesh.points[t[pairs[e][0]]].head<2>() + mesh.points[t[pairs[e][1]]].head<2>());
      // Exact: the midpoint is computed once by the same formula.
      REQUIRE((p2.coordinate(nodes[3 + e]) - mid).norm() == 0.0);
      REQUIRE(p2.midpointNode(t[pairs[e][1]], t[pairs[e][0]]) == nodes[3 + e]);
    }
  }
  // A labelled edge gives (a, mid, b) in its own orientation.
  const auto e = mesh.facet(0);
  const NodeList en = p2.edgeNodes(e[0], e[1]);
  REQUIRE(en.size == 3);
  REQUIRE(en[0] == e[0]);
  REQUIRE(en[2] == e[1]);
  REQUIRE(en[1] == p2.midpointNode(e[0], e[1]));
  REQUIRE(p2.edgeNodes(e[1], e[0])[0] == e[1]);
  // Not an edge: opposite corners of a cell across the other diagonal.
  REQUIRE_FALSE(p2.isEdge(1, n + 1));
  REQUIRE(p2.midpointNode(1, n + 1) == -1);

  // Patch nodes: bottom has n + 1 vertices and n midpoints.
  REQUIRE(p1.patchNodes(1).size() == static_cast<std::size_t>(n + 1));
  REQUIRE(p2.patchNodes(1).size() == static_cast<std::size_t>(2 * n + 1));
  REQUIRE(p2.patchNodes(99).empty());
}

TEST_CASE("fe P2 space on a split mesh has distinct midpoints on the two sides", "[fe][space]") {
  const Mesh mesh = test::splitFourTriangleMesh();
  const LagrangeSpace V(mesh, 2);
  // Each half has 5 distinct edges; none is shared across the split.
  REQUIRE(V.numEdges() == 10);
  REQUIRE(V.numNodes() == 8 + 10);
  const Index midPlus = V.midpointNode(2, 3), midMinus = V.midpointNode(6, 7);
  REQUIRE(midPlus >= 8);
  REQUIRE(midMinus >= 8);
  REQUIRE(midPlus != midMinus);
  // Coincident coordinates, different numbers: keyed by node numbers, not by position.
  REQUIRE((V.coordinate(midPlus) - Vector2(0.5, 0.5)).norm() == 0.0);
  REQUIRE((V.coordinate(midMinus) - Vector2(0.5, 0.5)).norm() == 0.0);
  // (2, 7) mixes the two sides: not an edge.
  REQUIRE_FALSE(V.isEdge(2, 7));
  // The two halves share no node at all.
  std::set<Index> top, bottom;
  for (Index c = 0; c < V.numCells(); ++c)
    for (Index n : V.cellNodes(c)) (mesh.cellRegion[c] == 1 ? top : bottom).insert(n);
  for (Index n : top) REQUIRE(bottom.count(n) == 0);
  REQUIRE(top.size() + bottom.size() == static_cast<std::size_t>(V.numNodes()));
}

TEST_CASE("fe LagrangeSpace rejects a labelled edge that is no triangle side", "[fe][space]") {
  Mesh mesh = test::unitSquareMesh(2);
  mesh.facetVertices.insert(mesh.facetVertices.end(),
                            {0, 8});  // corner to corner: crosses the mesh, not a side
  mesh.facetLabel.push_back(7);
  try {
    LagrangeSpace V(mesh, 1);
    FAIL("no InputError");
  } catch (const InputError& e) {
    REQUIRE(e.location().file == mesh.source);
    REQUIRE_THAT(e.message(), Catch::Contains("label 7") && Catch::Contains("not a side"));
  }
}
