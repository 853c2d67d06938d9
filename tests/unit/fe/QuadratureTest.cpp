// Quadrature rules (fe/Quadrature.hpp): exactness on monomials up to the stated degree, and
// failure one degree above (so the tests can tell a rule of the wrong degree).
#include <catch2/catch.hpp>
#include <cmath>

#include "friction/fe/Quadrature.hpp"

using namespace friction;

namespace {

double factorial(int k) { return k <= 1 ? 1.0 : k * factorial(k - 1); }

/// ∫ over the reference triangle (0,0), (1,0), (0,1) of ξ^i η^j = i! j! / (i + j + 2)!,
/// divided by its area 1/2 (the rules' weights are area fractions).
double exactMeanMonomial(int i, int j) {
  return 2.0 * factorial(i) * factorial(j) / factorial(i + j + 2);
}

double ruleMeanMonomial(const TriangleQuadrature& rule, int i, int j) {
  double s = 0.0;
  for (int q = 0; q < rule.size(); ++q)
    s +=
        rule.weights[q] * std::pow(rule.barycentric[q][1], i) * std::pow(rule.barycentric[q][2], j);
  return s;
}

}  // namespace

TEST_CASE("fe triangle quadrature is exact to its degree", "[fe][quadrature]") {
  // Round-off: a handful of products and sums of O(1) numbers, ≈ 1e-16 each; 1e-14 leaves a
  // margin of about 50 while any real degree defect is ≥ 1e-4 (checked below).
  for (int requested : {0, 1, 2, 3, 4, 5, 6, 7, 8, 10}) {
    const TriangleQuadrature rule = triangleQuadrature(requested);
    CAPTURE(requested, rule.degree, rule.size());
    REQUIRE(rule.degree >= requested);
    double sumW = 0.0;
    for (int q = 0; q < rule.size(); ++q) {
      REQUIRE(rule.weights[q] > 0.0);
      const auto& l = rule.barycentric[q];
      REQUIRE(l[0] + l[1] + l[2] == Approx(1.0).margin(1e-15));
      sumW += rule.weights[q];
    }
    REQUIRE(sumW == Approx(1.0).margin(1e-14));
    for (int i = 0; i <= rule.degree; ++i)
      for (int j = 0; i + j <= rule.degree; ++j) {
        CAPTURE(i, j);
        REQUIRE(ruleMeanMonomial(rule, i, j) == Approx(exactMeanMonomial(i, j)).margin(1e-14));
      }
  }
  // One degree more is not integrated exactly by the fixed rules (the test could fail).
  for (int d : {1, 2, 5}) {
    const TriangleQuadrature rule = triangleQuadrature(d);
    double worst = 0.0;
    for (int i = 0; i <= d + 1; ++i)
      worst = std::max(
          worst, std::abs(ruleMeanMonomial(rule, i, d + 1 - i) - exactMeanMonomial(i, d + 1 - i)));
    CAPTURE(d);
    REQUIRE(worst > 1e-4);
  }
}

TEST_CASE("fe Gauss-Legendre on a segment is exact to degree 2n-1", "[fe][quadrature]") {
  // Newton converges to machine precision; 1e-14 is a margin of ~50 over round-off.
  for (int n = 1; n <= 8; ++n) {
    const SegmentQuadrature rule = gaussLegendre(n);
    CAPTURE(n);
    REQUIRE(rule.degree == 2 * n - 1);
    for (int q = 1; q < n; ++q) REQUIRE(rule.points[q] > rule.points[q - 1]);
    for (int k = 0; k <= 2 * n; ++k) {
      double s = 0.0;
      for (int q = 0; q < n; ++q) s += rule.weights[q] * std::pow(rule.points[q], k);
      CAPTURE(k);
      if (k <= 2 * n - 1)
        REQUIRE(s == Approx(1.0 / (k + 1)).margin(1e-14));
      else  // degree 2n is not exact: the remainder is (n!)⁴ / ((2n + 1) ((2n)!)²) for
            // x^{2n} on [0, 1]; it is ≥ 3e-10 here, so 1e-4 relative is far above round-off.
        REQUIRE(s - 1.0 / (k + 1) ==
                Approx(-std::pow(factorial(n), 4) / ((2 * n + 1) * std::pow(factorial(2 * n), 2)))
                    .epsilon(1e-4));
    }
  }
  REQUIRE(segmentQuadrature(7).size() == 4);
  REQUIRE(segmentQuadrature(8).size() == 5);
}
