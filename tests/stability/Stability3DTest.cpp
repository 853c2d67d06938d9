// The stability suite in 3D (ctest label "stability"): hard set-ups of the fault-in-cube
// case (tests/regression/cases/faultInCube: the unit cube on a fixed base, its lid moved
// sideways and down, a square fault at z = 1/2), each generated in the build tree and run
// with the real binaries. Every run gets the 2D suite's checks, read from the 3D table:
// no NaN or Inf written (but a tip's traction columns), an explicit status for every step
// that agrees with its residual, equilibrium to round-off, dissipation τ·β ≤ 0 node by
// node, J never increasing within a step.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../regression/CaseRunner.hpp"
#include "StabilityChecks.hpp"

using namespace friction::regression;

namespace {

const char* const kCase = "tests:faultInCube";
const double kTolerance = 1e-10;  // the case's optimizer tolerance on ‖D‖/‖Σ‖

// ---- structured tetrahedral meshes written as Medit .mesh ----

// The box [0,1]³ on the grid lines xs, ys, zs (increasing from 0 to 1), each hexahedron cut
// into the six Kuhn tetrahedra of its main diagonal (conforming across cells, and every
// tetrahedron has vertices on two z levels: none lies flat on the fault). Boundary
// triangles: bottom 1, top 2, sides 3 (the face x = 1 gets rightLabel); the fault (label 5)
// is the grid plane z = zs[k] over columns i0..i1, rows j0..j1.
struct Fault {
  int k, i0, i1, j0, j1;
};

void writeGridMesh(const fs::path& path, const std::vector<double>& xs,
                   const std::vector<double>& ys, const std::vector<double>& zs, const Fault& f,
                   int rightLabel = 3) {
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1,
            nz = static_cast<int>(zs.size()) - 1;
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  using Tet = std::array<int, 4>;
  std::vector<Tet> tets;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          Tet t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          // Positive volume: the permutation's sign decides the orientation.
          if ((p[0] == 0 && p[1] == 2) || (p[0] == 1 && p[1] == 0) || (p[0] == 2 && p[1] == 1))
            std::swap(t[1], t[2]);
          tets.push_back(t);
        }
  auto point = [&](int v) {
    const int i = v % (nx + 1), j = (v / (nx + 1)) % (ny + 1), k = v / ((nx + 1) * (ny + 1));
    return std::array<int, 3>{i, j, k};
  };
  // Faces: boundary ones appear once; fault ones are interior faces in the fault's rectangle.
  std::map<std::array<int, 3>, int> faces;
  for (const Tet& t : tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f3;
      int n = 0;
      for (int a = 0; a < 4; ++a)
        if (a != skip) f3[n++] = t[a];
      std::sort(f3.begin(), f3.end());
      ++faces[f3];
    }
  std::vector<std::pair<std::array<int, 3>, int>> triangles;
  for (const auto& [face, uses] : faces) {
    std::array<int, 3> lo{1 << 30, 1 << 30, 1 << 30}, hi{-1, -1, -1};
    for (int v : face) {
      const auto g = point(v);
      for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], g[d]), hi[d] = std::max(hi[d], g[d]);
    }
    if (uses == 1) {
      const int label = hi[2] == 0 ? 1 : lo[2] == nz ? 2 : lo[0] == nx ? rightLabel : 3;
      triangles.push_back({face, label});
    } else if (lo[2] == f.k && hi[2] == f.k && lo[0] >= f.i0 && hi[0] <= f.i1 && lo[1] >= f.j0 &&
               hi[1] <= f.j1) {
      triangles.push_back({face, 5});
    }
  }
  std::ofstream out(path);
  out.precision(17);
  const int np = (nx + 1) * (ny + 1) * (nz + 1);
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << np << "\n";
  for (int v = 0; v < np; ++v) {
    const auto g = point(v);
    out << xs[g[0]] << " " << ys[g[1]] << " " << zs[g[2]] << " 0\n";
  }
  out << "Tetrahedra\n" << tets.size() << "\n";
  for (const Tet& t : tets)
    out << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << " " << t[3] + 1 << " 2\n";
  out << "Triangles\n" << triangles.size() << "\n";
  for (const auto& [t, label] : triangles)
    out << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << " " << label << "\n";
  out << "End\n";
}

std::vector<double> uniform(int n) {
  std::vector<double> v(n + 1);
  for (int i = 0; i <= n; ++i) v[i] = double(i) / n;
  return v;
}

// The fault-in-cube case on a grid mesh (n cells a side, h = 1/n; the fault [1/4, 3/4]² at
// z = 1/2, or [1/4, 1] × [1/4, 3/4] reaching the face x = 1 if toRight).
void useGridMesh(Case& c, const std::vector<double>& zs, int n, bool toRight = false) {
  writeGridMesh(c.dir() / "constant/mesh/cube.mesh", uniform(n), uniform(n), zs,
                {static_cast<int>(std::find(zs.begin(), zs.end(), 0.5) - zs.begin()), n / 4,
                 toRight ? n : 3 * n / 4, n / 4, 3 * n / 4},
                toRight ? 4 : 3);
  c.edit("system/meshDict", "cube\\.msh", "cube.mesh");
  REQUIRE(std::find(zs.begin(), zs.end(), 0.5) != zs.end());
}

// ---- the checks every run gets ----

struct RunSummary {
  std::vector<std::string> times, statuses;
  std::vector<double> relResidual;
  bool allConverged() const {
    return std::all_of(statuses.begin(), statuses.end(),
                       [](const std::string& s) { return s == "converged"; });
  }
};

RunSummary checkRun(Case& c, int exitCode) {
  INFO(c.log());
  CHECK((exitCode == 0 || exitCode == 3));
  RunSummary sum;
  std::vector<std::pair<double, std::string>> folders;
  for (const auto& e : fs::directory_iterator(c.dir())) {
    const std::string name = e.path().filename().string();
    char* end = nullptr;
    const double t = std::strtod(name.c_str(), &end);
    if (e.is_directory() && name != "0" && *end == '\0' && name[0] != '.')
      folders.push_back({t, name});
  }
  std::sort(folders.begin(), folders.end());
  for (const auto& [time, name] : folders) {
    const fs::path dir = c.dir() / name;
    INFO("time folder " << name);
    // No NaN or Inf written (a tip row holds the body's stress there).
    checkWrittenFinite(dir);
    const auto status = readStatus(dir / "solverStatus");
    REQUIRE(status.count("status"));
    REQUIRE(status.count("relResidual"));
    const std::string st = status.at("status");
    const double rel = std::stod(status.at("relResidual"));
    sum.times.push_back(name);
    sum.statuses.push_back(st);
    sum.relResidual.push_back(rel);
    CHECK((st == "converged" || st == "maxIterations" || st == "stalled" || st == "diverged" ||
           st == "inaccurate" || st == "nucleation"));
    // The status written is the status of the state written (a nucleation may be an
    // equilibrium, unstable, or none: its residual says which).
    if (st != "nucleation") CHECK((st == "converged") == (rel <= kTolerance));
    CHECK(std::stod(status.at("equilibriumResidual")) <= 1e-8);
    const Table t = c.namedTable(name, "fault");
    REQUIRE(!t.comments.empty());
    CHECK(t.comments[0].rfind("# status " + st + " ", 0) == 0);
    // Dissipation τ·β ≤ 0 at every node, to the solver's tolerance (relative to Σ), where the
    // state is a solution (converged, or inaccurate by round-off only): a step stopped at
    // maxIterations writes an iterate, and says so.
    if (st != "converged" && st != "inaccurate") continue;
    double sigmaMax = 0, betaMax = 0;
    int traction = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.state[i] == "tip") continue;
      ++traction;
      sigmaMax = std::max({sigmaMax, t.at(i, "tauMagnitude"), std::abs(t.at(i, "sigmaN"))});
      betaMax = std::max(betaMax, std::hypot(t.at(i, "slipIncrement1"), t.at(i, "slipIncrement2")));
    }
    CHECK(traction > 0);
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.state[i] == "tip") continue;
      const double power =
          t.at(i, "tau1") * t.at(i, "slipIncrement1") + t.at(i, "tau2") * t.at(i, "slipIncrement2");
      CHECK(power <= 1e-8 * sigmaMax * betaMax + 1e-300);
    }
  }
  CHECK(!sum.statuses.empty());
  CHECK((exitCode == 0) == sum.allConverged());
  if (exitCode == 3) CHECK_THAT(c.log(), Catch::Contains("did not converge"));
  checkHistoryDecreasing(c.dir());
  return sum;
}

// The slip vector (slipX, slipY) of every non-tip row, by position.
std::map<std::pair<long, long>, std::array<double, 2>> slipByPosition(const Table& t) {
  std::map<std::pair<long, long>, std::array<double, 2>> m;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    m[{std::lround(t.at(i, "x") * 1e6), std::lround(t.at(i, "y") * 1e6)}] = {t.at(i, "slipX"),
                                                                             t.at(i, "slipY")};
  return m;
}

// max |a − b| / max |b| over the nodes of b (the same nodes in a).
double slipDifference(const Table& a, const Table& b) {
  const auto sa = slipByPosition(a), sb = slipByPosition(b);
  REQUIRE(sa.size() == sb.size());
  double diff = 0, scale = 0;
  for (const auto& [p, v] : sb) {
    REQUIRE(sa.count(p));
    const auto& w = sa.at(p);
    diff = std::max(diff, std::hypot(w[0] - v[0], w[1] - v[1]));
    scale = std::max(scale, std::hypot(v[0], v[1]));
  }
  REQUIRE(scale > 0);  // the fault slips: a zero slip would compare nothing
  return diff / scale;
}

int count(const Table& t, const std::string& state) {
  return static_cast<int>(std::count(t.state.begin(), t.state.end(), state));
}

}  // namespace

TEST_CASE("stability 3D: slivers along the fault", "[stability][3d]") {
  // Layers of height δ·h on both sides of the fault (h = 1/12) in a 12-cell cube: the
  // tetrahedra there have aspect ratio 1/δ. As δ → 0 the thin layers tie their nodes to the
  // fault's, so the slip tends to that of the regular grid with the other layers alike.
  const int n = 12;
  const double h = 1.0 / n;
  Case reg(kCase, "stab3d-sliver-regular");
  useGridMesh(reg, uniform(n), n);
  const int rr = reg.solve();
  const RunSummary sr = checkRun(reg, rr);
  REQUIRE(rr == 0);
  const Table regular = reg.namedTable("1", "fault");
  CHECK(count(regular, "slip") > 0);
  for (const double delta : {1e-4, 1e-6, 1e-8}) {
    DYNAMIC_SECTION("sliver height " << delta << " h") {
      std::vector<double> zs;
      const double thin = delta * h;
      for (int k = 0; k <= n / 2; ++k) zs.push_back(k * (0.5 - thin) / (n / 2));
      zs.push_back(0.5);
      for (int k = n / 2; k >= 0; --k) zs.push_back(1 - k * (0.5 - thin) / (n / 2));
      std::ostringstream label;
      label << "stab3d-sliver-" << delta;
      Case c(kCase, label.str());
      useGridMesh(c, zs, n);
      const int rc = c.solve();
      INFO(c.log());
      const RunSummary s = checkRun(c, rc);
      const double d = slipDifference(c.namedTable("1", "fault"), regular);
      // Measured (rc, last status, relResidual, d): 1e-4: 0, converged, 1.2e-11, 7.1e-5;
      // 1e-6: 3, inaccurate, 1.1e-9, 7.2e-7; 1e-8: 3, inaccurate, 1.5e-7, 3.0e-7. The
      // layers move by δ·h: d falls like δ until round-off (κ ~ 1/δ) takes over.
      WARN("delta " << delta << ": rc " << rc << ", status " << s.statuses.back()
                    << ", relResidual " << s.relResidual.back() << ", slip difference " << d);
      CHECK(d <= 10 * delta + 1e-6);
      if (delta == 1e-4) CHECK(rc == 0);
      if (delta == 1e-8) {
        // Round-off misses the tolerance: said, with the reason, never 'converged'.
        CHECK(rc == 3);
        CHECK(s.statuses.back() == "inaccurate");
        CHECK_THAT(c.log(), Catch::Contains("ill-conditioned") && Catch::Contains("slivers"));
      }
    }
  }
}

TEST_CASE("stability 3D: nearly incompressible rock with P1", "[stability][3d]") {
  // P1 tetrahedra lock as nu -> 0.5 (the log warns); K's conditioning grows like
  // 1/(1 - 2 nu): the status must say whether the state written meets the tolerance (the
  // 2D case "the status written is the status of the state written (nu = 0.4999999999)").
  for (const char* nu : {"0.49", "0.4999", "0.4999999"}) {
    DYNAMIC_SECTION("nu = " << nu) {
      Case c(kCase, std::string("stab3d-nu-") + nu);
      c.edit("constant/mechanicalProperties", "nu +0\\.25;", std::string("nu ") + nu + ";");
      const int rc = c.solve();
      INFO(c.log());
      const RunSummary s = checkRun(c, rc);
      CHECK(s.statuses.size() == 4);
      CHECK_THAT(c.log(), Catch::Contains(std::string("Warning: nu = ") + nu +
                                          " with P1 elements: P1 locks"));
      // Every step converges. At 0.4999999 the interface stiffness (S_tt's diagonal, ~λ) is
      // 10⁶ times γ = E/h: Newton crawled there (J falling ~1 % an iteration, every step at
      // maxIterations, relResidual 3.4e-6 .. 5.9e-7) until it iterated with its own γ
      // (measured since: 4-5 iterations a step, relResidual ≤ 1.2e-11); the log says so.
      CHECK(rc == 0);
      CHECK(s.allConverged());
      // (From 0.4999 on, λ/E ≥ 1.7e3: Newton's own γ; at 0.49, λ/E = 16: the case's.)
      const std::string v = nu;
      if (v == "0.49")
        CHECK_THAT(c.log(), !Catch::Contains("Newton's gamma"));
      else
        CHECK_THAT(c.log(), Catch::Contains("Newton's gamma"));
      const Table t = c.namedTable("1", "fault");
      CHECK(count(t, "slip") + count(t, "stick") > 0);
    }
  }
  SECTION("nu = 0.25: no warning") {
    Case c(kCase, "stab3d-nu-0.25");
    const int rc = c.solve();
    checkRun(c, rc);
    CHECK(rc == 0);
    CHECK_THAT(c.log(), !Catch::Contains("P1 locks"));
  }
}

TEST_CASE("stability 3D: gamma over ten orders of magnitude gives the same slip",
          "[stability][3d]") {
  Case ref(kCase, "stab3d-gamma-reference");
  const int rr = ref.solve();
  checkRun(ref, rr);
  REQUIRE(rr == 0);
  const Table b = ref.namedTable("1", "fault");
  CHECK(count(b, "slip") > 0);
  for (const char* gamma : {"1e-5", "1e-3", "1e-1", "1e1", "1e3", "1e5"}) {
    DYNAMIC_SECTION("gammaRelative = " << gamma) {
      Case c(kCase, std::string("stab3d-gamma-") + gamma);
      c.edit("system/frictionSolution", "zeta +0;",
             std::string("zeta 0; gammaRelative ") + gamma + ";");
      const int rc = c.solve();
      INFO(c.log());
      const RunSummary s = checkRun(c, rc);
      const double d = slipDifference(c.namedTable("1", "fault"), b);
      // D = 0 does not depend on γ, so neither does the slip: to the solver tolerance
      // (‖D‖ ≤ 1e-10 ‖Σ‖) times the interface operator's conditioning, 1e-8 of the largest
      // slip (measured 2.4e-10 at 1e-3, 0 above: the same Newton path). At 1e-5 (γ ~ 0.1 MPa/m
      // against an interface stiffness ~ 10 GPa/m) Newton crawled (J falling ~1 % an
      // iteration, every step at maxIterations, the slip within 5.5e-3 of the reference)
      // until it iterated with its own γ there; the stop rule still uses the case's γ.
      CHECK(rc == 0);
      CHECK(s.allConverged());
      CHECK(d <= 1e-8);
      if (std::string(gamma) == "1e-5") CHECK_THAT(c.log(), Catch::Contains("Newton's gamma"));
    }
  }
}

TEST_CASE("stability 3D: load, unload, reverse load", "[stability][3d]") {
  Case c(kCase, "stab3d-reverse");
  c.edit("0/D", "\\(\\(0 \\(0 0 0\\)\\) \\(1 \\(0.002 0.001 -0.001\\)\\)\\)",
         "((0 (0 0 0)) (1 (0.002 0.001 -0.001)) (2 (0 0 -0.001)) (3 (-0.002 -0.001 -0.001)))");
  c.edit("system/controlDict", "endTime +1;", "endTime 3;");
  const int rc = c.solve();
  INFO(c.log());
  const RunSummary s = checkRun(c, rc);
  CHECK(rc == 0);
  REQUIRE(s.times.size() == 12);
  CHECK(s.allConverged());
  // Forward (t <= 1) the fault slips; unloading (t = 1.25, 1.5) it sticks, the slip kept,
  // while the shear falls and turns round; from t = 1.75 (lid still sheared forwards: the
  // slip's own back stress) it slips backwards. Measured, non-tip nodes slipping of 24:
  // 24 up to t = 1, then 0, 1, then 24 to t = 3.
  const Table t1 = c.namedTable("1", "fault");
  auto dot = [](const Table& a, std::size_t i, const Table& b, const char* x, const char* y) {
    return a.at(i, std::string(x) + "1") * b.at(i, std::string(y) + "1") +
           a.at(i, std::string(x) + "2") * b.at(i, std::string(y) + "2");
  };
  double slipMax = 0;
  for (std::size_t i = 0; i < t1.rows.size(); ++i)
    slipMax = std::max(slipMax, t1.at(i, "slipMagnitude"));
  CHECK(count(t1, "slip") > 0);
  for (const char* time : {"1.25", "1.5"}) {
    INFO("t = " << time);
    const Table t = c.namedTable(time, "fault");
    REQUIRE(t.rows.size() == t1.rows.size());
    CHECK(count(t, "stick") > 5 * count(t, "slip"));
    int reversedShear = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      if (t.state[i] != "stick") continue;
      CHECK(t.at(i, "slipIncrement1") == 0.0);
      CHECK(t.at(i, "slipIncrement2") == 0.0);
      CHECK(std::hypot(t.at(i, "slip1") - t1.at(i, "slip1"),
                       t.at(i, "slip2") - t1.at(i, "slip2")) <= 1e-12 * slipMax);
      reversedShear += dot(t, i, t1, "tau", "tau") < 0;
    }
    if (std::string(time) == "1.25") CHECK(count(t, "slip") == 0);
    if (std::string(time) == "1.5") CHECK(reversedShear > 0);  // turned, still held
  }
  for (const char* time : {"1.75", "2", "2.5", "3"}) {
    INFO("t = " << time);
    const Table t = c.namedTable(time, "fault");
    REQUIRE(t.rows.size() == t1.rows.size());
    CHECK(count(t, "slip") > 0);
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (t.state[i] == "slip") CHECK(dot(t, i, t1, "slipIncrement", "slipIncrement") < 0);
  }
  const Table t3 = c.namedTable("3", "fault");
  int back = 0;
  for (std::size_t i = 0; i < t3.rows.size(); ++i) {
    if (t3.state[i] == "tip") continue;
    ++back;
    // Slipped back past zero: the slip at t = 3 points against the forward slip.
    CHECK(dot(t3, i, t1, "slip", "slip") < 0);
  }
  CHECK(back > 0);
}

TEST_CASE("stability 3D: slip-weakening, gentle and abrupt", "[stability][3d]") {
  // μ from 0.2 to 0.1 over D_c: far above the slips of the case (~1e-3 m), the weakening is
  // gentle and every step is a stable equilibrium; at 1e-7 m it is abrupt: the first step
  // that slips loses the equilibrium, which must be said (status nucleation, exit 3, the run
  // stops there) with every value written finite.
  for (const char* dc : {"10", "1e-7"}) {
    const bool gentle = std::string(dc) == "10";
    DYNAMIC_SECTION("criticalSlip " << dc) {
      Case c(kCase, std::string("stab3d-weakening-") + (gentle ? "gentle" : "abrupt"));
      c.edit("constant/fractureProperties", "law +coulomb;\\n +frictionCoefficient +0.2;",
             std::string("law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.1; "
                         "criticalSlip ") +
                 dc + ";");
      const int rc = c.solve();
      INFO(c.log());
      const RunSummary s = checkRun(c, rc);
      REQUIRE(!s.statuses.empty());
      if (gentle) {
        CHECK(rc == 0);
        CHECK(s.allConverged());
        const auto last = readStatus(c.dir() / s.times.back() / "solverStatus");
        REQUIRE(last.count("patchStiffness"));
        CHECK(std::stod(last.at("patchStiffness")) > 0);
        CHECK(count(c.namedTable(s.times.back(), "fault"), "slip") > 0);
      } else {
        CHECK(rc == 3);
        CHECK(s.statuses.back() == "nucleation");
        for (std::size_t i = 0; i + 1 < s.statuses.size(); ++i) CHECK(s.statuses[i] == "converged");
        CHECK_THAT(c.log(), Catch::Contains("the quasi-static equilibrium is lost"));
        CHECK_THAT(c.log(), Catch::Contains("slipping on 'fault'"));
        CHECK_THAT(c.log(), Catch::Contains("m2 around ("));
        CHECK(s.times.size() < 4);  // stopped before endTime
      }
    }
  }
}

TEST_CASE("stability 3D: a fault reaching a Dirichlet face", "[stability][3d]") {
  const int n = 12;
  Case c(kCase, "stab3d-dirichlet");
  useGridMesh(c, uniform(n), n, true);
  c.edit("system/meshDict", "fault 5; \\}", "fault 5; right 4; }");
  c.edit("0/D", "sides +\\{ type free; \\}",
         "sides { type free; }\n    right { type fixedDisplacement; value (0 0 0); }");
  const int rc = c.solve();
  INFO(c.log());
  checkRun(c, rc);
  CHECK(rc == 0);
  const Table t = c.namedTable("1", "fault");
  int onFace = 0, held = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.at(i, "x") != 1.0) continue;
    ++onFace;
    CHECK(t.at(i, "slipMagnitude") == 0.0);
    if (t.state[i] != "tip") {
      ++held;
      CHECK(t.state[i] == "stick");
    }
  }
  // Measured: 7 rows on the face (2 of them tips), 5 held, 40 of 45 traction nodes slip. The
  // log counts the held nodes, not the tips (they have no jump to hold).
  CHECK(held > 0);
  CHECK(held < onFace);
  CHECK_THAT(c.log(), Catch::Contains("Note: " + std::to_string(held) +
                                      " fracture node(s) lie on a Dirichlet patch"));
  CHECK(count(t, "slip") > 0);
}

TEST_CASE("stability 3D: a block held only by a fault that opens", "[stability][3d]") {
  // The fault cuts the cube in two at z = 1/2 (it reaches every side face); the bottom is
  // fixed, the top free, and a fluid pressure pushes the faces apart: nothing holds the upper
  // half once the fault opens, so no equilibrium exists (the pressure's net force on it has
  // no reaction). The solver must say so and stop with a non-zero exit, never write a NaN,
  // never abort.
  const int n = 6;
  Case c(kCase, "stab3d-floating");
  writeGridMesh(c.dir() / "constant/mesh/cube.mesh", uniform(n), uniform(n), uniform(n),
                {n / 2, 0, n, 0, n});
  c.edit("system/meshDict", "cube\\.msh", "cube.mesh");
  c.edit("0/D", "top +\\{[^}]*\\}", "top { type free; }");
  writeText(c.dir() / "constant/fractureProperties",
            "fault { contact unilateral; law coulomb; frictionCoefficient 0.2; }\n");
  writeText(c.dir() / "constant/effects",
            "fluid { type fracturePressure; fracture fault; pressure 1e6; }\n");
  const int rc = c.solve();
  INFO(c.log());
  // The interface operator is singular along the rigid motions of the upper half, and what
  // the dense LU makes of that is round-off: measured with one ordering of the factor, huge
  // pivots (slip up to 2.9e10 m, opening up to 1.7e11 m at t = 1, note 3 of the judging);
  // with another (the ordering on the graph of the nodes), a step the line search refuses
  // (slip and opening 0, note 4). Every step stalled either way, exit 3, and the note names
  // the part and the remedy (a closed fracture).
  const RunSummary s = checkRun(c, rc);
  CHECK(rc == 3);
  CHECK(s.times.size() == 4);
  for (const std::string& st : s.statuses) CHECK(st == "stalled");
  CHECK_THAT(c.log(), Catch::Contains("touches no Dirichlet patch and only 'fault' holds it"));
  CHECK_THAT(c.log(), (Catch::Contains("opening up to") &&
                       Catch::Contains("keep its fracture closed (contact bilateral")) ||
                          (Catch::Contains("where they all open nothing holds the part") &&
                           Catch::Contains("make the fracture bilateral")));
  const Table t = c.namedTable("1", "fault");
  CHECK(count(t, "open") == static_cast<int>(t.rows.size()));  // no tip: the fault cuts through
  // The same block with the fault kept closed (bilateral): the fault holds it, the pressure
  // only lowers the friction bound, and the run converges.
  Case b(kCase, "stab3d-floating-bilateral");
  writeGridMesh(b.dir() / "constant/mesh/cube.mesh", uniform(n), uniform(n), uniform(n),
                {n / 2, 0, n, 0, n});
  b.edit("system/meshDict", "cube\\.msh", "cube.mesh");
  b.edit("0/D", "top +\\{[^}]*\\}", "top { type free; }");
  writeText(b.dir() / "constant/effects",
            "fluid { type fracturePressure; fracture fault; pressure 1e6; }\n");
  const int rb = b.solve();
  INFO(b.log());
  checkRun(b, rb);
  CHECK(rb == 0);
}
