// Quadrature rules (see Quadrature.hpp). The low-degree triangle and tetrahedron rules are the
// classical symmetric ones; higher degrees use the conical (Duffy) product of Gauss–Legendre
// rules, which needs no tabulated constants and is exact for any degree we ask.
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

namespace {

void addPoint(TetrahedronQuadrature& rule, double l0, double l1, double l2, double l3, double w) {
  rule.barycentric.push_back({l0, l1, l2, l3});
  rule.weights.push_back(w);
}

/// The four permutations of (a, b, b, b) with one weight.
void addOrbit4(TetrahedronQuadrature& rule, double a, double b, double w) {
  addPoint(rule, a, b, b, b, w);
  addPoint(rule, b, a, b, b, w);
  addPoint(rule, b, b, a, b, w);
  addPoint(rule, b, b, b, a, w);
}

/// The six permutations of (a, a, b, b) with one weight.
void addOrbit6(TetrahedronQuadrature& rule, double a, double b, double w) {
  addPoint(rule, a, a, b, b, w);
  addPoint(rule, a, b, a, b, w);
  addPoint(rule, a, b, b, a, w);
  addPoint(rule, b, a, a, b, w);
  addPoint(rule, b, a, b, a, w);
  addPoint(rule, b, b, a, a, w);
}

}  // namespace

TetrahedronQuadrature tetrahedronQuadrature(int degree) {
  FRICTION_ASSERT(degree >= 0, "quadrature degree must be non-negative");
  TetrahedronQuadrature rule;
  if (degree <= 1) {
    rule.degree = 1;
    addPoint(rule, 0.25, 0.25, 0.25, 0.25, 1.0);
  } else if (degree == 2) {
    // Four interior points on the medians: a = (5 + 3√5)/20, b = (5 − √5)/20.
    rule.degree = 2;
    const double s = std::sqrt(5.0);
    addOrbit4(rule, (5.0 + 3.0 * s) / 20, (5.0 - s) / 20, 0.25);
  } else if (degree <= 5) {
    // Degree 5 with 14 points and positive weights (the classical degree-3 rule of 5 points
    // has a negative centroid weight, so it serves degrees 3 and 4 as well): N. J. Walkington,
    // "Quadrature on simplices of arbitrary dimension", Carnegie Mellon University, Center for
    // Nonlinear Analysis report 00-CNA-023 (2000). Two orbits (a, a, a, 1 − 3a) and one orbit
    // (c, c, 1/2 − c, 1/2 − c); weights as fractions of the volume.
    rule.degree = 5;
    const double a1 = 0.31088591926330060980, w1 = 0.11268792571801585080;
    const double a2 = 0.092735250310891226402, w2 = 0.073493043116361949544;
    const double c = 0.045503704125649649492, w3 = 0.042546020777081466438;
    addOrbit4(rule, 1.0 - 3 * a1, a1, w1);
    addOrbit4(rule, 1.0 - 3 * a2, a2, w2);
    addOrbit6(rule, c, 0.5 - c, w3);
  } else {
    // Collapsed product: ξ = u, η = (1 − u) v, ζ = (1 − u)(1 − v) w on the reference
    // tetrahedron, Jacobian (1 − u)² (1 − v). A polynomial of degree d becomes degree d + 2
    // in u, d + 1 in v and d in w, so n Gauss points with 2n − 1 ≥ d + 2 are exact.
    const int n = (degree + 4) / 2;
    const SegmentQuadrature g = gaussLegendre(n);
    rule.degree = 2 * n - 3;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const double u = g.points[i], v = g.points[j], w = g.points[k];
          const double xi = u, eta = (1.0 - u) * v, zeta = (1.0 - u) * (1.0 - v) * w;
          // Reference volume is 1/6: the fraction of volume is 6 · w_u w_v w_w (1 − u)² (1 − v).
          addPoint(
              rule, 1.0 - xi - eta - zeta, xi, eta, zeta,
              6.0 * g.weights[i] * g.weights[j] * g.weights[k] * (1.0 - u) * (1.0 - u) * (1.0 - v));
        }
  }
  return rule;
}

template <>
SimplexQuadrature<1> simplexQuadrature<1>(int degree) {
  const SegmentQuadrature g = segmentQuadrature(degree);
  SimplexQuadrature<1> rule;
  rule.degree = g.degree;
  rule.weights = g.weights;
  // λ0 = 1 − s, λ1 = s: the segment's own parameter s from its first to its second vertex.
  for (double s : g.points) rule.barycentric.push_back({1.0 - s, s});
  return rule;
}

template <>
SimplexQuadrature<2> simplexQuadrature<2>(int degree) {
  return triangleQuadrature(degree);
}

template <>
SimplexQuadrature<3> simplexQuadrature<3>(int degree) {
  return tetrahedronQuadrature(degree);
}

}  // namespace friction
