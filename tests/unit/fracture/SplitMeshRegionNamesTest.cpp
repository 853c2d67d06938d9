// constant/splitMesh keeps the mesh's region names (for materials per region, README
// "Materials per region") when the cells lie in several regions, and only then: a one-region
// mesh's split mesh stays as it was before names were kept, and a split mesh without names
// (older, or of one region) still reads.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "../mesh/MeshTestHelpers.hpp"
#include "TestMeshes.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"

using namespace friction;
using namespace friction::test;
using Catch::Matchers::Contains;

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("the split mesh keeps region names when the cells lie in several regions",
          "[split][io][material]") {
  const int n = 6;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 3, 1, 5, 5, "crack");
  m.regionNames = {{1, "reservoir"}, {2, "caprock"}};
  TempDir dir;
  const std::string path = dir.file("splitMesh");

  SECTION("one region: no names written, none read") {
    std::fill(m.cellRegion.begin(), m.cellRegion.end(), 1);
    writeSplitMesh(splitFractures(m, {{"crack", 5, {}}}), path);
    CHECK_THAT(readText(path), !Contains("regionNames"));
    const SplitMesh r = readSplitMesh(path);
    CHECK(r.mesh.regionNames.empty());
    CHECK(r.mesh.cellRegion == m.cellRegion);
  }
  SECTION("two regions: the names round-trip") {
    int lower = 0;
    for (Index c = 0; c < m.numCells(); ++c) {
      double y = 0;
      for (Index v : m.cell(c)) y += m.points[v].y() / 3;
      m.cellRegion[c] = y < 0.5 ? 1 : 2;
      lower += m.cellRegion[c] == 1;
    }
    REQUIRE(lower > 0);
    REQUIRE(lower < m.numCells());
    writeSplitMesh(splitFractures(m, {{"crack", 5, {}}}), path);
    CHECK_THAT(readText(path), Contains("regionNames"));
    const SplitMesh r = readSplitMesh(path);
    CHECK(r.mesh.regionNames == m.regionNames);
    CHECK(r.mesh.cellRegion == m.cellRegion);

    // A name that is no dictionary word (gmsh allows "upper layer") is left out, and the
    // split mesh still reads: that region is region2 to the materials.
    m.regionNames[2] = "upper layer";
    writeSplitMesh(splitFractures(m, {{"crack", 5, {}}}), path);
    const SplitMesh spaced = readSplitMesh(path);
    CHECK(spaced.mesh.regionNames == std::map<int, std::string>{{1, "reservoir"}});
  }
}
