// The 3D fracture outputs of one fracture, written from synthetic rows and read back: the table
// (output/FieldWriter, writeFractureTable with dim 3) by parsing it here, the fault-surface
// .vtp (output/VtkWriter, writeFractureVtp with triangles) by VTK itself (readFaultVtp.py, run
// with Debian's /usr/bin/python3 and python3-vtk9), which also checks the .vtp against the
// table. The 2D table layout is checked too (the regression suites hold its bytes).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "friction/fracture/SignConventions.hpp"
#include "friction/output/FieldWriter.hpp"
#include "friction/output/VtkWriter.hpp"

using namespace friction;
namespace fs = std::filesystem;

namespace {

fs::path freshTempDir(const std::string& tag) {
  const fs::path dir =
      fs::temp_directory_path() / ("friction-fracout-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// A flat square fault of side kSide, tilted (n = (1, 2, 2)/3), corners c0 + L (a t₁ + b t₂)
// for (a, b) = (0,0) (1,0) (1,1) (0,1); triangles (0 1 2) and (0 2 3), whose right-hand normal
// is n (t₁ × t₂ = n). P2 adds the five edge midpoints, rows 4..8 in the order of kEdges.
constexpr double kSide = 2.0;
const Eigen::Vector3d kNormal = Eigen::Vector3d(1, 2, 2) / 3;
const Point kCorner(0.25, -0.5, 1.0);
constexpr int kEdges[5][2] = {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 0}};
constexpr int kTip = 3;  // row 3 is a tip: no recovered traction
const char* const kStates[3] = {"stick", "slip", "open"};

std::vector<FractureRow> faultRows(int degree) {
  const auto t = tangentBasis(kNormal);
  const double ab[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<Point> x;
  for (const auto& c : ab) x.push_back(kCorner + kSide * (c[0] * t[0] + c[1] * t[1]));
  if (degree == 2)
    for (const auto& e : kEdges) x.push_back(0.5 * (x[e[0]] + x[e[1]]));
  std::vector<FractureRow> rows;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double s = static_cast<double>(i);
    FractureRow r;
    r.position = x[i];
    r.normal = kNormal;
    r.tangent = t;
    r.slip = {1e-3 * (1 + s), -4e-4 * s};
    r.slipIncrement = {2e-4 * s, 1e-4};
    // A tip's row has the body's stress there and residual 0 (FrictionCase::fractureRows).
    const bool tip = i == static_cast<std::size_t>(kTip);
    r.sigmaN = -1e6 * (1 + s);
    r.tau = {3e5 * (1 + s), -4e5 * (1 + s)};
    r.ST = std::hypot(r.tau[0], r.tau[1]) / -r.sigmaN;
    r.residual = {tip ? 0.0 : 3e-9 * s, tip ? 0.0 : 4e-9 * s};
    r.state = tip ? "tip" : kStates[i % 3];
    rows.push_back(r);
  }
  return rows;
}

std::vector<std::array<Index, 6>> faultTriangles(int degree) {
  if (degree == 1) return {{0, 1, 2, 0, 0, 0}, {0, 2, 3, 0, 0, 0}};
  // Midpoint rows: 4 + index in kEdges; (0 1 2): 01 12 20; (0 2 3): 02 23 30.
  return {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 6, 7, 8}};
}

double number(const std::string& w) { return w == "nan" ? std::nan("") : std::stod(w); }

}  // namespace

TEST_CASE("3D fracture table: columns, frame line, slip in x y z, magnitudes, tips",
          "[output][fracture][3d]") {
  const fs::path dir = freshTempDir("table");
  std::vector<FractureRow> rows = faultRows(2);
  const fs::path path = dir / "fault.dat";
  writeFractureTable(path.string(), rows, "status converged iterations 3", 17, 3);
  const auto text = lines(path);
  REQUIRE(text.size() == 3 + rows.size());
  CHECK(text[0] ==
        "# x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1 "
        "slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual state");
  CHECK(text[1] == "# status converged iterations 3");

  // Flat: one frame, n t1 t2 read back to round-off of 17 digits.
  const auto frame = words(text[2]);
  REQUIRE(frame.size() == 14);  // # frame n (3) t1 (3) t2 (3)
  CHECK(frame[0] == "#");
  CHECK(frame[1] == "frame");
  CHECK(frame[2] == "n");
  CHECK(frame[6] == "t1");
  CHECK(frame[10] == "t2");
  const auto vec = [&](int at) {
    return Eigen::Vector3d(std::stod(frame[at].substr(1)), std::stod(frame[at + 1]),
                           std::stod(frame[at + 2]));
  };
  CHECK((vec(3) - kNormal).norm() < 1e-15);
  CHECK((vec(7) - rows[0].tangent[0]).norm() < 1e-15);
  CHECK((vec(11) - rows[0].tangent[1]).norm() < 1e-15);

  // Columns by name.
  const auto names = words(text[0]);
  const auto col = [&](const std::vector<std::string>& w, const std::string& name) {
    for (std::size_t c = 1; c < names.size(); ++c)
      if (names[c] == name) return number(w[c - 1]);
    FAIL("no column " << name);
    return 0.0;
  };
  int tips = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const FractureRow& r = rows[i];
    const auto w = words(text[3 + i]);
    INFO("row " << i << ": " << text[3 + i]);
    REQUIRE(w.size() == names.size() - 1);
    // 17 digits read back: the written values to a few ulps of each quantity's scale.
    const Eigen::Vector3d x(col(w, "x"), col(w, "y"), col(w, "z"));
    CHECK((x - r.position).norm() < 1e-15 * 4);
    CHECK(Eigen::Vector3d(col(w, "nx"), col(w, "ny"), col(w, "nz")) == r.normal);
    CHECK(col(w, "slip1") == r.slip[0]);
    CHECK(col(w, "slip2") == r.slip[1]);
    const Eigen::Vector3d slip = r.slip[0] * r.tangent[0] + r.slip[1] * r.tangent[1];
    const Eigen::Vector3d slipXyz(col(w, "slipX"), col(w, "slipY"), col(w, "slipZ"));
    CHECK((slipXyz - slip).norm() < 1e-15 * slip.norm() + 1e-300);
    // The slip vector lies in the fault plane and has the slip's magnitude.
    CHECK(std::abs(slipXyz.dot(kNormal)) < 1e-15 * slip.norm() + 1e-300);
    CHECK(std::abs(col(w, "slipMagnitude") - std::hypot(r.slip[0], r.slip[1])) <
          1e-15 * slip.norm() + 1e-300);
    CHECK(col(w, "slipIncrement1") == r.slipIncrement[0]);
    CHECK(col(w, "slipIncrement2") == r.slipIncrement[1]);
    CHECK(w.back() == r.state);
    // A tip's row is written as any other (its values are the body's stress there).
    if (r.state == "tip") ++tips;
    CHECK(col(w, "sigmaN") == r.sigmaN);
    CHECK(col(w, "tau1") == r.tau[0]);
    CHECK(col(w, "tau2") == r.tau[1]);
    // τ = (3, −4)·1e5 (1 + i): |τ| = 5e5 (1 + i), to round-off.
    CHECK(std::abs(col(w, "tauMagnitude") - 5e5 * (1.0 + i)) < 1e-15 * 5e5 * (1.0 + i));
    CHECK(col(w, "ST") == r.ST);
    // residual = |D| = 5e-9 i; 0 at the tip.
    const double residual = r.state == "tip" ? 0.0 : 5e-9 * i;
    CHECK(std::abs(col(w, "residual") - residual) < 1e-15 * 5e-9 * (1.0 + i));
  }
  CHECK(tips == 1);

  // Curved: one normal differs by more than 1e-12: the frame is per node, in the columns.
  rows[5].normal = Eigen::Vector3d(1, 2, 2.00001).normalized();
  rows[5].tangent = tangentBasis(rows[5].normal);
  writeFractureTable(path.string(), rows, "status converged", 17, 3);
  CHECK(lines(path)[2] ==
        "# frame per node: n in columns nx ny nz, t1 = tangentBasis(n), t2 = n x t1 "
        "(docs/method.md)");
  // A difference of 1e-13 is still one frame (flat to 1e-12).
  rows[5].normal = kNormal + Eigen::Vector3d(1e-13, 0, 0);
  rows[5].tangent = rows[0].tangent;
  writeFractureTable(path.string(), rows, "status converged", 17, 3);
  CHECK(lines(path)[2].rfind("# frame n (", 0) == 0);
  fs::remove_all(dir);
}

TEST_CASE("2D fracture table: the layout of the 2D solver, components [0]", "[output][fracture]") {
  const fs::path dir = freshTempDir("table2d");
  FractureRow r;
  r.s = 0.5;
  r.position = Point(0.25, 0.75, 0);
  r.slip = {1e-3, 7.0};  // component [1] does not exist in 2D: not written
  r.slipIncrement = {2e-4, 7.0};
  r.sigmaN = -1e6;
  r.tau = {-2e5, 7.0};
  r.ST = 0.2;
  r.residual = {-3e-9, 7.0};
  // t_Γ = (0.6, 0.8), n_Γ = (t_y, −t_x): nx ny tx ty, and the slip vector slip·t_Γ.
  r.tangent[0] = Eigen::Vector3d(0.6, 0.8, 0);
  r.normal = Eigen::Vector3d(0.8, -0.6, 0);
  r.state = "slip";
  FractureRow tip = r;  // a tip's row: the body's stress, residual 0, written alike
  tip.slip[0] = tip.slipIncrement[0] = tip.residual[0] = 0;
  tip.state = "tip";
  writeFractureTable((dir / "a.dat").string(), {r, tip}, "status converged", 6, 2);
  const auto text = lines(dir / "a.dat");
  REQUIRE(text.size() == 4);
  CHECK(text[0] ==
        "# s x y slip slipIncrement sigmaN tau ST residual nx ny tx ty slipX slipY state");
  CHECK(text[1] == "# status converged");
  CHECK(text[2] ==
        "0.5 0.25 0.75 0.001 0.0002 -1e+06 -200000 0.2 -3e-09 0.8 -0.6 0.6 0.8 0.0006 0.0008 slip");
  CHECK(text[3] == "0.5 0.25 0.75 0 0 -1e+06 -200000 0.2 0 0.8 -0.6 0.6 0.8 0 0 tip");
  // The new columns come last before the state: the first nine keep their places, and the
  // opening and pressure columns come between them and the frame.
  FractureRow o = r;
  o.hasOpening = o.hasPressure = true;
  o.opening = 1e-4;
  o.pressure = 2e5;
  o.sigmaNEffective = -8e5;
  o.deltaCFS = 3e4;
  writeFractureTable((dir / "b.dat").string(), {o}, "status converged", 6, 2);
  const auto withColumns = lines(dir / "b.dat");
  REQUIRE(withColumns.size() == 3);
  CHECK(withColumns[0] ==
        "# s x y slip slipIncrement sigmaN tau ST residual opening pressure "
        "sigmaNEffective deltaCFS nx ny tx ty slipX slipY state");
  CHECK(withColumns[2] ==
        "0.5 0.25 0.75 0.001 0.0002 -1e+06 -200000 0.2 -3e-09 0.0001 200000 "
        "-800000 30000 0.8 -0.6 0.6 0.8 0.0006 0.0008 slip");
  fs::remove_all(dir);
}

TEST_CASE("3D fault-surface .vtp reads back in VTK: triangles, arrays, and the table's values",
          "[output][vtk][3d]") {
  const int degree = GENERATE(1, 2);
  INFO("degree " << degree);
  const fs::path dir = freshTempDir("vtp" + std::to_string(degree));
  const auto rows = faultRows(degree);
  const fs::path vtp = dir / "fault_1.vtp", dat = dir / "fault.dat";
  writeFractureVtp(vtp.string(), rows, 17, faultTriangles(degree), degree == 1 ? 3 : 6);
  writeFractureTable(dat.string(), rows, "status converged", 17, 3);

  REQUIRE(fs::exists("/usr/bin/python3"));  // Debian's, which sees python3-vtk9
  const fs::path script = fs::path(FRICTION_SOURCE_DIR) / "tests/unit/output/readFaultVtp.py";
  REQUIRE(fs::exists(script));
  // P1: one VTK triangle per fault triangle; P2: four (VTK's poly data has no quadratic cells).
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "/usr/bin/python3 '" << script.string() << "' '" << vtp.string() << "' '" << dat.string()
      << "' --points " << rows.size() << " --cells " << (degree == 1 ? 2 : 8) << " --firstArea "
      << (degree == 1 ? 0.5 : 0.125) * kSide * kSide << " --area " << kSide * kSide
      << " --tips 1 > '" << (dir / "log").string() << "' 2>&1";
  const int status = std::system(cmd.str().c_str());
  std::ifstream log(dir / "log");
  std::stringstream text;
  text << log.rdbuf();
  INFO(cmd.str() << "\n" << text.str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  fs::remove_all(dir);
}

TEST_CASE("writeFractureVtp refuses triangles that are not rows", "[output][vtk][3d]") {
  const fs::path dir = freshTempDir("vtpbad");
  const auto rows = faultRows(1);
  const fs::path path = dir / "a.vtp";
  CHECK_THROWS_AS(writeFractureVtp(path.string(), rows, 8, {{0, 1, 4, 0, 0, 0}}, 3),
                  std::invalid_argument);
  CHECK_THROWS_AS(writeFractureVtp(path.string(), rows, 8, {{0, 1, 2, 0, 0, 0}}, 4),
                  std::invalid_argument);
  CHECK_FALSE(fs::exists(path));
  fs::remove_all(dir);
}

TEST_CASE("3D outputs mark where fault surfaces meet: the table's notes, the .vtp's array",
          "[output][vtk][3d][intersection]") {
  const fs::path dir = freshTempDir("meet");
  const auto rows = faultRows(1);
  const fs::path dat = dir / "fault.dat", vtp = dir / "fault_1.vtp", plain = dir / "plain_1.vtp";
  // The notes follow the frame line (line 3 stays the frame).
  writeFractureTable(dat.string(), rows, "status converged", 8, 3,
                     {"intersection (abutting) with 'main': ends on it"});
  const auto table = lines(dat);
  REQUIRE(table.size() == 4 + rows.size());
  CHECK(table[2].rfind("# frame", 0) == 0);
  CHECK(table[3] == "# intersection (abutting) with 'main': ends on it");
  // One code per fracture node: an Int32 array 'intersection', its legend in the comment.
  writeFractureVtp(vtp.string(), rows, 8, faultTriangles(1), 3, VtkFormat::ascii, {1, 2, 0, 4});
  std::ifstream in(vtp);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  CHECK(s.find("point array intersection (where fault surfaces meet): 0 no other fault, 1 passes "
               "through, 2 ends on another (held), 3 ends together with another, 4 tip") !=
        std::string::npos);
  const auto at = s.find("Name=\"intersection\"");
  REQUIRE(at != std::string::npos);
  const auto values = s.find(">", at) + 1;
  CHECK(words(s.substr(values, s.find("</DataArray>", values) - values)) ==
        std::vector<std::string>{"1", "2", "0", "4"});
  // Without codes (a fault that meets none) the file is as before: no such array, no legend.
  writeFractureVtp(plain.string(), rows, 8, faultTriangles(1), 3, VtkFormat::ascii);
  std::ifstream in2(plain);
  std::stringstream text2;
  text2 << in2.rdbuf();
  CHECK(text2.str().find("intersection") == std::string::npos);
  CHECK_THROWS_AS(writeFractureVtp(vtp.string(), rows, 8, faultTriangles(1), 3, VtkFormat::ascii,
                                   {1, 2, 0, 4, 1}),
                  std::invalid_argument);
  fs::remove_all(dir);
}
