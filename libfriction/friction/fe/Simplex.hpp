// Simplex kernels: geometry, P1 / P2 Lagrange bases, element stiffness and load integrals on
// affine triangles (dim = 2) and tetrahedra (dim = 3), templated on the dimension and
// instantiated for 2 and 3 in Simplex.cpp (docs/method.md §1, §4, §7).
//
// Element geometry is carried by barycentric coordinates: on an affine simplex ∇λ_i is
// constant, so every basis gradient is a polynomial in λ times the ∇λ_i, and no
// reference-element Jacobian inverse per quadrature point is needed. The kernels know nothing
// of meshes: they take the dim + 1 vertex coordinates of one cell.
//
// Local node order (the order LagrangeSpace and the mesh readers give a cell's nodes):
//  * P1: the vertices 0 … dim.
//  * P2 triangle: v0 v1 v2, mid(01), mid(12), mid(20).
//  * P2 tetrahedron: v0 v1 v2 v3, mid(01), mid(12), mid(20), mid(03), mid(13), mid(23): VTK's
//    VTK_QUADRATIC_TETRA order. gmsh's 10-node tetrahedron (element type 11) numbers its edges
//    (01), (12), (20), (30), (32), (31): its nodes 8 and 9 are our 9 and 8, so a gmsh reader
//    swaps those two (edge direction does not matter for a midpoint).
// Facet node order: the 2D edge (a, b) is (a, [mid], b), as LagrangeSpace::edgeNodes; a
// triangular face of a tetrahedron is ordered as a P1 / P2 triangle.
#pragma once

#include <Eigen/Core>
#include <array>

#include "friction/fe/Quadrature.hpp"

namespace friction {

template <int dim>
using SimplexPoint = Eigen::Matrix<double, dim, 1>;
template <int dim>
using Barycentric = std::array<double, dim + 1>;

namespace detail {
template <int dim>
constexpr std::array<std::array<int, 2>, dim*(dim + 1) / 2> simplexEdges();
template <>
constexpr std::array<std::array<int, 2>, 1> simplexEdges<1>() {
  return {{{0, 1}}};
}
template <>
constexpr std::array<std::array<int, 2>, 3> simplexEdges<2>() {
  return {{{0, 1}, {1, 2}, {2, 0}}};
}
template <>
constexpr std::array<std::array<int, 2>, 6> simplexEdges<3>() {
  return {{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
}
}  // namespace detail

/// Node counts of the P1 / P2 Lagrange elements on a dim-simplex.
template <int dim>
struct SimplexNodes {
  static constexpr int numVertices = dim + 1;
  static constexpr int numEdges = dim * (dim + 1) / 2;
  /// The most nodes of any element here (P2).
  static constexpr int max = numVertices + numEdges;
  static constexpr int count(int degree) { return degree == 1 ? numVertices : max; }
  /// Edge e joins local vertices edges[e][0] and edges[e][1]; P2 node numVertices + e is its
  /// midpoint.
  static constexpr std::array<std::array<int, 2>, numEdges> edges = detail::simplexEdges<dim>();
};

/// An affine simplex: its vertices, measure (area, volume) [m^dim] and the constant
/// barycentric gradients ∇λ_i [1/m].
template <int dim>
struct Simplex {
  using Point = SimplexPoint<dim>;

  /// In 2D the vertices must be counter-clockwise (checked in debug builds, as the mesh layer
  /// orients triangles); a tetrahedron may have either orientation.
  explicit Simplex(const std::array<Point, dim + 1>& vertices);

  std::array<Point, dim + 1> vertex;
  double measure = 0.0;
  std::array<Point, dim + 1> gradLambda;

  /// Barycentric coordinates of x: λ_i(x) = λ_i(v0) + ∇λ_i · (x − v0).
  Barycentric<dim> barycentric(const Point& x) const;
  /// The point with barycentric coordinates l: Σ l_i v_i.
  Point point(const Barycentric<dim>& l) const;
};

/// Basis values at barycentric point l, in the local node order above (degree 1 or 2).
template <int dim>
void basisValues(int degree, const Barycentric<dim>& l, double* phi);

/// Basis gradients [1/m] at barycentric point l.
template <int dim>
void basisGradients(int degree, const Barycentric<dim>& l, const Simplex<dim>& s,
                    SimplexPoint<dim>* grad);

/// Element stiffness with interleaved dofs (dim · node + component).
template <int dim>
using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor,
                                    dim * SimplexNodes<dim>::max, dim * SimplexNodes<dim>::max>;

/// Element stiffness K_e = ∫ B_iᵀ D B_j of an isotropic material [N/m in 2D per m of
/// thickness, N/m in 3D] by the rule (degree 0 is exact for P1, 2 for P2). D is the Voigt
/// matrix of the dimension (Material::voigtMatrix, voigtMatrix3d), written out in Lamé form:
/// for row dof (i, r) and column dof (j, s), λ ∂_r φ_i ∂_s φ_j + μ ∂_s φ_i ∂_r φ_j
/// + μ δ_rs ∇φ_i · ∇φ_j, with λ = λ* (Material::lambdaStar) in 2D and λ in 3D, μ the shear
/// modulus [Pa]. The Lamé form costs a third of B_iᵀ D B_j and is the 2D assembly's formula.
template <int dim>
void elementStiffness(int degree, const Simplex<dim>& s, double lambda, double mu,
                      const SimplexQuadrature<dim>& rule, ElementMatrix<dim>& ke);

/// Body load ∫ f · φ_i by the rule: for each quadrature point and node i in order,
/// add(i, φ_i f(x_q) |S| w_q), the contribution as a dim-vector [N, or N/m in 2D]. The caller
/// scatters each contribution as it comes (assembly order is part of the result's rounding).
template <int dim, class Field, class Add>
void addBodyLoad(int degree, const Simplex<dim>& s, const SimplexQuadrature<dim>& rule,
                 const Field& f, Add&& add) {
  double phi[SimplexNodes<dim>::max];
  const int n = SimplexNodes<dim>::count(degree);
  for (int q = 0; q < rule.size(); ++q) {
    basisValues<dim>(degree, rule.barycentric[q], phi);
    const SimplexPoint<dim> fq = s.measure * rule.weights[q] * f(s.point(rule.barycentric[q]));
    for (int i = 0; i < n; ++i) add(i, SimplexPoint<dim>(phi[i] * fq));
  }
}

/// A facet of a dim-simplex (an edge in 2D, a triangle in 3D) in dim-space: its dim vertices
/// and measure (length, area) [m^(dim−1)].
template <int dim>
struct SimplexFacet {
  using Point = SimplexPoint<dim>;

  explicit SimplexFacet(const std::array<Point, dim>& vertices);

  std::array<Point, dim> vertex;
  double measure = 0.0;

  /// The point with barycentric coordinates l on the facet.
  Point point(const Barycentric<dim - 1>& l) const;
};

/// Number of nodes on a facet: dim for P1; 3 (edge) or 6 (triangle) for P2.
template <int dim>
constexpr int facetNodeCount(int degree) {
  return SimplexNodes<dim - 1>::count(degree);
}

/// Facet basis values at barycentric point l of the facet, in the facet node order above.
template <int dim>
void facetBasisValues(int degree, const Barycentric<dim - 1>& l, double* phi);

/// Surface load ∫ g · φ_i over the facet by the rule (simplexQuadrature<dim − 1>): for each
/// quadrature point and facet node i in order, add(i, φ_i g(x_q) |F| w_q).
template <int dim, class Field, class Add>
void addFacetLoad(int degree, const SimplexFacet<dim>& facet,
                  const SimplexQuadrature<dim - 1>& rule, const Field& g, Add&& add) {
  double phi[SimplexNodes<dim - 1>::max];
  const int n = facetNodeCount<dim>(degree);
  for (int q = 0; q < rule.size(); ++q) {
    facetBasisValues<dim>(degree, rule.barycentric[q], phi);
    const SimplexPoint<dim> gq =
        facet.measure * rule.weights[q] * g(facet.point(rule.barycentric[q]));
    for (int i = 0; i < n; ++i) add(i, SimplexPoint<dim>(phi[i] * gq));
  }
}

/// Lumped (nodal-quadrature) facet mass as fractions of the facet's measure, one per facet
/// node; they sum to 1. Edge: trapezoid 1/2, 1/2 (P1), Simpson 1/6, 4/6, 1/6 (P2). Triangle:
/// 1/3 each (P1); P2 gets the P1-iso-P2 nodal quadrature, 1/12 per vertex and 1/4 per
/// mid-edge node (docs/method.md §7: row-sum lumping would give the vertices zero weight).
template <int dim>
const double* facetLumpedMass(int degree);

/// Consistent facet mass ∫_F φ_i φ_j / |F| between facet nodes i and j.
template <int dim>
double facetConsistentMass(int degree, int i, int j);

}  // namespace friction
