// The case's 0/D on a 3D mesh (BoundaryConditions.hpp): on the unit cube of tetrahedra
// (FeTestMeshes.hpp, faces x0 x1 y0 y1 z0 z1), P1 and P2 — the traction and pressure loads are
// the exact ∫ g·φ_i of a constant traction (total force and first moment), a pressure pushes
// inward on every face, fixedDisplacement fixes exactly the components listed, and wrong
// component counts are InputErrors naming the key. 2D: 'z' is refused.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "../fe/FeTestMeshes.hpp"
#include "friction/case/BoundaryConditions.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/LagrangeSpace.hpp"

using namespace friction;

namespace {

const char* const kFaces[6] = {"x0", "x1", "y0", "y1", "z0", "z1"};

/// A 0/D whose boundaryField gives `entries` and lists every other face of the cube free.
Dictionary zeroD(const std::string& entries, const std::vector<std::string>& given) {
  std::string text = "boundaryField\n{\n" + entries;
  for (const char* f : kFaces)
    if (std::find(given.begin(), given.end(), f) == given.end())
      text += std::string(f) + " { type free; }\n";
  return Dictionary::parse(text + "}\n", "0/D");
}

std::string errorOf(const Dictionary& d, const Mesh& mesh) {
  try {
    BoundaryConditions bc(d, mesh, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// Outward unit normal of cube face k (0..5 = x0 x1 y0 y1 z0 z1).
Point faceNormal(int k) {
  Point n = Point::Zero();
  n[k / 2] = k % 2 == 0 ? -1.0 : 1.0;
  return n;
}

/// Nodes of the space on the face with label `label` (1..6), checked non-empty.
std::vector<Index> faceNodes(const LagrangeSpace& V, int label) {
  std::vector<Index> nodes = V.patchNodes(label);
  REQUIRE(!nodes.empty());
  return nodes;
}

}  // namespace

TEST_CASE("3D traction: the nodal loads are the exact integral of a constant traction",
          "[case][bc3d]") {
  const Mesh mesh = test::unitCubeMesh(2, 0.3);
  const Point g(1.5e6, -2.0e6, 3.0e6);  // [Pa]
  const Dictionary d = zeroD("x1 { type traction; traction (1.5e6 -2e6 3e6); }\n", {"x1"});
  const BoundaryConditions bc(d, mesh, {});
  d.checkAllRead();
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    const LagrangeSpace V(mesh, degree);
    const Eigen::VectorXd F = bc.neumannLoad(V, 0.0);
    // On the face x = 1 (area 1): Σ F = g A and Σ F y = g ∫ y dA = g/2 (exact for a
    // constant traction, P1 and P2 alike); nothing off the face.
    Point total = Point::Zero(), moment = Point::Zero();
    double offFace = 0.0;
    const std::vector<Index> onFace = faceNodes(V, 2);
    for (Index n = 0; n < V.numNodes(); ++n) {
      const Point f(F[V.dof(n, 0)], F[V.dof(n, 1)], F[V.dof(n, 2)]);
      if (std::binary_search(onFace.begin(), onFace.end(), n)) {
        total += f;
        moment += f * V.point(n).y();
      } else {
        offFace = std::max(offFace, f.norm());
      }
    }
    // Sums of a few dozen terms of size 1e6: 1e-9 relative is round-off.
    CHECK((total - g).norm() <= 1e-9 * g.norm());
    CHECK((moment - 0.5 * g).norm() <= 1e-9 * g.norm());
    CHECK(offFace == 0.0);
    if (degree == 2) {
      // ∫ φ over a P2 triangle is 0 at its vertices: the load sits on the midpoints.
      double atVertices = 0.0;
      for (Index n : onFace)
        if (n < mesh.numPoints())
          for (int c = 0; c < 3; ++c) atVertices = std::max(atVertices, std::abs(F[V.dof(n, c)]));
      CHECK(atVertices == 0.0);
    }
  }
}

TEST_CASE("3D pressure pushes inward on every face of the cube", "[case][bc3d]") {
  const Mesh mesh = test::unitCubeMesh(2, 0.3);
  const double p = 2.5e6;  // [Pa]
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    const LagrangeSpace V(mesh, degree);
    // One face at a time: the force on face k is −p n_k A (A = 1), every node pushed inward.
    for (int k = 0; k < 6; ++k) {
      CAPTURE(kFaces[k]);
      const Dictionary d =
          zeroD(std::string(kFaces[k]) + " { type pressure; pressure 2.5e6; }\n", {kFaces[k]});
      const BoundaryConditions bc(d, mesh, {});
      const Eigen::VectorXd F = bc.neumannLoad(V, 0.0);
      Point total = Point::Zero();
      int pushedInward = 0;
      const std::vector<Index> onFace = faceNodes(V, k + 1);
      for (Index n : onFace) {
        const Point f(F[V.dof(n, 0)], F[V.dof(n, 1)], F[V.dof(n, 2)]);
        total += f;
        // Along −n only (no tangential part), never outward.
        CHECK((f - f.dot(faceNormal(k)) * faceNormal(k)).norm() <= 1e-9 * p);
        CHECK(f.dot(faceNormal(k)) <= 0.0);
        pushedInward += f.dot(faceNormal(k)) < 0.0;
      }
      CHECK(pushedInward > 0);
      CHECK((total + p * faceNormal(k)).norm() <= 1e-9 * p);
    }
    // All six faces: a closed surface under uniform pressure has no resultant.
    std::string all;
    for (const char* f : kFaces) all += std::string(f) + " { type pressure; pressure 2.5e6; }\n";
    const BoundaryConditions bc(zeroD(all, {"x0", "x1", "y0", "y1", "z0", "z1"}), mesh, {});
    const Eigen::VectorXd F = bc.neumannLoad(V, 0.0);
    REQUIRE(F.norm() > 0.0);
    Point total = Point::Zero();
    for (Index n = 0; n < V.numNodes(); ++n)
      total += Point(F[V.dof(n, 0)], F[V.dof(n, 1)], F[V.dof(n, 2)]);
    CHECK(total.norm() <= 1e-9 * p);
  }
}

TEST_CASE("3D fixedDisplacement fixes exactly the components listed", "[case][bc3d]") {
  const Mesh mesh = test::unitCubeMesh(2);
  const Dictionary d = zeroD(
      "z0 { type fixedDisplacement; components (x z); value table ((0 (0 0 0)) (2 (0.2 0.4 "
      "-0.6))); }\n",
      {"z0"});
  const BoundaryConditions bc(d, mesh, {});
  d.checkAllRead();
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    const LagrangeSpace V(mesh, degree);
    DirichletConditions dirichlet(V);
    bc.fix(dirichlet);
    bc.setValues(dirichlet, 1.0);  // halfway through the table: (0.1 0.2 −0.3)
    const std::vector<Index> onFace = faceNodes(V, 5);
    for (Index n : onFace) {
      CHECK(dirichlet.isFixed(V.dof(n, 0)));
      CHECK(!dirichlet.isFixed(V.dof(n, 1)));
      CHECK(dirichlet.isFixed(V.dof(n, 2)));
      CHECK(dirichlet.values()[V.dof(n, 0)] == Approx(0.1));
      CHECK(dirichlet.values()[V.dof(n, 2)] == Approx(-0.3));
    }
    // Two components on every node of the face, nothing else.
    CHECK(dirichlet.numFixed() == 2 * static_cast<Index>(onFace.size()));
  }
  SECTION("all three components without 'components'") {
    const BoundaryConditions all(
        zeroD("z0 { type fixedDisplacement; value uniform (0 0 0.01); }\n", {"z0"}), mesh, {});
    const LagrangeSpace V(mesh, 1);
    DirichletConditions dirichlet(V);
    all.fix(dirichlet);
    all.setValues(dirichlet, 0.0);
    const std::vector<Index> onFace = faceNodes(V, 5);
    CHECK(dirichlet.numFixed() == 3 * static_cast<Index>(onFace.size()));
    for (Index n : onFace) CHECK(dirichlet.values()[V.dof(n, 2)] == 0.01);
  }
}

TEST_CASE("3D 0/D: wrong component counts and words are errors naming the key", "[case][bc3d]") {
  const Mesh mesh = test::unitCubeMesh(1);
  struct Bad {
    const char* entry;
    const char* message;
  };
  for (const Bad& b : {
           Bad{"x0 { type fixedDisplacement; value (0 0); }",
               "patch 'x0': key 'value': expected a vector (x y z), got (0 0)"},
           Bad{"x0 { type fixedDisplacement; value table ((0 (0 0)) (1 (0 1))); }",
               "patch 'x0': key 'value': table rows must hold a vector (x y z) after the time"},
           Bad{"x0 { type traction; traction (1 2 3 4); }",
               "patch 'x0': key 'traction': expected a vector (x y z), got (1 2 3 4)"},
           Bad{"x0 { type fixedDisplacement; components (x w); value (0 0 0); }",
               "patch 'x0': key 'components': expected a non-empty subset of (x y z), e.g. (x z)"},
           Bad{"x0 { type fixedDisplacement; components (z z); value (0 0 0); }",
               "patch 'x0': key 'components': expected a non-empty subset of (x y z), e.g. (x z)"},
           Bad{"x0 { type fixedDisplacement; components (); value (0 0 0); }",
               "patch 'x0': key 'components': expected a non-empty subset of (x y z), e.g. (x z)"},
       }) {
    CAPTURE(b.entry);
    const std::string message = errorOf(zeroD(std::string(b.entry) + "\n", {"x0"}), mesh);
    CHECK(message.find(b.message) != std::string::npos);
    CHECK(message.rfind("0/D:", 0) == 0);
  }
  SECTION("a pressure patch's triangle that no tetrahedron has") {
    Mesh bad = mesh;
    // (1 0 0) (0 1 0) (0 0 1): every Kuhn tetrahedron has the corners 0 and 7, this has neither.
    bad.addFacet({1, 2, 4}, 2);
    CHECK(errorOf(zeroD("x1 { type pressure; pressure 1; }\n", {"x1"}), bad) ==
          "unitCube1: the triangle (1 0 0) (0 1 0) (0 0 1) of patch 'x1' is not a face of any "
          "tetrahedron");
  }
  SECTION("every boundary patch (triangles) must be listed") {
    const Dictionary d = Dictionary::parse(
        "boundaryField { x0 { type free; } x1 { type free; } y0 { type free; } y1 { type free; "
        "} z0 { type free; } }\n",
        "0/D");
    CHECK(errorOf(d, mesh).find("boundaryField has no entry for patch 'z1'") != std::string::npos);
  }
}

TEST_CASE("2D 0/D: 'z' is refused, three components are refused", "[case][bc3d]") {
  const Mesh mesh = test::unitSquareMesh(2);
  const auto d2 = [](const std::string& bottom) {
    return Dictionary::parse("boundaryField { bottom " + bottom +
                                 " right { type free; } top { type free; } left { type free; } }",
                             "0/D");
  };
  const std::string z =
      errorOf(d2("{ type fixedDisplacement; components (x z); value (0 0); }"), mesh);
  CHECK(z.find("patch 'bottom': key 'components': 'z' has no meaning on a 2D mesh") !=
        std::string::npos);
  const std::string three = errorOf(d2("{ type fixedDisplacement; value (0 0 0); }"), mesh);
  CHECK(three.find("patch 'bottom': key 'value': expected a vector (x y)") != std::string::npos);
  // The 2D forms are read as before.
  const BoundaryConditions ok(d2("{ type fixedDisplacement; components (y); value (0 0); }"), mesh,
                              {});
  REQUIRE(ok.patches().size() == 4);
  CHECK(ok.patches()[0].components == FixedComponents::y);
}
