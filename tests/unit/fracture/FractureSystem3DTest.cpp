// The finite-element SlipResponse on a 3D split mesh (docs/method.md §7): box meshes of Kuhn
// tetrahedra with a plane fault, bottom clamped. Checks what is known exactly: zero data give
// zero tractions; a zero jump gives the unsplit solve; M·S is symmetric; the factorisation's
// interface operator equals the dual solves'; a uniform jump on a fault that cuts the box moves
// the upper block rigidly; and the tangent basis is a choice the tractions do not depend on.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "TestBoxMeshes.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;
using namespace friction::test;
using Eigen::VectorXd;

namespace {

// across: the whole plane z = 1/2 (reaches all four side faces, no tip line); twoFaces: reaches
// x = 0 and x = 1 only; inside: a tip line all round.
enum class Fault { across, twoFaces, inside };

// A rotation with no axis-aligned image of the z axis, so that n_Γ is generic.
Eigen::Matrix3d tilt() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// The unit box of n³ Kuhn cubes (possibly rotated), fault on z = 1/2, clamped bottom (patch 5);
// the top (patch 6) moved by `top` when topFixed, else free. λ = μ = 1.
struct Box {
  Mesh mesh;
  SplitMesh split;
  Material material = Material::fromLame(1.0, 1.0);
  std::unique_ptr<FractureSystem> sys;

  Box(int n, int degree, Fault fault, const Point& top, bool topFixed = true,
      const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(), bool schur = false) {
    mesh = boxMesh(n);
    const int lo = fault == Fault::inside ? 1 : 0, hi = fault == Fault::inside ? n - 1 : n;
    const int b0 = fault == Fault::across ? 0 : 1, b1 = fault == Fault::across ? n : n - 1;
    addPlaneFault(mesh, n, 2, n / 2, lo, hi, b0, b1, 7, "fault");
    for (Point& p : mesh.points) p = rotation * p;
    split = splitFractures(mesh, {{"fault", 7, {}}});
    sys = std::make_unique<FractureSystem>(split, degree, material);
    sys->dirichlet().fixPatch(5, FixedComponents::all);
    if (topFixed) sys->dirichlet().fixPatch(6, FixedComponents::all);
    REQUIRE(sys->factor("cholmod", schur) == FactorStatus::ok);
    sys->dirichlet().setPatchValue(5, Point(0, 0, 0));
    if (topFixed) sys->dirichlet().setPatchValue(6, top);
    sys->setStep(VectorXd::Zero(sys->splitSpace().numDofs()), VectorXd::Zero(2 * sys->size()));
  }
};

// Tangential components of the d-vectors J (3 per node) on the nodes' bases, and normal ones.
void components(const FractureSystem& sys, const VectorXd& J, VectorXd& qt, VectorXd& qn) {
  const Eigen::Index n = sys.size();
  qt.resize(2 * n);
  qn.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const ControlNode& v = sys.controlNodes()[i];
    const Point j = J.segment<3>(3 * i);
    qt[2 * i] = j.dot(v.tangent[0]);
    qt[2 * i + 1] = j.dot(v.tangent[1]);
    qn[i] = j.dot(v.normal);
  }
}

// Σ as d-vectors from its components: τ₁ t₁ + τ₂ t₂ + σ_n n_Γ per node.
VectorXd assemble(const FractureSystem& sys, const VectorXd& tau, const VectorXd& sigmaN) {
  const Eigen::Index n = sys.size();
  VectorXd s(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const ControlNode& v = sys.controlNodes()[i];
    s.segment<3>(3 * i) =
        tau[2 * i] * v.tangent[0] + tau[2 * i + 1] * v.tangent[1] + sigmaN[i] * v.normal;
  }
  return s;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

}  // namespace

TEST_CASE("3D FractureSystem: control nodes, frames and Γ weights", "[fracture][fe][3d]") {
  for (int degree : {1, 2})
    for (Fault f : {Fault::twoFaces, Fault::inside}) {
      Box b(4, degree, f, Point::Zero(), true, tilt());
      const FractureGeometry& g = b.split.fractures[0];
      const auto& nodes = b.sys->controlNodes();
      REQUIRE(b.sys->dimension() == 3);
      REQUIRE(b.sys->blockSize() == 2);
      // P2 adds one node per edge of the surface: E = V + F − 1 (a disc, Euler).
      const Eigen::Index edges = g.numNodes() + static_cast<Eigen::Index>(g.triangles.size()) - 1;
      CHECK(b.sys->size() == g.numNodes() + (degree == 2 ? edges : 0));
      int tips = 0, split = 0;
      for (const ControlNode& v : nodes) {
        tips += v.tip;
        split += !v.tip;
        CHECK(v.tip == (v.plus == v.minus));
        // (t₁, t₂, n_Γ): orthonormal and right-handed; a flat fault has one normal.
        CHECK((v.normal - g.normal[0]).norm() < 1e-14);
        CHECK(std::abs(v.tangent[0].dot(v.normal)) < 1e-14);
        CHECK((v.tangent[0].cross(v.tangent[1]) - v.normal).norm() < 1e-14);
        // Midpoints sit halfway between two fault nodes: on the plane of the fault.
        CHECK(std::abs((v.position - b.mesh.points[g.node[0]]).dot(v.normal)) < 1e-14);
      }
      CHECK(tips > 0);
      CHECK(split > 0);
      // Each triangle's lumped weights sum to its area (P1: A/3 ×3; P2: A/12 ×3 + A/4 ×3).
      CHECK(b.sys->weights().sum() == Approx(g.area(b.mesh.points)).epsilon(1e-13));
      CHECK(b.sys->weights().minCoeff() > 0);
    }
}

TEST_CASE("3D FractureSystem: zero data give exactly zero tractions", "[fracture][fe][3d]") {
  for (int degree : {1, 2}) {
    Box b(4, degree, Fault::twoFaces, Point::Zero(), true, tilt());
    VectorXd tau, sigmaN;
    b.sys->primal(VectorXd::Zero(2 * b.sys->size()), tau, sigmaN);
    REQUIRE(tau.size() == 2 * b.sys->size());
    CHECK(tau.cwiseAbs().maxCoeff() == 0.0);
    CHECK(sigmaN.cwiseAbs().maxCoeff() == 0.0);
  }
}

TEST_CASE("3D FractureSystem: with β = 0 the split solve is the unsplit linear solve",
          "[fracture][fe][3d]") {
  const Point top(0.01, -0.02, -0.03);
  for (int degree : {1, 2})
    for (Fault f : {Fault::twoFaces, Fault::inside}) {
      Box b(4, degree, f, top);
      VectorXd tau, sigmaN;
      b.sys->primal(VectorXd::Zero(2 * b.sys->size()), tau, sigmaN);
      const VectorXd us = b.sys->lastSplitDisplacement();

      // The same body without the fault, solved on its own.
      LagrangeSpace space(b.mesh, degree);
      ElasticityAssembler assembler(space, b.material);
      DirichletConditions dc(space);
      dc.fixPatch(5, FixedComponents::all);
      dc.fixPatch(6, FixedComponents::all);
      dc.setPatchValue(5, Point(0, 0, 0));
      dc.setPatchValue(6, top);
      ReducedSystem rs(assembler.stiffness(), dc);
      SparseFactor factor("cholmod");
      REQUIRE(factor.factor(rs.matrix()) == FactorStatus::ok);
      const VectorXd u = rs.expand(factor.solve(rs.rhs(VectorXd::Zero(space.numDofs()), dc)), dc);

      // Node by node through the cells (the split keeps the cells and their local order).
      const double scale = u.cwiseAbs().maxCoeff();
      REQUIRE(scale > 0);
      double worst = 0;
      for (Index c = 0; c < space.numCells(); ++c) {
        const NodeList s = b.sys->splitSpace().cellNodes(c), o = space.cellNodes(c);
        for (int k = 0; k < o.size; ++k)
          for (int a = 0; a < 3; ++a)
            worst = std::max(worst, std::abs(us[3 * s[k] + a] - u[3 * o[k] + a]));
      }
      // Two factorisations of the same matrix: round-off only.
      CHECK(worst <= 1e-12 * scale);
      // Top pushed down: a net compressive normal force on the fault (node by node the
      // sign may vary near the tip line and between P2 vertices and midpoints).
      double force = 0;
      for (Eigen::Index i = 0; i < b.sys->size(); ++i) force += b.sys->weights()[i] * sigmaN[i];
      CHECK(force < 0);
    }
}

TEST_CASE("3D FractureSystem: M·S is symmetric, normal jumps included", "[fracture][fe][3d]") {
  for (int degree : {1, 2})
    for (Fault f : {Fault::across, Fault::twoFaces, Fault::inside}) {
      Box b(4, degree, f, Point::Zero(), true, tilt());
      const Eigen::Index n = b.sys->size();
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> u(-1, 1);
      auto random = [&](Eigen::Index m) {
        return VectorXd(VectorXd::NullaryExpr(m, [&] { return u(rng); }));
      };
      const VectorXd at = random(2 * n), an = random(n), ct = random(2 * n), cn = random(n);
      VectorXd tA, nA, tC, nC;
      b.sys->dual(at, an, tA, &nA);
      b.sys->dual(ct, cn, tC, &nC);
      const VectorXd& w = b.sys->weights();
      const VectorXd& mask = b.sys->freeMask();
      REQUIRE(mask.sum() > 0);
      double lhs = 0, rhs = 0, size = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double l =
            w[i] * mask[i] * (tA.segment<2>(2 * i).dot(ct.segment<2>(2 * i)) + nA[i] * cn[i]);
        const double r =
            w[i] * mask[i] * (tC.segment<2>(2 * i).dot(at.segment<2>(2 * i)) + nC[i] * an[i]);
        lhs += l;
        rhs += r;
        size += std::abs(l) + std::abs(r);
      }
      CHECK(std::abs(lhs - rhs) <= 1e-10 * size);
    }
}

TEST_CASE("3D FractureSystem: the factorisation's interface operator equals the dual solves'",
          "[fracture][fe][3d]") {
  for (int degree : {1, 2})
    for (Fault f : {Fault::twoFaces, Fault::inside}) {
      Box b(4, degree, f, Point::Zero(), true, tilt(), true);
      REQUIRE(b.sys->jumpOperator().rows() == static_cast<Eigen::Index>(b.sys->jumpDofs().size()));
      REQUIRE(!b.sys->jumpDofs().empty());
      const InterfaceOperator fromFactor = b.sys->interfaceOperator(InterfaceMethod::factorisation);
      const InterfaceOperator blocks = b.sys->interfaceOperator(InterfaceMethod::blockSolves);
      const InterfaceOperator reference = b.sys->interfaceOperator(InterfaceMethod::dualSolves);
      REQUIRE(reference.Stt.cwiseAbs().maxCoeff() > 0);
      REQUIRE(reference.Snt.cwiseAbs().maxCoeff() > 0);
      CHECK(relativeDifference(fromFactor.Stt, reference.Stt) <= 1e-9);
      CHECK(relativeDifference(fromFactor.Snt, reference.Snt) <= 1e-9);
      CHECK(relativeDifference(blocks.Stt, reference.Stt) <= 1e-9);
      CHECK(relativeDifference(blocks.Snt, reference.Snt) <= 1e-9);
    }
}

TEST_CASE(
    "3D FractureSystem: a uniform jump on a fault across the box moves the upper block "
    "rigidly",
    "[fracture][fe][3d]") {
  // Lower block clamped, top free, no load: u = 0 below and u = j above the fault is an exact
  // discrete solution (piecewise constant, in the space) with zero stress, so every node
  // carries it and every traction is zero, up to round-off.
  const Point j(0.01, -0.02, 0);
  for (int degree : {1, 2}) {
    Box b(4, degree, Fault::across, Point::Zero(), false);
    const Eigen::Index n = b.sys->size();
    REQUIRE(b.sys->freeMask().sum() == n);  // no tips, none held: the jump is j everywhere
    VectorXd beta(2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const ControlNode& v = b.sys->controlNodes()[i];
      REQUIRE((v.normal - Point(0, 0, -1)).norm() == 0.0);  // Ω⁺ above
      beta[2 * i] = j.dot(v.tangent[0]);
      beta[2 * i + 1] = j.dot(v.tangent[1]);
    }
    VectorXd tau, sigmaN;
    b.sys->primal(beta, tau, sigmaN);
    const VectorXd u = b.sys->lastSplitDisplacement();
    const LagrangeSpace& space = b.sys->splitSpace();
    double worst = 0;
    for (Index c = 0; c < space.numCells(); ++c) {
      const NodeList s = space.cellNodes(c);
      Point centre = Point::Zero();
      for (int k = 0; k < s.size; ++k) centre += space.point(s[k]) / s.size;
      const Point expected = centre.z() > 0.5 ? j : Point::Zero();
      for (int k = 0; k < s.size; ++k)
        worst = std::max(worst, (u.segment<3>(3 * s[k]) - expected).cwiseAbs().maxCoeff());
    }
    CHECK(worst <= 1e-12 * j.norm());
    // Traction scale of this jump: μ |j| / h = 1 · 0.022 · 4.
    const double scale = j.norm() * 4;
    CHECK(tau.cwiseAbs().maxCoeff() <= 1e-10 * scale);
    CHECK(sigmaN.cwiseAbs().maxCoeff() <= 1e-10 * scale);
  }
}

TEST_CASE("3D FractureSystem: another tangent basis gives the same traction vector",
          "[fracture][fe][3d]") {
  for (int degree : {1, 2}) {
    Box b(4, degree, Fault::twoFaces, Point(0.01, -0.02, -0.03), true, tilt());
    REQUIRE(b.sys->freeMask().sum() > 0);
    const Eigen::Index n = b.sys->size();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const VectorXd J = VectorXd::NullaryExpr(3 * n, [&] { return u(rng); });
    VectorXd qt, qn, tau, sigmaN;
    // Dual: a full d-vector jump. Primal: its tangential part as β, with the load.
    components(*b.sys, J, qt, qn);
    b.sys->dual(qt, qn, tau, &sigmaN);
    const VectorXd dualBefore = assemble(*b.sys, tau, sigmaN);
    const VectorXd beta = 0.01 * qt;
    VectorXd tangentialJump(3 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const ControlNode& v = b.sys->controlNodes()[i];
      tangentialJump.segment<3>(3 * i) =
          beta[2 * i] * v.tangent[0] + beta[2 * i + 1] * v.tangent[1];
    }
    b.sys->primal(beta, tau, sigmaN);
    const VectorXd primalBefore = assemble(*b.sys, tau, sigmaN);

    for (Eigen::Index i = 0; i < n; ++i) {
      const ControlNode& v = b.sys->controlNodes()[i];
      const double angle = 0.3 + 0.9 * i;
      b.sys->setTangentBasis(i, std::cos(angle) * v.tangent[0] + std::sin(angle) * v.tangent[1]);
    }
    components(*b.sys, J, qt, qn);
    b.sys->dual(qt, qn, tau, &sigmaN);
    const VectorXd dualAfter = assemble(*b.sys, tau, sigmaN);
    VectorXd betaAfter, unused;
    components(*b.sys, tangentialJump, betaAfter, unused);
    b.sys->primal(betaAfter, tau, sigmaN);
    const VectorXd primalAfter = assemble(*b.sys, tau, sigmaN);
    // The components changed (the check below compares vectors, not numbers that stayed put).
    REQUIRE((betaAfter - beta).cwiseAbs().maxCoeff() > 1e-3 * beta.cwiseAbs().maxCoeff());
    // Same jump up to round-off of the frame products: same Σ.
    CHECK(relativeDifference(dualAfter, dualBefore) <= 1e-12);
    CHECK(relativeDifference(primalAfter, primalBefore) <= 1e-12);
  }
}
