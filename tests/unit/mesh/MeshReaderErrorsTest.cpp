// Tests that malformed mesh files are rejected with an InputError naming file:line and what
// was expected: one test per error path, with a section per format where the path exists in
// several. Each bad file is a small well-formed mesh (below) with one line changed, so the
// line numbers in the checks can be read off the base files' line comments.
#include <catch2/catch.hpp>

#include <sstream>

#include "MeshTestHelpers.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction;
using namespace friction::test;

namespace {

// Unit square, two triangles, four boundary edges. Line numbers on the right.
const std::string freeFem =
    "4 2 4\n"    // 1
    "0 0 1\n"    // 2
    "1 0 1\n"    // 3
    "1 1 2\n"    // 4
    "0 1 3\n"    // 5
    "1 2 3 1\n"  // 6
    "1 3 4 1\n"  // 7
    "1 2 1\n"    // 8
    "2 3 2\n"    // 9
    "3 4 3\n"    // 10
    "4 1 4\n";   // 11

const std::string gmsh22 =
    "$MeshFormat\n"      // 1
    "2.2 0 8\n"          // 2
    "$EndMeshFormat\n"   // 3
    "$Nodes\n"           // 4
    "4\n"                // 5
    "1 0 0 0\n"          // 6
    "2 1 0 0\n"          // 7
    "3 1 1 0\n"          // 8
    "4 0 1 0\n"          // 9
    "$EndNodes\n"        // 10
    "$Elements\n"        // 11
    "3\n"                // 12
    "1 1 2 7 1 1 2\n"    // 13
    "2 2 2 1 1 1 2 3\n"  // 14
    "3 2 2 1 1 1 3 4\n"  // 15
    "$EndElements\n";    // 16

const std::string gmsh41 =
    "$MeshFormat\n"          // 1
    "4.1 0 8\n"              // 2
    "$EndMeshFormat\n"       // 3
    "$Entities\n"            // 4
    "0 1 1 0\n"              // 5
    "1 0 0 0 1 0 0 1 7 0\n"  // 6
    "1 0 0 0 1 1 0 1 1 0\n"  // 7
    "$EndEntities\n"         // 8
    "$Nodes\n"               // 9
    "1 4 10 40\n"            // 10
    "2 1 0 4\n"              // 11
    "10\n"                   // 12
    "20\n"                   // 13
    "30\n"                   // 14
    "40\n"                   // 15
    "0 0 0\n"                // 16
    "1 0 0\n"                // 17
    "1 1 0\n"                // 18
    "0 1 0\n"                // 19
    "$EndNodes\n"            // 20
    "$Elements\n"            // 21
    "2 3 1 3\n"              // 22
    "1 1 1 1\n"              // 23
    "1 10 20\n"              // 24
    "2 1 2 2\n"              // 25
    "2 10 20 30\n"           // 26
    "3 10 30 40\n"           // 27
    "$EndElements\n";        // 28

// One tetrahedron with a labelled face (Medit, 3D).
const std::string medit =
    "MeshVersionFormatted 2\n"  // 1
    "Dimension 3\n"             // 2
    "Vertices\n"                // 3
    "4\n"                       // 4
    "0 0 0 1\n"                 // 5
    "1 0 0 1\n"                 // 6
    "0 1 0 1\n"                 // 7
    "0 0 1 1\n"                 // 8
    "Tetrahedra\n"              // 9
    "1\n"                       // 10
    "1 2 3 4 1\n"               // 11
    "Triangles\n"               // 12
    "1\n"                       // 13
    "1 2 3 5\n"                 // 14
    "End\n";                    // 15

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return text;
}

/// `text` with line `n` (1-based) replaced by `replacement` (which may hold several lines).
std::string replaceLine(const std::string& text, int n, const std::string& replacement) {
  auto lines = splitLines(text);
  REQUIRE(n >= 1);
  REQUIRE(n <= static_cast<int>(lines.size()));
  lines[n - 1] = replacement;
  return joinLines(lines);
}

/// `text` without line `n`.
std::string deleteLine(const std::string& text, int n) {
  auto lines = splitLines(text);
  REQUIRE(n >= 1);
  REQUIRE(n <= static_cast<int>(lines.size()));
  lines.erase(lines.begin() + (n - 1));
  return joinLines(lines);
}

/// The first `n` lines of `text`.
std::string firstLines(const std::string& text, int n) {
  auto lines = splitLines(text);
  lines.resize(n);
  return joinLines(lines);
}

}  // namespace

TEST_CASE("mesh: the unmodified base meshes of the error tests read without error",
          "[mesh][errors]") {
  // Otherwise the error tests below could pass for the wrong reason.
  TempDir dir;
  for (const std::string* text : {&freeFem, &gmsh22, &gmsh41}) {
    const Mesh m = readMesh(dir.write("base.msh", *text));
    INFO(m.format);
    CHECK(m.numPoints() == 4);
    CHECK(m.numCells() == 2);
    CHECK(m.totalMeasure() == 1.0);
  }
}

TEST_CASE("mesh: a mesh file that cannot be opened is an InputError naming the file",
          "[mesh][errors]") {
  TempDir dir;
  const std::string path = dir.file("missing.msh");
  try {
    readMesh(path);
    FAIL("no InputError for a missing file");
  } catch (const InputError& e) {
    CHECK(e.location().file == path);
    CHECK_THAT(e.what(), Catch::StartsWith(path + ": cannot open: no such file (expected the "
                                                  "mesh file"));
  }
}

TEST_CASE("mesh: an empty mesh file is rejected", "[mesh][errors]") {
  TempDir dir;
  requireReadError(dir, "empty.msh", "", 0, {"the file is empty", "nv nt nbe", "$MeshFormat"});
  requireReadError(dir, "blank.msh", "\n  \n\n", 3, {"the file is empty"});
}

TEST_CASE("mesh: a truncated mesh file is rejected, saying how many items were announced and found",
          "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM vertices") {
    requireReadError(dir, "trunc.msh", firstLines(freeFem, 3), 3,
                     {"unexpected end of file", "announces 4 vertices, found 2", "x y label"});
  }
  SECTION("FreeFEM triangles") {
    requireReadError(
        dir, "trunc.msh", firstLines(freeFem, 6), 6,
        {"unexpected end of file", "announces 2 triangles, found 1", "v1 v2 v3 region"});
  }
  SECTION("FreeFEM edges") {
    requireReadError(dir, "trunc.msh", firstLines(freeFem, 9), 9,
                     {"announces 4 edges, found 2", "v1 v2 label"});
  }
  SECTION("gmsh 2.2 nodes") {
    requireReadError(
        dir, "trunc22.msh", firstLines(gmsh22, 7), 7,
        {"unexpected end of file in $Nodes", "announces 4 nodes, found 2", "tag x y z"});
  }
  SECTION("gmsh 4.1 elements cut short before $EndElements") {
    requireReadError(dir, "trunc41.msh", deleteLine(gmsh41, 27), 27,
                     {"ends $Elements (opened at line 21) early", "announces 3 elements, found 2"});
  }
  SECTION("gmsh 4.1 nodes: the file ends within the coordinates") {
    requireReadError(
        dir, "trunc41.msh", firstLines(gmsh41, 17), 17,
        {"unexpected end of file in $Nodes", "announces 4 node coordinates, found 2", "x y z"});
  }
}

TEST_CASE("mesh: counts that disagree with the file are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM: more lines than the header announces") {
    requireReadError(
        dir, "more.msh", freeFem + "1 3 5\n", 12,
        {"goes on after the 4 edges", "expected the end of the file", "nv nt nbe = 4 2 4"});
  }
  SECTION("FreeFEM: fewer vertices announced than written") {
    requireReadError(
        dir, "fewer.msh", replaceLine(freeFem, 1, "3 2 4"), 5,
        {"expected triangle 1 of 2 as \"v1 v2 v3 region\"", "\"0 1 3\"", "check the counts"});
  }
  SECTION("FreeFEM: a header announcing far more than the file holds") {
    // Also checks that the reader does not allocate what a corrupt header announces.
    requireReadError(dir, "huge.msh", replaceLine(freeFem, 1, "2000000000 2000000000 4"), 6,
                     {"expected vertex 5 of 2000000000 as \"x y label\"", "found \"1 2 3 1\""});
  }
  SECTION("gmsh 2.2: more elements than announced") {
    requireReadError(dir, "more22.msh", replaceLine(gmsh22, 12, "2"), 15,
                     {"expected $EndElements to close $Elements (opened at line 11)",
                      "after the 2 elements it announces"});
  }
  SECTION("gmsh 4.1: node blocks that do not add up to the header's count") {
    requireReadError(
        dir, "nodes41.msh", replaceLine(gmsh41, 10, "1 5 10 40"), 10,
        {"$Nodes header announces 5 nodes", "blocks hold 4", "expected the counts to agree"});
  }
  SECTION("gmsh 4.1: element blocks that do not add up to the header's count") {
    requireReadError(dir, "elements41.msh", replaceLine(gmsh41, 22, "2 4 1 3"), 22,
                     {"$Elements header announces 4 elements", "blocks hold 3"});
  }
}

TEST_CASE("mesh: malformed lines are rejected with the expected syntax", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM header") {
    requireReadError(dir, "header.msh", replaceLine(freeFem, 1, "4 2"), 1,
                     {"expected the FreeFEM header \"nv nt nbe\"", "found \"4 2\""});
  }
  SECTION("FreeFEM vertex with a missing field") {
    requireReadError(dir, "vertex.msh", replaceLine(freeFem, 3, "1 0"), 3,
                     {"expected vertex 2 of 4 as \"x y label\"", "found \"1 0\""});
  }
  SECTION("FreeFEM triangle with a non-integer vertex") {
    requireReadError(dir, "triangle.msh", replaceLine(freeFem, 7, "1 3.5 4 1"), 7,
                     {"expected triangle 2 of 2 as \"v1 v2 v3 region\""});
  }
  SECTION("gmsh 4.1 node tag") {
    requireReadError(dir, "tag41.msh", replaceLine(gmsh41, 13, "abc"), 13,
                     {"expected the tag of node 2 of 4 (node block at line 11)", "nodeTag"});
  }
  SECTION("gmsh physical name without quotes") {
    requireReadError(
        dir, "names.msh",
        replaceLine(gmsh22, 3, "$EndMeshFormat\n$PhysicalNames\n1\n1 7 bottom\n$EndPhysicalNames"),
        6, {"expected physical name 1 of 1 as \"dimension tag \"name\"\""});
  }
  SECTION("gmsh 4.1 $Entities line") {
    requireReadError(dir, "entities.msh", replaceLine(gmsh41, 6, "1 0 0 0 1 0 0 2 7"), 6,
                     {"expected curve 1 of 1 as", "numPhysicalTags"});
  }
  SECTION("a FreeFEM reader given a gmsh file") {
    requireReadError(dir, "gmsh.msh", gmsh41, 1, {"expected the FreeFEM header", "gmsh file"},
                     [](const std::string& p) { return readFreeFemMesh(p); });
  }
  SECTION("a gmsh reader given a FreeFEM file") {
    requireReadError(dir, "freefem.msh", freeFem, 1, {"expected $MeshFormat", "found \"4 2 4\""},
                     [](const std::string& p) { return readGmshMesh(p); });
  }
}

TEST_CASE("mesh: vertex numbers out of range are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM triangle vertex beyond nv") {
    requireReadError(dir, "range.msh", replaceLine(freeFem, 6, "1 2 5 1"), 6,
                     {"triangle 1 refers to vertex 5", "expected a vertex number in 1..4"});
  }
  SECTION("FreeFEM edge vertex 0") {
    requireReadError(dir, "range.msh", replaceLine(freeFem, 8, "0 1 1"), 8,
                     {"edge 1 refers to vertex 0", "1..4"});
  }
}

TEST_CASE("mesh: gmsh elements that reference unknown nodes are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("gmsh 2.2 line element") {
    requireReadError(dir, "node22.msh", replaceLine(gmsh22, 13, "1 1 2 7 1 1 9"), 13,
                     {"element 1 refers to node 9", "$Nodes (line 4) does not define"});
  }
  SECTION("gmsh 4.1 line element") {
    requireReadError(dir, "node41.msh", replaceLine(gmsh41, 24, "1 10 25"), 24,
                     {"element 1 refers to node 25", "expected the tag of a node in $Nodes"});
  }
  SECTION("gmsh 4.1 triangle") {
    requireReadError(dir, "node41.msh", replaceLine(gmsh41, 27, "3 10 30 41"), 27,
                     {"element 3 refers to node 41"});
  }
}

TEST_CASE("mesh: duplicate gmsh node tags are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("dense tags") {
    requireReadError(dir, "dup22.msh", replaceLine(gmsh22, 9, "3 0 1 0"), 9,
                     {"node tag 3 is defined twice (lines 8 and 9)"});
  }
  SECTION("sparse tags") {
    std::string text = replaceLine(gmsh41, 10, "1 4 10 90000000000");
    text = replaceLine(text, 12, "90000000000");
    text = replaceLine(text, 15, "90000000000");
    requireReadError(dir, "dup41.msh", text, 15,
                     {"node tag 90000000000 is defined twice (lines 12 and 15)"});
  }
}

TEST_CASE("mesh: NaN or Inf coordinates are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM") {
    requireReadError(
        dir, "nan.msh", replaceLine(freeFem, 2, "nan 0 1"), 2,
        {"vertex 1 has coordinate x that is not a finite number", "expected finite coordinates"});
  }
  SECTION("gmsh 2.2") {
    requireReadError(dir, "inf22.msh", replaceLine(gmsh22, 8, "3 1 inf 0"), 8,
                     {"node 3 has coordinate y that is not a finite number"});
  }
  SECTION("gmsh 4.1") {
    requireReadError(dir, "inf41.msh", replaceLine(gmsh41, 17, "-inf 0 0"), 17,
                     {"node 20 has coordinate x that is not a finite number"});
  }
}

TEST_CASE("mesh: gmsh nodes off the plane z = 0 are rejected", "[mesh][errors]") {
  TempDir dir;
  requireReadError(dir, "z22.msh", replaceLine(gmsh22, 8, "3 1 1 0.5"), 8,
                   {"node 3 has z = 0.5", "expected a 2D mesh in the plane z = 0"});
  requireReadError(dir, "z41.msh", replaceLine(gmsh41, 18, "1 1 1e-6"), 18,
                   {"node 30 has z = ", "plane z = 0"});
}

TEST_CASE("mesh: zero-area triangles are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM: three vertices on a line") {
    requireReadError(dir, "flat.msh", replaceLine(freeFem, 4, "2 0 2"), 6,
                     {"triangle 1 (vertices 1 2 3", "has zero area",
                      "more than 1e-12 times its longest edge squared"});
  }
  SECTION("gmsh 4.1: area below 1e-12 of the longest edge squared") {
    requireReadError(dir, "flat41.msh", replaceLine(gmsh41, 18, "1 1e-13 0"), 26,
                     {"element 2 (vertices 10 20 30", "has zero area"});
  }
}

TEST_CASE("mesh: coordinates so large that areas and volumes overflow are refused at the vertex",
          "[mesh][errors]") {
  // 1e308 is a finite double, but the area or volume made from it is not: the message used to
  // call such a tetrahedron "zero volume (-0.000976562)". The bound, 1e100, keeps every product
  // of three coordinate differences finite.
  TempDir dir;
  const std::string expected = "expected |x|, |y|, |z| <= 1e100 (rescale the mesh";
  SECTION("FreeFEM") {
    requireReadError(dir, "huge.msh", replaceLine(freeFem, 3, "1e308 0 1"), 3,
                     {"vertex 2 has coordinate x = 1e+308, too large: the areas and volumes "
                      "computed from it would overflow a double",
                      expected});
    requireReadError(dir, "huge2.msh", replaceLine(freeFem, 5, "0 -1e101 3"), 5,
                     {"vertex 4 has coordinate y = -1e+101, too large", expected});
  }
  SECTION("Medit") {
    const Mesh m = readMesh(dir.write("base.mesh", medit));
    REQUIRE(m.numCells() == 1);
    requireReadError(dir, "huge.mesh", replaceLine(medit, 6, "1e308 0 0 1"), 6,
                     {"vertex 2 has coordinate x = 1e+308, too large", expected});
    requireReadError(dir, "hugez.mesh", replaceLine(medit, 8, "0 0 2e100 1"), 8,
                     {"vertex 4 has coordinate z = 2e+100, too large", expected});
  }
  SECTION("gmsh 2.2") {
    requireReadError(dir, "huge22.msh", replaceLine(gmsh22, 8, "3 1 1e308 0"), 8,
                     {"node 3 has coordinate y = 1e+308, too large", expected});
  }
  SECTION("gmsh 4.1") {
    requireReadError(dir, "huge41.msh", replaceLine(gmsh41, 17, "1e308 0 0"), 17,
                     {"node 20 has coordinate x = 1e+308, too large", expected});
  }
  SECTION("the bound itself is accepted") {
    const Mesh m = readMesh(dir.write(
        "edge.msh",
        replaceLine(replaceLine(replaceLine(replaceLine(freeFem, 2, "0 0 1"), 3, "1e100 0 1"), 4,
                                "1e100 1e100 2"),
                    5, "0 1e100 3")));
    CHECK(m.totalMeasure() == Approx(1e200));
  }
}

TEST_CASE("mesh: a label or region beyond the range of an int is out of range, every format",
          "[mesh][errors]") {
  // The mesh keeps labels and regions as int; 2147483648 used to be "expected ... as ...", as if
  // the line were malformed.
  TempDir dir;
  const std::string range =
      "is out of range: expected a whole number from -2147483648 to "
      "2147483647 (labels and regions are stored as int)";
  SECTION("FreeFEM") {
    requireReadError(dir, "region.msh", replaceLine(freeFem, 6, "1 2 3 2147483648"), 6,
                     {"triangle 1: region 2147483648 " + range});
    requireReadError(dir, "label.msh", replaceLine(freeFem, 9, "2 3 -2147483649"), 9,
                     {"edge 2: label -2147483649 " + range});
    requireReadError(dir, "huge.msh", replaceLine(freeFem, 10, "3 4 99999999999999999999"), 10,
                     {"edge 3: label 99999999999999999999 " + range});
  }
  SECTION("Medit") {
    requireReadError(dir, "region.mesh", replaceLine(medit, 11, "1 2 3 4 2147483648"), 11,
                     {"tetrahedron 1: region 2147483648 " + range});
    requireReadError(dir, "label.mesh", replaceLine(medit, 14, "1 2 3 2147483648"), 14,
                     {"triangle 1: label 2147483648 " + range});
  }
  SECTION("gmsh 2.2") {
    requireReadError(dir, "label22.msh", replaceLine(gmsh22, 13, "1 1 2 2147483648 1 1 2"), 13,
                     {"element 1: physical tag 2147483648 " + range});
    requireReadError(dir, "name22.msh",
                     replaceLine(gmsh22, 3,
                                 "$EndMeshFormat\n$PhysicalNames\n1\n1 2147483648 \"top\"\n"
                                 "$EndPhysicalNames"),
                     6, {"physical name 1: tag 2147483648 " + range});
  }
  SECTION("gmsh 4.1") {
    requireReadError(dir, "label41.msh", replaceLine(gmsh41, 6, "1 0 0 0 1 0 0 1 2147483648 0"), 6,
                     {"curve 1: physical tag 2147483648 " + range});
  }
  SECTION("the ends of the range are accepted") {
    const Mesh m =
        readMesh(dir.write("ends.msh", replaceLine(replaceLine(freeFem, 6, "1 2 3 2147483647"), 8,
                                                   "1 2 -2147483648")));
    CHECK(m.cellRegion[0] == 2147483647);
    CHECK(m.facetLabel[0] == -2147483648);
  }
}

TEST_CASE("mesh: clockwise triangles are rejected, naming the triangle and how to fix it",
          "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM") {
    requireReadError(dir, "cw.msh", replaceLine(freeFem, 7, "1 4 3 1"), 7,
                     {"triangle 2 (vertices 1 4 3", "is clockwise",
                      "expected counter-clockwise triangles", "swap two of them"});
  }
  SECTION("gmsh 2.2") {
    requireReadError(dir, "cw22.msh", replaceLine(gmsh22, 14, "2 2 2 1 1 1 3 2"), 14,
                     {"element 2 (vertices 1 3 2", "is clockwise",
                      "in gmsh reverse the orientation of surface 1", "Reverse Surface{1}"});
  }
  SECTION("gmsh 4.1") {
    requireReadError(dir, "cw41.msh", replaceLine(gmsh41, 27, "3 10 40 30"), 27,
                     {"element 3 (vertices 10 40 30", "is clockwise", "Reverse Surface{1}"});
  }
}

TEST_CASE("mesh: edges whose two ends are the same node are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM") {
    requireReadError(
        dir, "loop.msh", replaceLine(freeFem, 9, "2 2 2"), 9,
        {"edge 2 joins vertex 2 to itself", "expected an edge between two different vertices"});
  }
  SECTION("gmsh 4.1") {
    requireReadError(dir, "loop41.msh", replaceLine(gmsh41, 24, "1 10 10"), 24,
                     {"element 1 joins vertex 10 to itself"});
  }
}

TEST_CASE("mesh: unsupported gmsh element types are rejected, naming the type", "[mesh][errors]") {
  TempDir dir;
  SECTION("gmsh 2.2: 6-node triangle") {
    requireReadError(dir, "tri6.msh", replaceLine(gmsh22, 14, "2 9 2 1 1 1 2 3 5 6 7"), 14,
                     {"element type 9 (6-node second-order triangle) is not supported",
                      "P2 nodes are built from the P1 mesh: mesh with order 1"});
  }
  SECTION("gmsh 4.1: 3-node line") {
    requireReadError(dir, "line3.msh",
                     replaceLine(replaceLine(gmsh41, 23, "1 1 8 1"), 24, "1 10 20 15"), 23,
                     {"element type 8 (3-node second-order line) is not supported",
                      "P2 nodes are built from the P1 mesh: mesh with order 1"});
  }
  SECTION("gmsh 2.2: quadrangle") {
    requireReadError(
        dir, "quad.msh", replaceLine(gmsh22, 14, "2 3 2 1 1 1 2 3 4"), 14,
        {"element type 3 (4-node quadrangle) is not supported",
         "expected 2-node lines (type 1), 3-node triangles (type 2)", "do not recombine"});
  }
  SECTION("gmsh 4.1: hexahedron (tetrahedra are read: 3D meshes)") {
    requireReadError(dir, "hex.msh", replaceLine(gmsh41, 25, "3 1 5 2"), 25,
                     {"element type 5 (8-node hexahedron) is not supported",
                      "4-node tetrahedra (type 4)", "tetrahedra only in 3D"});
  }
}

TEST_CASE("mesh: missing gmsh $End markers are rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("$EndNodes") {
    requireReadError(dir, "endnodes.msh", deleteLine(gmsh22, 10), 10,
                     {"expected $EndNodes to close $Nodes (opened at line 4)",
                      "after the 4 nodes it announces", "found \"$Elements\""});
  }
  SECTION("$EndMeshFormat") {
    requireReadError(dir, "endformat.msh", deleteLine(gmsh22, 3), 3,
                     {"expected $EndMeshFormat to close $MeshFormat (opened at line 1)"});
  }
  SECTION("$EndElements at the end of the file") {
    requireReadError(
        dir, "endelements.msh", deleteLine(gmsh41, 28), 27,
        {"missing $EndElements", "the file ends inside $Elements (opened at line 21)"});
  }
  SECTION("the end of an unknown section") {
    requireReadError(dir, "enddata.msh", gmsh22 + "$NodeData\n1\n\"u\"\n", 19,
                     {"missing $EndNodeData", "$NodeData (opened at line 17)"});
  }
  SECTION("an $End marker with no open section") {
    requireReadError(dir, "stray.msh", gmsh22 + "$EndNodes\n", 17,
                     {"unexpected \"$EndNodes\"", "expected the start of a section"});
  }
}

TEST_CASE("mesh: a mesh without triangles is rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM") {
    requireReadError(dir, "none.msh", replaceLine(freeFem, 1, "4 0 4"), 1,
                     {"announces nt = 0 triangles", "expected a mesh with at least one triangle"});
  }
  SECTION("gmsh 2.2 with line elements only") {
    requireReadError(dir, "none22.msh",
                     firstLines(replaceLine(gmsh22, 12, "1"), 13) + "$EndElements\n", 11,
                     {"$Elements holds no 3-node triangles (type 2)", "gmsh -2"});
  }
}

TEST_CASE("mesh: binary mesh files are rejected with a clear message", "[mesh][errors]") {
  TempDir dir;
  SECTION("gmsh binary") {
    requireReadError(dir, "binary.msh",
                     "$MeshFormat\n4.1 1 8\n" + std::string("\x01\0\0\0", 4) + "\n$EndMeshFormat\n",
                     2, {"binary gmsh file", "expected an ASCII file", "without -bin"});
  }
  SECTION("other binary content") {
    requireReadError(dir, "binary.msh", "4 2 4\n" + std::string("\x7f\0\x13", 3), 2,
                     {"this is a binary file", "expected a text mesh"});
  }
}

TEST_CASE("mesh: gmsh format versions other than 2.2 and 4.1 are rejected", "[mesh][errors]") {
  TempDir dir;
  requireReadError(
      dir, "v40.msh", replaceLine(gmsh41, 2, "4 0 8"), 2,
      {"gmsh format version 4 is not supported", "expected 2.2 or 4.1", "-format msh41"});
}

TEST_CASE("mesh: a gmsh surface in two physical surfaces is rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("gmsh 2.2: the triangle written once per group") {
    requireReadError(
        dir, "regions22.msh", replaceLine(replaceLine(gmsh22, 12, "3"), 15, "3 2 2 2 1 1 2 3"), 15,
        {"surface 1 is in two physical surfaces (1 and 2)", "a triangle has one region"});
  }
  SECTION("gmsh 4.1: $Entities lists two groups") {
    requireReadError(dir, "regions41.msh", replaceLine(gmsh41, 7, "1 0 0 0 1 1 0 2 1 2 0"), 25,
                     {"surface 1 is in two physical surfaces (1 and 2 in $Entities at line 4)"});
  }
}

TEST_CASE("mesh: gmsh element blocks must follow $Nodes and name entities of $Entities",
          "[mesh][errors]") {
  TempDir dir;
  SECTION("$Elements before $Nodes") {
    const auto lines = splitLines(gmsh41);
    std::vector<std::string> swapped(lines.begin(), lines.begin() + 8);
    swapped.insert(swapped.end(), lines.begin() + 20, lines.end());
    swapped.insert(swapped.end(), lines.begin() + 8, lines.begin() + 20);
    requireReadError(dir, "order.msh", joinLines(swapped), 9,
                     {"$Elements comes before $Nodes", "expected $Nodes first"});
  }
  SECTION("an entity missing from $Entities") {
    requireReadError(dir, "entity.msh", replaceLine(gmsh41, 23, "1 4 1 1"), 23,
                     {"element block of curve 4", "$Entities (line 4) lists no such entity"});
  }
}

// Checks over the whole mesh (finishMesh): each names the line of the offending item.

TEST_CASE("mesh: a triangle listed twice is rejected at its second line", "[mesh][errors]") {
  TempDir dir;
  // Each side of a doubled triangle bounds two triangles, as inside a body: only this check
  // sees it (the stiffness would count the triangle twice).
  requireReadError(dir, "twice.msh",
                   replaceLine(replaceLine(freeFem, 1, "4 3 4"), 7, "1 3 4 1\n1 2 3 1"), 8,
                   {"the triangle with vertices 1 2 3 is listed twice (lines 6 and 8)"});
}

TEST_CASE("mesh: a side shared by three triangles is rejected", "[mesh][errors]") {
  TempDir dir;
  // Vertex 5 at (2, 0.5): triangle 1 5 3 is counter-clockwise and a third one on side 1-3.
  const std::string text = replaceLine(
      replaceLine(replaceLine(freeFem, 1, "5 3 4"), 5, "0 1 3\n2 0.5 0"), 8, "1 3 4 1\n1 5 3 1");
  requireReadError(dir, "three.msh", text, 9,
                   {"is a side of a third triangle here (the others are at lines 7 and 8)"});
}

TEST_CASE("mesh: a labelled edge that is no side of any triangle is rejected", "[mesh][errors]") {
  TempDir dir;
  SECTION("FreeFEM: the diagonal the triangles do not have") {
    requireReadError(dir, "diag.msh", replaceLine(freeFem, 9, "2 4 2"), 9,
                     {"the edge from vertex 2 (1 0) to vertex 4 (0 1) (label 2) is not a "
                      "side of any triangle"});
  }
  SECTION("gmsh 4.1: a line to a node no triangle uses") {
    // A fifth node (tag 50, on a point entity) and a line 10-50: the line's node must not
    // be dropped silently with the unused nodes.
    const std::string text =
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
        "$Entities\n1 1 1 0\n1 2 2 0 0\n1 0 0 0 1 0 0 1 7 0\n1 0 0 0 1 1 0 1 1 0\n$EndEntities\n"
        "$Nodes\n2 5 10 50\n2 1 0 4\n10\n20\n30\n40\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
        "0 1 0 1\n50\n2 2 0\n$EndNodes\n"                  // lines 10-24
        "$Elements\n2 4 1 5\n1 1 1 2\n1 10 20\n4 10 50\n"  // lines 25-29
        "2 1 2 2\n2 10 20 30\n3 10 30 40\n$EndElements\n";
    requireReadError(dir, "stray41.msh", text, 29,
                     {"the edge from vertex 10 (0 0) to vertex 50 (2 2) (label 7) is not a "
                      "side of any triangle",
                      "Curve{c} In Surface{s}"});
  }
}

TEST_CASE("mesh: an edge listed twice with one label is rejected", "[mesh][errors]") {
  TempDir dir;
  // Its boundary load would count twice. The same edge with another label is two patches.
  requireReadError(dir, "edge2.msh",
                   replaceLine(replaceLine(freeFem, 1, "4 2 5"), 11, "4 1 4\n2 1 1"), 12,
                   {"is listed twice with label 1 (lines 8 and 12)"});
  const Mesh m = readMesh(
      dir.write("edge2ok.msh", replaceLine(replaceLine(freeFem, 1, "4 2 5"), 11, "4 1 4\n2 1 9")));
  CHECK(m.facetLabel.size() == 5);
}

TEST_CASE("mesh: vertices no triangle uses are dropped and the rest renumbered", "[mesh][reader]") {
  TempDir dir;
  // Vertex 3 of 5 at (0.3, 0.7) is used by nothing; the others are the base square.
  const std::string text =
      "5 2 4\n0 0 1\n1 0 1\n0.3 0.7 0\n1 1 2\n0 1 3\n"
      "1 2 4 1\n1 4 5 1\n1 2 1\n2 4 2\n4 5 3\n5 1 4\n";
  const Mesh m = readMesh(dir.write("unused.msh", text));
  const Mesh base = readMesh(dir.write("base.msh", freeFem));
  REQUIRE(m.droppedPoints.size() == 1);
  CHECK(m.droppedPoints[0].number == 3);
  CHECK(m.droppedPoints[0].x == Point(0.3, 0.7, 0));
  CHECK(m.numPoints() == 4);
  CHECK(base.droppedPoints.empty());
  // Same triangles and edges, vertex for vertex (the numbering after the gap shifts by one).
  CHECK(geometryOf(m) == geometryOf(base));
  CHECK(m.cellVertices == base.cellVertices);
  CHECK(m.facetVertices == base.facetVertices);
}

TEST_CASE("mesh: numbers are parsed strictly", "[mesh][errors]") {
  // A decimal comma, two points, a bare exponent or trailing characters are not numbers:
  // reading a prefix of them would silently give another mesh.
  TempDir dir;
  for (const std::string bad : {"0,9", "1.5.3", "1e", "1x", "1e+", "--1", "0x1p0", "1..0"}) {
    INFO(bad);
    requireReadError(dir, "number.msh", replaceLine(freeFem, 3, bad + " 0 1"), 3,
                     {"expected vertex 2 of 4 as \"x y label\""});
    requireReadError(dir, "number41.msh", replaceLine(gmsh41, 17, bad + " 0 0"), 17,
                     {"expected the coordinates of node 2 of 4"});
  }
  requireReadError(dir, "trailing.msh", replaceLine(freeFem, 7, "1 3 4 1 x"), 7,
                   {"expected triangle 2 of 2 as \"v1 v2 v3 region\""});
  requireReadError(dir, "label.msh", replaceLine(freeFem, 8, "1 2 1.0"), 8,
                   {"expected edge 1 of 4 as \"v1 v2 label\""});
}
