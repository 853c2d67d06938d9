// Quadrature rules for the finite-element layer (docs/method.md §4: mass, stiffness, loads and the
// error norms of the manufactured-solution test): symmetric rules and collapsed Gauss products
// on triangles, Gauss–Legendre on segments.
#pragma once

#include <array>
#include <vector>

namespace friction {

/// A rule on a triangle T: ∫_T f ≈ |T| Σ_q weights[q] f(x_q), with x_q given by its barycentric
/// coordinates (λ0, λ1, λ2) with respect to the triangle's vertices 0, 1, 2. The weights sum
/// to 1 (they are fractions of the area), so the same rule serves every triangle.
struct TriangleQuadrature {
  std::vector<std::array<double, 3>> barycentric;
  std::vector<double> weights;
  /// Polynomials of total degree ≤ degree are integrated exactly (up to round-off).
  int degree = 0;

  int size() const { return static_cast<int>(weights.size()); }
};

/// The cheapest rule this library has that is exact to total degree ≥ degree (degree ≥ 0):
/// centroid (1 point, degree 1), 3 interior points (degree 2), Radon's 7 points (degree 5),
/// and above that a collapsed (Duffy) product of Gauss–Legendre rules, all weights positive.
TriangleQuadrature triangleQuadrature(int degree);

/// Gauss–Legendre rule on the unit segment [0, 1]: ∫_0^1 f(s) ds ≈ Σ_q weights[q] f(points[q]).
/// The weights sum to 1; points are increasing.
struct SegmentQuadrature {
  std::vector<double> points;
  std::vector<double> weights;
  /// Polynomials of degree ≤ degree are integrated exactly: 2 · size − 1.
  int degree = 0;

  int size() const { return static_cast<int>(weights.size()); }
};

/// n-point Gauss–Legendre rule on [0, 1] (n ≥ 1), exact to degree 2n − 1. Nodes are computed
/// by Newton's method on the Legendre polynomial to full double precision.
SegmentQuadrature gaussLegendre(int numPoints);

/// Gauss–Legendre rule with the fewest points that is exact to degree ≥ degree.
SegmentQuadrature segmentQuadrature(int degree);

}  // namespace friction
