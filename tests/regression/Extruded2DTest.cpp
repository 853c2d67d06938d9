// The 2D inclined crack (cases/inclinedCrack) extruded in z (tests/regression/cases/
// extrudedCrack: the same square and crack, two layers of prisms cut into tetrahedra, the
// crack a surface through both z faces, rollers u_z = 0 on the z faces) against the 2D solver
// on the matching 2D mesh (the base of the extrusion) and against the analytic slip.
//
// Plane strain: the 2D solution with u_z = 0 solves the 3D problem, so both discrete
// solutions approximate one field. They are not equal: P1 on tetrahedra cut from prisms is a
// larger space than the 2D P1 space extruded (it contains it, plus fields varying in z), and
// the cut is not symmetric in z, so the 2D solution is not the 3D Galerkin solution. The
// agreement is therefore to discretisation error, measured at two mesh sizes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "CaseRunner.hpp"

using namespace friction::regression;

namespace {

constexpr double kA = 0.05;    // crack half-length [m]
constexpr double kTheta = 60;  // crack angle from the x axis [degrees]
constexpr double kMuF = 0.4;

// Analytic slip magnitude (cases/inclinedCrack/README.md; plane strain, whole crack slipping,
// finite-square factor r = 1.0033).
double analyticSlip(double xi) {
  const double E = 10e9, nu = 0.25, tau = 4.3301e6, sigmaN = 2.5e6, r = 1.0033;
  return r * 4 * (1 - nu * nu) / E * (tau - kMuF * sigmaN) *
         std::sqrt(std::max(kA * kA - xi * xi, 0.0));
}

const double kPi = std::acos(-1.0);
const double kDx = std::cos(kTheta * kPi / 180), kDy = std::sin(kTheta * kPi / 180);

// Signed distance from the crack centre (0.5, 0.5) along the crack.
double xiOf(double x, double y) { return (x - 0.5) * kDx + (y - 0.5) * kDy; }

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

fs::path geoFile() {
  return fs::path(FRICTION_SOURCE_DIR) / "tests" / "regression" / "cases" / "extrudedCrack" /
         "constant" / "mesh" / "extrudedCrack.geo";
}

/// gmsh on extrudedCrack.geo with h = a/hDivisor, writing `out`.
void mesh(int dim, int hDivisor, const fs::path& out, const fs::path& log) {
  const std::string cmd = "gmsh -" + std::to_string(dim) + " -format msh41 -setnumber dim " +
                          std::to_string(dim) + " -setnumber h " + number(kA / hDivisor) + " '" +
                          geoFile().string() + "' -o '" + out.string() + "'";
  INFO(cmd << "\n" << readText(log));
  REQUIRE(run(cmd, log) == 0);
}

/// The 2D reference: cases/inclinedCrack on the base mesh of the extrusion.
std::vector<Row> solve2D(int hDivisor) {
  Case c("inclinedCrack", "extruded-2d-h" + std::to_string(hDivisor));
  mesh(2, hDivisor, c.dir() / "constant" / "mesh" / "inclinedCrack.msh", c.dir() / "log.gmsh");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  return c.table("1", "crack");
}

Table solve3D(int hDivisor) {
  Case c("tests:extrudedCrack", "extruded-3d-h" + std::to_string(hDivisor));
  const fs::path msh = c.dir() / "constant" / "mesh" / "extrudedCrack.msh";
  if (hDivisor == 16) {
    // The committed mesh is what the .geo makes (gmsh is deterministic: one thread, a seed).
    mesh(3, 16, c.dir() / "fresh.msh", c.dir() / "log.gmsh");
    CHECK(readText(c.dir() / "fresh.msh") == readText(msh));
  }
  mesh(3, hDivisor, msh, c.dir() / "log.gmsh");
  const int rc = c.solve();
  INFO(c.log());
  REQUIRE(rc == 0);
  return c.namedTable("1", "crack");
}

struct Agreement {
  double slip = 0;  ///< max over layers of ‖v3 − v2‖_L²(Γ) / ‖v2‖_L²(Γ), slip vectors
  double sigmaN = 0;                       ///< the same for σ_n
  double tau = 0;                          ///< the same for |τ|
  double slipZFaces = 0, slipZInside = 0;  ///< max |slipZ| / max |slip2D|: z faces, inside
  double analytic3 = 0, analytic2 = 0;     ///< relative L²(Γ) slip error against the formula
  int layers = 0, states = 0, compared = 0;
};

Agreement compare(const std::vector<Row>& two, const Table& three) {
  // 2D: t_Γ runs from the end smallest in x to the other (docs/method.md, sign conventions),
  // n_Γ = (t_y, −t_x).
  const double tx = kDx, ty = kDy, n2x = ty, n2y = -tx;
  const auto w = trapezoid(two);
  double slipMax = 0;
  for (const Row& r : two) slipMax = std::max(slipMax, std::abs(r.slip));
  REQUIRE(slipMax > 0);
  Agreement a;
  std::map<long, std::vector<std::size_t>> layer;  // z in units of 1e-9 m → rows
  for (std::size_t i = 0; i < three.rows.size(); ++i)
    layer[std::lround(three.at(i, "z") * 1e9)].push_back(i);
  a.layers = static_cast<int>(layer.size());
  double num2 = 0, den2 = 0;
  for (std::size_t j = 0; j < two.size(); ++j) {
    const double ana = analyticSlip(xiOf(two[j].x, two[j].y));
    num2 += w[j] * std::pow(std::abs(two[j].slip) - ana, 2);
    den2 += w[j] * ana * ana;
  }
  a.analytic2 = std::sqrt(num2 / den2);
  for (const auto& [z, rows] : layer) {
    INFO("layer z = " << z * 1e-9);
    REQUIRE(rows.size() == two.size());
    double ds = 0, ns = 0, dn = 0, nn = 0, dt = 0, nt = 0, da = 0, na = 0;
    for (std::size_t i : rows) {
      const double x = three.at(i, "x"), y = three.at(i, "y");
      const auto match = std::find_if(two.begin(), two.end(), [&](const Row& r) {
        return std::abs(r.x - x) <= 1e-12 && std::abs(r.y - y) <= 1e-12;
      });
      INFO("3D node (" << x << ", " << y << ")");
      REQUIRE(match != two.end());
      const std::size_t j = static_cast<std::size_t>(match - two.begin());
      ++a.compared;
      a.states += three.state[i] == two[j].state;
      // The two splitters may pick opposite sides as Ω⁺: the jump changes sign with n_Γ.
      const double side = three.at(i, "nx") * n2x + three.at(i, "ny") * n2y;
      REQUIRE(std::abs(std::abs(side) - 1) <= 1e-9);
      const double ex = side * two[j].slip * tx, ey = side * two[j].slip * ty;
      ds += w[j] * (std::pow(three.at(i, "slipX") - ex, 2) +
                    std::pow(three.at(i, "slipY") - ey, 2) + std::pow(three.at(i, "slipZ"), 2));
      ns += w[j] * two[j].slip * two[j].slip;
      double& slipZ =
          z == layer.begin()->first || z == layer.rbegin()->first ? a.slipZFaces : a.slipZInside;
      slipZ = std::max(slipZ, std::abs(three.at(i, "slipZ")) / slipMax);
      const double ana = analyticSlip(xiOf(x, y));
      da += w[j] * std::pow(three.at(i, "slipMagnitude") - ana, 2);
      na += w[j] * ana * ana;
      if (two[j].state == "tip") continue;
      dn += w[j] * std::pow(three.at(i, "sigmaN") - two[j].sigmaN, 2);
      nn += w[j] * two[j].sigmaN * two[j].sigmaN;
      dt += w[j] * std::pow(three.at(i, "tauMagnitude") - std::abs(two[j].tau), 2);
      nt += w[j] * two[j].tau * two[j].tau;
    }
    a.slip = std::max(a.slip, std::sqrt(ds / ns));
    a.sigmaN = std::max(a.sigmaN, std::sqrt(dn / nn));
    a.tau = std::max(a.tau, std::sqrt(dt / nt));
    a.analytic3 = std::max(a.analytic3, std::sqrt(da / na));
  }
  return a;
}

}  // namespace

// A roller holds only the jump component it fixes: on the z faces the crack's nodes keep
// their slip along the in-plane tangent and the slip's z component is held at zero
// (README, fracture node states).
//
// The tolerances are about 1.5 times the measured values: slip difference 0.0168 (a/8),
// 0.0077 (a/16), order 1.1; sigma_n and |tau| 0.024, 0.020 (the nodal tractions next to the
// tips converge slowly in both); max |slipZ| / max |slip| 1.3e-3, 7.8e-4 inside, 0 on the z
// faces; against the formula 3D 0.120, 0.065, 2D 0.112, 0.062.
TEST_CASE("3D: the inclined crack extruded in z agrees with the 2D solver on the base mesh",
          "[regression][3d]") {
  std::map<int, Agreement> at;
  for (int d : {8, 16}) {
    const std::vector<Row> two = solve2D(d);
    const Table three = solve3D(d);
    const Agreement a = compare(two, three);
    at[d] = a;
    WARN("h = a/" << d << ": " << a.layers << " layers, " << a.compared
                  << " nodes; relative L2 difference 3D - 2D: slip " << a.slip << ", sigmaN "
                  << a.sigmaN << ", |tau| " << a.tau << "; max |slipZ| / max |slip|: z faces "
                  << a.slipZFaces << ", inside " << a.slipZInside << "; states equal " << a.states
                  << "/" << a.compared << "; relative L2 error against the formula: 3D "
                  << a.analytic3 << ", 2D " << a.analytic2);
    // Two layers of thickness h: the z faces and one layer inside.
    CHECK(a.layers == 3);
    // Both within the inclined-crack test's bound of the formula (2.5 h/a).
    CHECK(a.analytic2 <= 2.5 / d);
    CHECK(a.analytic3 <= 2.5 / d);
    // Discretisation error: slip to 0.2 h/a (measured 0.13 h/a), tractions to 3 %.
    CHECK(a.slip <= 0.2 / d);
    CHECK(a.sigmaN <= 0.03);
    CHECK(a.tau <= 0.03);
    CHECK(a.states == a.compared);
    // u_z = 0 on both copies on the z faces: no z slip there at all. Inside, the cut of the
    // prisms is not symmetric in z, so a small z slip of the discretisation's size remains.
    CHECK(a.slipZFaces == 0.0);
    CHECK(a.slipZInside <= 2e-3);
  }
  // Discretisation error, not a modelling one: the difference shrinks with h at order >= 0.75
  // (as the inclined-crack test requires of the error itself; measured 1.1).
  CHECK(at[16].slip <= std::pow(2.0, -0.75) * at[8].slip);
}
