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
//  * `data`: Δp_b at points at listed times gives the answers of `change` and `regions` when it
//    holds their values; far and malformed rows are refused naming the file and line.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "../dict/DictTestSupport.hpp"
#include "../fe/FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/effect/GivenField.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/linalg/SparseFactor.hpp"

using namespace friction;

namespace {

const std::vector<std::string> kNoFractures;

std::unique_ptr<Effect> effect(const std::string& text, int dim,
                               const std::vector<std::string>& fractures = kNoFractures,
                               const std::string& caseDir = ".") {
  const Dictionary d = Dictionary::parse(text, "constant/effects");
  auto e = Effect::New("rock", d, fractures, caseDir, dim);
  d.checkAllRead();
  return e;
}

/// The message of the InputError the effect's dictionary (and setMesh, on `mesh`) raises.
std::string errorOf(const std::string& text, const Mesh* mesh = nullptr,
                    const std::string& caseDir = ".") {
  try {
    auto e = effect(text, 2, kNoFractures, caseDir);
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
                       const Eigen::Vector3d& exact, const std::string& caseDir = ".") {
  SplitMesh split;
  split.mesh = dim == 2 ? test::unitSquareMesh(4, 0.3) : test::unitCubeMesh(3, 0.3);
  const LagrangeSpace V(split.mesh, degree);
  const ElasticityAssembler a(V, material);
  auto e = effect(text, dim, kNoFractures, caseDir);
  e->setMesh(split.mesh);
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

/// Rows "t x y [z] p" of a uniform value at each listed time, on a grid of 3 points per side
/// of the unit square or cube (corners included: inside the body).
std::string uniformRows(int dim, const std::vector<std::pair<double, double>>& table) {
  std::ostringstream s;
  s << "# t x y" << (dim == 3 ? " z" : "") << " p\n";
  for (const auto& [t, p] : table)
    for (int i = 0; i < (dim == 3 ? 27 : 9); ++i) {
      s << t << " " << (i % 3) * 0.5 << " " << (i / 3 % 3) * 0.5;
      if (dim == 3) s << " " << (i / 9) * 0.5;
      s << " " << p << "\n";
    }
  return s.str();
}

Point centroidOf(const Mesh& m, Index c) {
  Point x = Point::Zero();
  for (Index v : m.cell(c)) x += m.points[static_cast<std::size_t>(v)] / (m.dim + 1);
  return x;
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

TEST_CASE("porePressure: data giving a uniform change at listed times is the change's table",
          "[effect][porePressure]") {
  // The same table as `change` (three times; t = 1 lies between the first two): the cells all
  // take the listed values, so the loads and stress offsets are those of `change` up to the
  // round-off of scaling the load before or after the assembly (a few ulp of each entry), and
  // the confined layer meets its known answer as closely as with `change` (see above).
  dicttest::TempDir dir;
  const std::vector<std::pair<double, double>> table = {{0, 0}, {2, 4e6}, {4, -1e6}};
  dir.write("constant/p2.dat", uniformRows(2, table));
  dir.write("constant/p3.dat", uniformRows(3, table));
  const std::string change =
      "type porePressure; biotCoefficient 0.8; change table ((0 0) (2 4e6) (4 -1e6));";
  const double alpha = 0.8, dp = 2e6, nu = 0.25;
  const double lateral = -alpha * dp * (1 - 2 * nu) / (1 - nu);
  const Material strain = Material::fromYoungPoisson(10e9, nu);
  for (int dim : {2, 3}) {
    const std::string data = "type porePressure; biotCoefficient 0.8; data \"constant/p" +
                             std::to_string(dim) + ".dat\";";
    SplitMesh split;
    split.mesh = dim == 2 ? test::unitSquareMesh(4, 0.3) : test::unitCubeMesh(3, 0.3);
    const LagrangeSpace V(split.mesh, 2);
    const ElasticityAssembler a(V, strain);
    auto byChange = effect(change, dim);
    auto byData = effect(data, dim, kNoFractures, dir.path().string());
    CHECK(byData->givesStressOffset());
    CHECK_THAT(byData->describe(),
               Catch::Contains("data from " + (dir.path() / "constant").string() + "/p" +
                               std::to_string(dim) + ".dat at 3 times"));
    std::ostringstream log;
    const std::vector<ControlNode> nodes;
    for (auto* e : {byChange.get(), byData.get()}) {
      e->setMesh(split.mesh);
      e->bind(EffectContext{split, nodes, kNoFractures, log, &a});
    }
    for (double t : {-1.0, 1.0, 3.0, 9.0}) {
      Eigen::VectorXd Fc = Eigen::VectorXd::Zero(V.numDofs()), Fd = Fc;
      byChange->addLoad(a, t, Fc);
      byData->addLoad(a, t, Fd);
      CHECK((Fd - Fc).norm() <= 1e-14 * std::max(Fc.norm(), 1.0));
      double worst = 0;
      for (Index c = 0; c < V.numCells(); ++c)
        worst = std::max(worst, (byData->stressOffset(c, Point::Zero(), t) -
                                 byChange->stressOffset(c, Point::Zero(), t))
                                    .cwiseAbs()
                                    .maxCoeff());
      CHECK(worst <= 1e-14 * 4e6);
    }
    const Confined c =
        dim == 3 ? confinedLayer(3, 1, strain, data, {lateral, lateral, 0}, dir.path().string())
                 : confinedLayer(2, 1, strain, data, {lateral, 0, lateral}, dir.path().string());
    CHECK(c.cells > 20);
    CHECK(c.worst <= 1e-9 * alpha * dp);
  }
}

TEST_CASE("porePressure: data that differ per region give the regions' answer, added to change",
          "[effect][porePressure]") {
  dicttest::TempDir dir;
  SECTION("loads and stresses") {
    // The two-region square of above; one row per cell at its centroid (a reservoir
    // simulator's cell-centred export), −4e6 in the reservoir, 0 in the caprock, from t = 1.
    SplitMesh split;
    split.mesh = test::unitSquareMesh(6, 0.3);
    Mesh& m = split.mesh;
    for (Index c = 0; c < m.numCells(); ++c)
      m.cellRegion[static_cast<std::size_t>(c)] = centroidOf(m, c).y() < 0.5 ? 1 : 2;
    m.regionNames = {{1, "reservoir"}, {2, "caprock"}};
    std::ostringstream rows;
    rows.precision(17);
    for (double t : {0.0, 1.0})
      for (Index c = m.numCells() - 1; c >= 0; --c) {  // any order within a time
        const Point x = centroidOf(m, c);
        const bool reservoir = m.cellRegion[static_cast<std::size_t>(c)] == 1;
        rows << t << " " << x.x() << " " << x.y() << " " << (reservoir ? -4e6 * t : 0.0) << "\n";
      }
    dir.write("p.dat", rows.str());
    const LagrangeSpace V(m, 2);
    const ElasticityAssembler a(V, Material::fromYoungPoisson(10e9, 0.25));
    auto byRegions = effect(
        "type porePressure; biotCoefficient 0.5; regions { reservoir { change table ((0 0) (1 "
        "-4e6)); } }",
        2);
    auto byData = effect("type porePressure; biotCoefficient 0.5; data \"p.dat\";", 2, kNoFractures,
                         dir.path().string());
    std::ostringstream log;
    const std::vector<ControlNode> nodes;
    for (auto* e : {byRegions.get(), byData.get()}) {
      e->setMesh(m);
      e->bind(EffectContext{split, nodes, kNoFractures, log, &a});
    }
    for (double t : {0.25, 2.0}) {
      Eigen::VectorXd Fr = Eigen::VectorXd::Zero(V.numDofs()), Fd = Fr;
      byRegions->addLoad(a, t, Fr);
      byData->addLoad(a, t, Fd);
      CHECK(Fr.norm() > 0);
      CHECK((Fd - Fr).norm() <= 1e-14 * Fr.norm());
      for (Index c = 0; c < m.numCells(); ++c)
        CHECK(byData->stressOffset(c, Point::Zero(), t)(0, 0) ==
              Approx(byRegions->stressOffset(c, Point::Zero(), t)(0, 0)).margin(1e-14 * 4e6));
    }
  }
  SECTION("fracture pressure") {
    // The split four-triangle mesh of the fracture test above: region 1 (cells 2, 3) changes by
    // −6e5 at t = 1, given per cell; both effects add 3e5 everywhere.
    SplitMesh split;
    split.mesh = test::splitFourTriangleMesh();
    std::ostringstream rows;
    rows.precision(17);
    for (double t : {0.0, 1.0})
      for (Index c = 0; c < split.mesh.numCells(); ++c) {
        const Point x = centroidOf(split.mesh, c);
        const bool region1 = split.mesh.cellRegion[static_cast<std::size_t>(c)] == 1;
        rows << t << " " << x.x() << " " << x.y() << " " << (region1 ? -6e5 * t : 0.0) << "\n";
      }
    dir.write("p.dat", rows.str());
    const LagrangeSpace V(split.mesh, 1);
    const ElasticityAssembler a(V, Material::fromYoungPoisson(10e9, 0.25));
    const std::vector<std::string> fractures = {"fault"};
    const std::string common =
        "type porePressure; biotCoefficient 0.7; initial 1e6; change "
        "table ((0 0) (1 3e5)); ";
    auto byRegions =
        effect(common + "regions { region1 { change table ((0 0) (1 -6e5)); } }", 2, fractures);
    auto byData = effect(common + "data \"p.dat\";", 2, fractures, dir.path().string());
    std::vector<ControlNode> nodes(2);
    nodes[0].plus = 2, nodes[0].minus = 6, nodes[0].position = Point(0, 0.5, 0);
    nodes[1].plus = 3, nodes[1].minus = 7, nodes[1].position = Point(1, 0.5, 0);
    std::ostringstream log;
    Eigen::VectorXd pr = Eigen::VectorXd::Zero(2), pd = pr;
    byRegions->bind(EffectContext{split, nodes, fractures, log, &a, {0}});
    byData->bind(EffectContext{split, nodes, fractures, log, &a, {0}});
    byRegions->addFracturePressure(nodes, fractures, 0.5, pr);
    byData->addFracturePressure(nodes, fractures, 0.5, pd);
    // Region 1 weighs 2/3 at (0, ½) and 1/3 at (1, ½) (the fracture test above).
    CHECK(pr[0] == Approx(1e6 + 1.5e5 - 2.0 / 3 * 3e5).epsilon(1e-14));
    CHECK(pd[0] == Approx(pr[0]).epsilon(1e-14));
    CHECK(pd[1] == Approx(pr[1]).epsilon(1e-14));
    CHECK(pd[1] != Approx(pd[0]));
  }
}

TEST_CASE("porePressure: data rows outside the body or malformed are refused naming the line",
          "[effect][porePressure]") {
  dicttest::TempDir dir;
  const Mesh square = test::unitSquareMesh(4);  // cells of diameter √2/4 ≈ 0.354 m
  const std::string file = (dir.path() / "p.dat").string();
  const std::string key = "type porePressure; biotCoefficient 1; data \"p.dat\";";
  const auto errorFor = [&](const std::string& rows, const std::string& extra = "") {
    dir.write("p.dat", rows);
    return errorOf(key + extra, &square, dir.path().string());
  };
  // Inside, and on the boundary: accepted.
  CHECK(errorFor("0 0 0 1\n0 1 1 2\n1 0.5 0.5 3\n") == "(no InputError)");
  // 3 m above the square (the wrong unit or origin): refused at its line, by default and
  // within an explicit maxDistance; a larger maxDistance lets it pass.
  const std::string far = "0 0.5 0.5 1\n# a comment\n0 0.5 3 2\n";
  CHECK_THAT(errorFor(far), Catch::StartsWith(file + ":3: the point (0.5 3 0) is ") &&
                                Catch::Contains("m from the nearest cell centroid") &&
                                Catch::Contains("data rows must lie in the body") &&
                                Catch::Contains("default: the mesh's largest cell diameter"));
  CHECK_THAT(errorFor(far, " maxDistance 1;"),
             Catch::StartsWith(file + ":3:") && Catch::Contains("within maxDistance 1 m"));
  CHECK(errorFor(far, " maxDistance 5;") == "(no InputError)");
  // Malformed rows.
  CHECK_THAT(errorFor("0 0.5 0.5 1\n0 0.5 0.5\n"),
             Catch::StartsWith(file + ":2: expected four numbers 't x y p' (time [s], position "
                                      "[m], pressure change [Pa]), got '0 0.5 0.5' (3 items)"));
  CHECK_THAT(errorFor("0 0.5 0.5 1\n1 0.5 abc 1\n"),
             Catch::StartsWith(file + ":2: expected four numbers") &&
                 Catch::Contains("'abc' is not a number"));
  CHECK_THAT(errorFor("1 0.5 0.5 1\n0 0.5 0.5 1\n"),
             Catch::StartsWith(file + ":2: time 0 before the previous row's 1"));
  CHECK_THAT(errorFor("# nothing\n"), Catch::StartsWith(file + ": no rows"));
  // A missing file: at the key.
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1;\ndata \"none.dat\";", &square,
                     dir.path().string()),
             Catch::StartsWith("constant/effects:2") && Catch::Contains("none.dat"));
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; maxDistance 1;"),
             Catch::Contains("maxDistance"));
}

TEST_CASE(
    "porePressure: data script takes the caller's field, a uniform one gives the change's table",
    "[effect][porePressure][givenField]") {
  // The FreeFEM plug-in's pressure = P, pressureTimes = T (GivenField.hpp): Δp_b per vertex at
  // listed times, each cell the mean of its vertices'. A uniform field holding the table's
  // values gives the loads and stress offsets of `change` up to the round-off of scaling the
  // load before or after the assembly (as `data` above), at, between and beyond the times.
  const std::string change =
      "type porePressure; biotCoefficient 0.8; change table ((0 0) (2 4e6) (4 -1e6));";
  const std::string script = "type porePressure; biotCoefficient 0.8; data script;";
  const Material strain = Material::fromYoungPoisson(10e9, 0.25);
  for (int dim : {2, 3}) {
    SplitMesh split;
    split.mesh = dim == 2 ? test::unitSquareMesh(4, 0.3) : test::unitCubeMesh(3, 0.3);
    const LagrangeSpace V(split.mesh, 2);
    const ElasticityAssembler a(V, strain);
    auto byChange = effect(change, dim);
    auto byScript = effect(script, dim);
    CHECK(byScript->givesStressOffset());
    byScript->setMesh(split.mesh);
    // No field given (frictionSolver on the command line): refused naming the key.
    try {
      byScript->takeGivenFields({}, split.mesh);
      FAIL("no InputError");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::StartsWith("constant/effects:1: key 'data': 'script' says the "
                                             "program running the case gives") &&
                               Catch::Contains("frictionSolve(\"case\", pressure = P"));
    }
    GivenField f;
    f.caller = "frictionSolve";
    f.name = "pressure";
    f.timesName = "pressureTimes";
    f.times = {0, 2, 4};
    f.values.resize(split.mesh.numPoints(), 3);
    f.values.col(0).setConstant(0);
    f.values.col(1).setConstant(4e6);
    f.values.col(2).setConstant(-1e6);
    CHECK(byScript->takeGivenFields({{kPorePressureChange, f}}, split.mesh) ==
          std::vector<std::string>{kPorePressureChange});
    CHECK_THAT(byScript->describe(),
               Catch::Contains("data from frictionSolve's pressure at 3 times"));
    std::ostringstream log;
    const std::vector<ControlNode> nodes;
    byChange->setMesh(split.mesh);
    for (auto* e : {byChange.get(), byScript.get()})
      e->bind(EffectContext{split, nodes, kNoFractures, log, &a});
    for (double t : {-1.0, 1.0, 2.0, 3.0, 9.0}) {
      Eigen::VectorXd Fc = Eigen::VectorXd::Zero(V.numDofs()), Fs = Fc;
      byChange->addLoad(a, t, Fc);
      byScript->addLoad(a, t, Fs);
      if (t > 0) CHECK(Fc.norm() > 0);  // (before the first time: nothing, in both)
      CHECK((Fs - Fc).norm() <= 1e-14 * Fc.norm());
      double worst = 0;
      for (Index c = 0; c < V.numCells(); ++c)
        worst = std::max(worst, (byScript->stressOffset(c, Point::Zero(), t) -
                                 byChange->stressOffset(c, Point::Zero(), t))
                                    .cwiseAbs()
                                    .maxCoeff());
      CHECK(worst <= 1e-14 * 4e6);
    }
  }
  CHECK_THAT(errorOf(script + " maxDistance 1;"),
             Catch::Contains("key 'maxDistance': applies to a data file only"));
  // A file named script: in quotes.
  CHECK_THAT(errorOf("type porePressure; biotCoefficient 1; data \"script\";"),
             Catch::Contains("script") && !Catch::Contains("'script' says"));
}

TEST_CASE("GivenField: checks, the unsplit mesh's numbering, the mean over each cell",
          "[effect][givenField]") {
  GivenField f;
  f.caller = "frictionSolve";
  f.name = "pressure";
  f.timesName = "pressureTimes";
  const auto error = [&f] {
    try {
      f.check();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no InputError)");
  };
  CHECK(error() ==
        "pressureTimes: expected at least one time [s] (one per column of pressure), "
        "got none");
  f.times = {0, 1, 1};
  f.values = Eigen::MatrixXd::Zero(4, 3);
  CHECK(error() ==
        "pressureTimes: entry 2 (1) does not follow entry 1 (1); expected times [s] "
        "strictly increasing");
  f.times = {0, 1};
  CHECK(error() == "pressure: expected one column per time of pressureTimes (2), got 3 columns");
  f.values = Eigen::MatrixXd::Zero(4, 2);
  f.values(3, 1) = std::nan("");
  CHECK(error() == "pressure: row 3, column 1 is nan; expected finite values");
  f.values(3, 1) = 0;
  CHECK(error() == "(no InputError)");

  // A square of two triangles whose vertex 2 has a copy (split mesh vertex 4).
  SplitMesh split;
  split.mesh = test::unitSquareMesh(1);
  REQUIRE(split.mesh.numPoints() == 4);
  REQUIRE(split.mesh.numCells() == 2);
  split.mesh.points.push_back(split.mesh.points[2]);
  split.origin = {0, 1, 2, 3, 2};
  for (Index& v : split.mesh.cellVertices)
    if (v == 2) {
      v = 4;  // the first cell with vertex 2 takes its copy
      break;
    }
  f.values.col(1) << 1, 2, 3, 4;
  const GivenField g = f.onSplitMesh(split);
  REQUIRE(g.values.rows() == 5);
  CHECK(g.values(4, 1) == 3);
  CHECK(g.values.topRows(4) == f.values);
  // A row per split-mesh vertex is taken as it is; another count is refused naming both.
  CHECK(g.onSplitMesh(split).values == g.values);
  f.values.conservativeResize(3, 2);
  CHECK_THROWS_WITH(f.onSplitMesh(split),
                    "pressure: expected one row per vertex of the split mesh (5) or of the "
                    "unsplit mesh (4), got 3 rows");
  // The mean over each cell of its vertices' values: the mean of a linear function is its value
  // at the centroid; equal values give that value to the bit.
  const Mesh m = test::unitSquareMesh(3, 0.3);
  GivenField h = f;
  h.values.resize(m.numPoints(), 2);
  for (Index i = 0; i < m.numPoints(); ++i) {
    h.values(i, 0) = 0.1;
    h.values(i, 1) = 1 + 2 * m.points[i].x() - 3 * m.points[i].y();
  }
  const std::vector<Eigen::VectorXd> mean = h.cellMeans(m);
  REQUIRE(mean.size() == 2);
  for (Index c = 0; c < m.numCells(); ++c) {
    const Point x = centroidOf(m, c);
    CHECK(mean[0][c] == 0.1);
    CHECK(std::abs(mean[1][c] - (1 + 2 * x.x() - 3 * x.y())) <= 1e-15 * 4);
  }
}
