// coincidentPoints and unlabelledBoundaryFacets (MeshCheck.hpp): a hidden cut is found at any
// scale, a sound mesh gives nothing, unlabelled boundary sides are exactly the unlabelled ones.
#include <catch2/catch.hpp>

#include "../fracture/TestMeshes.hpp"
#include "friction/mesh/MeshCheck.hpp"

using namespace friction;
using namespace friction::test;

namespace {

// The n x n grid cut along x = 1/2 from the bottom to the top: the nodes of that column get
// a copy (offset by `offset`) that the triangles and boundary edges right of it use.
Mesh cutGrid(int n, double scale, double offset) {
  Mesh m = gridMesh(n);
  for (Point& p : m.points) p *= scale;
  std::vector<Index> copy(m.points.size(), -1);
  for (int j = 0; j <= n; ++j) {
    const Index v = gridNode(n, n / 2, j);
    copy[v] = m.numPoints();
    m.points.push_back(m.points[v] + Point(offset, 0, 0));
  }
  const auto right = [&](const Point& c) { return c.x() > 0.5 * scale; };
  for (Index c = 0; c < m.numCells(); ++c) {
    const auto t = m.cell(c);
    if (right((m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3))
      for (Index& v : t)
        if (copy[v] >= 0) v = copy[v];
  }
  for (Index f = 0; f < m.numFacets(); ++f) {
    const auto e = m.facet(f);
    if (right(0.5 * (m.points[e[0]] + m.points[e[1]])))
      for (Index& v : e)
        if (copy[v] >= 0) v = copy[v];
  }
  return m;
}

}  // namespace

TEST_CASE("mesh checks: a sound mesh has no coincident points and no unlabelled boundary",
          "[mesh][check]") {
  for (double scale : {1e-9, 1.0, 1e6}) {
    INFO("scale " << scale);
    Mesh m = gridMesh(8);
    for (Point& p : m.points) p *= scale;
    CHECK(coincidentPoints(m).empty());
    CHECK(unlabelledBoundaryFacets(m).empty());
  }
}

TEST_CASE("mesh checks: a hidden cut is found as coincident points at any scale", "[mesh][check]") {
  const int n = 6;
  // Exactly coincident, and off by round-off of the coordinates (1e-16 relative).
  for (double scale : {1e-9, 1.0, 1e6})
    for (double relOffset : {0.0, 1e-15}) {
      INFO("scale " << scale << ", offset " << relOffset);
      const Mesh m = cutGrid(n, scale, relOffset * scale);
      const auto pairs = coincidentPoints(m);
      REQUIRE(pairs.size() == static_cast<std::size_t>(n + 1));  // one per node of the column
      for (const auto& [a, b] : pairs) {
        CHECK(a < b);
        CHECK(m.points[a].x() == Approx(0.5 * scale).epsilon(1e-12));
        CHECK((m.points[a] - m.points[b]).norm() <= 1e-14 * scale);
      }
      // The two lips, n sides each, with no label.
      const auto edges = unlabelledBoundaryFacets(m);
      CHECK(edges.size() == static_cast<std::size_t>(2 * 2 * n));
      for (Index v : edges) CHECK(m.points[v].x() == Approx(0.5 * scale).epsilon(1e-12));
    }
  // Vertices a tenth of a side apart are not coincident: only a cut's copies are.
  CHECK(coincidentPoints(cutGrid(n, 1.0, 0.1 / n)).empty());
}

TEST_CASE("mesh checks: boundary sides without a label are listed, oriented counter-clockwise",
          "[mesh][check]") {
  const int n = 4;
  Mesh m = gridMesh(n);
  // Remove the labels of the right side (label 2).
  std::vector<Index> edges;
  std::vector<int> labels;
  for (Index e = 0; e < m.numFacets(); ++e)
    if (m.facetLabel[e] != 2) {
      edges.insert(edges.end(), m.facet(e).begin(), m.facet(e).end());
      labels.push_back(m.facetLabel[e]);
    }
  m.facetVertices = edges;
  m.facetLabel = labels;
  const auto found = unlabelledBoundaryFacets(m);
  REQUIRE(found.size() == static_cast<std::size_t>(2 * n));
  for (std::size_t i = 0; i < found.size(); i += 2) {
    const Index e[2] = {found[i], found[i + 1]};
    CHECK(m.points[e[0]].x() == 1.0);
    CHECK(m.points[e[1]].x() == 1.0);
    CHECK(m.points[e[1]].y() > m.points[e[0]].y());  // the body on the left: upwards
  }
  // An interior labelled edge does not count as a boundary; an interior side is not listed.
  CHECK(coincidentPoints(m).empty());
}
