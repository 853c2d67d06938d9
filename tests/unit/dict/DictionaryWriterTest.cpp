// DictionaryWriter: output that Dictionary::read reads back to identical values and that
// OpenFOAM's foamDictionary parses; diff-friendly list layout; the atomic write.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace fs = std::filesystem;

namespace {

std::string fileText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Doubles that stress the conversion: non-terminating binary fractions, extremes of the
/// exponent range (up to 1e300 in magnitude, the most OpenFOAM reads), a subnormal, a signed
/// zero and integers beyond 2^53.
const std::vector<double> kHardDoubles = {0.1,
                                          1.0 / 3.0,
                                          -2.0 / 3.0,
                                          M_PI,
                                          1e-300,
                                          -1e300,
                                          std::numeric_limits<double>::denorm_min(),
                                          -0.0,
                                          9007199254740993.0,
                                          1e21,
                                          123456789.125};

DictionaryWriter sampleWriter() {
  DictionaryWriter w("dictionary", "sample", "a note with \"quotes\"");
  w.comment("values of every kind");
  w.entry("scalar", 0.1);
  w.entry("count", 42);
  w.entry("big", 9007199254740993L);
  w.entryWord("law", "coulomb");
  w.entryString("file", "constant/mesh with space.msh");
  w.entryString("multiline", "line one\nline \"two\"");
  w.entry("gravity", Vector2(0, -9.81));
  w.entry("hard", kHardDoubles);
  w.entry("ints", std::vector<int>{3, -1, 0});
  w.entryWords("names", {"left", "right", "crack_1"});
  w.beginDict("solid");
  w.entry("E", 2.5e10);
  w.beginDict("inner");
  w.entry("edges", std::vector<std::array<int, 2>>{{0, 1}, {1, 2}});
  w.endDict();
  w.endDict();
  std::vector<Vector2> points;
  for (int i = 0; i < 1000; ++i) points.emplace_back(i / 7.0, -i * 0.1);
  w.entry("points", points);
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < 20; ++i) tris.push_back({i, i + 1, i + 2});
  w.entry("triangles", tris);
  w.entry("empty", std::vector<double>{});
  w.entryRaw("field", "nonuniform List<scalar> 2(1 2)");
  return w;
}

}  // namespace

TEST_CASE("the writer's output reads back to identical values", "[dict][writer]") {
  TempDir dir;
  const std::string path = (dir.path() / "sample").string();
  sampleWriter().writeAtomic(path);

  const Dictionary d = Dictionary::read(path);
  CHECK(d.subDict("FoamFile").getWord("object") == "sample");
  CHECK(d.subDict("FoamFile").getWord("note") == "a note with \"quotes\"");
  CHECK(d.getScalar("scalar") == 0.1);
  CHECK(d.getInt("count") == 42);
  CHECK(d.getInt("big") == 9007199254740993L);
  CHECK(d.getWord("law") == "coulomb");
  CHECK(d.getFileName("file") == "constant/mesh with space.msh");
  CHECK(d.getWord("multiline") == "line one\nline \"two\"");
  CHECK(d.getVector("gravity") == Vector2(0, -9.81));
  const std::vector<double> hard = d.getScalarList("hard");
  REQUIRE(hard.size() == kHardDoubles.size());
  for (std::size_t i = 0; i < hard.size(); ++i) {
    CHECK(hard[i] == kHardDoubles[i]);  // bit-exact, sign of zero included
    CHECK(std::signbit(hard[i]) == std::signbit(kHardDoubles[i]));
  }
  CHECK(d.getIntList("ints") == std::vector<long>{3, -1, 0});
  CHECK(d.getWordList("names") == std::vector<std::string>{"left", "right", "crack_1"});
  const Dictionary& solid = d.subDict("solid");
  CHECK(solid.getScalar("E") == 2.5e10);
  CHECK(solid.subDict("inner").getIntTupleList<2>("edges") ==
        std::vector<std::array<long, 2>>{{0, 1}, {1, 2}});
  const std::vector<Vector2> points = d.getVectorList("points");
  REQUIRE(points.size() == 1000);
  for (int i = 0; i < 1000; ++i) CHECK(points[i] == Vector2(i / 7.0, -i * 0.1));
  const auto tris = d.getIntTupleList<3>("triangles");
  REQUIRE(tris.size() == 20);
  CHECK(tris[19] == std::array<long, 3>{19, 20, 21});
  CHECK(d.getScalarList("empty").empty());
  CHECK(d.getScalarList("field") == std::vector<double>{1, 2});
  CHECK_NOTHROW(d.checkAllRead());
}

TEST_CASE("long lists are written one item per line, short ones on one line", "[dict][writer]") {
  DictionaryWriter w("dictionary", "layout");
  w.entry("short", std::vector<double>{1, 2, 3});
  std::vector<Vector2> v(12, Vector2(0.5, 1));
  w.entry("vectors", v);
  w.beginDict("sub");
  w.entry("edges", std::vector<std::array<int, 2>>(11, {4, 5}));
  w.endDict();
  const std::string text = w.str();
  CHECK_THAT(text, Contains("\nshort       3(1 2 3);\n"));
  CHECK_THAT(text, Contains("\nvectors     12\n(\n    (0.5 1)\n    (0.5 1)\n"));
  CHECK_THAT(text, Contains("\n    edges       11\n    (\n        (4 5)\n"));
  // Each item on a line of its own: 12 + 11 item lines.
  std::istringstream lines(text);
  int itemLines = 0;
  for (std::string line; std::getline(lines, line);)
    if (line == "    (0.5 1)" || line == "        (4 5)") ++itemLines;
  CHECK(itemLines == 23);
}

TEST_CASE("the writer's precision and its refusals of what OpenFOAM cannot read",
          "[dict][writer]") {
  DictionaryWriter w("dictionary", "p");
  w.setPrecision(6);
  w.entry("third", 1.0 / 3.0);
  CHECK_THAT(w.str(), Contains("third       0.333333;"));
  CHECK_THROWS_AS(w.setPrecision(0), std::invalid_argument);
  CHECK_THROWS_AS(w.entry("x", std::nan("")), std::domain_error);
  CHECK_THROWS_AS(w.entry("x", std::numeric_limits<double>::infinity()), std::domain_error);
  CHECK_THROWS_AS(w.entry("x", -1.0000000000000001e301), std::domain_error);
  CHECK_THROWS_AS(w.entryWord("x", "two words"), std::invalid_argument);
  CHECK_THROWS_AS(w.entry("bad key", 1), std::invalid_argument);
  CHECK_THROWS_AS(w.entryString("x", "ends with a backslash\\"), std::invalid_argument);
  w.beginDict("open");
  CHECK_THROWS_AS(w.str(), std::logic_error);
  w.endDict();
  CHECK_THROWS_AS(w.endDict(), std::logic_error);
  CHECK_NOTHROW(w.str());
}

TEST_CASE("writeAtomic replaces the file and reports a missing or unwritable folder",
          "[dict][writer]") {
  TempDir dir;
  const fs::path path = dir.path() / "out";
  DictionaryWriter first("dictionary", "out");
  first.entry("a", 1);
  first.writeAtomic(path.string());
  DictionaryWriter second("dictionary", "out");
  second.entry("a", 2);
  second.writeAtomic(path.string());
  CHECK(fileText(path) == second.str());
  // Nothing but the file is left in the folder (no temporary files).
  CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);

  const std::string missing = (dir.path() / "absent" / "out").string();
  CHECK(inputErrorOf([&] { second.writeAtomic(missing); }) ==
        missing + ": cannot write: the folder '" + (dir.path() / "absent").string() +
            "' does not exist");

  // root may write anywhere on a normal file system: it gets /proc instead, where no file
  // can be created.
  fs::path locked = "/proc";
  if (::geteuid() != 0) {
    locked = dir.path() / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  }
  const std::string target = (locked / "out").string();
  CHECK_THAT(inputErrorOf([&] { second.writeAtomic(target); }),
             StartsWith(target + ": cannot write: cannot create a file in the folder '" +
                        locked.string() + "'"));
  if (locked != "/proc") fs::permissions(locked, fs::perms::owner_all);
}

TEST_CASE("OpenFOAM's foamDictionary reads the writer's output", "[dict][writer][openfoam]") {
  const std::string foamDictionary = "/usr/bin/foamDictionary";
  if (!fs::exists(foamDictionary))
    FAIL(foamDictionary + " is missing: install Debian's 'openfoam' package (see README.md)");

  TempDir dir;
  const fs::path path = dir.path() / "sample";
  sampleWriter().writeAtomic(path.string());

  // Runs foamDictionary on the file with args; returns its exit code and standard output.
  const auto run = [&](const std::string& args, std::string& out) {
    const fs::path outFile = dir.path() / "stdout";
    const std::string command = "WM_PROJECT_DIR=/usr/share/openfoam " + foamDictionary + " '" +
                                path.string() + "' " + args + " > '" + outFile.string() + "' 2> '" +
                                (dir.path() / "stderr").string() + "'";
    const int status = std::system(command.c_str());
    out = fileText(outFile);
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    INFO("stderr: " << fileText(dir.path() / "stderr"));
    REQUIRE(WIFEXITED(status));
    return WEXITSTATUS(status);
  };

  std::string out;
  REQUIRE(run("-keywords", out) == 0);
  CHECK(out ==
        "FoamFile\nscalar\ncount\nbig\nlaw\nfile\nmultiline\ngravity\nhard\nints\nnames\nsolid\n"
        "points\ntriangles\nempty\nfield");
  REQUIRE(run("-entry solid/E -value", out) == 0);
  CHECK(out == "2.5e+10");
  REQUIRE(run("-entry law -value", out) == 0);
  CHECK(out == "coulomb");
  REQUIRE(run("-entry gravity -value", out) == 0);
  CHECK(out == "( 0 -9.81 )");
  REQUIRE(run("-entry solid/inner -keywords", out) == 0);
  CHECK(out == "edges");
  REQUIRE(run("-entry file -value", out) == 0);
  CHECK(out == "\"constant/mesh with space.msh\"");
  // A file foamDictionary cannot parse gives exit code 1: the check above is a real one.
  std::ofstream(path) << "a (1 2;\n";
  CHECK(run("-keywords", out) == 1);
}
