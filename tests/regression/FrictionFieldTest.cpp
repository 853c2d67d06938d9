// Friction coefficient, cohesion and threshold as fields along a fracture (issue #13;
// FrictionField.hpp), through the real binaries: every constant form of a field gives the
// number's outputs byte for byte (2D and 3D), a field changes the answer where the physics
// says it must (a bonded half sticks, Coulomb holds node by node with the node's own μ_f), and
// bad input is refused naming the file, the key and the place.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "CaseRunner.hpp"

using namespace friction::regression;

namespace {

const char* const kCube = "tests:faultInCube";

std::string fileOf(const Case& c, const std::string& relative) {
  return readText(c.dir() / relative);
}

/// The outputs a field must leave unchanged: the fracture table and the displacement.
void checkSameAs(const Case& base, const Case& c, const std::string& fracture) {
  const std::string table = "1/fractures/" + fracture + ".dat";
  REQUIRE(fs::exists(base.dir() / table));
  CHECK(fileOf(c, table) == fileOf(base, table));
  CHECK(fileOf(c, "1/D") == fileOf(base, "1/D"));
}

/// A points file "x y [z] value" with one row per row of the table (its coordinates as written).
void writePoints(const fs::path& file, const Table& t, int dim, double (*value)(double x)) {
  std::ofstream out(file);
  out.precision(17);
  out << "# x y" << (dim == 3 ? " z" : "") << " value\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    out << t.at(i, "x") << " " << t.at(i, "y") << " ";
    if (dim == 3) out << t.at(i, "z") << " ";
    out << value(t.at(i, "x")) << "\n";
  }
}

std::string setMu(const std::string& field) { return "frictionCoefficient " + field; }

}  // namespace

TEST_CASE("friction fields: every constant form equals the number (inclined crack, 2D)",
          "[regression][field]") {
  Case base("inclinedCrack", "field-base");
  REQUIRE(base.solve() == 0);
  const Table t = base.namedTable("1", "crack");
  struct Variant {
    const char* label;
    std::string field;
  };
  const std::vector<Variant> variants = {
      {"table", "{ type arclength; table ((0 0.4) (0.02 0.4) (1 0.4)); }"},
      {"depth", "{ type depth; value 0.4; gradient 0; reference 0.5; }"},
      {"points", "{ type points; file \"constant/mu.dat\"; }"},
  };
  for (const Variant& v : variants) {
    DYNAMIC_SECTION(v.label) {
      Case c("inclinedCrack", std::string("field-constant-") + v.label);
      c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;", setMu(v.field));
      writePoints(c.dir() / "constant" / "mu.dat", t, 2, [](double) { return 0.4; });
      REQUIRE(c.solve() == 0);
      INFO(c.log());
      // The range the log states: the number at every node.
      CHECK_THAT(c.log(), Catch::Contains("Fracture crack: frictionCoefficient from min 0.4 to "
                                          "max 0.4 over " +
                                          std::to_string(t.rows.size()) + " nodes"));
      checkSameAs(base, c, "crack");
    }
  }
}

TEST_CASE("friction fields: a bonded half of the inclined crack sticks, the other half slips",
          "[regression][field]") {
  // μ_f = 0.4 for s < 0.05 (the slip tendency there, 1.73, exceeds it: slip) and 10 beyond
  // (far above 1.73 and above what the slipping half adds at the transition: stick).
  Case c("inclinedCrack", "field-bonded-half");
  c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;",
         setMu("{ type arclength; table ((0 0.4) (0.05 0.4) (0.0500001 10) (1 10)); }"));
  REQUIRE(c.solve() == 0);
  INFO(c.log());
  CHECK_THAT(c.log(), Catch::Contains("frictionCoefficient from min 0.4 to max 10"));
  const Table t = c.namedTable("1", "crack");
  double maxSlip = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    maxSlip = std::max(maxSlip, std::abs(t.at(i, "slip")));
  REQUIRE(maxSlip > 1e-6);  // the free half slips (analytic scale 6e-5 m for the whole crack)
  int slipping = 0, sticking = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const double s = t.at(i, "s");
    INFO("row " << i << ", s = " << s << ", state " << t.state[i]);
    if (t.state[i] == "tip") continue;
    const double sigmaN = t.at(i, "sigmaN"), tau = std::abs(t.at(i, "tau"));
    REQUIRE(sigmaN < 0);  // compressed everywhere
    if (s > 0.0505) {
      // Bonded: no slip beyond the solver's tolerance (‖D‖ ≤ 1e-10 ‖Σ‖, D = γβ on stick
      // nodes, so β is 1e-10 of the traction's slip scale), and |τ| within the bound.
      CHECK(t.state[i] == "stick");
      CHECK(std::abs(t.at(i, "slip")) <= 1e-6 * maxSlip);
      CHECK(tau <= 10 * -sigmaN);
      ++sticking;
    } else if (s < 0.0495) {
      // Free: Coulomb at its bound with μ_f = 0.4 (the tolerance 1e-10 and the table's 12
      // digits: 1e-7 relative).
      CHECK(t.state[i] == "slip");
      CHECK(tau == Approx(0.4 * -sigmaN).epsilon(1e-7));
      ++slipping;
    }
  }
  CHECK(sticking >= 5);
  CHECK(slipping >= 5);
}

TEST_CASE("friction fields: with mu_f growing with depth, Coulomb holds with each node's mu_f",
          "[regression][field]") {
  // μ_f(y) = 0.4 − 4 (y − 0.5): 0.23 at the upper tip (y = 0.5433), 0.57 at the lower one.
  Case c("inclinedCrack", "field-depth");
  c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;",
         setMu("{ type depth; value 0.4; gradient -4; reference 0.5; }"));
  REQUIRE(c.solve() == 0);
  INFO(c.log());
  CHECK_THAT(c.log(), Catch::Contains("frictionCoefficient from min 0.22") &&
                          Catch::Contains("to max 0.57"));
  const Table t = c.namedTable("1", "crack");
  int slipping = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    INFO("row " << i << ", state " << t.state[i]);
    if (t.state[i] == "tip") continue;
    const double mu = 0.4 - 4 * (t.at(i, "y") - 0.5);
    const double sigmaN = t.at(i, "sigmaN"), tau = std::abs(t.at(i, "tau"));
    REQUIRE(sigmaN < 0);
    if (t.state[i] == "slip") {
      CHECK(tau == Approx(mu * -sigmaN).epsilon(1e-7));
      ++slipping;
    } else {
      CHECK(t.state[i] == "stick");
      CHECK(tau <= mu * -sigmaN * (1 + 1e-9));
    }
  }
  // Slip tendency 1.73 against μ_f ≤ 0.57: the whole crack slips.
  CHECK(slipping >= 10);
}

TEST_CASE(
    "friction fields in 3D: constant forms equal the number and a points field holds node "
    "by node",
    "[regression][field][3d]") {
  Case base(kCube, "field-3d-base");
  REQUIRE(base.solve() == 0);
  const Table t = base.namedTable("1", "fault");
  SECTION("depth, no gradient") {
    Case c(kCube, "field-3d-depth");
    c.edit("constant/fractureProperties", "frictionCoefficient 0\\.2;",
           setMu("{ type depth; value 0.2; gradient 0; }"));
    REQUIRE(c.solve() == 0);
    CHECK_THAT(c.log(), Catch::Contains("frictionCoefficient from min 0.2 to max 0.2"));
    checkSameAs(base, c, "fault");
  }
  SECTION("points, the same value at every node") {
    Case c(kCube, "field-3d-points");
    c.edit("constant/fractureProperties", "frictionCoefficient 0\\.2;",
           setMu("{ type points; file \"constant/mu.dat\"; }"));
    writePoints(c.dir() / "constant" / "mu.dat", t, 3, [](double) { return 0.2; });
    REQUIRE(c.solve() == 0);
    checkSameAs(base, c, "fault");
  }
  SECTION("points, mu_f 2 for x < 0.5 and 0.2 beyond") {
    Case c(kCube, "field-3d-halves");
    c.edit("constant/fractureProperties", "frictionCoefficient 0\\.2;",
           setMu("{ type points; file \"constant/mu.dat\"; }"));
    const auto mu = [](double x) { return x < 0.5 ? 2.0 : 0.2; };
    writePoints(c.dir() / "constant" / "mu.dat", t, 3, mu);
    REQUIRE(c.solve() == 0);
    INFO(c.log());
    const Table h = c.namedTable("1", "fault");
    REQUIRE(h.rows.size() == t.rows.size());
    int slipLow = 0, stickHigh = 0;
    for (std::size_t i = 0; i < h.rows.size(); ++i) {
      INFO("row " << i << ", state " << h.state[i]);
      if (h.state[i] == "tip") continue;
      const double m = mu(h.at(i, "x")), sigmaN = h.at(i, "sigmaN"), tau = h.at(i, "tauMagnitude");
      REQUIRE(sigmaN < 0);
      if (h.state[i] == "slip") {
        CHECK(tau == Approx(m * -sigmaN).epsilon(1e-7));
        slipLow += m == 0.2;
      } else {
        CHECK(h.state[i] == "stick");
        CHECK(tau <= m * -sigmaN * (1 + 1e-9));
        stickHigh += m == 2.0;
      }
    }
    // The base case slips on most nodes with 0.2; μ_f = 2 sticks everywhere on its own.
    CHECK(slipLow >= 5);
    CHECK(stickHigh >= 5);
  }
}

TEST_CASE("friction fields: a Tresca threshold along the crack bounds |tau| node by node",
          "[regression][field]") {
  // g(s) = 2 MPa at s = 0 to 8 MPa at s = 0.1 against |τ| = 4.33 MPa far from the crack: the
  // low end slips at its own bound, the high end may hold.
  Case c("inclinedCrack", "field-tresca");
  c.edit("constant/fractureProperties", "law +coulomb;\\s*frictionCoefficient 0\\.4;",
         "law tresca; threshold { type arclength; table ((0 2e6) (0.1 8e6) (1 8e6)); }");
  REQUIRE(c.solve() == 0);
  INFO(c.log());
  CHECK_THAT(c.log(), Catch::Contains("Fracture crack: threshold from min 2e+06 to max 8e+06"));
  const Table t = c.namedTable("1", "crack");
  int slipping = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    INFO("row " << i << ", state " << t.state[i]);
    if (t.state[i] == "tip") continue;
    const double g = 2e6 + 6e6 * std::min(t.at(i, "s") / 0.1, 1.0), tau = std::abs(t.at(i, "tau"));
    if (t.state[i] == "slip") {
      CHECK(tau == Approx(g).epsilon(1e-7));
      ++slipping;
    } else {
      CHECK(t.state[i] == "stick");
      CHECK(tau <= g * (1 + 1e-9));
    }
  }
  CHECK(slipping >= 5);
}

TEST_CASE(
    "friction fields on P2: a points file over vertices and midpoints equals the number and "
    "the depth field holds at the midpoints too",
    "[regression][field]") {
  const auto p2 = [](Case& c) {
    c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
  };
  Case base("inclinedCrack", "field-P2-base");
  p2(base);
  REQUIRE(base.solve() == 0);
  const Table t = base.namedTable("1", "crack");
  SECTION("points, 0.4 at every node") {
    Case c("inclinedCrack", "field-P2-points");
    p2(c);
    c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;",
           setMu("{ type points; file \"constant/mu.dat\"; }"));
    writePoints(c.dir() / "constant" / "mu.dat", t, 2, [](double) { return 0.4; });
    REQUIRE(c.solve() == 0);
    checkSameAs(base, c, "crack");
  }
  SECTION("depth: Coulomb with each node's own mu_f, midpoints included") {
    Case c("inclinedCrack", "field-P2-depth");
    p2(c);
    c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;",
           setMu("{ type depth; value 0.4; gradient -4; reference 0.5; }"));
    REQUIRE(c.solve() == 0);
    INFO(c.log());
    const Table d = c.namedTable("1", "crack");
    int slipping = 0;
    for (std::size_t i = 0; i < d.rows.size(); ++i) {
      INFO("row " << i << ", state " << d.state[i]);
      if (d.state[i] != "slip") continue;
      const double mu = 0.4 - 4 * (d.at(i, "y") - 0.5);
      CHECK(std::abs(d.at(i, "tau")) == Approx(mu * -d.at(i, "sigmaN")).epsilon(1e-7));
      ++slipping;
    }
    // P2 has twice the nodes of P1's 33, nearly all of them slipping (slip tendency 1.73).
    CHECK(slipping >= 40);
  }
}

TEST_CASE(
    "friction fields: a cohesion field with depth, |tau| = c(y) - mu_f sigma_n where it "
    "slips",
    "[regression][field]") {
  // c(y) = 0.5 MPa − 10 MPa/m (y − 0.5): 0.067 MPa at the upper tip, 0.93 MPa at the lower
  // one, all below the driving τ_eff = 3.33 MPa: the crack slips, each node at its own bound.
  Case c("inclinedCrack", "field-cohesion");
  c.edit("constant/fractureProperties", "law +coulomb;",
         "law coulombCohesion; cohesion { type depth; value 5e5; gradient -1e7; reference 0.5; }");
  REQUIRE(c.solve() == 0);
  INFO(c.log());
  CHECK_THAT(c.log(), Catch::Contains("Fracture crack: cohesion from min 6") &&
                          Catch::Contains(" Pa over 33 nodes"));
  const Table t = c.namedTable("1", "crack");
  int slipping = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    INFO("row " << i << ", state " << t.state[i]);
    if (t.state[i] == "tip") continue;
    const double bound = 5e5 - 1e7 * (t.at(i, "y") - 0.5) - 0.4 * t.at(i, "sigmaN");
    const double tau = std::abs(t.at(i, "tau"));
    if (t.state[i] == "slip") {
      CHECK(tau == Approx(bound).epsilon(1e-7));
      ++slipping;
    } else {
      CHECK(t.state[i] == "stick");
      CHECK(tau <= bound * (1 + 1e-9));
    }
  }
  CHECK(slipping >= 10);
}
