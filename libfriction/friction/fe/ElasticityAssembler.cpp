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

constexpr int kMaxNodes = SimplexNodes<3>::max;

/// The cell's simplex from the mesh (the one place that reads cell vertices).
template <int dim>
Simplex<dim> cellGeometry(const Mesh& mesh, Index cell);

template <>
Simplex<2> cellGeometry<2>(const Mesh& mesh, Index cell) {
  std::array<Vector2, 3> vertex;
  for (int i = 0; i < 3; ++i) vertex[i] = mesh.points[mesh.cellVertex(cell, i)].head<2>();
  return Simplex<2>(vertex);
}

template <>
Simplex<3> cellGeometry<3>(const Mesh& mesh, Index cell) {
  std::array<Point, 4> vertex;
  for (int i = 0; i < 4; ++i) vertex[i] = mesh.points[mesh.cellVertex(cell, i)];
  return Simplex<3>(vertex);
}

/// x as the kernels of the dimension see it, and back.
template <int dim>
SimplexPoint<dim> local(const Point& x) {
  return x.head<dim>();
}
template <int dim>
Point global(const SimplexPoint<dim>& x) {
  if constexpr (dim == 2)
    return Point(x.x(), x.y(), 0.0);
  else
    return x;
}

/// Run body<dim>() for the mesh's dimension: the one dispatch of each call.
template <class Body>
decltype(auto) dispatch(const Mesh& mesh, Body&& body) {
  FRICTION_ASSERT(mesh.dim == 2 || mesh.dim == 3, "the mesh's dimension has no element kernels");
  if (mesh.dim == 3) return body(std::integral_constant<int, 3>());
  return body(std::integral_constant<int, 2>());
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
Eigen::SparseMatrix<double> assembleStiffness(const LagrangeSpace& V, const MaterialMap& materials,
                                              const std::vector<char>* use = nullptr) {
  const Mesh& mesh = V.mesh();
  const Index nn = V.numNodes(), nc = V.numCells();
  const int npc = V.nodesPerCell();

  // Node graph in compressed rows: node → cells, then node → sorted neighbour nodes.
  // use: the cells assembled (all when null); a node of none of them has an empty column.
  const auto used = [use](Index c) { return !use || (*use)[static_cast<std::size_t>(c)] != 0; };
  std::vector<Index> cellStart(static_cast<std::size_t>(nn) + 1, 0);
  for (Index c = 0; c < nc; ++c)
    if (used(c))
      for (Index n : V.cellNodes(c)) ++cellStart[n + 1];
  for (Index n = 0; n < nn; ++n) cellStart[n + 1] += cellStart[n];
  std::vector<Index> cellOf(static_cast<std::size_t>(cellStart[nn]));
  {
    std::vector<Index> fill(cellStart.begin(), cellStart.end() - 1);
    for (Index c = 0; c < nc; ++c)
      if (used(c))
        for (Index n : V.cellNodes(c)) cellOf[fill[n]++] = c;
  }
  std::vector<Index> adjStart(static_cast<std::size_t>(nn) + 1, 0);
  std::vector<Index> adj;
  // Typical node degrees (the node itself included): P1 / P2 triangles 7 / 12, tetrahedra 15 /
  // about 30; only a capacity hint.
  if (!use)
    adj.reserve(static_cast<std::size_t>(nn) *
                (dim == 2 ? (npc == 3 ? 7 : 12) : (npc == 4 ? 15 : 30)));
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
  // The same λ, μ for every cell of a homogeneous body (the uniform map's ofCell is that one
  // material).
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(V.degree() == 1 ? 0 : 2);
  ElementMatrix<dim> ke;
  for (Index c = 0; c < nc; ++c) {
    if (!used(c)) continue;
    const NodeList nodes = V.cellNodes(c);
    const Material& material = materials.ofCell(c);
    const double lam = lameLambda<dim>(material), mu = material.mu();
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

template <int dim>
Eigen::VectorXd assembleBodyForce(const LagrangeSpace& V, const VectorField& f) {
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(5);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  const auto field = [&f](const SimplexPoint<dim>& x) -> SimplexPoint<dim> {
    return local<dim>(f(global<dim>(x)));
  };
  for (Index c = 0; c < V.numCells(); ++c) {
    const NodeList nodes = V.cellNodes(c);
    addBodyLoad<dim>(
        V.degree(), cellGeometry<dim>(V.mesh(), c), rule, field,
        [&](int i, const SimplexPoint<dim>& load) { F.segment<dim>(dim * nodes[i]) += load; });
  }
  return F;
}

template <int dim>
Eigen::VectorXd assembleCellBodyForce(const LagrangeSpace& V,
                                      const std::function<Point(Index)>& f) {
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(5);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  for (Index c = 0; c < V.numCells(); ++c) {
    const SimplexPoint<dim> value = local<dim>(f(c));
    if (value.isZero()) continue;
    const auto field = [&value](const SimplexPoint<dim>&) { return value; };
    const NodeList nodes = V.cellNodes(c);
    addBodyLoad<dim>(
        V.degree(), cellGeometry<dim>(V.mesh(), c), rule, field,
        [&](int i, const SimplexPoint<dim>& load) { F.segment<dim>(dim * nodes[i]) += load; });
  }
  return F;
}

/// F_i = ∫ b · αp · div φ_i (ElasticityAssembler::pressureLoad); alphaP(cell, l, x) gives αp
/// at the point of barycentric coordinates l, x, of the cell.
template <int dim, class Field>
Eigen::VectorXd assemblePressureLoad(const LagrangeSpace& V, const ElasticityAssembler& a,
                                     const Field& alphaP) {
  // αp linear times div φ_i (constant for P1, linear for P2): degree 1 or 2 is exact.
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(V.degree());
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  SimplexPoint<dim> grad[kMaxNodes];
  for (Index c = 0; c < V.numCells(); ++c) {
    const Simplex<dim> g = cellGeometry<dim>(V.mesh(), c);
    const NodeList nodes = V.cellNodes(c);
    const double b = a.pressureFactor(c);
    for (int q = 0; q < rule.size(); ++q) {
      const auto& l = rule.barycentric[q];
      const double value = alphaP(c, l, global<dim>(g.point(l)));
      if (value == 0.0) continue;
      basisGradients<dim>(V.degree(), l, g, grad);
      const double w = g.measure * rule.weights[q] * b * value;
      // div (φ_i e_r) = ∂_r φ_i: dof (i, r) takes w ∂_r φ_i.
      for (int i = 0; i < nodes.size; ++i) F.segment<dim>(dim * nodes[i]) += w * grad[i];
    }
  }
  return F;
}

/// The vertices of facet k of a flat list (d per facet) as the kernels see them.
template <int dim>
SimplexFacet<dim> facetGeometry(const LagrangeSpace& V, const Index* vertices) {
  std::array<SimplexPoint<dim>, dim> x;
  for (int i = 0; i < dim; ++i) x[i] = local<dim>(V.point(vertices[i]));
  return SimplexFacet<dim>(x);
}

template <int dim>
Eigen::VectorXd assembleTraction(const LagrangeSpace& V, int label, const VectorField& g) {
  // 2D: 4-point Gauss–Legendre on each edge; 3D: a degree-7 triangle rule (P2 times a
  // quadratic traction stays exact).
  const SimplexQuadrature<dim - 1> rule = simplexQuadrature<dim - 1>(7);
  const auto field = [&g](const SimplexPoint<dim>& x) -> SimplexPoint<dim> {
    return local<dim>(g(global<dim>(x)));
  };
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  for (Index f : V.labelledFacets(label)) {
    const Index* vertices = &V.mesh().facetVertices[static_cast<std::size_t>(f) * dim];
    const NodeList nodes = V.facetNodes(vertices);
    addFacetLoad<dim>(
        V.degree(), facetGeometry<dim>(V, vertices), rule, field,
        [&](int i, const SimplexPoint<dim>& load) { F.segment<dim>(dim * nodes[i]) += load; });
  }
  return F;
}

template <int dim>
ErrorNorms computeErrorNorms(const LagrangeSpace& V, const Eigen::VectorXd& u,
                             const VectorField& exact, const TensorField& exactGradient) {
  using Vec = SimplexPoint<dim>;
  using Mat = Eigen::Matrix<double, dim, dim>;
  const SimplexQuadrature<dim> rule = simplexQuadrature<dim>(8);
  double l2 = 0.0, h1 = 0.0;
  double phi[kMaxNodes];
  Vec grad[kMaxNodes];
  for (Index c = 0; c < V.numCells(); ++c) {
    const Simplex<dim> g = cellGeometry<dim>(V.mesh(), c);
    const NodeList nodes = V.cellNodes(c);
    for (int q = 0; q < rule.size(); ++q) {
      const auto& l = rule.barycentric[q];
      basisValues<dim>(V.degree(), l, phi);
      basisGradients<dim>(V.degree(), l, g, grad);
      Vec uh = Vec::Zero();
      Mat Gh = Mat::Zero();
      for (int i = 0; i < nodes.size; ++i) {
        const Vec ui = u.segment<dim>(dim * nodes[i]);
        uh += phi[i] * ui;
        Gh += ui * grad[i].transpose();
      }
      const Point x = global<dim>(g.point(l));
      const double w = g.measure * rule.weights[q];
      l2 += w * (local<dim>(exact(x)) - uh).squaredNorm();
      h1 += w * (exactGradient(x).template topLeftCorner<dim, dim>() - Gh).squaredNorm();
    }
  }
  return {std::sqrt(l2), std::sqrt(h1)};
}

template <int dim>
Eigen::Matrix<double, dim, dim> gradientAt(const LagrangeSpace& V, const Eigen::VectorXd& u,
                                           Index cell, const SimplexPoint<dim>& x) {
  const Simplex<dim> g = cellGeometry<dim>(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  SimplexPoint<dim> grad[kMaxNodes];
  basisGradients<dim>(V.degree(), g.barycentric(x), g, grad);
  Eigen::Matrix<double, dim, dim> G = Eigen::Matrix<double, dim, dim>::Zero();
  for (int i = 0; i < nodes.size; ++i) G += u.segment<dim>(dim * nodes[i]) * grad[i].transpose();
  return G;
}

template <int dim>
SimplexPoint<dim> displacementAt(const LagrangeSpace& V, const Eigen::VectorXd& u, Index cell,
                                 const SimplexPoint<dim>& x) {
  const Simplex<dim> g = cellGeometry<dim>(V.mesh(), cell);
  const NodeList nodes = V.cellNodes(cell);
  double phi[kMaxNodes];
  basisValues<dim>(V.degree(), g.barycentric(x), phi);
  SimplexPoint<dim> value = SimplexPoint<dim>::Zero();
  for (int i = 0; i < nodes.size; ++i) value += phi[i] * u.segment<dim>(dim * nodes[i]);
  return value;
}

}  // namespace

ElasticityAssembler::ElasticityAssembler(const LagrangeSpace& space, const MaterialMap& materials)
    : space_(&space), materials_(materials) {}

Eigen::SparseMatrix<double> ElasticityAssembler::stiffness() const {
  return dispatch(space_->mesh(), [&](auto d) {
    return assembleStiffness<decltype(d)::value>(*space_, materials_);
  });
}

Eigen::SparseMatrix<double> ElasticityAssembler::stiffness(const std::vector<char>& cells) const {
  FRICTION_ASSERT(static_cast<Index>(cells.size()) == space_->numCells(), "one flag per cell");
  return dispatch(space_->mesh(), [&](auto d) {
    return assembleStiffness<decltype(d)::value>(*space_, materials_, &cells);
  });
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const Point& f) const {
  return bodyForce(VectorField([f](const Point&) { return f; }));
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const Vector2& f) const {
  return bodyForce(Point(f.x(), f.y(), 0.0));
}

Eigen::VectorXd ElasticityAssembler::bodyForce(const VectorField& f) const {
  return dispatch(space_->mesh(),
                  [&](auto d) { return assembleBodyForce<decltype(d)::value>(*space_, f); });
}

Eigen::VectorXd ElasticityAssembler::cellBodyForce(const std::function<Point(Index)>& f) const {
  return dispatch(space_->mesh(),
                  [&](auto d) { return assembleCellBodyForce<decltype(d)::value>(*space_, f); });
}

double ElasticityAssembler::pressureFactor(Index cell) const {
  const Material& m = materials_.ofCell(cell);
  if (space_->dim() == 3 || !m.planeStress()) return 1.0;
  return 2 * m.mu() / (m.lambda() + 2 * m.mu());
}

Eigen::VectorXd ElasticityAssembler::pressureLoad(const CellScalarField& alphaP) const {
  return dispatch(space_->mesh(), [&](auto d) {
    constexpr int dim = decltype(d)::value;
    return assemblePressureLoad<dim>(
        *space_, *this,
        [&](Index c, const Barycentric<dim>&, const Point& x) { return alphaP(c, x); });
  });
}

Eigen::VectorXd ElasticityAssembler::pressureLoad(const Eigen::VectorXd& alphaPAtPoints) const {
  const Mesh& mesh = space_->mesh();
  FRICTION_ASSERT(alphaPAtPoints.size() == static_cast<Eigen::Index>(mesh.points.size()),
                  "one value per mesh point");
  return dispatch(mesh, [&](auto d) {
    constexpr int dim = decltype(d)::value;
    return assemblePressureLoad<dim>(*space_, *this,
                                     [&](Index c, const Barycentric<dim>& l, const Point&) {
                                       double value = 0.0;
                                       for (int v = 0; v <= dim; ++v)
                                         value += l[v] * alphaPAtPoints[mesh.cellVertex(c, v)];
                                       return value;
                                     });
  });
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const Point& g) const {
  return traction(label, VectorField([g](const Point&) { return g; }));
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const Vector2& g) const {
  return traction(label, Point(g.x(), g.y(), 0.0));
}

Eigen::VectorXd ElasticityAssembler::traction(int label, const VectorField& g) const {
  return dispatch(space_->mesh(),
                  [&](auto d) { return assembleTraction<decltype(d)::value>(*space_, label, g); });
}

Eigen::VectorXd ElasticityAssembler::lumpedFacetMass(
    const std::vector<Index>& facetVertices) const {
  const LagrangeSpace& V = *space_;
  return dispatch(V.mesh(), [&](auto d) {
    constexpr int dim = decltype(d)::value;
    FRICTION_ASSERT(facetVertices.size() % dim == 0, "d vertices per facet");
    const double* w = facetLumpedMass<dim>(V.degree());
    Eigen::VectorXd m = Eigen::VectorXd::Zero(V.numNodes());
    for (std::size_t k = 0; k < facetVertices.size(); k += dim) {
      const double measure = facetGeometry<dim>(V, &facetVertices[k]).measure;
      const NodeList nodes = V.facetNodes(&facetVertices[k]);
      for (int i = 0; i < nodes.size; ++i) m[nodes[i]] += w[i] * measure;
    }
    return m;
  });
}

Eigen::SparseMatrix<double> ElasticityAssembler::consistentFacetMass(
    const std::vector<Index>& facetVertices) const {
  const LagrangeSpace& V = *space_;
  return dispatch(V.mesh(), [&](auto d) {
    constexpr int dim = decltype(d)::value;
    FRICTION_ASSERT(facetVertices.size() % dim == 0, "d vertices per facet");
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(facetVertices.size() / dim *
                     static_cast<std::size_t>(V.nodesPerFacet() * V.nodesPerFacet()));
    for (std::size_t k = 0; k < facetVertices.size(); k += dim) {
      const double measure = facetGeometry<dim>(V, &facetVertices[k]).measure;
      const NodeList nodes = V.facetNodes(&facetVertices[k]);
      for (int i = 0; i < nodes.size; ++i)
        for (int j = 0; j < nodes.size; ++j)
          triplets.emplace_back(nodes[i], nodes[j],
                                measure * facetConsistentMass<dim>(V.degree(), i, j));
    }
    Eigen::SparseMatrix<double> M(V.numNodes(), V.numNodes());
    M.setFromTriplets(triplets.begin(), triplets.end());
    return M;
  });
}

Eigen::VectorXd ElasticityAssembler::lumpedEdgeMass(
    const std::vector<std::array<Index, 2>>& edges) const {
  const LagrangeSpace& V = *space_;
  FRICTION_ASSERT(V.dim() == 2, "lumpedEdgeMass: a 2D mesh");
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
  FRICTION_ASSERT(V.dim() == 2, "consistentEdgeMass: a 2D mesh");
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

Point ElasticityAssembler::displacement(const Eigen::VectorXd& u, Index cell,
                                        const Point& x) const {
  return dispatch(space_->mesh(), [&](auto d) {
    constexpr int dim = decltype(d)::value;
    return global<dim>(displacementAt<dim>(*space_, u, cell, local<dim>(x)));
  });
}

Eigen::Matrix3d ElasticityAssembler::displacementGradient(const Eigen::VectorXd& u, Index cell,
                                                          const Point& x) const {
  return dispatch(space_->mesh(), [&](auto d) {
    constexpr int dim = decltype(d)::value;
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    G.topLeftCorner<dim, dim>() = gradientAt<dim>(*space_, u, cell, local<dim>(x));
    return G;
  });
}

Eigen::Matrix3d ElasticityAssembler::strain(const Eigen::VectorXd& u, Index cell,
                                            const Point& x) const {
  const Eigen::Matrix3d G = displacementGradient(u, cell, x);
  return 0.5 * (G + G.transpose());
}

Eigen::Matrix3d ElasticityAssembler::stress(const Eigen::VectorXd& u, Index cell,
                                            const Point& x) const {
  const Eigen::Matrix3d e = strain(u, cell, x);
  const Material& material = materials_.ofCell(cell);
  if (space_->dim() == 3) return material.stress3d(e);
  const Eigen::Matrix2d e2 = e.topLeftCorner<2, 2>();
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  sigma.topLeftCorner<2, 2>() = material.stress(e2);
  sigma(2, 2) = material.outOfPlaneStress(e2);
  return sigma;
}

Vector2 ElasticityAssembler::displacement(const Eigen::VectorXd& u, Index cell,
                                          const Vector2& x) const {
  FRICTION_ASSERT(space_->dim() == 2, "2D evaluation on a 2D mesh");
  return displacementAt<2>(*space_, u, cell, x);
}

Eigen::Matrix2d ElasticityAssembler::displacementGradient(const Eigen::VectorXd& u, Index cell,
                                                          const Vector2& x) const {
  FRICTION_ASSERT(space_->dim() == 2, "2D evaluation on a 2D mesh");
  return gradientAt<2>(*space_, u, cell, x);
}

Eigen::Matrix2d ElasticityAssembler::strain(const Eigen::VectorXd& u, Index cell,
                                            const Vector2& x) const {
  const Eigen::Matrix2d G = displacementGradient(u, cell, x);
  return 0.5 * (G + G.transpose());
}

Eigen::Matrix2d ElasticityAssembler::stress(const Eigen::VectorXd& u, Index cell,
                                            const Vector2& x) const {
  return materials_.ofCell(cell).stress(strain(u, cell, x));
}

ErrorNorms ElasticityAssembler::errorNorms(const Eigen::VectorXd& u, const VectorField& exact,
                                           const TensorField& exactGradient) const {
  return dispatch(space_->mesh(), [&](auto d) {
    return computeErrorNorms<decltype(d)::value>(*space_, u, exact, exactGradient);
  });
}

}  // namespace friction
