// Node splitting on tetrahedral meshes (docs/method.md §7): fault surfaces of triangles in a
// box of Kuhn tetrahedra (TestBoxMeshes.hpp). Counts of copies, which tetrahedra use which
// copy, n_Γ and its sign (SignConventions.hpp), node kinds, area and tip-line length, the
// refusals, the round trip through constant/splitMesh and the topology of the cut.
#include <catch2/catch.hpp>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "TestBoxMeshes.hpp"
#include "friction/case/FrictionCase.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"
#include "friction/mesh/MeshTopology.hpp"

using namespace friction;
using namespace friction::test;
using Catch::Matchers::Contains;

namespace {

Point centroid(const Mesh& m, Index t) {
  Point c = Point::Zero();
  for (Index v : m.cell(t)) c += m.points[v];
  return c / 4;
}

std::string splitError(const Mesh& m, const std::vector<FractureSpec>& specs) {
  try {
    splitFractures(m, specs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Every tetrahedron with a vertex on a split node uses the copy of its side: the plus copy
// where its centroid lies against n_Γ (Ω⁺), the minus copy where it lies along n_Γ. Returns
// how many (tetrahedron, vertex) pairs were checked on each side.
std::pair<int, int> checkSides(const SplitMesh& s) {
  int plusChecked = 0, minusChecked = 0;
  for (const FractureGeometry& g : s.fractures)
    for (Index i = 0; i < g.numNodes(); ++i) {
      if (g.plus[i] == g.minus[i]) continue;  // a tip serves both sides
      for (Index t = 0; t < s.mesh.numCells(); ++t)
        for (Index v : s.mesh.cell(t)) {
          if (s.origin[v] != g.node[i]) continue;
          const double side = (centroid(s.mesh, t) - s.mesh.points[v]).dot(g.normal[i]);
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
  return {plusChecked, minusChecked};
}

// The fault's triangles after the split: a triangle with a split vertex is a boundary facet of
// the split mesh on both sides (a lip through the plus copies, one through the minus copies);
// one whose three vertices are all single (tips) stays a facet of two tetrahedra.
void checkLips(const SplitMesh& s, int expectedLips) {
  const MeshTopology topo(s.mesh);
  int lips = 0;
  for (const FractureGeometry& g : s.fractures) {
    std::map<Index, Index> minusOf;
    for (Index i = 0; i < g.numNodes(); ++i) minusOf[g.plus[i]] = g.minus[i];
    for (const auto& t : g.triangles) {
      const Index p = topo.findFacet({t[0], t[1], t[2]});
      const Index m = topo.findFacet({minusOf[t[0]], minusOf[t[1]], minusOf[t[2]]});
      REQUIRE(p >= 0);
      REQUIRE(m >= 0);
      const bool split = minusOf[t[0]] != t[0] || minusOf[t[1]] != t[1] || minusOf[t[2]] != t[2];
      if (split) {
        CHECK(p != m);
        CHECK(topo.isBoundary(p));
        CHECK(topo.isBoundary(m));
        ++lips;
      } else {
        CHECK(p == m);
        CHECK(topo.numCellsOf(p) == 2);
      }
    }
  }
  CHECK(lips == expectedLips);
}

Index countKind(const FractureGeometry& g, FractureNodeKind k) { return g.numOfKind(k); }

}  // namespace

TEST_CASE("3D: a fault across the box in x splits its nodes on x = 0 and x = 1, not its tip lines",
          "[split][3d]") {
  // Plane z = 1/2, x in [0, 1], y in [1/4, 3/4]: it reaches the faces x = 0 and x = 1; its
  // edges y = 1/4 and y = 3/4 are tip lines inside the body.
  const int n = 4;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, n, 1, n - 1, 7, "fault");
  const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  REQUIRE(s.fractures.size() == 1);
  const FractureGeometry& g = s.fractures[0];

  // Nodes (n + 1) × (n − 1) = 15: on the tip lines (j = 1, 3, including their ends on x = 0
  // and x = 1, where the tip line meets ∂Ω) single, the rest duplicated.
  CHECK(g.numNodes() == 15);
  CHECK(countKind(g, FractureNodeKind::tip) == 10);
  CHECK(countKind(g, FractureNodeKind::interior) == 3);
  CHECK(countKind(g, FractureNodeKind::boundary) == 2);
  CHECK(g.numDuplicated() == 5);
  CHECK(s.mesh.numPoints() == m.numPoints() + 5);
  CHECK(s.mesh.numCells() == m.numCells());
  for (Index i = 0; i < g.numNodes(); ++i) {
    const Point& x = m.points[g.node[i]];
    const bool onTipLine = std::abs(x.y() - 0.25) < 1e-12 || std::abs(x.y() - 0.75) < 1e-12;
    const bool onDomainBoundary = x.x() < 1e-12 || x.x() > 1 - 1e-12;
    CHECK(g.plus[i] == g.node[i]);
    CHECK((g.kind[i] == FractureNodeKind::tip) == onTipLine);
    if (!onTipLine) CHECK((g.kind[i] == FractureNodeKind::boundary) == onDomainBoundary);
    // A horizontal fault: n_Γ = (0, 0, −1), Ω⁺ above (SignConventions.hpp), exactly.
    CHECK(g.normal[i] == Point(0, 0, -1));
    if (i > 0) CHECK(g.node[i] > g.node[i - 1]);  // ascending node order
  }
  // Triangles oriented along n_Γ.
  REQUIRE(g.triangles.size() == 2 * n * (n - 2));
  for (const auto& t : g.triangles)
    CHECK((m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).z() < 0);
  // Area 1 × 1/2; tip lines 2 × 1 (the edges on x = 0 and x = 1 lie on ∂Ω). Sums of a few
  // exact products of 1/4: round-off only.
  CHECK(g.area(m.points) == Approx(0.5).epsilon(1e-14));
  CHECK(g.tipLineLength(m) == Approx(2.0).epsilon(1e-14));
  CHECK(g.arclength.empty());
  CHECK(g.tangent.empty());

  // Ω⁺ above uses the plus copies only, Ω⁻ below the minus copies.
  const auto [plusChecked, minusChecked] = checkSides(s);
  CHECK(plusChecked > 0);
  CHECK(minusChecked > 0);
  for (Index t = 0; t < s.mesh.numCells(); ++t)
    if (centroid(s.mesh, t).z() > 0.5)
      for (Index v : s.mesh.cell(t)) CHECK(v < m.numPoints());
  // Every triangle has a split vertex here.
  checkLips(s, 2 * n * (n - 2));
  // Boundary patches keep their triangles, renumbered to the copies.
  CHECK(s.mesh.numFacets() == m.numFacets() - 2 * n * (n - 2));
}

TEST_CASE("3D: a fault inside the box keeps its whole tip line single", "[split][3d]") {
  // Plane z = 1/2, x and y in [1/6, 5/6]: nodes 5 × 5, the 9 inner ones split.
  const int n = 6;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 3, 1, n - 1, 1, n - 1, 7, "fault");
  const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  const FractureGeometry& g = s.fractures.at(0);
  CHECK(g.numNodes() == 25);
  CHECK(countKind(g, FractureNodeKind::interior) == 9);
  CHECK(countKind(g, FractureNodeKind::boundary) == 0);
  CHECK(countKind(g, FractureNodeKind::tip) == 16);
  CHECK(g.numDuplicated() == 9);
  CHECK(s.mesh.numPoints() == m.numPoints() + 9);
  CHECK(g.area(m.points) == Approx(4.0 / 9).epsilon(1e-14));
  CHECK(g.tipLineLength(m) == Approx(8.0 / 3).epsilon(1e-14));
  for (const Point& nv : g.normal) CHECK(nv == Point(0, 0, -1));
  const auto [plusChecked, minusChecked] = checkSides(s);
  CHECK(plusChecked > 0);
  CHECK(minusChecked > 0);
  // Two corner triangles (in the squares at (4/6, 1/6) and (1/6, 4/6)) have three tip
  // vertices: they stay glued.
  checkLips(s, 2 * 16 - 2);
  CHECK(g.numGluedTriangles() == 2);
}

TEST_CASE("3D: a fault one cell wide has no node to split, and the summary counts it glued",
          "[split][3d]") {
  // One square of the plane z = 1/2 inside the box: its 4 nodes are all on the tip line.
  const int n = 4;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 1, 2, 1, 2, 7, "fault");
  const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  const FractureGeometry& g = s.fractures.at(0);
  REQUIRE(g.triangles.size() == 2);
  CHECK(g.numTips() == 4);
  CHECK(g.numDuplicated() == 0);
  CHECK(g.numGluedTriangles() == 2);
  CHECK(s.mesh.numPoints() == m.numPoints());
}

TEST_CASE("3D: n_Γ's sign follows the largest component of the mean normal", "[split][3d]") {
  const int n = 4;
  for (int axis = 0; axis < 3; ++axis) {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, axis, 2, 1, 3, 1, 3, 7, "fault");
    const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
    Point expected = Point::Zero();
    expected[axis] = -1;
    for (const Point& nv : s.fractures.at(0).normal) CHECK(nv == expected);
    const auto [plusChecked, minusChecked] = checkSides(s);
    CHECK(plusChecked > 0);
    CHECK(minusChecked > 0);
  }
}

TEST_CASE("3D: an L-shaped fault gets area-weighted normals at its fold", "[split][3d]") {
  // z = 1/2 for x in [1/4, 1/2] and x = 1/2 for z in [1/4, 1/2]: one surface, folded down,
  // the two parts of equal area. The mean normal has |n_x| = |n_z|: the tie goes to x (the
  // earlier axis), n_x < 0, so the vertical part has n_Γ = −x and the horizontal one −z.
  // (Folded up instead, a Kuhn tetrahedron at the fold would have all four vertices on it.)
  const int n = 4;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 1, 2, 1, 3, 7, "fault");
  addPlaneFault(m, n, 0, 2, 1, 3, 1, 2, 7, "fault");
  const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  const FractureGeometry& g = s.fractures.at(0);
  int folded = 0;
  for (Index i = 0; i < g.numNodes(); ++i) {
    // Expected: the normalised sum of the adjacent triangles' normals times their areas (all
    // 1/32 here), each −z on the horizontal part and −x on the vertical one.
    Point sum = Point::Zero();
    for (const auto& t : g.triangles) {
      if (std::find(t.begin(), t.end(), g.node[i]) == t.end()) continue;
      const bool horizontal = std::abs(m.points[t[0]].z() - 0.5) < 1e-12 &&
                              std::abs(m.points[t[1]].z() - 0.5) < 1e-12 &&
                              std::abs(m.points[t[2]].z() - 0.5) < 1e-12;
      sum += horizontal ? Point(0, 0, -1) : Point(-1, 0, 0);
    }
    CHECK((g.normal[i] - sum.normalized()).norm() < 1e-15);
    const Point& x = m.points[g.node[i]];
    if (std::abs(x.x() - 0.5) < 1e-12 && std::abs(x.z() - 0.5) < 1e-12) ++folded;
    // The middle of the fold has three triangles on either part.
    if ((x - Point(0.5, 0.5, 0.5)).norm() < 1e-12)
      CHECK((g.normal[i] - Point(-1, 0, -1).normalized()).norm() < 1e-15);
  }
  CHECK(folded == 3);
  // Ω⁻ is the quadrant x < 1/2, z < 1/2 (n_Γ points into it from both parts); near the fold
  // the node normal is diagonal, so sides are told by position, not by n_Γ.
  int plusChecked = 0, minusChecked = 0;
  for (Index t = 0; t < s.mesh.numCells(); ++t) {
    const Point c = centroid(s.mesh, t);
    const bool minusSide = c.x() < 0.5 && c.z() < 0.5;
    for (Index v : s.mesh.cell(t))
      for (Index i = 0; i < g.numNodes(); ++i)
        if (s.origin[v] == g.node[i] && g.plus[i] != g.minus[i]) {
          CHECK(v == (minusSide ? g.minus[i] : g.plus[i]));
          ++(minusSide ? minusChecked : plusChecked);
        }
  }
  CHECK(plusChecked > 0);
  CHECK(minusChecked > 0);
}

TEST_CASE("3D: refusals name the mesh, the fracture and a point", "[split][3d]") {
  const int n = 4;
  SECTION("no triangles") {
    Mesh m = boxMesh(n);
    CHECK_THAT(splitError(m, {{"fault", 9, {}}}),
               Contains("fracture 'fault' (label 9) has no triangles in box4"));
  }
  SECTION("a triangle on the outer boundary") {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 0, 1, 2, 1, 2, 7, "fault");
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}),
               Contains("lies on the outer boundary of the mesh") && Contains("box4"));
  }
  SECTION("a triangle that is not a face of any tetrahedron") {
    Mesh m = boxMesh(n);
    // (0,0,2)-(1,0,2)-(0,1,2) in grid units: across the Kuhn diagonal of its square.
    m.addFacet({boxNode(n, 0, 0, 2), boxNode(n, 1, 0, 2), boxNode(n, 0, 1, 2)}, 7);
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}),
               Contains("is not a face of any tetrahedron") && Contains("(0 0 0.5)"));
  }
  SECTION("already split") {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 2, 1, 3, 1, 3, 7, "fault");
    SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
    for (const auto& t : s.fractures[0].triangles) s.mesh.addFacet({t[0], t[1], t[2]}, 7);
    CHECK_THAT(splitError(s.mesh, {{"fault", 7, {}}}),
               Contains("is already split in this mesh") &&
                   Contains("give splitFractureNodes the unsplit mesh"));
  }
  SECTION("a tetrahedron with all four vertices on the fault") {
    Mesh m = boxMesh(n);
    // Two faces of one inner tetrahedron: a manifold, open, orientable surface of two
    // triangles that holds all four vertices.
    Index t = 0;
    while (m.cellVertex(t, 0) != boxNode(n, 1, 1, 1)) ++t;
    const auto c = m.cell(t);
    m.addFacet({c[0], c[1], c[2]}, 7);
    m.addFacet({c[0], c[1], c[3]}, 7);
    m.labelNames[7] = "fault";
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}),
               Contains("has all four vertices on fracture 'fault' (label 7)"));
  }
  SECTION("a non-manifold surface") {
    Mesh m = boxMesh(n);
    // z = 1/2 for x in [1/4, 3/4] and x = 1/2 for z in [1/2, 3/4]: a T, three triangles on
    // each edge of the line x = z = 1/2.
    addPlaneFault(m, n, 2, 2, 1, 3, 1, 3, 7, "fault");
    addPlaneFault(m, n, 0, 2, 1, 3, 2, 3, 7, "fault");
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}), Contains("is not a manifold surface") &&
                                                      Contains("(0.5 0.25 0.5)") &&
                                                      Contains("3 of its triangles"));
  }
  SECTION("a non-orientable surface") {
    // A Möbius band of six tetrahedron faces (found by a search over the Kuhn faces in grid
    // units): manifold, open, one piece, but no consistent orientation.
    Mesh m = boxMesh(n);
    const int band[6][3][3] = {
        {{1, 1, 1}, {2, 2, 1}, {2, 2, 2}}, {{1, 1, 1}, {2, 1, 1}, {2, 2, 1}},
        {{1, 1, 1}, {2, 1, 1}, {2, 1, 2}}, {{2, 1, 1}, {2, 1, 2}, {3, 2, 2}},
        {{2, 1, 1}, {2, 2, 2}, {3, 2, 2}}, {{2, 2, 1}, {2, 2, 2}, {3, 2, 2}}};
    for (const auto& t : band) {
      auto v = [&](int k) { return boxNode(n, t[k][0], t[k][1], t[k][2]); };
      m.addFacet({v(0), v(1), v(2)}, 7);
    }
    m.labelNames[7] = "fault";
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}),
               Contains("fracture 'fault' (label 7) is not an orientable surface"));
  }
  SECTION("a closed surface") {
    Mesh m = boxMesh(n);
    for (int axis = 0; axis < 3; ++axis)
      for (int level : {1, 3}) addPlaneFault(m, n, axis, level, 1, 3, 1, 3, 7, "fault");
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}), Contains("is a closed surface"));
  }
  SECTION("a surface in two pieces") {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 1, 1, 2, 1, 2, 7, "fault");
    addPlaneFault(m, n, 2, 3, 2, 3, 2, 3, 7, "fault");
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}), Contains("is made of several pieces") &&
                                                      Contains("one contains (0.25 0.25 0.25)") &&
                                                      Contains("another (0.5 0.5 0.75)"));
  }
  SECTION("two pieces that touch at a node only") {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 2, 1, 2, 1, 2, 7, "fault");
    addPlaneFault(m, n, 2, 2, 2, 3, 2, 3, 7, "fault");
    CHECK_THAT(splitError(m, {{"fault", 7, {}}}), Contains("is made of several pieces"));
  }
}

TEST_CASE("3D: a split mesh survives constant/splitMesh unchanged", "[split][3d][io]") {
  const int n = 4;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, n, 1, n - 1, 7, "fault");
  SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  s.madeFrom = {"constant/mesh/box.mesh", "fnv1a64:0123456789abcdef", "fnv1a64:fedcba9876543210"};
  const std::string dir =
      std::filesystem::temp_directory_path().string() + "/split3d-" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/splitMesh";
  writeSplitMesh(s, path);
  const SplitMesh r = readSplitMesh(path);
  CHECK(r.mesh.dim == 3);
  CHECK(r.mesh.points == s.mesh.points);
  CHECK(r.mesh.cellVertices == s.mesh.cellVertices);
  CHECK(r.mesh.cellRegion == s.mesh.cellRegion);
  CHECK(r.origin == s.origin);
  // Patches come back grouped by label, in each label's order.
  std::multiset<std::pair<int, std::array<Index, 3>>> a, b;
  for (Index e = 0; e < s.mesh.numFacets(); ++e)
    a.insert({s.mesh.facetLabel[e],
              {s.mesh.facetVertex(e, 0), s.mesh.facetVertex(e, 1), s.mesh.facetVertex(e, 2)}});
  for (Index e = 0; e < r.mesh.numFacets(); ++e)
    b.insert({r.mesh.facetLabel[e],
              {r.mesh.facetVertex(e, 0), r.mesh.facetVertex(e, 1), r.mesh.facetVertex(e, 2)}});
  CHECK(a == b);
  REQUIRE(r.fractures.size() == 1);
  const FractureGeometry &x = s.fractures[0], &y = r.fractures[0];
  CHECK(y.name == x.name);
  CHECK(y.label == x.label);
  CHECK(y.node == x.node);
  CHECK(y.plus == x.plus);
  CHECK(y.minus == x.minus);
  CHECK(y.kind == x.kind);
  CHECK(y.normal == x.normal);
  CHECK(y.triangles == x.triangles);
  CHECK(r.madeFrom.meshHash == s.madeFrom.meshHash);
  // Written again, the file is the same byte for byte.
  writeSplitMesh(r, path + "2");
  auto text = [](const std::string& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  CHECK(text(path) == text(path + "2"));
  CHECK_THAT(text(path), Contains("dimension   3;") && Contains("tetrahedra") &&
                             !Contains("arclength") && !Contains("edges"));

  SECTION("malformed files are refused") {
    std::string t = text(path);
    auto readError = [&](const std::string& content) {
      std::ofstream(path + "3") << content;
      try {
        readSplitMesh(path + "3");
      } catch (const InputError& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    std::string bad = t;
    bad.replace(bad.find("dimension   3;"), 14, "dimension 4;");
    CHECK_THAT(readError(bad), Contains("key 'dimension': 4 (expected 2 or 3)"));
    // A tetrahedron turned inside out.
    bad = t;
    const auto at = bad.find("tetrahedra");
    const auto open = bad.find('(', bad.find('(', at) + 1);  // the list's first tuple
    const auto close = bad.find(')', open);
    std::istringstream tet(bad.substr(open + 1, close - open - 1));
    long v[4];
    tet >> v[0] >> v[1] >> v[2] >> v[3];
    bad.replace(open, close - open + 1,
                "(" + std::to_string(v[1]) + " " + std::to_string(v[0]) + " " +
                    std::to_string(v[2]) + " " + std::to_string(v[3]) + ")");
    CHECK_THAT(readError(bad), Contains("tetrahedron 0 is inverted or degenerate"));
    // A fracture triangle whose minus copies are not a face.
    bad = t;
    const auto ft = bad.find("triangles", bad.find("fractures"));
    const auto fo = bad.find('(', bad.find('(', ft) + 1);
    const auto fc = bad.find(')', fo);
    std::istringstream tri(bad.substr(fo + 1, fc - fo - 1));
    long w[3];
    tri >> w[0] >> w[1] >> w[2];
    bad.replace(fo, fc - fo + 1,
                "(" + std::to_string(w[0]) + " " + std::to_string(w[1]) + " " +
                    std::to_string(x.node.back()) + ")");
    CHECK_THAT(readError(bad), Contains("key 'triangles'"));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("3D: frictionSolver's case reads a 3D split mesh and refuses 2D-only keys",
          "[split][3d]") {
  // A case folder whose constant/splitMesh is current (its record matches the files) and 3D:
  // the case reads on, and the material's 2D key planeStress is refused with the reason.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("split3d-case-" + std::to_string(::getpid()));
  fs::create_directories(dir / "system");
  fs::create_directories(dir / "constant" / "mesh");
  fs::copy_file(fs::path(FRICTION_SOURCE_DIR) / "cases/paperBenchmark/system/controlDict",
                dir / "system" / "controlDict", fs::copy_options::overwrite_existing);
  std::ofstream(dir / "system" / "meshDict") << "// any text: only its hash is compared\n";
  std::ofstream(dir / "constant" / "mesh" / "box.mesh") << "// idem\n";
  const int n = 2;
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 1, 0, 2, 0, 1, 7, "fault");
  SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  s.madeFrom = {"constant/mesh/box.mesh", fileHash((dir / "constant/mesh/box.mesh").string()),
                fileHash((dir / "system/meshDict").string())};
  writeSplitMesh(s, (dir / "constant" / "splitMesh").string());
  std::ofstream(dir / "constant" / "mechanicalProperties") << "E 1e9;\nnu 0.25;\nplaneStress no;\n";
  std::string message = "no error";
  try {
    FrictionCase c(dir.string());
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK_THAT(message, Contains("constant/mechanicalProperties") && Contains("planeStress") &&
                          Contains("has no meaning in 3D"));
  fs::remove_all(dir);
}

TEST_CASE("3D: an inclined fault (the plane x = y) inside the box", "[split][3d]") {
  // Kuhn tetrahedra are the regions x_a ≥ x_b ≥ x_c of each cube, so the plane x = y is a
  // union of their faces: per cube on it, the rectangle (i,i,k)-(i+1,i+1,k+1) in two
  // triangles. Here i, k in {1, 2} of n = 4: 3 × 3 nodes, the middle one split.
  const int n = 4;
  Mesh m = boxMesh(n);
  for (int i = 1; i < 3; ++i)
    for (int k = 1; k < 3; ++k) {
      const Index a = boxNode(n, i, i, k), b = boxNode(n, i + 1, i + 1, k),
                  c = boxNode(n, i + 1, i + 1, k + 1), d = boxNode(n, i, i, k + 1);
      m.addFacet({a, b, c}, 7);
      m.addFacet({a, d, c}, 7);
    }
  m.labelNames[7] = "fault";
  const SplitMesh s = splitFractures(m, {{"fault", 7, {}}});
  const FractureGeometry& g = s.fractures.at(0);
  CHECK(g.numNodes() == 9);
  CHECK(g.numDuplicated() == 1);
  CHECK(g.numTips() == 8);
  // The mean normal ∝ ±(1, −1, 0): |n_x| = |n_y|, the tie goes to x, n_x < 0. Round-off of a
  // normalised sum of a few equal vectors: 1e-15.
  for (const Point& nv : g.normal) CHECK((nv - Point(-1, 1, 0).normalized()).norm() < 1e-15);
  // Rectangles √2/4 × 1/4, four of them; the tip line is the whole rim, 2 (2 √2/4 + 2/4).
  CHECK(g.area(m.points) == Approx(std::sqrt(2.0) / 4).epsilon(1e-14));
  CHECK(g.tipLineLength(m) == Approx(std::sqrt(2.0) + 1).epsilon(1e-14));
  // Ω⁺ (x > y) uses the plus copy, Ω⁻ (y > x) the minus copy.
  const auto [plusChecked, minusChecked] = checkSides(s);
  CHECK(plusChecked > 0);
  CHECK(minusChecked > 0);
  // Two of the eight triangles ((3/4, 3/4, 1/4)-(3/4, 3/4, 1/2) side and its mirror at the top
  // left) have three tip vertices and stay glued.
  checkLips(s, 6);
}
