// Quadrature rules (fe/Quadrature.hpp): exactness on monomials up to the stated degree (on
// triangles, segments and a skewed tetrahedron), and failure one degree above (so the tests can
// tell a rule of the wrong degree).
#include <Eigen/Dense>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

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

namespace {

/// A polynomial in the barycentric coordinates (λ0, λ1, λ2, λ3) of a tetrahedron: exponents
/// → coefficient.
using BarycentricPolynomial = std::map<std::array<int, 4>, double>;

/// ∫_T x^a y^b z^c over the tetrahedron T with vertices v: x = Σ λ_i v_i expanded in the
/// barycentric coordinates, each monomial integrated by the Dirichlet formula
/// ∫_T Π λ_i^k_i = 6 |T| Π k_i! / (Σ k_i + 3)! (the reference tetrahedron's a! b! c! / (a + b +
/// c + 3)!, mapped).
double exactTetrahedronMonomial(const std::array<Eigen::Vector3d, 4>& v, double volume, int a,
                                int b, int c) {
  BarycentricPolynomial p{{{0, 0, 0, 0}, 1.0}};
  const int power[3] = {a, b, c};
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < power[axis]; ++k) {
      BarycentricPolynomial next;
      for (const auto& [e, coef] : p)
        for (int i = 0; i < 4; ++i) {
          std::array<int, 4> f = e;
          ++f[i];
          next[f] += coef * v[i][axis];
        }
      p = std::move(next);
    }
  double sum = 0.0;
  for (const auto& [e, coef] : p)
    sum += coef * 6.0 * volume * factorial(e[0]) * factorial(e[1]) * factorial(e[2]) *
           factorial(e[3]) / factorial(e[0] + e[1] + e[2] + e[3] + 3);
  return sum;
}

double ruleTetrahedronMonomial(const TetrahedronQuadrature& rule,
                               const std::array<Eigen::Vector3d, 4>& v, double volume, int a, int b,
                               int c) {
  double s = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) x += rule.barycentric[q][i] * v[i];
    s += rule.weights[q] * std::pow(x.x(), a) * std::pow(x.y(), b) * std::pow(x.z(), c);
  }
  return volume * s;
}

}  // namespace

TEST_CASE("fe tetrahedron quadrature is exact to its degree on a skewed tetrahedron",
          "[fe][quadrature]") {
  // A skewed tetrahedron (no symmetry), coordinates ≤ 1.3 in size, volume ≈ 0.12.
  const std::array<Eigen::Vector3d, 4> v = {
      Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1.3, 0.1, -0.1),
      Eigen::Vector3d(0.4, 1.1, 0.2), Eigen::Vector3d(0.9, 0.8, 0.55)};
  Eigen::Matrix3d J;
  for (int k = 0; k < 3; ++k) J.col(k) = v[k + 1] - v[0];
  const double volume = std::abs(J.determinant()) / 6;
  REQUIRE(volume > 0.05);
  // The reference: the exact integral of the Dirichlet formula checked on the reference
  // tetrahedron (v = 0, e_x, e_y, e_z) against a! b! c! / (a + b + c + 3)!.
  const std::array<Eigen::Vector3d, 4> ref = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                              Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  REQUIRE(exactTetrahedronMonomial(ref, 1.0 / 6, 2, 1, 3) ==
          Approx(factorial(2) * factorial(1) * factorial(3) / factorial(9)).epsilon(1e-14));

  // Round-off: sums of a few hundred products of numbers ≤ 1.3^9 ≈ 11 times the volume;
  // 1e-13 · volume · max|x|^degree is a margin of ~50, while a degree defect is ≥ 1e-5 (below).
  for (int requested : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}) {
    const TetrahedronQuadrature rule = tetrahedronQuadrature(requested);
    CAPTURE(requested, rule.degree, rule.size());
    REQUIRE(rule.degree >= requested);
    double sumW = 0.0;
    for (int q = 0; q < rule.size(); ++q) {
      REQUIRE(rule.weights[q] > 0.0);
      const auto& l = rule.barycentric[q];
      for (double li : l) REQUIRE(li >= 0.0);
      REQUIRE(l[0] + l[1] + l[2] + l[3] == Approx(1.0).margin(1e-15));
      sumW += rule.weights[q];
    }
    REQUIRE(sumW == Approx(1.0).margin(1e-14));
    for (int a = 0; a <= rule.degree; ++a)
      for (int b = 0; a + b <= rule.degree; ++b)
        for (int c = 0; a + b + c <= rule.degree; ++c) {
          CAPTURE(a, b, c);
          const double tol = 1e-13 * volume * std::pow(1.3, a + b + c);
          REQUIRE(ruleTetrahedronMonomial(rule, v, volume, a, b, c) ==
                  Approx(exactTetrahedronMonomial(v, volume, a, b, c)).margin(tol));
        }
  }
  REQUIRE(tetrahedronQuadrature(1).size() == 1);
  REQUIRE(tetrahedronQuadrature(2).size() == 4);
  REQUIRE(tetrahedronQuadrature(5).size() == 14);
  // One degree more is not integrated exactly by the fixed rules (the test could fail).
  for (int d : {1, 2, 5}) {
    const TetrahedronQuadrature rule = tetrahedronQuadrature(d);
    double worst = 0.0;
    for (int a = 0; a <= d + 1; ++a)
      for (int b = 0; a + b <= d + 1; ++b) {
        const int c = d + 1 - a - b;
        worst = std::max(worst, std::abs(ruleTetrahedronMonomial(rule, ref, 1.0 / 6, a, b, c) -
                                         exactTetrahedronMonomial(ref, 1.0 / 6, a, b, c)));
      }
    CAPTURE(d);
    REQUIRE(worst > 1e-5);
  }
}

TEST_CASE("fe simplexQuadrature picks the rule of the dimension", "[fe][quadrature]") {
  // dim = 1 is Gauss–Legendre in barycentric form (1 − s, s), the same numbers bit for bit.
  const SimplexQuadrature<1> s = simplexQuadrature<1>(7);
  const SegmentQuadrature g = gaussLegendre(4);
  REQUIRE(s.size() == 4);
  REQUIRE(s.degree == 7);
  for (int q = 0; q < 4; ++q) {
    REQUIRE(s.barycentric[q][1] == g.points[q]);
    REQUIRE(s.barycentric[q][0] == 1.0 - g.points[q]);
    REQUIRE(s.weights[q] == g.weights[q]);
  }
  REQUIRE(simplexQuadrature<2>(5).size() == triangleQuadrature(5).size());
  REQUIRE(simplexQuadrature<3>(5).size() == 14);
}
