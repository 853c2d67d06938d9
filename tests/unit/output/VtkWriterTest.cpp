// The VTK XML output (output/VtkWriter) read back by VTK itself: readVtk.py, run with Debian's
// /usr/bin/python3 and python3-vtk9, reads the .pvd, .vtu and .vtp files and checks counts,
// cell types and node order, connectivity, the displacement on both sides of a fracture, the
// exact stress of a linear field and the fracture arrays (see readVtk.py for the list); on a
// tetrahedral box (P1 and P2) also VTK's own cell edges and cell volumes.
// A missing /usr/bin/python3 or vtk module fails the test: etc/debian-packages lists them.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "../fe/FeTestMeshes.hpp"
#include "../fracture/TestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fe/Material.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/output/VtkWriter.hpp"

using namespace friction;
namespace fs = std::filesystem;

namespace {

constexpr int kGrid = 4;            // 4 x 4 cells of the unit square, 32 triangles
constexpr double kFractureY = 0.5;  // fracture along grid row 2, across the whole width
constexpr int kFracturePoints = 7;  // synthetic fracture table rows
constexpr double kE = 2.0e10, kNu = 0.25;
// u = t (A x + b + c [x in Ω⁺]): linear on each side, so the FE stress is exact; the jump c
// makes the two coincident copies of each fracture node differ.
const double kA[4] = {2.0e-3, -2.0e-4, 5.0e-4, -3.0e-3};  // A = [[a11 a12] [a21 a22]]
const double kB[2] = {1.0e-2, -2.0e-2};                   // [m]
const double kC[2] = {4.0e-3, 1.0e-3};                    // jump [m]

/// The rows readVtk.py expects (keep in step with fractureRows there), scaled by t except
/// s and ST.
std::vector<FractureRow> fractureRows(double t) {
  const char* states[3] = {"stick", "slip", "open"};
  std::vector<FractureRow> rows;
  for (int i = 0; i < kFracturePoints; ++i) {
    const double s = double(i) / (kFracturePoints - 1);
    FractureRow r;
    r.s = s;
    r.position = Point(s, kFractureY, 0);
    r.slip[0] = t * 1e-3 * s;
    r.slipIncrement[0] = t * 2e-4 * s;
    r.sigmaN = t * -1e6 * (1 + s);
    r.tau[0] = t * 1e5 * s;
    r.ST = std::abs(r.tau[0]) / -r.sigmaN;
    r.residual[0] = t * 1e-9 * i;
    r.state = states[i % 3];
    rows.push_back(r);
  }
  return rows;
}

SplitMesh splitGrid() {
  Mesh m = test::gridMesh(kGrid);
  test::addHorizontalFracture(m, kGrid, kGrid / 2, 0, kGrid, 5, "crack");
  return splitFractures(m, {FractureSpec{"crack", 5, {}}});
}

/// u on every node, by the side of the cell that uses it (a node is used by one side only).
Eigen::VectorXd linearField(const LagrangeSpace& space, double t) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(space.numDofs());
  const Mesh& mesh = space.mesh();
  for (Index c = 0; c < space.numCells(); ++c) {
    const auto tri = mesh.cell(c);
    const double yc =
        (mesh.points[tri[0]].y() + mesh.points[tri[1]].y() + mesh.points[tri[2]].y()) / 3;
    const double plus = yc > kFractureY ? 1.0 : 0.0;
    for (const Index n : space.cellNodes(c)) {
      const Vector2& x = space.coordinate(n);
      u[space.dof(n, 0)] = t * (kA[0] * x.x() + kA[1] * x.y() + kB[0] + plus * kC[0]);
      u[space.dof(n, 1)] = t * (kA[2] * x.x() + kA[3] * x.y() + kB[1] + plus * kC[1]);
    }
  }
  return u;
}

fs::path freshTempDir(const std::string& tag) {
  const fs::path dir =
      fs::temp_directory_path() / ("friction-vtk-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Run readVtk.py on `pvd` with `arguments`; its output goes to dir/readVtk.log.
int runReadVtk(const fs::path& dir, const std::string& pvd, const std::string& arguments,
               std::string& log) {
  REQUIRE(fs::exists("/usr/bin/python3"));  // Debian's, which sees python3-vtk9
  const fs::path script = fs::path(FRICTION_SOURCE_DIR) / "tests/unit/output/readVtk.py";
  REQUIRE(fs::exists(script));
  const std::string cmd = "/usr/bin/python3 '" + script.string() + "' '" + pvd + "'" + arguments +
                          " > '" + (dir / "readVtk.log").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  log = cmd + "\n" + readFile(dir / "readVtk.log");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("VTK output of a linear field on a split mesh reads back in VTK with exact values",
          "[output][vtk]") {
  const int degree = GENERATE(1, 2);
  const bool planeStress = GENERATE(false, true);
  // Both data forms: the same checks read either back exactly (17 digits in ASCII).
  const VtkFormat format = GENERATE(VtkFormat::binary, VtkFormat::ascii);
  INFO("degree " << degree << ", planeStress " << planeStress << ", "
                 << (format == VtkFormat::binary ? "binary" : "ascii"));

  const SplitMesh split = splitGrid();
  const LagrangeSpace space(split.mesh, degree);
  const Material material = Material::fromYoungPoisson(kE, kNu, planeStress);
  const ElasticityAssembler assembler(space, material);

  // Counted by hand: 5 x 5 grid points + 5 Ω⁻ copies of the fracture nodes (both ends on the
  // boundary, so every one is duplicated) = 30; P2 adds one node per edge: 20 horizontal + 20
  // vertical + 16 diagonal edges of the grid + the 4 Ω⁻ fracture edges = 60, so 90.
  const int wantPoints = degree == 1 ? 30 : 90;
  REQUIRE(space.numNodes() == wantPoints);
  REQUIRE(space.numCells() == 32);

  const fs::path dir = freshTempDir("p" + std::to_string(degree) + (planeStress ? "s" : "e") +
                                    (format == VtkFormat::binary ? "b" : "a"));
  const fs::path caseDir = dir / "myCase";
  fs::create_directories(caseDir);
  VtkSeries series(caseDir.string(), "", format);
  CHECK(series.caseName() == "myCase");
  // 17 digits: the checks compare against exact values at round-off level.
  for (const double t : {0.5, 1.0}) {
    std::ostringstream name;
    name << t;
    series.write(t, name.str(), space, assembler, linearField(space, t),
                 {{"crack", fractureRows(t)}}, 17);
  }
  // Rewriting a time replaces its entry instead of adding one.
  series.write(1.0, "1", space, assembler, linearField(space, 1.0), {{"crack", fractureRows(1.0)}},
               17);

  CHECK(fs::is_regular_file(caseDir / "VTK" / "myCase.pvd"));
  CHECK(fs::is_regular_file(caseDir / "VTK" / "myCase_0.5.vtu"));
  CHECK(fs::is_regular_file(caseDir / "VTK" / "myCase_1.vtu"));
  CHECK(fs::is_regular_file(caseDir / "VTK" / "fractures" / "crack_0.5.vtp"));
  CHECK(fs::is_regular_file(caseDir / "VTK" / "fractures" / "crack_1.vtp"));
  CHECK(series.pvdPath() == (caseDir / "VTK" / "myCase.pvd").string());
  const std::string pvd = readFile(caseDir / "VTK" / "myCase.pvd");
  CHECK(countOf(pvd, "<DataSet ") == 4);  // 2 times x (mesh + 1 fracture)
  // The fracture's own series: its two files, part 0, at their times.
  const std::string own = readFile(caseDir / "VTK" / "fractures" / "crack.pvd");
  CHECK(countOf(own, "<DataSet ") == 2);
  CHECK(own.find("timestep=\"0.5\" group=\"\" part=\"0\" name=\"crack\" file=\"crack_0.5.vtp\"") !=
        std::string::npos);
  CHECK(own.find("timestep=\"1\" group=\"\" part=\"0\" name=\"crack\" file=\"crack_1.vtp\"") !=
        std::string::npos);
  // The data's form is the one asked for.
  const std::string vtu = readFile(caseDir / "VTK" / "myCase_1.vtu");
  CHECK((vtu.find("format=\"appended\"") != std::string::npos) == (format == VtkFormat::binary));
  CHECK((vtu.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos) ==
        (format == VtkFormat::binary));
  CHECK((vtu.find("format=\"ascii\"") != std::string::npos) == (format == VtkFormat::ascii));
  // No temporary files left beside the targets.
  for (const auto& e : fs::recursive_directory_iterator(caseDir / "VTK"))
    CHECK(e.path().filename().string().rfind(".", 0) != 0);

  std::ostringstream args;
  args.precision(17);
  args << " --E " << kE << " --nu " << kNu << (planeStress ? " --planeStress" : "") << " --A "
       << kA[0] << " " << kA[1] << " " << kA[2] << " " << kA[3] << " --b " << kB[0] << " " << kB[1]
       << " --jump " << kC[0] << " " << kC[1] << " --fractureY " << kFractureY << " --points "
       << wantPoints << " --cells 32 --degree " << degree << " --fracturePoints " << kFracturePoints
       << " --times 2";
  std::string log;
  const int code = runReadVtk(dir, series.pvdPath(), args.str(), log);
  INFO(log);
  REQUIRE(code == 0);
  fs::remove_all(dir);
}

TEST_CASE("VTK writers refuse what they cannot write and unknown fracture states",
          "[output][vtk]") {
  CHECK(vtkStateCode("stick") == 0);
  CHECK(vtkStateCode("slip") == 1);
  CHECK(vtkStateCode("open") == 2);
  CHECK_THROWS_AS(vtkStateCode("sliding"), std::invalid_argument);

  const fs::path dir = freshTempDir("errors");
  const fs::path missing = dir / "noSuchFolder" / "a.vtp";
  CHECK_THROWS_AS(writeFractureVtp(missing.string(), fractureRows(1), 8), InputError);
  CHECK_FALSE(fs::exists(missing));

  // An empty table is an empty data set, not a polyline with no points.
  writeFractureVtp((dir / "empty.vtp").string(), {}, 8);
  const std::string empty = readFile(dir / "empty.vtp");
  CHECK(empty.find("NumberOfPoints=\"0\"") != std::string::npos);
  CHECK(empty.find("NumberOfLines=\"0\"") != std::string::npos);
  // Binary too: empty arrays (a zlib header of no blocks) and the file closed after them.
  writeFractureVtp((dir / "emptyBinary.vtp").string(), {}, 8, {}, 3, VtkFormat::binary);
  const std::string emptyBinary = readFile(dir / "emptyBinary.vtp");
  CHECK(emptyBinary.find("NumberOfPoints=\"0\"") != std::string::npos);
  CHECK(emptyBinary.find("<AppendedData encoding=\"raw\">") != std::string::npos);
  CHECK(emptyBinary.size() > 11);
  CHECK(emptyBinary.compare(emptyBinary.size() - 11, 11, "</VTKFile>\n") == 0);

  // Names with XML specials stay well-formed attribute values.
  writePvd((dir / "a.pvd").string(), {{0.25, {"a&b.vtu", "x\"y.vtp"}, {"mesh", "<f>"}}}, 8);
  const std::string pvd = readFile(dir / "a.pvd");
  CHECK(pvd.find("file=\"a&amp;b.vtu\"") != std::string::npos);
  CHECK(pvd.find("file=\"x&quot;y.vtp\"") != std::string::npos);
  CHECK(pvd.find("name=\"&lt;f&gt;\"") != std::string::npos);
  CHECK(pvd.find("timestep=\"0.25\" group=\"\" part=\"1\"") != std::string::npos);
  fs::remove_all(dir);
}

namespace {

// 3D: u(x) = t (a + G x) on a jittered tetrahedral unit cube; G has a symmetric and a skew
// part (the skew part must not stress the body).
const double kG[9] = {2.0e-3,  -2.0e-4, 5.0e-4,   //
                      7.0e-4,  -3.0e-3, 1.5e-3,   //
                      -6.0e-4, 9.0e-4,  1.2e-3};  // G(i, j), row by row
const double kA3[3] = {1.0e-2, -2.0e-2, 3.0e-3};  // [m]

Eigen::VectorXd linearField3d(const LagrangeSpace& space, double t) {
  Eigen::VectorXd u(space.numDofs());
  for (Index n = 0; n < space.numNodes(); ++n) {
    const Point& x = space.point(n);
    for (int i = 0; i < 3; ++i)
      u[space.dof(n, i)] =
          t * (kA3[i] + kG[3 * i] * x.x() + kG[3 * i + 1] * x.y() + kG[3 * i + 2] * x.z());
  }
  return u;
}

}  // namespace

TEST_CASE("VTK output of a linear field on tetrahedra reads back in VTK with exact values",
          "[output][vtk][3d]") {
  const int degree = GENERATE(1, 2);
  const VtkFormat format = GENERATE(VtkFormat::binary, VtkFormat::ascii);
  INFO("degree " << degree << ", " << (format == VtkFormat::binary ? "binary" : "ascii"));

  Mesh mesh = test::unitCubeMesh(2, 0.3);
  // Regions 1 2 3 by cell number (readVtk.py --dim 3 expects 1 + c % 3).
  mesh.cellRegion.resize(static_cast<std::size_t>(mesh.numCells()));
  for (Index c = 0; c < mesh.numCells(); ++c)
    mesh.cellRegion[static_cast<std::size_t>(c)] = 1 + static_cast<int>(c % 3);
  const LagrangeSpace space(mesh, degree);
  const Material material = Material::fromYoungPoisson(kE, kNu, false);
  const ElasticityAssembler assembler(space, material);
  REQUIRE(space.dim() == 3);

  // 2³ cubes x 6 tetrahedra; P1 points 3³; P2 adds one node per edge, counted here from the
  // cells themselves.
  std::set<std::pair<Index, Index>> edges;
  for (Index c = 0; c < mesh.numCells(); ++c) {
    const auto v = mesh.cell(c);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(v[i], v[j]));
  }
  const Index wantPoints = degree == 1 ? 27 : 27 + static_cast<Index>(edges.size());
  REQUIRE(mesh.numCells() == 48);
  REQUIRE(space.numNodes() == wantPoints);

  const fs::path dir =
      freshTempDir("tet" + std::to_string(degree) + (format == VtkFormat::binary ? "b" : "a"));
  VtkSeries series((dir / "box").string(), "", format);
  for (const double t : {0.5, 1.0}) {
    std::ostringstream name;
    name << t;
    series.write(t, name.str(), space, assembler, linearField3d(space, t), {}, 17);
  }

  std::ostringstream args;
  args.precision(17);
  args << " --dim 3 --E " << kE << " --nu " << kNu << " --G";
  for (const double g : kG) args << " " << g;
  args << " --b " << kA3[0] << " " << kA3[1] << " " << kA3[2] << " --points " << wantPoints
       << " --cells 48 --degree " << degree << " --fracturePoints 0 --times 2";
  std::string log;
  const int code = runReadVtk(dir, series.pvdPath(), args.str(), log);
  INFO(log);
  REQUIRE(code == 0);
  fs::remove_all(dir);
}

namespace {

/// The "stress" rows (6 values each) of a .vtu written by writeVtu.
std::vector<std::vector<double>> stressRows(const std::string& vtu) {
  std::istringstream in(vtu);
  std::vector<std::vector<double>> rows;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("Name=\"stress\"") != std::string::npos) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.find("</DataArray>") != std::string::npos) break;
    std::istringstream v(line);
    std::vector<double> row;
    for (double x; v >> x;) row.push_back(x);
    rows.push_back(row);
  }
  return rows;
}

// σ⁰ with six distinct components, so that a component put in the wrong place shows [Pa].
Eigen::Matrix3d initialStress3d(Index, const Point&) {
  Eigen::Matrix3d s;
  s << -3e6, 4e5, 6e5,  //
      4e5, -2e6, 5e5,   //
      6e5, 5e5, -1e6;
  return s;
}

}  // namespace

TEST_CASE("writeVtu adds a stress offset: the whole tensor in 3D, its in-plane block and zz in 2D",
          "[output][vtk][3d]") {
  const fs::path dir = freshTempDir("initial");
  const Material material = Material::fromYoungPoisson(kE, kNu, false);
  const Eigen::Matrix3d s0 = initialStress3d(0, Point::Zero());

  // u = 0: the written stress is σ⁰ alone (to the written digits: 17).
  const Mesh cube = test::unitCubeMesh(1);
  const LagrangeSpace space3(cube, 1);
  writeVtu((dir / "a.vtu").string(), space3, ElasticityAssembler(space3, material),
           Eigen::VectorXd::Zero(space3.numDofs()), 17, initialStress3d);
  const auto rows3 = stressRows(readFile(dir / "a.vtu"));
  REQUIRE(rows3.size() == static_cast<std::size_t>(cube.numCells()));
  for (const auto& r : rows3)
    CHECK(r == std::vector<double>{s0(0, 0), s0(1, 1), s0(2, 2), s0(0, 1), s0(1, 2), s0(0, 2)});

  // 2D: σ⁰_yz and σ⁰_xz are not used; σ_zz is Hooke's out-of-plane stress (0 at u = 0) plus
  // the offset's zz (a pore pressure's −α_B Δp_b in plane strain; initialStress gives 0).
  const Mesh square = test::unitSquareMesh(2);
  const LagrangeSpace space2(square, 1);
  writeVtu((dir / "b.vtu").string(), space2, ElasticityAssembler(space2, material),
           Eigen::VectorXd::Zero(space2.numDofs()), 17, initialStress3d);
  const auto rows2 = stressRows(readFile(dir / "b.vtu"));
  REQUIRE(rows2.size() == static_cast<std::size_t>(square.numCells()));
  for (const auto& r : rows2)
    CHECK(r == std::vector<double>{s0(0, 0), s0(1, 1), s0(2, 2), s0(0, 1), 0, 0});
  fs::remove_all(dir);
}
