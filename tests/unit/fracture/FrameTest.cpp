// The frame of a fracture node (SignConventions.hpp, docs/method.md §7): in 3D the tangent
// basis from the normal is orthonormal and right-handed, with the stated tie-break; in 2D
// every control node carries t₁ = t_Γ = (−n_y, n_x).
#include <catch2/catch.hpp>

#include <random>

#include "TestMeshes.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SignConventions.hpp"

using namespace friction;
using namespace friction::test;
using Eigen::Vector3d;

TEST_CASE("the 3D tangent basis is orthonormal and right-handed", "[fracture][frame]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 1000; ++trial) {
    const Vector3d n = Vector3d(g(rng), g(rng), g(rng)).normalized();
    const auto [t1, t2] = tangentBasis(n);
    // Round-off of a projection, a normalisation and a cross product: 1e-15.
    CHECK(std::abs(t1.norm() - 1) <= 1e-15);
    CHECK(std::abs(t2.norm() - 1) <= 1e-15);
    CHECK(std::abs(t1.dot(n)) <= 1e-15);
    CHECK(std::abs(t2.dot(n)) <= 1e-15);
    CHECK(std::abs(t1.dot(t2)) <= 1e-15);
    CHECK((t1.cross(t2) - n).norm() <= 1e-15);  // (t₁, t₂, n_Γ) right-handed
    // t₁ lies in the plane of n_Γ and the axis least aligned with it.
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
    CHECK(std::abs(n.cross(Vector3d::Unit(axis)).dot(t1)) <= 1e-15);
    CHECK(t1[axis] > 0);
  }
}

TEST_CASE("the 3D tangent basis: axis normals and the tie-break", "[fracture][frame]") {
  // n = z: x and y tie (both 0): x, the earlier axis, gives t₁; t₂ = z × x = y.
  auto [a1, a2] = tangentBasis(Vector3d(0, 0, 1));
  CHECK(a1 == Vector3d(1, 0, 0));
  CHECK(a2 == Vector3d(0, 1, 0));
  // n = x: y and z tie: t₁ = y, t₂ = x × y = z.
  auto [b1, b2] = tangentBasis(Vector3d(1, 0, 0));
  CHECK(b1 == Vector3d(0, 1, 0));
  CHECK(b2 == Vector3d(0, 0, 1));
  // n = −y: x and z tie: t₁ = x, t₂ = −y × x = z.
  auto [c1, c2] = tangentBasis(Vector3d(0, -1, 0));
  CHECK(c1 == Vector3d(1, 0, 0));
  CHECK(c2 == Vector3d(0, 0, 1));
  // All three tie: x, projected: (2, −1, −1)/√6.
  const auto [d1, d2] = tangentBasis(Vector3d(1, 1, 1).normalized());
  CHECK((d1 - Vector3d(2, -1, -1) / std::sqrt(6.0)).norm() <= 1e-15);
  CHECK((d2 - Vector3d(1, 1, 1).normalized().cross(d1)).norm() == 0.0);
}

TEST_CASE("2D control nodes carry t = (-n_y, n_x) as their one tangent", "[fracture][frame]") {
  for (int degree : {1, 2}) {
    Mesh m = gridMesh(6);
    addHorizontalFracture(m, 6, 3, 1, 5, 5, "fracture");
    const SplitMesh split = splitFractures(m, {{"fracture", 5, {}}});
    const Material material = Material::fromLame(1.0, 1.0);
    FractureSystem sys(split, degree, material);
    CHECK(sys.dimension() == 2);
    CHECK(sys.blockSize() == 1);
    REQUIRE(sys.controlNodes().size() > 2);
    for (const ControlNode& v : sys.controlNodes()) {
      const Vector3d& t = v.tangent[0];
      CHECK(t == Vector3d(-v.normal.y(), v.normal.x(), 0));
      CHECK(v.normal.z() == 0.0);
      CHECK(std::abs(v.normal.norm() - 1) <= 1e-15);
      // A horizontal fracture is walked left to right (SignConventions.hpp).
      CHECK(t.x() == Approx(1.0));
    }
  }
}
