// constant/splitMesh: the checks readSplitMesh makes so that no hand-edited or damaged file
// reaches the solver (which would index out of its arrays), the record of what the split was
// made from, and the refusal of a stale split mesh (checkSplitMeshCurrent).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "../mesh/MeshTestHelpers.hpp"
#include "TestMeshes.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/fracture/SplitMeshIO.hpp"

using namespace friction;
using namespace friction::test;
using Catch::Matchers::Contains;

namespace {

SplitMesh splitGrid() {
  const int n = 6;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, 3, 1, 5, 5, "crack");
  return splitFractures(m, {{"crack", 5, {}}});
}

// Write `s`, read it back; the InputError's text, or "no error".
std::string readError(const TempDir& dir, const SplitMesh& s) {
  const std::string path = dir.file("splitMesh");
  writeSplitMesh(s, path);
  try {
    readSplitMesh(path);
  } catch (const InputError& e) {
    CHECK(e.location().file == path);
    CHECK(e.location().line > 0);
    return e.what();
  }
  return "no error";
}

std::string currentError(const std::string& caseDir, const SplitMesh& s) {
  try {
    checkSplitMeshCurrent(caseDir, s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("fileHash is FNV-1a 64-bit of the bytes", "[split][io]") {
  TempDir dir;
  // Reference values of the FNV test suite (Fowler, Noll, Vo).
  CHECK(fileHash(dir.write("empty", "")) == "fnv1a64:cbf29ce484222325");
  CHECK(fileHash(dir.write("a", "a")) == "fnv1a64:af63dc4c8601ec8c");
  CHECK(fileHash(dir.write("foobar", "foobar")) == "fnv1a64:85944171f73967e8");
  CHECK_THROWS_AS(fileHash(dir.file("missing")), InputError);
}

TEST_CASE("readSplitMesh accepts what splitFractures makes and refuses what would break the solver",
          "[split][io][errors]") {
  TempDir dir;
  const SplitMesh good = splitGrid();
  REQUIRE(readError(dir, good) == "no error");

  SECTION("a point no triangle uses") {
    SplitMesh s = good;
    s.mesh.points.push_back(Point(0.3, 0.3, 0));
    s.origin.push_back(0);  // a valid origin: only its use is missing
    CHECK_THAT(readError(dir, s), Contains("used by no triangle") && Contains("-overwrite"));
  }
  SECTION("a copy listed among the unsplit points") {
    SplitMesh s = good;
    std::swap(s.origin[0], s.origin[1]);
    CHECK_THAT(readError(dir, s), Contains("key 'origin'"));
  }
  SECTION("a triangle listed twice") {
    SplitMesh s = good;
    s.mesh.addCell({s.mesh.cellVertex(0, 0), s.mesh.cellVertex(0, 1), s.mesh.cellVertex(0, 2)}, 0);
    CHECK_THAT(readError(dir, s), Contains("have the same vertices"));
  }
  SECTION("a patch edge that is no triangle side") {
    SplitMesh s = good;
    s.mesh.facetVertices[0] = 0;
    s.mesh.facetVertices[1] = s.mesh.numPoints() - 1;
    CHECK_THAT(readError(dir, s), Contains("is not a side of any triangle"));
  }
  SECTION("a patch edge from a node to itself") {
    SplitMesh s = good;
    s.mesh.facetVertices[0] = 0;
    s.mesh.facetVertices[1] = 0;
    CHECK_THAT(readError(dir, s), Contains("is not a side of any triangle"));
  }
  SECTION("a frame that is not one (the solver would scale tractions by it)") {
    SplitMesh s = good;
    s.fractures[0].tangent[2] *= 1e300;
    CHECK_THAT(readError(dir, s), Contains("must be unit vectors"));
    s = good;
    s.fractures[0].normal[2] = -s.fractures[0].normal[2];
    CHECK_THAT(readError(dir, s), Contains("normal = (t_y, -t_x)"));
  }
  SECTION("an arclength that does not grow") {
    SplitMesh s = good;
    s.fractures[0].arclength[2] = s.fractures[0].arclength[1];
    CHECK_THAT(readError(dir, s), Contains("'arclength' must start at 0 and grow"));
  }
  SECTION("coordinates whose triangle area overflows") {
    SplitMesh s = good;
    s.mesh.points[0] = Point(-1e300, -1e300, 0);
    CHECK_THAT(readError(dir, s), Contains("not a finite number"));
  }
  SECTION("fracture nodes out of order") {
    SplitMesh s = good;
    FractureGeometry& g = s.fractures[0];
    std::swap(g.node[1], g.node[3]);
    std::swap(g.plus[1], g.plus[3]);
    std::swap(g.minus[1], g.minus[3]);
    CHECK_THAT(readError(dir, s), Contains("must be joined by triangle sides"));
  }
}

TEST_CASE("the split mesh records what it was made from, and a stale one is refused",
          "[split][io]") {
  TempDir dir;
  const std::string caseDir = dir.file("case");
  std::filesystem::create_directories(caseDir + "/system");
  std::filesystem::create_directories(caseDir + "/constant/mesh");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(caseDir + "/" + name) << text;
  };
  write("system/meshDict", "mesh \"constant/mesh/m.msh\";\n");
  write("constant/mesh/m.msh", "mesh bytes\n");

  SplitMesh s = splitGrid();
  s.madeFrom = {"constant/mesh/m.msh", fileHash(caseDir + "/constant/mesh/m.msh"),
                fileHash(caseDir + "/system/meshDict")};
  writeSplitMesh(s, caseDir + "/constant/splitMesh");
  const SplitMesh r = readSplitMesh(caseDir + "/constant/splitMesh");
  CHECK(r.madeFrom.mesh == s.madeFrom.mesh);
  CHECK(r.madeFrom.meshHash == s.madeFrom.meshHash);
  CHECK(r.madeFrom.meshDictHash == s.madeFrom.meshDictHash);
  CHECK(currentError(caseDir, r) == "no error");

  const std::string advice = "splitFractureNodes -case " + caseDir + " -overwrite";
  SECTION("the mesh changed") {
    write("constant/mesh/m.msh", "other bytes\n");
    const std::string e = currentError(caseDir, r);
    CHECK_THAT(e, Contains(caseDir + "/constant/splitMesh: is stale: the mesh file"));
    CHECK_THAT(e, Contains(advice));
  }
  SECTION("the mesh is gone") {
    std::filesystem::remove(caseDir + "/constant/mesh/m.msh");
    CHECK_THAT(currentError(caseDir, r), Contains("no longer exists") && Contains(advice));
  }
  SECTION("meshDict changed") {
    write("system/meshDict", "mesh \"constant/mesh/m.msh\"; // edited\n");
    CHECK_THAT(currentError(caseDir, r), Contains("meshDict changed") && Contains(advice));
  }
  SECTION("no record (a split mesh of an older splitFractureNodes)") {
    SplitMesh old = r;
    old.madeFrom = {};
    writeSplitMesh(old, caseDir + "/constant/splitMesh");
    const SplitMesh read = readSplitMesh(caseDir + "/constant/splitMesh");
    CHECK(read.madeFrom.empty());
    CHECK_THAT(currentError(caseDir, read),
               Contains("does not record which mesh") && Contains(advice));
  }
}
