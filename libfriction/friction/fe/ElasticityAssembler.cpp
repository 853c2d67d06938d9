// ElasticityAssembler: P1 / P2 elasticity on affine simplices (docs/method.md §1, §4): the
// global loops over the mesh; the element kernels (fe/Simplex.hpp) are templated on the
// dimension and instantiated once per call for the mesh's dimension.
#include "friction/fe/ElasticityAssembler.hpp"

#include <algorithm>
#include <cmath>

#include "friction/core/Assert.hpp"
#include "friction/fe/Quadrature.hpp"
#include "friction/fe/Simplex.hpp"

namespace friction {

namespace {

constexpr int kMaxNodes = SimplexNodes<2>::max;

/// The mesh's dimension: the element kernels are instantiated for it once per call.
int meshDimension(const Mesh&) { return 2; }

/// The cell's simplex from the mesh (the one place that reads cell vertices).
template <int dim>
Simplex<dim> cellGeometry(const Mesh& mesh, Index cell);

template <>
Simplex<2> cellGeometry<2>(const Mesh& mesh, Index cell) {
  std::array<Vector2, 3> vertex;
  for (int i = 0; i < 3; ++i) vertex[i] = mesh.points[mesh.cellVertex(cell, i)].head<2>();
  return Simplex<2>(vertex);
}

/// λ of the element law: λ* (plane strain or stress) in 2D, the 3D material's λ in 3D.
template <int dim>
double lameLambda(const Material& material) {
  if constexpr (dim == 2)
    return material.lambdaStar();
  else
    return material.lambda();
}

template <int dim>
Eigen::SparseMatrix<double> assembleStiffness(const LagrangeSpace& V, const Material& material) {
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

  // Dof pattern: column dim·n + c holds rows dim·m … dim·m + dim − 1 for each neighbour m of
  // n, so every column of a node has dim · deg(n) entries and rows are sorted because adj is.
  Eigen::SparseMatrix<double> K(V.numDofs(), V.numDofs());
  const Eigen::Index nnz = dim * dim * static_cast<Eigen::Index>(adj.size());
  K.resizeNonZeros(nnz);
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  double* value = K.valuePtr();
  for (Index n = 0; n < nn; ++n) {
    const Index deg = adjStart[n + 1] - adjStart[n];
    for (int c = 0; c < dim; ++c) {
      const Index col = dim * n + c;
      outer[col] = dim * dim * adjStart[n] + dim * c * deg;
      for (Index k = 0; k < deg; ++k)
        for (int r = 0; r < dim; ++r)
          inner[outer[col] + dim * k + r] = dim * adj[adjStart[n] + k] + r;
    }
  }
  outer[dim * nn] = static_cast<int>(nnz);
  std::fill(value, value + nnz, 0.0);

  // Element loop. P1 gradients are constant (one point); for P2 the integrand ∇φ_i · ∇φ_j is
  // quadratic, so the degree-2 rule is exact.
  const double lam = lameLambda<dim>(material), mu = material.mu();
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(V.degree() == 1 ? 0 : 2);
  ElementMatrix<dim> ke;
  for (Index c = 0; c < nc; ++c) {
    const NodeList nodes = V.cellNodes(c);
    elementStiffness<dim>(V.degree(), cellGeometry<dim>(mesh, c), lam, mu, rule, ke);
    // Scatter: column node b, row node a at position k of adj(b).
    for (int j = 0; j < npc; ++j) {
      const Index b = nodes[j];
      const Index* first = adj.data() + adjStart[b];
      const Index* last = adj.data() + adjStart[b + 1];
      for (int i = 0; i < npc; ++i) {
        const Index k = static_cast<Index>(std::lower_bound(first, last, nodes[i]) - first);
        for (int s = 0; s < dim; ++s) {
          double* colValues = value + outer[dim * b + s] + dim * k;
          for (int r = 0; r < dim; ++r) colValues[r] += ke(dim * i + r, dim * j + s);
        }
      }
    }
  }
  return K;
}

}  // namespace

ElasticityAssembler::ElasticityAssembler(const LagrangeSpace& space, const Material& material)
    : space_(&space), material_(&material) {}

Eigen::SparseMatrix<double> ElasticityAssembler::stiffness() const {
  switch (meshDimension(space_->mesh())) {
    case 2:
      return assembleStiffness<2>(*space_, *material_);
    default:
      FRICTION_ASSERT(false, "the mesh's dimension has no element kernels");
      return {};
  }
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const Vector2& f) const {
  return bodyForce(VectorField([f](const Vector2&) { return f; }));
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const VectorField& f) const {
  const LagrangeSpace& V = *space_;
  FRICTION_ASSERT(meshDimension(V.mesh()) == 2, "a 2D body force on a 2D mesh");
  const SimplexQuadrature<2> rule = simplexQuadrature<2>(5);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  for (Index c = 0; c < V.numCells(); ++c) {
    const NodeList nodes = V.cellNodes(c);
    addBodyLoad<2>(V.degree(), cellGeometry<2>(V.mesh(), c), rule, f,
                   [&](int i, const Vector2& load) { F.segment<2>(2 * nodes[i]) += load; });
  }
  return F;
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const Vector2& g) const {
  return traction(label, VectorField([g](const Vector2&) { return g; }));
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const VectorField& g) const {
  const LagrangeSpace& V = *space_;
  const SimplexQuadrature<1> rule = simplexQuadrature<1>(7);  // 4-point Gauss–Legendre
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  for (const auto& e : V.labelledEdges(label)) {
    const NodeList nodes = V.edgeNodes(e[0], e[1]);
    const Vector2& a = V.coordinate(e[0]);
    const Vector2& b = V.coordinate(e[1]);
    addFacetLoad<2>(V.degree(), SimplexFacet<2>({a, b}), rule, g,
                    [&](int i, const Vector2& load) { F.segment<2>(2 * nodes[i]) += load; });
  }
  return F;
}

Eigen::VectorXd ElasticityAssembler::lumpedEdgeMass(
    const std::vector<std::array<Index, 2>>& edges) const {
  const LagrangeSpace& V = *space_;
  // Trapezoid (P1) and Simpson (P2) weights: the row sums of the consistent mass, and the
  // nodal quadrature that keeps the friction law node by node (docs/method.md §4).
  const double* w = facetLumpedMass<2>(V.degree());
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
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(edges.size() * static_cast<std::size_t>(V.nodesPerEdge() * V.nodesPerEdge()));
  for (const auto& e : edges) {
    const double length = (V.coordinate(e[1]) - V.coordinate(e[0])).norm();
    const NodeList nodes = V.edgeNodes(e[0], e[1]);
    for (int i = 0; i < nodes.size; ++i)
      for (int j = 0; j < nodes.size; ++j)
        triplets.emplace_back(nodes[i], nodes[j],
                              length * facetConsistentMass<2>(V.degree(), i, j));
  }
  Eigen::SparseMatrix<double> M(V.numNodes(), V.numNodes());
  M.setFromTriplets(triplets.begin(), triplets.end());
  return M;
}

Vector2 ElasticityAssembler::displacement(const Eigen::VectorXd& u, Index cell,
                                          const Vector2& x) const {
  const LagrangeSpace& V = *space_;
  const Simplex<2> g = cellGeometry<2>(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  double phi[kMaxNodes];
  basisValues<2>(V.degree(), g.barycentric(x), phi);
  Vector2 value = Vector2::Zero();
  for (int i = 0; i < nodes.size; ++i) value += phi[i] * u.segment<2>(2 * nodes[i]);
  return value;
}

Eigen::Matrix2d ElasticityAssembler::displacementGradient(const Eigen::VectorXd& u, Index cell,
                                                          const Vector2& x) const {
  const LagrangeSpace& V = *space_;
  const Simplex<2> g = cellGeometry<2>(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  Vector2 grad[kMaxNodes];
  basisGradients<2>(V.degree(), g.barycentric(x), g, grad);
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
  const SimplexQuadrature<2> rule = simplexQuadrature<2>(8);
  double l2 = 0.0, h1 = 0.0;
  double phi[kMaxNodes];
  Vector2 grad[kMaxNodes];
  for (Index c = 0; c < V.numCells(); ++c) {
    const Simplex<2> g = cellGeometry<2>(V.mesh(), c);
    const NodeList nodes = V.cellNodes(c);
    for (int q = 0; q < rule.size(); ++q) {
      const auto& l = rule.barycentric[q];
      basisValues<2>(V.degree(), l, phi);
      basisGradients<2>(V.degree(), l, g, grad);
      Vector2 uh = Vector2::Zero();
      Eigen::Matrix2d Gh = Eigen::Matrix2d::Zero();
      for (int i = 0; i < nodes.size; ++i) {
        const Vector2 ui = u.segment<2>(2 * nodes[i]);
        uh += phi[i] * ui;
        Gh += ui * grad[i].transpose();
      }
      const Vector2 x = g.point(l);
      const double w = g.measure * rule.weights[q];
      l2 += w * (exact(x) - uh).squaredNorm();
      h1 += w * (exactGradient(x) - Gh).squaredNorm();
    }
  }
  return {std::sqrt(l2), std::sqrt(h1)};
}

}  // namespace friction
