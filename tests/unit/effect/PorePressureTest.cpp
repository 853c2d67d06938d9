// porePressure (PorePressure.hpp): the rock's pore pressure through a Biot coefficient.
//  * The laterally confined layer (docs/method.md §11): rollers on the sides and the bottom,
//    the top free (its load fixed: the change adds no traction there), a uniform Δp_b: the
//    total stress changes by Δσ_xx = Δσ_yy = −α_B Δp_b (1 − 2ν)/(1 − ν), Δσ_zz = 0 in 3D, and
//    the same in 2D plane strain (σ_zz as σ_xx there, ε_zz = 0); plane stress −α_B Δp_b
//    (1 − 2ν). P1 and P2 through the effect's load and stress offset.
//  * A change on one region loads that region's cells only.
//  * The fracture pressure: p_b0 + Δp_b at the nodes of fractures without a pressure of their
//    own, Δp_b of a region weighted by the measure of its cells around the node.
//  * Bad keys are InputErrors naming them.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "../fe/FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

const std::vector<std::string> kNoFractures;

std::unique_ptr<Effect> effect(const std::string& text, int dim,
                               const std::vector<std::string>& fractures = kNoFractures) {
  const Dictionary d = Dictionary::parse(text, "constant/effects");
  auto e = Effect::New("rock", d, fractures, ".", dim);
  d.checkAllRead();
  return e;
}

/// The message of the InputError the effect's dictionary (and setMesh, on `mesh`) raises.
std::string errorOf(const std::string& text, const Mesh* mesh = nullptr) {
  try {
    auto e = effect(text, 2);
    if (mesh) e->setMesh(*mesh);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// The confined layer on the unit square (2D) or cube (3D), distorted: rollers on the sides
/// and the bottom, the top free; returns the worst deviation of the cells' total stress from
/// the exact change (σ_xx, σ_yy, σ_zz as `exact`, shears 0) [Pa], and the top's u_v.
struct Confined {
  double worst = 0, topLift = 0;
  int cells = 0;
};
Confined confinedLayer(int dim, int degree, const Material& material, const std::string& text,
                       const Eigen::Vector3d& exact) {
  SplitMesh split;
  split.mesh = dim == 2 ? test::unitSquareMesh(4, 0.3) : test::unitCubeMesh(3, 0.3);
  const LagrangeSpace V(split.mesh, degree);
  const ElasticityAssembler a(V, material);
  auto e = effect(text, dim);
  std::ostringstream log;
  const std::vector<ControlNode> nodes;
  e->bind(EffectContext{split, nodes, kNoFractures, log, &a});
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  e->addLoad(a, 1.0, F);

  DirichletConditions bc(V);
  if (dim == 2) {  // labels 1..4 = bottom, right, top, left
    REQUIRE(bc.fixPatch(1, FixedComponents::y) > 0);
    REQUIRE(bc.fixPatch(2, FixedComponents::x) > 0);
    REQUIRE(bc.fixPatch(4, FixedComponents::x) > 0);
  } else {  // labels 1..6 = x0, x1, y0, y1, z0, z1
    for (int label : {1, 2}) REQUIRE(bc.fixPatch(label, FixedComponents::x) > 0);
    for (int label : {3, 4}) REQUIRE(bc.fixPatch(label, FixedComponents::y) > 0);
    REQUIRE(bc.fixPatch(5, FixedComponents::z) > 0);
  }
  const ReducedSystem reduced(a.stiffness(), bc);
  SparseFactor factor("cholmod");
  REQUIRE(factor.factor(reduced.matrix()) == FactorStatus::ok);
  const Eigen::VectorXd u = reduced.expand(factor.solve(reduced.rhs(F, bc)), bc);

  Confined result;
  const int vertical = dim - 1;
  for (Index n = 0; n < V.numNodes(); ++n)
    if (V.point(n)[vertical] == 1.0) result.topLift = u[V.dof(n, vertical)];
  for (Index c = 0; c < V.numCells(); ++c) {
    Point centroid = Point::Zero();
    for (Index v : split.mesh.cell(c)) centroid += split.mesh.points[v] / (dim + 1);
    const Eigen::Matrix3d s = a.stress(u, c, centroid) + e->stressOffset(c, centroid, 1.0);
    Eigen::Matrix3d expected = exact.asDiagonal();
    result.worst = std::max(result.worst, (s - expected).cwiseAbs().maxCoeff());
    ++result.cells;
  }
  return result;
}

}  // namespace

TEST_CASE("porePressure: the laterally confined layer, 3D and 2D, P1 and P2",
          "[effect][porePressure]") {
  // Δp_b = 2e6 Pa with α_B = 0.8; E = 10 GPa, ν = 0.25: Δσ_xx = Δσ_yy = −0.8 · 2e6 · 2/3.
  // The exact displacement is linear (u_v = α_B Δp_b/(λ + 2μ) · v, the rest 0; plane stress:
  // α_B Δp_b / (2(λ + μ)) · y), so P1 and P2 hold it and the load is integrated exactly: what
  // remains is the direct solve's round-off, eps · cond(K) ≲ 1e-13 of the stress on these
  // meshes; 1e-9 · α_B Δp_b leaves a wide margin and is far below a wrong sign (2 α_B Δp_b), a
  // missing stress offset (α_B Δp_b) or the plane-stress factor left out (α_B Δp_b / 3).
  const double alpha = 0.8, dp = 2e6, E = 10e9, nu = 0.25;
  const double lateral = -alpha * dp * (1 - 2 * nu) / (1 - nu);
  const std::string text = "type porePressure; biotCoefficient 0.8; change table ((0 0) (2 4e6));";
  const Material strain = Material::fromYoungPoisson(E, nu);
  const double constrained = strain.lambda() + 2 * strain.mu();
  for (int degree : {1, 2}) {
    DYNAMIC_SECTION("P" << degree) {
      const Confined c3 = confinedLayer(3, degree, strain, text, {lateral, lateral, 0});
      CHECK(c3.cells > 100);
      CHECK(c3.worst <= 1e-9 * alpha * dp);
      // A positive change lifts the free top: the pressure expands the rock.
      CHECK(c3.topLift == Approx(alpha * dp / constrained).epsilon(1e-9));
      // Plane strain: σ_zz = λ ε_yy − α_B Δp_b = the lateral value too.
      const Confined c2 = confinedLayer(2, degree, strain, text, {lateral, 0, lateral});
      CHECK(c2.cells > 20);
      CHECK(c2.worst <= 1e-9 * alpha * dp);
      CHECK(c2.topLift == Approx(alpha * dp / constrained).epsilon(1e-9));
      // Plane stress (σ_zz = 0): ε_xx = 0, σ_yy = σ_zz = 0 give σ_xx = −α_B Δp_b (1 − 2ν).
      const Material plate = Material::fromYoungPoisson(E, nu, true);
      const Confined ps = confinedLayer(2, degree, plate, text, {-alpha * dp * (1 - 2 * nu), 0, 0});
      CHECK(ps.worst <= 1e-9 * alpha * dp);
      CHECK(ps.topLift == Approx(alpha * dp / (2 * (plate.lambda() + plate.mu()))).epsilon(1e-9));
    }
  }
}

TEST_CASE("porePressure: a change on one region loads that region's cells only",
          "[effect][porePressure]") {
  // The unit square in two regions, 'reservoir' (1) below y = 1/2 and 'caprock' (2) above.
  SplitMesh split;
  split.mesh = test::unitSquareMesh(6, 0.3);
  Mesh& m = split.mesh;
  for (Index c = 0; c < m.numCells(); ++c) {
    double y = 0;
    for (Index v : m.cell(c)) y += m.points[v].y() / 3;
    m.cellRegion[static_cast<std::size_t>(c)] = y < 0.5 ? 1 : 2;
  }
  m.regionNames = {{1, "reservoir"}, {2, "caprock"}};
  const LagrangeSpace V(m, 2);
  const ElasticityAssembler a(V, Material::fromYoungPoisson(10e9, 0.25));
  auto e =
      effect("type porePressure; biotCoefficient 0.5; regions { reservoir { change -4e6; } }", 2);
  e->setMesh(m);
  std::ostringstream log;
  const std::vector<ControlNode> nodes;
  e->bind(EffectContext{split, nodes, kNoFractures, log, &a});
  Eigen::VectorXd F = Eigen::VectorXd::Zero(V.numDofs());
  e->addLoad(a, 0.0, F);
  // The ∫ over the reservoir's cells, and nothing at the nodes of caprock cells only.
  const double alphaDp = 0.5 * -4e6;
  const Eigen::VectorXd expected = a.pressureLoad([&](Index c, const Point&) {
    return m.cellRegion[static_cast<std::size_t>(c)] == 1 ? alphaDp : 0.0;
  });
  CHECK((F - expected).norm() <= 1e-14 * expected.norm());
  CHECK(expected.norm() > 0);
  std::vector<char> inReservoir(static_cast<std::size_t>(V.numNodes()), 0);
  for (Index c = 0; c < V.numCells(); ++c)
    if (m.cellRegion[static_cast<std::size_t>(c)] == 1)
      for (Index n : V.cellNodes(c)) inReservoir[static_cast<std::size_t>(n)] = 1;
  int outside = 0;
  for (Index n = 0; n < V.numNodes(); ++n)
    if (!inReservoir[static_cast<std::size_t>(n)]) {
      ++outside;
      CHECK(F[V.dof(n, 0)] == 0.0);
      CHECK(F[V.dof(n, 1)] == 0.0);
    }
  CHECK(outside > 20);
  // Its virtual work against v = x: α_B Δp_b · 2 · |Ω_reservoir|.
  double area = 0, work = 0;
  for (Index c = 0; c < m.numCells(); ++c)
    if (m.cellRegion[static_cast<std::size_t>(c)] == 1) area += std::abs(m.signedMeasure(c));
  for (Index n = 0; n < V.numNodes(); ++n)
    work += F[V.dof(n, 0)] * V.point(n).x() + F[V.dof(n, 1)] * V.point(n).y();
  CHECK(work == Approx(alphaDp * 2 * area).epsilon(1e-12));
  // The written stress changes in the reservoir only.
  for (Index c = 0; c < m.numCells(); ++c) {
    const Eigen::Matrix3d s = e->stressOffset(c, Point::Zero(), 0.0);
    CHECK(s(0, 0) == (m.cellRegion[static_cast<std::size_t>(c)] == 1 ? -alphaDp : 0.0));
  }
}

TEST_CASE("porePressure: fractures without a pressure of their own take p_b0 + dp_b",
          "[effect][porePressure]") {
  // Two unit-width halves split along y = 1/2 (FeTestMeshes.hpp): the top half (cells 2, 3) is
  // region 1, the bottom half (cells 0, 1) region 2. Control nodes at (0, ½) (copies 2 and 6)
  // and (1, ½) (copies 3 and 7) of fracture 'fault', and one of 'other' with a pressure of its
  // own. Each triangle has area 1/4. Around (0, ½): both top cells and one bottom cell, so
  // region 1 weighs 2/3; around (1, ½): one top cell and both bottom cells, 1/3.
  SplitMesh split;
  split.mesh = test::splitFourTriangleMesh();
  const LagrangeSpace V(split.mesh, 1);
  const ElasticityAssembler a(V, Material::fromYoungPoisson(10e9, 0.25));
  const std::vector<std::string> fractures = {"fault", "other"};
  auto e = effect(
      "type porePressure; biotCoefficient 0.7; initial { type depth; value 1e6; gradient -1e4; "
      "} change table ((0 0) (1 3e5)); regions { region1 { change table ((0 0) (1 -6e5)); } }",
      2, fractures);
  std::vector<ControlNode> nodes(3);
  nodes[0].plus = 2, nodes[0].minus = 6, nodes[0].position = Point(0, 0.5, 0);
  nodes[1].plus = 3, nodes[1].minus = 7, nodes[1].position = Point(1, 0.5, 0);
  nodes[2].plus = nodes[2].minus = 0, nodes[2].fracture = 1;
  std::ostringstream log;
  e->bind(EffectContext{split, nodes, fractures, log, &a, {0, 1}});
  Eigen::VectorXd p = Eigen::VectorXd::Zero(3);
  e->addFracturePressure(nodes, fractures, 0.5, p);
  const double p0 = 1e6 - 1e4 * 0.5, everywhere = 1.5e5, region1 = -3e5;
  CHECK(p[0] == Approx(p0 + everywhere + 2.0 / 3 * region1).epsilon(1e-14));
  CHECK(p[1] == Approx(p0 + everywhere + 1.0 / 3 * region1).epsilon(1e-14));
  CHECK(p[2] == 0);  // 'other' keeps its own pressure
  CHECK(e->givesFracturePressure());
  CHECK_THAT(log.str(), Catch::Contains("Fracture other: a fluid pressure of its own, not the "
                                        "rock's pore pressure (rock)"));
  CHECK_THAT(log.str(),
             Catch::Contains("Fracture fault: initial pore pressure of the rock (rock) from min "
                             "995000 to max 995000 Pa over 2 nodes"));
  CHECK(e->describe() ==
        "biotCoefficient 0.7, initial p_b depth: 1e+06 at y = 0 m, gradient -10000 per m, "
        "everywhere a change in time (table), in region region1 a change in time (table); one "
        "way (the pressure is given); the fractures without a pressure of their own take p_b");
}

TEST_CASE("porePressure: bad keys are InputErrors naming them", "[effect][porePressure]") {
  Mesh layered = test::unitSquareMesh(2);
  layered.cellRegion.assign(layered.cellRegion.size(), 1);
  layered.cellRegion[0] = 2;
  layered.regionNames = {{1, "reservoir"}, {2, "caprock"}};
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1.5;"),
             Catch::Contains("biotCoefficient") && Catch::Contains("[0, 1]"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient -0.1;"),
             Catch::Contains("biotCoefficient"));
  CHECK_THAT(errorOf("type porePressure;"), Catch::Contains("biotCoefficient"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; initial { type arclength; table "
                     "((0 1) (1 2)); }"),
             Catch::Contains("key 'type': the rock's pore pressure is a field of the body"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; regions 3;"),
             Catch::Contains("key 'regions': expected a sub-dictionary"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; regions { reservoir 3; }"),
             Catch::Contains("key 'reservoir': expected a sub-dictionary with the region's "
                             "change"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; regions { reservoir { } }"),
             Catch::Contains("change"));
  CHECK_THAT(
      errorOf("type porePressure; biotCoefficient 1; regions { reservoi { change 1; } }", &layered),
      Catch::Contains("'reservoi' is no region of the mesh unitSquare2") &&
          Catch::Contains("reservoir") &&
          Catch::Contains("(regions: reservoir (region1), caprock (region2); an entry is a "
                          "region's name or region<number>)"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; regions { reservoir { change 1; } "
                     "region1 { change 2; } }",
                     &layered),
             Catch::Contains("region 1 has two entries, 'reservoir' and 'region1'"));
  CHECK(errorOf("type porePressure; biotCoefficient 1; regions { region2 { change 1; } }",
                &layered) == "(no InputError)");
}
