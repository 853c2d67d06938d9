// Strictness of what a user writes: every number is a whole finite number (in dictionaries,
// tables and fracturePressure values files), a byte-order mark is no part of a key, a
// suggestion is made only for a near miss, a key of another dictionary of the file is said to
// belong there, and alternative keys given together are named as alternatives.
#include <catch2/catch.hpp>

#include <cmath>

#include "DictTestSupport.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/Number.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fe/Material.hpp"
#include "friction/fracture/FractureSystem.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const char* const kBom = "\xEF\xBB\xBF";

/// The pressure a fracturePressure effect puts at arclengths s on fracture "crack".
std::vector<double> pressureAt(const std::unique_ptr<Effect>& effect,
                               const std::vector<double>& s) {
  std::vector<ControlNode> nodes(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) nodes[k].arclength = s[k];
  Eigen::VectorXd p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(s.size()));
  effect->addFracturePressure(nodes, {"crack"}, 0.0, p);
  return {p.data(), p.data() + p.size()};
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------------------

TEST_CASE("a number is the whole token and finite", "[dict][numbers]") {
  for (const auto& [text, value] :
       std::vector<std::pair<const char*, double>>{{"0", 0},
                                                   {"-2", -2},
                                                   {"+2", 2},
                                                   {"0.9", 0.9},
                                                   {".5", 0.5},
                                                   {"-.5", -0.5},
                                                   {"5.", 5},
                                                   {"1e-3", 1e-3},
                                                   {"1E+3", 1e3},
                                                   {"1e-310", 1e-310},
                                                   {"1.7e308", 1.7e308}}) {
    INFO(text);
    REQUIRE(parseNumber(text).has_value());
    CHECK(*parseNumber(text) == value);
  }
  for (const char* text : {"",      "0,9",      "1.5.3",  "1e", "1e+", "nan", "-nan", "inf",
                           "-inf",  "infinity", "0x10",   "2m", "1 ",  " 1",  "+-1",  "--1",
                           "1e400", "-1e400",   "1e-400", ".",  "-",   "e5"}) {
    INFO("'" << text << "'");
    CHECK_FALSE(parseNumber(text).has_value());
  }
}

TEST_CASE("a mistyped number in a dictionary is refused with the key, line and why",
          "[dict][numbers]") {
  struct Bad {
    const char* value;
    const char* why;
  };
  for (const Bad& b :
       {Bad{"0,9", "'0,9' has a decimal comma: write 0.9"},
        Bad{"1.5.3", "'1.5.3' is the number '1.5' followed by '.3'"},
        Bad{"1e", "an exponent needs digits"}, Bad{"nan", "'nan' is not a finite number"},
        Bad{"-inf", "'-inf' is not a finite number"}, Bad{"0x10", "'0x10' is hexadecimal"},
        Bad{"2m", "without a unit"}}) {
    INFO(b.value);
    const Dictionary d = Dictionary::parse(std::string("x 1;\nE ") + b.value + ";\n", "m");
    const std::string m = inputErrorOf([&] { d.getScalar("E"); });
    CHECK_THAT(m,
               StartsWith("m:2: key 'E': expected a number, got '" + std::string(b.value) + "'"));
    CHECK_THAT(m, Contains(b.why));
    // The same inside a vector, a list and a table row: located at the item's line.
    const Dictionary v = Dictionary::parse(std::string("g\n(0\n ") + b.value + ");\n", "m");
    CHECK_THAT(inputErrorOf([&] { v.getVector("g"); }),
               StartsWith("m:1: key 'g'") && Contains(b.why));
    CHECK_THAT(inputErrorOf([&] { v.getScalarList("g"); }),
               StartsWith("m:3: key 'g': item 1: expected a number") && Contains(b.why));
    const Dictionary t =
        Dictionary::parse(std::string("t\n(\n (0 1)\n (1 ") + b.value + ")\n);\n", "m");
    CHECK_THAT(inputErrorOf([&] { t.getTable("t"); }),
               StartsWith("m:4: key 't': item 1: expected a row") && Contains(b.why));
  }
}

TEST_CASE("a number out of the range of a double is an error, not inf or 0", "[dict][numbers]") {
  for (const char* text : {"1e400", "-1e400", "1e-400"}) {
    INFO(text);
    CHECK(inputErrorOf([&] { Dictionary::parse(std::string("a 1;\nE ") + text + ";\n", "m"); }) ==
          std::string("m:2: number ") + text +
              " is out of the range of a double (nonzero magnitudes from 4.9e-324 to 1.8e308)");
  }
  // A list size that does not fit an integer is said to be one, not read as 0.
  CHECK(inputErrorOf([] { Dictionary::parse("a 99999999999999999999(1);", "m"); }) ==
        "m:1: key 'a': list size 99999999999999999999 is too large (expected the number of "
        "items before '(')");
}

TEST_CASE("'uniform' may precede a single value, 'nonuniform' and 'List<>' only a list",
          "[dict][numbers]") {
  const Dictionary d = Dictionary::parse(
      "a uniform 3;\nv uniform (1 2);\nl List<scalar> 2(1 2);\nn nonuniform 3;\n"
      "w nonuniform (1 2);\nu uniform uniform 3;\n",
      "m");
  CHECK(d.getScalar("a") == 3);
  CHECK(d.getVector("v") == Vector2(1, 2));
  CHECK(d.getScalarList("l") == std::vector<double>{1, 2});
  CHECK(inputErrorOf([&] { d.getScalar("n"); }) ==
        "m:4: key 'n': expected a number, got 'nonuniform 3'");
  CHECK(inputErrorOf([&] { d.getVector("w"); }) ==
        "m:5: key 'w': expected a vector (x y), got 'nonuniform (1 2)'");
  CHECK(inputErrorOf([&] { d.getScalar("u"); }) ==
        "m:6: key 'u': expected a number, got 'uniform uniform 3'");
}

// ---------------------------------------------------------------------------------------
// Byte-order mark and header
// ---------------------------------------------------------------------------------------

TEST_CASE("a UTF-8 byte-order mark is skipped, in the file and in an included file",
          "[dict][bom]") {
  TempDir dir;
  dir.write("inc", std::string(kBom) + "nu 0.3;\n");
  const std::string path = dir.write(
      "m", std::string(kBom) + "FoamFile { version 2.0; format ascii; }\nE 1;\n#include \"inc\"\n");
  const Dictionary d = Dictionary::read(path);
  CHECK(d.keys() == std::vector<std::string>{"FoamFile", "E", "nu"});
  CHECK(d.getScalar("E") == 1);
  CHECK(d.getScalar("nu") == 0.3);
  CHECK_NOTHROW(d.checkAllRead());
  // Without a header the mark would otherwise stick to the first key itself.
  const Dictionary bare = Dictionary::parse(std::string(kBom) + "E 2;\n", "m");
  CHECK(bare.keys() == std::vector<std::string>{"E"});
  CHECK(bare.getScalar("E") == 2);
  // Only at the start: elsewhere the bytes are part of the text (a word here).
  const Dictionary inside = Dictionary::parse(std::string("E ") + kBom + ";\n", "m");
  CHECK(inside.getWord("E") == kBom);
}

TEST_CASE("a key with an invisible character is named with the character and its line",
          "[dict][invisible]") {
  // Pasted from a web page or a word processor, "nu" followed by a zero-width space or a
  // no-break space looks like "nu" in every editor.
  struct Case {
    std::string text;
    std::string shown;
    std::string character;
  };
  for (const Case& c : {Case{"E 1e9;\nnu\u200b 0.3;\n", "nu<U+200B>", "U+200B ZERO WIDTH SPACE"},
                        Case{"E 1e9;\nnu\u00a0 0.3;\n", "nu<U+00A0>", "U+00A0 NO-BREAK SPACE"},
                        // a no-break space where a space belongs: the key swallows the value
                        Case{"E 1e9;\nnu\u00a00.3;\n", "nu<U+00A0>0.3", "U+00A0 NO-BREAK SPACE"},
                        Case{"E 1e9;\n\u2060nu 0.3;\n", "<U+2060>nu", "U+2060 WORD JOINER"}}) {
    INFO(c.shown);
    const Dictionary d = Dictionary::parse(c.text, "mech");
    const std::string m = inputErrorOf([&] { d.getScalar("nu"); });
    CHECK_THAT(m, StartsWith("mech:2: missing key 'nu' in mech (expected a number): the key "
                             "written here is '" +
                             c.shown + "', which has the invisible character " + c.character));
    // Read as optional, the key is unknown: the same explanation.
    const Dictionary o = Dictionary::parse(c.text, "mech");
    o.getScalar("E");
    CHECK(o.getScalarOr("nu", 0.25) == 0.25);
    CHECK_THAT(inputErrorOf([&] { o.checkAllRead(); }),
               StartsWith("mech:2: unknown key '" + c.shown +
                          "' in mech, which has the invisible character " + c.character) &&
                   Contains("(it reads as 'nu')"));
  }
  CHECK_THAT(inputErrorOf([] { Dictionary::parse("a\u200b 1;\n", "t").checkAllRead(); }),
             Contains("U+200B ZERO WIDTH SPACE after 'a'; delete it"));
}

TEST_CASE("a control byte the user wrote is shown escaped, and the message keeps file:line",
          "[dict][invisible]") {
  // A NUL printed as a C string (printf, std::cerr << what()) ends the message where it stands.
  using namespace std::string_literals;
  const std::string text = "a 1;\nb\0c 2;\nx 1\0;\ny 2\x01 (3);\n"s;
  REQUIRE(text.size() == 28);
  const Dictionary d = Dictionary::parse(text, "dict");
  const auto printed = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(printed([&] { d.getScalar("x"); }),
             StartsWith("dict:3: key 'x': expected a number, got '1\\0' ('1\\0' is the number "
                        "'1' followed by '\\0'") &&
                 Catch::Matchers::EndsWith(")"));
  CHECK_THAT(printed([&] { d.getScalar("y"); }),
             StartsWith("dict:4: key 'y': expected a number, got '2\\x01 (3)'"));
  d.getScalar("a");
  CHECK_THAT(printed([&] { d.checkAllRead(); }),
             StartsWith("dict:2: unknown key 'b<U+0000>c' in dict, which has the invisible "
                        "character U+0000 NUL after 'b'"));
}

TEST_CASE("a dictionary without a FoamFile header reads like one with it and binary is refused",
          "[dict][header]") {
  TempDir dir;
  const std::string with = dir.write("with", "FoamFile\n{\n    format ascii;\n}\nE 1;\n");
  const std::string without = dir.write("without", "E 1;\n");
  for (const std::string& path : {with, without}) {
    const Dictionary d = Dictionary::read(path);
    CHECK(d.getScalar("E") == 1);
    CHECK_NOTHROW(d.checkAllRead());
  }
  const std::string binary = dir.write("binary", "FoamFile\n{\n    format binary;\n}\nE 1;\n");
  CHECK(inputErrorOf([&] { Dictionary::read(binary); }) ==
        binary + ":3: FoamFile: format 'binary' is not read (expected 'ascii')");
}

// ---------------------------------------------------------------------------------------
// Suggestions
// ---------------------------------------------------------------------------------------

TEST_CASE("edit distance counts a swap of neighbours as one slip and ignores case",
          "[dict][suggest]") {
  CHECK(editDistance("fractrues", "fractures") == 1);
  CHECK(editDistance("tolerence", "tolerance") == 1);
  CHECK(editDistance("writeVtk", "writeVTK") == 0);
  CHECK(editDistance("ab", "ba") == 1);
  CHECK(editDistance("", "abc") == 3);
  CHECK(editDistance("tolerance", "zeta") == 7);
  CHECK(editDistance("adjoint", "exact") == 6);
  CHECK(typoDistance(2) == 1);
  CHECK(typoDistance(9) == 3);
  CHECK(closestMatch("tolerance", {"zeta", "gamma", "gradient"}).empty());
  CHECK(closestMatch("adjoint", {"exact", "frozenRho"}).empty());
  CHECK(closestMatch("nus", {"E", "nu"}) == "nu");
  CHECK(suggestionText("coulmb", {"tresca", "coulomb"}) == "; did you mean 'coulomb'?");
  CHECK(suggestionText("Youngs", {"E", "nu"}).empty());
}

TEST_CASE("a choice far from every valid one gets no 'did you mean'", "[dict][suggest]") {
  const Dictionary d = Dictionary::parse("gradient adjoint;\nlaw coulmb;\n", "s");
  CHECK(inputErrorOf([&] {
          d.getChoice("gradient", {"exact", "frozenRho"});
        }) == "s:1: key 'gradient': unknown value 'adjoint' (valid values are: exact, frozenRho)");
  CHECK(inputErrorOf([&] {
          d.getChoice("law", {"tresca", "coulomb"});
        }) ==
        "s:2: key 'law': unknown value 'coulmb'; did you mean 'coulomb'? (valid values are: "
        "tresca, coulomb)");
  CHECK(inputErrorOf([&] { Dictionary::parse("alpha 1;\nb $tolerance;\n", "s"); }) ==
        "s:2: key 'b': undefined variable '$tolerance': no entry 'tolerance' before it in this "
        "or an enclosing dictionary");
}

TEST_CASE("an unknown key that another dictionary of the file reads is said to belong there",
          "[dict][suggest]") {
  const std::string text = R"(FoamFile { format ascii; }
control
{
    gamma 2;
    tolerance 1e-8;
    optimizer
    {
        type armijo;
        zeta 0;
    }
}
maxIterations 10;
)";
  const auto readAll = [](const Dictionary& d) {
    const Dictionary& control = d.subDict("control");
    control.getScalarOr("gamma", 1);
    control.getScalarOr("zeta", 0);
    const Dictionary& opt = control.subDict("optimizer");
    opt.getWord("type");
    opt.getScalarOr("tolerance", 1e-6);
    opt.getIntOr("maxIterations", 100);
  };
  const Dictionary d = Dictionary::parse(text, "system/frictionSolution");
  readAll(d);
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "system/frictionSolution:5: unknown key 'tolerance' in system/frictionSolution/control; "
        "it belongs in control/optimizer (valid keys here: gamma, optimizer, zeta)");
  d.subDict("control").values("tolerance");
  // And downwards: a key of the parent written in the sub-dictionary.
  CHECK(inputErrorOf([&] { d.checkAllRead(); }) ==
        "system/frictionSolution:9: unknown key 'zeta' in "
        "system/frictionSolution/control/optimizer; it belongs in control (valid keys here: "
        "maxIterations, tolerance, type)");
  d.subDict("control").subDict("optimizer").values("zeta");
  CHECK_THAT(inputErrorOf([&] { d.checkAllRead(); }),
             StartsWith("system/frictionSolution:12: unknown key 'maxIterations' in "
                        "system/frictionSolution; it belongs in control/optimizer"));

  SECTION("not between siblings: another patch reads 'value' because of its type") {
    const Dictionary D = Dictionary::parse(
        "boundaryField\n{\n    bottom { type fixedDisplacement; value (0 0); }\n"
        "    left { type traction; value (0 0); traction (1 0); }\n}\n",
        "0/D");
    const Dictionary& f = D.subDict("boundaryField");
    f.subDict("bottom").getWord("type");
    f.subDict("bottom").getVector("value");
    f.subDict("left").getWord("type");
    f.subDict("left").getVector("traction");
    CHECK(inputErrorOf([&] { D.checkAllRead(); }) ==
          "0/D:4: unknown key 'value' in 0/D/boundaryField/left (valid keys: traction, type)");
  }
}

// ---------------------------------------------------------------------------------------
// Alternative keys
// ---------------------------------------------------------------------------------------

TEST_CASE("keys of two alternatives are named as alternatives", "[dict][alternatives]") {
  SECTION("E with lambda") {
    const Dictionary d = Dictionary::parse("E 1e9;\nnu 0.3;\nlambda 1;\n", "mech");
    CHECK(inputErrorOf([&] { Material::read(d); }) ==
          "mech:3: keys 'E' (line 1) and 'lambda' in mech belong to alternatives: give E and nu, "
          "lambda and mu, or K and G, not both");
  }
  SECTION("a mix: lambda with nu") {
    const Dictionary d = Dictionary::parse("nu 0.3;\nlambda 1;\nmu 1;\n", "mech");
    CHECK_THAT(
        inputErrorOf([&] { Material::read(d); }),
        StartsWith("mech:2: keys 'nu' (line 1) and 'lambda' in mech belong to alternatives"));
  }
  SECTION("neither") {
    const Dictionary d = Dictionary::parse("planeStress no;\n", "mech");
    CHECK(inputErrorOf([&] { Material::read(d); }) ==
          "mech: missing keys in mech: give E and nu, lambda and mu, or K and G");
  }
  SECTION("one pair, complete or not") {
    const Material m = Material::read(Dictionary::parse("E 2.6;\nnu 0.3;\n", "mech"));
    CHECK(m.youngModulus() == Approx(2.6).epsilon(1e-14));  // E -> λ, μ -> E: rounding only
    CHECK(m.poissonRatio() == Approx(0.3).epsilon(1e-14));
    const Dictionary lame = Dictionary::parse("lambda 2;\nmu 1;\nplaneStress yes;\n", "mech");
    const Material l = Material::read(lame);
    CHECK((l.lambda() == 2 && l.mu() == 1 && l.planeStress()));
    CHECK_NOTHROW(lame.checkAllRead());
    CHECK_THAT(inputErrorOf([] { Material::read(Dictionary::parse("E 1;\n", "mech")); }),
               StartsWith("mech: missing key 'nu' in mech"));
  }
  SECTION("the generic form with a default, as for gamma and gammaRelative") {
    const Dictionary d = Dictionary::parse("gammaRelative 2;\ngamma 1;\n", "c");
    CHECK(inputErrorOf([&] {
            d.alternative({{"gamma"}, {"gammaRelative"}}, 1);
          }) ==
          "c:2: keys 'gammaRelative' (line 1) and 'gamma' in c are alternatives: give gamma, or "
          "gammaRelative, not both");
    CHECK(Dictionary::parse("zeta 0;\n", "c").alternative({{"gamma"}, {"gammaRelative"}}, 1) == 1);
    CHECK(Dictionary::parse("gamma 1;\n", "c").alternative({{"gamma"}, {"gammaRelative"}}, 1) == 0);
  }
}

// ---------------------------------------------------------------------------------------
// fracturePressure values files
// ---------------------------------------------------------------------------------------

TEST_CASE("a fracturePressure values file is read strictly, line by line", "[dict][values]") {
  TempDir dir;
  const Dictionary d = Dictionary::parse(
      "type fracturePressure;\nfracture crack;\nvalues \"constant/p.dat\";\n", "constant/effects");
  const std::string file = (dir.path() / "constant/p.dat").lexically_normal().string();
  const auto make = [&] { return Effect::New("pore", d, {"crack"}, dir.path().string(), 2); };

  SECTION("good lines, comments, blank lines, CRLF and a byte-order mark") {
    dir.write("constant/p.dat", std::string(kBom) + "# s p\r\n0 1\r\n\r\n  # mid\n1 3e0\n2\t-1\n");
    const auto e = make();
    // Linear interpolation between the rows, constant beyond the ends.
    CHECK(pressureAt(e, {-1, 0, 0.5, 1, 1.5, 2, 3}) == std::vector<double>{1, 1, 2, 3, 1, -1, -1});
  }
  struct Bad {
    const char* text;
    int line;
    const char* message;
  };
  const std::string expected = "expected two numbers 's p' (arclength [m], pressure [Pa]), got ";
  for (const Bad& b :
       {Bad{"0 1\n0.5 0,9\n", 2, "'0.5 0,9': '0,9' has a decimal comma: write 0.9"},
        Bad{"0 0,9\n", 1, "'0 0,9': '0,9' has a decimal comma: write 0.9"},
        Bad{"0 1\n1.5.3 2\n", 2, "'1.5.3 2': '1.5.3' is the number '1.5' followed by '.3'"},
        Bad{"0 1e\n", 1,
            "'0 1e': '1e' is the number '1' followed by 'e' (an exponent needs digits, e.g. 1e-3)"},
        Bad{"0 nan\n", 1, "'0 nan': 'nan' is not a finite number (nan and inf are not accepted)"},
        Bad{"0 inf\n", 1, "'0 inf': 'inf' is not a finite number (nan and inf are not accepted)"},
        Bad{"0 0x10\n", 1, "'0 0x10': '0x10' is hexadecimal: write the number in decimal"},
        Bad{"0 1e400\n", 1,
            "'0 1e400': '1e400' is out of the range of a double (nonzero magnitudes from 4.9e-324 "
            "to 1.8e308)"},
        Bad{"0 1MPa\n", 1,
            "'0 1MPa': '1MPa' is the number '1' followed by 'MPa' (numbers are written without a "
            "unit: values are in SI units)"},
        Bad{"0 one\n", 1, "'0 one': 'one' is not a number"}, Bad{"0 1 2\n", 1, "'0 1 2' (3 items)"},
        Bad{"# s p\n\n0\n", 3, "'0' (1 item)"}, Bad{"0 1 # note\n", 1, "'0 1 # note' (4 items)"},
        Bad{"0 1\n0 2\n", 2, "'0 2' after s = 0"}}) {
    DYNAMIC_SECTION(b.text) {
      dir.write("constant/p.dat", b.text);
      const bool order = std::string(b.message).find("after s =") != std::string::npos;
      CHECK(inputErrorOf(make) ==
            file + ":" + std::to_string(b.line) + ": " +
                (order ? "expected two numbers 's p' (arclength [m], pressure [Pa]) with s "
                         "increasing, got "
                       : expected) +
                b.message);
    }
  }
  SECTION("pressure and values are alternatives") {
    const Dictionary both = Dictionary::parse(
        "type fracturePressure;\nfracture crack;\npressure 1;\nvalues \"constant/p.dat\";\n",
        "constant/effects");
    CHECK(inputErrorOf([&] { Effect::New("pore", both, {"crack"}, dir.path().string(), 2); }) ==
          "constant/effects:4: keys 'pressure' (line 3) and 'values' in constant/effects are "
          "alternatives: give pressure, or values, not both");
  }
}

TEST_CASE("K and G are the third pair of constants, and other codes' names get the way forward",
          "[dict][material]") {
  // K = 5/3 GPa, G = 1 GPa: λ = K − 2G/3 = 1 GPa, μ = 1 GPa, so E = 2.5 GPa and ν = 0.25.
  const Dictionary d = Dictionary::parse("K 1.6666666666666667e9;\nG 1e9;\n", "mech");
  const Material m = Material::read(d);
  CHECK(std::abs(m.youngModulus() - 2.5e9) <= 1e-6);
  CHECK(std::abs(m.poissonRatio() - 0.25) <= 1e-15);
  CHECK_THAT(inputErrorOf([&] { Material::read(Dictionary::parse("K -1;\nG 1;\n", "mech")); }),
             StartsWith("mech:1: key 'K'"));
  CHECK(inputErrorOf(
            [&] { Material::read(Dictionary::parse("shearModulus 1e9;\nK 1e9;\n", "mech")); }) ==
        "mech:1: unknown key 'shearModulus': libfriction names it 'G'; the constants are "
        "E and nu, lambda and mu, or K and G (bulk and shear moduli) [Pa]");
  // advise(): checkAllRead gives the advice instead of a spelling guess.
  const Dictionary e = Dictionary::parse("nu 0.2;\nplaneStrain yes;\n", "mech");
  e.getScalar("nu");
  e.advise("planeStrain", "write planeStress no");
  CHECK(inputErrorOf([&] { e.checkAllRead(); }) ==
        "mech:2: unknown key 'planeStrain' in mech: write planeStress no");
}
