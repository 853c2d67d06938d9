// Friction parameters as fields along a fracture (FrictionField.hpp): each form evaluated on
// synthetic fracture nodes against values computed by hand, the constant forms equal to the
// number to the last bit, and every bad input an InputError naming the file, key and node.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/law/FrictionLaw.hpp"

using namespace friction;
namespace fs = std::filesystem;

namespace {

/// A straight 2D fracture from (0, 0) to (0.3, 0.4) (length 0.5) with n nodes, or the same
/// points with z = y and y = 0 in 3D (a fault surface's nodes along a dipping line).
std::vector<ControlNode> line(int n, int dim = 2) {
  std::vector<ControlNode> nodes(n);
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    nodes[i].arclength = dim == 2 ? 0.5 * t : 0;
    nodes[i].position = dim == 2 ? Point(0.3 * t, 0.4 * t, 0) : Point(0.3 * t, 0, 0.4 * t);
    nodes[i].x = nodes[i].position.head<2>();
  }
  return nodes;
}

std::vector<const ControlNode*> pointers(const std::vector<ControlNode>& nodes) {
  std::vector<const ControlNode*> p;
  for (const auto& n : nodes) p.push_back(&n);
  return p;
}

fs::path caseDir() {
  const fs::path d =
      fs::temp_directory_path() / ("frictionFieldTest-" + std::to_string(::getpid()));
  fs::create_directories(d / "constant");
  return d;
}

FrictionField field(const std::string& text, Bounds b = Bounds::nonNegative(), int dim = 2) {
  const Dictionary d = Dictionary::parse(text, "constant/fractureProperties");
  FrictionField f = FrictionField::read(d, "frictionCoefficient", b, caseDir().string(), dim);
  d.checkAllRead();
  return f;
}

/// The InputError's text of reading and evaluating `text` on nodes.
std::string errorOf(const std::string& text, const std::vector<ControlNode>& nodes,
                    Bounds b = Bounds::nonNegative(), int dim = 2) {
  try {
    field(text, b, dim).evaluate(pointers(nodes));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST_CASE("friction field: a number is a constant, as before", "[unit][law][field]") {
  const FrictionField f = field("frictionCoefficient 0.6;");
  CHECK(f.isConstant());
  CHECK(f.value() == 0.6);
  const auto nodes = line(5);
  const Eigen::VectorXd v = f.evaluate(pointers(nodes));
  REQUIRE(v.size() == 5);
  for (Eigen::Index i = 0; i < v.size(); ++i) CHECK(v[i] == 0.6);
  CHECK(f.describe() == "0.6");
}

TEST_CASE("friction field: arclength table, linear between rows", "[unit][law][field]") {
  const auto nodes = line(11);  // s = 0, 0.05, ..., 0.5
  const FrictionField f =
      field("frictionCoefficient { type arclength; table ((0 0.2) (0.25 0.7) (0.5 0.3)); }");
  CHECK_FALSE(f.isConstant());
  const Eigen::VectorXd v = f.evaluate(pointers(nodes));
  REQUIRE(v.size() == 11);
  for (int i = 0; i < 11; ++i) {
    const double s = nodes[i].arclength;
    const double expected = s <= 0.25 ? 0.2 + (s / 0.25) * 0.5 : 0.7 - ((s - 0.25) / 0.25) * 0.4;
    // Interpolation of numbers of size 1: round-off of a few ulps.
    CHECK(v[i] == Approx(expected).epsilon(1e-14));
  }
  // A constant table gives the number itself, bit for bit (a + w (b − a) with b = a).
  const Eigen::VectorXd c =
      field("frictionCoefficient { type arclength; table ((0 0.37) (0.1 0.37) (0.5 0.37)); }")
          .evaluate(pointers(nodes));
  for (Eigen::Index i = 0; i < c.size(); ++i) CHECK(c[i] == 0.37);
}

TEST_CASE("friction field: arclength file, the values file's format", "[unit][law][field]") {
  const fs::path dir = caseDir();
  std::ofstream(dir / "constant" / "mu.dat") << "# s mu\n0 0.5\n\n0.5 0.9\n";
  const auto nodes = line(3);
  const Eigen::VectorXd v =
      field("frictionCoefficient { type arclength; file \"constant/mu.dat\"; }")
          .evaluate(pointers(nodes));
  REQUIRE(v.size() == 3);
  CHECK(v[0] == 0.5);
  CHECK(v[1] == Approx(0.7).epsilon(1e-15));
  CHECK(v[2] == 0.9);
}

TEST_CASE("friction field: depth, value + gradient (v - reference), v = y in 2D, z in 3D",
          "[unit][law][field]") {
  for (int dim : {2, 3}) {
    const auto nodes = line(5, dim);
    const Eigen::VectorXd v =
        field("frictionCoefficient { type depth; value 0.6; gradient -0.5; reference 0.2; }",
              Bounds::nonNegative(), dim)
            .evaluate(pointers(nodes));
    REQUIRE(v.size() == 5);
    for (int i = 0; i < 5; ++i)
      CHECK(v[i] == Approx(0.6 - 0.5 * (nodes[i].position[dim - 1] - 0.2)).epsilon(1e-15));
    // No gradient: the number to the last bit.
    const Eigen::VectorXd c = field("frictionCoefficient { type depth; value 0.6; gradient 0; }",
                                    Bounds::nonNegative(), dim)
                                  .evaluate(pointers(nodes));
    for (Eigen::Index i = 0; i < c.size(); ++i) CHECK(c[i] == 0.6);
  }
}

TEST_CASE("friction field: points, each node the nearest row's value, 2D and 3D",
          "[unit][law][field]") {
  const fs::path dir = caseDir();
  for (int dim : {2, 3}) {
    const auto nodes = line(4, dim);
    {
      std::ofstream out(dir / "constant" / "mu.dat");
      out.precision(17);
      out << "# one row per node, in reverse order: the rows are matched by position\n";
      for (int i = 3; i >= 0; --i) {
        out << nodes[i].position.x() << " " << nodes[i].position.y() << " ";
        if (dim == 3) out << nodes[i].position.z() << " ";
        out << 0.1 * (i + 1) << "\n";
      }
    }
    const Eigen::VectorXd v =
        field("frictionCoefficient { type points; file \"constant/mu.dat\"; }",
              Bounds::nonNegative(), dim)
            .evaluate(pointers(nodes));
    REQUIRE(v.size() == 4);
    for (int i = 0; i < 4; ++i) CHECK(v[i] == 0.1 * (i + 1));
  }
  // Scattered values with maxDistance: the nearest of two rows.
  std::ofstream(dir / "constant" / "mu.dat") << "0 0 0.1\n0.3 0.4 0.9\n";
  const auto nodes = line(5);
  const Eigen::VectorXd v =
      field("frictionCoefficient { type points; file \"constant/mu.dat\"; maxDistance 1; }")
          .evaluate(pointers(nodes));
  REQUIRE(v.size() == 5);
  CHECK(v[0] == 0.1);
  CHECK(v[1] == 0.1);
  CHECK(v[3] == 0.9);
  CHECK(v[4] == 0.9);
  // Without maxDistance the rows must sit on the nodes: the node at s = 0.125 has none.
  const std::string e =
      errorOf("frictionCoefficient { type points; file \"constant/mu.dat\"; }", nodes);
  CHECK_THAT(e, Catch::Contains("constant/fractureProperties:1:") &&
                    Catch::Contains("frictionCoefficient") && Catch::Contains("no row of") &&
                    Catch::Contains("(0.075 0.1)") && Catch::Contains("maxDistance"));
}

TEST_CASE("friction field: bad input names the file, the key and the node", "[unit][law][field]") {
  const auto nodes = line(5);
  SECTION("a negative value at a node") {
    const std::string e = errorOf(
        "\nfrictionCoefficient { type depth; value 0.5; gradient 1; reference 0.75; }", nodes);
    CHECK_THAT(e, Catch::Contains("constant/fractureProperties:2:") &&
                      Catch::Contains("'frictionCoefficient'") && Catch::Contains("-0.25") &&
                      Catch::Contains(">= 0") && Catch::Contains("(0 0)"));
  }
  SECTION("a threshold must be positive at every node") {
    const std::string e = errorOf("frictionCoefficient { type arclength; table ((0 1) (0.5 0)); }",
                                  nodes, Bounds::positive());
    CHECK_THAT(e, Catch::Contains("the value 0 is not > 0") && Catch::Contains("s = 0.5 m"));
  }
  SECTION("a table that does not cover the fracture") {
    const std::string e =
        errorOf("frictionCoefficient { type arclength; table ((0 0.5) (0.4 0.5)); }", nodes);
    CHECK_THAT(e, Catch::Contains("covers s in [0, 0.4]") && Catch::Contains("s = 0.5"));
  }
  SECTION("an unknown type lists the valid ones") {
    const std::string e = errorOf("frictionCoefficient { type dept; value 1; gradient 0; }", nodes);
    CHECK_THAT(e, Catch::Contains("dept") && Catch::Contains("arclength, points, depth"));
  }
  SECTION("an arclength field on a 3D mesh") {
    const std::string e = errorOf("frictionCoefficient { type arclength; table ((0 1) (1 1)); }",
                                  line(3, 3), Bounds::nonNegative(), 3);
    CHECK_THAT(e, Catch::Contains("fault surface") && Catch::Contains("points or depth"));
  }
  SECTION("a malformed line of a file") {
    std::ofstream(caseDir() / "constant" / "bad.dat") << "0 0.5\n0.25 0,7\n";
    const std::string e =
        errorOf("frictionCoefficient { type arclength; file \"constant/bad.dat\"; }", nodes);
    CHECK_THAT(e, Catch::Contains("bad.dat:2:") && Catch::Contains("decimal comma"));
  }
  SECTION("a points file with a missing coordinate") {
    std::ofstream(caseDir() / "constant" / "bad.dat") << "0 0 0.5\n0.25 0.7\n";
    const std::string e =
        errorOf("frictionCoefficient { type points; file \"constant/bad.dat\"; }", nodes);
    CHECK_THAT(e, Catch::Contains("bad.dat:2:") && Catch::Contains("'x y value'") &&
                      Catch::Contains("(2 items)"));
  }
  SECTION("a points file with two values at one point") {
    std::ofstream(caseDir() / "constant" / "bad.dat") << "0 0 0.5\n0.3 0.4 0.6\n0 0 0.7\n";
    const std::string e =
        errorOf("frictionCoefficient { type points; file \"constant/bad.dat\"; }", nodes);
    CHECK_THAT(e, Catch::Contains("bad.dat:3:") && Catch::Contains("the same point as line 1") &&
                      Catch::Contains("(0.7, not 0.5)"));
  }
  SECTION("a missing file") {
    const std::string e =
        errorOf("frictionCoefficient { type points; file \"constant/none.dat\"; }", nodes);
    CHECK_THAT(e, Catch::Contains("none.dat") && Catch::Contains("cannot open"));
  }
  SECTION("an unknown key of a field") {
    const std::string e =
        errorOf("frictionCoefficient { type depth; value 1; gradient 0; refrence 2; }", nodes);
    CHECK_THAT(e, Catch::Contains("refrence") && Catch::Contains("reference"));
  }
}

TEST_CASE("friction laws read their parameters as fields", "[unit][law][field]") {
  const Dictionary d = Dictionary::parse(
      "law coulombCohesion; frictionCoefficient { type depth; value 0.5; gradient 0; }\n"
      "cohesion 2e6;",
      "constant/fractureProperties");
  const auto law = FrictionLaw::New(d, ".", 2);
  d.checkAllRead();
  CHECK(law->name() == "coulombCohesion");
  CHECK_FALSE(law->mu().isConstant());
  CHECK(law->cohesion().isConstant());
  CHECK(law->cohesion().value() == 2e6);
  CHECK(law->cohesionKey() == "cohesion");
  const auto none = FrictionLaw::New(Dictionary::parse("law frictionless;", "f"), ".", 2);
  CHECK(none->mu().isConstant());
  CHECK(none->mu().value() == 0);
  CHECK(none->cohesion().value() == 0);
}
