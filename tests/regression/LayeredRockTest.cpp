// Materials per region (constant/mechanicalProperties 'regions', README "Materials per
// region") through the real binaries on tests/regression/cases/layeredRock (two layers,
// "reservoir" below y = 1/2 and "caprock" above, gmsh physical surfaces) and on
// tests/regression/cases/faultInCube cut into two regions (3D):
//  * a two-layer column under uniaxial load against its exact, piecewise-linear solution,
//    without and with a fracture along the interface (σ_n = −p, τ = 0 recovered there);
//  * the inclined crack across the interface takes the stiff layer's E for γ; P1's locking
//    warning names its region;
//  * two regions with equal constants give the one-material run bit for bit (2D and 3D);
//  * two different materials in 3D run and converge;
//  * the mistakes a user makes in the regions form are named, with file, line and key.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "CaseRunner.hpp"
#include "friction/mesh/MeshReader.hpp"

using namespace friction::regression;

namespace {

fs::path geoFile() {
  return fs::path(FRICTION_SOURCE_DIR) / "tests" / "regression" / "cases" / "layeredRock" /
         "constant" / "mesh" / "layeredRock.geo";
}

/// The case's mesh from layeredRock.geo, with (crack 1) or without (crack 0) the crack.
void makeMesh(const Case& c, int crack) {
  const fs::path log = c.dir() / "log.gmsh";
  const std::string cmd = "gmsh -2 -format msh41 -setnumber crack " + std::to_string(crack) + " '" +
                          geoFile().string() + "' -o '" +
                          (c.dir() / "constant" / "mesh" / "layeredRock.msh").string() + "'";
  const int rc = run(cmd, log);
  INFO(cmd << "\n" << readText(log));
  REQUIRE(rc == 0);
}

/// The arrays of an ASCII .vtu as the solver writes it (one DataArray per block, its values
/// between the opening and closing lines), by name; the points' array has the name "".
std::map<std::string, std::vector<double>> readVtu(const fs::path& file) {
  std::map<std::string, std::vector<double>> arrays;
  std::istringstream in(readText(file));
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("<DataArray") == std::string::npos) continue;
    std::string name;
    const auto at = line.find("Name=\"");
    if (at != std::string::npos) name = line.substr(at + 6, line.find('"', at + 6) - at - 6);
    std::vector<double>& values = arrays[name];
    while (std::getline(in, line) && line.find("</DataArray>") == std::string::npos) {
      std::istringstream s(line);
      for (std::string item; s >> item;) values.push_back(std::strtod(item.c_str(), nullptr));
    }
  }
  return arrays;
}

/// The one .vtu of time 1 in the case's VTK folder.
fs::path vtuOf(const Case& c) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(c.dir() / "VTK"))
    if (e.path().extension() == ".vtu") files.push_back(e.path());
  REQUIRE(files.size() == 1);
  return files.front();
}

/// Plane-strain constrained modulus λ + 2μ = E(1 − ν)/((1 + ν)(1 − 2ν)) and λ [Pa].
double constrained(double E, double nu) { return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); }
double lame(double E, double nu) { return E * nu / ((1 + nu) * (1 - 2 * nu)); }

std::string regionsText(const std::string& reservoir, const std::string& caprock) {
  return "regions\n{\n    reservoir   { " + reservoir + " }\n    caprock     { " + caprock +
         " }\n}";
}

}  // namespace

TEST_CASE("layered rock: a two-layer column under uniaxial load is exact per layer",
          "[regression][materials]") {
  // Rollers on the left, right and bottom, pressure p on the top, no crack: u_x = 0, ε_xx = 0,
  // σ_yy = −p in both layers, ε_yy = −p/(λ_i + 2μ_i) in layer i, σ_xx = σ_zz = λ_i ε_yy, so
  // u_y is linear in each layer and continuous at y = 1/2 (plane strain). P1 and P2 hold it
  // exactly (the mesh follows the interface): what remains is round-off. With a fracture along
  // the whole interface (μ_f 0.4; the rollers hold u_x = 0, so nothing slides) the state is the
  // same, and the traction recovered there from the residual (53), between a soft and a stiff
  // cell on each side, is σ_n = −p, τ = 0: the bimaterial check of the recovery.
  const double p = 1e7, E1 = 10e9, nu1 = 0.25, E2 = 30e9, nu2 = 0.3;
  const double e1 = -p / constrained(E1, nu1), e2 = -p / constrained(E2, nu2);
  const auto exactUy = [&](double y) { return y <= 0.5 ? e1 * y : e1 * 0.5 + e2 * (y - 0.5); };
  for (int order : {1, 2})
    for (bool fracture : {false, true}) {
      DYNAMIC_SECTION("P" << order << (fracture ? ", fracture along the interface" : "")) {
        Case c("tests:layeredRock", "layered-column-P" + std::to_string(order) +
                                        (fracture ? "-fracture" : "") + "/layeredRock");
        makeMesh(c, fracture ? 2 : 0);
        if (!fracture) {
          c.edit("system/meshDict", "fractures +\\(crack\\);", "fractures ();");
          c.edit("constant/fractureProperties", "crack\\s*\\{[^}]*\\}", "");
        }
        c.edit("0/D", "right +\\{ type free; \\}",
               "right   { type fixedDisplacement; components (x); value (0 0); }");
        if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
        const int rc = c.solve();
        INFO(c.log());
        REQUIRE(rc == 0);
        // The log lists the materials per region.
        CHECK_THAT(c.log(), Catch::Contains("Materials: 2 regions, plane strain"));
        CHECK_THAT(c.log(), Catch::Contains("Material reservoir (region 1, "));
        CHECK_THAT(c.log(), Catch::Contains("): E 1e+10 Pa, nu 0.25"));
        CHECK_THAT(c.log(), Catch::Contains("Material caprock (region 2, "));
        CHECK_THAT(c.log(), Catch::Contains("): E 3e+10 Pa, nu 0.3"));

        auto vtu = readVtu(vtuOf(c));
        const auto& x = vtu[""];
        const auto& u = vtu["displacement"];
        REQUIRE(x.size() >= 3 * 20);
        REQUIRE(u.size() == x.size());
        // What remains is round-off and the files' 12 significant digits (writePrecision 12):
        // measured 1.5e-12 of the top's displacement, P1 and P2; 1e-10 leaves a margin of ~60
        // and is far below what a wrong layer's modulus would make (a factor 3 in ε_yy).
        const double scale = std::abs(exactUy(1.0));
        double worst = 0;
        int above = 0, below = 0;
        for (std::size_t k = 0; 3 * k < x.size(); ++k) {
          const double y = x[3 * k + 1];
          worst = std::max({worst, std::abs(u[3 * k]), std::abs(u[3 * k + 1] - exactUy(y))});
          (y > 0.5 ? above : below) += 1;
        }
        CHECK(above > 10);
        CHECK(below > 10);
        CHECK(worst <= 1e-10 * scale);

        // Stresses per cell (the writer's centroid value): σ_yy = −p, σ_xx = σ_zz = λ_i ε_yy,
        // σ_xy = 0, each layer with its own λ_i; 1e-8 p for the same round-off and digits.
        const auto& stress = vtu["stress"];
        const auto& region = vtu["region"];
        REQUIRE(!region.empty());
        REQUIRE(stress.size() == 6 * region.size());
        int cells[3] = {0, 0, 0};
        for (std::size_t k = 0; k < region.size(); ++k) {
          const int r = static_cast<int>(region[k]);
          REQUIRE((r == 1 || r == 2));
          ++cells[r];
          const double sxx = r == 1 ? lame(E1, nu1) * e1 : lame(E2, nu2) * e2;
          CHECK(std::abs(stress[6 * k + 0] - sxx) <= 1e-8 * p);
          CHECK(std::abs(stress[6 * k + 1] + p) <= 1e-8 * p);
          CHECK(std::abs(stress[6 * k + 2] - sxx) <= 1e-8 * p);
          CHECK(std::abs(stress[6 * k + 3]) <= 1e-8 * p);
        }
        CHECK(cells[1] > 10);
        CHECK(cells[2] > 10);

        if (fracture) {
          // σ_n = −p and τ = 0 at every node of the interface, the jump zero; 1e-8 p as above.
          // Except τ at the two end nodes: they lie on the roller patches, where the residual
          // carries the rollers' reaction as well, and σ_xx = λ_i ε_yy differs between the
          // layers (measured: τ = ±1.9e6 Pa there, twice the jump of σ_xx); the solver holds
          // their jump at zero and says so.
          CHECK_THAT(c.log(), Catch::Contains("2 fracture node(s) lie on a Dirichlet patch"));
          const auto rows = c.table("1", "crack");
          REQUIRE(rows.size() >= 11);
          int interior = 0;
          for (const Row& r : rows) {
            INFO("s = " << r.s);
            const bool end = r.x < 1e-12 || r.x > 1 - 1e-12;
            interior += !end;
            CHECK(std::abs(r.y - 0.5) < 1e-12);
            CHECK(std::abs(r.sigmaN + p) <= 1e-8 * p);
            if (!end) CHECK(std::abs(r.tau) <= 1e-8 * p);
            CHECK(std::abs(r.slip) <= 1e-10 * scale);
            CHECK(r.state == "stick");
          }
          CHECK(interior == static_cast<int>(rows.size()) - 2);
        }
      }
    }
}

TEST_CASE("layered rock: two regions with equal constants are the one-material run",
          "[regression][materials]") {
  // The same λ, μ in every cell through the same arithmetic (the element matrices, the
  // stresses, γ = E/h and the step scale from the same E): the outputs are the same bit for
  // bit, so the comparison is of the files' bytes, with no tolerance.
  std::map<std::string, std::string> outputsOf[2];
  std::string gammaLine[2];
  for (int regions : {0, 1}) {
    Case c("tests:layeredRock",
           std::string("layered-equal/") + (regions ? "regions" : "flat") + "/layeredRock");
    makeMesh(c, 1);
    const std::string body = regions ? regionsText("E 10e9; nu 0.25;", "E 10e9; nu 0.25;")
                                     : std::string("E 10e9;\nnu 0.25;");
    c.edit("constant/mechanicalProperties", "regions\\s*\\{[\\s\\S]*\\}\\s*\\}", body);
    const int rc = c.solve();
    INFO(c.log());
    REQUIRE(rc == 0);
    for (const char* file : {"1/fractures/crack.dat", "1/D", "1/solverStatus"})
      outputsOf[regions][file] = readText(c.dir() / file);
    outputsOf[regions]["vtu"] = readText(vtuOf(c));
    const std::string log = c.log();
    const auto at = log.find("gamma ");
    REQUIRE(at != std::string::npos);
    gammaLine[regions] = log.substr(at, log.find(',', at) - at);
    CHECK_THAT(log, Catch::Contains(regions ? "Materials: 2 regions" : "Material: E 1e+10 Pa"));
  }
  REQUIRE(outputsOf[0].size() == 4);
  for (const auto& [file, text] : outputsOf[0]) {
    INFO(file);
    REQUIRE(text.size() > 100);
    CHECK(text == outputsOf[1][file]);
  }
  CHECK(gammaLine[0] == gammaLine[1]);
}

TEST_CASE("layered rock: the crack across the interface sees the stiff layer's E in gamma",
          "[regression][materials]") {
  // γ's default is gammaRelative·E/h with E the largest of the cells that touch the crack:
  // the crack crosses into the caprock, so E = 3e10 Pa there; the run converges.
  Case c("tests:layeredRock", "layered-crack/layeredRock");
  makeMesh(c, 1);
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  CHECK_THAT(c.log(),
             Catch::Contains("E for gammaRelative and alphaRelative 3e+10 Pa (the largest E of "
                             "the cells that touch a fracture)"));
  const auto rows = c.table("1", "crack");
  int slipping = 0;
  for (const Row& r : rows)
    if (r.state == "slip") ++slipping;
  CHECK(slipping > 0);
  CHECK_THAT(c.log(), !Catch::Contains("P1 locks"));

  // P1's locking warning names the region whose ν is near 1/2, and only that one.
  Case w("tests:layeredRock", "layered-crack-nu/layeredRock");
  makeMesh(w, 1);
  w.edit("constant/mechanicalProperties", "caprock +\\{ E 30e9; nu 0.3; \\}",
         "caprock { E 30e9; nu 0.49; }");
  REQUIRE(w.solve() == 0);
  CHECK_THAT(w.log(), Catch::Contains("Warning: nu = 0.49 in region caprock with P1 elements"));
  CHECK_THAT(w.log(), !Catch::Contains("in region reservoir"));
}

TEST_CASE("layered rock: mistakes in the regions form are named", "[regression][materials]") {
  struct Bad {
    const char* label;
    std::string body;
    const char* lineText;  ///< a text of the line the error names
    std::vector<std::string> expected;
  };
  const std::vector<Bad> bad = {
      {"unknownName",
       "regions\n{\n    reservior { E 10e9; nu 0.25; }\n    caprock { E 30e9; nu 0.3; }\n}",
       "reservior {",
       {"'reservior' is no region of the mesh", "did you mean 'reservoir'?",
        "regions: reservoir (region1), caprock (region2)"}},
      {"missingRegion",
       "regions\n{\n    reservoir { E 10e9; nu 0.25; }\n}",
       "regions",
       {"key 'regions': no material for 'caprock' (region 2, ", "or a 'default' entry",
        "regions: reservoir (region1), caprock (region2)"}},
      {"bothForms",
       "E 10e9;\nnu 0.25;\nregions\n{\n    default { E 10e9; nu 0.25; }\n}",
       "E 10e9;",
       {"key 'E' together with 'regions'", "not both"}},
      {"badValue",
       "regions\n{\n    reservoir { E 10e9; nu 0.5; }\n    caprock { E 30e9; nu 0.3; }\n}",
       "reservoir {",
       {"key 'nu'", "0.5"}},
      {"planeStressInRegion",
       "regions\n{\n    reservoir { E 10e9; nu 0.25; planeStress yes; }\n    caprock { E 30e9; "
       "nu 0.3; }\n}",
       "reservoir {",
       {"key 'planeStress' is one setting for the whole body"}},
      {"twice",
       "regions\n{\n    reservoir { E 10e9; nu 0.25; }\n    region1 { E 10e9; nu 0.25; }\n    "
       "caprock { E 30e9; nu 0.3; }\n}",
       "region1 {",
       {"has two entries, 'reservoir' and 'region1'"}},
  };
  for (const Bad& b : bad) {
    DYNAMIC_SECTION(b.label) {
      Case c("tests:layeredRock", std::string("layered-bad/") + b.label);
      makeMesh(c, 1);
      const fs::path bin = FRICTION_BIN_DIR;
      REQUIRE(
          run("'" + (bin / "splitFractureNodes").string() + "' -case '" + c.dir().string() + "'",
              c.dir() / "log.splitFractureNodes") == 0);
      c.edit("constant/mechanicalProperties", "regions\\s*\\{[\\s\\S]*\\}\\s*\\}", b.body);
      const fs::path file = c.dir() / "constant" / "mechanicalProperties";
      int line = 0;
      {
        std::ifstream in(file);
        std::string l;
        for (int n = 1; std::getline(in, l); ++n)
          if (l.find(b.lineText) != std::string::npos) {
            line = n;
            break;
          }
      }
      REQUIRE(line > 0);
      const int rc =
          run("'" + (bin / "frictionSolver").string() + "' -case '" + c.dir().string() + "'",
              c.dir() / "log.frictionSolver");
      const std::string out = c.log();
      INFO(out);
      CHECK(rc == 1);
      CHECK_THAT(out,
                 Catch::Contains("constant/mechanicalProperties:" + std::to_string(line) + ": "));
      for (const std::string& e : b.expected) CHECK_THAT(out, Catch::Contains(e));
      CHECK_FALSE(fs::exists(c.dir() / "1"));
    }
  }
}

namespace {

/// Medit .mesh of m with each tetrahedron's region from `regionOf(centroid)`.
void writeMedit(const fs::path& path, const friction::Mesh& m,
                const std::function<int(const friction::Point&)>& regionOf) {
  std::ofstream out(path);
  out.precision(17);
  out << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << m.points.size() << "\n";
  for (const auto& x : m.points) out << x.x() << " " << x.y() << " " << x.z() << " 0\n";
  out << "Tetrahedra\n" << m.numCells() << "\n";
  for (friction::Index c = 0; c < m.numCells(); ++c) {
    friction::Point centroid = friction::Point::Zero();
    for (friction::Index v : m.cell(c)) {
      out << v + 1 << " ";
      centroid += m.points[v] / 4;
    }
    out << regionOf(centroid) << "\n";
  }
  out << "Triangles\n" << m.numFacets() << "\n";
  for (friction::Index f = 0; f < m.numFacets(); ++f) {
    for (friction::Index v : m.facet(f)) out << v + 1 << " ";
    out << m.facetLabel[f] << "\n";
  }
  out << "End\n";
}

}  // namespace

TEST_CASE("layered rock 3D: two regions of tetrahedra, equal constants and a contrast",
          "[regression][materials]") {
  // tests/regression/cases/faultInCube with its tetrahedra in region 1 (centroid x < 1/2) and
  // 2 (x > 1/2): the square fault crosses the interface. A Medit file names no region, so the
  // entries are numbers.
  const fs::path source = fs::path(FRICTION_SOURCE_DIR) / "tests" / "regression" / "cases" /
                          "faultInCube" / "constant" / "mesh" / "cube.msh";
  const friction::Mesh mesh = friction::readMesh(source.string());
  REQUIRE(mesh.dim == 3);
  const auto regionOf = [](const friction::Point& x) { return x.x() < 0.5 ? 1 : 2; };
  const auto runWith = [&](const std::string& label, const std::string& materials) {
    Case c("tests:faultInCube", "layered-3d/" + label + "/faultInCube");
    writeMedit(c.dir() / "constant" / "mesh" / "cube.mesh", mesh, regionOf);
    c.edit("system/meshDict", "cube\\.msh", "cube.mesh");
    c.edit("constant/mechanicalProperties", "E +[^;]*;\\s*(//[^\\n]*)?\\s*nu +[^;]*;", materials);
    const int rc = c.solve();
    INFO(c.log());
    REQUIRE(rc == 0);
    return c;
  };
  // The case's own constants (E 1e9 Pa, nu 0.25), once for the body or per region.
  const Case one = runWith("flat", "E 1e9;\nnu 0.25;");
  const Case two =
      runWith("equal", "regions { region1 { E 1e9; nu 0.25; } region2 { E 1e9; nu 0.25; } }");
  CHECK_THAT(two.log(), Catch::Contains("Materials: 2 regions, 3D"));
  for (const char* file : {"1/fractures/fault.dat", "1/D"}) {
    INFO(file);
    const std::string a = readText(one.dir() / file);
    REQUIRE(a.size() > 100);
    CHECK(a == readText(two.dir() / file));
  }
  // Region 2 a hundred times stiffer: the run converges, and γ takes the stiff E (the fault
  // touches both regions).
  const Case contrast =
      runWith("contrast", "regions { region1 { E 1e9; nu 0.25; } default { E 1e11; nu 0.3; } }");
  CHECK_THAT(contrast.log(), Catch::Contains("Material region2 (region 2, "));
  CHECK_THAT(contrast.log(), Catch::Contains(", entry default): E 1e+11 Pa, nu 0.3"));
  CHECK_THAT(contrast.log(), Catch::Contains("E for gammaRelative and alphaRelative 1e+11 Pa"));
  CHECK(std::regex_search(readText(contrast.dir() / "1" / "solverStatus"),
                          std::regex("\\nstatus +converged;")));
}

namespace {

const char* kEffectsHeader =
    "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n    object "
    "effects;\n}\n";

}  // namespace

TEST_CASE("layered rock: a depleting reservoir layer, the pore pressure's change on it only",
          "[regression][porePressure]") {
  // The column of the test above (rollers on the left, right and bottom, p = 10 MPa on the top
  // at t = 1), and porePressure with a change Δp_b = −5 MPa on 'reservoir' only, α_B = 0.9.
  // Each layer stays uniform: σ_yy = −p in both (the top's load is fixed); in the reservoir
  // (λ₁ + 2μ₁) ε_yy − α_B Δp_b = −p, σ_xx = σ_zz = λ₁ ε_yy − α_B Δp_b (total stresses, plane
  // strain); the caprock as without pressure. P1 and P2 hold it (u_y linear in each layer).
  const double p = 1e7, E1 = 10e9, nu1 = 0.25, E2 = 30e9, nu2 = 0.3, alpha = 0.9, dp = -5e6;
  const double e1 = (-p + alpha * dp) / constrained(E1, nu1), e2 = -p / constrained(E2, nu2);
  const auto exactUy = [&](double y) { return y <= 0.5 ? e1 * y : e1 * 0.5 + e2 * (y - 0.5); };
  for (int order : {1, 2}) {
    DYNAMIC_SECTION("P" << order) {
      Case c("tests:layeredRock", "layered-depletion-P" + std::to_string(order) + "/layeredRock");
      makeMesh(c, 0);
      c.edit("system/meshDict", "fractures +\\(crack\\);", "fractures ();");
      c.edit("constant/fractureProperties", "crack\\s*\\{[^}]*\\}", "");
      c.edit("0/D", "right +\\{ type free; \\}",
             "right   { type fixedDisplacement; components (x); value (0 0); }");
      if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
      writeText(c.dir() / "constant" / "effects",
                std::string(kEffectsHeader) +
                    "rock { type porePressure; biotCoefficient 0.9;\n"
                    "       regions { reservoir { change table ((0 0) (1 -5e6)); } } }\n");
      const int rc = c.solve();
      INFO(c.log());
      REQUIRE(rc == 0);
      CHECK_THAT(c.log(), Catch::Contains("Effect rock: porePressure, biotCoefficient 0.9, "
                                          "initial p_b 0 Pa, in region reservoir a change in "
                                          "time (table); one way"));

      auto vtu = readVtu(vtuOf(c));
      const auto& x = vtu[""];
      const auto& u = vtu["displacement"];
      REQUIRE(x.size() >= 3 * 20);
      REQUIRE(u.size() == x.size());
      // Round-off and the 12 digits written, as in the column test: 1e-10 of the top's
      // displacement, 1e-8 p for the stresses; a change loading the caprock too, or with the
      // wrong sign, is off by α_B Δp_b/(λ + 2μ) in ε_yy (a third of it) and α_B Δp_b in σ.
      const double scale = std::abs(exactUy(1.0));
      double worst = 0;
      for (std::size_t k = 0; 3 * k < x.size(); ++k)
        worst =
            std::max({worst, std::abs(u[3 * k]), std::abs(u[3 * k + 1] - exactUy(x[3 * k + 1]))});
      CHECK(worst <= 1e-10 * scale);
      const auto& stress = vtu["stress"];
      const auto& region = vtu["region"];
      REQUIRE(stress.size() == 6 * region.size());
      int cells[3] = {0, 0, 0};
      for (std::size_t k = 0; k < region.size(); ++k) {
        const int r = static_cast<int>(region[k]);
        REQUIRE((r == 1 || r == 2));
        ++cells[r];
        const double sxx = r == 1 ? lame(E1, nu1) * e1 - alpha * dp : lame(E2, nu2) * e2;
        CHECK(std::abs(stress[6 * k + 0] - sxx) <= 1e-8 * p);
        CHECK(std::abs(stress[6 * k + 1] + p) <= 1e-8 * p);
        CHECK(std::abs(stress[6 * k + 2] - sxx) <= 1e-8 * p);
        CHECK(std::abs(stress[6 * k + 3]) <= 1e-8 * p);
      }
      CHECK(cells[1] > 10);
      CHECK(cells[2] > 10);
    }
  }
}

TEST_CASE("layered rock: a fault in a depleting layer takes the rock's pore pressure",
          "[regression][porePressure]") {
  // The inclined crack (60°, μ_f 2: it sticks) in one material (E 10 GPa, ν 1/4 in both
  // layers), rollers on the left, right and bottom, p = 10 MPa on the top; porePressure with
  // α_B = 1, p_b0 = 3e6 − 1e4 y [Pa] and Δp_b = −2 MPa everywhere at t = 1. The stress is
  // uniform: σ_yy = −p, σ_xx = λ/(λ + 2μ) (−p + α_B Δp_b) − α_B Δp_b = −2 MPa (total), so on
  // the crack (t = (cos 60°, sin 60°), n = (t_y, −t_x)) σ_n = σ_xx n_x² + σ_yy n_y² and
  // τ = σ_xx n_x t_x + σ_yy n_y t_y are the total tractions recovered from the residual; the
  // crack has no pressure of its own, so p = p_b0 + Δp_b and σ'_n = σ_n + p. With a
  // faultPressure of its own (5e5 Pa) the crack keeps that one instead, and the tractions stay.
  const double p = 1e7, alpha = 1, dp = -2e6, lambdaOverM = 1.0 / 3;
  const double sxx = lambdaOverM * (-p + alpha * dp) - alpha * dp, syy = -p;
  const double pi = std::acos(-1.0), c60 = std::cos(pi / 3), s60 = std::sin(pi / 3);
  const double nx = s60, ny = -c60, tx = c60, ty = s60;
  const double sigmaN = sxx * nx * nx + syy * ny * ny, tau = sxx * nx * tx + syy * ny * ty;
  for (bool own : {false, true}) {
    DYNAMIC_SECTION((own ? "with a faultPressure of its own" : "the rock's pressure")) {
      Case c("tests:layeredRock",
             std::string("layered-fault-depletion-") + (own ? "own" : "rock") + "/layeredRock");
      makeMesh(c, 1);
      c.edit("constant/mechanicalProperties", "caprock +\\{ E 30e9; nu 0.3; \\}",
             "caprock { E 10e9; nu 0.25; }");
      c.edit("constant/fractureProperties", "frictionCoefficient 0.4;", "frictionCoefficient 2;");
      c.edit("0/D", "right +\\{ type free; \\}",
             "right   { type fixedDisplacement; components (x); value (0 0); }");
      writeText(c.dir() / "constant" / "effects",
                std::string(kEffectsHeader) +
                    "rock { type porePressure; biotCoefficient 1;\n"
                    "       initial { type depth; value 3e6; gradient -1e4; }\n"
                    "       change table ((0 0) (1 -2e6)); }\n" +
                    (own ? "fluid { type faultPressure; fracture crack; initial 5e5; }\n" : ""));
      const int rc = c.solve();
      INFO(c.log());
      REQUIRE(rc == 0);
      CHECK_THAT(c.log(), Catch::Contains(own ? "Fracture crack: a fluid pressure of its own"
                                              : "Fracture crack: initial pore pressure of the "
                                                "rock (rock) from min"));
      const Table t = c.namedTable("1", "crack");
      int interior = 0;
      for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const double y = t.at(i, "y");
        const double pressure = own ? 5e5 : 3e6 - 1e4 * y + dp;
        INFO("row " << i << " y = " << y);
        // 12 digits written; the recovery's round-off as in the column test: 1e-8 p.
        CHECK(std::abs(t.at(i, "pressure") - pressure) <= 1e-8 * p);
        if (t.state[i] == "tip") continue;
        ++interior;
        CHECK(t.state[i] == "stick");
        CHECK(std::abs(t.at(i, "sigmaN") - sigmaN) <= 1e-8 * p);
        CHECK(std::abs(t.at(i, "tau") - tau) <= 1e-8 * p);
        CHECK(std::abs(t.at(i, "sigmaNEffective") - (sigmaN + pressure)) <= 1e-8 * p);
        CHECK(std::abs(t.at(i, "slip")) <= 1e-15);
      }
      CHECK(interior >= 10);
      // The written stress is total: σ_xx = −2 MPa in every cell.
      auto vtu = readVtu(vtuOf(c));
      const auto& stress = vtu["stress"];
      REQUIRE(stress.size() > 6 * 20);
      for (std::size_t k = 0; 6 * k < stress.size(); ++k) {
        CHECK(std::abs(stress[6 * k + 0] - sxx) <= 1e-8 * p);
        CHECK(std::abs(stress[6 * k + 1] - syy) <= 1e-8 * p);
      }
    }
  }
}

TEST_CASE(
    "layered rock: gravity with a density per layer and the in-situ profile that balances "
    "it move nothing",
    "[regression][effects][materials]") {
  // Reservoir below y = 1/2 (ρ = 2000 kg/m³), caprock above (ρ = 3000), the top free, g down:
  // the lithostatic σ_yy(y) = −g ∫_y^1 ρ, σ_xx = σ_zz... = 0.5 σ_yy, piecewise linear with its
  // kink at the interface. Given as a profile, its divergence balances the layered weight
  // cell by cell (the interface is a mesh line), so the in-situ state alone moves nothing.
  const double g = 9.81, top = 3000 * g * 0.5, bottom = top + 2000 * g * 0.5;  // |σ_yy| [Pa]
  const auto num = [](double v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
  };
  const std::string profile = "profile ((0 (" + num(-0.5 * bottom) + " " + num(-bottom) +
                              " 0)) (0.5 (" + num(-0.5 * top) + " " + num(-top) +
                              " 0)) (1 (0 0 0)));";
  const auto effects = [&](const std::string& density) {
    return std::string(kEffectsHeader) + "gravity { type bodyForce; " + density +
           " g (0 -9.81); }\ninSitu { type initialStress; " + profile + " }\n";
  };
  const auto layered = [&](const std::string& label, const std::string& density) {
    auto c = std::make_unique<Case>("tests:layeredRock", label + "/layeredRock");
    makeMesh(*c, 1);
    c->edit("0/D", "top +\\{[^}]*\\}", "top { type free; }");
    c->edit("0/D", "right +\\{ type free; \\}",
            "right { type fixedDisplacement; components (x); value (0 0); }");
    writeText(c->dir() / "constant" / "effects", effects(density));
    return c;
  };
  auto balanced = layered("layered-gravity",
                          "regions { reservoir { density 2000; } caprock { density 3000; } }");
  REQUIRE(balanced->solve() == 0);
  INFO(balanced->log());
  CHECK_THAT(
      balanced->log(),
      Catch::Contains("Effect gravity: bodyForce, density reservoir 2000 caprock 3000 kg/m3"));
  CHECK_THAT(balanced->log(), Catch::Contains("sigma0 piecewise linear in y, 3 rows"));
  // The crack's tractions are σ⁰ resolved on it, node by node; nothing slips or moves.
  const auto rows = balanced->table("1", "crack");
  const double theta = 60 * M_PI / 180;
  int checked = 0;
  for (const Row& r : rows) {
    if (r.state == "tip") continue;
    const double syy =
        r.y >= 0.5 ? -top * (1 - r.y) / 0.5 : -(top + (bottom - top) * (0.5 - r.y) / 0.5);
    const double sxx = 0.5 * syy;
    // Normal of the crack (its direction (cos θ, sin θ)): ±(−sin θ, cos θ).
    const double nx = -std::sin(theta), ny = std::cos(theta);
    const double sn = sxx * nx * nx + syy * ny * ny;
    const double tau = (syy - sxx) * nx * ny;
    CHECK(r.sigmaN == Approx(sn).margin(1e-9 * bottom));
    CHECK(std::abs(r.tau) == Approx(std::abs(tau)).margin(1e-9 * bottom));
    CHECK(std::abs(r.slip) <= 1e-12);
    ++checked;
  }
  CHECK(checked > 10);
  // The largest displacement of a case's 1/D (its "(x y z)" lines).
  const auto largest = [](const Case& c) {
    std::istringstream in(readText(c.dir() / "1" / "D"));
    double m = 0;
    int n = 0;
    const std::regex vec("^\\(([^ ]+) ([^ ]+) ([^ ]+)\\)$");
    std::smatch v;
    for (std::string line; std::getline(in, line);)
      if (std::regex_match(line, v, vec)) {
        m = std::max(m, std::hypot(std::stod(v[1]), std::stod(v[2])));
        ++n;
      }
    REQUIRE(n > 100);
    return m;
  };
  // ρ g L² / E ≈ 3e-6 m is the scale of what gravity alone would move: round-off of it.
  const double scale = 3000 * g / 1e10;
  CHECK(largest(*balanced) <= 1e-9 * scale);
  // One density for both layers with the same profile is out of balance: the body moves.
  auto unbalanced = layered("layered-gravity-one", "density 2000;");
  REQUIRE(unbalanced->solve() == 0);
  CHECK(largest(*unbalanced) > 1e-3 * scale);
}
