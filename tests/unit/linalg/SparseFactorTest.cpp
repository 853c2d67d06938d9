// SparseFactor (linalg/SparseFactor.hpp): both backends solve an SPD system to round-off,
// for one and several right-hand sides; the counters count; singular and indefinite matrices
// give a status value; a typo in the backend name is an InputError listing valid names.
#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "../fe/FeTestMeshes.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

/// A reduced elasticity matrix (P2, left side fixed): SPD, a few thousand unknowns, entries
/// of order E = 1e10 Pa, so that relative tolerances are really relative.
Eigen::SparseMatrix<double> spdMatrix(Eigen::SparseMatrix<double>* full = nullptr) {
  static const Mesh mesh = test::unitSquareMesh(12, 0.3);
  static const LagrangeSpace V(mesh, 2);
  static const Material material = Material::fromYoungPoisson(1e10, 0.35);
  const Eigen::SparseMatrix<double> K = ElasticityAssembler(V, material).stiffness();
  if (full) *full = K;
  DirichletConditions bc(V);
  bc.fixPatch(4, FixedComponents::all);
  return ReducedSystem(K, bc).matrix();
}

}  // namespace

TEST_CASE("linalg SparseFactor backends solve an SPD system to round-off", "[linalg]") {
  const std::string backend = GENERATE(as<std::string>{}, "cholmod", "simplicialLDLT");
  CAPTURE(backend);
  const Eigen::SparseMatrix<double> A = spdMatrix();
  SparseFactor factor(backend);
  REQUIRE(factor.backend() == backend);
  REQUIRE_FALSE(factor.ok());
  REQUIRE(factor.numFactorizations() == 0);
  REQUIRE(factor.factor(A) == FactorStatus::ok);
  REQUIRE(factor.ok());
  REQUIRE(factor.rows() == A.rows());
  REQUIRE(factor.minPivotRatio() > factor.pivotTolerance());
  REQUIRE(factor.factorSeconds() >= 0.0);

  // Manufactured: x known, b = A x.
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    X(i, 0) = std::sin(0.1 * i);
    X(i, 1) = 1.0;
    X(i, 2) = (i % 7) - 3.0;
  }
  const Eigen::MatrixXd B = A * X;
  // Backward error ‖A x − b‖ / (‖A‖ ‖x‖) of a Cholesky solve is a small multiple of eps
  // (~1e-16 · growth); 1e-14 allows for the sum over ~30 entries per row. The forward error
  // is at most cond(A) ≈ 1e4 (h = 1/12, P2) times that: 1e-10 relative.
  const double normA = Eigen::MatrixXd(A).cwiseAbs().rowwise().sum().maxCoeff();
  const Eigen::VectorXd x = factor.solve(Eigen::VectorXd(B.col(0)));
  REQUIRE((A * x - B.col(0)).cwiseAbs().maxCoeff() <= 1e-14 * normA * x.cwiseAbs().maxCoeff());
  REQUIRE((x - X.col(0)).cwiseAbs().maxCoeff() <= 1e-10);
  const Eigen::MatrixXd Y = factor.solve(B);
  REQUIRE((Y - X).cwiseAbs().maxCoeff() <= 1e-10);
  REQUIRE(factor.numSolves() == 1 + 3);
  REQUIRE(factor.numFactorizations() == 1);
}

TEST_CASE("linalg SparseFactor backends agree with each other", "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.0);
  SparseFactor a("cholmod"), c("simplicialLDLT");
  REQUIRE(a.factor(A) == FactorStatus::ok);
  REQUIRE(c.factor(A) == FactorStatus::ok);
  const Eigen::VectorXd xa = a.solve(b), xc = c.solve(b);
  // Two backward-stable solves differ by at most ~cond(A) · eps relative (see above).
  REQUIRE((xa - xc).norm() <= 1e-10 * xa.norm());
}

TEST_CASE("linalg SparseFactor reports singular and indefinite matrices as values", "[linalg]") {
  const std::string backend = GENERATE(as<std::string>{}, "cholmod", "simplicialLDLT");
  CAPTURE(backend);
  SparseFactor factor(backend);
  // The free-floating stiffness matrix has the three rigid modes in its null space.
  Eigen::SparseMatrix<double> K;
  spdMatrix(&K);
  REQUIRE(factor.factor(K) == FactorStatus::notPositiveDefinite);
  REQUIRE_FALSE(factor.ok());
  // An indefinite matrix.
  Eigen::SparseMatrix<double> D(3, 3);
  D.insert(0, 0) = 2.0;
  D.insert(1, 1) = -1.0;
  D.insert(2, 2) = 3.0;
  D.makeCompressed();
  REQUIRE(factor.factor(D) == FactorStatus::notPositiveDefinite);
  // Recovers: the next good matrix factors fine.
  REQUIRE(factor.factor(spdMatrix()) == FactorStatus::ok);
  REQUIRE(factor.numFactorizations() == 3);
  REQUIRE(std::string(toString(FactorStatus::notPositiveDefinite)) == "notPositiveDefinite");
}

TEST_CASE("linalg SparseFactor rejects an unknown backend with the valid names", "[linalg]") {
  REQUIRE(SparseFactor::backendNames() == std::vector<std::string>{"cholmod", "simplicialLDLT"});
  try {
    SparseFactor factor("cholmd", SourceLocation{"system/solverDict", 12});
    FAIL("no InputError");
  } catch (const InputError& e) {
    REQUIRE(e.location().file == "system/solverDict");
    REQUIRE(e.location().line == 12);
    REQUIRE_THAT(e.message(), Catch::Contains("'cholmd'") &&
                                  Catch::Contains("did you mean 'cholmod'") &&
                                  Catch::Contains("cholmod, simplicialLDLT"));
  }
}
