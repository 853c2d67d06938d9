// Tests of the mesh readers on files written by the real tools: gmsh meshes a .geo in
// formats 4.1 and 2.2 and our reading is compared with gmsh's own C++ API reading the same
// file; FreeFEM meshes an .edp and our reading is compared with what FreeFEM's readmesh
// gives. Also the tool-made files we must reject: order-2, binary and clockwise meshes.
#include <gmsh.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "MeshTestHelpers.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction;
using namespace friction::test;

namespace {

// Unit square, boundary curves 1..4 (bottom, right, top, left), an interior crack at y = 0.5
// embedded in the surface, an extra group "all" holding the bottom and the crack (so those
// edges appear twice), and a physical point (point elements to be skipped).
const std::string squareGeo = R"(
lc = 0.08;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc}; Point(5) = {0.25, 0.5, 0, lc}; Point(6) = {0.75, 0.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve{5} In Surface{1};
Physical Curve("bottom", 1) = {1};
Physical Curve("right", 2) = {2};
Physical Curve("top", 3) = {3};
Physical Curve("left", 4) = {4};
Physical Curve("fracture", 5) = {5};
Physical Curve("all", 6) = {1, 5};
Physical Surface("domain", 1) = {1};
Physical Point("corner", 9) = {1};
)";

using XY = std::pair<double, double>;
using Triangle = std::array<XY, 3>;

// A triangle as its vertex coordinates, rotated to start at the smallest one: the same
// triangle with the same orientation gives the same value whatever its first vertex.
Triangle canonical(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// What gmsh's API reads from a .msh file, in the same terms as our Mesh.
struct GmshReading {
  std::vector<XY> points;                   // sorted
  std::multiset<Triangle> triangles;        // canonical
  std::set<std::pair<XY, XY>> lines;        // distinct line elements, unoriented
  std::size_t lineElements = 0;             // line elements as gmsh's reader keeps them
  std::size_t lineElementsTimesGroups = 0;  // ... counted once per physical group of their curve
  std::map<int, std::string> labelNames, regionNames;
};

GmshReading readWithGmshApi(const std::string& file) {
  GmshReading r;
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(file);
  std::vector<std::size_t> nodeTags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(nodeTags, coords, parametric);
  std::map<std::size_t, XY> byTag;
  for (std::size_t i = 0; i < nodeTags.size(); ++i) {
    byTag[nodeTags[i]] = {coords[3 * i], coords[3 * i + 1]};
    r.points.push_back(byTag[nodeTags[i]]);
  }
  std::sort(r.points.begin(), r.points.end());

  std::vector<std::size_t> elementTags, elementNodes;
  gmsh::model::mesh::getElementsByType(2, elementTags, elementNodes);
  for (std::size_t e = 0; e < elementTags.size(); ++e)
    r.triangles.insert(canonical({byTag[elementNodes[3 * e]], byTag[elementNodes[3 * e + 1]],
                                  byTag[elementNodes[3 * e + 2]]}));

  gmsh::vectorpair curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) {
    std::vector<int> physical;
    gmsh::model::getPhysicalGroupsForEntity(dim, tag, physical);
    // Fresh vectors: getElementsByType takes non-empty ones as preallocated and keeps them.
    std::vector<std::size_t> lineTags, lineNodes;
    gmsh::model::mesh::getElementsByType(1, lineTags, lineNodes, tag);
    r.lineElements += lineTags.size();
    r.lineElementsTimesGroups += lineTags.size() * std::max<std::size_t>(1, physical.size());
    for (std::size_t e = 0; e < lineTags.size(); ++e)
      r.lines.insert(std::minmax(byTag[lineNodes[2 * e]], byTag[lineNodes[2 * e + 1]]));
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (dim == 1) r.labelNames[tag] = name;
    if (dim == 2) r.regionNames[tag] = name;
  }
  gmsh::finalize();
  return r;
}

double labelLength(const Mesh& m, int label) {
  double length = 0;
  for (Index e = 0; e < m.numFacets(); ++e)
    if (m.facetLabel[e] == label)
      length += (m.points[m.facetVertex(e, 1)] - m.points[m.facetVertex(e, 0)]).norm();
  return length;
}

}  // namespace

TEST_CASE("mesh: readMesh agrees with gmsh's own reader on meshes gmsh writes as 4.1 and 2.2",
          "[mesh][tools]") {
  TempDir dir;
  dir.write("square.geo", squareGeo);
  REQUIRE(run(dir, "gmsh -2 -format msh41 -o square41.msh square.geo") == 0);
  REQUIRE(run(dir, "gmsh -2 -format msh22 -o square22.msh square.geo") == 0);

  std::map<std::string, Mesh> meshes;
  for (const std::string name : {"square41.msh", "square22.msh"}) {
    INFO(name);
    const Mesh m = readMesh(dir.file(name));
    const GmshReading ref = readWithGmshApi(dir.file(name));
    REQUIRE(ref.points.size() > 100);  // a real mesh, not a trivial one

    std::vector<XY> points;
    for (const friction::Point& p : m.points) points.emplace_back(p.x(), p.y());
    std::sort(points.begin(), points.end());
    // Both readers turn the same decimal text into the nearest double: exact equality.
    CHECK(points == ref.points);

    std::multiset<Triangle> triangles;
    for (Index c = 0; c < m.numCells(); ++c)
      if (const auto t = m.cell(c); true)
        triangles.insert(canonical({XY(m.points[t[0]].x(), m.points[t[0]].y()),
                                    XY(m.points[t[1]].x(), m.points[t[1]].y()),
                                    XY(m.points[t[2]].x(), m.points[t[2]].y())}));
    CHECK(static_cast<std::size_t>(m.numCells()) == ref.triangles.size());
    CHECK(triangles == ref.triangles);  // same triangles, same orientation

    // One edge per line element and physical group. gmsh's own reader keeps the copies a 2.2
    // file holds (one per group) as separate elements, and a 4.1 line element once.
    if (name == "square41.msh")
      CHECK(static_cast<std::size_t>(m.numFacets()) == ref.lineElementsTimesGroups);
    else
      CHECK(static_cast<std::size_t>(m.numFacets()) == ref.lineElements);
    std::set<std::pair<XY, XY>> lines;
    for (Index f = 0; f < m.numFacets(); ++f)
      if (const auto e = m.facet(f); true)
        lines.insert(std::minmax(XY(m.points[e[0]].x(), m.points[e[0]].y()),
                                 XY(m.points[e[1]].x(), m.points[e[1]].y())));
    CHECK(lines == ref.lines);
    CHECK(m.labelNames == ref.labelNames);
    CHECK(m.regionNames == ref.regionNames);
    CHECK(m.cellRegion == std::vector<int>(m.numCells(), 1));
    // Lengths of the labelled curves; round-off only (gmsh writes 16 digits).
    CHECK(labelLength(m, 1) == Approx(1.0).epsilon(1e-12));
    CHECK(labelLength(m, 5) == Approx(0.5).epsilon(1e-12));
    CHECK(labelLength(m, 6) == Approx(1.5).epsilon(1e-12));
    CHECK(m.totalMeasure() == Approx(1.0).epsilon(1e-12));
    meshes[name] = m;
  }
  // The two files hold the same mesh; read alike, edge for edge.
  CHECK(geometryOf(meshes["square41.msh"]) == geometryOf(meshes["square22.msh"]));
}

TEST_CASE("mesh: readMesh agrees with FreeFEM's readmesh on a mesh FreeFEM writes",
          "[mesh][tools]") {
  TempDir dir;
  // The mesh is saved, read back with readmesh, and everything FreeFEM then knows is
  // printed with 17 digits for comparison.
  dir.write("square.edp", R"(
border a(t=0, 1) { x=t; y=0; label=1; }
border b(t=0, 1) { x=1; y=t; label=2; }
border c(t=1, 0) { x=t; y=1; label=3; }
border d(t=1, 0) { x=0; y=t; label=4; }
border frac(t=0.25, 0.75) { x=t; y=0.5; label=5; }
mesh Th = buildmesh(a(12) + b(12) + c(12) + d(12) + frac(6));
savemesh(Th, "square.msh");
mesh T = readmesh("square.msh");
ofstream f("reference.txt");
f.precision(17);
f << T.nv << " " << T.nt << " " << T.nbe << " " << T.area << endl;
for (int i = 0; i < T.nv; i++) f << T(i).x << " " << T(i).y << endl;
for (int k = 0; k < T.nt; k++) f << T[k][0] << " " << T[k][1] << " " << T[k][2] << " " << T[k].label << endl;
for (int k = 0; k < T.nbe; k++) f << T.be(k)[0] << " " << T.be(k)[1] << " " << T.be(k).label << endl;
)");
  REQUIRE(run(dir, "FreeFem++ -nw -ns -v 0 square.edp") == 0);
  const Mesh m = readMesh(dir.file("square.msh"));
  CHECK(m.format == "FreeFEM .msh");

  std::ifstream ref(dir.file("reference.txt"));
  int nv, nt, nbe;
  double area;
  REQUIRE(ref >> nv >> nt >> nbe >> area);
  REQUIRE(m.numPoints() == nv);
  REQUIRE(m.numCells() == nt);
  REQUIRE(m.numFacets() == nbe);
  CHECK(m.totalMeasure() == Approx(area).epsilon(1e-12));
  // FreeFEM's readmesh and ours read the same text: the same doubles.
  for (Index i = 0; i < nv; ++i) {
    double x, y;
    REQUIRE(ref >> x >> y);
    CHECK(m.points[i] == friction::Point(x, y, 0));
  }
  for (Index k = 0; k < nt; ++k) {
    std::array<Index, 3> t;
    int region;
    REQUIRE(ref >> t[0] >> t[1] >> t[2] >> region);
    CHECK(std::array<Index, 3>{m.cellVertex(k, 0), m.cellVertex(k, 1), m.cellVertex(k, 2)} == t);
    CHECK(m.cellRegion[k] == region);
  }
  std::set<std::pair<Index, Index>> refEdges, ourEdges;
  for (int k = 0; k < nbe; ++k) {
    Index a, b;
    int label;
    REQUIRE(ref >> a >> b >> label);
    CHECK(m.facetLabel[k] == label);
    CHECK(std::minmax(m.facetVertex(k, 0), m.facetVertex(k, 1)) == std::minmax(a, b));
  }
  // The interior crack: its edges carry label 5 and add up to its length.
  CHECK(labelLength(m, 5) == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("mesh: order-2 gmsh meshes are rejected, saying to mesh with order 1", "[mesh][tools]") {
  TempDir dir;
  dir.write("square.geo", squareGeo);
  REQUIRE(run(dir, "gmsh -2 -order 2 -format msh41 -o p2.msh square.geo") == 0);
  // The error is at the first block of 3-node lines: "1 curveTag 8 count" in $Elements
  // (before it only point blocks, whose element lines have two fields).
  std::ifstream in(dir.file("p2.msh"));
  std::string text, l;
  int line = 0, blockLine = 0, elementsLine = 0;
  while (std::getline(in, l)) {
    text += l + "\n";
    ++line;
    if (l == "$Elements") elementsLine = line;
    std::istringstream fields(l);
    std::vector<std::string> f{std::istream_iterator<std::string>(fields), {}};
    if (elementsLine && line > elementsLine + 1 && !blockLine && f.size() == 4 && f[0] == "1" &&
        f[2] == "8")
      blockLine = line;
  }
  REQUIRE(blockLine > 0);
  requireReadError(dir, "p2copy.msh", text, blockLine,
                   {"element type 8 (3-node second-order line)",
                    "P2 nodes are built from the P1 mesh: mesh with order 1"});
}

TEST_CASE("mesh: binary gmsh files are rejected, saying to write ASCII", "[mesh][tools]") {
  TempDir dir;
  dir.write("square.geo", squareGeo);
  REQUIRE(run(dir, "gmsh -2 -bin -format msh41 -o binary.msh square.geo") == 0);
  bool thrown = false;
  try {
    readMesh(dir.file("binary.msh"));
  } catch (const InputError& e) {
    thrown = true;
    INFO(e.what());
    CHECK(e.location().line == 2);
    CHECK(std::string(e.what()).find("binary gmsh file") != std::string::npos);
  }
  CHECK(thrown);
}

TEST_CASE("mesh: a gmsh surface meshed clockwise is rejected with how to reverse it",
          "[mesh][tools]") {
  TempDir dir;
  dir.write("square.geo", squareGeo + "Reverse Surface{1};\n");
  REQUIRE(run(dir, "gmsh -2 -format msh41 -o reversed.msh square.geo") == 0);
  bool thrown = false;
  try {
    readMesh(dir.file("reversed.msh"));
  } catch (const InputError& e) {
    thrown = true;
    INFO(e.what());
    CHECK(e.location().line > 0);
    CHECK(std::string(e.what()).find("is clockwise") != std::string::npos);
    CHECK(std::string(e.what()).find("Reverse Surface{1}") != std::string::npos);
  }
  CHECK(thrown);
}

TEST_CASE("mesh: a gmsh Physical Point off the mesh is dropped, the rest read as without it",
          "[mesh][tools]") {
  // gmsh writes a node for a physical point that no surface embeds; no triangle uses it.
  // Kept, it was a node without stiffness and crashed the solver.
  TempDir dir;
  dir.write("square.geo", squareGeo);
  dir.write("probe.geo",
            squareGeo + "Point(7) = {0.4, 0.8, 0, lc};\nPhysical Point(\"probe\", 8) = {7};\n");
  for (const std::string format : {"msh41", "msh22"}) {
    INFO(format);
    REQUIRE(run(dir, "gmsh -2 -format " + format + " -o square.msh square.geo") == 0);
    REQUIRE(run(dir, "gmsh -2 -format " + format + " -o probe.msh probe.geo") == 0);
    const Mesh plain = readMesh(dir.file("square.msh"));
    const Mesh probe = readMesh(dir.file("probe.msh"));
    CHECK(plain.droppedPoints.empty());  // the corner's physical point is a mesh vertex
    REQUIRE(probe.droppedPoints.size() == 1);
    CHECK(probe.droppedPoints[0].x == friction::Point(0.4, 0.8, 0));
    CHECK(probe.droppedPoints[0].number > 0);
    CHECK(geometryOf(probe) == geometryOf(plain));
    std::vector<char> used(probe.points.size(), 0);
    for (Index c = 0; c < probe.numCells(); ++c)
      if (const auto t = probe.cell(c); true)
        for (Index v : t) used.at(v) = 1;
    CHECK(std::count(used.begin(), used.end(), 0) == 0);
  }
}
