// Fracture tables (README.md, "Fracture tables"; issue 28 item 11): the values at tips, and the
// frame and slip-vector columns of the 2D table.
//  * A tip has no jump and no recovered traction; its row gives the body's stress at the node
//    (the mean over the cells around it, in-situ stress and pore-pressure term included)
//    resolved on the node's frame. Under a uniform stress that nothing makes slip, that is
//    exactly what every other node recovers: the tips' σ_n, τ, ST, σ'_n and ΔCFS equal the
//    interior rows' and the closed form n·σ·n, t·σ·n, in 2D and 3D, P1 and P2.
//  * 2D: nx ny tx ty are n_Γ and t_Γ (unit, orthogonal, n = (t_y, −t_x)), slipX slipY the slip
//    vector slip·t_Γ; on the inclined crack under vertical compression its sign is the
//    physical one: the upper block slides down the crack.
//  * No table and no .vtp holds a nan.
#include <algorithm>
#include <cmath>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "CaseRunner.hpp"

namespace friction::regression {

namespace {

// Round-off of the recovery (a few operations on values of size |σ|) and of the tables'
// twelve digits, far below the tolerance: 1e-8 relative to the stress's size.
constexpr double kRelative = 1e-8;

// No "nan" (nor "inf") in a time folder's tables and the VTK files (ASCII) of a case.
void checkNoNan(const fs::path& caseDir) {
  const std::regex bad("(^|[^A-Za-z])-?(inf|nan)([^A-Za-z]|$)", std::regex::icase);
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(caseDir)) {
    const std::string name = e.path().filename().string();
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() ||
        !(ext == ".vtp" || ext == ".vtu" ||
          (ext == ".dat" && e.path().parent_path().filename() == "fractures")))
      continue;
    ++files;
    INFO(e.path().string());
    CHECK_FALSE(std::regex_search(readText(e.path()), bad));
  }
  CHECK(files >= 3);  // the table, the .vtp and the .vtu at least
}

// Rows in state tip and the others (which must all stick: the state is uniform only then).
void splitRows(const Table& t, std::vector<std::size_t>& tips, std::vector<std::size_t>& others) {
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    INFO("row " << i << ", state " << t.state[i]);
    if (t.state[i] == "tip") {
      tips.push_back(i);
    } else {
      CHECK(t.state[i] == "stick");
      others.push_back(i);
    }
  }
  REQUIRE(tips.size() >= 2);
  REQUIRE(others.size() >= 3);
}

// Column `name` of every tip row equals that of every row in `others` (margin: kRelative ×
// scale) and the expected value given per row.
void checkColumn(const Table& t, const std::string& name, const std::vector<std::size_t>& tips,
                 const std::vector<std::size_t>& others, double scale,
                 const std::function<double(std::size_t)>& expected) {
  for (const std::size_t i : tips) {
    INFO(name << " at tip row " << i);
    CHECK(t.at(i, name) == Approx(expected(i)).epsilon(0).margin(kRelative * scale));
    for (const std::size_t j : others) {
      INFO("against row " << j);
      CHECK(t.at(i, name) == Approx(t.at(j, name)).epsilon(0).margin(kRelative * scale));
    }
  }
}

}  // namespace

TEST_CASE("fracture tables: a tip's tractions are the body's stress there (2D, uniform stress)",
          "[regression][format][tipStress]") {
  for (const int order : {1, 2}) {
    DYNAMIC_SECTION("P" << order) {
      // The inclined crack (rollers left and bottom, p = 1e7 Pa on top, the right side free)
      // with an in-situ stress and a uniform pore-pressure change: the total stress is σ⁰ +
      // diag(0, −p) everywhere (the boundary conditions act on the perturbation, whose total
      // stress the pore-pressure term is part of). μ_f = 100: nothing slips, the displacement
      // is linear, and every node's traction is that stress's.
      Case c("inclinedCrack", "tipStress2d-P" + std::to_string(order));
      c.edit("constant/fractureProperties", "frictionCoefficient 0\\.4;",
             "frictionCoefficient 100;");
      if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
      c.edit("system/controlDict", "writePrecision +12;", "writePrecision 12;\nvtkFormat ascii;");
      writeText(c.dir() / "constant/effects",
                "inSitu { type initialStress; stress (-2e7 -1.5e7 4e6); }\n"
                "rock { type porePressure; biotCoefficient 0.8; initial 1e6; "
                "change table ((0 0) (1 -3e6)); }\n");
      const int rc = c.solve();
      INFO(c.log());
      REQUIRE(rc == 0);
      const Table t = c.namedTable("1", "crack");
      std::vector<std::size_t> tips, others;
      splitRows(t, tips, others);
      Eigen::Matrix2d sigma;
      sigma << -2e7, 4e6, 4e6, -1.5e7 - 1e7;
      const double scale = 3e7, p = 1e6 - 3e6;  // p_b = initial + change at t = 1
      const auto n = [&](std::size_t i) { return Eigen::Vector2d(t.at(i, "nx"), t.at(i, "ny")); };
      const auto tg = [&](std::size_t i) { return Eigen::Vector2d(t.at(i, "tx"), t.at(i, "ty")); };
      const auto sn = [&](std::size_t i) { return n(i).dot(sigma * n(i)); };
      const auto tau = [&](std::size_t i) { return tg(i).dot(sigma * n(i)); };
      checkColumn(t, "sigmaN", tips, others, scale, sn);
      checkColumn(t, "tau", tips, others, scale, tau);
      checkColumn(t, "ST", tips, others, 1.0,
                  [&](std::size_t i) { return std::abs(tau(i)) / -(sn(i) + p); });
      checkColumn(t, "sigmaNEffective", tips, others, scale,
                  [&](std::size_t i) { return sn(i) + p; });
      // ΔCFS against the initial state (σ⁰ and p_b0 at startTime): Δ|τ| + μ_f Δσ'_n.
      Eigen::Matrix2d sigma0;
      sigma0 << -2e7, 4e6, 4e6, -1.5e7;
      checkColumn(t, "deltaCFS", tips, others, 100 * scale, [&](std::size_t i) {
        return std::abs(tau(i)) - std::abs(tg(i).dot(sigma0 * n(i))) +
               100 * (sn(i) + p - (n(i).dot(sigma0 * n(i)) + 1e6));
      });
      for (const std::size_t i : tips) {
        INFO("tip row " << i);
        CHECK(t.at(i, "residual") == 0.0);  // the law is not imposed at a tip
        CHECK(t.at(i, "slip") == 0.0);
      }
      checkNoNan(c.dir());
    }
  }
}

TEST_CASE("fracture tables: a tip's tractions are the body's stress there (3D, uniform stress)",
          "[regression][format][3d][tipStress]") {
  // The cube with its fault z = 1/2 (tip line inside the body): sides held in x and y, the
  // bottom fixed, the top moved down by 1 mm: u = (0, 0, −0.001 z), uniform strain. With an
  // in-situ stress whose shear loads the fault, σ = σ⁰ + C:ε everywhere, and μ_f = 10 holds it.
  // P2: the tip line's edge midpoints are tips too.
  for (const int order : {1, 2}) {
    DYNAMIC_SECTION("P" << order) {
      Case c("tests:faultInCube", "tipStress3d-P" + std::to_string(order));
      if (order == 2) c.edit("system/frictionSolution", "elementOrder +1;", "elementOrder 2;");
      c.edit("constant/fractureProperties", "frictionCoefficient 0\\.2;",
             "frictionCoefficient 10;");
      c.edit("0/D", "sides +\\{ type free; \\}",
             "sides   { type fixedDisplacement; components (x y); value (0 0 0); }");
      c.edit("0/D", "\\(0\\.002 0\\.001 -0\\.001\\)", "(0 0 -0.001)");
      writeText(c.dir() / "constant/effects",
                "inSitu { type initialStress; stress (-3e7 -3.5e7 -4e7 1e6 2e6 3e6); }\n");
      {
        const std::string dict = readText(c.dir() / "system/controlDict");
        writeText(c.dir() / "system/controlDict", dict + "\nvtkFormat ascii;\n");
      }
      const int rc = c.solve();
      INFO(c.log());
      REQUIRE(rc == 0);
      const Table t = c.namedTable("1", "fault");
      // E = 1e9 Pa, ν = 0.25: λ + 2μ = 1.2e9 Pa, λ = 4e8 Pa; ε_zz = −0.001.
      Eigen::Matrix3d sigma;
      sigma << -3e7 - 4e5, 1e6, 3e6, 1e6, -3.5e7 - 4e5, 2e6, 3e6, 2e6, -4e7 - 1.2e6;
      std::vector<std::size_t> tips, inside;
      std::vector<std::size_t> all;
      splitRows(t, tips, all);
      // The rows on the sides are held by the rollers, whose reactions their recovered traction
      // includes: compare with the rows inside.
      for (const std::size_t i : all)
        if (std::min({t.at(i, "x"), 1 - t.at(i, "x"), t.at(i, "y"), 1 - t.at(i, "y")}) > 1e-9)
          inside.push_back(i);
      REQUIRE(inside.size() >= 3);
      const auto n = [&](std::size_t i) {
        return Eigen::Vector3d(t.at(i, "nx"), t.at(i, "ny"), t.at(i, "nz"));
      };
      // The table's tangent basis: t₁ = tangentBasis(n) for this flat fault, from the frame line.
      std::smatch m;
      REQUIRE(t.comments.size() >= 2);
      REQUIRE(
          std::regex_search(t.comments[1], m,
                            std::regex("t1 \\(([^ ]+) ([^ ]+) ([^ )]+)\\) t2 \\(([^ ]+) ([^ ]+) "
                                       "([^ )]+)\\)")));
      const Eigen::Vector3d t1(std::stod(m[1]), std::stod(m[2]), std::stod(m[3]));
      const Eigen::Vector3d t2(std::stod(m[4]), std::stod(m[5]), std::stod(m[6]));
      const double scale = 4e7;
      checkColumn(t, "sigmaN", tips, inside, scale,
                  [&](std::size_t i) { return n(i).dot(sigma * n(i)); });
      checkColumn(t, "tau1", tips, inside, scale,
                  [&](std::size_t i) { return t1.dot(sigma * n(i)); });
      checkColumn(t, "tau2", tips, inside, scale,
                  [&](std::size_t i) { return t2.dot(sigma * n(i)); });
      checkColumn(t, "ST", tips, inside, 1.0, [&](std::size_t i) {
        const Eigen::Vector3d s = sigma * n(i);
        return (s - s.dot(n(i)) * n(i)).norm() / -s.dot(n(i));
      });
      for (const std::size_t i : tips) {
        INFO("tip row " << i);
        CHECK(t.at(i, "residual") == 0.0);
        CHECK(t.at(i, "slipMagnitude") == 0.0);
      }
      checkNoNan(c.dir());
    }
  }
}

TEST_CASE("fracture tables: 2D frame and slip-vector columns and the slip's physical sign",
          "[regression][format]") {
  // The inclined crack at 60° under vertical compression slips along its whole length
  // (cases/inclinedCrack/README.md): the block above it slides down the crack relative to the
  // one below.
  Case c("inclinedCrack", "frameColumns2d");
  c.edit("system/controlDict", "writePrecision +12;", "writePrecision 12;\nvtkFormat ascii;");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  const std::string text = readText(c.dir() / "1" / "fractures" / "crack.dat");
  // The columns of before keep their places: the new ones come just before the state.
  CHECK(text.rfind(
            "# s x y slip slipIncrement sigmaN tau ST residual nx ny tx ty slipX slipY state\n",
            0) == 0);
  const Table t = c.namedTable("1", "crack");
  int slipping = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    INFO("row " << i << ", state " << t.state[i]);
    const Eigen::Vector2d n(t.at(i, "nx"), t.at(i, "ny")), tg(t.at(i, "tx"), t.at(i, "ty"));
    CHECK(n.norm() == Approx(1).epsilon(1e-11));
    CHECK(tg.norm() == Approx(1).epsilon(1e-11));
    CHECK(std::abs(n.dot(tg)) <= 1e-11);
    // n_Γ = (t_y, −t_x) (SignConventions.hpp); the crack at 60°: t_Γ = (cos 60°, sin 60°).
    CHECK(n.x() == Approx(tg.y()).margin(1e-11));
    CHECK(n.y() == Approx(-tg.x()).margin(1e-11));
    CHECK(tg.x() == Approx(0.5).margin(1e-9));
    CHECK(tg.y() == Approx(std::sqrt(3.0) / 2).margin(1e-9));
    const double slip = t.at(i, "slip");
    CHECK(t.at(i, "slipX") == Approx(slip * tg.x()).margin(1e-12 * std::abs(slip) + 1e-300));
    CHECK(t.at(i, "slipY") == Approx(slip * tg.y()).margin(1e-12 * std::abs(slip) + 1e-300));
    if (t.state[i] != "slip") continue;
    ++slipping;
    // Ω⁺ (left of t_Γ) is the upper-left block; [[u]] = u⁺ − u⁻ is its motion relative to
    // the lower-right one: down the crack, towards −x and −y.
    CHECK(t.at(i, "slipX") < 0);
    CHECK(t.at(i, "slipY") < 0);
  }
  CHECK(slipping >= 10);  // the whole crack slips: the sign checks above checked some
  checkNoNan(c.dir());
}

}  // namespace friction::regression
