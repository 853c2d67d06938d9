// What a dictionary may hold is bounded (DictionaryLimits): the bytes of a file with what it
// includes, the items of one list, the items of the whole dictionary ('$' copies included).
// Beyond a bound the message names the file, the line where there is one, and the bound, at
// once (the reader keeps ~40 bytes per item: a 200 MB list used to take 30-50 s and ~8 GB before
// "out of memory" with no file named). Large data belongs in a values file, which has its own,
// larger bound. Big files are sparse (resize_file): the size is refused before anything is read.
#include <catch2/catch.hpp>

#include <string>

#include "DictTestSupport.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/NumberRows.hpp"

using namespace friction;
using namespace friction::dicttest;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// A list of n numbers on one line: "(0 1 2 ...)".
std::string listOf(std::size_t n) {
  std::string s = "(";
  for (std::size_t i = 0; i < n; ++i) s += (i ? " " : "") + std::to_string(i % 10);
  return s + ")";
}

}  // namespace

TEST_CASE("what a dictionary may hold is bounded, and the message names the file and the bound",
          "[dict][limits]") {
  TempDir dir;
  const DictionaryLimits limits = DictionaryLimits::caseFile();
  REQUIRE(limits.bytes == 8u << 20);
  REQUIRE(limits.listItems == 100'000);

  SECTION("a dictionary file above the size limit, read or included") {
    const std::string big = dir.write("big", "");
    std::filesystem::resize_file(big, (9u << 20) + 1);
    CHECK_THAT(inputErrorOf([&] { Dictionary::read(big); }),
               StartsWith(big + ": is 9.0 MiB (9437185 bytes), larger than the limit of 8 MiB "
                                "for a dictionary; data this large belongs in a values file"));
    const std::string main = dir.write("main", "a 1;\n#include \"big\"\n");
    CHECK_THAT(inputErrorOf([&] { Dictionary::read(main); }),
               StartsWith(main + ":2: #include: '" + big + "' is 9.0 MiB"));
  }
  SECTION("files that pass the limit together, at the #include that passes it") {
    // 5 MB of comment lines each: either alone is a fine dictionary.
    std::string comments;
    while (comments.size() < 5'000'000) comments += "// " + std::string(200, 'x') + "\n";
    dir.write("one", comments + "a 1;\n");
    dir.write("two", comments + "b 2;\n");
    const std::string main = dir.write("main", "#include \"one\"\n#include \"two\"\n");
    CHECK_THAT(inputErrorOf([&] { Dictionary::read(main); }),
               StartsWith(main + ":2: #include: '" + (dir.path() / "two").string() +
                          "' brings the text read for this dictionary to ") &&
                   Contains("beyond the limit of 8 MiB for a dictionary with the files it "
                            "includes"));
  }
  SECTION("a list above the item limit, written out or declared with its size") {
    CHECK_NOTHROW(Dictionary::parse("a 1;\nl " + listOf(100'000) + ";\n", "d"));
    CHECK_THAT(inputErrorOf([] { Dictionary::parse("a 1;\nl " + listOf(100'001) + ";\n", "d"); }),
               StartsWith("d:2: key 'l': the list opened here has more than 100000 items, beyond "
                          "the limit of 100000 for a list in a dictionary; data this large "
                          "belongs in a values file"));
    CHECK_THAT(inputErrorOf([] { Dictionary::parse("l\n200000\n(\n1 2\n);\n", "d"); }),
               StartsWith("d:2: key 'l': the list opened here is declared with 200000 items, "
                          "beyond the limit of 100000"));
  }
  SECTION("a dictionary that '$' copies make huge") {
    // a: 1000 items; b: 100 copies of a; c: 100 copies of b = 10^7 items from 1 kB of text.
    std::string b = "b (", c = "c (";
    for (int i = 0; i < 100; ++i) b += "$a ", c += "$b ";
    const std::string text = "a " + listOf(1000) + ";\n" + b + ");\n" + c + ");\n";
    CHECK_THAT(inputErrorOf([&] { Dictionary::parse(text, "d"); }),
               StartsWith("d:3: the dictionary holds more than 2000000 items"));
  }
  SECTION("a values file above its own, larger limit, at the key") {
    const std::string values = dir.write("p.dat", "");
    std::filesystem::resize_file(values, (64u << 20) + 1);
    const Dictionary d = Dictionary::parse("x 0;\nvalues \"p.dat\";\n", "effects");
    std::string path;
    CHECK_THAT(inputErrorOf([&] { readValuesFile(d, "values", dir.path().string(), path); }),
               StartsWith("effects:2: key 'values': '" + values +
                          "' is 64.0 MiB (67108865 bytes), larger than the limit of 64 MiB for a "
                          "values file"));
  }
  SECTION("the files the programs write have the larger bounds of data") {
    const Dictionary d = Dictionary::parse("points " + listOf(300'000) + ";\n", "splitMesh", ".",
                                           DictionaryLimits::dataFile());
    CHECK(d.getScalarList("points").size() == 300'000);
  }
}
