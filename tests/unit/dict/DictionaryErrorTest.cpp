// Dictionary errors: every syntax error and every typed-access error is an InputError whose
// message names file:line, the key where there is one, and what was expected.
#include <catch2/catch.hpp>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

std::string parseError(const std::string& text) {
  return inputErrorOf([&] { Dictionary::parse(text, "case/dict"); });
}

}  // namespace

TEST_CASE("syntax errors name file, line and what was expected", "[dict][errors]") {
  SECTION("unterminated block comment, at the line it opens") {
    const std::string m = parseError("a 1;\n/* open\nb 2;\n");
    CHECK_THAT(m, StartsWith("case/dict:2: unterminated comment"));
    CHECK_THAT(m, Contains("expected '*/'"));
  }
  SECTION("unterminated string at the end of its line") {
    const std::string m = parseError("a 1;\nname \"abc;\nb 2;\n");
    CHECK_THAT(m, StartsWith("case/dict:2: unterminated string"));
    CHECK_THAT(m, Contains("expected '\"'"));
  }
  SECTION("unterminated string at the end of the file") {
    CHECK_THAT(parseError("name \"abc\\\n"), StartsWith("case/dict:1: unterminated string"));
  }
  SECTION("unterminated list closed by ';'") {
    const std::string m = parseError("a 1;\nv (1 2;\n");
    CHECK_THAT(m, StartsWith("case/dict:2: key 'v': unterminated list"));
    CHECK_THAT(m, Contains("expected ')'"));
    CHECK_THAT(m, Contains("got ';' at line 2"));
  }
  SECTION("unterminated list at the end of the file") {
    const std::string m = parseError("v\n(\n(1 2)\n");
    CHECK_THAT(m, StartsWith("case/dict:2: key 'v': unterminated list"));
    CHECK_THAT(m, Contains("end of file"));
  }
  SECTION("unterminated dictionary, at its '{'") {
    const std::string m = parseError("a 1;\nsolid\n{\n    E 1;\n");
    CHECK_THAT(m, StartsWith("case/dict:3: unterminated dictionary 'solid'"));
    CHECK_THAT(m, Contains("expected '}'"));
  }
  SECTION("missing ';' before a '}'") {
    const std::string m = parseError("solid\n{\n    E 1\n}\n");
    CHECK_THAT(m, StartsWith("case/dict:3: key 'E': expected ';'"));
    CHECK_THAT(m, Contains("'}' at line 4"));
  }
  SECTION("missing ';' at the end of the file") {
    const std::string m = parseError("a 1;\nb 2");
    CHECK_THAT(m, StartsWith("case/dict:2: key 'b': expected ';'"));
    CHECK_THAT(m, Contains("end of file"));
  }
  SECTION("missing ';' before a sub-dictionary") {
    CHECK_THAT(parseError("a 1\nsolid { E 1; }\n"),
               StartsWith("case/dict:1: key 'a': expected ';' to end the entry, got '{'"));
  }
  SECTION("a dictionary inside a list") {
    CHECK_THAT(parseError("boundary\n(\n    left { type wall; }\n);\n"),
               StartsWith("case/dict:3: key 'boundary': a dictionary inside a list is not "
                          "supported"));
  }
  SECTION("a directive inside a list") {
    CHECK_THAT(parseError("l (1\n#include \"x\");\n"),
               StartsWith("case/dict:1: key 'l': unterminated list") &&
                   Contains("got '#include' at line 2"));
  }
  SECTION("unexpected '}'") {
    CHECK_THAT(parseError("a 1;\n}\n"),
               StartsWith("case/dict:2: unexpected '}': no dictionary is open"));
  }
  SECTION("unexpected ')'") {
    CHECK_THAT(parseError("a 1);\n"), StartsWith("case/dict:1: key 'a': unexpected ')'"));
  }
  SECTION("undefined $name") {
    const std::string m = parseError("nu 0.3;\nsolid { nu $Nu; }\n");
    CHECK_THAT(m, StartsWith("case/dict:2: key 'nu': undefined variable '$Nu'"));
    CHECK_THAT(m, Contains("did you mean '$nu'?"));
  }
  SECTION("$name defined only later") {
    CHECK_THAT(parseError("a $b;\nb 1;\n"),
               StartsWith("case/dict:1: key 'a': undefined variable '$b'"));
  }
  SECTION("unknown directive") {
    const std::string m = parseError("a 1;\n#inputMode merge\n");
    CHECK_THAT(m, StartsWith("case/dict:2: unknown directive '#inputMode'"));
    CHECK_THAT(m, Contains("expected #include"));
  }
  SECTION("a number where a key belongs") {
    CHECK_THAT(parseError("1 2;\n"), StartsWith("case/dict:1: expected a key (a word)"));
  }
  SECTION("a '(' where a key belongs") {
    CHECK_THAT(parseError("a 1;\n(1 2);\n"), StartsWith("case/dict:2: expected a key"));
  }
  SECTION("sized list with fewer items than declared") {
    const std::string m = parseError("a 1;\nb 3(1 2);\n");
    CHECK_THAT(m, StartsWith("case/dict:2: key 'b': the list is declared with 3 items but has 2"));
  }
  SECTION("sized list with more items than declared, in OpenFOAM's long layout") {
    const std::string m = parseError("points 2\n(\n(0 0)\n(1 0)\n(0 1)\n);\n");
    CHECK_THAT(m, StartsWith("case/dict:1: key 'points': the list is declared with 2 items but "
                             "has 3"));
  }
  SECTION("sized nested list with a wrong count") {
    CHECK_THAT(parseError("t 2((0 1) 3(1 2));\n"),
               StartsWith("case/dict:1: key 't': the list is declared with 3 items but has 2"));
  }
  SECTION("a number out of the range of a double") {
    CHECK_THAT(parseError("a\n1e999;\n"), StartsWith("case/dict:2: number 1e999 is out of"));
  }
  SECTION("a missing file") {
    const std::string m =
        inputErrorOf([] { Dictionary::read("/nonexistent-friction/constant/material"); });
    CHECK_THAT(m, StartsWith("/nonexistent-friction/constant/material: cannot open"));
  }
}

TEST_CASE("range and type errors name file:line, key, what was expected and what was found",
          "[dict][errors]") {
  const Dictionary d = Dictionary::parse(
      "a 1;\nb 2;\nc 3;\nd 4;\ne 5;\nf 6;\ng 7;\nh 8;\ni 9;\nj 10;\nk 11;\n"
      "nu 0.7;\n"  // line 12
      "E -1;\n"
      "Emod abc;\n"
      "n 1.5;\n"
      "m -3;\n"
      "v (1 2 3);\n"
      "flag maybe;\n"
      "type coulmb;\n"
      "vs\n(\n    (0 0)\n    (1 2 3)\n);\n"  // lines 20-24, the bad item on 23
      "tris ((0 1 2) (1 2));\n"
      "ints (1 x 3);\n"
      "split 1\nnext 2;\n"  // lines 27-28: a forgotten ';'
      "sub { x 1; }\n",
      "constant/material");

  CHECK(inputErrorOf([&] {
          d.getScalar("nu", Bounds{0, 0.5, false, true});
        }) == "constant/material:12: key 'nu': expected a number in [0, 0.5), got 0.7");
  CHECK(inputErrorOf([&] { d.getScalar("E", Bounds::positive()); }) ==
        "constant/material:13: key 'E': expected a number > 0, got -1");
  CHECK(inputErrorOf([&] { d.getScalar("Emod"); }) ==
        "constant/material:14: key 'Emod': expected a number, got 'abc'");
  CHECK(inputErrorOf([&] { d.getInt("n"); }) ==
        "constant/material:15: key 'n': expected an integer, got 1.5");
  CHECK(inputErrorOf([&] { d.getInt("m", Bounds::nonNegative()); }) ==
        "constant/material:16: key 'm': expected an integer >= 0, got -3");
  CHECK(inputErrorOf([&] { d.getVector("v"); }) ==
        "constant/material:17: key 'v': expected a vector (x y), got (1 2 3)");
  CHECK_THAT(inputErrorOf([&] { d.getBool("flag"); }),
             StartsWith("constant/material:18: key 'flag': expected true/false, yes/no or "
                        "on/off, got 'maybe'"));
  CHECK(inputErrorOf([&] {
          d.getChoice("type", {"coulomb", "tresca"});
        }) ==
        "constant/material:19: key 'type': unknown type 'coulmb'; did you mean 'coulomb'? "
        "(valid types are: coulomb, tresca)");
  CHECK(inputErrorOf([&] { d.getVectorList("vs"); }) ==
        "constant/material:23: key 'vs': item 1: expected a vector (x y), got (1 2 3)");
  CHECK(inputErrorOf([&] { d.getIntTupleList<3>("tris"); }) ==
        "constant/material:25: key 'tris': item 1: expected a tuple (3 integers), got (1 2)");
  CHECK(inputErrorOf([&] { d.getIntList("ints"); }) ==
        "constant/material:26: key 'ints': item 1: expected an integer, got 'x'");
  CHECK_THAT(inputErrorOf([&] { d.getScalar("split"); }),
             StartsWith("constant/material:27: key 'split': expected a number, got '1 next 2' "
                        "(missing ';' at the end of line 27?)"));
  CHECK_THAT(inputErrorOf([&] { d.getScalar("sub"); }),
             StartsWith("constant/material:29: key 'sub': expected a number, got a dictionary"));
  CHECK_THAT(inputErrorOf([&] { d.subDict("nu"); }),
             StartsWith("constant/material:12: key 'nu': expected a dictionary"));
  // An absent key is located at the dictionary, and a near miss is pointed out.
  CHECK(inputErrorOf([&] { d.getScalar("rho", Bounds::positive()); }) ==
        "constant/material: missing key 'rho' in constant/material (expected a number > 0)");
  const Dictionary typo = Dictionary::parse("solid\n{\n    Nu 0.3;\n}\n", "constant/material");
  CHECK(inputErrorOf([&] { typo.subDict("solid").getScalar("nu"); }) ==
        "constant/material:2: missing key 'nu' in constant/material/solid (expected a number); "
        "is 'Nu' at constant/material:3 a misspelling of it?");
  CHECK_THAT(inputErrorOf([&] { d.subDict("solid"); }),
             StartsWith("constant/material: missing sub-dictionary 'solid'"));
  // The optional getters still check a value that is present.
  CHECK_THAT(inputErrorOf([&] { d.getScalarOr("nu", 0.2, Bounds::closed(0, 0.5)); }),
             StartsWith("constant/material:12: key 'nu': expected a number in [0, 0.5]"));
  // fail() locates a caller's own check at the entry.
  CHECK(inputErrorOf([&] { d.fail("E", "key 'E': too soft"); }) ==
        "constant/material:13: key 'E': too soft");
}

TEST_CASE("table errors name the row", "[dict][errors]") {
  const Dictionary d = Dictionary::parse(
      "decreasing ((0 1) (2 3) (1 4));\n"
      "sizes\n(\n    (0 (0 0))\n    (1 (1 1 1))\n);\n"
      "empty ();\n"
      "notRows (1 2);\n",
      "t");
  CHECK_THAT(inputErrorOf([&] { d.getTable("decreasing"); }),
             StartsWith("t:1: key 'decreasing': item 2: expected x greater than 2"));
  CHECK_THAT(inputErrorOf([&] { d.getTable("sizes"); }),
             StartsWith("t:5: key 'sizes': item 1: expected y with 2 components"));
  CHECK_THAT(inputErrorOf([&] { d.getTable("empty"); }),
             StartsWith("t:7: key 'empty': expected a table with at least one row"));
  CHECK_THAT(inputErrorOf([&] { d.getTable("notRows"); }),
             StartsWith("t:8: key 'notRows': item 0: expected a row (x y)"));
}
