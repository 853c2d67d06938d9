// Values at points at listed times (flow/PointData.hpp): the k-d tree finds what a scan in order
// finds (ties included: the effects' nearest rows must not depend on the search), the rows are
// grouped by time, and a time is bracketed linearly between the listed times, constantly beyond.
#include <catch2/catch.hpp>
#include <random>

#include "../dict/DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/flow/PointData.hpp"

using namespace friction;

TEST_CASE("NearestPoint: the nearest point as a scan finds it, ties to the lowest index",
          "[flow][pointData]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int dim : {2, 3}) {
    for (bool grid : {false, true}) {
      // Random points, or a coarse grid (in 2D each point listed four times) where queries at
      // the cells' centres are equally near to several points.
      std::vector<Point> points;
      for (int i = 0; i < (grid ? 64 : 300); ++i)
        points.push_back(grid ? Point(i % 4 * 0.5 - 0.75, i / 4 % 4 * 0.5 - 0.75,
                                      dim == 3 ? i / 16 * 0.5 - 0.75 : 0.0)
                              : Point(u(random), u(random), dim == 3 ? u(random) : 0.0));
      const NearestPoint tree(points);
      int ties = 0;
      for (int q = 0; q < 2000; ++q) {
        // Half the queries at grid cell centres, equidistant from several grid points.
        const Point x = q % 2 ? Point(u(random), u(random), dim == 3 ? u(random) : 0.0)
                              : Point(q / 2 % 3 * 0.5 - 0.5, q / 6 % 3 * 0.5 - 0.5,
                                      dim == 3 ? q / 18 % 3 * 0.5 - 0.5 : 0.0);
        std::size_t best = 0;
        double bestD2 = std::numeric_limits<double>::infinity();
        int equal = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
          const double d2 = (points[i] - x).squaredNorm();
          if (d2 < bestD2) bestD2 = d2, best = i, equal = 0;
          if (d2 == bestD2) ++equal;
        }
        ties += equal > 1;
        double d2 = -1;
        REQUIRE(tree.nearest(x, d2) == best);
        CHECK(d2 == bestD2);
      }
      CHECK((ties > 100) == grid);
    }
  }
}

TEST_CASE("PointData: rows grouped by time, nearest values, the bracket of a time",
          "[flow][pointData]") {
  dicttest::TempDir dir;
  dir.write("p.dat", "# t x y p\n0 0 0 1\n0 1 0 2\n\n5 1 0 20\n5 0 0 10\n5 0 1 30\n");
  const Dictionary d = Dictionary::parse("data \"p.dat\";", "constant/effects");
  const PointData data = PointData::read(d, "data", dir.path().string(), 2, "p", "value [Pa]");
  REQUIRE(data.times() == std::vector<double>{0, 5});
  CHECK(data.rows(1).size() == 3);
  CHECK(data.rows(1)[0].line == 5);
  CHECK(data.describe() == "data from " + (dir.path() / "p.dat").string() + " at 2 times");
  const std::vector<Eigen::VectorXd> v =
      data.nearestValues({Point(0.1, 0, 0), Point(0.9, 0.2, 0), Point(0.2, 0.9, 0)});
  CHECK(v[0] == Eigen::Vector3d(1, 2, 1));
  CHECK(v[1] == Eigen::Vector3d(10, 20, 30));
  const auto at = [&](double t) {
    const PointData::Bracket b = data.bracket(t);
    return v[b.lower][0] + b.weight * (v[b.upper][0] - v[b.lower][0]);
  };
  CHECK(at(-1) == 1);
  CHECK(at(0) == 1);
  CHECK(at(2) == Approx(1 + 2.0 / 5 * 9).epsilon(1e-15));
  CHECK(at(5) == 10);
  CHECK(at(50) == 10);
}
