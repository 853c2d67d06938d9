// The 3D solver where fault surfaces meet (README "Intersections (3D)"): the exact
// reduction of issue #31 — a fault abutting the main one, bonded (a law that sticks), gives the
// main fault's answer alone to round-off, P1 and P2; with zero jump on the abutting fault,
// the lifting and the recovery are those of the main fault alone for any jump of it. What is
// refused where faults meet says which configuration and why.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "TestBoxMeshes.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::test;
using Catch::Matchers::Contains;
using Eigen::VectorXd;

namespace {

constexpr int n = 6;

// The unit box of 6³ Kuhn cubes, clamped bottom, lid moved by (0.03, −0.02, −0.01); the main
// fault 'a' on z = 1/2 across in x, y in [1/6, 5/6] (tip lines at y = 1/6, 5/6); with
// `abutting`, 'b' on x = 1/2 above it (y in [1/6, 5/6], z in [1/2, 5/6]), ending on 'a'.
// λ = μ = 1.
struct Faults {
  Mesh mesh;
  SplitMesh split;
  std::unique_ptr<FractureSystem> sys;
  Faults(bool abutting, int degree = 1) {
    mesh = boxMesh(n);
    addPlaneFault(mesh, n, 2, 3, 0, n, 1, 5, 7, "a");
    std::vector<FractureSpec> specs{{"a", 7, {}}};
    if (abutting) {
      addPlaneFault(mesh, n, 0, 3, 1, 5, 3, 5, 8, "b");
      specs.push_back({"b", 8, {}});
    }
    split = splitFractures(mesh, specs);
    sys = std::make_unique<FractureSystem>(split, degree, Material::fromLame(1.0, 1.0));
    sys->dirichlet().fixPatch(5, FixedComponents::all);
    sys->dirichlet().fixPatch(6, FixedComponents::all);
    REQUIRE(sys->factor("cholmod") == FactorStatus::ok);
    sys->dirichlet().setPatchValue(5, Point(0, 0, 0));
    sys->dirichlet().setPatchValue(6, Point(0.03, -0.02, -0.01));
    sys->setStep(VectorXd::Zero(sys->splitSpace().numDofs()), VectorXd::Zero(2 * sys->size()));
  }
  // The number of control nodes of 'a' (listed first: its vertices, in P2 then its mid-edge
  // nodes).
  Eigen::Index mainNodes() const {
    Eigen::Index count = 0;
    for (const ControlNode& v : sys->controlNodes()) count += v.fracture == 0;
    return count;
  }
};

double relativeDifference(const VectorXd& a, const VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

}  // namespace

TEST_CASE(
    "3D intersections: with no jump on an abutting fault, the main fault's response is "
    "its response alone",
    "[fracture][fe][3d][intersection]") {
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  Faults alone(false, degree), both(true, degree);
  const Eigen::Index na = alone.mainNodes();
  REQUIRE(both.mainNodes() == na);
  REQUIRE(both.sys->size() > na);
  // b's nodes on the intersection are held (abutting; its two ends there are tips), in P2
  // also the mid-edge nodes of its 4 edges there.
  int held = 0;
  for (const ControlNode& v : both.sys->controlNodes()) held += v.junction;
  CHECK(held == (degree == 1 ? 3 : 3 + 4));
  // A jump on a (random, tangential) and none on b.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  VectorXd betaA(2 * na);
  for (Eigen::Index i = 0; i < betaA.size(); ++i) betaA[i] = u(rng);
  VectorXd betaB = VectorXd::Zero(2 * both.sys->size());
  betaB.head(2 * na) = betaA;
  VectorXd tauA, sigmaA, tauB, sigmaB;
  alone.sys->primal(betaA, tauA, sigmaA);
  both.sys->primal(betaB, tauB, sigmaB);
  // The main fault's nodes: same frames, same weights, same tractions (to round-off: the same
  // operations in another order).
  for (Eigen::Index i = 0; i < na; ++i) {
    CHECK(both.sys->controlNodes()[i].normal == alone.sys->controlNodes()[i].normal);
    CHECK(both.sys->weights()[i] == Approx(alone.sys->weights()[i]).epsilon(1e-14));
  }
  CHECK(relativeDifference(tauA, tauB.head(2 * na)) < 1e-10);
  CHECK(relativeDifference(sigmaA, sigmaB.head(na)) < 1e-10);
}

TEST_CASE("3D intersections: a bonded abutting fault gives the main fault's answer alone",
          "[fracture][fe][3d][intersection]") {
  // Coulomb, μ = 0.3 on a; on b μ and a cohesion so large that it sticks everywhere.
  const int degree = GENERATE(1, 2);
  INFO("P" << degree);
  std::vector<VectorXd> betas, taus;
  for (bool abutting : {false, true}) {
    Faults f(abutting, degree);
    const Eigen::Index size = f.sys->size(), na = f.mainNodes();
    VectorXd mu = VectorXd::Constant(size, 0.3), cohesion = VectorXd::Zero(size);
    mu.tail(size - na).setConstant(1e6);
    cohesion.tail(size - na).setConstant(1e6);
    ControlProblem p(*f.sys, mu, cohesion, 4.0, 0.0, GradientKind::exact);
    auto opt = Optimizer::New(Dictionary::parse(
        "type semismoothNewton; variant condensed; tolerance 1e-12; maxIterations 50;", "test"));
    VectorXd beta = VectorXd::Zero(2 * size);
    REQUIRE(opt->minimize(p, beta).status == OptimizerStatus::converged);
    const ControlState s = p.evaluate(beta);
    int slipping = 0;
    for (Eigen::Index i = 0; i < size; ++i) {
      if (i < na)
        slipping += s.node[i].state == SlipState::slip;
      else
        CHECK(s.node[i].state != SlipState::slip);
    }
    REQUIRE(slipping > 0);  // the main fault slips: the comparison is not of zeros
    if (abutting) CHECK(beta.tail(2 * (size - na)).cwiseAbs().maxCoeff() == 0.0);
    betas.push_back(beta.head(2 * na));
    taus.push_back(s.tau.head(2 * na));
  }
  CHECK(relativeDifference(betas[0], betas[1]) < 1e-9);
  CHECK(relativeDifference(taus[0], taus[1]) < 1e-9);
}

TEST_CASE("3D intersections: what is refused where fault surfaces meet says which and why",
          "[fracture][fe][3d][intersection]") {
  SECTION("two fractures listing the same triangle") {
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 3, 0, n, 1, 5, 7, "a");
    addPlaneFault(m, n, 2, 3, 2, 4, 2, 4, 8, "b");  // a patch of a, labelled again
    CHECK_THROWS_WITH(splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}}),
                      Contains("fractures 'a' and 'b' share the triangle (") &&
                          Contains("a fracture patch must be listed once"));
  }
  SECTION("a split mesh whose sectors at an intersection node do not fit its faults") {
    // The crossing of a and b (four sectors per inner node of their curve); one tetrahedron
    // at the node x = y = z = 1/2 is given the copy of the sector across both faults, as a
    // hand-edited constant/splitMesh could: the jumps around the node no longer add up.
    Mesh m = boxMesh(n);
    addPlaneFault(m, n, 2, 3, 0, n, 1, 5, 7, "a");
    addPlaneFault(m, n, 0, 3, 1, 5, 0, n, 8, "b");
    SplitMesh s = splitFractures(m, {{"a", 7, {}}, {"b", 8, {}}});
    const Index v = boxNode(n, 3, 3, 3);
    // The copies of v by the quadrant (x > 1/2, z > 1/2) of the tetrahedra that use them.
    std::map<int, Index> copyIn;
    std::vector<std::pair<Index, int>> uses;  // (cell, its local vertex at v)
    for (Index c = 0; c < s.mesh.numCells(); ++c) {
      Point centre = Point::Zero();
      for (Index x : s.mesh.cell(c)) centre += s.mesh.points[x] / 4;
      for (int k = 0; k < 4; ++k)
        if (s.origin[s.mesh.cell(c)[k]] == v) {
          const int quadrant = (centre.x() > 0.5) + 2 * (centre.z() > 0.5);
          copyIn[quadrant] = s.mesh.cell(c)[k];
          if (quadrant == 0) uses.push_back({c, k});
        }
    }
    REQUIRE(copyIn.size() == 4);
    REQUIRE(!uses.empty());
    s.mesh.cell(uses.front().first)[uses.front().second] = copyIn[3];
    CHECK_THROWS_WITH(FractureSystem(s, 1, Material::fromLame(1.0, 1.0)),
                      Contains("the split mesh's intersection node (0.5 0.5 0.5) is not "
                               "consistent (its fractures' jumps do not add up to zero around "
                               "it); split the mesh again with splitFractureNodes"));
  }
}
