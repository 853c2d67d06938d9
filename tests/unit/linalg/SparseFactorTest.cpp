// SparseFactor (linalg/SparseFactor.hpp): both backends solve an SPD system to round-off,
// for one and several right-hand sides; the counters count; singular and indefinite matrices
// give a status value; a typo in the backend name is an InputError listing valid names; the
// cholmod backend orders as told (SparseFactor::setOrdering).
#include <Eigen/Dense>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <vector>

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

/// The relative pivot test passed: minPivotRatio above the tolerance, or NaN for a backend
/// that judges its pivots itself (mumps, which then reported ok).
bool pivotsPass(const SparseFactor& factor) {
  if (factor.backend() == "mumps" || factor.iterative())
    return factor.ok() && std::isnan(factor.minPivotRatio());
  return factor.minPivotRatio() > factor.pivotTolerance();
}

/// The number of different column patterns of A (sets of rows), counted independently of
/// SparseFactor's grouping.
double distinctColumns(const Eigen::SparseMatrix<double>& A) {
  std::set<std::vector<int>> patterns;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    std::vector<int> rows;
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      rows.push_back(static_cast<int>(it.row()));
    std::sort(rows.begin(), rows.end());
    patterns.insert(rows);
  }
  return static_cast<double>(patterns.size());
}

/// CG's relative residual for the iterative backend (amg) in these tests: tighter than the
/// default 1e-10, so that the direct backends' checks apply with bounds scaled by it.
constexpr double amgTolerance = 1e-12;

/// A backend by name, the iterative one set to amgTolerance.
SparseFactor backendNamed(const std::string& name) {
  SparseFactor factor(name);
  factor.setIterativeTolerance(amgTolerance);
  return factor;
}

}  // namespace

TEST_CASE("linalg SparseFactor backends solve an SPD system to round-off", "[linalg]") {
  const std::string backend = GENERATE(from_range(SparseFactor::backendNames()));
  CAPTURE(backend);
  const Eigen::SparseMatrix<double> A = spdMatrix();
  SparseFactor factor = backendNamed(backend);
  REQUIRE(factor.backend() == backend);
  REQUIRE_FALSE(factor.ok());
  REQUIRE(factor.numFactorizations() == 0);
  REQUIRE(factor.factor(A) == FactorStatus::ok);
  REQUIRE(factor.ok());
  REQUIRE(factor.rows() == A.rows());
  REQUIRE(pivotsPass(factor));
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
  if (factor.iterative()) {
    // CG stops at ‖A x − b‖ ≤ tol ‖b‖ (its recursively updated residual: the true one may
    // drift by a few ulps of ‖A‖ ‖x‖ more, hence the factor 2); the forward error is then at
    // most cond(A) ≈ 1e4 times that, ×10 for the max norm against the 2-norm.
    REQUIRE((A * x - B.col(0)).norm() <= 2 * amgTolerance * B.col(0).norm());
    REQUIRE((x - X.col(0)).cwiseAbs().maxCoeff() <= 1e5 * amgTolerance * X.col(0).norm());
    const Eigen::MatrixXd Y = factor.solve(B);
    for (Eigen::Index c = 0; c < 3; ++c)
      REQUIRE((Y.col(c) - X.col(c)).cwiseAbs().maxCoeff() <= 1e5 * amgTolerance * X.col(c).norm());
    // The check solve of the setup measured the same kind of error.
    REQUIRE(factor.analysis().iterativeForwardError > 0);
    REQUIRE(factor.analysis().iterativeForwardError <= 1e5 * amgTolerance);
    REQUIRE(factor.currentAnalysis().iterativeSolves == 1 + 1 + 3);  // the check, 1, 3
    REQUIRE(factor.currentAnalysis().iterativeUnconverged == 0);
  } else {
    REQUIRE((A * x - B.col(0)).cwiseAbs().maxCoeff() <= 1e-14 * normA * x.cwiseAbs().maxCoeff());
    REQUIRE((x - X.col(0)).cwiseAbs().maxCoeff() <= 1e-10);
    const Eigen::MatrixXd Y = factor.solve(B);
    REQUIRE((Y - X).cwiseAbs().maxCoeff() <= 1e-10);
  }
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
  const std::string backend = GENERATE(from_range(SparseFactor::backendNames()));
  CAPTURE(backend);
  SparseFactor factor = backendNamed(backend);
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
#if defined(FRICTION_WITH_MUMPS) && defined(FRICTION_WITH_HYPRE)
  REQUIRE(SparseFactor::backendNames() ==
          std::vector<std::string>{"cholmod", "simplicialLDLT", "mumps", "amg"});
#elif defined(FRICTION_WITH_MUMPS)
  REQUIRE(SparseFactor::backendNames() ==
          std::vector<std::string>{"cholmod", "simplicialLDLT", "mumps"});
  try {
    SparseFactor factor("amg", SourceLocation{"system/frictionSolution", 3});
    FAIL("no InputError");
  } catch (const InputError& e) {
    REQUIRE_THAT(e.message(),
                 Catch::Contains("not in this build") && Catch::Contains("-DFRICTION_HYPRE=ON"));
  }
#else
  REQUIRE(SparseFactor::backendNames() == std::vector<std::string>{"cholmod", "simplicialLDLT"});
  // A build without MUMPS names what it lacks.
  try {
    SparseFactor factor("mumps", SourceLocation{"system/frictionSolution", 3});
    FAIL("no InputError");
  } catch (const InputError& e) {
    REQUIRE_THAT(e.message(),
                 Catch::Contains("not in this build") && Catch::Contains("-DFRICTION_MUMPS=ON"));
  }
#endif
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

namespace {

/// A border for spdMatrix(): m columns, each coupling a few rows (as a jump couples the dofs
/// next to a fracture), and a diagonally dominant C, so that [A B; Bᵀ C] is SPD.
void border(Eigen::Index n, Eigen::Index m, Eigen::SparseMatrix<double>& B,
            Eigen::SparseMatrix<double>& C) {
  std::vector<Eigen::Triplet<double>> tb, tc;
  for (Eigen::Index a = 0; a < m; ++a) {
    for (int k = 0; k < 4; ++k)
      tb.emplace_back((7 * a + 13 * k) % n, a, 1e9 * std::cos(1.0 + a + k));
    tc.emplace_back(a, a, 1e11);
    if (a > 0) tc.emplace_back(a, a - 1, -2e9), tc.emplace_back(a - 1, a, -2e9);
  }
  B.resize(n, m);
  B.setFromTriplets(tb.begin(), tb.end());
  C.resize(m, m);
  C.setFromTriplets(tc.begin(), tc.end());
}

}  // namespace

TEST_CASE("linalg SparseFactor forms the Schur complement C - B^T A^-1 B with the factorisation",
          "[linalg]") {
  const std::string backend = GENERATE(from_range(SparseFactor::backendNames()));
  CAPTURE(backend);
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows(), m = 40;
  Eigen::SparseMatrix<double> B, C;
  border(n, m, B, C);

  // Reference: dense A⁻¹ B by a dense Cholesky (independent of SparseFactor).
  const Eigen::MatrixXd Ad(A);
  const Eigen::MatrixXd reference =
      Eigen::MatrixXd(C) - Eigen::MatrixXd(B).transpose() * Ad.llt().solve(Eigen::MatrixXd(B));

  SparseFactor factor = backendNamed(backend);
  REQUIRE(factor.factorWithSchur(A, B, C) == FactorStatus::ok);
  // The bounds below are the direct backends' round-off. amg solves by CG to amgTolerance, so
  // its A⁻¹ B errs by up to cond(A) ≈ 1e4 times that: its bounds are 1e5 · amgTolerance
  // relative (×10 margin) where the direct ones' are 1e-10 and 1e-9.
  const bool iterative = factor.iterative();
  const double solveBound = iterative ? 1e5 * amgTolerance : 1e-10;
  const double schurBound = iterative ? 1e5 * amgTolerance : 1e-9;
  REQUIRE(factor.ok());
  REQUIRE(factor.numFactorizations() == 1);
  const Eigen::MatrixXd& S = factor.schurComplement();
  REQUIRE(S.rows() == m);
  REQUIRE(S.cols() == m);
  // Both are round-off of cond(A) ≈ 1e4 times eps on entries of size ‖C‖ = 1e11: 1e-9
  // relative is a wide margin that a wrong sign or a missing block would not meet.
  const double scale = reference.cwiseAbs().maxCoeff();
  REQUIRE(scale > 0);
  CHECK((S - reference).cwiseAbs().maxCoeff() <= schurBound * scale);
  CHECK((S - S.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  // cholmod and mumps deliver it from the bordered factorisation, with no back-substitution;
  // simplicialLDLT and amg spend one per border column.
  if (backend != "simplicialLDLT" && !iterative)
    CHECK(factor.schurSolves() == 0);
  else
    CHECK(factor.schurSolves() == m);
  CHECK(factor.numSolves() == factor.schurSolves());

  // After the bordered factorisation, solve() still solves with A (not with the bordered
  // matrix): one and several right-hand sides.
  Eigen::MatrixXd X(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) X(i, 0) = std::sin(0.1 * i), X(i, 1) = (i % 5) - 2.0;
  const Eigen::MatrixXd Y = factor.solve(Eigen::MatrixXd(A * X));
  CHECK((Y - X).cwiseAbs().maxCoeff() <= solveBound * (iterative ? X.norm() : 1.0));
  const Eigen::VectorXd y = factor.solve(Eigen::VectorXd(A * X.col(0)));
  CHECK((y - X.col(0)).cwiseAbs().maxCoeff() <= solveBound * (iterative ? X.norm() : 1.0));
  CHECK(pivotsPass(factor));

  // The complement by blocks of solves, from the same factor, agrees.
  const long before = factor.numSolves();
  const Eigen::MatrixXd byBlocks = factor.schurBySolves(B, C);
  CHECK(factor.numSolves() - before == m);
  CHECK((byBlocks - reference).cwiseAbs().maxCoeff() <= schurBound * scale);

  // A plain factor() afterwards forgets the complement.
  REQUIRE(factor.factor(A) == FactorStatus::ok);
  CHECK(factor.schurComplement().size() == 0);
}

TEST_CASE("linalg SparseFactor: a semi-definite complement is formed, a singular A is reported",
          "[linalg]") {
  const std::string backend = GENERATE(from_range(SparseFactor::backendNames()));
  CAPTURE(backend);
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  // C = Bᵀ A⁻¹ B exactly for B = A E (E two unit columns): the complement is zero, so the
  // bordered matrix is only semi-definite (as when a part of the body is held by a
  // fracture alone). The complement must still come out, as zero to round-off.
  Eigen::SparseMatrix<double> E(n, 2);
  E.insert(3, 0) = 1.0;
  E.insert(n / 2, 1) = 1.0;
  const Eigen::SparseMatrix<double> B = A * E;
  const Eigen::SparseMatrix<double> C = E.transpose() * B;
  SparseFactor factor = backendNamed(backend);
  REQUIRE(factor.factorWithSchur(A, B, C) == FactorStatus::ok);
  const double scale = Eigen::MatrixXd(C).cwiseAbs().maxCoeff();
  REQUIRE(scale > 0);
  // Round-off for a factor; amg's CG to amgTolerance errs by cond(A) ≈ 1e4 times it (×10).
  CHECK(factor.schurComplement().cwiseAbs().maxCoeff() <=
        (factor.iterative() ? 1e5 * amgTolerance : 1e-10) * scale);

  // A singular A is A's failure, reported as factor() reports it.
  Eigen::SparseMatrix<double> K;
  spdMatrix(&K);
  Eigen::SparseMatrix<double> BK(K.rows(), 1), CK(1, 1);
  BK.insert(0, 0) = 1.0;
  CK.insert(0, 0) = 1.0;
  CHECK(factor.factorWithSchur(K, BK, CK) == FactorStatus::notPositiveDefinite);
  CHECK_FALSE(factor.ok());
}

TEST_CASE("linalg SparseFactor reports the ordering and the size of the factor it made",
          "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  const Eigen::SparseMatrix<double> lower = A.triangularView<Eigen::Lower>();

  SparseFactor cholmod("cholmod");
  REQUIRE(cholmod.factor(A) == FactorStatus::ok);
  const FactorAnalysis plain = cholmod.analysis();
  // L holds at least the lower triangle of A (no cancellation is assumed by the symbolic
  // count) and at most a dense triangle; a factorisation costs at least one operation per
  // entry of L.
  CHECK(plain.entries >= static_cast<double>(lower.nonZeros()));
  CHECK(plain.entries <= 0.5 * static_cast<double>(n) * static_cast<double>(n + 1));
  CHECK(plain.flops >= plain.entries);
  CHECK(plain.bytes >= 8 * plain.entries);
  CHECK_THAT(std::string("natural given AMD METIS NESDIS COLAMD"), Catch::Contains(plain.ordering));
  CHECK_FALSE(plain.ordering.empty());
  CHECK(cholmod.schurFallbackReason().empty());

  // Bordered: the same ordering of A, and the border's rows and block on top of A's factor.
  const Eigen::Index m = 40;
  Eigen::SparseMatrix<double> B, C;
  border(n, m, B, C);
  REQUIRE(cholmod.factorWithSchur(A, B, C) == FactorStatus::ok);
  REQUIRE(cholmod.schurSolves() == 0);
  CHECK(cholmod.schurFallbackReason().empty());
  CHECK(cholmod.analysis().ordering == plain.ordering);
  CHECK(cholmod.analysis().entries >= plain.entries + 0.5 * m * (m + 1));
  CHECK(cholmod.analysis().flops > plain.flops);

  // A backend that does not know its factor's size says so with zeros (no line in the log).
  SparseFactor ldlt("simplicialLDLT");
  REQUIRE(ldlt.factor(A) == FactorStatus::ok);
  CHECK(ldlt.analysis().entries == 0);
  CHECK(ldlt.analysis().ordering.empty());
}

#ifdef FRICTION_WITH_MUMPS
TEST_CASE("linalg SparseFactor mumps reports its ordering, factor size and memory", "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  const Eigen::SparseMatrix<double> lower = A.triangularView<Eigen::Lower>();
  SparseFactor mumps("mumps");
  REQUIRE(mumps.factor(A) == FactorStatus::ok);
  const FactorAnalysis a = mumps.analysis();
  // As for cholmod: L holds at least A's lower triangle, at most a dense one.
  CHECK(a.entries >= static_cast<double>(lower.nonZeros()));
  CHECK(a.entries <= 0.5 * static_cast<double>(n) * static_cast<double>(n + 1));
  CHECK(a.flops >= a.entries);
  // METIS's order of A, computed by CHOLMOD and given to MUMPS (MumpsBackend.cpp says why),
  // also with a border, whose unknowns it puts last.
  CHECK(a.ordering == "METIS (by CHOLMOD)");
  // One rank here (the unit tests run without mpirun): it holds everything.
  CHECK(a.ranks == 1);
  CHECK(a.rankMemoryMax > 8 * a.entries);
  CHECK(a.memoryTotal == a.rankMemoryMax);
  Eigen::SparseMatrix<double> B, C;
  border(n, 40, B, C);
  REQUIRE(mumps.factorWithSchur(A, B, C) == FactorStatus::ok);
  CHECK(mumps.schurSolves() == 0);
  CHECK(mumps.analysis().ordering == "METIS (by CHOLMOD)");
  CHECK(mumps.analysis().entries >= a.entries + 0.5 * 40 * 41);
}
#endif

TEST_CASE("linalg SparseFactor cholmod orders as told, once, and says what chose the ordering",
          "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  Eigen::SparseMatrix<double> B, C;
  border(n, 40, B, C);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  SparseFactor reference("cholmod");
  reference.setOrdering(Ordering::amd, 2);
  REQUIRE(reference.factor(A) == FactorStatus::ok);
  const Eigen::VectorXd x0 = reference.solve(b);

  // Each ordering is the one CHOLMOD's factor says it used (L->ordering), with and without the
  // border, and the answer is the same to round-off.
  const struct {
    Ordering ordering;
    const char* word;
    const char* used;
  } cases[] = {{Ordering::amd, "amd", "AMD"},
               {Ordering::metis, "metis", "METIS"},
               {Ordering::nesdis, "nesdis", "NESDIS"}};
  std::vector<double> entries;
  for (const auto& c : cases) {
    CAPTURE(c.word);
    CHECK(toString(c.ordering) == c.word);
    CHECK(orderingNamed(c.word) == c.ordering);
    SparseFactor f("cholmod");
    REQUIRE(f.takesOrdering());
    f.setOrdering(c.ordering, 2);
    REQUIRE(f.factor(A) == FactorStatus::ok);
    CHECK(f.analysis().ordering == c.used);
    CHECK(f.analysis().orderingChoice == std::string("ordering ") + c.word);
    // Ordered on the graph of the groups of equal columns: a node's two components (and in
    // P2 the nodes of a corner's one triangle, which have the same neighbours).
    CHECK(f.analysis().orderedGroups == distinctColumns(A));
    CHECK(f.analysis().orderedGroups <= n / 2);
    entries.push_back(f.analysis().entries);
    CHECK((f.solve(b) - x0).norm() <= 1e-10 * x0.norm());
    REQUIRE(f.factorWithSchur(A, B, C) == FactorStatus::ok);
    REQUIRE(f.schurSolves() == 0);
    CHECK(f.analysis().ordering == c.used);
    CHECK(f.analysis().orderedGroups == distinctColumns(A));
    CHECK(f.analysis().orderingSeconds > 0);
    CHECK((f.solve(b) - x0).norm() <= 1e-10 * x0.norm());
  }
  // Different orderings, different factors: the setting reached CHOLMOD.
  CHECK(entries[0] != entries[1]);
  CHECK(entries[0] != entries[2]);

  // auto: the rule's ordering for the dimension and the size, and the log's reason.
  for (int dim : {2, 3}) {
    CAPTURE(dim);
    SparseFactor f("cholmod");
    f.setOrdering(Ordering::automatic, dim);
    REQUIRE(f.factorWithSchur(A, B, C) == FactorStatus::ok);
    const Ordering chosen = automaticOrdering(dim, n);
    REQUIRE(chosen != Ordering::automatic);
    REQUIRE(chosen != Ordering::cholmodDefault);  // one ordering, not several tried
    for (const auto& c : cases)
      if (c.ordering == chosen) CHECK(f.analysis().ordering == c.used);
    CHECK(f.analysis().orderingChoice ==
          "auto, " + std::to_string(dim) + "D, " + std::to_string(n) + " unknowns");
  }

  // CHOLMOD's own strategy: its choice, and whether it tried METIS after AMD.
  SparseFactor f("cholmod");
  f.setOrdering(Ordering::cholmodDefault, 2);
  REQUIRE(f.factor(A) == FactorStatus::ok);
  CHECK_THAT(f.analysis().orderingChoice, Catch::StartsWith("cholmodDefault, AMD "));
  CHECK(f.analysis().orderedGroups == 0);  // CHOLMOD's strategy orders A's own graph
  CHECK((f.solve(b) - x0).norm() <= 1e-10 * x0.norm());

  // The other backends have their own ordering and report no choice.
  SparseFactor ldlt("simplicialLDLT");
  CHECK_FALSE(ldlt.takesOrdering());
  REQUIRE(ldlt.factor(A) == FactorStatus::ok);
  CHECK(ldlt.analysis().orderingChoice.empty());
}

TEST_CASE("linalg SparseFactor predicts cholmod's factor and factors in the predicted order",
          "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  Eigen::SparseMatrix<double> B, C;
  border(n, 40, B, C);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const Ordering ordering : {Ordering::amd, Ordering::metis, Ordering::automatic}) {
    CAPTURE(toString(ordering));
    SparseFactor plain("cholmod"), predicted("cholmod");
    plain.setOrdering(ordering, 2);
    predicted.setOrdering(ordering, 2);
    REQUIRE(plain.factor(A) == FactorStatus::ok);
    FactorAnalysis p;
    REQUIRE(predicted.predict(A, p));
    // The entries and flops are CHOLMOD's counts from the same ordering and column counts as
    // the factorisation's: equal, not near. The bytes assume the padding measured in 3D.
    CHECK(p.entries == plain.analysis().entries);
    CHECK(p.flops == plain.analysis().flops);
    CHECK(p.ordering == plain.analysis().ordering);
    CHECK(p.bytes == 8 * p.entries * SparseFactor::predictedPadding);
    CHECK(p.orderedGroups == distinctColumns(A));
    // The factorisation takes the kept ordering (said in the log) and makes the same factor:
    // the same solution bit for bit.
    REQUIRE(predicted.factor(A) == FactorStatus::ok);
    CHECK_THAT(predicted.analysis().orderingChoice,
               Catch::EndsWith(", ordered once for the prediction"));
    CHECK(predicted.analysis().entries == plain.analysis().entries);
    CHECK(predicted.solve(b) == plain.solve(b));
    // Kept once: the next factorisation orders again, as every factorisation did before.
    REQUIRE(predicted.factor(A) == FactorStatus::ok);
    CHECK_THAT(predicted.analysis().orderingChoice,
               !Catch::Contains("ordered once for the prediction"));
    // Bordered: the kept ordering of A, then the border last; S as without the prediction.
    SparseFactor borderedPlain("cholmod"), borderedPredicted("cholmod");
    borderedPlain.setOrdering(ordering, 2);
    borderedPredicted.setOrdering(ordering, 2);
    REQUIRE(borderedPlain.factorWithSchur(A, B, C) == FactorStatus::ok);
    REQUIRE(borderedPredicted.predict(A, p));
    REQUIRE(borderedPredicted.factorWithSchur(A, B, C) == FactorStatus::ok);
    CHECK_THAT(borderedPredicted.analysis().orderingChoice,
               Catch::EndsWith(", ordered once for the prediction"));
    CHECK(borderedPredicted.schurComplement() == borderedPlain.schurComplement());
  }
  // Another pattern than the predicted one is ordered anew (the kept ordering is not its).
  SparseFactor f("cholmod");
  f.setOrdering(Ordering::amd, 2);
  FactorAnalysis p;
  REQUIRE(f.predict(A, p));
  Eigen::SparseMatrix<double> other = A;
  other.coeffRef(n - 1, 0) = other.coeffRef(0, n - 1) = 1.0;  // a new entry, still SPD
  REQUIRE(f.factor(other) == FactorStatus::ok);
  CHECK_THAT(f.analysis().orderingChoice, !Catch::Contains("prediction"));
  // No prediction where the ordering is CHOLMOD's own (it orders inside its analysis) or the
  // backend is not cholmod.
  SparseFactor strategy("cholmod");
  strategy.setOrdering(Ordering::cholmodDefault, 2);
  CHECK_FALSE(strategy.predict(A, p));
  SparseFactor ldlt("simplicialLDLT");
  CHECK_FALSE(ldlt.predict(A, p));
}

TEST_CASE("linalg SparseFactor cholmod orders the graph of equal columns wherever they are",
          "[linalg]") {
  // The stiffness with its unknowns shuffled: a node's two components are no longer
  // neighbours in the numbering, and the matrix is left uncompressed. The groups are found
  // all the same, and the factor solves to round-off with and without a border.
  const Eigen::SparseMatrix<double> A0 = spdMatrix();
  const Eigen::Index n = A0.rows();
  REQUIRE(distinctColumns(A0) <= n / 2);
  Eigen::VectorXi order(n);
  for (Eigen::Index i = 0; i < n; ++i) order[i] = static_cast<int>((i * 7919) % n);
  REQUIRE(std::set<int>(order.data(), order.data() + n).size() == static_cast<std::size_t>(n));
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(order);
  Eigen::SparseMatrix<double> A = P * A0 * P.transpose();
  A.uncompress();
  REQUIRE_FALSE(A.isCompressed());
  Eigen::SparseMatrix<double> B, C;
  border(n, 40, B, C);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  for (const Ordering o : {Ordering::amd, Ordering::metis}) {
    CAPTURE(toString(o));
    SparseFactor f("cholmod");
    f.setOrdering(o, 2);
    REQUIRE(f.factor(A) == FactorStatus::ok);
    CHECK(f.analysis().orderedGroups == distinctColumns(A0));
    const Eigen::VectorXd x = f.solve(b);
    CHECK((A * x - b).norm() <= 1e-10 * b.norm());
    REQUIRE(f.factorWithSchur(A, B, C) == FactorStatus::ok);
    CHECK(f.analysis().orderedGroups == distinctColumns(A0));
    CHECK((A * f.solve(b) - b).norm() <= 1e-10 * b.norm());
  }
  // No two columns alike (a diagonal): as many groups as columns, still exact.
  Eigen::SparseMatrix<double> D(n, n);
  for (Eigen::Index i = 0; i < n; ++i) D.insert(i, i) = 1.0 + static_cast<double>(i);
  D.makeCompressed();
  SparseFactor f("cholmod");
  f.setOrdering(Ordering::amd, 2);
  REQUIRE(f.factor(D) == FactorStatus::ok);
  CHECK(f.analysis().orderedGroups == n);
  CHECK((D * f.solve(b) - b).norm() <= 1e-14 * b.norm());
}

TEST_CASE("linalg SparseFactor cholmod solves on the reach of a set of rows, to the bit",
          "[linalg]") {
  const Eigen::SparseMatrix<double> A = spdMatrix();
  const Eigen::Index n = A.rows();
  REQUIRE(n > 500);
  // Every 7th row: right-hand sides vanish elsewhere; the solution is read on these rows.
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 3; i < n; i += 7) rows.push_back(i);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, 5);
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (Eigen::Index c = 0; c < 5; ++c)
      B(rows[a], c) = std::sin(0.37 * static_cast<double>(a) + 1.3 * static_cast<double>(c)) + 0.1;
  for (const Ordering ordering : {Ordering::metis, Ordering::amd}) {
    CAPTURE(toString(ordering));
    SparseFactor f("cholmod");
    f.setOrdering(ordering, 2);
    REQUIRE(f.factor(A) == FactorStatus::ok);
    const Eigen::MatrixXd whole = f.solve(B);
    const Eigen::VectorXd wholeOne = f.solve(Eigen::VectorXd(B.col(0)));
    const SolveReach reach = f.restrictSolves(rows);
    const double share = reach.share;
    CHECK(reach.supernodes > 0);
    CHECK(reach.supernodes <= reach.ofSupernodes);
    CHECK(share > 0);
    CHECK(share <= 1);
    const long solves = f.numSolves();
    const Eigen::MatrixXd part = f.solveRestricted(B);
    const Eigen::VectorXd partOne = f.solveRestricted(Eigen::VectorXd(B.col(0)));
    CHECK(f.numSolves() == solves + 6);
    // The same BLAS calls per supernode as CHOLMOD's whole solve: equal on the rows, bit for
    // bit, for one right-hand side (dtrsv, dgemv) and for a block (dtrsm, dgemm).
    for (const Eigen::Index r : rows) {
      for (Eigen::Index c = 0; c < 5; ++c) REQUIRE(part(r, c) == whole(r, c));
      REQUIRE(partOne[r] == wholeOne[r]);
    }
    CHECK(whole.norm() > 0);

    // One row reaches only its supernode's ancestors: less than the whole factor, and a
    // right-hand side outside that reach is refused, not answered wrongly.
    const Eigen::Index middle = rows[rows.size() / 2];
    const double one = f.restrictSolves({middle}).share;
    CHECK(one > 0);
    CHECK(one < share);
    int refused = 0, answered = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e[j] = 1;
      try {
        const Eigen::VectorXd x = f.solveRestricted(e);
        ++answered;
        REQUIRE(x[middle] == f.solve(e)[middle]);
      } catch (const std::logic_error&) {
        ++refused;
      }
    }
    CHECK(refused > 0);
    CHECK(answered > 0);

    // A new factorisation ends the restriction: solves are whole again.
    REQUIRE(f.factor(A) == FactorStatus::ok);
    const Eigen::VectorXd full = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    CHECK(f.solveRestricted(full) == f.solve(full));
  }

  // Where the factor cannot solve on a reach, the solves are whole and say so.
  SparseFactor ldlt("simplicialLDLT");
  REQUIRE(ldlt.factor(A) == FactorStatus::ok);
  CHECK(ldlt.restrictSolves(rows).share < 0);
  CHECK(ldlt.solveRestricted(B) == ldlt.solve(B));
  Eigen::SparseMatrix<double> Bb, C;
  border(n, 40, Bb, C);
  SparseFactor bordered("cholmod");
  REQUIRE(bordered.factorWithSchur(A, Bb, C) == FactorStatus::ok);
  REQUIRE(bordered.schurSolves() == 0);
  CHECK(bordered.restrictSolves(rows).share < 0);
  CHECK(bordered.solveRestricted(B) == bordered.solve(B));
}
