// Fractures that open (contact unilateral, docs/method.md §8), in 2D, against what the physics
// requires: Sneddon's pressurised crack (cases/sneddonCrack, its sneddonError.py), the net
// pressure, a partly open crack node by node, opening and closing over load cycles, restart.
// The crack: half-length a = 1 m on the x axis (n_Γ = (0, −1)), in a square of half-width
// 50a held on its sides, E = 10 GPa, ν = 0.25, plane strain, μ_f = 0.6.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "CaseRunner.hpp"

using namespace friction::regression;

namespace {

/// One number of sneddonError.py's output ("name   value").
double sneddonValue(const std::string& out, const std::string& name) {
  std::smatch m;
  const std::regex r("(^|\n)" + name + " +([-+0-9.eE]+)");
  INFO(out);
  REQUIRE(std::regex_search(out, m, r));
  return std::stod(m[2].str());
}

/// sneddonError.py on the solved case with `options`; exit 0 required (its checks passed).
std::string sneddonError(const Case& c, const std::string& options = "") {
  const fs::path script = fs::path(FRICTION_SOURCE_DIR) / "cases/sneddonCrack/sneddonError.py";
  const fs::path log = c.dir() / "log.sneddonErrorTest";
  const int rc =
      run("/usr/bin/python3 '" + script.string() + "' -case '" + c.dir().string() + "' " + options,
          log);
  const std::string out = readText(log);
  INFO(out);
  CHECK(rc == 0);
  return out;
}

/// The effects of the case: the fluid pressure `pressure` (a value or "table (...)" or
/// "values \"...\""), and with stress an in-situ stress (sxx syy sxy) [Pa].
void setEffects(Case& c, const std::string& pressure, const std::string& stress = "") {
  std::string text =
      "FoamFile { version 2.0; format ascii; class dictionary; object effects; }\n"
      "fluid { type fracturePressure; fracture crack; pressure " +
      pressure + "; }\n";
  if (!stress.empty()) text += "inSitu { type initialStress; stress " + stress + "; }\n";
  writeText(c.dir() / "constant/effects", text);
}

/// Rows of the table in a given state.
int countState(const Table& t, const std::string& state) {
  return static_cast<int>(std::count(t.state.begin(), t.state.end(), state));
}

/// The table's text without its `opening` column (the column before the state).
std::string withoutOpening(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# s ", 0) == 0) {
      const auto at = line.find(" opening state");
      REQUIRE(at != std::string::npos);
      line = line.substr(0, at) + " state";
    } else if (!line.empty() && line[0] != '#') {
      const auto last = line.rfind(' ');
      const auto before = line.rfind(' ', last - 1);
      REQUIRE(before != std::string::npos);
      line = line.substr(0, before) + line.substr(last);
    }
    out << line << "\n";
  }
  return out.str();
}

}  // namespace

TEST_CASE("Sneddon's pressurised crack, P1 and P2: the opening converges to the exact one",
          "[regression][opening]") {
  // Exact: g = 4(1 − ν²) p/E √(a² − x²), τ = 0 and σ_n = −p on the open faces. Measured rel.
  // L² errors (sneddonError.py, 6 Gauss points per element):
  //   h = a/16, a/32, a/64   P1: 0.0493, 0.0273, 0.0161   P2: 0.0150, 0.00767, 0.00410
  // The √ at the tips bounds the L² order near 1 for both orders (observed 0.76–0.9: the
  // discrete tip row pins g = 0 there); P2 is 3–4 times more accurate on the same mesh.
  // Asserted: within 10 % of the measured values (the meshes are reproduced exactly by
  // gmsh, meshesReproduce.sh), a factor ≥ 1.5 per halving of h, P2 ≥ 3× better than P1.
  const char* h[] = {"0.0625", "0.03125", "0.015625"};
  const double limit[2][3] = {{0.0543, 0.0301, 0.0178}, {0.0165, 0.00845, 0.00451}};
  double error[2][3];
  for (int order = 1; order <= 2; ++order)
    for (int m = 0; m < 3; ++m) {
      Case c("sneddonCrack", "opening/sneddon-P" + std::to_string(order) + "-" + h[m]);
      if (m > 0) c.remesh(std::string("-h ") + h[m]);
      if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
      REQUIRE(c.solve() == 0);
      INFO(c.log());
      // The opening's start g = 0 has σ'_n = p > 0 everywhere: Newton finds the open set at
      // once and solves the linear problem on it.
      CHECK_THAT(c.log(), Catch::Contains("  iterations 1  backSubstitutions 2 "));
      // τ = 0 and σ_n = −p on the open faces: the open rows of Newton's linear solve, to
      // round-off (measured ≤ 1.5e-13 p).
      const std::string out = sneddonError(c, "--maxTraction 1e-10");
      const Table t = c.namedTable("1", "crack");
      const int nodes = static_cast<int>(t.rows.size());
      CHECK(countState(t, "tip") == 2);
      CHECK(countState(t, "open") == nodes - 2);
      CHECK(sneddonValue(out, "minOpening") >= 0);
      error[order - 1][m] = sneddonValue(out, "relL2Error");
      CHECK(error[order - 1][m] <= limit[order - 1][m]);
    }
  for (int order = 0; order < 2; ++order)
    for (int m = 0; m + 1 < 3; ++m) CHECK(error[order][m] / error[order][m + 1] >= 1.5);
  for (int m = 0; m < 3; ++m) CHECK(error[0][m] >= 3 * error[1][m]);
}

TEST_CASE("Sneddon: the held outer square (half-width 50a) costs under 0.1 % of the opening",
          "[regression][opening]") {
  // The displacement of the pressurised crack decays like a²/r: holding the sides at 50a
  // lowers the opening by O((a/L)²). Measured (P2, h = a/32): the centre opening 3.73725e-4
  // (L = 50a) against 3.73966e-4 (100a) and 3.72937e-4 (25a): 0.064 % and 0.21 % below the
  // 100a value, falling like (a/L)^1.7. The exact value is 3.75e-4: the discretisation
  // error (0.3 % at the centre) dominates at 50a.
  double centre[2];
  const char* R[] = {"50", "100"};
  for (int i = 0; i < 2; ++i) {
    Case c("sneddonCrack", std::string("opening/sneddon-R") + R[i]);
    c.remesh(std::string("-h 0.03125 -R ") + R[i] + (i ? " -dMax 60" : ""));
    c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
    REQUIRE(c.solve() == 0);
    const Table t = c.namedTable("1", "crack");
    double best = 1e300;
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      if (std::abs(t.at(r, "x")) < best) {
        best = std::abs(t.at(r, "x"));
        centre[i] = t.at(r, "opening");
      }
    REQUIRE(best < 1e-9);  // the centre node (gmsh places it to ~1e-11)
  }
  const double deficit = (centre[1] - centre[0]) / centre[1];
  CHECK(deficit > 0);
  CHECK(deficit < 1e-3);
}

TEST_CASE("Net pressure: the crack opens only when p > |sigma_n_inf|, by p + sigma_n_inf",
          "[regression][opening]") {
  // Remote stress σ_yy = −S = −0.5 MPa on the crack's plane and a shear σ_xy = τ∞ = 0.2 MPa.
  const std::string stress = "(-0.3e6 -0.5e6 0.2e6)";
  // Below: p = 0.3 MPa, σ'_n = −0.2 MPa, ρ = 0.12 MPa < τ∞: the crack slides closed. The
  // unilateral run is the bilateral one digit for digit (every column but the opening, the
  // solver status line included), and every opening is 0.
  Case bilateral("sneddonCrack", "opening/net-bilateral");
  setEffects(bilateral, "0.3e6", stress);
  bilateral.edit("constant/fractureProperties", "contact +unilateral;", "contact bilateral;");
  REQUIRE(bilateral.solve() == 0);
  Case closed("sneddonCrack", "opening/net-closed");
  setEffects(closed, "0.3e6", stress);
  REQUIRE(closed.solve() == 0);
  {
    const Table t = closed.namedTable("1", "crack");
    CHECK(countState(t, "slip") == static_cast<int>(t.rows.size()) - 2);
    for (std::size_t r = 0; r < t.rows.size(); ++r) CHECK(t.at(r, "opening") == 0);
    const std::string a = readText(bilateral.dir() / "1/fractures/crack.dat");
    const std::string b = readText(closed.dir() / "1/fractures/crack.dat");
    CHECK(a.find("opening") == std::string::npos);
    CHECK(withoutOpening(b) == a);
  }
  // Above, without the shear: the whole crack opens by the net pressure p − S, g = (p − S)/p'
  // g' of a pure pressure p' run on the same mesh (linearity: to round-off).
  Case pure("sneddonCrack", "opening/net-pure");
  REQUIRE(pure.solve() == 0);
  const Table t0 = pure.namedTable("1", "crack");
  for (const double p : {0.6e6, 0.8e6}) {
    Case c("sneddonCrack", "opening/net-open-" + std::to_string(static_cast<int>(p)));
    setEffects(c, std::to_string(p), "(-0.3e6 -0.5e6 0)");
    REQUIRE(c.solve() == 0);
    const Table t = c.namedTable("1", "crack");
    REQUIRE(t.rows.size() == t0.rows.size());
    CHECK(countState(t, "open") == static_cast<int>(t.rows.size()) - 2);
    const double scale = (p - 0.5e6) / 1e6;
    double gmax = 0, differ = 0;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      gmax = std::max(gmax, t.at(r, "opening"));
      differ = std::max(differ, std::abs(t.at(r, "opening") - scale * t0.at(r, "opening")));
      // σ_n = −p on the open faces is the total stress, whatever the remote one.
      if (t.state[r] == "open") CHECK(std::abs(t.at(r, "sigmaN") + p) <= 1e-9 * p);
    }
    REQUIRE(gmax > 0);
    CHECK(differ <= 1e-10 * gmax);  // measured ≤ 1e-15 relative
  }
  // With the shear too: the open faces carry no shear, so they slide as the mode II crack,
  // |s| = 4(1 − ν²) τ∞/E √(a² − x²), beside Sneddon's opening of p − S. At h = a/16 P1
  // measured: opening 0.0510 (0.0493 without the shear: the discrete slip–opening coupling
  // of an unsymmetric mesh), slip 0.0705; asserted within 10 %.
  Case sheared("sneddonCrack", "opening/net-open-sheared");
  setEffects(sheared, "0.8e6", stress);
  REQUIRE(sheared.solve() == 0);
  const std::string out =
      sneddonError(sheared, "-p 0.8e6 -sigmaN=-0.5e6 -tau 0.2e6 --maxTraction 1e-10");
  CHECK(sneddonValue(out, "openNodes") == 31);
  CHECK(sneddonValue(out, "relL2Error") <= 0.056);
  CHECK(sneddonValue(out, "slipRelL2Error") <= 0.078);
}
