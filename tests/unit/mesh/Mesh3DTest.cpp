// 3D meshes: the unit cube cut into the 6 tetrahedra around its diagonal (0,0,0)-(1,1,1),
// written in the test as Medit .mesh and gmsh 4.1 / 2.2, with its 12 boundary triangles
// labelled by cube face and an internal fault made of the 2 faces in the plane x = y; and a
// real gmsh run of a cube with an embedded square. Counts, labels, names, orientation, the
// refusals (negative or flat tetrahedra, vertices out of range, labelled triangles that are
// no face, tetrahedra listed twice), the mesh checks and the FE spaces on a mesh read from a file.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <sstream>

#include "MeshTestHelpers.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/MeshCheck.hpp"
#include "friction/mesh/MeshReader.hpp"
#include "friction/mesh/MeshTopology.hpp"

using namespace friction;
using namespace friction::test;

namespace {

// Vertex 1 + x + 2y + 4z (1-based) at (x, y, z) ∈ {0, 1}³.
std::vector<std::array<int, 3>> cubeVertices() {
  std::vector<std::array<int, 3>> v;
  for (int k = 0; k < 8; ++k) v.push_back({k & 1, (k >> 1) & 1, (k >> 2) & 1});
  return v;
}
// One tetrahedron per order of the axes (0, e_a, e_a + e_b, (1,1,1)); the odd orders have two
// vertices swapped so that every volume is +1/6.
const std::vector<std::array<int, 4>> cubeTetrahedra = {{1, 2, 4, 8}, {1, 6, 2, 8}, {1, 4, 3, 8},
                                                        {1, 3, 7, 8}, {1, 5, 6, 8}, {1, 7, 5, 8}};
// Boundary triangles with the cube face as label (x=0: 1, x=1: 2, y=0: 3, y=1: 4, z=0: 5,
// z=1: 6), then the fault (label 7) in the plane x = y.
const std::vector<std::array<int, 4>> cubeTriangles = {
    {1, 2, 4, 5}, {2, 4, 8, 2}, {1, 2, 6, 3}, {2, 6, 8, 2}, {1, 3, 4, 5},
    {3, 4, 8, 4}, {1, 3, 7, 1}, {3, 7, 8, 4}, {1, 5, 6, 3}, {5, 6, 8, 6},
    {1, 5, 7, 1}, {5, 7, 8, 6}, {1, 5, 8, 7}, {1, 4, 8, 7}};

std::string medit(const std::vector<std::array<int, 4>>& tets = cubeTetrahedra,
                  const std::vector<std::array<int, 4>>& tris = cubeTriangles) {
  std::ostringstream s;
  s << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n8\n";
  for (const auto& p : cubeVertices()) s << p[0] << " " << p[1] << " " << p[2] << " 0\n";
  s << "\nTetrahedra\n" << tets.size() << "\n";
  for (const auto& t : tets) s << t[0] << " " << t[1] << " " << t[2] << " " << t[3] << " 9\n";
  s << "\nTriangles\n" << tris.size() << "\n";
  for (const auto& t : tris) s << t[0] << " " << t[1] << " " << t[2] << " " << t[3] << "\n";
  s << "\nEnd\n";
  return s.str();
}

const std::string physicalNames =
    "$PhysicalNames\n3\n2 7 \"fault\"\n2 1 \"left\"\n3 9 \"rock\"\n$EndPhysicalNames\n";

std::string gmsh22() {
  std::ostringstream s;
  s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" << physicalNames << "$Nodes\n8\n";
  const auto v = cubeVertices();
  for (int k = 0; k < 8; ++k)
    s << k + 1 << " " << v[k][0] << " " << v[k][1] << " " << v[k][2] << "\n";
  s << "$EndNodes\n$Elements\n" << 1 + cubeTriangles.size() + cubeTetrahedra.size() << "\n";
  int tag = 1;
  s << tag++ << " 15 2 0 1 1\n";  // a point element: skipped
  for (const auto& t : cubeTriangles)
    s << tag++ << " 2 2 " << t[3] << " " << t[3] << " " << t[0] << " " << t[1] << " " << t[2]
      << "\n";
  for (const auto& t : cubeTetrahedra)
    s << tag++ << " 4 2 9 1 " << t[0] << " " << t[1] << " " << t[2] << " " << t[3] << "\n";
  s << "$EndElements\n";
  return s.str();
}

// 4.1: one surface entity per label (its physical group has the label's number), one volume.
std::string gmsh41() {
  std::ostringstream s;
  s << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" << physicalNames;
  s << "$Entities\n0 0 7 1\n";
  for (int l = 1; l <= 7; ++l) s << l << " 0 0 0 1 1 1 1 " << l << " 0\n";
  s << "1 0 0 0 1 1 1 1 9 0\n$EndEntities\n";
  s << "$Nodes\n1 8 1 8\n3 1 0 8\n";
  for (int k = 1; k <= 8; ++k) s << k << "\n";
  for (const auto& p : cubeVertices()) s << p[0] << " " << p[1] << " " << p[2] << "\n";
  s << "$EndNodes\n$Elements\n8 " << cubeTriangles.size() + cubeTetrahedra.size() << " 1 "
    << cubeTriangles.size() + cubeTetrahedra.size() << "\n";
  int tag = 1;
  for (int l = 1; l <= 7; ++l) {
    int n = 0;
    for (const auto& t : cubeTriangles) n += t[3] == l;
    s << "2 " << l << " 2 " << n << "\n";
    for (const auto& t : cubeTriangles)
      if (t[3] == l) s << tag++ << " " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  s << "3 1 4 " << cubeTetrahedra.size() << "\n";
  for (const auto& t : cubeTetrahedra)
    s << tag++ << " " << t[0] << " " << t[1] << " " << t[2] << " " << t[3] << "\n";
  s << "$EndElements\n";
  return s.str();
}

// The line of `text` (1-based) that holds `needle` first.
int lineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

void checkCube(const Mesh& m) {
  CHECK(m.dim == 3);
  CHECK(m.verticesPerCell() == 4);
  CHECK(m.verticesPerFacet() == 3);
  CHECK(m.numPoints() == 8);
  CHECK(m.numCells() == 6);
  CHECK(m.numFacets() == 14);
  CHECK(m.cellRegion == std::vector<int>(6, 9));
  for (Index c = 0; c < m.numCells(); ++c)
    CHECK(m.signedMeasure(c) == Approx(1.0 / 6).epsilon(1e-14));  // exact up to round-off
  CHECK(m.totalMeasure() == Approx(1.0).epsilon(1e-14));
  // Labels in file order per label, the fault's faces inside the body.
  std::map<int, int> perLabel;
  for (int l : m.facetLabel) ++perLabel[l];
  CHECK(perLabel == std::map<int, int>{{1, 2}, {2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2}, {7, 2}});
  const auto topo = m.topology();
  CHECK(topo->dimension() == 3);
  CHECK(topo->numFacets() == 18);  // 12 on the boundary, 6 inside (each around the diagonal)
  CHECK(topo->overSharedFacets().empty());
  int faultFaces = 0;
  for (Index e = 0; e < m.numFacets(); ++e) {
    const auto v = m.facet(e);
    const Index f = topo->findFacet({v[0], v[1], v[2]});
    REQUIRE(f >= 0);
    CHECK(topo->numCellsOf(f) == (m.facetLabel[e] == 7 ? 2 : 1));
    if (m.facetLabel[e] != 7) continue;
    ++faultFaces;
    for (Index k : v) CHECK(m.points[k].x() == m.points[k].y());
  }
  CHECK(faultFaces == 2);
  CHECK(unlabelledBoundaryFacets(m).empty());
  CHECK(coincidentPoints(m).empty());
}

}  // namespace

TEST_CASE("mesh 3D: Medit and gmsh 2.2 / 4.1 files of one cube read alike", "[mesh][3d]") {
  TempDir dir;
  const Mesh medit3 = readMesh(dir.write("cube.mesh", medit()));
  const Mesh g22 = readMesh(dir.write("cube22.msh", gmsh22()));
  const Mesh g41 = readMesh(dir.write("cube41.msh", gmsh41()));
  CHECK(medit3.format == "Medit .mesh");
  CHECK(readMeditMesh(dir.file("cube.mesh")).numCells() == 6);
  CHECK(g22.format == "gmsh .msh 2.2");
  CHECK(g41.format == "gmsh .msh 4.1");
  for (const Mesh* m : {&medit3, &g22, &g41}) {
    INFO(m->format);
    checkCube(*m);
    CHECK(m->droppedPoints.empty());  // the point element's node is a vertex of the cube
  }
  // Same cells, same labelled faces, same orientation (all three number the nodes alike).
  CHECK(g22.cellVertices == medit3.cellVertices);
  CHECK(g41.cellVertices == medit3.cellVertices);
  CHECK(g22.facetVertices == medit3.facetVertices);
  CHECK(g22.facetLabel == medit3.facetLabel);
  // gmsh's names of dimension 2 are labels, of dimension 3 regions.
  for (const Mesh* m : {&g22, &g41}) {
    CHECK(m->labelNames == std::map<int, std::string>{{1, "left"}, {7, "fault"}});
    CHECK(m->regionNames == std::map<int, std::string>{{9, "rock"}});
  }
  CHECK(formatPoint(medit3.points[7], 3) == "(1 1 1)");
  CHECK(formatPoint(medit3.points[7], 2) == "(1 1)");
}

TEST_CASE("mesh 3D: unlabelled boundary faces are listed, pointing out of the body",
          "[mesh][3d][check]") {
  TempDir dir;
  // Without the labels of the face x = 1 (label 2).
  std::vector<std::array<int, 4>> tris;
  for (const auto& t : cubeTriangles)
    if (t[3] != 2) tris.push_back(t);
  const Mesh m = readMesh(dir.write("open.mesh", medit(cubeTetrahedra, tris)));
  const std::vector<Index> found = unlabelledBoundaryFacets(m);
  REQUIRE(found.size() == 2 * 3);
  for (int f = 0; f < 2; ++f) {
    const Point& a = m.points[found[3 * f]];
    const Point& b = m.points[found[3 * f + 1]];
    const Point& c = m.points[found[3 * f + 2]];
    for (const Point* p : {&a, &b, &c}) CHECK(p->x() == 1.0);
    CHECK((b - a).cross(c - a).x() > 0);  // the right-hand normal points out (+x)
  }
}

TEST_CASE("mesh 3D: bad tetrahedra and faces are refused at their line", "[mesh][3d][errors]") {
  TempDir dir;
  SECTION("negative volume (two vertices swapped)") {
    auto tets = cubeTetrahedra;
    std::swap(tets[2][1], tets[2][2]);
    const std::string text = medit(tets);
    requireReadError(dir, "negative.mesh", text, lineOf(text, "1 3 4 8 9"),
                     {"tetrahedron 3 (vertices 1 3 4 8", "has negative volume",
                      "expected tetrahedra of positive volume", "swap two of its vertices"});
  }
  SECTION("negative volume in gmsh") {
    std::string text = gmsh22();
    const std::string good = "4 2 9 1 1 4 3 8", bad = "4 2 9 1 1 3 4 8";
    text.replace(text.find(good), good.size(), bad);
    requireReadError(dir, "negative.msh", text, lineOf(text, bad),
                     {"has negative volume", "gmsh writes them so"});
  }
  SECTION("zero volume (four vertices in a plane)") {
    auto tets = cubeTetrahedra;
    tets.push_back({1, 2, 4, 3});  // the face z = 0
    const std::string text = medit(tets);
    requireReadError(dir, "flat.mesh", text, lineOf(text, "1 2 4 3 9"),
                     {"tetrahedron 7", "has zero volume", "longest edge cubed"});
  }
  SECTION("a vertex out of range") {
    auto tets = cubeTetrahedra;
    tets[0][3] = 9;
    const std::string text = medit(tets);
    requireReadError(dir, "range.mesh", text, lineOf(text, "1 2 4 9 9"),
                     {"tetrahedron 1 refers to vertex 9", "expected a vertex number in 1..8"});
  }
  SECTION("a labelled triangle that is no face of a tetrahedron") {
    auto tris = cubeTriangles;
    tris.push_back({2, 3, 5, 8});  // three corners of the cube: no face
    const std::string text = medit(cubeTetrahedra, tris);
    requireReadError(dir, "noface.mesh", text, lineOf(text, "2 3 5 8"),
                     {"(label 8) is not a face of any tetrahedron", "Surface{s} In Volume{v}"});
  }
  SECTION("a tetrahedron listed twice") {
    auto tets = cubeTetrahedra;
    tets.push_back(tets[4]);
    const std::string text = medit(tets);
    requireReadError(dir, "twice.mesh", text, lineOf(text, "1 7 5 8 9") + 1,
                     {"is listed twice", "expected each tetrahedron once"});
  }
  SECTION("a triangle with a repeated vertex") {
    auto tris = cubeTriangles;
    tris.push_back({2, 2, 5, 8});
    const std::string text = medit(cubeTetrahedra, tris);
    requireReadError(dir, "repeated.mesh", text, lineOf(text, "2 2 5 8"),
                     {"triangle 15 is a triangle with a repeated vertex"});
  }
  SECTION("a 2D Medit file") {
    requireReadError(dir, "flat2d.mesh", "MeshVersionFormatted 2\nDimension 2\n", 2,
                     {"Dimension 2: expected 3"});
  }
  SECTION("a truncated file") {
    std::string text = medit();
    text = text.substr(0, text.find("\nEnd"));
    requireReadError(dir, "truncated.mesh", text, lineOf(text, "1 4 8 7"),
                     {"ends without \"End\""});
  }
  SECTION("hexahedra") {
    std::string text = medit();
    text.replace(text.find("End"), 3, "Hexahedra\n0\nEnd");
    requireReadError(dir, "hex.mesh", text, lineOf(text, "Hexahedra"),
                     {"section \"Hexahedra\" is not supported"});
  }
}

TEST_CASE("mesh 3D: a tetrahedral mesh read from a file carries the FE spaces", "[mesh][3d]") {
  TempDir dir;
  const Mesh m = readMesh(dir.write("cube.mesh", medit()));
  // P1: one node per point, three components. P2: plus one node per edge — the cube's 12
  // edges, its 6 face diagonals and the one body diagonal of the six tetrahedra (Euler:
  // 8 − 19 + 18 − 6 = 1).
  const LagrangeSpace p1(m, 1), p2(m, 2);
  CHECK(p1.numNodes() == 8);
  CHECK(p1.numDofs() == 24);
  CHECK(p2.numEdges() == 19);
  CHECK(p2.numNodes() == 27);
  CHECK(p2.numDofs() == 81);
}

TEST_CASE("mesh 3D: a gmsh cube with an embedded square reads with the square inside",
          "[mesh][3d][tools]") {
  TempDir dir;
  dir.write("cube.geo", R"(
lc = 0.3;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; };
Point(101) = {0.25, 0.25, 0.5, lc}; Point(102) = {0.75, 0.25, 0.5, lc};
Point(103) = {0.75, 0.75, 0.5, lc}; Point(104) = {0.25, 0.75, 0.5, lc};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Surface{101} In Volume{out[1]};
Physical Surface("outside", 1) = {1, out[0], out[2], out[3], out[4], out[5]};
Physical Surface("fault", 5) = {101};
Physical Volume("rock", 2) = {out[1]};
)");
  REQUIRE(run(dir, "gmsh -3 -format msh41 -o cube41.msh cube.geo") == 0);
  REQUIRE(run(dir, "gmsh -3 -format msh22 -o cube22.msh cube.geo") == 0);
  for (const std::string name : {"cube41.msh", "cube22.msh"}) {
    INFO(name);
    const Mesh m = readMesh(dir.file(name));
    CHECK(m.dim == 3);
    CHECK(m.numCells() > 24);
    CHECK(m.totalMeasure() == Approx(1.0).epsilon(1e-12));
    CHECK(m.labelNames == std::map<int, std::string>{{1, "outside"}, {5, "fault"}});
    CHECK(m.regionNames == std::map<int, std::string>{{2, "rock"}});
    CHECK(m.cellRegion == std::vector<int>(m.numCells(), 2));
    const auto topo = m.topology();
    double faultArea = 0, outsideArea = 0;
    int faultFaces = 0;
    for (Index e = 0; e < m.numFacets(); ++e) {
      const auto v = m.facet(e);
      const Index f = topo->findFacet({v[0], v[1], v[2]});
      REQUIRE(f >= 0);
      const double area =
          0.5 * (m.points[v[1]] - m.points[v[0]]).cross(m.points[v[2]] - m.points[v[0]]).norm();
      if (m.facetLabel[e] == 5) {
        ++faultFaces;
        faultArea += area;
        CHECK(topo->numCellsOf(f) == 2);  // embedded: a tetrahedron on each side
        for (Index k : v) CHECK(m.points[k].z() == Approx(0.5));
      } else {
        outsideArea += area;
        CHECK(topo->numCellsOf(f) == 1);
      }
    }
    CHECK(faultFaces > 0);
    CHECK(faultArea == Approx(0.25).epsilon(1e-12));
    CHECK(outsideArea == Approx(6.0).epsilon(1e-12));
    CHECK(unlabelledBoundaryFacets(m).empty());
  }
}

TEST_CASE("mesh 3D: FreeFEM's savemesh of an extruded mesh3 reads with its fault inside",
          "[mesh][3d][tools]") {
  TempDir dir;
  // A square with an interior fault (label 5) extruded in z into tetrahedra: the fault
  // becomes internal triangles labelled 5 (a vertical surface), top 6 and bottom 7.
  dir.write("cube.edp", R"(
load "msh3"
border b1(t=0,1){x=t; y=0; label=1;}
border b2(t=0,1){x=1; y=t; label=2;}
border b3(t=1,0){x=t; y=1; label=3;}
border b4(t=1,0){x=0; y=t; label=4;}
border frac(t=0.25,0.75){x=t; y=0.5; label=5;}
mesh Th2 = buildmesh(b1(4)+b2(4)+b3(4)+b4(4)+frac(2));
int[int] rup=[0,6], rdown=[0,7], lmid=[1,1,2,2,3,3,4,4,5,5];
mesh3 Th = buildlayers(Th2, 2, zbound=[0,1], labelmid=lmid, labelup=rup, labeldown=rdown);
savemesh(Th, "cube.mesh");
ofstream f("reference.txt");
f.precision(17);
f << Th.nv << " " << Th.nt << " " << Th.nbe << " " << Th.measure << endl;
)");
  REQUIRE(run(dir,
              "FF_LOADPATH='/usr/lib/freefem++;./' "
              "FF_INCLUDEPATH=/usr/include/freefem++/idp FreeFem++ -nw -ns -v 0 cube.edp") == 0);
  const Mesh m = readMesh(dir.file("cube.mesh"));
  std::ifstream ref(dir.file("reference.txt"));
  int nv, nt, nbe;
  double volume;
  REQUIRE(ref >> nv >> nt >> nbe >> volume);
  CHECK(m.format == "Medit .mesh");
  CHECK(m.dim == 3);
  CHECK(m.numPoints() == nv);
  CHECK(m.numCells() == nt);
  CHECK(m.numFacets() == nbe);
  CHECK(m.totalMeasure() == Approx(volume).epsilon(1e-12));
  CHECK(volume == Approx(1.0).epsilon(1e-12));
  const auto topo = m.topology();
  double faultArea = 0;
  for (Index e = 0; e < m.numFacets(); ++e) {
    const auto v = m.facet(e);
    const Index f = topo->findFacet({v[0], v[1], v[2]});
    REQUIRE(f >= 0);
    CHECK(topo->numCellsOf(f) == (m.facetLabel[e] == 5 ? 2 : 1));
    if (m.facetLabel[e] == 5)
      faultArea +=
          0.5 * (m.points[v[1]] - m.points[v[0]]).cross(m.points[v[2]] - m.points[v[0]]).norm();
  }
  CHECK(faultArea == Approx(0.5).epsilon(1e-12));  // 0.5 long, 1 high
  CHECK(unlabelledBoundaryFacets(m).empty());
}

TEST_CASE(
    "mesh 3D: a hidden cut (a face whose vertices have copies) is found, a sound mesh has "
    "none",
    "[mesh][3d][check]") {
  // Two tetrahedra on either side of the face (0,0,0) (1,0,0) (0,1,0); the lower one uses
  // copies of its vertices, so the face is a cut.
  Mesh m;
  m.dim = 3;
  m.points = {{0, 0, 0},  {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
              {0, 0, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.addCell({0, 1, 2, 3});
  m.addCell({5, 7, 6, 4});
  REQUIRE(m.signedMeasure(0) > 0);
  REQUIRE(m.signedMeasure(1) > 0);
  const auto pairs = coincidentPoints(m);
  CHECK(pairs == std::vector<std::pair<Index, Index>>{{0, 5}, {1, 6}, {2, 7}});
  // Joined through the face: no pair.
  m.points.resize(5);
  m.cellVertices = {0, 1, 2, 3, 0, 2, 1, 4};
  CHECK(coincidentPoints(m).empty());
  const CellSizes sizes = cellSizes(m);
  CHECK(sizes.total == Approx(1.0 / 3));
  CHECK(sizes.smallest == Approx(1.0 / 6));
  CHECK(sizes.largest == Approx(1.0 / 6));
}
