// Effects on a 3D mesh (Effect.hpp): bodyForce and initialStress's gradient load integrate to
// the exact resultant on the unit cube of tetrahedra (P1 and P2), initialStress adds n·σ⁰n and
// t_c·σ⁰n to the fracture tractions with σ⁰ varying along z, fracturePressure takes a constant
// but refuses a values file, and wrong counts are InputErrors naming the key. 2D: σ⁰ in the
// upper-left block.
#include <catch2/catch.hpp>
#include <string>

#include "../fe/FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;

namespace {

std::unique_ptr<Effect> effect(const std::string& text, int dim) {
  const Dictionary d = Dictionary::parse(text, "constant/effects");
  auto e = Effect::New("e", d, {"crack"}, ".", dim);
  d.checkAllRead();
  return e;
}

std::string errorOf(const std::string& text, int dim) {
  try {
    effect(text, dim);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// Σ over nodes of the load, per component.
Point resultant(const LagrangeSpace& V, const Eigen::VectorXd& F) {
  Point r = Point::Zero();
  for (Index n = 0; n < V.numNodes(); ++n)
    for (int c = 0; c < 3; ++c) r[c] += F[V.dof(n, c)];
  return r;
}

}  // namespace

TEST_CASE("3D bodyForce and the initial-stress gradient load sum to their resultants",
          "[effect][effect3d]") {
  const Mesh mesh = test::unitCubeMesh(2, 0.3);  // volume 1: boundary nodes stay on the cube
  const Material material = Material::fromYoungPoisson(1e10, 0.25);
  const auto gravity = effect("type bodyForce; density 2500; g (1 -2 -9.81);", 3);
  CHECK(gravity->describe() == "density 2500 kg/m3, g (1 -2 -9.81) m/s2");
  // ∂σ⁰/∂z = (xx yy zz xy yz xz) = (1 2 3 4 5 6) e3 Pa/m: div σ⁰ = (xz, yz, zz) = (6 5 3) e3.
  const auto inSitu = effect(
      "type initialStress; stress (-1e6 -2e6 -3e6 0 0 0); gradient (1e3 2e3 3e3 4e3 5e3 6e3);", 3);
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    const LagrangeSpace V(mesh, degree);
    const ElasticityAssembler assembler(V, material);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
    gravity->addLoad(assembler, 0.0, F);
    // ρ g V with V = 1 [N]; a sum of ~100 terms: 1e-10 relative is round-off.
    const Point rhoG = 2500.0 * Point(1, -2, -9.81);
    CHECK((resultant(V, F) - rhoG).norm() <= 1e-10 * rhoG.norm());
    F.setZero();
    inSitu->addLoad(assembler, 0.0, F);
    const Point divSigma(6e3, 5e3, 3e3);
    CHECK((resultant(V, F) - divSigma).norm() <= 1e-10 * divSigma.norm());
  }
}

TEST_CASE("3D initialStress: σ⁰(z) and its fracture traction n·σ⁰n, t_c·σ⁰n",
          "[effect][effect3d]") {
  const auto inSitu = effect(
      "type initialStress; stress (-10e6 -20e6 -30e6 1e6 2e6 3e6); "
      "gradient (1e4 2e4 3e4 4e4 5e4 6e4);",
      3);
  CHECK(inSitu->describe() ==
        "sigma0 (xx yy zz xy yz xz) = (-1e+07 -2e+07 -3e+07 1e+06 2e+06 3e+06) Pa + z (10000 "
        "20000 30000 40000 50000 60000) Pa/m");
  // At z = −100: σ⁰ = s + z g, written out entry by entry.
  const Point x(7.0, -3.0, -100.0);
  Eigen::Matrix3d expected;
  expected << -10e6 - 1e6, 1e6 - 4e6, 3e6 - 6e6,  //
      1e6 - 4e6, -20e6 - 2e6, 2e6 - 5e6,          //
      3e6 - 6e6, 2e6 - 5e6, -30e6 - 3e6;
  CHECK((inSitu->initialStress(x) - expected).norm() <= 1e-9 * expected.norm());

  // A node with n = (1 2 2)/3, t1 = (2 −2 1)/3, t2 = n × t1 = (2 1 −2)/3.
  ControlNode node;
  node.position = x;
  node.normal = Eigen::Vector3d(1, 2, 2) / 3;
  node.tangent = {Eigen::Vector3d(2, -2, 1) / 3, Eigen::Vector3d(2, 1, -2) / 3};
  Eigen::VectorXd sigmaN(1), tau(2);
  sigmaN << 5.0;  // the effect adds to what is there
  tau << -1.0, 2.0;
  inSitu->addFractureTraction({node}, 0.0, sigmaN, tau);
  const auto quadratic = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    double s = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s += a[i] * expected(i, j) * b[j];
    return s;
  };
  // Entries ~3e7: 1e-9 relative is round-off.
  CHECK(sigmaN[0] == Approx(5.0 + quadratic(node.normal, node.normal)).epsilon(1e-12).margin(1e-2));
  CHECK(tau[0] ==
        Approx(-1.0 + quadratic(node.tangent[0], node.normal)).epsilon(1e-12).margin(1e-2));
  CHECK(tau[1] ==
        Approx(2.0 + quadratic(node.tangent[1], node.normal)).epsilon(1e-12).margin(1e-2));
  // The shear on the tangents is not zero here: the check sees both tangents.
  CHECK(std::abs(quadratic(node.tangent[0], node.normal)) > 1e6);
  CHECK(std::abs(quadratic(node.tangent[1], node.normal)) > 1e6);

  SECTION("a uniform pure shear σ_xz = τ on the plane z = const: σ_n = 0, τ along x") {
    const auto shear = effect("type initialStress; stress (0 0 0 0 0 4e6);", 3);
    ControlNode flat;
    flat.position = Point(0.3, 0.2, 0.1);
    flat.normal = Eigen::Vector3d(0, 0, 1);
    flat.tangent = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
    Eigen::VectorXd s = Eigen::VectorXd::Zero(1), t = Eigen::VectorXd::Zero(2);
    shear->addFractureTraction({flat}, 0.0, s, t);
    CHECK(s[0] == 0.0);
    CHECK(t[0] == 4e6);
    CHECK(t[1] == 0.0);
  }
}

TEST_CASE("2D initialStress: σ⁰ in the upper-left block, σ⁰_zz = 0", "[effect][effect3d]") {
  const auto inSitu = effect("type initialStress; stress (-1e6 -2e6 3e5); gradient (10 20 30);", 2);
  const Eigen::Matrix3d s = inSitu->initialStress(Point(5.0, -100.0, 0.0));
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  expected.topLeftCorner<2, 2>() << -1e6 - 1e3, 3e5 - 3e3, 3e5 - 3e3, -2e6 - 2e3;
  CHECK((s - expected).norm() <= 1e-9 * expected.norm());
  CHECK(inSitu->describe() == "sigma0 (xx yy xy) = (-1e+06 -2e+06 300000) Pa + y (10 20 30) Pa/m");
}

TEST_CASE("3D fracturePressure: a constant is read, a values file is refused with the reason",
          "[effect][effect3d]") {
  const auto pore = effect("type fracturePressure; fracture crack; pressure 3e6;", 3);
  std::vector<ControlNode> nodes(2);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(2);
  pore->addFracturePressure(nodes, {"crack"}, 0.0, p);
  CHECK(p[0] == 3e6);
  CHECK(p[1] == 3e6);
  const std::string values =
      errorOf("type fracturePressure; fracture crack; values \"constant/p.dat\";", 3);
  CHECK(values.rfind("constant/effects:1: key 'values': a values file gives p along the "
                     "arclength s of a fracture curve",
                     0) == 0);
}

TEST_CASE("3D effects: wrong counts are errors naming the key and the 3D form",
          "[effect][effect3d]") {
  struct Bad {
    const char* text;
    const char* message;
  };
  for (const Bad& b : {
           Bad{"type bodyForce; density 1; g (0 -9.81);",
               "key 'g': expected (gx gy gz) [m/s2] on a 3D mesh, got 2 numbers"},
           Bad{"type initialStress; stress (1 2 3);",
               "key 'stress': expected (sxx syy szz sxy syz sxz) [Pa] on a 3D mesh, got 3 "
               "numbers"},
           Bad{"type initialStress; stress (1 2 3 4 5 6); gradient (1 2 3);",
               "key 'gradient': expected (dsxx/dz dsyy/dz dszz/dz dsxy/dz dsyz/dz dsxz/dz) "
               "[Pa/m] on a 3D mesh, got 3 numbers"},
       }) {
    CAPTURE(b.text);
    const std::string message = errorOf(b.text, 3);
    CHECK(message.find(b.message) != std::string::npos);
    CHECK(message.rfind("constant/effects:1:", 0) == 0);
  }
  // And the 2D forms in 2D, as before.
  CHECK(errorOf("type initialStress; stress (1 2 3 4 5 6);", 2)
            .find("key 'stress': expected (sxx syy sxy) [Pa]") != std::string::npos);
}
