// ElasticityAssembler: P1 / P2 plane elasticity on affine triangles (docs/method.md §1, §4).
//
// Element geometry is carried by barycentric coordinates: on an affine triangle ∇λ_i is
// constant, so every basis gradient is a polynomial in λ times the three ∇λ_i, and no
// reference-element Jacobian inverse per quadrature point is needed.
#include "friction/fe/ElasticityAssembler.hpp"

#include <algorithm>
#include <cmath>

#include "friction/core/Assert.hpp"
#include "friction/fe/Quadrature.hpp"

namespace friction {

namespace {

constexpr int kMaxNodes = 6;
constexpr int kEdgeVertex[3][2] = {{0, 1}, {1, 2}, {2, 0}};

/// Affine triangle: first vertex, area and the constant barycentric gradients.
struct CellGeometry {
  Vector2 p0;
  double area = 0.0;
  std::array<Vector2, 3> gradLambda;
  std::array<Vector2, 3> vertex;

  /// Barycentric coordinates of x: λ_i(x) = λ_i(p0) + ∇λ_i · (x − p0).
  std::array<double, 3> barycentric(const Vector2& x) const {
    const Vector2 d = x - p0;
    return {1.0 + gradLambda[0].dot(d), gradLambda[1].dot(d), gradLambda[2].dot(d)};
  }
  Vector2 point(const std::array<double, 3>& l) const {
    return l[0] * vertex[0] + l[1] * vertex[1] + l[2] * vertex[2];
  }
};

CellGeometry cellGeometry(const Mesh& mesh, Index cell) {
  CellGeometry g;
  for (int i = 0; i < 3; ++i) g.vertex[i] = mesh.points[mesh.cellVertex(cell, i)].head<2>();
  const Vector2& a = g.vertex[0];
  const Vector2& b = g.vertex[1];
  const Vector2& c = g.vertex[2];
  g.p0 = a;
  const double twiceArea = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
  FRICTION_ASSERT(twiceArea > 0.0, "triangle is not counter-clockwise");
  g.area = 0.5 * twiceArea;
  // ∇λ_i is the inward normal of the opposite side scaled by 1/(2 area).
  g.gradLambda[0] = Vector2(b.y() - c.y(), c.x() - b.x()) / twiceArea;
  g.gradLambda[1] = Vector2(c.y() - a.y(), a.x() - c.x()) / twiceArea;
  g.gradLambda[2] = Vector2(a.y() - b.y(), b.x() - a.x()) / twiceArea;
  return g;
}

/// Basis values at barycentric point l, in LagrangeSpace's local node order.
void basisValues(int degree, const std::array<double, 3>& l, double* phi) {
  if (degree == 1) {
    phi[0] = l[0];
    phi[1] = l[1];
    phi[2] = l[2];
    return;
  }
  for (int i = 0; i < 3; ++i) phi[i] = l[i] * (2.0 * l[i] - 1.0);
  for (int e = 0; e < 3; ++e) phi[3 + e] = 4.0 * l[kEdgeVertex[e][0]] * l[kEdgeVertex[e][1]];
}

/// Basis gradients [1/m] at barycentric point l.
void basisGradients(int degree, const std::array<double, 3>& l, const CellGeometry& g,
                    Vector2* grad) {
  if (degree == 1) {
    for (int i = 0; i < 3; ++i) grad[i] = g.gradLambda[i];
    return;
  }
  for (int i = 0; i < 3; ++i) grad[i] = (4.0 * l[i] - 1.0) * g.gradLambda[i];
  for (int e = 0; e < 3; ++e) {
    const int a = kEdgeVertex[e][0], b = kEdgeVertex[e][1];
    grad[3 + e] = 4.0 * (l[a] * g.gradLambda[b] + l[b] * g.gradLambda[a]);
  }
}

/// Basis values on an edge at s ∈ [0, 1] from a to b, node order (a, [mid], b).
void edgeBasisValues(int degree, double s, double* phi) {
  if (degree == 1) {
    phi[0] = 1.0 - s;
    phi[1] = s;
  } else {
    phi[0] = (1.0 - s) * (1.0 - 2.0 * s);
    phi[1] = 4.0 * s * (1.0 - s);
    phi[2] = s * (2.0 * s - 1.0);
  }
}

}  // namespace

ElasticityAssembler::ElasticityAssembler(const LagrangeSpace& space, const Material& material)
    : space_(&space), material_(&material) {}

Eigen::SparseMatrix<double> ElasticityAssembler::stiffness() const {
  const LagrangeSpace& V = *space_;
  const Mesh& mesh = V.mesh();
  const Index nn = V.numNodes(), nc = V.numCells();
  const int npc = V.nodesPerCell();

  // Node graph in compressed rows: node → cells, then node → sorted neighbour nodes.
  std::vector<Index> cellStart(static_cast<std::size_t>(nn) + 1, 0);
  for (Index c = 0; c < nc; ++c)
    for (Index n : V.cellNodes(c)) ++cellStart[n + 1];
  for (Index n = 0; n < nn; ++n) cellStart[n + 1] += cellStart[n];
  std::vector<Index> cellOf(static_cast<std::size_t>(cellStart[nn]));
  {
    std::vector<Index> fill(cellStart.begin(), cellStart.end() - 1);
    for (Index c = 0; c < nc; ++c)
      for (Index n : V.cellNodes(c)) cellOf[fill[n]++] = c;
  }
  std::vector<Index> adjStart(static_cast<std::size_t>(nn) + 1, 0);
  std::vector<Index> adj;
  adj.reserve(static_cast<std::size_t>(nn) * (npc == 3 ? 7 : 12));
  std::vector<Index> scratch;
  for (Index n = 0; n < nn; ++n) {
    scratch.clear();
    for (Index k = cellStart[n]; k < cellStart[n + 1]; ++k)
      for (Index m : V.cellNodes(cellOf[k])) scratch.push_back(m);
    std::sort(scratch.begin(), scratch.end());
    adj.insert(adj.end(), scratch.begin(), std::unique(scratch.begin(), scratch.end()));
    adjStart[n + 1] = static_cast<Index>(adj.size());
  }
  std::vector<Index>().swap(cellOf);

  // Dof pattern: column 2n + c holds rows 2m, 2m + 1 for each neighbour m of n, so both
  // columns of a node have 2 · deg(n) entries and rows are sorted because adj is.
  Eigen::SparseMatrix<double> K(V.numDofs(), V.numDofs());
  const Eigen::Index nnz = 4 * static_cast<Eigen::Index>(adj.size());
  K.resizeNonZeros(nnz);
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* value = K.valuePtr();
  for (Index n = 0; n < nn; ++n) {
    const Index deg = adjStart[n + 1] - adjStart[n];
    for (int c = 0; c < 2; ++c) {
      const Index col = 2 * n + c;
      outer[col] = 4 * adjStart[n] + 2 * c * deg;
      for (Index k = 0; k < deg; ++k) {
        inner[outer[col] + 2 * k] = 2 * adj[adjStart[n] + k];
        inner[outer[col] + 2 * k + 1] = 2 * adj[adjStart[n] + k] + 1;
      }
    }
  }
  outer[2 * nn] = static_cast<int>(nnz);
  std::fill(value, value + nnz, 0.0);

  // Element loop. P1 gradients are constant (one point); for P2 the integrand ∇φ_i · ∇φ_j is
  // quadratic, so the three-point degree-2 rule is exact.
  const double lam = material_->lambdaStar(), mu = material_->mu();
  const TriangleQuadrature rule = triangleQuadrature(V.degree() == 1 ? 0 : 2);
  Vector2 grad[kMaxNodes];
  double ke[2 * kMaxNodes][2 * kMaxNodes];
  for (Index c = 0; c < nc; ++c) {
    const CellGeometry g = cellGeometry(mesh, c);
    const NodeList nodes = V.cellNodes(c);
    for (int i = 0; i < 2 * npc; ++i)
      for (int j = 0; j < 2 * npc; ++j) ke[i][j] = 0.0;
    for (int q = 0; q < rule.size(); ++q) {
      basisGradients(V.degree(), rule.barycentric[q], g, grad);
      const double w = g.area * rule.weights[q];
      // Row dof (i, r), column dof (j, c):
      // λ* ∂_r φ_i ∂_c φ_j + μ ∂_c φ_i ∂_r φ_j + μ δ_rc ∇φ_i · ∇φ_j.
      for (int i = 0; i < npc; ++i)
        for (int j = 0; j < npc; ++j) {
          const Vector2& gi = grad[i];
          const Vector2& gj = grad[j];
          const double dot = mu * gi.dot(gj);
          for (int r = 0; r < 2; ++r)
            for (int s = 0; s < 2; ++s)
              ke[2 * i + r][2 * j + s] +=
                  w * (lam * gi[r] * gj[s] + mu * gi[s] * gj[r] + (r == s ? dot : 0.0));
        }
    }
    // Scatter: column node b, row node a at position k of adj(b).
    for (int j = 0; j < npc; ++j) {
      const Index b = nodes[j];
      const Index* first = adj.data() + adjStart[b];
      const Index* last = adj.data() + adjStart[b + 1];
      for (int i = 0; i < npc; ++i) {
        const Index k = static_cast<Index>(std::lower_bound(first, last, nodes[i]) - first);
        for (int s = 0; s < 2; ++s) {
          double* colValues = value + outer[2 * b + s] + 2 * k;
          colValues[0] += ke[2 * i][2 * j + s];
          colValues[1] += ke[2 * i + 1][2 * j + s];
        }
      }
    }
  }
  return K;
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const Vector2& f) const {
  return bodyForce(VectorField([f](const Vector2&) { return f; }));
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const VectorField& f) const {
  const LagrangeSpace& V = *space_;
  const int npc = V.nodesPerCell();
  const TriangleQuadrature rule = triangleQuadrature(5);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  double phi[kMaxNodes];
  for (Index c = 0; c < V.numCells(); ++c) {
    const CellGeometry g = cellGeometry(V.mesh(), c);
    const NodeList nodes = V.cellNodes(c);
    for (int q = 0; q < rule.size(); ++q) {
      basisValues(V.degree(), rule.barycentric[q], phi);
      const Vector2 fq = g.area * rule.weights[q] * f(g.point(rule.barycentric[q]));
      for (int i = 0; i < npc; ++i) {
        F[2 * nodes[i]] += phi[i] * fq.x();
        F[2 * nodes[i] + 1] += phi[i] * fq.y();
      }
    }
  }
  return F;
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const Vector2& g) const {
  return traction(label, VectorField([g](const Vector2&) { return g; }));
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const VectorField& g) const {
  const LagrangeSpace& V = *space_;
  const SegmentQuadrature rule = gaussLegendre(4);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  double phi[3];
  for (const auto& e : V.labelledEdges(label)) {
    const NodeList nodes = V.edgeNodes(e[0], e[1]);
    const Vector2& a = V.coordinate(e[0]);
    const Vector2& b = V.coordinate(e[1]);
    const double length = (b - a).norm();
    for (int q = 0; q < rule.size(); ++q) {
      const double s = rule.points[q];
      edgeBasisValues(V.degree(), s, phi);
      const Vector2 gq = length * rule.weights[q] * g((1.0 - s) * a + s * b);
      for (int i = 0; i < nodes.size; ++i) {
        F[2 * nodes[i]] += phi[i] * gq.x();
        F[2 * nodes[i] + 1] += phi[i] * gq.y();
      }
    }
  }
  return F;
}

Eigen::VectorXd ElasticityAssembler::lumpedEdgeMass(
    const std::vector<std::array<Index, 2>>& edges) const {
  const LagrangeSpace& V = *space_;
  // Trapezoid (P1) and Simpson (P2) weights: the row sums of the consistent mass, and the
  // nodal quadrature that keeps the friction law node by node (docs/method.md §4).
  static constexpr double kP1[2] = {0.5, 0.5};
  static constexpr double kP2[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
  const double* w = V.degree() == 1 ? kP1 : kP2;
  Eigen::VectorXd m = Eigen::VectorXd::Zero(V.numNodes());
  for (const auto& e : edges) {
    const double length = (V.coordinate(e[1]) - V.coordinate(e[0])).norm();
    const NodeList nodes = V.edgeNodes(e[0], e[1]);
    for (int i = 0; i < nodes.size; ++i) m[nodes[i]] += w[i] * length;
  }
  return m;
}

Eigen::SparseMatrix<double> ElasticityAssembler::consistentEdgeMass(
    const std::vector<std::array<Index, 2>>& edges) const {
  const LagrangeSpace& V = *space_;
  // ∫_0^1 φ_i φ_j ds for the edge bases in order (a, [mid], b).
  static constexpr double kP1[2][2] = {{2.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 6}};
  static constexpr double kP2[3][3] = {{4.0 / 30, 2.0 / 30, -1.0 / 30},
                                       {2.0 / 30, 16.0 / 30, 2.0 / 30},
                                       {-1.0 / 30, 2.0 / 30, 4.0 / 30}};
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(edges.size() * static_cast<std::size_t>(V.nodesPerEdge() * V.nodesPerEdge()));
  for (const auto& e : edges) {
    const double length = (V.coordinate(e[1]) - V.coordinate(e[0])).norm();
    const NodeList nodes = V.edgeNodes(e[0], e[1]);
    for (int i = 0; i < nodes.size; ++i)
      for (int j = 0; j < nodes.size; ++j)
        triplets.emplace_back(nodes[i], nodes[j],
                              length * (V.degree() == 1 ? kP1[i][j] : kP2[i][j]));
  }
  Eigen::SparseMatrix<double> M(V.numNodes(), V.numNodes());
  M.setFromTriplets(triplets.begin(), triplets.end());
  return M;
}

Vector2 ElasticityAssembler::displacement(const Eigen::VectorXd& u, Index cell,
                                          const Vector2& x) const {
  const LagrangeSpace& V = *space_;
  const CellGeometry g = cellGeometry(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  double phi[kMaxNodes];
  basisValues(V.degree(), g.barycentric(x), phi);
  Vector2 value = Vector2::Zero();
  for (int i = 0; i < nodes.size; ++i) value += phi[i] * u.segment<2>(2 * nodes[i]);
  return value;
}

Eigen::Matrix2d ElasticityAssembler::displacementGradient(const Eigen::VectorXd& u, Index cell,
                                                          const Vector2& x) const {
  const LagrangeSpace& V = *space_;
  const CellGeometry g = cellGeometry(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  Vector2 grad[kMaxNodes];
  basisGradients(V.degree(), g.barycentric(x), g, grad);
  Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
  for (int i = 0; i < nodes.size; ++i) G += u.segment<2>(2 * nodes[i]) * grad[i].transpose();
  return G;
}

Eigen::Matrix2d ElasticityAssembler::strain(const Eigen::VectorXd& u, Index cell,
                                            const Vector2& x) const {
  const Eigen::Matrix2d G = displacementGradient(u, cell, x);
  return 0.5 * (G + G.transpose());
}

Eigen::Matrix2d ElasticityAssembler::stress(const Eigen::VectorXd& u, Index cell,
                                            const Vector2& x) const {
  return material_->stress(strain(u, cell, x));
}

ErrorNorms ElasticityAssembler::errorNorms(const Eigen::VectorXd& u, const VectorField& exact,
                                           const TensorField& exactGradient) const {
  const LagrangeSpace& V = *space_;
  const TriangleQuadrature rule = triangleQuadrature(8);
  double l2 = 0.0, h1 = 0.0;
  double phi[kMaxNodes];
  Vector2 grad[kMaxNodes];
  for (Index c = 0; c < V.numCells(); ++c) {
    const CellGeometry g = cellGeometry(V.mesh(), c);
    const NodeList nodes = V.cellNodes(c);
    for (int q = 0; q < rule.size(); ++q) {
      const auto& l = rule.barycentric[q];
      basisValues(V.degree(), l, phi);
      basisGradients(V.degree(), l, g, grad);
      Vector2 uh = Vector2::Zero();
      Eigen::Matrix2d Gh = Eigen::Matrix2d::Zero();
      for (int i = 0; i < nodes.size; ++i) {
        const Vector2 ui = u.segment<2>(2 * nodes[i]);
        uh += phi[i] * ui;
        Gh += ui * grad[i].transpose();
      }
      const Vector2 x = g.point(l);
      const double w = g.area * rule.weights[q];
      l2 += w * (exact(x) - uh).squaredNorm();
      h1 += w * (exactGradient(x) - Gh).squaredNorm();
    }
  }
  return {std::sqrt(l2), std::sqrt(h1)};
}

}  // namespace friction
