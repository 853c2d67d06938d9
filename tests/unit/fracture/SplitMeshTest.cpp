// Node splitting (docs/method.md): counts, single tips, sides, n_Γ orientation, area, and the
// refusals. Sign conventions under test: SignConventions.hpp.
#include <catch2/catch.hpp>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "TestMeshes.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"

using namespace friction;
using namespace friction::test;
using Catch::Matchers::Contains;

namespace {

Vector2 centroid(const Mesh& m, Index t) {
  return (m.points[m.cell(t)[0]].head<2>() + m.points[m.cell(t)[1]].head<2>() +
          m.points[m.cell(t)[2]].head<2>()) /
         3;
}

// Every triangle that touches a fracture node uses the copy of its own side: the plus copy
// when its centroid lies on the side opposite to n_Γ, the minus copy otherwise.
void checkSides(const SplitMesh& s) {
  int plusChecked = 0, minusChecked = 0;
  for (const FractureGeometry& g : s.fractures)
    for (Index i = 0; i < g.numNodes(); ++i)
      for (Index t = 0; t < s.mesh.numCells(); ++t) {
        const auto& tri = s.mesh.cell(t);
        for (Index v : tri) {
          if (s.origin[v] != g.node[i]) continue;
          const double side =
              (centroid(s.mesh, t) - s.mesh.points[v].head<2>()).dot(g.normal[i].head<2>());
          if (g.plus[i] == g.minus[i]) continue;  // a tip serves both sides
          if (side < -1e-12) {
            CHECK(v == g.plus[i]);
            ++plusChecked;
          }
          if (side > 1e-12) {
            CHECK(v == g.minus[i]);
            ++minusChecked;
          }
        }
      }
  // Both sides of some split node were looked at: a mesh with nothing split checks nothing.
  CHECK(plusChecked > 0);
  CHECK(minusChecked > 0);
}

std::string splitError(const Mesh& m, const std::vector<FractureSpec>& specs) {
  try {
    splitFractures(m, specs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a fracture across the whole width duplicates every node, ends included", "[split]") {
  const int n = 8;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, n / 2, 0, n, 5, "fracture");
  const SplitMesh s = splitFractures(m, {{"fracture", 5, {}}});

  REQUIRE(s.fractures.size() == 1);
  const FractureGeometry& g = s.fractures[0];
  CHECK(g.numNodes() == n + 1);
  CHECK(g.numTips() == 0);
  CHECK(g.numDuplicated() == n + 1);
  CHECK(g.kind.front() == FractureNodeKind::boundary);
  CHECK(g.kind.back() == FractureNodeKind::boundary);
  CHECK(s.mesh.numPoints() == m.numPoints() + n + 1);
  CHECK(s.mesh.numCells() == m.numCells());
  // The fracture cuts the square in two.
  CHECK(connectedComponents(m) == 1);
  CHECK(connectedComponents(s.mesh) == 2);
  // Walked left to right: t = (1, 0), n = (0, -1), Ω⁺ above (SignConventions.hpp).
  for (Index i = 0; i < g.numNodes(); ++i) {
    CHECK(s.mesh.points[g.node[i]].x() == Approx(double(i) / n));
    CHECK(g.arclength[i] == Approx(double(i) / n));
    CHECK(g.tangent[i].x() == Approx(1.0));
    CHECK(g.normal[i].y() == Approx(-1.0));
    CHECK(s.origin[g.plus[i]] == g.node[i]);
    CHECK(s.origin[g.minus[i]] == g.node[i]);
  }
  checkSides(s);
  CHECK(s.mesh.totalMeasure() == Approx(m.totalMeasure()).epsilon(1e-14));
  // Every triangle stays counter-clockwise.
  for (Index t = 0; t < s.mesh.numCells(); ++t) CHECK(s.mesh.signedMeasure(t) > 0);
  // Fracture edges leave the patch list; the boundary patches keep their edge counts and the
  // left/right edges next to the fracture end use the copy of their own side.
  CHECK(s.mesh.facetLabel.size() == m.facetLabel.size() - n);
  for (std::size_t e = 0; e < s.mesh.facetLabel.size(); ++e) {
    const Vector2 mid = (s.mesh.points[s.mesh.facet(e)[0]].head<2>() +
                         s.mesh.points[s.mesh.facet(e)[1]].head<2>()) /
                        2;
    for (Index v : s.mesh.facet(e)) {
      if (v == g.plus.front() || v == g.plus.back()) CHECK(mid.y() > 0.5);
      if (v == g.minus.front() || v == g.minus.back()) CHECK(mid.y() < 0.5);
    }
  }
}

TEST_CASE("an interior fracture keeps its two tips single", "[split]") {
  const int n = 8;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 4, 2, 6, 5, "crack");
  const SplitMesh s = splitFractures(m, {{"crack", 5, {}}});
  const FractureGeometry& g = s.fractures[0];
  CHECK(g.numNodes() == 5);
  CHECK(g.numTips() == 2);
  CHECK(g.kind.front() == FractureNodeKind::tip);
  CHECK(g.kind.back() == FractureNodeKind::tip);
  CHECK(g.plus.front() == g.minus.front());
  CHECK(g.plus.back() == g.minus.back());
  CHECK(g.numDuplicated() == 3);
  CHECK(s.mesh.numPoints() == m.numPoints() + 3);
  CHECK(connectedComponents(s.mesh) == 1);
  CHECK(g.length() == Approx(0.5));
  checkSides(s);
}

TEST_CASE("several disjoint fractures are split independently", "[split]") {
  const int n = 10;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 3, 0, n, 5, "lower");
  addHorizontalFracture(m, n, 7, 2, 8, 6, "upper");
  const SplitMesh s = splitFractures(m, {{"lower", 5, {}}, {"upper", 6, {}}});
  REQUIRE(s.fractures.size() == 2);
  CHECK(s.fractures[0].numDuplicated() == n + 1);
  CHECK(s.fractures[1].numTips() == 2);
  CHECK(s.fractures[1].numDuplicated() == 5);
  CHECK(s.mesh.numPoints() == m.numPoints() + n + 1 + 5);
  CHECK(connectedComponents(s.mesh) == 2);
  checkSides(s);
}

TEST_CASE("an inclined fracture has a consistent unit normal pointing from plus to minus",
          "[split]") {
  // Along the cell diagonals from (0.25,0.25) to (0.75,0.75): walked upwards,
  // t = (1,1)/√2, n = (1,-1)/√2.
  const int n = 8;
  Mesh m = gridMesh(n);
  for (int k = 2; k < 6; ++k) {
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, k, k), gridNode(n, k + 1, k + 1)});
    m.facetLabel.push_back(7);
  }
  m.labelNames[7] = "diag";
  const SplitMesh s = splitFractures(m, {{"diag", 7, {}}});
  const FractureGeometry& g = s.fractures[0];
  REQUIRE(g.numNodes() == 5);
  for (Index i = 0; i < g.numNodes(); ++i) {
    CHECK(g.normal[i].norm() == Approx(1.0));
    CHECK(g.normal[i].head<2>().dot(g.tangent[i]) == Approx(0.0).margin(1e-15));
    // t = (−n_y, n_x)
    CHECK(g.tangent[i].x() == Approx(-g.normal[i].y()));
    CHECK(g.tangent[i].y() == Approx(g.normal[i].x()));
    CHECK(g.normal[i].x() == Approx(std::sqrt(0.5)));
    CHECK(g.normal[i].y() == Approx(-std::sqrt(0.5)));
  }
  CHECK(g.length() == Approx(std::sqrt(0.5)));
  checkSides(s);
}

TEST_CASE("the normal is consistent along a bent fracture", "[split]") {
  // Horizontal from (0,0.5) to (0.5,0.5), then diagonal up to (0.75,0.75).
  const int n = 8;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 4, 0, 4, 5, "bent");
  m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 4, 4), gridNode(n, 5, 5)});
  m.facetLabel.push_back(5);
  m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 6, 6), gridNode(n, 5, 5)});
  m.facetLabel.push_back(5);
  const SplitMesh s = splitFractures(m, {{"bent", 5, {}}});
  const FractureGeometry& g = s.fractures[0];
  REQUIRE(g.numNodes() == 7);
  for (Index i = 0; i + 1 < g.numNodes(); ++i) CHECK(g.normal[i].dot(g.normal[i + 1]) > 0.5);
  CHECK(g.kind.front() == FractureNodeKind::boundary);
  CHECK(g.kind.back() == FractureNodeKind::tip);
  checkSides(s);
}

TEST_CASE("splitting refuses what it cannot split, saying why", "[split][errors]") {
  const int n = 8;
  SECTION("a fracture patch with no edges") {
    Mesh m = gridMesh(n);
    SourceLocation where{"system/meshDict", 17};
    CHECK_THAT(splitError(m, {{"ghost", 9, where}}),
               Contains("system/meshDict:17") && Contains("'ghost'") && Contains("no edges"));
  }
  SECTION("branching edges") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 0, n, 5, "fracture");
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 4, 4), gridNode(n, 4, 5)});
    m.facetLabel.push_back(5);
    CHECK_THAT(splitError(m, {{"fracture", 5, {}}}),
               Contains("branches at (0.5 0.5)") && Contains("give each branch its own label"));
  }
  SECTION("a triangle with all three vertices on the fracture") {
    Mesh m = gridMesh(n);
    // Edges (2,4)-(3,4) and (3,4)-(3,5) are two sides of the grid triangle
    // {(2,4), (3,4), (3,5)}: all of its vertices lie on the fracture.
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 2, 4), gridNode(n, 3, 4)});
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 3, 4), gridNode(n, 3, 5)});
    m.facetLabel.insert(m.facetLabel.end(), {5, 5});
    CHECK_THAT(splitError(m, {{"kink", 5, {}}}),
               Contains("all three vertices on fracture 'kink'") && Contains("refining"));
  }
  SECTION("a fracture on the outer boundary") {
    Mesh m = gridMesh(n);
    CHECK_THAT(splitError(m, {{"bottom", 1, {}}}), Contains("outer boundary") && Contains("grid8"));
  }
  SECTION("a closed fracture") {
    Mesh m = gridMesh(n);
    for (auto [a, b] : std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>>{
             {{2, 2}, {4, 2}}, {{4, 2}, {4, 4}}, {{4, 4}, {2, 4}}, {{2, 4}, {2, 2}}}) {
      // Straight runs of grid edges around a 2x2 block.
      const int di = (b.first > a.first) - (b.first < a.first);
      const int dj = (b.second > a.second) - (b.second < a.second);
      for (int i = a.first, j = a.second; i != b.first || j != b.second; i += di, j += dj) {
        m.facetVertices.insert(m.facetVertices.end(),
                               {gridNode(n, i, j), gridNode(n, i + di, j + dj)});
        m.facetLabel.push_back(5);
      }
    }
    CHECK_THAT(splitError(m, {{"loop", 5, {"d", 3}}}), Contains("d:3") && Contains("closed curve"));
  }
  SECTION("a mesh that is already split") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 0, n, 5, "fracture");
    SplitMesh s = splitFractures(m, {{"fracture", 5, {}}});
    // Put the fracture edges back as a patch of the split mesh, as a split mesh exported to a
    // mesh file would have them, and split again.
    for (Index i = 0; i + 1 < s.fractures[0].numNodes(); ++i) {
      s.mesh.facetVertices.insert(s.mesh.facetVertices.end(),
                                  {s.fractures[0].plus[i], s.fractures[0].plus[i + 1]});
      s.mesh.facetLabel.push_back(5);
    }
    CHECK_THAT(splitError(s.mesh, {{"fracture", 5, {}}}), Contains("already split"));
  }
}

namespace {

/// Vertical fracture along grid column i from row j0 to j1 (edges reversed, as above).
void addVerticalFracture(Mesh& m, int n, int i, int j0, int j1, int label,
                         const std::string& name) {
  for (int j = j0; j < j1; ++j) {
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, i, j + 1), gridNode(n, i, j)});
    m.facetLabel.push_back(label);
  }
  m.labelNames[label] = name;
}

/// The kind of fracture f at unsplit node v (which must be one of its nodes).
FractureNodeKind kindAt(const SplitMesh& s, std::size_t f, Index v) {
  const FractureGeometry& g = s.fractures.at(f);
  const auto it = std::find(g.node.begin(), g.node.end(), v);
  REQUIRE(it != g.node.end());
  return g.kind[it - g.node.begin()];
}

/// The distinct split-mesh copies of unsplit node v that the cells use.
std::set<Index> copiesOf(const SplitMesh& s, Index v) {
  std::set<Index> copies;
  for (Index t = 0; t < s.mesh.numCells(); ++t)
    for (Index w : s.mesh.cell(t))
      if (s.origin[w] == v) copies.insert(w);
  return copies;
}

/// Around junction node v: every cell uses one copy, and two cells that share an edge from v
/// use the same copy unless that edge is a fracture edge (a sector is connected, and the
/// fractures separate the sectors).
void checkSectors(const SplitMesh& s, const Mesh& unsplit, Index v) {
  std::map<std::pair<Index, Index>, std::vector<Index>> copyAcross;  // edge (v, w) -> copies
  for (Index t = 0; t < unsplit.numCells(); ++t) {
    const auto tri = unsplit.cell(t);
    const auto split = s.mesh.cell(t);
    for (int k = 0; k < 3; ++k)
      if (tri[k] == v)
        for (int l = 1; l < 3; ++l) copyAcross[{v, tri[(k + l) % 3]}].push_back(split[k]);
  }
  std::set<std::pair<Index, Index>> fractureEdges;
  for (std::size_t e = 0; e < unsplit.facetLabel.size(); ++e) {
    const Index a = unsplit.facetVertices[2 * e], b = unsplit.facetVertices[2 * e + 1];
    if (a == v) fractureEdges.insert({v, b});
    if (b == v) fractureEdges.insert({v, a});
  }
  int interiorEdges = 0, cutEdges = 0;
  for (const auto& [edge, copies] : copyAcross) {
    if (copies.size() != 2) continue;  // a boundary edge
    if (fractureEdges.count(edge)) {
      CHECK(copies[0] != copies[1]);
      ++cutEdges;
    } else {
      CHECK(copies[0] == copies[1]);
      ++interiorEdges;
    }
  }
  CHECK(cutEdges > 0);
  CHECK(interiorEdges > 0);
}

}  // namespace

TEST_CASE("junctions: one copy per sector, and the kind of each fracture there", "[split]") {
  const int n = 8;
  const Index centre = gridNode(n, 4, 4);
  SECTION("T: a fracture that ends on one passing through") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 2, 6, 5, "main");
    addVerticalFracture(m, n, 4, 4, 7, 6, "branch");
    const SplitMesh s = splitFractures(m, {{"main", 5, {}}, {"branch", 6, {}}});
    CHECK(copiesOf(s, centre).size() == 3);
    CHECK(kindAt(s, 0, centre) == FractureNodeKind::crossing);
    CHECK(kindAt(s, 1, centre) == FractureNodeKind::abutting);
    checkSectors(s, m, centre);
    CHECK(connectedComponents(s.mesh) == 1);  // the branch ends inside: its tip holds
  }
  SECTION("X: two fractures that cross") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 2, 6, 5, "a");
    addVerticalFracture(m, n, 4, 1, 7, 6, "b");
    const SplitMesh s = splitFractures(m, {{"a", 5, {}}, {"b", 6, {}}});
    CHECK(copiesOf(s, centre).size() == 4);
    CHECK(kindAt(s, 0, centre) == FractureNodeKind::crossing);
    CHECK(kindAt(s, 1, centre) == FractureNodeKind::crossing);
    checkSectors(s, m, centre);
  }
  SECTION("two fractures that end at one node inside the body are joined") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 2, 4, 5, "a");
    addHorizontalFracture(m, n, 4, 4, 6, 6, "b");
    const SplitMesh s = splitFractures(m, {{"a", 5, {}}, {"b", 6, {}}});
    CHECK(copiesOf(s, centre).size() == 2);
    CHECK(kindAt(s, 0, centre) == FractureNodeKind::joined);
    CHECK(kindAt(s, 1, centre) == FractureNodeKind::joined);
    checkSectors(s, m, centre);
  }
  SECTION("three fractures that end at one node") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 2, 4, 5, "a");
    addHorizontalFracture(m, n, 4, 4, 6, 6, "b");
    addVerticalFracture(m, n, 4, 4, 7, 7, "c");
    const SplitMesh s = splitFractures(m, {{"a", 5, {}}, {"b", 6, {}}, {"c", 7, {}}});
    CHECK(copiesOf(s, centre).size() == 3);
    for (std::size_t f = 0; f < 3; ++f) CHECK(kindAt(s, f, centre) == FractureNodeKind::abutting);
    checkSectors(s, m, centre);
  }
  SECTION("two fractures that end on the outer boundary at one node") {
    Mesh m = gridMesh(n);
    const Index corner = gridNode(n, 4, 0);  // on the bottom side
    addVerticalFracture(m, n, 4, 0, 3, 5, "a");
    // The second one runs along the grid's (0,0)-(1,1) diagonals from the same node.
    bool diagonal = false;
    for (Index t = 0; t < m.numCells(); ++t) {
      const auto c = m.cell(t);
      const bool hasA = std::find(c.begin(), c.end(), corner) != c.end();
      const bool hasB = std::find(c.begin(), c.end(), gridNode(n, 5, 1)) != c.end();
      diagonal = diagonal || (hasA && hasB);
    }
    REQUIRE(diagonal);
    m.facetVertices.insert(m.facetVertices.end(), {corner, gridNode(n, 5, 1)});
    m.facetVertices.insert(m.facetVertices.end(), {gridNode(n, 5, 1), gridNode(n, 6, 2)});
    m.facetLabel.insert(m.facetLabel.end(), {6, 6});
    m.labelNames[6] = "b";
    const SplitMesh s = splitFractures(m, {{"a", 5, {}}, {"b", 6, {}}});
    CHECK(copiesOf(s, corner).size() == 3);
    CHECK(kindAt(s, 0, corner) == FractureNodeKind::boundary);
    CHECK(kindAt(s, 1, corner) == FractureNodeKind::boundary);
  }
  SECTION("a fracture passing through a node where another passes through and a third ends") {
    Mesh m = gridMesh(n);
    addHorizontalFracture(m, n, 4, 2, 6, 5, "a");
    addVerticalFracture(m, n, 4, 1, 7, 6, "b");
    m.facetVertices.insert(m.facetVertices.end(), {centre, gridNode(n, 5, 5)});
    m.facetLabel.push_back(7);
    m.labelNames[7] = "c";
    bool diagonal = false;
    for (Index t = 0; t < m.numCells(); ++t) {
      const auto c = m.cell(t);
      diagonal = diagonal || (std::find(c.begin(), c.end(), centre) != c.end() &&
                              std::find(c.begin(), c.end(), gridNode(n, 5, 5)) != c.end());
    }
    REQUIRE(diagonal);
    const SplitMesh s = splitFractures(m, {{"a", 5, {}}, {"b", 6, {}}, {"c", 7, {}}});
    CHECK(copiesOf(s, centre).size() == 5);
    CHECK(kindAt(s, 0, centre) == FractureNodeKind::crossing);
    CHECK(kindAt(s, 1, centre) == FractureNodeKind::crossing);
    CHECK(kindAt(s, 2, centre) == FractureNodeKind::abutting);
    checkSectors(s, m, centre);
  }
}

TEST_CASE("the split mesh file reads back to the same split mesh", "[split][io]") {
  const int n = 6;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 3, 1, 5, 5, "crack");
  m.labelNames[5] = "crack";
  bool junctions = false;
  SECTION("one fracture") {}
  SECTION("fractures at junctions: a crossing, an abutting end, two joined ends") {
    junctions = true;
    addVerticalFracture(m, n, 3, 0, 5, 6, "cross");   // crosses "crack" at (3, 3)
    addVerticalFracture(m, n, 2, 3, 5, 7, "branch");  // abuts "crack" at (2, 3)
    addHorizontalFracture(m, n, 3, 5, 6, 8, "tail");  // joins "crack" at (5, 3), ends outside
  }
  std::vector<FractureSpec> specs;
  for (const auto& [label, name] : m.labelNames)
    if (label >= 5) specs.push_back({name, label, {}});
  const SplitMesh s = splitFractures(m, specs);
  if (junctions) {  // every junction kind goes through the file
    Index kinds[3] = {0, 0, 0};
    for (const FractureGeometry& g : s.fractures) {
      kinds[0] += g.numOfKind(FractureNodeKind::crossing);
      kinds[1] += g.numOfKind(FractureNodeKind::abutting);
      kinds[2] += g.numOfKind(FractureNodeKind::joined);
    }
    CHECK(kinds[0] == 3);  // "crack" at (2, 3) and (3, 3), "cross" at (3, 3)
    CHECK(kinds[1] == 1);
    CHECK(kinds[2] == 2);
  }
  const auto dir =
      std::filesystem::temp_directory_path() / ("friction-splitio-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "splitMesh").string();
  writeSplitMesh(s, path);
  const SplitMesh r = readSplitMesh(path);
  std::filesystem::remove_all(dir);

  CHECK(r.mesh.points == s.mesh.points);  // precision 17 round-trips exactly
  CHECK(r.mesh.cellVertices == s.mesh.cellVertices);
  CHECK(r.origin == s.origin);
  CHECK(r.mesh.facetLabel.size() == s.mesh.facetLabel.size());
  REQUIRE(r.fractures.size() == s.fractures.size());
  for (std::size_t f = 0; f < s.fractures.size(); ++f) {
    CHECK(r.fractures[f].node == s.fractures[f].node);
    CHECK(r.fractures[f].plus == s.fractures[f].plus);
    CHECK(r.fractures[f].minus == s.fractures[f].minus);
    CHECK(r.fractures[f].kind == s.fractures[f].kind);
    CHECK(r.fractures[f].normal == s.fractures[f].normal);
    CHECK(r.fractures[f].arclength == s.fractures[f].arclength);
  }
}
