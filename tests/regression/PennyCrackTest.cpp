// The penny-shaped crack (cases/pennyCrack) against its analytic slip (docs/method.md, three
// dimensions): a disc of radius a = 1 m in a cube of side 8a under a uniform remote stress
// (initialStress: σ_n∞ = −10 MPa, |τ∞| = 6 MPa, μ_f = 0.3), so every node off the tip line
// slips, parallel to the resolved shear, with |[[u]]|(r) ∝ √(a² − r²). cases/pennyCrack's
// pennyError.py does the comparison (relative L²(Γ) error of |slip| on the fault triangles,
// angles, the law node by node); these tests read its numbers and assert what the physics
// requires. The finite cube (half-width L = 4a) lowers the slip by about 0.5 % against
// L = 8a (amplitude ratios 0.8928 and 0.8972 at h = a/16, measured in the case README; a
// deficit like (a/L)³), well under the discretisation error of every mesh used here.
#include <catch2/catch.hpp>

#include <regex>

#include "CaseRunner.hpp"
#include "friction/control/Optimizer.hpp"

using namespace friction::regression;

namespace {

/// One number of pennyError.py's output ("name   value ...").
double pennyValue(const std::string& out, const std::string& name) {
  return scriptValue(out, name);
}

/// Run pennyError.py on the solved case with `options`; returns its output (exit 0 required:
/// its --max checks passed).
std::string pennyError(const Case& c, const std::string& options) {
  return runCaseScript(c.dir(), "cases/pennyCrack/pennyError.py", options);
}

/// The case at disc mesh size h (Allmesh -h; the committed mesh is h = a/8), solved with
/// elements of `order`.
std::string solvePenny(Case& c, const std::string& h, int order = 1) {
  if (h != "0.125") c.remesh("-h " + h);
  if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  // Pointwise checks away from the tip line, where the √ of the rim does not dominate:
  //  * the law |τ| = μ_f|σ_n| at every slipping node with r < 0.8a to 1e-9: the solver stops
  //    at ‖D‖_M ≤ 1e-10 ‖Σ‖_M, a weighted mean over the fault, and its Newton solves no more
  //    accurately than that needs; the largest node's relative deviation is 10–15× that
  //    residual (measured: 1.2e-10 at ‖D‖/‖Σ‖ = 7.9e-12, h = a/16, krylov);
  //  * the slip direction parallel to the resolved remote shear within 0.5° at r < 0.5a
  //    (measured 0.33°, 0.14°, 0.045° at h = a/8, a/16, a/32) and exactly opposite to the
  //    node's τ (the law);
  //  * σ_n unchanged by the slip (the analytic answer) within 2 % at r < 0.5a (measured
  //    ≤ 1.4 %: mesh noise of the recovered traction).
  const std::string law = pennyError(c, "-inner 0.8 --maxLaw 1e-9");
  CHECK_THAT(law, Catch::Contains("states                   stick 0 slip"));
  CHECK(pennyValue(law, "innerSlipNodes") > 50);
  const std::string inner = pennyError(c, "-inner 0.5 --maxAngle 0.5");
  CHECK(pennyValue(inner, "maxSigmaNChange") <= 0.02);
  return law;
}

}  // namespace

TEST_CASE("penny crack, P1: the slip converges to the analytic slip", "[regression][3d][penny]") {
  Case coarse("pennyCrack", "penny-h8");
  const double e8 = pennyValue(solvePenny(coarse, "0.125"), "relL2Error");
  Case fine("pennyCrack", "penny-h16");
  const double e16 = pennyValue(solvePenny(fine, "0.0625"), "relL2Error");
  // Measured 0.2235 and 0.1312 (order 0.77): the √(a² − r²) at the rim and the grading of
  // the volume mesh hold P1 below order 1 (cases/pennyCrack/README.md). Asserted: the error
  // falls by a factor 1.5 at least per halving of h, and stays within 10 % of the measured
  // values (the mesh is reproduced exactly by gmsh, meshesReproduce.sh).
  CHECK(e8 <= 0.25);
  CHECK(e16 <= 0.145);
  CHECK(e8 / e16 >= 1.5);
}

TEST_CASE("penny crack, P2: three times more accurate than P1 on the same mesh",
          "[regression][3d][penny]") {
  Case c("pennyCrack", "penny-P2-h8");
  const double e = pennyValue(solvePenny(c, "0.125", 2), "relL2Error");
  // Measured 0.0722 at h = a/8 (P1: 0.2235); the fault tractions of P2 triangles come from
  // the consistent mass of Γ (docs/method.md §4). The integrated error of even the exact
  // nodal values is 0.015 here (the √ at the rim): P2 is not at that floor yet.
  CHECK(e <= 0.08);
  CHECK(e >= 0.015);
  // The coarser mesh a/4 (measured 0.1340: order 0.89 to a/8; the third mesh, a/16, is the
  // long test below): the error falls by a factor 1.6 at least per halving of h.
  Case coarse("pennyCrack", "penny-P2-h4");
  const double e4 = pennyValue(solvePenny(coarse, "0.25", 2), "relL2Error");
  CHECK(e4 <= 0.15);
  CHECK(e4 / e >= 1.6);
}

TEST_CASE("penny crack, P2 at h = a/16 (long: 220 s, 9.4 GB)", "[.][pennyLong]") {
  Case c("pennyCrack", "penny-P2-h16");
  const double e16 = pennyValue(solvePenny(c, "0.0625", 2), "relL2Error");
  // Measured 0.0390: order 0.89 from a/8 (0.0722), as from a/4 to a/8 (0.1340 → 0.0722).
  CHECK(e16 <= 0.043);
  CHECK(e16 >= 0.015);
}

TEST_CASE("penny crack, P1 at h = a/32 (long: 90 s, 5 GB)", "[.][pennyLong]") {
  Case c("pennyCrack", "penny-h32");
  const double e32 = pennyValue(solvePenny(c, "0.03125"), "relL2Error");
  // Measured 0.0805 (order 0.70 from a/16).
  CHECK(e32 <= 0.09);
}

TEST_CASE(
    "penny crack, variant auto: krylov on a fault above the 3D threshold, condensed below "
    "it and where S is needed",
    "[regression][3d][penny][optimizer]") {
  // The disc at h = 0.045a in a coarse cube (growth 2 per metre up to a): 1 893 fault nodes,
  // above SemismoothNewton::krylovFromNodes(3, dofs), in ~16 000 dofs. The default variant (auto)
  // takes krylov, says so in the log with the node count and the threshold, factors the plain
  // K (no jump unknowns last) and gives the condensed variant's slip. The committed mesh (273
  // nodes) stays condensed, and so does the fine fault when it may open (the krylov variant
  // refuses openings): the log says why. (Weakening and quasiDynamic: the unit test of
  // chooseFor; FrictionCase hands them over as it hands over the opening.)
  const auto dofsIn = [](const std::string& log) {
    std::smatch m;
    REQUIRE(std::regex_search(log, m, std::regex("(\\d+) dofs \\(P1\\)")));
    return std::stol(m[1]);
  };
  // "T, the 3D threshold for krylov at D dofs", of the run whose log is given
  const auto threshold = [&](const std::string& log) {
    const long dofs = dofsIn(log);
    return std::to_string(friction::SemismoothNewton::krylovFromNodes(3, dofs)) +
           ", the 3D threshold for krylov at " + std::to_string(dofs) + " dofs";
  };
  const auto nodesIn = [](const std::string& log) {
    std::smatch m;
    REQUIRE(std::regex_search(log, m, std::regex("(\\d+) fracture control nodes\n")));
    return std::stol(m[1]);
  };
  {
    Case small("pennyCrack", "penny-auto-small");
    REQUIRE(small.solve() == 0);
    INFO(small.log());
    CHECK_THAT(small.log(), Catch::Contains("Newton variant: condensed (variant auto: 273 fracture "
                                            "control nodes < " +
                                            threshold(small.log()) + ")\n"));
    CHECK_THAT(small.log(), Catch::Contains("jump unknowns last"));
  }
  Case k("pennyCrack", "penny-auto-krylov");
  k.remesh("-h 0.045 -hFar 1 -slope 2");
  const fs::path msh = fs::path("constant") / "mesh" / "pennyCrack.msh";
  REQUIRE(k.solve() == 0);
  const std::string log = k.log();
  INFO(log);
  const long nodes = nodesIn(log);
  REQUIRE(nodes >= friction::SemismoothNewton::krylovFromNodes(3, dofsIn(log)));
  CHECK_THAT(log, Catch::Contains("Newton variant: krylov (variant auto: " + std::to_string(nodes) +
                                  " fracture control nodes >= " + threshold(log) + ")\n"));
  CHECK_THAT(log, Catch::Contains("GMRES products per Newton iteration"));
  CHECK_THAT(log, !Catch::Contains("jump unknowns last"));
  {
    // What the krylov variant holds for the fault, counted: positive in each part, the total
    // and the per-node figure consistent, and far below the dense S_tt it does without
    // (8 bytes × (2n)² over n nodes: 32 n bytes per node).
    std::smatch m;
    REQUIRE(std::regex_search(
        log, m,
        std::regex("fault operator ([0-9.e+-]+) MB counted, ([0-9.e+-]+) kB per fault node "
                   "\\(probed S ([0-9.e+-]+), its LU ([0-9.e+-]+), products kept ([0-9.e+-]+), "
                   "GMRES ([0-9.e+-]+)\\)")));
    const double total = std::stod(m[1]), perNode = std::stod(m[2]);
    double parts = 0;
    for (int g = 3; g <= 6; ++g) {
      CHECK(std::stod(m[g]) > 0);
      parts += std::stod(m[g]);
    }
    CHECK(std::abs(parts - total) <= 0.01 * total);  // each printed to 3 digits
    CHECK(std::abs(perNode - 1e3 * total / static_cast<double>(nodes)) <= 0.01 * perNode);
    CHECK(perNode * 1e3 < 0.25 * 32.0 * static_cast<double>(nodes));
  }
  {
    // Its dual solves visit the fault band's reach in the factor: the band holds at least the
    // three components of each fault node (of both sides where it has two), and the reach is
    // part of the factor.
    std::smatch m;
    REQUIRE(std::regex_search(
        log, m,
        std::regex("the fractures' reach in the factor \\(([0-9]+) unknowns at the fractures; a "
                   "product's back-substitution reads ([0-9.]+) % of the factor's values, "
                   "([0-9]+) of its ([0-9]+) supernodes\\)")));
    CHECK(std::stol(m[1]) >= 3 * nodes);
    CHECK(std::stol(m[1]) < dofsIn(log));
    CHECK(std::stod(m[2]) > 0);
    CHECK(std::stod(m[2]) <= 100);
    CHECK(std::stol(m[3]) > 0);
    CHECK(std::stol(m[3]) <= std::stol(m[4]));
  }

  Case c("pennyCrack", "penny-auto-condensed");
  fs::copy_file(k.dir() / msh, c.dir() / msh, fs::copy_options::overwrite_existing);
  c.edit("system/frictionSolution", "type +semismoothNewton;",
         "type semismoothNewton; variant condensed;");
  REQUIRE(c.solve() == 0);
  CHECK_THAT(c.log(), !Catch::Contains("Newton variant:"));  // given, not chosen
  CHECK_THAT(c.log(), Catch::Contains("jump unknowns last"));
  CHECK_THAT(c.log(), !Catch::Contains("reach in the factor"));  // the bordered factor: whole
  const Table a = c.namedTable("1", "fault"), b = k.namedTable("1", "fault");
  REQUIRE(a.rows.size() == b.rows.size());
  double scale = 0, differ = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    scale = std::max(scale, a.at(i, "slipMagnitude"));
    for (const char* col : {"slipX", "slipY", "slipZ"})
      differ = std::max(differ, std::abs(a.at(i, col) - b.at(i, col)));
  }
  REQUIRE(scale > 0);
  // Both stop at ‖D‖ ≤ 1e-10 ‖Σ‖: the slips agree to that times S's conditioning.
  CHECK(differ <= 1e-7 * scale);

  Case o("pennyCrack", "penny-auto-opening");
  fs::copy_file(k.dir() / msh, o.dir() / msh, fs::copy_options::overwrite_existing);
  o.edit("constant/fractureProperties", "frictionCoefficient 0.3;",
         "frictionCoefficient 0.3;\n    contact unilateral;");
  REQUIRE(o.solve() == 0);
  INFO(o.log());
  CHECK_THAT(o.log(),
             Catch::Contains("Newton variant: condensed (variant auto: " + std::to_string(nodes) +
                             " fracture control nodes >= " + threshold(o.log()) +
                             "; condensed all the same: the dense S is needed for "
                             "fractures that open (contact unilateral))\n"));
  CHECK_THAT(o.log(), Catch::Contains("jump unknowns last"));
}
