// Effects switched on per case (constant/effects) against known answers, and the work a case
// does not call for being skipped (issue: simulate only the effects a scene calls for).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "CaseRunner.hpp"
#include "friction/case/FrictionCase.hpp"

using namespace friction::regression;

namespace {

const char* kEffectsHeader =
    "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object "
    "effects;\n}\n";

double maxAbsSlip(const std::vector<Row>& rows) {
  double m = 0;
  for (const Row& r : rows) m = std::max(m, std::abs(r.slip));
  return m;
}

// Relative L²(Γ) error of the inclined crack's slip against the analytic profile with
// effective shear τ_eff (plane strain, r = 1.0033 for the finite square).
double crackError(const std::vector<Row>& rows, double tauEff) {
  const double a = 0.05, E = 10e9, nu = 0.25;
  const auto w = trapezoid(rows);
  double num = 0, den = 0;
  const Row &f = rows.front(), &l = rows.back();
  const double tx = l.x - f.x, ty = l.y - f.y, len = std::hypot(tx, ty);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double xi = ((rows[i].x - 0.5) * tx + (rows[i].y - 0.5) * ty) / len;
    const double ana =
        1.0033 * 4 * (1 - nu * nu) / E * tauEff * std::sqrt(std::max(a * a - xi * xi, 0.0));
    num += w[i] * std::pow(std::abs(rows[i].slip) - ana, 2);
    den += w[i] * ana * ana;
  }
  return std::sqrt(num / den);
}

bool sameTables(const Case& a, const Case& b, const std::string& time, const std::string& f) {
  return readText(a.dir() / time / "fractures" / (f + ".dat")) ==
         readText(b.dir() / time / "fractures" / (f + ".dat"));
}

}  // namespace

TEST_CASE("gravity column: sigma_yy = -rho g (H - y), with no fracture and no control loop",
          "[regression][effects]") {
  Case c("paperBenchmark", "effects-gravity");
  // The unit square without its fracture: bottom fixed, sides on rollers, top free.
  c.edit("system/meshDict", "fractures +\\(fracture\\);", "fractures ();");
  c.edit("constant/fractureProperties", "fracture\\s*\\{[^}]*\\}", "");
  c.edit("0/D", "top\\s*\\{[^}]*\\}", "top { type free; }");
  c.edit("0/D", "left +\\{ type free; \\}",
         "left { type fixedDisplacement; components (x); value (0 0); }");
  c.edit("0/D", "right +\\{ type free; \\}",
         "right { type fixedDisplacement; components (x); value (0 0); }");
  c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
  writeText(
      c.dir() / "constant" / "effects",
      std::string(kEffectsHeader) + "gravity { type bodyForce; density 2000; g (0 -9.81); }\n");
  // The utility splits nothing; then the library runs the case so the stress can be probed.
  REQUIRE(run("'" + (fs::path(FRICTION_BIN_DIR) / "splitFractureNodes").string() + "' -case '" +
                  c.dir().string() + "'",
              c.dir() / "log.splitFractureNodes") == 0);
  friction::FrictionCase fc(c.dir().string());
  std::ostringstream log;
  REQUIRE(fc.setup(log) == friction::FactorStatus::ok);
  const auto results = fc.run(log);
  INFO(log.str());
  CHECK_THAT(log.str(), Catch::Contains("Effect gravity: bodyForce"));
  CHECK_THAT(log.str(), Catch::Contains("no fracture: no split stiffness, no control loop"));
  CHECK(fc.system().numAssemblies() == 1);
  CHECK(fc.system().size() == 0);
  CHECK(fc.system().factorization().numSolves() == 1);  // one step, one solve, no iteration
  REQUIRE(results.size() == 1);
  CHECK(results[0].report.iterations == 0);

  // P2 holds the exact (quadratic) displacement of the column: the stress is exact.
  const auto& asmb = fc.system().splitAssembler();
  const Eigen::VectorXd u = fc.system().lastSplitDisplacement();
  const double rhoG = 2000 * 9.81;
  for (friction::Index cell = 0; cell < fc.splitMesh().mesh.numCells(); cell += 97) {
    const auto t = fc.splitMesh().mesh.cell(cell);
    const friction::Vector2 x =
        (fc.splitMesh().mesh.points[t[0]].head<2>() + fc.splitMesh().mesh.points[t[1]].head<2>() +
         fc.splitMesh().mesh.points[t[2]].head<2>()) /
        3;
    const Eigen::Matrix2d s = asmb.stress(u, cell, x);
    // Round-off of a 10⁴-dof solve of stresses of size ρg ≈ 2·10⁴ Pa.
    CHECK(s(1, 1) == Approx(-rhoG * (1 - x.y())).margin(1e-6 * rhoG));
    CHECK(s(0, 1) == Approx(0).margin(1e-6 * rhoG));
  }
}

TEST_CASE("initial stress alone reproduces the boundary-loaded inclined crack",
          "[regression][effects]") {
  Case loaded("inclinedCrack", "effects-crack-loaded");
  REQUIRE(loaded.solve() == 0);
  Case insitu("inclinedCrack", "effects-crack-insitu");
  insitu.edit("0/D", "top +\\{[^}]*\\}", "top { type free; }");
  writeText(insitu.dir() / "constant" / "effects",
            std::string(kEffectsHeader) + "inSitu { type initialStress; stress (0 -1e7 0); }\n");
  const int rc = insitu.solve();
  INFO(insitu.log());
  REQUIRE(rc == 0);
  CHECK_THAT(insitu.log(), Catch::Contains("Effect inSitu: initialStress"));
  const auto a = loaded.table("1", "crack"), b = insitu.table("1", "crack");
  REQUIRE(a.size() == b.size());
  // The uniform far field is exact in P1 either way; the crack's perturbation problem is the
  // same, so only round-off separates the two (1e-8 of the slip).
  for (std::size_t i = 0; i < a.size(); ++i)
    CHECK(std::abs(a[i].slip - b[i].slip) <= 1e-8 * maxAbsSlip(a));
  CHECK(crackError(b, 4.3301e6 - 0.4 * 2.5e6) <= 2.5 / 16);
}

TEST_CASE("an in-situ stress with its own traction on a face again is noted as a double load",
          "[regression][effects]") {
  const std::string effects =
      std::string(kEffectsHeader) + "inSitu { type initialStress; stress (0 -1e7 0); }\n";
  // The top keeps its pressure table ((0 0) (1 1e7)): at endTime it is σ⁰·n, the same load.
  Case twice("inclinedCrack", "effects-crack-twice");
  writeText(twice.dir() / "constant" / "effects", effects);
  REQUIRE(twice.solve() == 0);
  CHECK_THAT(twice.log(),
             Catch::Contains("Note: patch 'top' applies the in-situ traction σ⁰·n (initialStress) "
                             "again"));
  // The same traction written as a traction, and the other patches: only the top is named.
  Case traction("inclinedCrack", "effects-crack-twice-traction");
  traction.edit("0/D", "top +\\{[^}]*\\}", "top { type traction; traction (0 -1e7); }");
  writeText(traction.dir() / "constant" / "effects", effects);
  REQUIRE(traction.solve() == 0);
  CHECK_THAT(traction.log(), Catch::Contains("Note: patch 'top' applies the in-situ traction"));
  CHECK_THAT(traction.log(), !Catch::Contains("Note: patch 'right'"));
  // Half of it is a load of its own (a change), not a repeat: no note; nor without σ⁰.
  Case change("inclinedCrack", "effects-crack-change");
  change.edit("0/D", "top +\\{[^}]*\\}", "top { type traction; traction (0 -5e6); }");
  writeText(change.dir() / "constant" / "effects", effects);
  REQUIRE(change.solve() == 0);
  CHECK_THAT(change.log(), !Catch::Contains("Note: patch"));
  Case plain("inclinedCrack", "effects-crack-plain");
  REQUIRE(plain.solve() == 0);
  CHECK_THAT(plain.log(), !Catch::Contains("Note: patch"));
}

TEST_CASE("a uniform fracture pressure acts through the effective normal stress",
          "[regression][effects]") {
  Case c("inclinedCrack", "effects-crack-pressure");
  writeText(c.dir() / "constant" / "effects",
            std::string(kEffectsHeader) +
                "pore { type fracturePressure; fracture crack; pressure 1e6; }\n");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  const auto rows = c.table("1", "crack");
  // Analytic slip with σ_n replaced by σ_n + p: τ_eff = |τ| − μ_f(|σ_n| − p). The same
  // tolerance as the analytic test at h = a/16; and the error must be of the same size as
  // without pressure (0.062), which a wrong effective stress (error ~0.12) would exceed.
  const double err = crackError(rows, 4.3301e6 - 0.4 * (2.5e6 - 1e6));
  WARN("inclined crack with p = 1 MPa: relative L2 slip error " << err);
  CHECK(err <= 0.08);
  int slipping = 0;
  for (const Row& r : rows)
    if (r.state == "slip") {
      ++slipping;
      CHECK(r.ST == Approx(0.4).epsilon(1e-9));  // ST on σ_n + p
    }
  CHECK(slipping > 0);  // the crack slips under this load (see the slip error above)
}

TEST_CASE("cohesion shifts the threshold exactly", "[regression][effects]") {
  SECTION("coulombCohesion with mu_f = 0 is Tresca, bit for bit") {
    Case a("paperBenchmark", "effects-cohesion-mu0");
    a.edit("constant/fractureProperties", "law +coulomb;\\s*frictionCoefficient 0.2;",
           "law coulombCohesion; frictionCoefficient 0; cohesion 0.01;");
    Case b("paperBenchmark", "effects-tresca");
    b.edit("constant/fractureProperties", "law +coulomb;\\s*frictionCoefficient 0.2;",
           "law tresca; threshold 0.01;");
    REQUIRE(a.solve() == 0);
    REQUIRE(b.solve() == 0);
    CHECK(sameTables(a, b, "1", "fracture"));
  }
  SECTION("at slipping nodes |tau| = c - mu_f sigma_n") {
    Case c("paperBenchmark", "effects-cohesion");
    c.edit("constant/fractureProperties", "law +coulomb;\\s*frictionCoefficient 0.2;",
           "law coulombCohesion; frictionCoefficient 0.2; cohesion 0.001;");
    REQUIRE(c.solve() == 0);
    int slipping = 0;
    for (const Row& r : c.table("1", "fracture")) {
      if (r.state != "slip") continue;
      ++slipping;
      // Newton converges to ‖D‖ ≤ 1e-10 ‖Σ‖: the law holds to that relative level.
      CHECK(std::abs(r.tau) == Approx(0.001 - 0.2 * r.sigmaN).epsilon(1e-8));
    }
    CHECK(slipping > 0);
  }
}

TEST_CASE("an effect switched off reproduces the run without it bit for bit",
          "[regression][effects]") {
  Case base("inclinedCrack", "effects-base");
  REQUIRE(base.solve() == 0);
  Case off("inclinedCrack", "effects-off");
  writeText(off.dir() / "constant" / "effects",
            std::string(kEffectsHeader) +
                "pore { type fracturePressure; fracture crack; pressure 5e6; active no; }\n"
                "gravity { type bodyForce; density 2500; g (0 -9.81); active no; }\n");
  REQUIRE(off.solve() == 0);
  CHECK_THAT(off.log(), Catch::Contains("Effect pore: switched off"));
  CHECK(sameTables(base, off, "1", "crack"));
  CHECK(readText(base.dir() / "1" / "D") == readText(off.dir() / "1" / "D"));
}

TEST_CASE("steps whose loads did not change reuse the previous solution", "[regression][effects]") {
  Case c("paperBenchmark", "effects-unchanged");
  c.edit("0/D", "\\(1 \\(-0.02 -0.025\\)\\)", "(0.5 (-0.02 -0.025))");
  c.edit("system/controlDict", "deltaT +1;", "deltaT 0.25;");
  REQUIRE(c.solve() == 0);
  const std::string log = c.log();
  // Steps 0.75 and 1 have the loads of 0.5: no solve, no iteration.
  std::istringstream in(log);
  int reused = 0;
  for (std::string line; std::getline(in, line);)
    if (line.find("previous solution reused") != std::string::npos) {
      ++reused;
      CHECK_THAT(line, Catch::Contains("iterations 0 ") && Catch::Contains("backSubstitutions 0 "));
    }
  CHECK(reused == 2);
  const auto a = c.table("0.5", "fracture"), b = c.table("1", "fracture");
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].slip == b[i].slip);
    CHECK(b[i].slipIncrement == 0.0);
  }
  // And a fracture that sticks at its trial state stops after that one primal solve.
  Case stuck("paperBenchmark", "effects-stuck");
  stuck.edit("constant/fractureProperties", "frictionCoefficient 0.2;", "frictionCoefficient 2;");
  REQUIRE(stuck.solve() == 0);
  CHECK_THAT(stuck.log(), Catch::Contains("iterations 0 "));
}

TEST_CASE("steps whose fault pressure did not change reuse the previous solution",
          "[regression][effects]") {
  // The inclined crack's load ramped to t = 0.5 and then held, steps of 0.25. A faultPressure
  // whose field is constant in time (`initial` alone) leaves the steps after 0.5 nothing new:
  // 0.75 and 1 reuse 0.5's answer. One whose change goes on to t = 0.75 makes 0.75 a new
  // step (solved) and only 1 a reused one: the pressure is part of what is compared.
  const auto run = [](const std::string& label, const std::string& fluid) {
    auto c = std::make_unique<Case>("inclinedCrack", label);
    c->edit("0/D", "\\(1 1e7\\)", "(0.5 1e7)");
    c->edit("system/controlDict", "deltaT +1;", "deltaT 0.25;");
    writeText(c->dir() / "constant" / "effects",
              std::string(kEffectsHeader) + "fluid { type faultPressure; fracture crack; " + fluid +
                  " }\n");
    const int rc = c->solve();
    INFO(c->log());
    REQUIRE(rc == 0);
    return c;
  };
  // The times whose step reused the previous answer, from the log's step lines.
  const auto reusedTimes = [](const Case& c) {
    std::vector<std::string> times;
    std::istringstream in(c.log());
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("Time = ", 0) != 0) continue;
      INFO(line);
      CHECK_THAT(line, Catch::Contains(" converged"));
      if (line.find("loads unchanged: previous solution reused") == std::string::npos) continue;
      CHECK_THAT(line, Catch::Contains("iterations 0 ") && Catch::Contains("backSubstitutions 0 "));
      times.push_back(line.substr(7, line.find(' ', 7) - 7));
    }
    return times;
  };
  // The columns a reused step keeps: every one but slipIncrement (0 after a reused step).
  const auto sameState = [](const Case& c, const std::string& a, const std::string& b) {
    const Table x = c.namedTable(a, "crack"), y = c.namedTable(b, "crack");
    REQUIRE(x.rows.size() == y.rows.size());
    REQUIRE(x.columns == y.columns);
    int slipping = 0;
    for (std::size_t i = 0; i < x.rows.size(); ++i) {
      CHECK(x.state[i] == y.state[i]);
      slipping += x.state[i] == "slip";
      for (const char* col : {"slip", "sigmaN", "tau", "pressure", "sigmaNEffective"}) {
        const double u = x.at(i, col), v = y.at(i, col);
        CHECK(((std::isnan(u) && std::isnan(v)) || u == v));
      }
      CHECK(y.at(i, "slipIncrement") == 0.0);
    }
    CHECK(slipping > 0);  // the crack slips: the reused answer is not a trivial one
  };

  const auto constant = run("effects-constant-pressure", "initial 1e6;");
  CHECK(reusedTimes(*constant) == std::vector<std::string>{"0.75", "1"});
  sameState(*constant, "0.5", "1");
  CHECK(constant->namedTable("1", "crack").at(1, "pressure") == 1e6);

  const auto ending =
      run("effects-ending-pressure", "initial 1e6; change table ((0 0) (0.75 5e5));");
  CHECK(reusedTimes(*ending) == std::vector<std::string>{"1"});
  sameState(*ending, "0.75", "1");
  CHECK(ending->namedTable("1", "crack").at(1, "pressure") == 1.5e6);
  // 0.75 had a new pressure, so a new answer: the crack slipped further.
  const Table before = ending->namedTable("0.5", "crack"),
              after = ending->namedTable("0.75", "crack");
  double grew = 0;
  for (std::size_t i = 0; i < after.rows.size(); ++i)
    grew = std::max(grew, std::abs(after.at(i, "slip")) - std::abs(before.at(i, "slip")));
  CHECK(grew > 0);
}
