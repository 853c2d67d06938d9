// Dictionary grammar: the OpenFOAM syntax the reader accepts (Dictionary.hpp), with the
// file:line every entry keeps, and OpenFOAM's rules for repeated keys.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("scalars, words, strings and nested dictionaries keep their file and line",
          "[dict][grammar]") {
  const Dictionary d = Dictionary::parse(R"(FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      material;
}
// a line comment
E       1e9;   /* a block comment
                  over two lines */
nu      0.3;
name    "granite block";
type    coulomb;
solid
{
    rho 2700;
    inner { depth -3.5; }
}
)",
                                         "constant/material");
  CHECK(d.getScalar("E") == 1e9);
  CHECK(d.getScalar("nu") == 0.3);
  CHECK(d.getWord("name") == "granite block");
  CHECK(d.getWord("type") == "coulomb");
  CHECK(d.keys() == std::vector<std::string>{"FoamFile", "E", "nu", "name", "type", "solid"});
  CHECK(d.subDict("FoamFile").getWord("object") == "material");

  CHECK(d.location("E").str() == "constant/material:9");
  CHECK(d.location("nu").str() == "constant/material:11");
  const Dictionary& solid = d.subDict("solid");
  CHECK(solid.scope() == "constant/material/solid");
  CHECK(solid.location().str() == "constant/material:15");  // its '{'
  CHECK(solid.location("rho").str() == "constant/material:16");
  const Dictionary& inner = solid.subDict("inner");
  CHECK(inner.scope() == "constant/material/solid/inner");
  CHECK(inner.getScalar("depth") == -3.5);
  CHECK(inner.location("depth").line == 17);
  CHECK(d.isDict("solid"));
  CHECK_FALSE(d.isDict("nu"));
  CHECK(d.findDict("absent") == nullptr);
}

TEST_CASE("lists, vectors, sized lists and uniform values", "[dict][grammar]") {
  const Dictionary d = Dictionary::parse(R"(
v        (1 -2.5);
u        uniform (3 4);
sized    3(1 2 3);
typed    List<scalar> 3(1.5 2 3);
field    nonuniform List<vector> 2((0 0) (1 1));
ints     (0 -1 2);
words    (a b "c d");
empty    0();
tris     ((0 1 2) (2 3 0));
edges    2((0 1)(1 2));
nested   ((1 2) ((3) 4) ());
points   3
(
    (0 0)
    (1 0)
    (0 1)
);
)",
                                         "test");
  CHECK(d.getVector("v") == Vector2(1, -2.5));
  CHECK(d.getVector("u") == Vector2(3, 4));
  CHECK(d.getScalarList("sized") == std::vector<double>{1, 2, 3});
  CHECK(d.getScalarList("typed") == std::vector<double>{1.5, 2, 3});
  CHECK(d.getVectorList("field") == std::vector<Vector2>{{0, 0}, {1, 1}});
  CHECK(d.getIntList("ints") == std::vector<long>{0, -1, 2});
  CHECK(d.getWordList("words") == std::vector<std::string>{"a", "b", "c d"});
  CHECK(d.getScalarList("empty").empty());
  CHECK(d.getIntTupleList<3>("tris") == std::vector<std::array<long, 3>>{{0, 1, 2}, {2, 3, 0}});
  CHECK(d.getIntTupleList<2>("edges") == std::vector<std::array<long, 2>>{{0, 1}, {1, 2}});
  // OpenFOAM's long-list layout: the size alone on a line, then the list.
  CHECK(d.getVectorList("points") == std::vector<Vector2>{{0, 0}, {1, 0}, {0, 1}});
  CHECK(d.location("points").line == 13);

  const std::vector<Value>& nested = d.values("nested");
  REQUIRE(nested.size() == 1);
  REQUIRE(nested[0].isList());
  REQUIRE(nested[0].items.size() == 3);
  CHECK(nested[0].items[1].items[0].isList());
  CHECK(nested[0].items[1].items[0].items[0].number == 3);
  CHECK(nested[0].items[2].items.empty());
  CHECK(nested[0].str() == "((1 2) ((3) 4) ())");
}

TEST_CASE("a number followed by a list on the same line is a table row, not a sized list",
          "[dict][grammar]") {
  const Dictionary d = Dictionary::parse(
      "load ((0 (0 0)) (1 (-0.02 -0.025)) (2.5 (1e-3 +4)));\n"
      "scalarTable\n(\n    (0 1)\n    (2 3)\n);\n",
      "test");
  const Table t = d.getTable("load");
  CHECK(t.x == std::vector<double>{0, 1, 2.5});
  REQUIRE(t.y.size() == 3);
  CHECK(t.y[0] == std::vector<double>{0, 0});
  CHECK(t.y[1] == std::vector<double>{-0.02, -0.025});
  CHECK(t.y[2] == std::vector<double>{1e-3, 4});
  const Table s = d.getTable("scalarTable");
  CHECK(s.x == std::vector<double>{0, 2});
  CHECK(s.y == std::vector<std::vector<double>>{{1}, {3}});
}

TEST_CASE("a key given twice in one file is an error naming both lines",
          "[dict][grammar][duplicates]") {
  // OpenFOAM takes the last one (foamDictionary v1912); a case that says two things is
  // ambiguous, so the reader refuses it, for values and dictionaries, at any depth.
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("a 1;\nb 2;\na 3;\n", "test"); }),
             StartsWith("test:3: key 'a' is given twice in test (first at line 1): expected each "
                        "key once; delete one"));
  CHECK_THAT(
      inputErrorOf([] { Dictionary::parse("d { x 1; y 2; }\n\nd { y 3; z 4; }\n", "test"); }),
      StartsWith("test:3: key 'd' is given twice in test (first at line 1)"));
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("d\n{\n    x 1;\n    x 1;\n}\n", "test"); }),
             StartsWith("test:4: key 'x' is given twice in test/d (first at line 3)"));
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("v 1;\nv { a 1; }\n", "test"); }),
             StartsWith("test:2: key 'v' is given twice in test (first at line 1)"));
  // The same key in different dictionaries is no duplicate.
  const Dictionary d = Dictionary::parse("a 1;\nd { a 2; }\ne { a 3; }\n", "test");
  CHECK(d.getScalar("a") == 1);
  CHECK(d.subDict("d").getScalar("a") == 2);
}

TEST_CASE("numbers keep their text, integers convert exactly, and number-like words stay words",
          "[dict][grammar]") {
  const Dictionary d = Dictionary::parse(
      "big 9007199254740993;\nexp 1.5e-3;\nplus +2;\nwhole 2.0;\nhalf 2.5;\npoint .5;\n"
      "word 1abc;\nminf -inf;\ntiny 5e-324;\n",
      "test");
  CHECK(d.getInt("big") == 9007199254740993L);  // beyond 2^53: not through a double
  CHECK(d.values("exp")[0].text == "1.5e-3");
  CHECK(d.getScalar("exp") == 1.5e-3);
  CHECK(d.getInt("plus") == 2);
  CHECK(d.getInt("whole") == 2);
  CHECK_THROWS_AS(d.getInt("half"), InputError);
  CHECK(d.getScalar("point") == 0.5);
  CHECK(d.values("word")[0].isWord());
  CHECK(d.getWord("word") == "1abc");
  CHECK(d.values("minf")[0].isWord());
  CHECK(d.getScalar("tiny") == 5e-324);
}

TEST_CASE("comments end words and numbers, but not inside strings or paths", "[dict][grammar]") {
  const Dictionary d = Dictionary::parse(
      "mesh constant/mesh.msh; // the mesh\n"
      "x 1// no space before the comment\n;\n"
      "y /* inline */ 2;\n"
      "s \"a // not a comment /* either */\";\n"
      "q \"say \\\"hi\\\"\";\n"
      "multi \"one\\\ntwo\";\n"
      "after 7;\n",
      "test");
  CHECK(d.getFileName("mesh") == "constant/mesh.msh");
  CHECK(d.getScalar("x") == 1);
  CHECK(d.getScalar("y") == 2);
  CHECK(d.getWord("s") == "a // not a comment /* either */");
  CHECK(d.getWord("q") == "say \"hi\"");
  CHECK(d.getWord("multi") == "one\ntwo");
  CHECK(d.location("after").line == 9);  // the escaped newline is counted
}

TEST_CASE("booleans, choices and defaults", "[dict][grammar]") {
  const Dictionary d = Dictionary::parse("a true;\nb off;\nc yes;\ntype tresca;\nn 5;\n", "test");
  CHECK(d.getBool("a"));
  CHECK_FALSE(d.getBool("b"));
  CHECK(d.getBoolOr("c", false));
  CHECK(d.getBoolOr("absent", true));
  CHECK(d.getChoice("type", {"coulomb", "tresca"}) == "tresca");
  CHECK(d.getChoiceOr("law", {"coulomb", "tresca"}, "coulomb") == "coulomb");
  CHECK(d.getIntOr("n", 1) == 5);
  CHECK(d.getIntOr("m", 1) == 1);
  CHECK(d.getScalarOr("dt", 0.25) == 0.25);
  CHECK(d.getWordOr("solver", "direct") == "direct");
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE("a dictionary built in code behaves like a parsed one", "[dict][grammar]") {
  Dictionary d = Dictionary::parse("", "built");
  Value x;
  x.kind = Value::Kind::Number;
  x.number = 0.1;
  d.set("x", {x});
  Dictionary& sub = d.setDict("sub");
  Value hello;
  hello.text = "hello";
  sub.set("w", {hello});
  CHECK(sub.scope() == "built/sub");
  CHECK(d.values("x")[0].str() == "0.1");
  CHECK(d.getScalar("x") == 0.1);
  CHECK(d.subDict("sub").getWord("w") == "hello");

  const Dictionary copy = d;  // deep copy, read flags included
  CHECK_NOTHROW(copy.checkAllRead());
  d.set("x", {hello});
  CHECK(copy.getScalar("x") == 0.1);
}

TEST_CASE("Bounds describe themselves the way messages quote them", "[dict][grammar]") {
  const Bounds halfOpen{0, 0.5, false, true};
  const Bounds below{-std::numeric_limits<double>::infinity(), 1, false, true};
  CHECK(Bounds{}.str().empty());
  CHECK(Bounds::positive().str() == "> 0");
  CHECK(Bounds::nonNegative().str() == ">= 0");
  CHECK(Bounds::closed(0, 1).str() == "in [0, 1]");
  CHECK(halfOpen.str() == "in [0, 0.5)");
  CHECK(below.str() == "< 1");
  CHECK(Bounds::positive().contains(1e-300));
  CHECK_FALSE(Bounds::positive().contains(0));
  CHECK(Bounds::nonNegative().contains(0));
  CHECK_FALSE(halfOpen.contains(0.5));
  CHECK(halfOpen.contains(0));
  CHECK_FALSE(Bounds{}.contains(std::nan("")));
}
