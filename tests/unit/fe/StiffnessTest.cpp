// Stiffness matrix (fe/ElasticityAssembler.hpp): symmetry, the three rigid-body modes as its
// exact null space, and positive definiteness once they are fixed — for P1 and P2, plane
// strain and plane stress, on a distorted mesh and on a split mesh (docs/method.md §4, §10).
#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "FeTestMeshes.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

/// The three rigid modes as full dof vectors: x translation, y translation, rotation about
/// (0.5, 0.5) (an infinitesimal rotation: u = ω × (x − x0)).
Eigen::MatrixXd rigidModes(const LagrangeSpace& V) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(V.numDofs(), 3);
  for (Index n = 0; n < V.numNodes(); ++n) {
    const Vector2 x = V.coordinate(n) - Vector2(0.5, 0.5);
    R(2 * n, 0) = 1.0;
    R(2 * n + 1, 1) = 1.0;
    R(2 * n, 2) = -x.y();
    R(2 * n + 1, 2) = x.x();
  }
  return R;
}

}  // namespace

TEST_CASE("fe stiffness is symmetric with exactly the three rigid modes as null space",
          "[fe][stiffness]") {
  const int degree = GENERATE(1, 2);
  const bool planeStress = GENERATE(false, true);
  CAPTURE(degree, planeStress);
  const Mesh mesh = test::unitSquareMesh(3, 0.4);
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromYoungPoisson(2.0e9, 0.3, planeStress);
  const ElasticityAssembler assembler(V, material);
  const Eigen::SparseMatrix<double> K = assembler.stiffness();
  REQUIRE(K.rows() == V.numDofs());
  REQUIRE(K.isCompressed());

  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  const double scale = Kd.cwiseAbs().maxCoeff();
  // Symmetry: entry (i, j) and (j, i) are sums of the same element terms in possibly another
  // order, so they agree to a few ulps of the largest entry; 1e-14 · max|K| is ~50 ulps.
  REQUIRE((Kd - Kd.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);

  // Rigid modes: each entry of K r cancels ~20 terms of size max|K| · |r| (|r| ≤ 1), so
  // round-off is ~20 ulps; 1e-13 · max|K| leaves a margin of about 20.
  const Eigen::MatrixXd KR = Kd * rigidModes(V);
  for (int mode = 0; mode < 3; ++mode) {
    CAPTURE(mode);
    REQUIRE(KR.col(mode).cwiseAbs().maxCoeff() <= 1e-13 * scale);
  }
  // Exactly three zero eigenvalues: the rigid modes and nothing else. On this small mesh the
  // smallest deformation eigenvalue is > 1e-3 of the largest (a loose, mesh-independent
  // bound would be h²); round-off eigenvalues are < 1e-14 of it.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Kd);
  const Eigen::VectorXd ev = eig.eigenvalues();
  const double evMax = ev.maxCoeff();
  for (int k = 0; k < 3; ++k) REQUIRE(std::abs(ev[k]) <= 1e-12 * evMax);
  REQUIRE(ev[3] >= 1e-3 * evMax);

  // Fixing the left side removes the rigid modes: K_ff is positive definite, both by its
  // eigenvalues and by the factorisation the runs use.
  DirichletConditions bc(V);
  REQUIRE(bc.fixPatch(4, FixedComponents::all) == (degree == 1 ? 4 : 7));
  const ReducedSystem reduced(K, bc);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigFf{Eigen::MatrixXd(reduced.matrix())};
  REQUIRE(eigFf.eigenvalues().minCoeff() >= 1e-4 * evMax);
  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  // The full K is singular: the factorisation says so instead of crashing.
  REQUIRE(factor.factor(K) == FactorStatus::notPositiveDefinite);
}

TEST_CASE("fe stiffness of a split mesh decouples the two sides", "[fe][stiffness]") {
  const int degree = GENERATE(1, 2);
  CAPTURE(degree);
  const Mesh mesh = test::splitFourTriangleMesh();
  const LagrangeSpace V(mesh, degree);
  const Material material = Material::fromLame(1.0, 1.0);
  const Eigen::MatrixXd K = Eigen::MatrixXd(ElasticityAssembler(V, material).stiffness());
  // Two free bodies: six rigid modes (three per half). Same tolerances as above.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const Eigen::VectorXd ev = eig.eigenvalues();
  for (int k = 0; k < 6; ++k) REQUIRE(std::abs(ev[k]) <= 1e-12 * ev.maxCoeff());
  REQUIRE(ev[6] >= 1e-3 * ev.maxCoeff());
  // No entry couples the + copy of the fracture to the − copy (exact zero, not round-off).
  for (Index a : {2, 3}) {
    for (Index b : {6, 7})
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) REQUIRE(K(2 * a + r, 2 * b + c) == 0.0);
  }
  if (degree == 2) {
    const Index mp = V.midpointNode(2, 3), mm = V.midpointNode(6, 7);
    REQUIRE(K(2 * mp, 2 * mm) == 0.0);
    REQUIRE(K(2 * mp, 2 * mp) > 0.0);
    REQUIRE(K(2 * mm, 2 * mm) > 0.0);
  }
}

TEST_CASE("fe stiffness of a part of the cells: the parts add up to the whole", "[fe][stiffness]") {
  // ElasticityAssembler::stiffness(cells): the band of cells around the fractures and each
  // rank's own cells in a parallel run (README "Running in parallel") rely on it.
  const int degree = GENERATE(1, 2);
  const bool threeD = GENERATE(false, true);
  CAPTURE(degree, threeD);
  const Mesh mesh = threeD ? test::unitCubeMesh(3, 0.3) : test::unitSquareMesh(6, 0.3);
  const LagrangeSpace V(mesh, degree);
  const ElasticityAssembler assembler(V, Material::fromYoungPoisson(3.0e10, 0.25));
  const Eigen::SparseMatrix<double> K = assembler.stiffness();
  const Index cells = V.numCells();
  REQUIRE(cells > 3);

  // All cells: the same matrix, entry for entry (the same sums in the same order).
  const std::vector<char> all(static_cast<std::size_t>(cells), 1);
  const Eigen::SparseMatrix<double> Kall = assembler.stiffness(all);
  REQUIRE(Kall.nonZeros() == K.nonZeros());
  CHECK(Eigen::MatrixXd(Kall - K).cwiseAbs().maxCoeff() == 0.0);

  // Three contiguous blocks (as three ranks take them): their sum is K to round-off (the sums
  // are grouped otherwise: a few ulps of the largest entry), and each holds only its cells'
  // entries.
  Eigen::SparseMatrix<double> sum(K.rows(), K.cols());
  for (int part = 0; part < 3; ++part) {
    std::vector<char> mine(static_cast<std::size_t>(cells), 0);
    std::fill(mine.begin() + cells * part / 3, mine.begin() + cells * (part + 1) / 3, 1);
    const Eigen::SparseMatrix<double> Kp = assembler.stiffness(mine);
    CHECK(Kp.nonZeros() < K.nonZeros());
    CHECK(Eigen::MatrixXd(Kp - Eigen::SparseMatrix<double>(Kp.transpose())).cwiseAbs().maxCoeff() <=
          1e-12 * K.coeffs().cwiseAbs().maxCoeff());
    sum += Kp;
  }
  const double scale = K.coeffs().cwiseAbs().maxCoeff();
  REQUIRE(scale > 0);
  CHECK(Eigen::MatrixXd(sum - K).cwiseAbs().maxCoeff() <= 1e-14 * scale);

  // One cell alone: its element matrix, d·(nodes per cell) rows and columns at most.
  std::vector<char> one(static_cast<std::size_t>(cells), 0);
  one[1] = 1;
  const Eigen::SparseMatrix<double> K1 = assembler.stiffness(one);
  const long n = static_cast<long>(V.nodesPerCell()) * (threeD ? 3 : 2);
  CHECK(K1.nonZeros() == n * n);
}
