// Simplex kernels (fe/Simplex.hpp) at element level, on vertex arrays built here: partition of
// unity and interpolation of the P1 / P2 bases, gradients against finite differences, the 3D
// element stiffness (symmetry, exactly six rigid modes, patch test, B^T D B with the 6 × 6
// Voigt matrix), facet loads and masses, and the 2D instantiation against an independently
// written triangle formula (docs/method.md §1, §4, §7).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "friction/fe/Material.hpp"
#include "friction/fe/Simplex.hpp"

using namespace friction;

namespace {

using Point3 = SimplexPoint<3>;

/// A skewed tetrahedron (no right angle, no symmetry, aspect about 4) and the same with two
/// vertices swapped (the other orientation).
Simplex<3> skewedTetrahedron(bool swapped = false) {
  std::array<Point3, 4> v = {Point3(0.1, -0.2, 0.3), Point3(1.3, 0.1, -0.1), Point3(0.4, 1.1, 0.2),
                             Point3(0.9, 0.8, 0.55)};
  if (swapped) std::swap(v[1], v[2]);
  return Simplex<3>(v);
}

Simplex<2> skewedTriangle() {
  return Simplex<2>(
      {SimplexPoint<2>(0.1, -0.2), SimplexPoint<2>(1.3, 0.1), SimplexPoint<2>(0.5, 0.9)});
}

/// Barycentric coordinates of the local nodes: vertices, then edge midpoints.
template <int dim>
std::vector<Barycentric<dim>> nodeBarycentrics(int degree) {
  std::vector<Barycentric<dim>> nodes;
  for (int i = 0; i <= dim; ++i) {
    Barycentric<dim> l{};
    l[i] = 1.0;
    nodes.push_back(l);
  }
  if (degree == 2)
    for (const auto& e : SimplexNodes<dim>::edges) {
      Barycentric<dim> l{};
      l[e[0]] = l[e[1]] = 0.5;
      nodes.push_back(l);
    }
  return nodes;
}

/// Deterministic interior barycentric points.
template <int dim>
std::vector<Barycentric<dim>> samplePoints() {
  std::vector<Barycentric<dim>> points;
  for (int k = 1; k <= 7; ++k) {
    Barycentric<dim> l;
    double sum = 0.0;
    for (int i = 0; i <= dim; ++i) sum += (l[i] = 0.1 + std::fmod(0.37 * k * (i + 1), 1.0));
    for (double& x : l) x /= sum;
    points.push_back(l);
  }
  return points;
}

}  // namespace

TEST_CASE("fe simplex geometry: measure, barycentric coordinates and points", "[fe][simplex]") {
  for (bool swapped : {false, true}) {
    const Simplex<3> s = skewedTetrahedron(swapped);
    CAPTURE(swapped);
    Eigen::Matrix3d J;
    for (int k = 0; k < 3; ++k) J.col(k) = s.vertex[k + 1] - s.vertex[0];
    // One determinant of O(1) entries: round-off ~1e-16; 1e-14 relative leaves a margin.
    REQUIRE(s.measure == Approx(std::abs(J.determinant()) / 6).epsilon(1e-14));
    REQUIRE(s.measure > 0.05);
    // λ_i(v_j) = δ_ij and point(barycentric(x)) = x (a handful of O(1) operations: 1e-14).
    for (int j = 0; j < 4; ++j) {
      const Barycentric<3> l = s.barycentric(s.vertex[j]);
      for (int i = 0; i < 4; ++i) REQUIRE(l[i] == Approx(i == j ? 1.0 : 0.0).margin(1e-14));
    }
    for (const auto& l : samplePoints<3>()) {
      const Barycentric<3> back = s.barycentric(s.point(l));
      for (int i = 0; i < 4; ++i) REQUIRE(back[i] == Approx(l[i]).margin(1e-14));
    }
  }
}

TEST_CASE("fe simplex bases: partition of unity and interpolation", "[fe][simplex]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  auto check = [degree](auto dimTag) {
    constexpr int dim = decltype(dimTag)::value;
    const int n = SimplexNodes<dim>::count(degree);
    const auto nodes = nodeBarycentrics<dim>(degree);
    REQUIRE(static_cast<int>(nodes.size()) == n);
    REQUIRE(n == (degree == 1 ? dim + 1 : (dim + 1) * (dim + 2) / 2));
    double phi[SimplexNodes<dim>::max];
    // Basis i is 1 at node i and 0 at the others: exact in binary (λ ∈ {0, 1/2, 1}).
    for (int j = 0; j < n; ++j) {
      basisValues<dim>(degree, nodes[j], phi);
      for (int i = 0; i < n; ++i) {
        CAPTURE(dim, i, j);
        REQUIRE(phi[i] == (i == j ? 1.0 : 0.0));
      }
    }
    // Σ φ_i = 1 anywhere (a sum of ~10 O(1) terms: 1e-14).
    for (const auto& l : samplePoints<dim>()) {
      basisValues<dim>(degree, l, phi);
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += phi[i];
      REQUIRE(sum == Approx(1.0).margin(1e-14));
    }
  };
  check(std::integral_constant<int, 2>());
  check(std::integral_constant<int, 3>());
  // The node order stated in Simplex.hpp, written out independently: triangle mid(01),
  // mid(12), mid(20); tetrahedron VTK_QUADRATIC_TETRA's (01), (12), (20), (03), (13), (23).
  const std::array<std::array<int, 2>, 3> triangleEdges = {{{0, 1}, {1, 2}, {2, 0}}};
  const std::array<std::array<int, 2>, 6> tetrahedronEdges = {
      {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  REQUIRE(SimplexNodes<2>::edges == triangleEdges);
  REQUIRE(SimplexNodes<3>::edges == tetrahedronEdges);
  if (degree == 2) {
    double phi[10];
    basisValues<3>(2, {0.0, 0.5, 0.0, 0.5}, phi);  // mid(13) is node 8
    REQUIRE(phi[8] == 1.0);
    basisValues<3>(2, {0.0, 0.0, 0.5, 0.5}, phi);  // mid(23) is node 9
    REQUIRE(phi[9] == 1.0);
  }
}

TEST_CASE("fe simplex gradients match finite differences of the values", "[fe][simplex]") {
  const int degree = GENERATE(1, 2);
  const bool swapped = GENERATE(false, true);
  CAPTURE(degree, swapped);
  const Simplex<3> s = skewedTetrahedron(swapped);
  const int n = SimplexNodes<3>::count(degree);
  auto values = [&](const Point3& x, double* phi) {
    basisValues<3>(degree, s.barycentric(x), phi);
  };
  // Central differences are exact for quadratics, so only round-off remains: ~1e-16 / h with
  // values O(1), i.e. ~1e-10 for h = 1e-6; gradients are O(1..10): 1e-8 absolute is a margin
  // of 100, while a wrong edge or a missing factor is off by O(1).
  const double h = 1e-6;
  for (const auto& l : samplePoints<3>()) {
    const Point3 x = s.point(l);
    Point3 grad[SimplexNodes<3>::max];
    basisGradients<3>(degree, l, s, grad);
    double plus[SimplexNodes<3>::max], minus[SimplexNodes<3>::max];
    for (int k = 0; k < 3; ++k) {
      values(x + h * Point3::Unit(k), plus);
      values(x - h * Point3::Unit(k), minus);
      for (int i = 0; i < n; ++i) {
        CAPTURE(i, k);
        REQUIRE(grad[i][k] == Approx((plus[i] - minus[i]) / (2 * h)).margin(1e-8));
      }
    }
  }
}

namespace {

/// The six rigid modes at the element's nodes: three translations, three infinitesimal
/// rotations u = ω × (x − c) about the centroid.
Eigen::MatrixXd rigidModes3d(const Simplex<3>& s, int degree) {
  const auto nodes = nodeBarycentrics<3>(degree);
  const int n = static_cast<int>(nodes.size());
  const Point3 c = s.point({0.25, 0.25, 0.25, 0.25});
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, 6);
  for (int i = 0; i < n; ++i) {
    const Point3 x = s.point(nodes[i]) - c;
    for (int k = 0; k < 3; ++k) {
      R(3 * i + k, k) = 1.0;
      R.block<3, 1>(3 * i, 3 + k) = Point3::Unit(k).cross(x);
    }
  }
  return R;
}

/// Strain in Voigt form (εxx, εyy, εzz, 2εyz, 2εxz, 2εxy) of a symmetric tensor.
Eigen::Matrix<double, 6, 1> voigt(const Eigen::Matrix3d& e) {
  Eigen::Matrix<double, 6, 1> v;
  v << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
  return v;
}

}  // namespace

TEST_CASE("fe 3D element stiffness: symmetric, six rigid modes, patch test, B^T D B",
          "[fe][simplex][stiffness]") {
  const int degree = GENERATE(1, 2);
  const bool swapped = GENERATE(false, true);
  CAPTURE(degree, swapped);
  const Simplex<3> s = skewedTetrahedron(swapped);
  const Material material = Material::fromYoungPoisson(2.0e9, 0.3);
  const SimplexQuadrature<3> rule = tetrahedronQuadrature(degree == 1 ? 0 : 2);
  ElementMatrix<3> ke;
  elementStiffness<3>(degree, s, material.lambda(), material.mu(), rule, ke);
  const int n = SimplexNodes<3>::count(degree);
  REQUIRE(ke.rows() == 3 * n);
  REQUIRE(ke.cols() == 3 * n);
  const Eigen::MatrixXd K = ke;
  const double scale = K.cwiseAbs().maxCoeff();
  REQUIRE(scale > 0.0);

  // Symmetry: (i, j) and (j, i) are the same products in another order: a few ulps of the
  // largest entry; 1e-14 · max|K| is ~50 ulps.
  REQUIRE((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);

  // K r = 0 for the six rigid modes: each entry cancels ~30 terms of size max|K| · |r|
  // (|r| ≤ 1): round-off ~30 ulps; 1e-13 · max|K| leaves a margin.
  const Eigen::MatrixXd KR = K * rigidModes3d(s, degree);
  for (int mode = 0; mode < 6; ++mode) {
    CAPTURE(mode);
    REQUIRE(KR.col(mode).cwiseAbs().maxCoeff() <= 1e-13 * scale);
  }
  // Positive semi-definite with exactly six zero eigenvalues: round-off eigenvalues are
  // < 1e-14 of the largest, the smallest deformation mode of this element is > 1e-3 of it.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const Eigen::VectorXd ev = eig.eigenvalues();
  const double evMax = ev.maxCoeff();
  for (int k = 0; k < 6; ++k) REQUIRE(std::abs(ev[k]) <= 1e-12 * evMax);
  REQUIRE(ev[6] >= 1e-3 * evMax);

  // Patch test at element level: for u(x) = A x + b the energy uᵀ K u is ∫ ε : C : ε
  // = |T| ε_vᵀ D ε_v with the 6 × 6 Voigt matrix (constant strain). ~100 terms of size
  // max|K| |u|²: 1e-12 relative.
  const Eigen::Matrix<double, 6, 6> D = material.voigtMatrix3d();
  const auto nodes = nodeBarycentrics<3>(degree);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::Matrix3d A;
    for (int k = 0; k < 9; ++k) A(k / 3, k % 3) = std::sin(1.7 * k + 0.9 * trial);
    const Point3 b(0.3, -0.1 * trial, 0.2);
    Eigen::VectorXd u(3 * n);
    for (int i = 0; i < n; ++i) u.segment<3>(3 * i) = A * s.point(nodes[i]) + b;
    const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
    const double exact = s.measure * voigt(eps).dot(D * voigt(eps));
    REQUIRE(u.dot(K * u) == Approx(exact).epsilon(1e-12));
  }

  // The Lamé form equals ∫ Bᵀ D B, B the 6 × 3n strain-displacement matrix, by the same rule:
  // same quantities summed in another order, 1e-13 of max|K|.
  Eigen::MatrixXd BtDB = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Point3 grad[SimplexNodes<3>::max];
  for (int q = 0; q < rule.size(); ++q) {
    basisGradients<3>(degree, rule.barycentric[q], s, grad);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3 * n);
    for (int i = 0; i < n; ++i) {
      const Point3& g = grad[i];
      B(0, 3 * i) = g.x();
      B(1, 3 * i + 1) = g.y();
      B(2, 3 * i + 2) = g.z();
      B(3, 3 * i + 1) = g.z();
      B(3, 3 * i + 2) = g.y();
      B(4, 3 * i) = g.z();
      B(4, 3 * i + 2) = g.x();
      B(5, 3 * i) = g.y();
      B(5, 3 * i + 1) = g.x();
    }
    BtDB += s.measure * rule.weights[q] * B.transpose() * D * B;
  }
  REQUIRE((K - BtDB).cwiseAbs().maxCoeff() <= 1e-13 * scale);
}

TEST_CASE("fe 3D Voigt matrix and stress: sigma = lambda tr(eps) I + 2 mu eps",
          "[fe][simplex][material]") {
  const Material material = Material::fromLame(1.7e9, 0.9e9);
  const double lambda = 1.7e9, mu = 0.9e9;
  const Eigen::Matrix<double, 6, 6> D = material.voigtMatrix3d();
  REQUIRE((D - D.transpose()).cwiseAbs().maxCoeff() == 0.0);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::Matrix3d e;
    for (int k = 0; k < 9; ++k) e(k / 3, k % 3) = std::cos(2.3 * k + 1.1 * trial);
    e = 0.5 * (e + e.transpose()).eval();
    const Eigen::Matrix3d sigma = lambda * e.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu * e;
    const Eigen::Matrix<double, 6, 1> sv = D * voigt(e);
    // A few products of O(1e9): 1e-14 relative to the largest stress is ~50 ulps.
    const double tol = 1e-14 * sigma.cwiseAbs().maxCoeff();
    const int row[6] = {0, 1, 2, 1, 0, 0}, col[6] = {0, 1, 2, 2, 2, 1};
    for (int k = 0; k < 6; ++k) {
      CAPTURE(trial, k);
      REQUIRE(sv[k] == Approx(sigma(row[k], col[k])).margin(tol));
    }
    REQUIRE((material.stress3d(e) - sigma).cwiseAbs().maxCoeff() <= tol);
  }
}

TEST_CASE("fe 3D facets: area, surface loads and masses by the triangle rules", "[fe][simplex]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Simplex<3> s = skewedTetrahedron();
  const SimplexFacet<3> face({s.vertex[1], s.vertex[2], s.vertex[3]});
  const double area = 0.5 * (s.vertex[2] - s.vertex[1]).cross(s.vertex[3] - s.vertex[1]).norm();
  REQUIRE(face.measure == Approx(area).epsilon(1e-14));
  const int n = facetNodeCount<3>(degree);
  REQUIRE(n == (degree == 1 ? 3 : 6));

  // A constant traction: the nodal forces sum to g · area, and each node gets g times the
  // integral of its basis (P1: area/3; P2: 0 at vertices, area/3 at mid-edge nodes).
  const Point3 g(1.0, -2.0, 0.5);
  std::vector<Point3> f(static_cast<std::size_t>(n), Point3::Zero());
  addFacetLoad<3>(
      degree, face, triangleQuadrature(2), [&](const Point3&) { return g; },
      [&](int i, const Point3& load) { f[static_cast<std::size_t>(i)] += load; });
  for (int i = 0; i < n; ++i) {
    const double share = degree == 1 ? 1.0 / 3 : (i < 3 ? 0.0 : 1.0 / 3);
    CAPTURE(i);
    REQUIRE((f[static_cast<std::size_t>(i)] - share * area * g).norm() <= 1e-14 * g.norm());
  }

  // The consistent mass is ∫ φ_i φ_j / |F| (degree-4 rule: exact for P2 products); the lumped
  // weights are positive, sum to 1 and, for P1, are the row sums. Fractions of O(1): 1e-15.
  const TriangleQuadrature rule = triangleQuadrature(4);
  const double* lumped = facetLumpedMass<3>(degree);
  double lumpedSum = 0.0;
  for (int i = 0; i < n; ++i) {
    REQUIRE(lumped[i] > 0.0);
    lumpedSum += lumped[i];
    double rowSum = 0.0;
    for (int j = 0; j < n; ++j) {
      double m = 0.0;
      double phi[6];
      for (int q = 0; q < rule.size(); ++q) {
        facetBasisValues<3>(degree, rule.barycentric[q], phi);
        m += rule.weights[q] * phi[i] * phi[j];
      }
      CAPTURE(i, j);
      REQUIRE(facetConsistentMass<3>(degree, i, j) == Approx(m).margin(1e-15));
      rowSum += facetConsistentMass<3>(degree, i, j);
    }
    if (degree == 1) REQUIRE(lumped[i] == Approx(rowSum).margin(1e-15));
  }
  REQUIRE(lumpedSum == Approx(1.0).margin(1e-15));
  // P1-iso-P2 weights integrate the P2 interpolant of a linear function exactly (they are
  // the P1 lumped weights of the four sub-triangles): Σ w_i f(x_i) = f(centroid).
  if (degree == 2) {
    const auto nodes = nodeBarycentrics<2>(2);
    double sum = 0.0, centroid = 0.0;
    for (int i = 0; i < 6; ++i) sum += lumped[i] * (0.3 + 2.0 * nodes[i][1] - nodes[i][2]);
    centroid = 0.3 + 2.0 / 3 - 1.0 / 3;
    REQUIRE(sum == Approx(centroid).margin(1e-15));
  }
}

TEST_CASE("fe 2D kernels: the dim = 2 instantiation against a plain triangle formula",
          "[fe][simplex][stiffness]") {
  // An independent element stiffness: reference triangle (0,0), (1,0), (0,1), Jacobian
  // J = [b − a, c − a], reference gradients mapped by J⁻ᵀ, B with engineering shear and the
  // 3 × 3 Voigt matrix, degree-2 rule, written without barycentric coordinates.
  const int degree = GENERATE(1, 2);
  const bool planeStress = GENERATE(false, true);
  CAPTURE(degree, planeStress);
  const Material material = Material::fromYoungPoisson(3.0e10, 0.25, planeStress);
  const Simplex<2> s = skewedTriangle();
  const Eigen::Vector2d a = s.vertex[0], b = s.vertex[1], c = s.vertex[2];
  Eigen::Matrix2d J;
  J.col(0) = b - a;
  J.col(1) = c - a;
  const Eigen::Matrix2d JinvT = J.inverse().transpose();
  const double area = 0.5 * J.determinant();
  REQUIRE(s.measure == Approx(area).epsilon(1e-15));
  const int n = degree == 1 ? 3 : 6;
  // Reference basis gradients at (ξ, η), order v0 v1 v2 mid(01) mid(12) mid(20).
  auto refGrad = [degree](double xi, double eta) {
    Eigen::Matrix<double, 2, 6> g = Eigen::Matrix<double, 2, 6>::Zero();
    if (degree == 1) {
      g << -1, 1, 0, 0, 0, 0, -1, 0, 1, 0, 0, 0;
    } else {
      const double z = 1 - xi - eta;
      g.col(0) << -(4 * z - 1), -(4 * z - 1);
      g.col(1) << 4 * xi - 1, 0;
      g.col(2) << 0, 4 * eta - 1;
      g.col(3) << 4 * (z - xi), -4 * xi;
      g.col(4) << 4 * eta, 4 * xi;
      g.col(5) << -4 * eta, 4 * (z - eta);
    }
    return g;
  };
  const Eigen::Matrix3d D = material.voigtMatrix();
  const double pts[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  Eigen::MatrixXd plain = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (const auto& p : pts) {
    const Eigen::Matrix<double, 2, 6> g = JinvT * refGrad(p[0], p[1]);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, 2 * n);
    for (int i = 0; i < n; ++i) {
      B(0, 2 * i) = g(0, i);
      B(1, 2 * i + 1) = g(1, i);
      B(2, 2 * i) = g(1, i);
      B(2, 2 * i + 1) = g(0, i);
    }
    plain += area / 3 * B.transpose() * D * B;
  }
  ElementMatrix<2> ke;
  elementStiffness<2>(degree, s, material.lambdaStar(), material.mu(), triangleQuadrature(2), ke);
  REQUIRE(ke.rows() == 2 * n);
  // Same integrand, different operations (inverse Jacobian, Voigt products): round-off of a
  // few ulps per entry; 1e-14 of the largest entry.
  const double scale = plain.cwiseAbs().maxCoeff();
  REQUIRE(scale > 0.0);
  REQUIRE((Eigen::MatrixXd(ke) - plain).cwiseAbs().maxCoeff() <= 1e-14 * scale);
}
