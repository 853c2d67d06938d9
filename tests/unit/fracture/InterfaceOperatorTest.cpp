// The interface operator S (docs/method.md §4): formed from the one factorisation (the
// Schur complement of the stiffness in the variables (free dofs, jumps)), from blocks of
// solves, and column by column from dual solves — the three agree to round-off, for P1 and
// P2, fractures with tips, ends held on a Dirichlet patch, and a part held by the fracture
// alone; and the solves after the bordered factorisation are those of the plain one.
#include <catch2/catch.hpp>

#include "TestMeshes.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::test;

namespace {

struct Scene {
  const char* name;
  int i0, i1;                        // the fracture along the middle row, columns i0..i1
  std::vector<int> clamped, roller;  // patches fixed in x and y / in x only
};

std::unique_ptr<FractureSystem> make(const SplitMesh& split, const Material& material, int degree,
                                     const Scene& scene, const std::string& backend, bool bordered,
                                     FactorStatus& status) {
  auto sys = std::make_unique<FractureSystem>(split, degree, material);
  for (int p : scene.clamped) sys->dirichlet().fixPatch(p, FixedComponents::all);
  for (int p : scene.roller) sys->dirichlet().fixPatch(p, FixedComponents::x);
  status = sys->factor(backend, bordered);
  return sys;
}

}  // namespace

TEST_CASE("the interface operator from the factorisation equals the one from dual solves",
          "[fracture][fe]") {
  const int n = 8;
  const Scene scenes[] = {
      // Interior crack: single nodes at both tips.
      {"interior", 2, 6, {1, 3}, {}},
      // Across the body, one end on a roller patch: that node's jump is held.
      {"held end", 0, n, {1}, {4}},
      // Across the body, only the bottom clamped: the top part is held by the fracture
      // alone, so S is only semi-definite (a rigid motion of the top is a jump).
      {"held by the fracture", 0, n, {1}, {}},
  };
  const Material material = Material::fromYoungPoisson(1e10, 0.3);
  for (const Scene& scene : scenes)
    for (int degree : {1, 2})
      for (const std::string backend : {"cholmod", "simplicialLDLT"}) {
        CAPTURE(scene.name, degree, backend);
        Mesh m = gridMesh(n);
        addHorizontalFracture(m, n, n / 2, scene.i0, scene.i1, 5, "fracture");
        const SplitMesh split = splitFractures(m, {{"fracture", 5, {}}});
        FactorStatus plainStatus, borderedStatus;
        auto plain = make(split, material, degree, scene, backend, false, plainStatus);
        auto bordered = make(split, material, degree, scene, backend, true, borderedStatus);
        REQUIRE(plainStatus == FactorStatus::ok);
        REQUIRE(borderedStatus == FactorStatus::ok);
        const Eigen::Index nodes = plain->size();
        REQUIRE(nodes > 2);
        REQUIRE(plain->factorization().schurComplement().size() == 0);
        REQUIRE(bordered->jumpOperator().rows() ==
                static_cast<Eigen::Index>(bordered->jumpDofs().size()));

        const InterfaceOperator reference = plain->interfaceOperator(InterfaceMethod::dualSolves);
        CHECK(reference.method == InterfaceMethod::dualSolves);
        CHECK(reference.solves == plain->freeMask().sum());
        const InterfaceOperator fromFactor =
            bordered->interfaceOperator(InterfaceMethod::factorisation);
        const InterfaceOperator byBlocks = plain->interfaceOperator(InterfaceMethod::blockSolves);
        CHECK(byBlocks.method == InterfaceMethod::blockSolves);
        CHECK(byBlocks.solves == static_cast<long>(plain->jumpDofs().size()));
        if (backend == "cholmod") {
          CHECK(fromFactor.method == InterfaceMethod::factorisation);
          CHECK(fromFactor.solves == 0);
          CHECK(bordered->factorization().numSolves() == 0);
        } else {
          // The fallback: blocks of solves during the factorisation, and said so.
          CHECK(fromFactor.method == InterfaceMethod::blockSolves);
          CHECK(bordered->factorization().schurSolves() ==
                static_cast<long>(bordered->jumpDofs().size()));
        }

        // Round-off of solves with cond(K) ≲ 1e5 (h = 1/8, P2) on entries of size E/h:
        // 1e-9 relative to the largest entry.
        const double scale = reference.Stt.cwiseAbs().maxCoeff();
        REQUIRE(scale > 0);
        for (const InterfaceOperator* op : {&fromFactor, &byBlocks}) {
          CHECK((op->Stt - reference.Stt).cwiseAbs().maxCoeff() <= 1e-9 * scale);
          CHECK((op->Snt - reference.Snt).cwiseAbs().maxCoeff() <= 1e-9 * scale);
        }
        // Held nodes have zero columns; free nodes a positive diagonal (M·S is a Schur
        // complement of the stiffness, so positive semi-definite, and no free node's slip
        // is free of strain energy).
        for (Eigen::Index k = 0; k < nodes; ++k) {
          if (plain->freeMask()[k] == 0)
            CHECK(fromFactor.Stt.col(k).cwiseAbs().maxCoeff() == 0.0);
          else
            CHECK(fromFactor.Stt(k, k) > 0);
        }

        // The bordered factor solves with K: a primal solve gives the plain one's result.
        const Eigen::VectorXd load =
            Eigen::VectorXd::LinSpaced(plain->splitSpace().numDofs(), -1e6, 2e6);
        const Eigen::VectorXd slip = Eigen::VectorXd::LinSpaced(nodes, 1e-4, -2e-4);
        Eigen::VectorXd tauA, snA, tauB, snB;
        for (FractureSystem* sys : {plain.get(), bordered.get()}) sys->setStep(load, slip);
        plain->primal(Eigen::VectorXd::Constant(nodes, 1e-5), tauA, snA);
        bordered->primal(Eigen::VectorXd::Constant(nodes, 1e-5), tauB, snB);
        const double tscale = std::max(tauA.cwiseAbs().maxCoeff(), snA.cwiseAbs().maxCoeff());
        REQUIRE(tscale > 0);
        for (Eigen::Index k = 0; k < nodes; ++k) {
          if (plain->controlNodes()[k].tip) continue;
          CHECK(std::abs(tauA[k] - tauB[k]) <= 1e-9 * tscale);
          CHECK(std::abs(snA[k] - snB[k]) <= 1e-9 * tscale);
        }
        CHECK(bordered->equilibriumResidual() <= 1e-12);
      }
}
