// MaterialMap (fe/MaterialMap.hpp): constant/mechanicalProperties per mesh region. The flat
// form is one material; the regions form gives each cell its region's material, keyed by the
// mesh's name or number, with 'default' for the rest; every mistake is an InputError with the
// line, the key and what was expected. And the assembler uses the cell's material.
#include <catch2/catch.hpp>
#include <string>

#include "FeTestMeshes.hpp"
#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fe/MaterialMap.hpp"

using namespace friction;

namespace {

/// The unit square 4 × 4, its lower half region 1 ("reservoir"), its upper half region 2
/// ("caprock"); with `third`, the top row region 3 (unnamed).
Mesh layeredSquare(bool third = false) {
  Mesh m = test::unitSquareMesh(4);
  for (Index c = 0; c < m.numCells(); ++c) {
    double y = 0;
    for (Index v : m.cell(c)) y += m.points[v].y() / 3;
    m.cellRegion[c] = y < 0.5 ? 1 : (third && y > 0.75 ? 3 : 2);
  }
  m.regionNames = {{1, "reservoir"}, {2, "caprock"}};
  return m;
}

std::string errorOf(const std::string& text, const Mesh& mesh) {
  try {
    MaterialMap::read(Dictionary::parse(text, "mech"), mesh);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("expected an InputError, none was thrown");
  return "";
}

}  // namespace

TEST_CASE("fe material map: the flat form is one material for every cell", "[fe][material]") {
  const Mesh mesh = layeredSquare();
  const MaterialMap map = MaterialMap::read(Dictionary::parse("E 2e9;\nnu 0.3;\n", "mech"), mesh);
  CHECK(map.uniform());
  CHECK(map.regions().empty());
  REQUIRE(map.materials().size() == 1);
  CHECK(map.ofCell(0).youngModulus() == Approx(2e9).epsilon(1e-14));
  CHECK(map.maxYoungModulus() == map.ofCell(0).youngModulus());
}

TEST_CASE("fe material map: regions by name, by number and default", "[fe][material]") {
  const Mesh mesh = layeredSquare(true);
  const Dictionary d = Dictionary::parse(
      "planeStress yes;\nregions\n{\n  reservoir { E 10e9; nu 0.25; }\n  region3 { lambda 2e9; "
      "mu 1e9; }\n  default { E 30e9; nu 0.3; }\n}\n",
      "mech");
  const MaterialMap map = MaterialMap::read(d, mesh);
  d.checkAllRead();
  CHECK_FALSE(map.uniform());
  CHECK(map.planeStress());
  REQUIRE(map.regions().size() == 3);
  Index total = 0;
  for (const auto& r : map.regions()) total += r.cells;
  CHECK(total == mesh.numCells());
  CHECK(map.regions()[0].name == "reservoir");
  CHECK(map.regions()[0].entry == "reservoir");
  CHECK(map.regions()[1].name == "caprock");
  CHECK(map.regions()[1].entry == "default");
  CHECK(map.regions()[2].number == 3);
  CHECK(map.regions()[2].entry == "region3");
  // Every cell has its region's material (all three regions hold cells).
  int seen[4] = {0, 0, 0, 0};
  for (Index c = 0; c < mesh.numCells(); ++c) {
    const int r = mesh.cellRegion[c];
    ++seen[r];
    const double e = map.ofCell(c).youngModulus();
    if (r == 1) CHECK(e == Approx(10e9).epsilon(1e-14));
    if (r == 2) CHECK(e == Approx(30e9).epsilon(1e-14));
    if (r == 3) CHECK(map.ofCell(c).mu() == 1e9);
    CHECK(map.ofCell(c).planeStress());
  }
  CHECK(seen[1] > 0);
  CHECK(seen[2] > 0);
  CHECK(seen[3] > 0);
  CHECK(map.maxYoungModulus() == Approx(30e9).epsilon(1e-14));
  // Among the reservoir's cells alone the largest E is the reservoir's.
  std::vector<Index> lower;
  for (Index c = 0; c < mesh.numCells(); ++c)
    if (mesh.cellRegion[c] == 1) lower.push_back(c);
  REQUIRE(!lower.empty());
  CHECK(map.maxYoungModulus(lower) == Approx(10e9).epsilon(1e-14));
}

TEST_CASE("fe material map: mistakes are InputErrors with line and key", "[fe][material]") {
  const Mesh mesh = layeredSquare();
  // An unknown name: a suggestion and the regions available.
  CHECK(errorOf("regions\n{\n  reservior { E 1e9; nu 0.2; }\n  caprock { E 1e9; nu 0.2; }\n}\n",
                mesh) ==
        "mech:3: 'reservior' is no region of the mesh unitSquare4; did you mean 'reservoir'? "
        "(regions: reservoir (region1), caprock (region2); an entry is a region's name, "
        "region<number>, or 'default')");
  // A region without a material: listed with its number and cells.
  CHECK(errorOf("regions\n{\n  reservoir { E 1e9; nu 0.2; }\n}\n", mesh) ==
        "mech:1: key 'regions': no material for 'caprock' (region 2, 16 triangles) (expected an "
        "entry for every region of the mesh unitSquare4, by name or as region<number>, or a "
        "'default' entry; regions: reservoir (region1), caprock (region2))");
  // The same region by name and by number.
  CHECK(errorOf("regions\n{\n  reservoir { E 1e9; nu 0.2; }\n  region1 { E 1e9; nu 0.2; }\n  "
                "default { E 1e9; nu 0.2; }\n}\n",
                mesh) ==
        "mech:4: region 'reservoir' (region 1, 16 triangles) has two entries, 'reservoir' and "
        "'region1' (expected one per region)");
  // Both forms.
  CHECK(errorOf("E 1e9;\nnu 0.2;\nregions { default { E 1e9; nu 0.2; } }\n", mesh) ==
        "mech:1: key 'E' together with 'regions': give the material once for the whole body (E, "
        "nu or lambda, mu or K, G here) or per region inside 'regions', not both");
  // planeStress inside a region.
  CHECK(errorOf("regions\n{\n  default\n  {\n    E 1e9;\n    nu 0.2;\n    planeStress yes;\n  "
                "}\n}\n",
                mesh) ==
        "mech:7: key 'planeStress' is one setting for the whole body: put it beside 'regions' (in "
        "mech), not inside a region's entry");
  // A bad value: the region's line and key.
  const std::string bad = errorOf("regions\n{\n  default { E 1e9; nu 0.6; }\n}\n", mesh);
  CHECK_THAT(bad, Catch::StartsWith("mech:3:"));
  CHECK_THAT(bad, Catch::Contains("'nu'"));
  const std::string negative = errorOf("regions\n{\n  default { E -1e9; nu 0.2; }\n}\n", mesh);
  CHECK_THAT(negative, Catch::StartsWith("mech:3:"));
  CHECK_THAT(negative, Catch::Contains("'E'"));
  // Not a sub-dictionary.
  CHECK_THAT(errorOf("regions 3;\n", mesh),
             Catch::StartsWith("mech:1: key 'regions': expected a sub-dictionary"));
  CHECK_THAT(errorOf("regions { reservoir 3; }\n", mesh),
             Catch::StartsWith("mech:1: key 'reservoir': expected a sub-dictionary"));
  // A mesh without names (a split mesh of one region keeps none): the way out.
  Mesh unnamed = mesh;
  unnamed.regionNames.clear();
  CHECK_THAT(
      errorOf("regions { reservoir { E 1e9; nu 0.2; } default { E 1e9; nu 0.2; } }\n", unnamed),
      Catch::EndsWith("the mesh names no region (a split mesh keeps the names only when "
                      "its cells lie in several regions): use region<number>)"));
  // A number that no cell carries.
  CHECK_THAT(errorOf("regions { region7 { E 1e9; nu 0.2; } default { E 1e9; nu 0.2; } }\n", mesh),
             Catch::StartsWith("mech:1: 'region7' is no region of the mesh"));
}

TEST_CASE("fe material map: equal constants per region give the one-material stiffness",
          "[fe][material][stiffness]") {
  const Mesh mesh = layeredSquare();
  for (int degree : {1, 2}) {
    CAPTURE(degree);
    const LagrangeSpace V(mesh, degree);
    const Material one = Material::fromYoungPoisson(5e9, 0.27);
    const Dictionary d = Dictionary::parse(
        "regions { reservoir { E 5e9; nu 0.27; } caprock { E 5e9; nu 0.27; } }", "mech");
    const ElasticityAssembler a(V, one), b(V, MaterialMap::read(d, mesh));
    const Eigen::SparseMatrix<double> ka = a.stiffness(), kb = b.stiffness();
    REQUIRE(ka.nonZeros() > 0);
    // The same λ, μ per cell through the same arithmetic: the same bits.
    CHECK((ka - kb).norm() == 0.0);
  }
}

TEST_CASE("fe material map: stiffness and stress take each cell's material",
          "[fe][material][stiffness]") {
  // K is linear in the material per cell: K(E1 below, E2 above) = K(E1 everywhere) restricted
  // below + K(E2 everywhere) restricted above, i.e. with the same ν, K(E1, E2) = K_lower E1/E
  // + K_upper E2/E. Check through energies of a fixed displacement, and stresses per cell.
  const Mesh mesh = layeredSquare();
  const LagrangeSpace V(mesh, 1);
  const Dictionary d = Dictionary::parse(
      "regions { reservoir { E 1e9; nu 0.25; } caprock { E 1e13; nu 0.25; } }", "mech");
  const ElasticityAssembler layered(V, MaterialMap::read(d, mesh));
  // Uniform strain ε_yy = 1e-3 (u_y = 1e-3 y): σ_yy = (λ + 2μ) ε_yy per layer, plane strain.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(V.numDofs());
  for (Index n = 0; n < V.numNodes(); ++n) u[V.dof(n, 1)] = 1e-3 * V.coordinate(n).y();
  int checked = 0;
  for (Index c = 0; c < mesh.numCells(); ++c) {
    const Material m = Material::fromYoungPoisson(mesh.cellRegion[c] == 1 ? 1e9 : 1e13, 0.25);
    const auto t = mesh.cell(c);
    const Vector2 x =
        (mesh.points[t[0]].head<2>() + mesh.points[t[1]].head<2>() + mesh.points[t[2]].head<2>()) /
        3.0;
    const Eigen::Matrix2d s = layered.stress(u, c, x);
    CHECK(s(1, 1) == Approx((m.lambda() + 2 * m.mu()) * 1e-3).epsilon(1e-12));
    CHECK(s(0, 0) == Approx(m.lambda() * 1e-3).epsilon(1e-12));
    CHECK(layered.stress(u, c, Point(x.x(), x.y(), 0))(2, 2) ==
          Approx(m.lambda() * 1e-3).epsilon(1e-12));
    ++checked;
  }
  CHECK(checked == mesh.numCells());
  // Energy uᵀKu = Σ_layers (λ + 2μ) ε² area: the stiff layer counts 1e4 times the soft one.
  const Eigen::SparseMatrix<double> K = layered.stiffness();
  const Material soft = Material::fromYoungPoisson(1e9, 0.25);
  const Material stiff = Material::fromYoungPoisson(1e13, 0.25);
  const double expected =
      ((soft.lambda() + 2 * soft.mu()) + (stiff.lambda() + 2 * stiff.mu())) * 0.5 * 1e-6;
  // Round-off of sums of 1e13-sized terms: 1e-12 relative.
  CHECK(u.dot(K * u) == Approx(expected).epsilon(1e-12));
}
