// Quadrature rules for the finite-element layer (docs/method.md §4: mass, stiffness, loads and the
// error norms of the manufactured-solution test): symmetric rules and collapsed Gauss products
// on triangles and tetrahedra, Gauss–Legendre on segments.
#pragma once

#include <array>
#include <vector>

namespace friction {

/// A rule on a simplex S of dimension dim (a segment, a triangle, a tetrahedron):
/// ∫_S f ≈ |S| Σ_q weights[q] f(x_q), with x_q given by its barycentric coordinates
/// (λ0, …, λ_dim) with respect to the simplex's vertices. The weights sum to 1 (they are
/// fractions of the length, area or volume), so the same rule serves every simplex.
template <int dim>
struct SimplexQuadrature {
  std::vector<std::array<double, dim + 1>> barycentric;
  std::vector<double> weights;
  /// Polynomials of total degree ≤ degree are integrated exactly (up to round-off).
  int degree = 0;

  int size() const { return static_cast<int>(weights.size()); }
};

using TriangleQuadrature = SimplexQuadrature<2>;
using TetrahedronQuadrature = SimplexQuadrature<3>;

/// The cheapest rule this library has that is exact to total degree ≥ degree (degree ≥ 0):
/// centroid (1 point, degree 1), 3 interior points (degree 2), Radon's 7 points (degree 5),
/// and above that a collapsed (Duffy) product of Gauss–Legendre rules, all weights positive.
/// The same rules integrate over the triangular faces of tetrahedra.
TriangleQuadrature triangleQuadrature(int degree);

/// The same for tetrahedra: centroid (1 point, degree 1), 4 interior points (degree 2),
/// Walkington's 14 points (degree 5, positive weights; also for degrees 3 and 4), and above
/// that a collapsed product of Gauss–Legendre rules, all weights positive.
TetrahedronQuadrature tetrahedronQuadrature(int degree);

/// The rule of the dimension: gaussLegendre in barycentric form (1 − s, s) for dim = 1,
/// triangleQuadrature for 2, tetrahedronQuadrature for 3. Facets of a dim-simplex use
/// simplexQuadrature<dim − 1>.
template <int dim>
SimplexQuadrature<dim> simplexQuadrature(int degree);
template <>
SimplexQuadrature<1> simplexQuadrature<1>(int degree);
template <>
SimplexQuadrature<2> simplexQuadrature<2>(int degree);
template <>
SimplexQuadrature<3> simplexQuadrature<3>(int degree);

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
