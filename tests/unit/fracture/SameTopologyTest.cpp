// A FreeFEM mesh and a gmsh mesh of the same geometry (the paper benchmark: unit square cut
// across its whole width at y = 0.5) split into the same topology: one fracture, no tip,
// every node duplicated, ends on the left and right patches, the body cut in two, n_Γ = (0 -1).
#include <gmsh.h>
#include <catch2/catch.hpp>

#include <unistd.h>
#include <filesystem>

#include "TestMeshes.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction;

namespace {

struct Topology {
  Index fractureNodes, duplicated, tips;
  FractureNodeKind startKind, endKind;
  double length;
  int components;
  Vector2 normal;
  std::map<std::string, double> patchLength;
};

Topology topologyOf(const Mesh& mesh, int fractureLabel) {
  const SplitMesh s = splitFractures(mesh, {{"fracture", fractureLabel, {}}});
  const FractureGeometry& g = s.fractures.at(0);
  Topology t{g.numNodes(),
             g.numDuplicated(),
             g.numTips(),
             g.kind.front(),
             g.kind.back(),
             g.length(),
             test::connectedComponents(s.mesh),
             g.normal[g.numNodes() / 2].head<2>(),
             {}};
  for (std::size_t e = 0; e < s.mesh.facetLabel.size(); ++e)
    t.patchLength[s.mesh.labelNames.at(s.mesh.facetLabel[e])] +=
        (s.mesh.points[s.mesh.facet(e)[1]].head<2>() - s.mesh.points[s.mesh.facet(e)[0]].head<2>())
            .norm();
  return t;
}

// The same geometry built with the gmsh API: 40 segments on every curve, like square.edp's
// default, the fracture embedded in two surfaces (below and above).
std::string writeGmshSquare(const std::string& path) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("square");
  using gmsh::model::geo::addPoint;
  const int p1 = addPoint(0, 0, 0), p2 = addPoint(1, 0, 0), p3 = addPoint(1, 0.5, 0),
            p4 = addPoint(1, 1, 0), p5 = addPoint(0, 1, 0), p6 = addPoint(0, 0.5, 0);
  using gmsh::model::geo::addLine;
  const int bottom = addLine(p1, p2), r1 = addLine(p2, p3), r2 = addLine(p3, p4),
            top = addLine(p4, p5), l2 = addLine(p5, p6), l1 = addLine(p6, p1),
            frac = addLine(p6, p3);
  const int lower = gmsh::model::geo::addCurveLoop({bottom, r1, -frac, l1});
  const int upper = gmsh::model::geo::addCurveLoop({frac, r2, top, l2});
  const int s1 = gmsh::model::geo::addPlaneSurface({lower});
  const int s2 = gmsh::model::geo::addPlaneSurface({upper});
  for (int c : {bottom, top, frac}) gmsh::model::geo::mesh::setTransfiniteCurve(c, 41);
  for (int c : {r1, r2, l1, l2}) gmsh::model::geo::mesh::setTransfiniteCurve(c, 21);
  gmsh::model::geo::synchronize();
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {bottom}, 1), "bottom");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {r1, r2}, 2), "right");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {top}, 3), "top");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {l1, l2}, 4), "left");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {frac}, 5), "fracture");
  gmsh::model::addPhysicalGroup(2, {s1, s2}, 1);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::model::mesh::generate(2);
  gmsh::write(path);
  gmsh::finalize();
  return path;
}

}  // namespace

TEST_CASE("FreeFEM and gmsh meshes of the paper benchmark split into the same topology",
          "[split][gmsh][freefem]") {
  Mesh freefem =
      readMesh(std::string(FRICTION_SOURCE_DIR) + "/cases/paperBenchmark/constant/mesh/square.msh");
  freefem.labelNames = {{1, "bottom"}, {2, "right"}, {3, "top"}, {4, "left"}, {5, "fracture"}};

  const auto dir =
      std::filesystem::temp_directory_path() / ("friction-topology-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const Mesh gmshMesh = readMesh(writeGmshSquare((dir / "square.msh").string()));
  std::filesystem::remove_all(dir);
  REQUIRE(gmshMesh.labelNames.at(5) == "fracture");

  const Topology a = topologyOf(freefem, 5);
  const Topology b = topologyOf(gmshMesh, 5);
  CHECK(a.fractureNodes == b.fractureNodes);
  CHECK(a.duplicated == a.fractureNodes);
  CHECK(b.duplicated == b.fractureNodes);
  CHECK(a.tips == 0);
  CHECK(b.tips == 0);
  CHECK(a.startKind == FractureNodeKind::boundary);
  CHECK(b.startKind == FractureNodeKind::boundary);
  CHECK(a.endKind == FractureNodeKind::boundary);
  CHECK(b.endKind == FractureNodeKind::boundary);
  CHECK(a.components == 2);
  CHECK(b.components == 2);
  CHECK(a.length == Approx(1.0));
  CHECK(b.length == Approx(1.0));
  CHECK(a.normal.y() == Approx(-1.0));
  CHECK(b.normal.y() == Approx(-1.0));
  CHECK(a.patchLength.size() == 4);
  for (const auto& [name, length] : a.patchLength) {
    CHECK(length == Approx(1.0));
    CHECK(b.patchLength.at(name) == Approx(length));
  }
}
