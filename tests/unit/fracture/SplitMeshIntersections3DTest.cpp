// Fault surfaces that meet in 3D (README "Intersections (3D)"): every node on an intersection
// curve gets one copy per sector of the tetrahedra around it; each fracture's kind there
// (crossing, abutting, joined); the curves with their kind, length and nodes; the round trip
// through constant/splitMesh. Boxes of Kuhn tetrahedra (TestBoxMeshes.hpp), whose grid planes
// are unions of tetrahedron faces, so that two planes meet conformingly along a grid line.
#include <catch2/catch.hpp>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "TestBoxMeshes.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"

using namespace friction;
using namespace friction::test;

namespace {

constexpr int n = 4;

// Copies per unsplit node of the split mesh.
std::map<Index, int> copiesPerNode(const SplitMesh& s) {
  std::map<Index, int> copies;
  for (Index o : s.origin) ++copies[o];
  return copies;
}

// On the grid line x = 1/2, z = 1/2 (the intersection line of the planes x = 1/2 and z = 1/2).
bool onLine(const Point& p) {
  return std::abs(p.x() - 0.5) < 1e-12 && std::abs(p.z() - 0.5) < 1e-12;
}

// The tetrahedra around the nodes of the line x = z = 1/2 use one copy per region of
// `regionOf` (a label of where the tetrahedron's centroid lies), and different regions
// different copies. Returns how many (node, region) pairs were seen.
template <class Region>
int checkSectors(const SplitMesh& s, const Region& regionOf) {
  std::map<Index, std::map<int, std::set<Index>>> copyOf;  // node -> region -> copies used
  for (Index t = 0; t < s.mesh.numCells(); ++t) {
    Point c = Point::Zero();
    for (Index v : s.mesh.cell(t)) c += s.mesh.points[v] / 4;
    for (Index v : s.mesh.cell(t))
      if (onLine(s.mesh.points[v])) copyOf[s.origin[v]][regionOf(c)].insert(v);
  }
  int pairs = 0;
  for (const auto& [node, regions] : copyOf) {
    std::set<Index> all;
    for (const auto& [region, copies] : regions) {
      CHECK(copies.size() == 1);
      all.insert(copies.begin(), copies.end());
      ++pairs;
    }
    CHECK(all.size() == regions.size());
  }
  return pairs;
}

Index kindAtLine(const SplitMesh& s, std::size_t f, FractureNodeKind kind) {
  const FractureGeometry& g = s.fractures[f];
  Index count = 0;
  for (Index i = 0; i < g.numNodes(); ++i)
    count += g.kind[i] == kind && onLine(s.mesh.points[g.node[i]]);
  return count;
}

}  // namespace

TEST_CASE("3D intersections: two faults crossing along a line get four copies per node",
          "[split][3d][intersection]") {
  // a: the plane z = 1/2 across the box; b: the plane x = 1/2 for z in [1/4, 3/4], across
  // in y. They cross along x = z = 1/2, y in [0, 1] (5 nodes, both ends on the outer boundary).
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, n, 0, n, 7, "a");
  addPlaneFault(m, n, 0, 2, 0, n, 1, 3, 8, "b");
  const SplitMesh s = splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}});
  REQUIRE(s.fractures.size() == 2);
  const auto copies = copiesPerNode(s);
  int onCurve = 0;
  for (const auto& [v, c] : copies)
    if (onLine(m.points[v])) {
      CHECK(c == 4);
      ++onCurve;
    }
  CHECK(onCurve == 5);
  // a: 20 nodes off the line, two copies each; b: off the line, its tip lines z = 1/4, 3/4.
  CHECK(s.mesh.numPoints() == m.numPoints() + 20 + 3 * 5);
  // Four quadrants around the line, each one copy.
  CHECK(checkSectors(s, [](const Point& c) { return (c.x() > 0.5) + 2 * (c.z() > 0.5); }) == 5 * 4);
  // Both pass through: crossing inside, boundary at the two ends on y = 0 and y = 1.
  for (std::size_t f : {0, 1}) {
    CHECK(kindAtLine(s, f, FractureNodeKind::crossing) == 3);
    CHECK(kindAtLine(s, f, FractureNodeKind::boundary) == 2);
  }
  CHECK(s.fractures[1].numTips() == 10);

  const auto curves = intersectionCurves(s, m);
  REQUIRE(curves.size() == 1);
  CHECK(curves[0].kind() == "crossing");
  CHECK(curves[0].passing == std::vector<std::size_t>{0, 1});
  CHECK(curves[0].nodes.size() == 5);
  CHECK(curves[0].ends.size() == 2);
  CHECK(curves[0].length == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("3D intersections: a fault abutting another gets three copies per node, held ends",
          "[split][3d][intersection]") {
  // a: z = 1/2 across the box; b: x = 1/2 above it (z in [1/2, 1]), ending on a.
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, n, 0, n, 7, "a");
  addPlaneFault(m, n, 0, 2, 0, n, 2, n, 8, "b");
  const SplitMesh s = splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}});
  const auto copies = copiesPerNode(s);
  int onCurve = 0;
  for (const auto& [v, c] : copies)
    if (onLine(m.points[v])) {
      CHECK(c == 3);
      ++onCurve;
    }
  CHECK(onCurve == 5);
  CHECK(s.mesh.numPoints() == m.numPoints() + 20 + 10 + 2 * 5);
  // Below a one sector; above it, one on either side of b.
  CHECK(checkSectors(s, [](const Point& c) { return c.z() < 0.5 ? 0 : 1 + (c.x() > 0.5); }) ==
        5 * 3);
  CHECK(kindAtLine(s, 0, FractureNodeKind::crossing) == 3);
  CHECK(kindAtLine(s, 0, FractureNodeKind::boundary) == 2);
  CHECK(kindAtLine(s, 1, FractureNodeKind::abutting) == 5);
  // b's copies at its held nodes are the sectors on either side of it (above a).
  const FractureGeometry& b = s.fractures[1];
  for (Index i = 0; i < b.numNodes(); ++i)
    if (b.kind[i] == FractureNodeKind::abutting) CHECK(b.plus[i] != b.minus[i]);

  const auto curves = intersectionCurves(s, m);
  REQUIRE(curves.size() == 1);
  CHECK(curves[0].kind() == "abutting");
  CHECK(curves[0].passing == std::vector<std::size_t>{0});
  CHECK(curves[0].ending == std::vector<std::size_t>{1});
  CHECK(curves[0].length == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("3D intersections: two faults ending together act as one bent fault",
          "[split][3d][intersection]") {
  // a: z = 1/2 for x in [0, 1/2]; b: x = 1/2 for z in [1/2, 1]: an L across the box in y.
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, 2, 0, n, 7, "a");
  addPlaneFault(m, n, 0, 2, 0, n, 2, n, 8, "b");
  const SplitMesh s = splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}});
  for (const auto& [v, c] : copiesPerNode(s))
    if (onLine(m.points[v])) CHECK(c == 2);
  CHECK(kindAtLine(s, 0, FractureNodeKind::joined) == 5);
  CHECK(kindAtLine(s, 1, FractureNodeKind::joined) == 5);
  const auto curves = intersectionCurves(s, m);
  REQUIRE(curves.size() == 1);
  CHECK(curves[0].kind() == "joined");
  CHECK(curves[0].ending == std::vector<std::size_t>{0, 1});
}

TEST_CASE("3D intersections: the split mesh survives constant/splitMesh unchanged",
          "[split][3d][intersection][io]") {
  Mesh m = boxMesh(n);
  addPlaneFault(m, n, 2, 2, 0, n, 0, n, 7, "a");
  addPlaneFault(m, n, 0, 2, 0, n, 1, 3, 8, "b");
  const SplitMesh s = splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}});
  const std::string path = std::filesystem::temp_directory_path().string() + "/intersections3d-" +
                           std::to_string(::getpid());
  writeSplitMesh(s, path);
  const SplitMesh r = readSplitMesh(path);
  REQUIRE(r.fractures.size() == 2);
  for (std::size_t f = 0; f < 2; ++f) {
    CHECK(r.fractures[f].node == s.fractures[f].node);
    CHECK(r.fractures[f].plus == s.fractures[f].plus);
    CHECK(r.fractures[f].minus == s.fractures[f].minus);
    CHECK(r.fractures[f].kind == s.fractures[f].kind);
    CHECK(r.fractures[f].triangles == s.fractures[f].triangles);
  }
  CHECK(r.mesh.cellVertices == s.mesh.cellVertices);
  std::filesystem::remove(path);
}
