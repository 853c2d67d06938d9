// Quadrature rules (see Quadrature.hpp). The low-degree triangle rules are the classical
// closed-form ones; higher degrees use the conical (Duffy) product of Gauss–Legendre rules,
// which needs no tabulated constants and is exact for any degree we ask.
#include "friction/fe/Quadrature.hpp"

#include <cmath>

#include "friction/core/Assert.hpp"

namespace friction {

SegmentQuadrature gaussLegendre(int numPoints) {
  FRICTION_ASSERT(numPoints >= 1, "a Gauss rule needs at least one point");
  const int n = numPoints;
  SegmentQuadrature rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  rule.degree = 2 * n - 1;
  const double pi = std::acos(-1.0);
  // Roots of P_n on [-1, 1] by Newton from Chebyshev-like guesses; the rule is symmetric, so
  // only half the roots are computed and mirrored (this also keeps the middle node exactly 0).
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;  // P_0, P_1, then the three-term recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Recompute P_n' at the converged root for the weight 2 / ((1 − x²) P_n'²).
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1.0);
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    if (2 * i + 1 == n) x = 0.0;
    // Map [-1, 1] → [0, 1]: s = (1 + x)/2, weights halve. Root i is the (n-1-i)-th from left.
    rule.points[n - 1 - i] = 0.5 * (1.0 + x);
    rule.points[i] = 0.5 * (1.0 - x);
    rule.weights[n - 1 - i] = 0.5 * w;
    rule.weights[i] = 0.5 * w;
  }
  return rule;
}

SegmentQuadrature segmentQuadrature(int degree) {
  const int n = degree <= 1 ? 1 : (degree + 2) / 2;  // 2n − 1 ≥ degree
  return gaussLegendre(n);
}

namespace {

void addPoint(TriangleQuadrature& rule, double l0, double l1, double l2, double w) {
  rule.barycentric.push_back({l0, l1, l2});
  rule.weights.push_back(w);
}

/// The three permutations (a, b, b), (b, a, b), (b, b, a) with one weight.
void addOrbit3(TriangleQuadrature& rule, double a, double b, double w) {
  addPoint(rule, a, b, b, w);
  addPoint(rule, b, a, b, w);
  addPoint(rule, b, b, a, w);
}

}  // namespace

TriangleQuadrature triangleQuadrature(int degree) {
  FRICTION_ASSERT(degree >= 0, "quadrature degree must be non-negative");
  TriangleQuadrature rule;
  if (degree <= 1) {
    rule.degree = 1;
    addPoint(rule, 1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0);
  } else if (degree == 2) {
    // Interior three-point rule (Strang–Fix): points (2/3, 1/6, 1/6) and permutations.
    rule.degree = 2;
    addOrbit3(rule, 2.0 / 3, 1.0 / 6, 1.0 / 3);
  } else if (degree <= 5) {
    // Radon's seven-point rule, degree 5, in closed form.
    rule.degree = 5;
    const double s = std::sqrt(15.0);
    addPoint(rule, 1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40);
    const double a1 = (6.0 - s) / 21, w1 = (155.0 - s) / 1200;
    const double a2 = (6.0 + s) / 21, w2 = (155.0 + s) / 1200;
    addOrbit3(rule, 1.0 - 2 * a1, a1, w1);
    addOrbit3(rule, 1.0 - 2 * a2, a2, w2);
  } else {
    // Collapsed product: ξ = u, η = (1 − u) v on the reference triangle, Jacobian (1 − u).
    // A polynomial of degree d becomes degree d + 1 in u and d in v, so n Gauss points with
    // 2n − 1 ≥ d + 1 in each direction are exact.
    const int n = (degree + 3) / 2;
    const SegmentQuadrature g = gaussLegendre(n);
    rule.degree = 2 * n - 2;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = g.points[i], v = g.points[j];
        const double xi = u, eta = (1.0 - u) * v;
        // Reference area is 1/2: the fraction of area is 2 · w_u w_v (1 − u).
        addPoint(rule, 1.0 - xi - eta, xi, eta, 2.0 * g.weights[i] * g.weights[j] * (1.0 - u));
      }
  }
  return rule;
}

}  // namespace friction
