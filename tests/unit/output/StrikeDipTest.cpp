// strikeDipBasis (FieldWriter.hpp): the strike is horizontal and in the fault plane, the dip
// points down the plane, both unit and orthogonal to each other and to n, and do not depend
// on which side n points to (the fault dips to the strike's right); a horizontal fault takes
// the stated rule (strike = x, dip = −y).
#include <catch2/catch.hpp>
#include <cmath>

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
