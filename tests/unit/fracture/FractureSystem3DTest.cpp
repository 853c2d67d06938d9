// The finite-element SlipResponse on a 3D split mesh (docs/method.md §7): box meshes of Kuhn
// tetrahedra with a plane fault, bottom clamped. Checks what is known exactly: zero data give
// zero tractions; a zero jump gives the unsplit solve; M·S is symmetric; the factorisation's
// interface operator equals the dual solves'; a uniform jump on a fault that cuts the box moves
// the upper block rigidly; and the tangent basis is a choice the tractions do not depend on.
// P2 (the consistent recovery of Γ, docs/method.md §4): a uniform stress gives its traction at
// every node, the adjoint is the adjoint, and the exact gradient and Newton's Jacobian match
// finite differences on the finite-element response.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <Eigen/Geometry>

#include "TestBoxMeshes.hpp"
#include "friction/control/ControlProblem.hpp"
#include "friction/control/Optimizer.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SignConventions.hpp"
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

TEST_CASE("3D FractureSystem: the node graph is the fault triangles' edges",
          "[fracture][fe][3d][krylov]") {
  // What the krylov variant's probing colours (KrylovPreconditioner.hpp): symmetric, no self
  // loops. P1: one link per edge of the surface, E = V + F − 1 (a disc). P2: a triangle's six
  // nodes linked pairwise, 15 pairs per triangle, of which a pair lies in two triangles only
  // when both nodes are on their shared edge (its ends and midpoint: 3 pairs per interior
  // edge; 3F = 2 E_interior + E_boundary).
  for (int degree : {1, 2}) {
    Box b(4, degree, Fault::inside, Point::Zero());
    const FractureGeometry& g = b.split.fractures[0];
    const auto graph = b.sys->nodeGraph();
    REQUIRE(static_cast<Eigen::Index>(graph.size()) == b.sys->size());
    std::set<std::pair<Eigen::Index, Eigen::Index>> links;
    for (Eigen::Index i = 0; i < b.sys->size(); ++i)
      for (const Eigen::Index j : graph[i]) {
        CHECK(j != i);
        CHECK(std::count(graph[j].begin(), graph[j].end(), i) == 1);
        links.insert({std::min(i, j), std::max(i, j)});
      }
    const Eigen::Index faces = static_cast<Eigen::Index>(g.triangles.size());
    const Eigen::Index edges = g.numNodes() + faces - 1;
    if (degree == 1) CHECK(static_cast<Eigen::Index>(links.size()) == edges);
    if (degree == 2) {
      const Eigen::Index boundaryEdges = 2 * edges - 3 * faces, inner = edges - boundaryEdges;
      CHECK(static_cast<Eigen::Index>(links.size()) == 15 * faces - 3 * inner);
    }
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
  // P1 recovers with the lumped M = weights(): the dual map itself is M-self-adjoint. P2
  // recovers with the consistent mass: the bordered matrix's Schur complement is symmetric, and
  // adjoint() is the M-adjoint of β ↦ (τ, σ_n), which the exact gradient uses.
  for (int degree : {1, 2})
    for (Fault f : {Fault::across, Fault::twoFaces, Fault::inside}) {
      CAPTURE(degree, static_cast<int>(f));
      Box b(4, degree, f, Point::Zero(), true, tilt(), true);
      const Eigen::Index n = b.sys->size();
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> u(-1, 1);
      auto random = [&](Eigen::Index m) {
        return VectorXd(VectorXd::NullaryExpr(m, [&] { return u(rng); }));
      };
      const VectorXd at = random(2 * n), an = random(n), ct = random(2 * n), cn = random(n);
      const VectorXd& w = b.sys->weights();
      const VectorXd& mask = b.sys->freeMask();
      REQUIRE(mask.sum() > 0);
      const Eigen::MatrixXd& MS = b.sys->jumpOperator();
      REQUIRE(MS.rows() > 0);
      CHECK((MS - MS.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * MS.cwiseAbs().maxCoeff());
      VectorXd tA, nA, tC, nC;
      if (degree == 1) {
        b.sys->dual(at, an, tA, &nA);
        b.sys->dual(ct, cn, tC, &nC);
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
      // ⟨(τ, σ_n)(a), (ct, cn)⟩_M = ⟨a, adjoint(ct, cn)⟩_M for tangential jumps a.
      b.sys->dual(at, VectorXd::Zero(n), tA, &nA);
      VectorXd adj;
      b.sys->adjoint(ct, cn, adj);
      REQUIRE(adj.size() == 2 * n);
      double lhs = 0, rhs = 0, size = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double l = w[i] * (tA.segment<2>(2 * i).dot(ct.segment<2>(2 * i)) + nA[i] * cn[i]);
        const double r = w[i] * adj.segment<2>(2 * i).dot(at.segment<2>(2 * i));
        lhs += l;
        rhs += r;
        size += std::abs(l) + std::abs(r);
      }
      REQUIRE(size > 0);
      CHECK(std::abs(lhs - rhs) <= 1e-10 * size);
      // Held nodes get no gradient.
      for (Eigen::Index i = 0; i < n; ++i)
        if (mask[i] == 0) CHECK(adj.segment<2>(2 * i).norm() == 0.0);
    }
}

TEST_CASE("3D FractureSystem: a uniform stress gives its traction at every node but the tips",
          "[fracture][fe][3d]") {
  // u = G x on the whole boundary, no jump: the discrete solution is that linear field (in
  // the space for P1 and P2), the stress σ uniform, and the traction σ n_Γ at every node.
  // Lumped P2 weights gave 0 at the vertices and 4/3 σ n_Γ at the midpoints. P1's lumped
  // weights are the row sums of its mass: exact too, except at held nodes, whose recovered
  // value carries the reactions (P2 extends its value from the free nodes next to it).
  Eigen::Matrix3d G;
  G << 0.01, -0.02, 0.005, 0.015, -0.03, 0.01, -0.004, 0.02, -0.025;
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double lambda = 1.0, mu = 1.0;
  const Eigen::Matrix3d sigma = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  for (int degree : {1, 2})
    for (Fault f : {Fault::twoFaces, Fault::inside}) {
      CAPTURE(degree, static_cast<int>(f));
      Mesh mesh = boxMesh(4);
      const bool inside = f == Fault::inside;
      addPlaneFault(mesh, 4, 2, 2, inside ? 1 : 0, inside ? 3 : 4, 1, 3, 7, "fault");
      for (Point& p : mesh.points) p = tilt() * p;
      const SplitMesh split = splitFractures(mesh, {{"fault", 7, {}}});
      const Material material = Material::fromLame(lambda, mu);
      FractureSystem sys(split, degree, material);
      for (int patch = 1; patch <= 6; ++patch)
        sys.dirichlet().fixPatch(patch, FixedComponents::all);
      REQUIRE(sys.factor() == FactorStatus::ok);
      for (int patch = 1; patch <= 6; ++patch)
        sys.dirichlet().setPatchValue(patch, [&](const Point& x) { return Point(G * x); });
      sys.setStep(VectorXd::Zero(sys.splitSpace().numDofs()), VectorXd::Zero(2 * sys.size()));
      VectorXd tau, sigmaN;
      sys.primal(VectorXd::Zero(2 * sys.size()), tau, sigmaN);
      const double scale = sigma.norm();
      int checked = 0, midpoints = 0, held = 0;
      double worst = 0;
      for (Eigen::Index i = 0; i < sys.size(); ++i) {
        const ControlNode& v = sys.controlNodes()[i];
        if (v.tip || (degree == 1 && v.onDirichlet)) continue;
        const Point exact = sigma * v.normal;
        worst = std::max(worst, std::abs(sigmaN[i] - exact.dot(v.normal)));
        for (int c = 0; c < 2; ++c)
          worst = std::max(worst, std::abs(tau[2 * i + c] - exact.dot(v.tangent[c])));
        ++checked;
        midpoints += i >= split.fractures[0].numNodes();
        held += v.onDirichlet;
      }
      REQUIRE(checked > 0);
      if (degree == 2) REQUIRE(midpoints > 0);
      if (degree == 2 && !inside) REQUIRE(held > 0);
      CHECK(worst <= 1e-9 * scale);
      if (held == 0) continue;
      // Held nodes take part in the recovery (extended values): the interface operator and
      // the adjoint stay those of the map β ↦ (τ, σ_n).
      const InterfaceOperator blocks = sys.interfaceOperator(InterfaceMethod::blockSolves);
      const InterfaceOperator reference = sys.interfaceOperator(InterfaceMethod::dualSolves);
      CHECK(relativeDifference(blocks.Stt, reference.Stt) <= 1e-9);
      CHECK(relativeDifference(blocks.Snt, reference.Snt) <= 1e-9);
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> u(-1, 1);
      const Eigen::Index n = sys.size();
      const VectorXd a = VectorXd::NullaryExpr(2 * n, [&] { return u(rng); }),
                     ct = VectorXd::NullaryExpr(2 * n, [&] { return u(rng); }),
                     cn = VectorXd::NullaryExpr(n, [&] { return u(rng); });
      VectorXd t, sn, adj;
      sys.dual(a, VectorXd::Zero(n), t, &sn);
      sys.adjoint(ct, cn, adj);
      const VectorXd& w = sys.weights();
      double lhs = 0, rhs = 0, size = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        const double l = w[i] * (t.segment<2>(2 * i).dot(ct.segment<2>(2 * i)) + sn[i] * cn[i]);
        const double r = w[i] * adj.segment<2>(2 * i).dot(a.segment<2>(2 * i));
        lhs += l;
        rhs += r;
        size += std::abs(l) + std::abs(r);
      }
      REQUIRE(size > 0);
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

namespace {

// A β of at most the given scale where nodes slip and (with three free nodes or more) others
// stick, every free node away from a kink of D (|N| = ρ or ρ = 0): finite differences across a
// kink measure nothing.
VectorXd mixedBeta(ControlProblem& p, const FractureSystem& sys, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1), decades(-1.5, 0);
  const VectorXd& mask = sys.freeMask();
  for (int attempt = 0; attempt < 2000; ++attempt) {
    const double size = scale * std::pow(10.0, decades(rng));
    const VectorXd beta = VectorXd::NullaryExpr(p.size(), [&] { return size * u(rng); });
    const ControlState s = p.evaluate(beta);
    int stick = 0, slip = 0;
    double margin = 1e300, largest = 0;
    for (Eigen::Index i = 0; i < sys.size(); ++i) {
      if (mask[i] == 0) continue;
      const Eigen::Vector2d N = s.tau.segment<2>(2 * i) - p.gamma() * s.beta.segment<2>(2 * i);
      margin = std::min({margin, std::abs(N.norm() - s.rho[i]), std::abs(s.rho[i])});
      largest = std::max(largest, std::abs(s.rho[i]));
      stick += s.node[i].state == SlipState::stick;
      slip += s.node[i].state == SlipState::slip;
    }
    if (slip > 0 && (stick > 0 || stick + slip < 3) && margin > 0.02 * largest) return beta;
  }
  FAIL("no β away from kinks with both stick and slip nodes found");
  return {};
}

// Newton's Jacobian from the factorisation's interface operator, applied to d, against the
// central difference of D at β ± e·d (held components compared as zero).
void checkJacobian(FractureSystem& sys, const ControlProblem& p, const ControlState& s,
                   const VectorXd& d, const ControlState& plus, const ControlState& minus,
                   double e) {
  const Eigen::Index m = d.size();
  const InterfaceOperator op = sys.interfaceOperator(InterfaceMethod::factorisation);
  VectorXd Gd = VectorXd::Zero(m);
  for (Eigen::Index a = 0; a < m; ++a)
    for (Eigen::Index c = 0; c < m; ++c) Gd[a] += p.jacobianEntry(s, op.Stt, op.Snt, a, c) * d[c];
  const VectorXd fdD = (plus.D - minus.D) / (2 * e);
  REQUIRE(fdD.norm() > 0);
  CHECK((Gd.cwiseProduct(p.componentMask()) - fdD).norm() <= 1e-6 * fdD.norm());
}

}  // namespace

TEST_CASE("3D FractureSystem: the exact gradient and Newton's Jacobian match finite differences",
          "[fracture][fe][3d][gradient]") {
  // On the finite-element response, P1 and P2 (P2: Σ from the consistent mass, the gradient
  // from adjoint()), Coulomb with a ρ that follows σ_n, and the frozen-ρ gradient on Tresca.
  for (int degree : {1, 2})
    for (Fault f : {Fault::twoFaces, Fault::inside}) {
      DYNAMIC_SECTION("P" << degree << (f == Fault::inside ? " inside" : " two faces")) {
        Box b(4, degree, f, Point(0.01, -0.02, -0.03), true, tilt(), true);
        FractureSystem& sys = *b.sys;
        const Eigen::Index n = sys.size();
        const double gamma = 4.0;
        struct Law {
          double mu, cohesion;
          GradientKind kind;
        };
        for (const Law& law :
             {Law{0.3, 0.0, GradientKind::exact}, Law{0.0, 0.01, GradientKind::frozenRho}}) {
          CAPTURE(law.mu);
          std::mt19937 rng(degree * 10 + static_cast<int>(f));
          std::uniform_real_distribution<double> u(-1, 1);
          // Bounds that differ from node to node: some nodes stick, others slip.
          const VectorXd spread =
              VectorXd::NullaryExpr(n, [&] { return 1 + 4 * std::abs(u(rng)); });
          ControlProblem p(sys, law.mu * spread, law.cohesion * spread, gamma, 0.0, law.kind);
          const VectorXd beta = mixedBeta(p, sys, rng, 0.003);
          const ControlState s = p.evaluate(beta);
          const VectorXd d =
              VectorXd::NullaryExpr(2 * n, [&] { return u(rng); }).cwiseProduct(p.componentMask());
          // J is smooth between kinks: the central difference errs by O(ε²) and by
          // cancellation ~1e-16 J/ε; ε is 1e-4 of β.
          const double e = 3e-7;
          const ControlState plus = p.evaluate(beta + e * d), minus = p.evaluate(beta - e * d);
          const double fd = (plus.J - minus.J) / (2 * e);
          REQUIRE(std::abs(fd) > 0);
          CHECK(p.dot(p.gradient(s), d) == Approx(fd).epsilon(1e-6));
          checkJacobian(sys, p, s, d, plus, minus, e);
        }
      }
    }
}

TEST_CASE("3D FractureSystem: Newton's two variants reach the same solution",
          "[fracture][fe][3d]") {
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    Box b(4, degree, Fault::inside, Point(0.01, -0.02, -0.03), true, tilt(), true);
    const Eigen::Index n = b.sys->size();
    std::vector<VectorXd> solutions;
    for (const char* variant : {"condensed", "krylov"}) {
      ControlProblem p(*b.sys, VectorXd::Constant(n, 0.3), VectorXd::Zero(n), 4.0, 0.0,
                       GradientKind::exact);
      Dictionary d = Dictionary::parse(std::string("type semismoothNewton; variant ") + variant +
                                           "; tolerance 1e-11; maxIterations 50;",
                                       "test");
      auto opt = Optimizer::New(d);
      VectorXd beta = VectorXd::Zero(2 * n);
      const OptimizerReport rep = opt->minimize(p, beta);
      REQUIRE(rep.status == OptimizerStatus::converged);
      const ControlState s = p.evaluate(beta);
      int slip = 0;
      for (const auto& c : s.node) slip += c.state == SlipState::slip;
      REQUIRE(slip > 0);
      solutions.push_back(beta);
    }
    CHECK((solutions[0] - solutions[1]).norm() <= 1e-8 * solutions[0].norm());
  }
}

TEST_CASE("3D FractureSystem: P2 tractions agree with P1's on an embedded fault under load",
          "[fracture][fe][3d]") {
  // An embedded square fault in a box compressed and sheared through its top: the lumped P2
  // recovery put the vertices near σ_n = 0 ("open") and the midpoints at 4/3 of P1's σ_n.
  // After Newton (Coulomb), P2's σ_n at the nodes two elements or more from the tip line is
  // within a few percent of P1's at the same points.
  const int n = 8;
  const Point top(0.02, 0.01, -0.03);
  std::vector<std::vector<std::pair<Point, double>>> result(2);
  for (int degree : {1, 2}) {
    Box b(n, degree, Fault::inside, top, true, Eigen::Matrix3d::Identity(), true);
    const Eigen::Index m = b.sys->size();
    ControlProblem p(*b.sys, VectorXd::Constant(m, 0.15), VectorXd::Zero(m), 4.0 * n, 0.0,
                     GradientKind::exact);
    Dictionary d = Dictionary::parse(
        "type semismoothNewton; variant condensed; tolerance 1e-11; maxIterations 50;", "test");
    VectorXd beta = VectorXd::Zero(2 * m);
    REQUIRE(Optimizer::New(d)->minimize(p, beta).status == OptimizerStatus::converged);
    const ControlState s = p.evaluate(beta);
    int slip = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      const ControlNode& v = b.sys->controlNodes()[i];
      if (v.tip) continue;
      slip += s.node[i].state == SlipState::slip;
      CHECK(s.node[i].state != SlipState::open);
      CHECK(s.sigmaN[i] < 0);
      result[degree - 1].emplace_back(v.position, s.sigmaN[i]);
    }
    CHECK(slip > 0);
  }
  double worst = 0;
  int compared = 0;
  for (const auto& [x, v] : result[1]) {
    // Two elements or more from the tip line (the fault is [1/n, 1 − 1/n]² at z = 1/2).
    const double edge =
        std::min({x.x() - 1.0 / n, 1 - 1.0 / n - x.x(), x.y() - 1.0 / n, 1 - 1.0 / n - x.y()});
    if (edge < 2.0 / n - 1e-12) continue;
    // P1's value there: at a vertex its own; at a midpoint the mean of the P1 vertices
    // nearest to it (the two ends of a grid side, the four corners of a square's diagonal).
    double nearest = 1e300;
    for (const auto& entry : result[0]) nearest = std::min(nearest, (entry.first - x).norm());
    double sum = 0;
    int count = 0;
    for (const auto& [y, w] : result[0])
      if ((y - x).norm() <= nearest + 1e-12) {
        sum += w;
        ++count;
      }
    REQUIRE(count >= 1);
    const double ref = sum / count;
    worst = std::max(worst, std::abs(v - ref) / std::abs(ref));
    ++compared;
  }
  REQUIRE(compared > 0);
  INFO("compared " << compared << " worst " << worst);
  CHECK(worst <= 0.05);
}

namespace {

// The unit box with the vertical fault x = 1/2 over y ∈ [1/n, 1 − 1/n] and all z: it reaches
// the faces z = 0 and z = 1 (patches 5, 6), which fix `zFaces`; x = 0 is clamped and x = 1
// moved by `xmax` (compressed and sheared along y), so the fault closes and slips along y.
struct FaultToFaces {
  Mesh mesh;
  SplitMesh split;
  Material material = Material::fromLame(1.0, 1.0);
  std::unique_ptr<FractureSystem> sys;

  FaultToFaces(int n, int degree, FixedComponents zFaces,
               const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
    mesh = boxMesh(n);
    addPlaneFault(mesh, n, 0, n / 2, 1, n - 1, 0, n, 7, "fault");
    for (Point& p : mesh.points) p = rotation * p;
    split = splitFractures(mesh, {{"fault", 7, {}}});
    sys = std::make_unique<FractureSystem>(split, degree, material);
    sys->dirichlet().fixPatch(1, FixedComponents::all);
    sys->dirichlet().fixPatch(2, FixedComponents::all);
    sys->dirichlet().fixPatch(5, zFaces);
    sys->dirichlet().fixPatch(6, zFaces);
    REQUIRE(sys->factor("cholmod", true) == FactorStatus::ok);
    sys->dirichlet().setPatchValue(1, Point(0, 0, 0));
    sys->dirichlet().setPatchValue(2, Point(rotation * Point(-0.005, 0.01, 0)));
    sys->dirichlet().setPatchValue(5, Point(0, 0, 0));
    sys->dirichlet().setPatchValue(6, Point(0, 0, 0));
    sys->setStep(VectorXd::Zero(sys->splitSpace().numDofs()), VectorXd::Zero(2 * sys->size()));
  }
  // Control nodes on the z faces (unrotated mesh), tips excluded.
  std::vector<Eigen::Index> onZFaces() const {
    std::vector<Eigen::Index> r;
    for (Eigen::Index i = 0; i < sys->size(); ++i) {
      const ControlNode& v = sys->controlNodes()[i];
      const double z = sys->splitSpace().point(v.plus).z();
      if (!v.tip && (std::abs(z) < 1e-12 || std::abs(z - 1) < 1e-12)) r.push_back(i);
    }
    return r;
  }
};

}  // namespace

TEST_CASE("3D FractureSystem: a block of dual solves equals the dual solves column by column",
          "[fracture][fe][3d]") {
  // dualBlock is what the krylov variant's probing solves with (one multi-column
  // back-substitution): the same τ and σ_n as dual(), to round-off of the block solve; P2
  // recovers with the consistent mass, a roller zeroes a held component, and more than 64
  // columns go in several blocks. It counts one back-substitution per column.
  for (int degree : {1, 2})
    for (const Eigen::Index m : {Eigen::Index(1), Eigen::Index(5), Eigen::Index(70)}) {
      CAPTURE(degree, m);
      FaultToFaces b(4, degree, FixedComponents::z);
      FractureSystem& sys = *b.sys;
      const Eigen::Index n = sys.size();
      REQUIRE(sys.numPartlyHeldOnDirichlet() > 0);
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> u(-1, 1);
      const Eigen::MatrixXd qt = Eigen::MatrixXd::NullaryExpr(2 * n, m, [&] { return u(rng); });
      const Eigen::MatrixXd qn = Eigen::MatrixXd::NullaryExpr(n, m, [&] { return u(rng); });
      const long solves0 = sys.factorization().numSolves();
      Eigen::MatrixXd T, N;
      sys.dualBlock(qt, qn, T, &N);
      CHECK(sys.factorization().numSolves() - solves0 == m);
      REQUIRE(T.rows() == 2 * n);
      REQUIRE(T.cols() == m);
      REQUIRE(N.rows() == n);
      REQUIRE(N.cols() == m);
      Eigen::MatrixXd T1(2 * n, m), N1(n, m);
      for (Eigen::Index c = 0; c < m; ++c) {
        VectorXd t, sn;
        sys.dual(qt.col(c), qn.col(c), t, &sn);
        T1.col(c) = t;
        N1.col(c) = sn;
      }
      REQUIRE(T1.cwiseAbs().maxCoeff() > 0);
      CHECK(relativeDifference(T, T1) <= 1e-12);
      CHECK(relativeDifference(N, N1) <= 1e-12);
      // Without the normal part asked for, the same τ.
      Eigen::MatrixXd T2;
      sys.dualBlock(qt, qn, T2);
      CHECK(relativeDifference(T2, T1) <= 1e-12);
    }
}

TEST_CASE("3D FractureSystem: a roller holds only the jump component it fixes",
          "[fracture][fe][3d]") {
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    SECTION("rollers (z) on the faces the vertical fault reaches: the slip goes on along y") {
      FaultToFaces b(4, degree, FixedComponents::z);
      FractureSystem& sys = *b.sys;
      const auto face = b.onZFaces();
      REQUIRE(!face.empty());
      const VectorXd cm = sys.componentMask();
      CHECK(sys.numPartlyHeldOnDirichlet() == static_cast<int>(face.size()));
      CHECK(sys.numHeldOnDirichlet() == 0);
      for (Eigen::Index i : face) {
        const ControlNode& v = sys.controlNodes()[i];
        // n_Γ = ±e_x: tangentBasis gives t₁ = e_y, t₂ = ±e_z, the direction the roller fixes.
        CHECK(v.heldComponent == 1);
        CHECK(std::abs(v.tangent[0].y()) == Approx(1).margin(1e-12));
        CHECK(std::abs(v.tangent[1].z()) == Approx(1).margin(1e-12));
        CHECK(sys.freeMask()[i] == 1);
        CHECK(cm[2 * i] == 1);
        CHECK(cm[2 * i + 1] == 0);
      }
      const Eigen::Index n = sys.size();
      ControlProblem p(sys, VectorXd::Constant(n, 0.3), VectorXd::Zero(n), 4.0, 0.0,
                       GradientKind::exact);
      auto opt = Optimizer::New(
          Dictionary::parse("type semismoothNewton; tolerance 1e-11; maxIterations 50;", "test"));
      VectorXd beta = VectorXd::Zero(2 * n);
      REQUIRE(opt->minimize(p, beta).status == OptimizerStatus::converged);
      const ControlState s = p.evaluate(beta);
      int slipping = 0;
      for (Eigen::Index i : face) {
        const ControlNode& v = sys.controlNodes()[i];
        const Point jump = s.beta[2 * i] * v.tangent[0] + s.beta[2 * i + 1] * v.tangent[1];
        CHECK(jump.z() == 0.0);
        CHECK(s.tau[2 * i + 1] == 0.0);  // the roller's reaction is not a friction traction
        CHECK(s.sigmaN[i] < 0);
        slipping += s.node[i].state == SlipState::slip && std::abs(jump.y()) > 0;
      }
      CHECK(slipping > 0);
    }
    SECTION("rollers fixing the fault's normal component hold nothing of the jump") {
      FaultToFaces b(4, degree, FixedComponents::x);
      FractureSystem& sys = *b.sys;
      REQUIRE(!b.onZFaces().empty());
      CHECK(sys.numPartlyHeldOnDirichlet() == 0);
      CHECK(sys.numHeldOnDirichlet() == 0);
      const VectorXd cm = sys.componentMask();
      for (Eigen::Index i : b.onZFaces()) {
        CHECK(sys.freeMask()[i] == 1);
        CHECK(cm[2 * i] == 1);
        CHECK(cm[2 * i + 1] == 1);
      }
    }
    SECTION("a clamped face holds the whole jump") {
      FaultToFaces b(4, degree, FixedComponents::all);
      FractureSystem& sys = *b.sys;
      const auto face = b.onZFaces();
      REQUIRE(!face.empty());
      CHECK(sys.numPartlyHeldOnDirichlet() == 0);
      CHECK(sys.numHeldOnDirichlet() >= static_cast<int>(face.size()));  // and the tips
      const VectorXd cm = sys.componentMask();
      for (Eigen::Index i : face) {
        CHECK(sys.controlNodes()[i].onDirichlet);
        CHECK(sys.freeMask()[i] == 0);
        CHECK(cm[2 * i] == 0);
        CHECK(cm[2 * i + 1] == 0);
      }
    }
  }
}

TEST_CASE(
    "3D FractureSystem: with partly held nodes the gradient and Jacobian match finite "
    "differences",
    "[fracture][fe][3d][gradient]") {
  // Tilted, the roller's direction (the projection of e_z) is along neither vector of
  // tangentBasis(n_Γ): the basis is turned there (t₂ along it).
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    FaultToFaces b(4, degree, FixedComponents::z, tilt());
    FractureSystem& sys = *b.sys;
    const Eigen::Index n = sys.size();
    int turned = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const ControlNode& v = sys.controlNodes()[i];
      if (v.heldComponent < 0) continue;
      Point p = Point::UnitZ() - v.normal.z() * v.normal;
      turned += std::abs(v.tangent[1].dot(p.normalized())) > 1 - 1e-12 &&
                std::abs(tangentBasis(v.normal)[1].dot(p.normalized())) < 1 - 1e-6;
    }
    REQUIRE(turned > 0);
    const double gamma = 4.0;
    std::mt19937 rng(degree);
    std::uniform_real_distribution<double> u(-1, 1);
    const VectorXd spread = VectorXd::NullaryExpr(n, [&] { return 1 + 4 * std::abs(u(rng)); });
    ControlProblem p(sys, 0.3 * spread, VectorXd::Zero(n), gamma, 0.0, GradientKind::exact);
    const VectorXd beta = mixedBeta(p, sys, rng, 0.003);
    const ControlState s = p.evaluate(beta);
    const VectorXd d =
        VectorXd::NullaryExpr(2 * n, [&] { return u(rng); }).cwiseProduct(p.componentMask());
    const double e = 3e-7;
    const ControlState plus = p.evaluate(beta + e * d), minus = p.evaluate(beta - e * d);
    // J curves strongly here: the central difference's O(ε²) error was measured at 2.7e-6
    // of the gradient for P2 at this ε and 3e-5 at 1e-6. One Richardson step (differences at
    // ε and 2ε) removes it.
    const ControlState plus2 = p.evaluate(beta + 2 * e * d), minus2 = p.evaluate(beta - 2 * e * d);
    const double fd = (4 * (plus.J - minus.J) / (2 * e) - (plus2.J - minus2.J) / (4 * e)) / 3;
    REQUIRE(std::abs(fd) > 0);
    CHECK(p.dot(p.gradient(s), d) == Approx(fd).epsilon(1e-6));
    checkJacobian(sys, p, s, d, plus, minus, e);
  }
}
