// strikeDipBasis (FieldWriter.hpp): the strike is horizontal and in the fault plane, the dip
// points down the plane, both unit and orthogonal to each other and to n, and do not depend
// on which side n points to (the fault dips to the strike's right); a horizontal fault takes
// the stated rule (strike = x, dip = −y). strikeDipValues: the hanging wall's slip and τ on
// that basis, the same whichever side n_Γ points to.
#include <catch2/catch.hpp>
#include <cmath>

#include "friction/fracture/SignConventions.hpp"
#include "friction/output/FieldWriter.hpp"

using namespace friction;

TEST_CASE("strike and down-dip vectors of dipping, vertical and horizontal faults",
          "[output][strikeDip]") {
  const double pi = std::acos(-1.0);
  for (double dipAngle : {10.0, 45.0, 60.0, 89.0, 90.0})
    for (double azimuth : {0.0, 30.0, 135.0, 250.0})
      for (double side : {1.0, -1.0}) {
        CAPTURE(dipAngle, azimuth, side);
        // The normal of a plane dipping by dipAngle towards the azimuth (from x, about z).
        const double d = dipAngle * pi / 180, a = azimuth * pi / 180;
        const Eigen::Vector3d n = side * Eigen::Vector3d(std::sin(d) * std::cos(a),
                                                         std::sin(d) * std::sin(a), std::cos(d));
        Eigen::Vector3d strike, dip;
        strikeDipBasis(n, strike, dip);
        CHECK(strike.norm() == Approx(1).epsilon(1e-14));
        CHECK(dip.norm() == Approx(1).epsilon(1e-14));
        CHECK(std::abs(strike.dot(n)) < 1e-14);
        CHECK(std::abs(dip.dot(n)) < 1e-14);
        CHECK(std::abs(strike.dot(dip)) < 1e-14);
        CHECK(std::abs(strike.z()) < 1e-14);  // horizontal
        // Down the plane by the dip angle (vertical faults: straight down).
        CHECK(dip.z() == Approx(-std::sin(d)).epsilon(1e-12));
        // Either side's normal gives the same pair.
        Eigen::Vector3d strike2, dip2;
        strikeDipBasis(-n, strike2, dip2);
        CHECK((dip2 - dip).norm() < 1e-14);
        CHECK((strike2 - strike).norm() < 1e-14);
        // Right-hand rule: seen from above, dip is strike turned clockwise by 90°.
        if (dipAngle < 90) {
          const Eigen::Vector2d s2 = strike.head<2>(), d2 = dip.head<2>().normalized();
          CHECK((d2 - Eigen::Vector2d(s2.y(), -s2.x())).norm() < 1e-12);
        }
      }
  // Exactly vertical: dip straight down, strike of azimuth in [0°, 180°), either side.
  for (double azimuth : {0.0, 30.0, 90.0, 135.0, 250.0})
    for (double side : {1.0, -1.0}) {
      const double a = azimuth * pi / 180;
      Eigen::Vector3d strike, dip;
      strikeDipBasis(side * Eigen::Vector3d(std::cos(a), std::sin(a), 0), strike, dip);
      CHECK(dip == -Eigen::Vector3d::UnitZ());
      CHECK(strike.allFinite());
      CHECK(strike.norm() == Approx(1).epsilon(1e-14));
      CHECK(std::abs(strike.z()) == 0);
      CHECK((strike.x() > 1e-15 || (std::abs(strike.x()) <= 1e-15 && strike.y() > 0)));
    }
  Eigen::Vector3d strike, dip;
  strikeDipBasis(Eigen::Vector3d(0, 0, -1), strike, dip);
  CHECK(strike == Eigen::Vector3d::UnitX());
  CHECK(dip == -Eigen::Vector3d::UnitY());
}

namespace {

// A row of normal n on the node's tangent basis, with the jump `slip` (Ω⁺ minus Ω⁻) and the
// traction `tau` on Ω⁺ given as vectors [m, Pa].
FractureRow rowOf(const Eigen::Vector3d& n, const Eigen::Vector3d& slip,
                  const Eigen::Vector3d& tau) {
  FractureRow r;
  r.normal = n;
  r.tangent = tangentBasis(n);
  for (std::size_t c = 0; c < 2; ++c) {
    r.slip[c] = slip.dot(r.tangent[c]);
    r.tau[c] = tau.dot(r.tangent[c]);
  }
  return r;
}

}  // namespace

TEST_CASE("strike and dip values are the hanging wall's, whichever side n points to",
          "[output][strikeDip]") {
  const double pi = std::acos(-1.0);
  // A normal fault dipping 60° to the azimuth a, its hanging wall (above) moving down dip by
  // 2 mm and along strike by 1 mm, the traction on it opposite (Coulomb).
  for (double azimuth : {0.0, 100.0, 150.0, 250.0}) {
    CAPTURE(azimuth);
    const double d = 60 * pi / 180, a = azimuth * pi / 180;
    const Eigen::Vector3d up(std::sin(d) * std::cos(a), std::sin(d) * std::sin(a), std::cos(d));
    Eigen::Vector3d strike, dip;
    strikeDipBasis(up, strike, dip);
    const Eigen::Vector3d hangingSlip = 1e-3 * strike + 2e-3 * dip, hangingTau = -3e6 * dip;
    // n_Γ down (from the hanging wall: Ω⁺ is the hanging wall) and up (Ω⁺ the footwall, whose
    // jump and traction are the opposite ones).
    const std::array<double, 4> down = strikeDipValues(rowOf(-up, hangingSlip, hangingTau));
    const std::array<double, 4> upward = strikeDipValues(rowOf(up, -hangingSlip, -hangingTau));
    const std::array<double, 4> expected = {1e-3, 2e-3, 0, -3e6};
    for (std::size_t c = 0; c < 4; ++c) {
      const double scale = c < 2 ? 1e-3 : 3e6;
      CHECK(std::abs(down[c] - expected[c]) < 1e-12 * scale);
      CHECK(std::abs(upward[c] - expected[c]) < 1e-12 * scale);
    }
  }
  // A vertical fault: the hanging wall is the side to the right of strike (seen from above).
  const Eigen::Vector3d n(0, 1, 0);  // strike +x (azimuth 0°), right of it: −y
  Eigen::Vector3d strike, dip;
  strikeDipBasis(n, strike, dip);
  REQUIRE(strike == Eigen::Vector3d::UnitX());
  const Eigen::Vector3d slip = 1e-3 * strike;  // the −y side moves along +x
  CHECK(strikeDipValues(rowOf(n, slip, Eigen::Vector3d::Zero()))[0] == Approx(1e-3).epsilon(1e-12));
  CHECK(strikeDipValues(rowOf(-n, -slip, Eigen::Vector3d::Zero()))[0] ==
        Approx(1e-3).epsilon(1e-12));
  // A horizontal fault: the hanging wall is the side above.
  CHECK(strikeDipValues(rowOf(Eigen::Vector3d(0, 0, -1), 1e-3 * Eigen::Vector3d::UnitX(),
                              Eigen::Vector3d::Zero()))[0] == Approx(1e-3).epsilon(1e-12));
  CHECK(strikeDipValues(rowOf(Eigen::Vector3d(0, 0, 1), -1e-3 * Eigen::Vector3d::UnitX(),
                              Eigen::Vector3d::Zero()))[0] == Approx(1e-3).epsilon(1e-12));
}
