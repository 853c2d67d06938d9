// Tests of the mesh readers on well-formed files: one unit square written by hand in the
// three formats (FreeFEM, gmsh 2.2, gmsh 4.1 with non-contiguous node tags) reads to the same
// mesh; format detection by content; physical groups and names; sections and node layouts
// that gmsh may write. Malformed files are in MeshReaderErrorsTest.cpp, files written by the
// real tools in MeshReaderToolsTest.cpp.
#include <catch2/catch.hpp>

#include "MeshTestHelpers.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction;
using namespace friction::test;

namespace {

const std::string dataDir = std::string(FRICTION_TEST_DATA) + "/mesh/";

const std::string twoTriangles41Head =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Entities\n0 1 1 0\n"
    "1 0 0 0 1 0 0 2 7 8 0\n"
    "1 0 0 0 1 1 0 1 3 0\n"
    "$EndEntities\n";

}  // namespace

TEST_CASE("mesh: readMesh reads the same unit square from FreeFEM, gmsh 2.2 and gmsh 4.1 files",
          "[mesh][reader]") {
  const Mesh ff = readMesh(dataDir + "square.msh");
  const Mesh g22 = readMesh(dataDir + "square22.msh");
  const Mesh g41 = readMesh(dataDir + "square41.msh");

  CHECK(ff.format == "FreeFEM .msh");
  CHECK(g22.format == "gmsh .msh 2.2");
  CHECK(g41.format == "gmsh .msh 4.1");
  CHECK(g41.source == dataDir + "square41.msh");

  for (const Mesh* m : {&ff, &g22, &g41}) {
    INFO(m->format);
    CHECK(m->numPoints() == 15);
    CHECK(m->numCells() == 16);
    CHECK(m->numFacets() == 14);
    CHECK(m->facetLabel.size() == 14);
    CHECK(m->cellRegion == std::vector<int>(16, 1));
    // 16 triangles of area 1/16 each: exact in binary floating point.
    CHECK(m->totalMeasure() == 1.0);
    for (Index t = 0; t < m->numCells(); ++t) CHECK(m->signedMeasure(t) == 1.0 / 16);
    // The fracture: the last two edges, at y = 0.5 from x = 0.25 to 0.75.
    CHECK(m->facetLabel[12] == 5);
    CHECK(m->facetLabel[13] == 5);
    CHECK(m->points[m->facetVertex(12, 0)] == Point(0.25, 0.5, 0));
    CHECK(m->points[m->facetVertex(13, 1)] == Point(0.75, 0.5, 0));
  }
  // Same geometry, triangles (with orientation), edges and labels in the same order.
  CHECK(geometryOf(ff) == geometryOf(g22));
  CHECK(geometryOf(ff) == geometryOf(g41));
  // gmsh 2.2 file numbers its nodes like the FreeFEM file: identical connectivity.
  CHECK(ff.points == g22.points);
  CHECK(ff.cellVertices == g22.cellVertices);
  CHECK(ff.facetVertices == g22.facetVertices);
  CHECK(ff.facetLabel == g22.facetLabel);
  // gmsh 4.1 nodes are numbered in file order (tags 101, 12, 5, ...), not by tag.
  CHECK(g41.points[0] == Point(0, 0, 0));
  CHECK(g41.points[1] == Point(1, 0, 0));
  CHECK(g41.points[2] == Point(1, 1, 0));

  const std::map<int, std::string> labels{
      {1, "bottom"}, {2, "right"}, {3, "top"}, {4, "left"}, {5, "fracture"}};
  CHECK(g22.labelNames == labels);
  CHECK(g41.labelNames == labels);
  CHECK(g41.regionNames == std::map<int, std::string>{{1, "domain"}});
  CHECK(ff.labelNames.empty());

  // The format-specific readers give the same as readMesh.
  CHECK(geometryOf(readFreeFemMesh(dataDir + "square.msh")) == geometryOf(ff));
  CHECK(geometryOf(readGmshMesh(dataDir + "square41.msh")) == geometryOf(g41));
}

TEST_CASE("mesh: readMesh tells the format from the content, not the file name", "[mesh][reader]") {
  TempDir dir;
  std::ifstream in41(dataDir + "square41.msh"), inFF(dataDir + "square.msh");
  const std::string text41((std::istreambuf_iterator<char>(in41)), {});
  const std::string textFF((std::istreambuf_iterator<char>(inFF)), {});

  // gmsh content behind blank lines and in a file not named .msh.
  const Mesh g = readMesh(dir.write("gmshMesh.txt", "\n  \n" + text41));
  CHECK(g.format == "gmsh .msh 4.1");
  CHECK(g.numCells() == 16);
  // FreeFEM content in a file named like a gmsh file.
  const Mesh f = readMesh(dir.write("fromGmsh.msh", textFF));
  CHECK(f.format == "FreeFEM .msh");
  CHECK(f.numCells() == 16);
}

TEST_CASE("mesh: FreeFEM vertex labels are ignored and edges keep their file orientation",
          "[mesh][reader]") {
  TempDir dir;
  // Vertex labels as adaptmesh may leave them; the crack edge 2-4 written backwards (4 2).
  const Mesh m = readMesh(dir.write("labels.msh",
                                    "4 2 5\n"
                                    "0 0 123456\n1 0 -7\n1 1 0\n0 1 99\n"
                                    "1 2 3 4\n1 3 4 6\n"
                                    "1 2 1\n2 3 2\n3 4 3\n4 1 4\n3 1 5\n"));
  CHECK(m.cellRegion == std::vector<int>{4, 6});
  CHECK(m.facetLabel == std::vector<int>{1, 2, 3, 4, 5});
  CHECK(m.facet(m.numFacets() - 1)[0] == 2);
  CHECK(m.facet(m.numFacets() - 1)[1] == 0);
  CHECK(m.labelNames.empty());
  CHECK(m.totalMeasure() == 1.0);
}

TEST_CASE("mesh: a gmsh curve in several physical groups gives one edge per group in 2.2 and 4.1",
          "[mesh][reader]") {
  TempDir dir;
  // Bottom edge 1-2 in physical curves 7 and 8 ("bottom" and "all").
  const std::string names =
      "$PhysicalNames\n3\n1 7 \"bottom\"\n1 8 \"all boundary\"\n2 3 \"rock\"\n$EndPhysicalNames\n";
  const Mesh g22 = readMesh(
      dir.write("groups22.msh",
                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + names +
                    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                    "$Elements\n4\n1 1 2 7 1 1 2\n2 1 2 8 1 1 2\n3 2 2 3 1 1 2 3\n4 2 2 3 1 1 3 4\n"
                    "$EndElements\n"));
  const Mesh g41 = readMesh(dir.write(
      "groups41.msh", twoTriangles41Head + names +
                          "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                          "$EndNodes\n"
                          "$Elements\n2 3 1 3\n1 1 1 1\n1 1 2\n2 1 2 2\n2 1 2 3\n3 1 3 4\n"
                          "$EndElements\n"));
  for (const Mesh* m : {&g22, &g41}) {
    INFO(m->format);
    CHECK(m->facetVertices == std::vector<Index>{0, 1, 0, 1});
    CHECK(m->facetLabel == std::vector<int>{7, 8});
    CHECK(m->cellRegion == std::vector<int>{3, 3});
    CHECK(m->labelNames == std::map<int, std::string>{{7, "bottom"}, {8, "all boundary"}});
    CHECK(m->regionNames == std::map<int, std::string>{{3, "rock"}});
  }
}

TEST_CASE("mesh: gmsh elements without a physical group get label and region 0", "[mesh][reader]") {
  TempDir dir;
  // 2.2 with no tags at all, and 4.1 without $Entities (both as Mesh.SaveAll may write).
  const Mesh g22 = readMesh(dir.write("untagged22.msh",
                                      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                      "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                                      "$Elements\n2\n1 1 0 1 2\n2 2 0 1 2 3\n$EndElements\n"));
  const Mesh g41 = readMesh(dir.write("untagged41.msh",
                                      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                                      "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n"
                                      "$EndNodes\n"
                                      "$Elements\n2 2 1 2\n1 1 1 1\n1 1 2\n2 1 2 1\n2 1 2 3\n"
                                      "$EndElements\n"));
  for (const Mesh* m : {&g22, &g41}) {
    INFO(m->format);
    CHECK(m->facetLabel == std::vector<int>{0});
    CHECK(m->cellRegion == std::vector<int>{0});
    CHECK(m->totalMeasure() == 0.5);
  }
}

TEST_CASE(
    "mesh: gmsh readers skip unknown sections and take sparse tags, parametric nodes and CRLF",
    "[mesh][reader]") {
  TempDir dir;
  // Tags beyond 2^32 (sparse node map), parametric nodes on a curve (u after z), z at
  // round-off level, $Periodic and $NodeData sections, a point element, Windows line ends.
  std::string text =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$Entities\n0 1 1 0\n"
      "1 0 0 0 1 0 0 1 7 0\n"
      "1 0 0 0 1 1 0 1 3 0\n"
      "$EndEntities\n"
      "$Periodic\n0\n$EndPeriodic\n"
      "$Nodes\n2 4 5 50000000000\n"
      "1 1 1 2\n50000000000\n20000000000\n0 0 1e-17 0\n1 0 0 1\n"
      "2 1 0 2\n30000000000\n5\n1 1 -3e-17\n0 1 0\n"
      "$EndNodes\n"
      "$Elements\n2 3 1 3\n1 1 1 1\n1 50000000000 20000000000\n"
      "2 1 2 2\n2 50000000000 20000000000 30000000000\n3 50000000000 30000000000 5\n"
      "$EndElements\n"
      "$NodeData\n1\n\"temperature\"\n1\n0.0\n3\n0\n1\n4\n1 1\n2 2\n3 3\n4 4\n$EndNodeData\n";
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Mesh m = readMesh(dir.write("sparse.msh", crlf));
  REQUIRE(m.numPoints() == 4);
  CHECK(m.points[1] == Point(1, 0, 0));
  CHECK(m.points[3] == Point(0, 1, 0));
  CHECK(m.cellVertices == std::vector<Index>{0, 1, 2, 0, 2, 3});
  CHECK(m.facetVertices == std::vector<Index>{0, 1});
  CHECK(m.facetLabel == std::vector<int>{7});
  CHECK(m.totalMeasure() == 1.0);
}

TEST_CASE("mesh: signedMeasure is positive counter-clockwise and totalMeasure adds the areas",
          "[mesh][reader]") {
  Mesh m;
  m.points = {Point(0, 0, 0), Point(2, 0, 0), Point(0, 3, 0), Point(2, 3, 0)};
  m.cellVertices = {0, 1, 2, 1, 3, 2, 0, 2, 1};
  m.cellRegion = {0, 0, 0};
  CHECK(m.signedMeasure(0) == 3.0);
  CHECK(m.signedMeasure(1) == 3.0);
  CHECK(m.signedMeasure(2) == -3.0);
  CHECK(m.totalMeasure() == 9.0);
}
