// Bad input, one mistake at a time, through the real binaries (splitFractureNodes and
// frictionSolver) on copies of the cases: every user-facing error path must exit non-zero,
// name the file (and the line, where there is one), the key or item, and what was expected,
// and leave the case folder exactly as it was. The line
// numbers are computed from the edited file, never written down, so a reformatted case
// cannot make a check pass by accident or fail for no reason.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "CaseRunner.hpp"

using namespace friction::regression;

namespace {

/// Every file and folder under dir (relative paths), except the logs a run writes.
std::set<std::string> snapshot(const fs::path& dir) {
  std::set<std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (rel.rfind("log.", 0) == 0) continue;
    s.insert(rel);
  }
  return s;
}

/// 1-based number of the first line of file containing text (0 if none).
int lineOf(const fs::path& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(text) != std::string::npos) return n;
  return 0;
}

/// 1-based number of the first line of file that is text, blanks around it aside (0 if none):
/// for a bare key such as a dictionary's name, which other lines may contain.
int lineIs(const fs::path& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto first = line.find_first_not_of(" \t");
    const auto last = line.find_last_not_of(" \t\r");
    if (first != std::string::npos && line.substr(first, last - first + 1) == text) return n;
  }
  return 0;
}

std::string bin(const std::string& tool) { return (fs::path(FRICTION_BIN_DIR) / tool).string(); }

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// Split the case; the scenario's mistake is elsewhere, so this must work.
void split(const Case& c) {
  const int rc = run(bin("splitFractureNodes") + " -case " + quoted(c.dir()),
                     c.dir() / "log.splitFractureNodes");
  INFO(readText(c.dir() / "log.splitFractureNodes"));
  REQUIRE(rc == 0);
}

/// Run `tool args` in the case, expect exit status rc, every text of `expected` in its output
/// and no file created, removed or renamed in the case (logs aside). Returns the output.
std::string expectFailure(const Case& c, const std::string& tool, const std::string& args, int rc,
                          const std::vector<std::string>& expected) {
  const auto before = snapshot(c.dir());
  const fs::path log = c.dir() / ("log." + tool);
  const int status = run(bin(tool) + " " + args, log);
  const std::string out = readText(log);
  INFO(out);
  CHECK(status == rc);
  for (const std::string& e : expected) CHECK_THAT(out, Catch::Contains(e));
  CHECK(snapshot(c.dir()) == before);
  return out;
}

/// The usual shape: frictionSolver on a split case must fail with exit status 1.
void solverFails(const Case& c, const std::vector<std::string>& expected) {
  expectFailure(c, "frictionSolver", "-case " + quoted(c.dir()), 1, expected);
}

std::string at(const std::string& file, int line) {
  REQUIRE(line > 0);  // the edit's text must be found, or the line check checks nothing
  return file + ":" + std::to_string(line) + ":";
}

}  // namespace

TEST_CASE("bad command lines and case folders are refused with exit status 1 or 2",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-commandLine");

  SECTION("unknown option of frictionSolver") {
    split(c);
    expectFailure(c, "frictionSolver", "-case " + quoted(c.dir()) + " -bogusOption", 2,
                  {"bogusOption", "-help"});
  }
  SECTION("unknown option of splitFractureNodes") {
    expectFailure(c, "splitFractureNodes", "-case " + quoted(c.dir()) + " -bogusOption", 2,
                  {"bogusOption", "-help"});
  }
  SECTION("-case without its value") { expectFailure(c, "frictionSolver", "-case", 2, {"case"}); }
  SECTION("frictionSolver on a case folder that does not exist") {
    const fs::path missing = c.dir() / "noSuchCase";
    expectFailure(c, "frictionSolver", "-case " + quoted(missing), 1,
                  {"noSuchCase", "case folder does not exist", "-case"});
    CHECK_FALSE(fs::exists(missing));
  }
  SECTION("splitFractureNodes on a case folder that does not exist") {
    const fs::path missing = c.dir() / "noSuchCase";
    expectFailure(c, "splitFractureNodes", "-case " + quoted(missing), 1,
                  {"noSuchCase", "case folder does not exist", "-case"});
    CHECK_FALSE(fs::exists(missing));
  }
  SECTION("frictionSolver with -case naming a file") {
    split(c);
    expectFailure(c, "frictionSolver", "-case " + quoted(c.dir() / "system" / "controlDict"), 1,
                  {"system/controlDict", "is not a folder"});
  }
  SECTION("splitFractureNodes with -case naming a file") {
    expectFailure(c, "splitFractureNodes", "-case " + quoted(c.dir() / "system" / "meshDict"), 1,
                  {"system/meshDict", "is not a folder"});
  }
}

TEST_CASE("a missing dictionary or split mesh is named with what the case needs",
          "[regression][errors]") {
  for (const char* file : {"system/controlDict", "system/frictionSolution",
                           "constant/mechanicalProperties", "constant/fractureProperties", "0/D"}) {
    DYNAMIC_SECTION("missing " << file) {
      Case c("paperBenchmark", std::string("bad-missing-") + fs::path(file).filename().string());
      split(c);
      fs::remove(c.dir() / file);
      solverFails(c, {file, "cannot open"});
    }
  }
  SECTION("no constant/splitMesh") {
    Case c("paperBenchmark", "bad-missing-splitMesh");
    solverFails(c, {"constant/splitMesh", "run splitFractureNodes"});
  }
  SECTION("system/meshDict missing") {
    Case c("paperBenchmark", "bad-missing-meshDict");
    fs::remove(c.dir() / "system/meshDict");
    expectFailure(c, "splitFractureNodes", "-case " + quoted(c.dir()), 1,
                  {"system/meshDict", "cannot open"});
  }
}

TEST_CASE("bad meshDict entries name file, line, key and what was expected",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-meshDict");
  const fs::path dict = c.dir() / "system/meshDict";
  const std::string args = "-case " + quoted(c.dir());

  SECTION("mesh file that does not exist") {
    c.edit("system/meshDict", "square\\.msh", "squar.msh");
    expectFailure(
        c, "splitFractureNodes", args, 1,
        {at("system/meshDict", lineOf(dict, "squar.msh")), "mesh", "squar.msh", "does not exist"});
  }
  SECTION("patch label absent from the mesh") {
    c.edit("system/meshDict", "left +4;", "left 44;");
    expectFailure(c, "splitFractureNodes", args, 1,
                  {at("system/meshDict", lineOf(dict, "left 44;")), "left", "44"});
  }
  SECTION("negative patch label") {
    c.edit("system/meshDict", "left +4;", "left -4;");
    expectFailure(c, "splitFractureNodes", args, 1,
                  {at("system/meshDict", lineOf(dict, "left -4;")), "left", ">= 0"});
  }
  SECTION("a fracture listed twice") {
    c.edit("system/meshDict", "\\(fracture\\)", "(fracture fracture)");
    expectFailure(
        c, "splitFractureNodes", args, 1,
        {at("system/meshDict", lineOf(dict, "(fracture fracture)")), "fractures", "listed twice"});
  }
}

TEST_CASE("bad controlDict entries name file, line, key and what was expected",
          "[regression][errors]") {
  struct Bad {
    const char* label;
    const char* pattern;
    const char* replacement;
    const char* lineText;  // text of the edited line, to find its number
    std::vector<std::string> expected;
  };
  const std::vector<Bad> cases = {
      {"endBeforeStart", "endTime +1;", "endTime 0;", "endTime 0;", {"endTime", "after startTime"}},
      {"zeroDeltaT", "deltaT +1;", "deltaT 0;", "deltaT 0;", {"deltaT", "> 0"}},
      {"fractionalInterval",
       "writeInterval +1;",
       "writeInterval 1.5;",
       "writeInterval 1.5;",
       {"writeInterval", "whole number"}},
      {"unknownStopAt",
       "stopAt +endTime;",
       "stopAt end;",
       "stopAt end;",
       {"stopAt", "endTime, writeNow, noWriteNow, nextWrite"}},
      {"unknownStartFrom",
       "startFrom +startTime;",
       "startFrom latest;",
       "startFrom latest;",
       {"startFrom", "startTime, latestTime"}},
      {"unknownWriteControl",
       "writeControl +timeStep;",
       "writeControl clockTime;",
       "writeControl clockTime;",
       {"writeControl", "timeStep, runTime"}},
      {"precisionTooLarge",
       "writePrecision +10;",
       "writePrecision 40;",
       "writePrecision 40;",
       {"writePrecision", "40", "17"}},
      {"endTimeNotANumber", "endTime +1;", "endTime one;", "endTime one;", {"endTime", "one"}},
      {"typoKey",
       "deltaT +1;",
       "deltaT 1; writeVtk no;",
       "writeVtk",
       {"writeVtk", "did you mean 'writeVTK'"}},
  };
  for (const Bad& b : cases) {
    DYNAMIC_SECTION(b.label) {
      Case c("paperBenchmark", std::string("bad-controlDict-") + b.label);
      split(c);
      c.edit("system/controlDict", b.pattern, b.replacement);
      std::vector<std::string> expected = b.expected;
      expected.push_back(
          at("system/controlDict", lineOf(c.dir() / "system/controlDict", b.lineText)));
      solverFails(c, expected);
    }
  }
}

TEST_CASE("bad frictionSolution, mechanicalProperties and fractureProperties entries are named",
          "[regression][errors]") {
  struct Bad {
    const char* label;
    const char* file;
    const char* pattern;
    const char* replacement;
    const char* lineText;
    std::vector<std::string> expected;
  };
  const std::vector<Bad> cases = {
      {"unknownLinearSolver",
       "system/frictionSolution",
       "linearSolver +cholmod;",
       "linearSolver lu;",
       "linearSolver lu;",
       {"linearSolver", "lu", "cholmod, simplicialLDLT"}},
      {"unknownOrdering",
       "system/frictionSolution",
       "linearSolver +cholmod;",
       "linearSolver cholmod;\nordering colamd;",
       "ordering colamd;",
       {"ordering", "colamd", "auto, amd, metis, nesdis, cholmodDefault"}},
      {"orderingForSimplicialLDLT",
       "system/frictionSolution",
       "linearSolver +cholmod;",
       "linearSolver simplicialLDLT;\nordering metis;",
       "ordering metis;",
       {"key 'ordering'", "'simplicialLDLT' has its own ordering", "linearSolver cholmod"}},
      {"lowRankForCholmod",
       "system/frictionSolution",
       "linearSolver +cholmod;",
       "linearSolver cholmod;\nlowRank 1e-8;",
       "lowRank 1e-8;",
       {"key 'lowRank'", "'cholmod' has no low-rank or out-of-core factor",
        "needs 'linearSolver mumps'"}},
      {"outOfCoreForSimplicialLDLT",
       "system/frictionSolution",
       "linearSolver +cholmod;",
       "linearSolver simplicialLDLT;\noutOfCore yes;",
       "outOfCore yes;",
       {"key 'outOfCore'", "'simplicialLDLT' has no low-rank or out-of-core factor",
        "needs 'linearSolver mumps'"}},
      {"unknownGradient",
       "system/frictionSolution",
       "gradient +exact;",
       "gradient adjoint;",
       "gradient adjoint;",
       {"gradient", "adjoint", "exact, frozenRho"}},
      {"negativeGamma",
       "system/frictionSolution",
       "gamma +2;",
       "gamma -2;",
       "gamma -2;",
       {"gamma", "> 0"}},
      {"negativeZeta",
       "system/frictionSolution",
       "zeta +0;",
       "zeta -1;",
       "zeta -1;",
       {"zeta", ">= 0"}},
      {"unknownStopOn",
       "system/frictionSolution",
       "maxIterations +100;",
       "maxIterations 100; stopOn slip;",
       "stopOn slip;",
       {"stopOn", "residual, step"}},
      {"zeroTolerance",
       "system/frictionSolution",
       "tolerance +1e-10;",
       "tolerance 0;",
       "tolerance 0;",
       {"tolerance", "> 0"}},
      {"negativeMaxIterations",
       "system/frictionSolution",
       "maxIterations +100;",
       "maxIterations -1;",
       "maxIterations -1;",
       {"maxIterations", "-1"}},
      {"armijoCOutOfRange",
       "system/frictionSolution",
       "type +semismoothNewton;",
       "type armijo; armijoC 2;",
       "armijoC 2;",
       {"armijoC", "(0, 1)"}},
      {"negativeMu", "constant/mechanicalProperties", "mu +1;", "mu -1;", "mu -1;", {"mu", "> 0"}},
      {"negativeBulkModulus",
       "constant/mechanicalProperties",
       "lambda +1;",
       "lambda -1;",
       "lambda -1;",
       {"lambda", "λ + 2μ/3 > 0"}},
      {"negativeFrictionCoefficient",
       "constant/fractureProperties",
       "frictionCoefficient +0.2;",
       "frictionCoefficient -0.2;",
       "frictionCoefficient -0.2;",
       {"frictionCoefficient", ">= 0"}},
      {"trescaWithoutThreshold",
       "constant/fractureProperties",
       "law +coulomb;",
       "law tresca;",
       "",
       {"missing key 'threshold'", "> 0"}},
      {"unknownFractureEntry",
       "constant/fractureProperties",
       "\\nfracture\\n",
       "\nfractur\n",
       "fractur",
       {"fractur", "did you mean 'fracture'"}},
      {"unknownContact",
       "constant/fractureProperties",
       "frictionCoefficient +0.2;",
       "frictionCoefficient 0.2;\n    contact unilatral;",
       "contact unilatral;",
       {"contact", "unilatral", "bilateral, unilateral", "did you mean 'unilateral'"}},
      {"negativeGammaNormal",
       "system/frictionSolution",
       "gamma +2;",
       "gamma 2;\n    gammaNormal -1;",
       "gammaNormal -1;",
       {"gammaNormal", "> 0"}},
      {"gammaNormalAndRelative",
       "system/frictionSolution",
       "gamma +2;",
       "gamma 2;\n    gammaNormal 1e9;\n    gammaNormalRelative 1;",
       "gammaNormalRelative 1;",
       {"keys 'gammaNormal'", "and 'gammaNormalRelative'", "not both"}},
      {"toleranceInControl",
       "system/frictionSolution",
       "gamma +2;",
       "gamma 2; tolerance 1e-8;",
       "tolerance 1e-8;",
       {"unknown key 'tolerance' in", "control; it belongs in control/optimizer"}},
      {"gammaAndGammaRelative",
       "system/frictionSolution",
       "gamma +2;",
       "gamma 2;\n    gammaRelative 1;",
       "gammaRelative 1;",
       {"keys 'gamma'", "and 'gammaRelative'",
        "are alternatives: give gamma, or gammaRelative, not both"}},
      {"EWithLambda",
       "constant/mechanicalProperties",
       "lambda +1;",
       "E 1e9;\nlambda 1;",
       "lambda 1;",
       {"keys 'E'", "and 'lambda'",
        "belong to alternatives: give E and nu, lambda and mu, or K and G, not both"}},
      // Keys and types users bring from other codes: refused with the way forward.
      {"planeStrain",
       "constant/mechanicalProperties",
       "planeStress +no;",
       "planeStrain yes;",
       "planeStrain yes;",
       {"unknown key 'planeStrain'", "plane strain is the default in 2D (planeStress no)",
        "'planeStress yes;' for a thin plate"}},
      {"youngModulus",
       "constant/mechanicalProperties",
       "lambda +1;",
       "youngModulus 1e9;",
       "youngModulus 1e9;",
       {"unknown key 'youngModulus'", "libfriction names it 'E'", "or K and G"}},
      {"cohesionUnderCoulomb",
       "constant/fractureProperties",
       "frictionCoefficient +0.2;",
       "frictionCoefficient 0.2;\n    cohesion 1e6;",
       "cohesion 1e6;",
       {"unknown key 'cohesion'", "law coulomb has no cohesion; use law coulombCohesion"}},
      {"frictionAngleField",
       "constant/fractureProperties",
       "frictionCoefficient +0.2;",
       "frictionAngle { type depth; value 30; gradient 0; }",
       "frictionAngle {",
       {"key 'frictionAngle'", "a field is given as frictionCoefficient"}},
      {"frictionAngleRange",
       "constant/fractureProperties",
       "frictionCoefficient +0.2;",
       "frictionAngle 90;",
       "frictionAngle 90;",
       {"key 'frictionAngle'", "in [0, 90)"}},
      {"roller",
       "0/D",
       "left +\\{ type free; \\}",
       "left { type roller; }",
       "left { type roller; }",
       {"unknown type 'roller'",
        "'type fixedDisplacement; components (x); value (0 0);' with the held directions"}},
      {"rollerWithoutValue",
       "0/D",
       "bottom +\\{ type fixedDisplacement; value \\(0 0\\); \\}",
       "bottom { type fixedDisplacement; components (y); }",
       "bottom { type fixedDisplacement; components (y); }",
       {"missing key 'value' in patch 'bottom'", "e.g. value (0 0)"}},
      {"slipWeakeningFrictionCoefficient",
       "constant/fractureProperties",
       "law +coulomb;",
       "law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.1; criticalSlip 1e-3;",
       "frictionCoefficient 0.2;",
       {"unknown key 'frictionCoefficient'", "law slipWeakening takes 'staticCoefficient'"}},
      {"slipWeakeningNoCriticalSlip",
       "constant/fractureProperties",
       "law +coulomb;\n +frictionCoefficient +0.2;",
       "law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.1;",
       "law slipWeakening;",
       {"criticalSlip"}},
      {"slipWeakeningStrengthens",
       "constant/fractureProperties",
       "law +coulomb;\n +frictionCoefficient +0.2;",
       "law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.3; criticalSlip 1e-3;",
       "law slipWeakening;",
       {"key 'dynamicCoefficient'", "above staticCoefficient 0.2",
        "slip-weakening needs mu_d <= mu_s"}},
      {"slipWeakeningOpening",
       "constant/fractureProperties",
       "law +coulomb;\n +frictionCoefficient +0.2;",
       "law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.1; criticalSlip 1e-3;\n"
       "    contact unilateral;",
       "contact unilateral;",
       {"key 'contact'", "law slipWeakening is not yet solved with faces that open"}},
      {"slipWeakeningArmijo",
       "system/frictionSolution",
       "type +semismoothNewton;[^\n]*",
       "type armijo;",
       "type armijo;",
       {"key 'type'", "law slipWeakening", "semismoothNewton with variant condensed",
        "(nucleation)"}},
      {"decimalComma",
       "constant/mechanicalProperties",
       "mu +1;",
       "mu 0,9;",
       "mu 0,9;",
       {"key 'mu'", "expected a number > 0, got '0,9'", "has a decimal comma: write 0.9"}},
      {"numberOverflow",
       "constant/mechanicalProperties",
       "mu +1;",
       "mu 1e400;",
       "mu 1e400;",
       {"number 1e400 is out of the range of a double"}},
      {"numberWithUnit",
       "system/controlDict",
       "deltaT +1;",
       "deltaT 1s;",
       "deltaT 1s;",
       {"key 'deltaT'", "'1s' is the number '1' followed by 's'"}},
  };
  for (const Bad& b : cases) {
    DYNAMIC_SECTION(b.label) {
      Case c("paperBenchmark", std::string("bad-settings-") + b.label);
      split(c);
      c.edit(b.file, b.pattern, b.replacement);
      if (std::string(b.label) == "slipWeakeningArmijo")
        c.edit("constant/fractureProperties", "law +coulomb;\n +frictionCoefficient +0.2;",
               "law slipWeakening; staticCoefficient 0.2; dynamicCoefficient 0.1; "
               "criticalSlip 1e-3;");
      std::vector<std::string> expected = b.expected;
      // A missing key is reported where its dictionary starts (the '{' line, which the
      // case's layout does not pin down): there only the file is checked.
      const std::string label = b.label;
      if (label == "trescaWithoutThreshold" || label == "slipWeakeningNoCriticalSlip")
        expected.push_back(std::string(b.file) + ":");
      else if (label == "unknownFractureEntry")
        expected.push_back(at(b.file, lineIs(c.dir() / b.file, b.lineText)));
      else
        expected.push_back(at(b.file, lineOf(c.dir() / b.file, b.lineText)));
      solverFails(c, expected);
    }
  }
  SECTION("a choice far from every valid one gets no 'did you mean'") {
    Case c("paperBenchmark", "bad-settings-farChoice");
    split(c);
    c.edit("system/frictionSolution", "gradient +exact;", "gradient adjoint;");
    const std::string out =
        expectFailure(c, "frictionSolver", "-case " + quoted(c.dir()), 1,
                      {at("system/frictionSolution",
                          lineOf(c.dir() / "system/frictionSolution", "gradient adjoint;")),
                       "unknown value 'adjoint' (valid values are: exact, frozenRho)"});
    CHECK_THAT(out, !Catch::Contains("did you mean"));
  }
  SECTION("the krylov variant with a fracture that opens names the key and the way out") {
    Case c("paperBenchmark", "bad-settings-krylovOpening");
    split(c);
    c.edit("constant/fractureProperties", "frictionCoefficient +0.2;",
           "frictionCoefficient 0.2;\n    contact unilateral;");
    c.edit("system/frictionSolution", "type +semismoothNewton;",
           "type semismoothNewton;\n        variant krylov;");
    solverFails(c, {at("system/frictionSolution",
                       lineOf(c.dir() / "system/frictionSolution", "variant krylov;")),
                    "key 'variant'", "contact unilateral", "variant condensed"});
  }
  SECTION("no entry for a fracture of the mesh") {
    Case c("paperBenchmark", "bad-settings-noFractureEntry");
    split(c);
    c.edit("constant/fractureProperties", "\\nfracture\\n\\{[^}]*\\}", "\n");
    solverFails(c, {"constant/fractureProperties", "fracture", "law"});
  }
}

TEST_CASE("bad boundary conditions in 0/D name file, line, patch and what was expected",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-D");
  split(c);
  const fs::path D = c.dir() / "0/D";

  SECTION("a boundary patch missing") {
    c.edit("0/D", "left +\\{ type free; \\}", "");
    solverFails(c, {"0/D:", "left", "no entry", "type free"});
  }
  SECTION("unknown boundary condition type") {
    c.edit("0/D", "left +\\{ type free; \\}", "left { type slip; }");
    solverFails(c, {at("0/D", lineOf(D, "type slip;")), "slip",
                    "fixedDisplacement, traction, pressure, free"});
  }
  SECTION("fixedDisplacement with bad components") {
    c.edit("0/D", "bottom +\\{ type fixedDisplacement; value \\(0 0\\); \\}",
           "bottom { type fixedDisplacement; value (0 0); components (z); }");
    solverFails(c, {at("0/D", lineOf(D, "components (z)")), "components", "(x), (y) or (x y)"});
  }
  SECTION("fixedDisplacement with a component twice") {
    c.edit("0/D", "bottom +\\{ type fixedDisplacement; value \\(0 0\\); \\}",
           "bottom { type fixedDisplacement; value (0 0); components (x x); }");
    solverFails(c, {at("0/D", lineOf(D, "components (x x)")), "components", "(x), (y) or (x y)"});
  }
  SECTION("fixedDisplacement value with one component") {
    c.edit("0/D", "value +\\(0 0\\);", "value (0);");
    solverFails(c, {at("0/D", lineOf(D, "value (0);")), "value", "(x y)"});
  }
  SECTION("table with decreasing times") {
    c.edit("0/D", "table \\(\\(0 \\(0 0\\)\\) \\(1 ", "table ((1 (0 0)) (0 ");
    solverFails(c, {at("0/D", lineOf(D, "table ((1 (0 0)) (0 ")), "item 1", "increase strictly"});
  }
  SECTION("table rows of the wrong size") {
    c.edit("0/D", "table \\(\\(0 \\(0 0\\)\\) \\(1 \\(-0.02 -0.025\\)\\)\\)",
           "table ((0 0) (1 -0.02))");
    solverFails(c, {at("0/D", lineOf(D, "table ((0 0) (1 -0.02))")), "value", "(x y)"});
  }
  SECTION("no boundaryField") {
    c.edit("0/D", "boundaryField", "boundaryFields");
    solverFails(c, {"0/D", "boundaryField"});
  }
}

TEST_CASE("bad constant/effects entries name file, line, key and the valid choices",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-effects");
  split(c);
  const fs::path effects = c.dir() / "constant/effects";
  auto write = [&](const std::string& body) { writeText(effects, body); };

  SECTION("unknown effect type lists the valid types") {
    write("gravity\n{\n    type gravitation;\n}\n");
    solverFails(c, {at("constant/effects", 3), "type", "gravitation",
                    "bodyForce, initialStress, fracturePressure"});
  }
  SECTION("an entry that is not a dictionary lists the valid types") {
    write("\ngravity 9.81;\n");
    solverFails(
        c, {at("constant/effects", 2), "gravity", "bodyForce, initialStress, fracturePressure"});
  }
  SECTION("fracturePressure on a fracture that does not exist suggests the nearest") {
    write("pore\n{\n    type fracturePressure;\n    fracture fractur;\n    pressure 1;\n}\n");
    solverFails(c, {at("constant/effects", 4), "fracture", "fractur", "did you mean 'fracture'"});
  }
  SECTION("fracturePressure values file with a malformed line") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "# s p\n0 1\n0.5 one\n1 3\n");
    solverFails(c, {"constant/pressure.dat:3:", "0.5 one", "s p"});
  }
  SECTION("fracturePressure values file with a decimal comma") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "# s p\n0 1\n0.5 0,9\n1 3\n");
    solverFails(c, {"constant/pressure.dat:3:", "got '0.5 0,9'", "'0,9' has a decimal comma"});
  }
  SECTION("fracturePressure values file with three columns") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "0 1\n0.5 2 7\n1 3\n");
    solverFails(
        c, {"constant/pressure.dat:2:", "expected two numbers 's p'", "got '0.5 2 7' (3 items)"});
  }
  SECTION("fracturePressure values file with nan") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "0 1\n1 nan\n");
    solverFails(c, {"constant/pressure.dat:2:", "'nan' is not a finite number"});
  }
  SECTION("fracturePressure with both pressure and values") {
    write(
        "pore { type fracturePressure; fracture fracture;\n"
        "       pressure 1; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "0 1\n1 2\n");
    solverFails(c, {at("constant/effects", 2), "keys 'pressure' (line 2) and 'values'",
                    "are alternatives: give pressure, or values, not both"});
  }
  SECTION("fracturePressure values file with decreasing arclength") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "0 1\n0.5 2\n0.25 3\n");
    solverFails(c, {"constant/pressure.dat:3:", "increasing"});
  }
  SECTION("fracturePressure values file that does not exist") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/nothing.dat\"; }\n");
    solverFails(c, {at("constant/effects", 1), "values", "nothing.dat", "cannot open"});
  }
  SECTION("fracturePressure values naming a folder") {
    write("pore { type fracturePressure; fracture fracture; values \"constant\"; }\n");
    solverFails(c, {at("constant/effects", 1), "values", "cannot open", "a file"});
  }
  SECTION("fracturePressure values file without values") {
    write("pore { type fracturePressure; fracture fracture; values \"constant/pressure.dat\"; }\n");
    writeText(c.dir() / "constant/pressure.dat", "# nothing yet\n");
    solverFails(c, {"constant/pressure.dat", "no values", "s p"});
  }
  SECTION("initialStress with two components") {
    write("inSitu\n{\n    type initialStress;\n    stress (0 -1e7);\n}\n");
    solverFails(c, {at("constant/effects", 4), "stress", "(sxx syy sxy)"});
  }
  SECTION("initialStress gradient with two components") {
    write("inSitu { type initialStress; stress (0 -1e7 0);\n gradient (0 1); }\n");
    solverFails(c, {at("constant/effects", 2), "gradient", "(dsxx/dy dsyy/dy dsxy/dy)"});
  }
  SECTION("bodyForce with a negative density") {
    write("gravity { type bodyForce; density -1; g (0 -9.81); }\n");
    solverFails(c, {at("constant/effects", 1), "density", "> 0"});
  }
  SECTION("fracturePressure table of vectors") {
    write(
        "pore { type fracturePressure; fracture fracture;\n"
        "       pressure table ((0 (0 0)) (1 (1 1))); }\n");
    solverFails(c, {at("constant/effects", 2), "pressure", "a number"});
  }
}

TEST_CASE("a damaged split mesh is refused with file, line and key", "[regression][errors]") {
  Case c("paperBenchmark", "bad-splitMesh");
  split(c);
  const fs::path splitMesh = c.dir() / "constant/splitMesh";

  SECTION("an unknown node kind") {
    c.edit("constant/splitMesh", "\\binterior\\b", "inner");
    // The error points at the key 'kind' whose list holds the bad item: the last 'kind'
    // line before it.
    int keyLine = 0;
    {
      std::ifstream in(splitMesh);
      std::string line;
      for (int n = 1; std::getline(in, line) && line.find("inner") == std::string::npos; ++n)
        if (line.find("kind") != std::string::npos) keyLine = n;
    }
    solverFails(c, {at("constant/splitMesh", keyLine), "kind", "inner",
                    "expected interior, boundary, tip, crossing, abutting or joined"});
  }
  SECTION("a triangle with a node number out of range") {
    c.edit("constant/splitMesh", "triangles\\s*\\n?\\s*(\\d+)\\s*\\n?\\s*\\(\\s*\\(\\d+",
           "triangles\n$1\n(\n(999999");
    solverFails(c, {"constant/splitMesh:", "triangles", "999999"});
  }
}

TEST_CASE("startFrom latestTime with a state of another size is refused before any step",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-restartState");
  split(c);
  {
    const fs::path log = c.dir() / "log.frictionSolver.first";
    const int rc = run(bin("frictionSolver") + " -case " + quoted(c.dir()), log);
    INFO(readText(log));
    REQUIRE(rc == 0);
  }
  REQUIRE(fs::exists(c.dir() / "1/uniform/frictionState"));
  c.edit("system/controlDict", "startFrom +startTime;", "startFrom latestTime;");
  c.edit("system/controlDict", "endTime +1;", "endTime 2;");
  // Drop the first value of the slip list (its size prefix goes too, so the list parses).
  c.edit("1/uniform/frictionState", "slip\\s*\\n?\\s*\\d*\\s*\\n?\\s*\\(\\s*[^\\s)]+", "slip\n(");
  const fs::path state = c.dir() / "1/uniform/frictionState";
  solverFails(c, {at("1/uniform/frictionState", lineOf(state, "slip")), "slip",
                  "expected one per fracture node"});
  CHECK_FALSE(fs::exists(c.dir() / "2"));
}

TEST_CASE("startFrom latestTime after contact changed is refused before any step",
          "[regression][errors][opening]") {
  // A folder written with fractures that open holds the openings; a folder written without
  // them holds none: either way the restart cannot continue the run it names.
  for (const bool nowUnilateral : {false, true}) {
    DYNAMIC_SECTION((nowUnilateral ? "now unilateral" : "now bilateral")) {
      Case c("sneddonCrack", std::string("bad-restartContact-") + (nowUnilateral ? "u" : "b"));
      if (nowUnilateral)
        c.edit("constant/fractureProperties", "contact +unilateral;", "contact bilateral;");
      split(c);
      {
        const fs::path log = c.dir() / "log.frictionSolver.first";
        const int rc = run(bin("frictionSolver") + " -case " + quoted(c.dir()), log);
        INFO(readText(log));
        REQUIRE(rc == 0);
      }
      c.edit("constant/fractureProperties",
             nowUnilateral ? "contact bilateral;" : "contact +unilateral;",
             nowUnilateral ? "contact unilateral;" : "contact bilateral;");
      c.edit("system/controlDict", "startFrom +startTime;", "startFrom latestTime;");
      c.edit("system/controlDict", "endTime +1;", "endTime 2;");
      const fs::path state = c.dir() / "1/uniform/frictionState";
      if (nowUnilateral)
        solverFails(c, {"1/uniform/frictionState", "no key 'opening'", "contact unilateral"});
      else
        solverFails(c, {at("1/uniform/frictionState", lineOf(state, "opening")),
                        "could open (contact unilateral)", "-overwrite"});
      CHECK_FALSE(fs::exists(c.dir() / "2"));
    }
  }
}

TEST_CASE("a bad table in 0/D names the patch and the key it is the value of",
          "[regression][errors]") {
  Case c("paperBenchmark", "bad-D-tableKey");
  split(c);
  c.edit("0/D", "table \\(\\(0 \\(0 0\\)\\) \\(1 ", "table ((1 (0 0)) (0 ");
  solverFails(c, {"key 'value'", "top"});
}

TEST_CASE("what the reader accepts beyond OpenFOAM's rules reads as the plain form",
          "[regression][errors]") {
  // README "Dictionaries": a byte-order mark is skipped, the FoamFile header is optional and
  // 'uniform' may precede a constant value. The run must give the same table as the plain case.
  Case plain("paperBenchmark", "lenient-plain");
  REQUIRE(plain.solve() == 0);
  Case c("paperBenchmark", "lenient-edited");
  const fs::path controlDict = c.dir() / "system/controlDict";
  writeText(controlDict, "\xEF\xBB\xBF" + readText(controlDict));
  c.edit("constant/mechanicalProperties", "FoamFile\\s*\\{[^}]*\\}", "");
  c.edit("0/D", "value +\\(0 0\\);", "value uniform (0 0);");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  const std::vector<Row> a = plain.table("1", "fracture"), b = c.table("1", "fracture");
  REQUIRE(!a.empty());
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    // The same input read the same way: the same arithmetic, so the same digits.
    CHECK(a[i].slip == b[i].slip);
    CHECK(a[i].sigmaN == b[i].sigmaN);
  }
}

TEST_CASE("bad friction fields name file, line, key and the place where they fail",
          "[regression][errors][field]") {
  Case c("paperBenchmark", "bad-field");
  split(c);
  const std::string props = "constant/fractureProperties";
  const fs::path file = c.dir() / props;
  const auto mu = [&](const std::string& field) {
    c.edit(props, "frictionCoefficient 0\\.2;", "frictionCoefficient " + field);
    return lineOf(file, "frictionCoefficient {");
  };
  SECTION("a negative value at a node (the node named)") {
    const int line = mu("{ type depth; value -0.1; gradient 0; }");
    solverFails(c, {at(props, line), "'frictionCoefficient'", "the value -0.1 is not >= 0",
                    "the fracture node at ("});
  }
  SECTION("a table that does not cover the fracture") {
    const int line = mu("{ type arclength; table ((0 0.2) (0.001 0.2)); }");
    solverFails(c, {at(props, line), "'frictionCoefficient'", "the table covers s in [0, 0.001]"});
  }
  SECTION("an unknown type lists the valid ones") {
    const int line = mu("{ type linear; value 1; }");
    solverFails(c, {at(props, line), "linear", "arclength, points, depth"});
  }
  SECTION("a malformed values file") {
    mu("{ type arclength; file \"constant/mu.dat\"; }");
    writeText(c.dir() / "constant/mu.dat", "# s mu\n0 0.2\n0.5 0.2 0.3\n");
    solverFails(
        c, {"constant/mu.dat:3:", "expected two numbers 's value'", "got '0.5 0.2 0.3' (3 items)"});
  }
  SECTION("a points file that misses nodes") {
    mu("{ type points; file \"constant/mu.dat\"; }");
    writeText(c.dir() / "constant/mu.dat", "0.5 0.5 0.2\n");
    solverFails(c, {"'frictionCoefficient'", "no row of", "constant/mu.dat",
                    "list every fracture node or set maxDistance"});
  }
}

TEST_CASE("a FIFO or a device that a case names is refused at once, naming who named it",
          "[regression][errors][files]") {
  // Each used to block for ever (a FIFO), or read as empty (/dev/zero). The runs go through
  // `timeout`: a reader that blocks fails the check on the exit status instead of hanging.
  Case c("paperBenchmark", "bad-nonRegular");
  split(c);
  const fs::path fifo = c.dir() / "constant/fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string fifoIs = "it is a FIFO (named pipe), not a regular file";
  const auto refused = [&](const std::string& tool, const std::vector<std::string>& expected) {
    const auto before = snapshot(c.dir());
    const fs::path log = c.dir() / ("log." + tool);
    const int status = run("timeout -s KILL 60 " + bin(tool) + " -case " + quoted(c.dir()), log);
    const std::string out = readText(log);
    INFO(out);
    CHECK(status == 1);  // 137 (killed by timeout) when the reader blocked
    for (const std::string& e : expected) CHECK_THAT(out, Catch::Contains(e));
    CHECK(snapshot(c.dir()) == before);
  };

  SECTION("#include of a FIFO in system/controlDict") {
    writeText(c.dir() / "system/controlDict",
              readText(c.dir() / "system/controlDict") + "\n#include \"../constant/fifo\"\n");
    const int line = lineOf(c.dir() / "system/controlDict", "#include \"../constant/fifo\"");
    refused("frictionSolver",
            {at("system/controlDict", line), "#include: cannot open '", "constant/fifo", fifoIs});
  }
  SECTION("#include \"/dev/zero\" in constant/mechanicalProperties") {
    const fs::path mech = c.dir() / "constant/mechanicalProperties";
    writeText(mech, readText(mech) + "\n#include \"/dev/zero\"\n");
    refused("frictionSolver",
            {at("constant/mechanicalProperties", lineOf(mech, "#include \"/dev/zero\"")),
             "#include: cannot open '/dev/zero': it is a character device"});
  }
  SECTION("a fracturePressure values file that is a FIFO") {
    writeText(c.dir() / "constant/effects",
              "pore\n{\n    type fracturePressure;\n    fracture fracture;\n"
              "    values \"constant/fifo\";\n}\n");
    refused("frictionSolver",
            {at("constant/effects", 5), "key 'values': cannot open '", "constant/fifo", fifoIs});
  }
  SECTION("a friction field file that is a FIFO") {
    const std::string props = "constant/fractureProperties";
    c.edit(props, "frictionCoefficient 0\\.2;",
           "frictionCoefficient { type arclength; file \"constant/fifo\"; }");
    refused("frictionSolver", {at(props, lineOf(c.dir() / props, "file \"constant/fifo\"")),
                               "key 'file': cannot open '", "constant/fifo", fifoIs});
  }
  SECTION("a mesh file that is a FIFO") {
    c.edit("system/meshDict", "\"constant/mesh/square.msh\"", "\"constant/fifo\"");
    refused("splitFractureNodes",
            {at("system/meshDict", lineOf(c.dir() / "system/meshDict", "\"constant/fifo\"")),
             "key 'mesh': cannot open '", "constant/fifo", fifoIs});
  }
}

TEST_CASE(
    "keys other codes use: K and G, frictionAngle give the runs of lambda, mu and "
    "frictionCoefficient",
    "[regression][errors]") {
  Case plain("paperBenchmark", "foreign-keys-plain");
  split(plain);
  REQUIRE(plain.solve() == 0);
  Case other("paperBenchmark", "foreign-keys-other");
  split(other);
  // λ = μ = 1: K = λ + 2μ/3, G = μ; μ_f = 0.2 = tan(11.309932474020215°).
  other.edit("constant/mechanicalProperties", "lambda +1;", "K 1.6666666666666667;");
  other.edit("constant/mechanicalProperties", "mu +1;", "G 1;");
  other.edit("constant/fractureProperties", "frictionCoefficient +0.2;",
             "frictionAngle 11.309932474020215;");
  REQUIRE(other.solve() == 0);
  CHECK_THAT(other.log(), Catch::Contains("frictionCoefficient 0.2"));
  const auto a = plain.table("1", "fracture");
  const auto b = other.table("1", "fracture");
  REQUIRE(a.size() == b.size());
  double scale = 0;
  for (const auto& r : a) scale = std::max(scale, std::abs(r.slip));
  REQUIRE(scale > 0);
  // λ from K − 2G/3 and μ_f from tan differ from 1 and 0.2 in the last bit: the slips agree
  // to round-off (the solver's tolerance 1e-10 is far above it).
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(std::abs(a[i].slip - b[i].slip) <= 1e-9 * scale);
    CHECK(a[i].state == b[i].state);
  }
}
