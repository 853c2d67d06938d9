// ElasticityAssembler::pressureLoad, the load ∫ b αp div φ_i of a pore pressure (docs/method.md
// §11): over a closed body a uniform αp has zero resultant (its boundary terms cancel) and its
// virtual work against the uniform expansion v = x is αp · d · |Ω| (positive: a pressure
// pushes outwards), P1 and P2, 2D and 3D, on distorted meshes; plane stress scales it by
// (1 − 2ν)/(1 − ν); values at the points are interpolated linearly.
#include <catch2/catch.hpp>
#include <cmath>

#include "FeTestMeshes.hpp"
#include "friction/fe/ElasticityAssembler.hpp"

using namespace friction;

namespace {

/// Σ_i F_i v(x_i) for v = x: the virtual work of F against the uniform expansion (the P1 / P2
/// interpolant of x is x itself).
double workAgainstExpansion(const LagrangeSpace& V, const Eigen::VectorXd& F) {
  double w = 0;
  for (Index n = 0; n < V.numNodes(); ++n)
    for (int c = 0; c < V.dim(); ++c) w += F[V.dof(n, c)] * V.point(n)[c];
  return w;
}

/// The resultant force Σ_i F_i per component.
Eigen::Vector3d resultant(const LagrangeSpace& V, const Eigen::VectorXd& F) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (Index n = 0; n < V.numNodes(); ++n)
    for (int c = 0; c < V.dim(); ++c) r[c] += F[V.dof(n, c)];
  return r;
}

}  // namespace

TEST_CASE("pressureLoad: zero resultant, virtual work alpha p d |Omega| against v = x",
          "[fe][pressureLoad]") {
  // αp = 3e6 Pa on the unit square / cube (|Ω| = 1). The sums add O(N) terms of size αp h^(d−1)
  // with alternating signs: round-off ~1e-16 × N × αp; 1e-12 αp leaves a margin of 100 on
  // these meshes, while a wrong sign or a missing term is off by αp or more.
  const double alphaP = 3e6;
  const Material material = Material::fromYoungPoisson(10e9, 0.25);
  for (int dim : {2, 3})
    for (int degree : {1, 2}) {
      DYNAMIC_SECTION(dim << "D, P" << degree) {
        const Mesh mesh = dim == 2 ? test::unitSquareMesh(5, 0.4) : test::unitCubeMesh(2, 0.4);
        const LagrangeSpace V(mesh, degree);
        const ElasticityAssembler a(V, material);
        const Eigen::VectorXd F = a.pressureLoad([&](Index, const Point&) { return alphaP; });
        CHECK(F.norm() > 0.1 * alphaP);  // boundary nodes carry the load
        CHECK(resultant(V, F).norm() <= 1e-12 * alphaP);
        CHECK(workAgainstExpansion(V, F) == Approx(alphaP * dim * 1.0).epsilon(1e-12));
        // The same from values at the points.
        const Eigen::VectorXd atPoints =
            Eigen::VectorXd::Constant(static_cast<Eigen::Index>(mesh.points.size()), alphaP);
        CHECK((a.pressureLoad(atPoints) - F).norm() <= 1e-12 * F.norm());
        // A linear αp = αp₀ x at the points, interpolated exactly: ∫ αp div x = d αp₀ ∫ x = d
        // αp₀ / 2 on the unit square and cube.
        Eigen::VectorXd linear(atPoints.size());
        for (std::size_t i = 0; i < mesh.points.size(); ++i)
          linear[static_cast<Eigen::Index>(i)] = alphaP * mesh.points[i].x();
        CHECK(workAgainstExpansion(V, a.pressureLoad(linear)) ==
              Approx(alphaP * dim * 0.5).epsilon(1e-12));
      }
    }
}

TEST_CASE("pressureLoad: plane stress takes the in-plane share (1 - 2 nu)/(1 - nu)",
          "[fe][pressureLoad]") {
  // σ_zz = 0 in a thin plate: the pressure expands it across its thickness too, and what
  // remains in the plane is 2μ/(λ + 2μ) = (1 − 2ν)/(1 − ν) of αp (2/3 at ν = 1/4).
  const double alphaP = 3e6, nu = 0.25;
  const Mesh mesh = test::unitSquareMesh(4, 0.3);
  for (int degree : {1, 2}) {
    const LagrangeSpace V(mesh, degree);
    const ElasticityAssembler strain(V, Material::fromYoungPoisson(10e9, nu, false));
    const ElasticityAssembler stress(V, Material::fromYoungPoisson(10e9, nu, true));
    const auto p = [&](Index, const Point&) { return alphaP; };
    CHECK(strain.pressureFactor(0) == 1.0);
    CHECK(stress.pressureFactor(0) == Approx((1 - 2 * nu) / (1 - nu)).epsilon(1e-15));
    CHECK(workAgainstExpansion(V, stress.pressureLoad(p)) ==
          Approx(alphaP * 2 * (1 - 2 * nu) / (1 - nu)).epsilon(1e-12));
  }
}
