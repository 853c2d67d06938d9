// A fracture node on a Dirichlet patch has its jump held at zero and is reported
// (docs/method.md).
#include <catch2/catch.hpp>

#include "TestMeshes.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::test;

TEST_CASE("fracture ends on a Dirichlet patch hold their jump at zero", "[fracture][fe]") {
  const int n = 8;
  Mesh m = gridMesh(n);
  addHorizontalFracture(m, n, n / 2, 0, n, 5, "fracture");
  const SplitMesh split = splitFractures(m, {{"fracture", 5, {}}});
  const Material material = Material::fromLame(1.0, 1.0);
  for (int degree : {1, 2}) {
    FractureSystem sys(split, degree, material);
    sys.dirichlet().fixPatch(1, FixedComponents::all);
    sys.dirichlet().fixPatch(4, FixedComponents::x);  // roller on the left: holds one end
    REQUIRE(sys.factor("simplicialLDLT") == FactorStatus::ok);
    CHECK(sys.numHeldOnDirichlet() == 1);
    const auto& nodes = sys.controlNodes();
    CHECK(nodes.front().onDirichlet);
    CHECK(sys.freeMask()[0] == 0.0);
    CHECK_FALSE(nodes.back().onDirichlet);
    CHECK(sys.freeMask()[sys.size() - 1] == 1.0);
    // A slip imposed everywhere moves both copies of the held node alike.
    sys.dirichlet().setPatchValue(1, Vector2(0, 0));
    sys.dirichlet().setPatchValue(4, Vector2(0, 0));
    sys.setStep(Eigen::VectorXd::Zero(sys.splitSpace().numDofs()),
                Eigen::VectorXd::Zero(sys.size()));
    Eigen::VectorXd tau, sigmaN;
    sys.primal(Eigen::VectorXd::Constant(sys.size(), 1e-3), tau, sigmaN);
    const Eigen::VectorXd u = sys.lastSplitDisplacement();
    for (int c = 0; c < 2; ++c)
      CHECK(u[2 * nodes.front().plus + c] == u[2 * nodes.front().minus + c]);
    CHECK(u[2 * nodes.back().plus] - u[2 * nodes.back().minus] == Approx(1e-3));
  }
}
