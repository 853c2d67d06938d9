// #include (relative to the including file, entries keep their own file:line, cycles are
// errors) and $name expansion (current, then enclosing dictionaries; '$dict;' merges).
#include <catch2/catch.hpp>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("include reads files relative to the including file, keeping their file and line",
          "[dict][include]") {
  TempDir dir;
  dir.write("case/constant/material",
            "FoamFile { version 2.0; format ascii; class dictionary; object material; }\n"
            "#include \"common\"\n"  // line 2
            "nu 0.3;\n"
            "solid\n{\n    #include \"sub/solid\"\n    rho 2700;\n}\n");
  dir.write("case/constant/common",
            "FoamFile { version 2.0; format ascii; class dictionary; object common; }\n"
            "\n"
            "E 1e9;\n");
  dir.write("case/constant/sub/solid", "// solid parameters\nlambda 2;\n#include \"../more\"\n");
  dir.write("case/constant/more", "mu 3;\n");

  const std::string path = (dir.path() / "case/constant/material").string();
  const Dictionary d = Dictionary::read(path);
  const std::string constant = (dir.path() / "case/constant").string();
  CHECK(d.keys() == std::vector<std::string>{"FoamFile", "E", "nu", "solid"});
  // The included file's header is that file's, not this dictionary's.
  CHECK(d.subDict("FoamFile").getWord("object") == "material");
  CHECK(d.getScalar("E") == 1e9);
  CHECK(d.getScalar("nu") == 0.3);
  CHECK(d.location("E").str() == constant + "/common:3");
  CHECK(d.location("nu").str() == path + ":3");
  const Dictionary& solid = d.subDict("solid");
  CHECK(solid.keys() == std::vector<std::string>{"lambda", "mu", "rho"});
  CHECK(solid.location("lambda").str() == constant + "/sub/solid:2");
  CHECK(solid.location("mu").str() == constant + "/more:1");
  CHECK(solid.location("rho").str() == path + ":7");
  CHECK(solid.getScalar("lambda") == 2);
  CHECK(solid.getScalar("mu") == 3);
  CHECK(solid.getScalar("rho") == 2700);
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE("errors inside an included file name that file and line", "[dict][include]") {
  TempDir dir;
  dir.write("main", "a 1;\n#include \"inc\"\n");
  dir.write("inc", "b 2;\nc (1 2;\n");
  CHECK_THAT(inputErrorOf([&] { Dictionary::read((dir.path() / "main").string()); }),
             StartsWith((dir.path() / "inc").string() + ":2: key 'c': unterminated list"));
}

TEST_CASE("include cycles and missing files are errors at the #include line", "[dict][include]") {
  TempDir dir;
  SECTION("a cycle through two files") {
    dir.write("a", "x 1;\n#include \"b\"\n");
    dir.write("b", "y 2;\n\n#include \"a\"\n");
    const std::string m = inputErrorOf([&] { Dictionary::read((dir.path() / "a").string()); });
    CHECK_THAT(m, StartsWith((dir.path() / "b").string() + ":3: #include cycle: "));
    CHECK_THAT(m, Contains("/a -> ") && Contains("/b -> "));
  }
  SECTION("a file including itself") {
    dir.write("self", "#include \"self\"\n");
    CHECK_THAT(inputErrorOf([&] { Dictionary::read((dir.path() / "self").string()); }),
               StartsWith((dir.path() / "self").string() + ":1: #include cycle"));
  }
  SECTION("the same file included twice is no cycle") {
    dir.write("twice", "#include \"leaf\"\n#include \"leaf\"\n");
    dir.write("leaf", "z 3;\n");
    CHECK(Dictionary::read((dir.path() / "twice").string()).getScalar("z") == 3);
  }
  SECTION("a missing file") {
    dir.write("main", "x 1;\n#include \"absent\"\n");
    const std::string m = inputErrorOf([&] { Dictionary::read((dir.path() / "main").string()); });
    CHECK_THAT(m, StartsWith((dir.path() / "main").string() + ":2: #include: cannot open '" +
                             (dir.path() / "absent").string() + "'"));
  }
  SECTION("#includeIfPresent skips a missing file") {
    dir.write("main", "x 1;\n#includeIfPresent \"absent\"\n");
    CHECK(Dictionary::read((dir.path() / "main").string()).getScalar("x") == 1);
  }
  SECTION("a parsed text includes relative to the given folder") {
    dir.write("inc", "w 5;\n");
    CHECK(Dictionary::parse("#include \"inc\"\n", "text", dir.path().string()).getScalar("w") == 5);
  }
}

TEST_CASE("an entry may override one from an #include file, not one written beside it",
          "[dict][include][duplicates]") {
  // OpenFOAM's idiom: include the common settings, then change some. The overriding entry
  // takes the included one's place; a dictionary is merged into the included one.
  TempDir dir;
  dir.write("common", "E 1e9;\nnu 0.25;\nsolid { rho 2700; g 9.8; }\n");
  const std::string main = dir.write("main", "#include \"common\"\nnu 0.3;\nsolid { g 9.81; }\n");
  const Dictionary d = Dictionary::read(main);
  CHECK(d.keys() == std::vector<std::string>{"E", "nu", "solid"});
  CHECK(d.getScalar("nu") == 0.3);
  CHECK(d.location("nu").str() == main + ":2");
  CHECK(d.subDict("solid").getScalar("rho") == 2700);
  CHECK(d.subDict("solid").getScalar("g") == 9.81);
  // An included file may be overridden by a later one as well, and a file included twice
  // repeats nothing of its own.
  dir.write("more", "nu 0.35;\n");
  const std::string chain =
      dir.write("chain", "#include \"common\"\n#include \"more\"\n#include \"more\"\n");
  CHECK(Dictionary::read(chain).getScalar("nu") == 0.35);

  SECTION("a key written twice beside the #include is still a duplicate") {
    const std::string twice =
        dir.write("twice", "#include \"common\"\nnu 0.3;\nE 2e9;\nnu 0.31;\n");
    CHECK_THAT(
        inputErrorOf([&] { Dictionary::read(twice); }),
        StartsWith(twice + ":4: key 'nu' is given twice in " + twice + " (first at line 2)"));
  }
  SECTION("a key written twice in the included file is a duplicate there") {
    dir.write("bad", "a 1;\na 2;\n");
    const std::string inc = dir.write("inc", "#include \"bad\"\n");
    CHECK_THAT(inputErrorOf([&] { Dictionary::read(inc); }),
               StartsWith((dir.path() / "bad").string() + ":2: key 'a' is given twice"));
  }
}

TEST_CASE("variables expand from the current, then the enclosing dictionaries", "[dict][expand]") {
  const Dictionary d = Dictionary::parse(R"(
E      1e9;
x      1;
list   (0 $E ${x});
inner
{
    x      2;
    here   $x;
    outer  $E;
    deeper { y $x; }
}
)",
                                         "test");
  CHECK(d.getScalarList("list") == std::vector<double>{0, 1e9, 1});
  const Dictionary& inner = d.subDict("inner");
  CHECK(inner.getScalar("here") == 2);
  CHECK(inner.getScalar("outer") == 1e9);
  CHECK(inner.subDict("deeper").getScalar("y") == 2);
  // An expanded value is located where '$name' stands.
  CHECK(inner.location("outer").line == 9);
  CHECK(inner.getScalar("x") == 2);
  // E and x served as variables: they count as read.
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE(
    "a dictionary variable merges or copies a dictionary whose entries are then checked where they "
    "land",
    "[dict][expand]") {
  const Dictionary d = Dictionary::parse(R"(
common { E 1e9; nu 0.25; }
solid
{
    $common;
    nu 0.3;
}
copy $common;
)",
                                         "test");
  const Dictionary& solid = d.subDict("solid");
  CHECK(solid.keys() == std::vector<std::string>{"E", "nu"});
  CHECK(solid.getScalar("E") == 1e9);
  CHECK(solid.getScalar("nu") == 0.3);  // the later entry overrides the merged one
  const Dictionary& copy = d.subDict("copy");
  CHECK(copy.scope() == "test/copy");
  CHECK(copy.getScalar("nu") == 0.25);
  // copy/E was never read: the copy is checked like any dictionary.
  CHECK_THAT(inputErrorOf([&] { d.checkAllRead(); }),
             StartsWith("test:2: unknown key 'E' in test/copy"));
  CHECK_NOTHROW(copy.getScalar("E"));
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE("a variable used in the wrong place is an error saying why", "[dict][expand]") {
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("v 1;\n$v;\n", "t"); }),
             StartsWith("t:2: '$v' at the start of an entry merges a dictionary, but 'v' is a "
                        "value"));
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("d { a 1; }\nl (1 $d);\n", "t"); }),
             StartsWith("t:2: key 'l': '$d' is a dictionary and cannot be part of a list"));
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("d { a 1; }\nl 1 $d;\n", "t"); }),
             StartsWith("t:2: key 'l': '$d' is a dictionary; it can only stand alone"));
}

TEST_CASE("an included file sees the variables of the including dictionary", "[dict][expand]") {
  TempDir dir;
  dir.write("main", "E 5;\nsolid\n{\n    #include \"inc\"\n}\n");
  dir.write("inc", "stiffness $E;\n");
  const Dictionary d = Dictionary::read((dir.path() / "main").string());
  CHECK(d.subDict("solid").getScalar("stiffness") == 5);
  CHECK(d.subDict("solid").location("stiffness").str() == (dir.path() / "inc").string() + ":1");
}
