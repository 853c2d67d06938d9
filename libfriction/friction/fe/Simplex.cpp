// Simplex kernels (see Simplex.hpp), instantiated for triangles and tetrahedra.
#include "friction/fe/Simplex.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "friction/core/Assert.hpp"

namespace friction {

template <int dim>
Simplex<dim>::Simplex(const std::array<Point, dim + 1>& vertices) : vertex(vertices) {
  if constexpr (dim == 2) {
    // The triangle's closed forms, kept operation for operation: every 2D result is reproduced
    // byte for byte, which a generic inverse-Jacobian formula would not do.
    const Point& a = vertex[0];
    const Point& b = vertex[1];
    const Point& c = vertex[2];
    const double twiceArea = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    FRICTION_ASSERT(twiceArea > 0.0, "triangle is not counter-clockwise");
    measure = 0.5 * twiceArea;
    // ∇λ_i is the inward normal of the opposite side scaled by 1/(2 area).
    gradLambda[0] = Point(b.y() - c.y(), c.x() - b.x()) / twiceArea;
    gradLambda[1] = Point(c.y() - a.y(), a.x() - c.x()) / twiceArea;
    gradLambda[2] = Point(a.y() - b.y(), b.x() - a.x()) / twiceArea;
  } else {
    static_assert(dim == 3, "simplices of dimension 2 and 3 only");
    // The rows of the inverse of J = [e1 e2 e3] (e_k = v_k − v0) are ∇λ1..3: (e2 × e3)/det J
    // and cyclic. ∇λ0 comes from its own face (v1, v2, v3) rather than as −(∇λ1 + ∇λ2 + ∇λ3),
    // which would cancel on slivers. A signed det makes both orientations correct.
    const Point e1 = vertex[1] - vertex[0];
    const Point e2 = vertex[2] - vertex[0];
    const Point e3 = vertex[3] - vertex[0];
    const Point n1 = e2.cross(e3);
    const double det = e1.dot(n1);
    FRICTION_ASSERT(det != 0.0, "degenerate tetrahedron");
    measure = std::abs(det) / 6.0;
    gradLambda[0] = (vertex[3] - vertex[1]).cross(vertex[2] - vertex[1]) / det;
    gradLambda[1] = n1 / det;
    gradLambda[2] = e3.cross(e1) / det;
    gradLambda[3] = e1.cross(e2) / det;
  }
}

template <int dim>
Barycentric<dim> Simplex<dim>::barycentric(const Point& x) const {
  const Point d = x - vertex[0];
  Barycentric<dim> l;
  l[0] = 1.0 + gradLambda[0].dot(d);
  for (int i = 1; i <= dim; ++i) l[i] = gradLambda[i].dot(d);
  return l;
}

template <int dim>
SimplexPoint<dim> Simplex<dim>::point(const Barycentric<dim>& l) const {
  Point x = l[0] * vertex[0];
  for (int i = 1; i <= dim; ++i) x += l[i] * vertex[i];
  return x;
}

template <int dim>
void basisValues(int degree, const Barycentric<dim>& l, double* phi) {
  using Nodes = SimplexNodes<dim>;
  if (degree == 1) {
    for (int i = 0; i <= dim; ++i) phi[i] = l[i];
    return;
  }
  for (int i = 0; i <= dim; ++i) phi[i] = l[i] * (2.0 * l[i] - 1.0);
  for (int e = 0; e < Nodes::numEdges; ++e)
    phi[Nodes::numVertices + e] = 4.0 * l[Nodes::edges[e][0]] * l[Nodes::edges[e][1]];
}

template <int dim>
void basisGradients(int degree, const Barycentric<dim>& l, const Simplex<dim>& s,
                    SimplexPoint<dim>* grad) {
  using Nodes = SimplexNodes<dim>;
  if (degree == 1) {
    for (int i = 0; i <= dim; ++i) grad[i] = s.gradLambda[i];
    return;
  }
  for (int i = 0; i <= dim; ++i) grad[i] = (4.0 * l[i] - 1.0) * s.gradLambda[i];
  for (int e = 0; e < Nodes::numEdges; ++e) {
    const int a = Nodes::edges[e][0], b = Nodes::edges[e][1];
    grad[Nodes::numVertices + e] = 4.0 * (l[a] * s.gradLambda[b] + l[b] * s.gradLambda[a]);
  }
}

template <int dim>
void elementStiffness(int degree, const Simplex<dim>& s, double lambda, double mu,
                      const SimplexQuadrature<dim>& rule, ElementMatrix<dim>& ke) {
  const int n = SimplexNodes<dim>::count(degree);
  SimplexPoint<dim> grad[SimplexNodes<dim>::max];
  ke.setZero(dim * n, dim * n);
  for (int q = 0; q < rule.size(); ++q) {
    basisGradients<dim>(degree, rule.barycentric[q], s, grad);
    const double w = s.measure * rule.weights[q];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const SimplexPoint<dim>& gi = grad[i];
        const SimplexPoint<dim>& gj = grad[j];
        const double dot = mu * gi.dot(gj);
        for (int r = 0; r < dim; ++r)
          for (int c = 0; c < dim; ++c)
            ke(dim * i + r, dim * j + c) +=
                w * (lambda * gi[r] * gj[c] + mu * gi[c] * gj[r] + (r == c ? dot : 0.0));
      }
  }
}

template <int dim>
SimplexFacet<dim>::SimplexFacet(const std::array<Point, dim>& vertices) : vertex(vertices) {
  if constexpr (dim == 2)
    measure = (vertex[1] - vertex[0]).norm();
  else
    measure = 0.5 * (vertex[1] - vertex[0]).cross(vertex[2] - vertex[0]).norm();
}

template <int dim>
SimplexPoint<dim> SimplexFacet<dim>::point(const Barycentric<dim - 1>& l) const {
  Point x = l[0] * vertex[0];
  for (int i = 1; i < dim; ++i) x += l[i] * vertex[i];
  return x;
}

template <int dim>
void facetBasisValues(int degree, const Barycentric<dim - 1>& l, double* phi) {
  if constexpr (dim == 2) {
    // The edge's own order (a, [mid], b) and its closed forms in s = λ1 (λ0 = 1 − s), kept
    // operation for operation so that every 2D load is reproduced byte for byte.
    if (degree == 1) {
      phi[0] = l[0];
      phi[1] = l[1];
    } else {
      phi[0] = l[0] * (1.0 - 2.0 * l[1]);
      phi[1] = 4.0 * l[1] * l[0];
      phi[2] = l[1] * (2.0 * l[1] - 1.0);
    }
  } else {
    basisValues<dim - 1>(degree, l, phi);
  }
}

template <int dim>
const double* facetLumpedMass(int degree) {
  if constexpr (dim == 2) {
    static constexpr double kP1[2] = {0.5, 0.5};
    static constexpr double kP2[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
    return degree == 1 ? kP1 : kP2;
  } else {
    static constexpr double kP1[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    static constexpr double kP2[6] = {1.0 / 12, 1.0 / 12, 1.0 / 12, 0.25, 0.25, 0.25};
    return degree == 1 ? kP1 : kP2;
  }
}

template <int dim>
double facetConsistentMass(int degree, int i, int j) {
  if constexpr (dim == 2) {
    static constexpr double kP1[2][2] = {{2.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 6}};
    static constexpr double kP2[3][3] = {{4.0 / 30, 2.0 / 30, -1.0 / 30},
                                         {2.0 / 30, 16.0 / 30, 2.0 / 30},
                                         {-1.0 / 30, 2.0 / 30, 4.0 / 30}};
    return degree == 1 ? kP1[i][j] : kP2[i][j];
  } else {
    static constexpr double kP1[3][3] = {{2.0 / 12, 1.0 / 12, 1.0 / 12},
                                         {1.0 / 12, 2.0 / 12, 1.0 / 12},
                                         {1.0 / 12, 1.0 / 12, 2.0 / 12}};
    // Vertex i with the mid-edge node opposite it: −4; with the two adjacent ones: 0.
    static constexpr double kP2[6][6] = {
        {6.0 / 180, -1.0 / 180, -1.0 / 180, 0.0, -4.0 / 180, 0.0},
        {-1.0 / 180, 6.0 / 180, -1.0 / 180, 0.0, 0.0, -4.0 / 180},
        {-1.0 / 180, -1.0 / 180, 6.0 / 180, -4.0 / 180, 0.0, 0.0},
        {0.0, 0.0, -4.0 / 180, 32.0 / 180, 16.0 / 180, 16.0 / 180},
        {-4.0 / 180, 0.0, 0.0, 16.0 / 180, 32.0 / 180, 16.0 / 180},
        {0.0, -4.0 / 180, 0.0, 16.0 / 180, 16.0 / 180, 32.0 / 180}};
    return degree == 1 ? kP1[i][j] : kP2[i][j];
  }
}

#define FRICTION_INSTANTIATE_SIMPLEX(dim)                                                  \
  template struct Simplex<dim>;                                                            \
  template struct SimplexFacet<dim>;                                                       \
  template void basisValues<dim>(int, const Barycentric<dim>&, double*);                   \
  template void basisGradients<dim>(int, const Barycentric<dim>&, const Simplex<dim>&,     \
                                    SimplexPoint<dim>*);                                   \
  template void elementStiffness<dim>(int, const Simplex<dim>&, double, double,            \
                                      const SimplexQuadrature<dim>&, ElementMatrix<dim>&); \
  template void facetBasisValues<dim>(int, const Barycentric<dim - 1>&, double*);          \
  template const double* facetLumpedMass<dim>(int);                                        \
  template double facetConsistentMass<dim>(int, int, int);

FRICTION_INSTANTIATE_SIMPLEX(2)
FRICTION_INSTANTIATE_SIMPLEX(3)

#undef FRICTION_INSTANTIATE_SIMPLEX

}  // namespace friction
