// checkAllRead: an entry the program never read is an error naming it, its file:line and the
// nearest key the program asked for in that dictionary.
#include <catch2/catch.hpp>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("a misspelt key is reported with its line and the nearest key the program asked for",
          "[dict][unread]") {
  const Dictionary d = Dictionary::parse(R"(FoamFile
{
    version 2.0;
    format  ascii;
}
mesh      "constant/mesh.msh";
fractrues (crack);
)",
                                         "system/meshDict");
  CHECK(d.getFileName("mesh") == "constant/mesh.msh");
  CHECK_FALSE(d.found("fractures"));
  CHECK(d.getScalarOr("tolerance", 1e-8) == 1e-8);
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "system/meshDict:7: unknown key 'fractrues' in system/meshDict; did you mean "
        "'fractures'? (valid keys: fractures, mesh, tolerance)");
}

TEST_CASE("the suggestion is a near asked-for key, preferring those that are missing",
          "[dict][unread]") {
  const Dictionary d = Dictionary::parse("E 1;\nnu 0.3;\nYoungs 2;\nnus 4;\nrhoo 5;\n", "m");
  d.getScalar("E");
  d.getScalar("nu");
  d.getScalarOr("rho", 1);
  // 'Youngs' is far from every key: a guess would mislead, so none is offered.
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "m:3: unknown key 'Youngs' in m (valid keys: E, nu, rho)");
  d.values("Youngs");
  // 'nus' is one letter from the present 'nu' and far from the missing 'rho'.
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "m:4: unknown key 'nus' in m; did you mean 'nu'? (valid keys: E, Youngs, nu, rho)");
  d.values("nus");
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "m:5: unknown key 'rhoo' in m; did you mean 'rho'? (valid keys: E, Youngs, nu, nus, rho)");

  // Near both a present and a missing key: the missing one is the likely intended one.
  // 'xu' is one letter from both; 'mu' comes first but is present.
  const Dictionary both = Dictionary::parse("mu 1;\nxu 4;\n", "m");
  both.getScalar("mu");
  both.getScalarOr("nu", 1);
  CHECK_THAT(inputErrorOf([&] { both.checkAllRead(); }),
             StartsWith("m:2: unknown key 'xu' in m; did you mean 'nu'?"));
}

TEST_CASE("read sub-dictionaries are checked recursively, unread ones are unknown keys",
          "[dict][unread]") {
  const std::string text = R"(solid
{
    E 1;
    nu 0.3;
    extra 2;
}
fluid
{
    rho 1000;
}
)";
  SECTION("an unread entry in a read sub-dictionary") {
    const Dictionary d = Dictionary::parse(text, "constant/material");
    const Dictionary& solid = d.subDict("solid");
    solid.getScalar("E");
    solid.getScalar("nu");
    d.findDict("fluid")->getScalar("rho");
    CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
          "constant/material:5: unknown key 'extra' in constant/material/solid (valid keys: E, "
          "nu)");
  }
  SECTION("a sub-dictionary never asked for") {
    const Dictionary d = Dictionary::parse(text, "constant/material");
    d.subDict("solid").markAllRead();
    CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
          "constant/material:7: unknown key 'fluid' in constant/material (valid keys: solid)");
  }
  SECTION("markAllRead on the whole dictionary") {
    const Dictionary d = Dictionary::parse(text, "constant/material");
    d.markAllRead();
    CHECK_NOTHROW(d.checkAllRead());
  }
  SECTION("the first unread entry in file order is reported, depth first") {
    const Dictionary d = Dictionary::parse(text, "constant/material");
    d.subDict("solid");
    d.subDict("fluid");
    CHECK_THAT(inputErrorOf([&] { d.checkAllRead(); }),
               StartsWith("constant/material:3: unknown key 'E' in constant/material/solid "
                          "(no keys are read from constant/material/solid)"));
  }
}

TEST_CASE("the FoamFile header counts as read and a fully read dictionary passes",
          "[dict][unread]") {
  const Dictionary d = Dictionary::parse(
      "FoamFile { version 2.0; format ascii; class dictionary; object x; note \"n\"; }\n"
      "a 1;\n",
      "x");
  CHECK_THAT(inputErrorOf([&] { d.checkAllRead(); }), StartsWith("x:2: unknown key 'a' in x"));
  d.getScalar("a");
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE("an entry the program only checks for is reported as unused", "[dict][unread]") {
  const Dictionary d = Dictionary::parse("a 1;\n", "x");
  CHECK(d.found("a"));
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "x:1: key 'a' in x is never used (the program checks that it is there but does not "
        "read it)");
}
