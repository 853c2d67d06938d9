// libFuzzer target: Dictionary::parse on arbitrary text, then every typed accessor and
// checkAllRead on what was parsed. The contract under test (Dictionary.hpp): bad input of
// any kind ends in an InputError. Any other exception, a crash, a leak, UB or a hang is a
// finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "friction/dict/Dictionary.hpp"

namespace {

// Each accessor on its own: one that throws must not stop the others from being tried.
template <typename F>
void tryAccess(F&& f) {
  try {
    f();
  } catch (const friction::InputError&) {
  }
}

void exercise(const friction::Dictionary& d, int depth) {
  // checkAllRead on a copy first, while nothing is read: it must report (or accept) without
  // crashing on whatever keys and locations the parser produced.
  tryAccess([&] { friction::Dictionary(d).checkAllRead(); });
  for (const std::string& key : d.keys()) {
    tryAccess([&] { d.location(key).str(); });
    if (d.isDict(key)) {
      // Deep nesting is bounded by the input size; the cap keeps one input cheap.
      if (depth < 16) tryAccess([&] { exercise(d.subDict(key), depth + 1); });
      tryAccess([&] { d.getScalar(key); });  // a dictionary where a value is expected
      continue;
    }
    tryAccess([&] { d.values(key); });
    tryAccess([&] { d.getScalar(key, friction::Bounds::positive()); });
    tryAccess([&] { d.getInt(key, friction::Bounds::closed(0, 10)); });
    tryAccess([&] { d.getBool(key); });
    tryAccess([&] { d.getWord(key); });
    tryAccess([&] { d.getChoice(key, {"uniform", "table", "yes"}); });
    tryAccess([&] { d.getFileName(key); });
    tryAccess([&] { d.getVector(key); });
    tryAccess([&] { d.getScalarList(key); });
    tryAccess([&] { d.getIntList(key); });
    tryAccess([&] { d.getWordList(key); });
    tryAccess([&] { d.getVectorList(key); });
    tryAccess([&] { d.getIntTupleList<2>(key); });
    tryAccess([&] { d.getIntTupleList<3>(key); });
    tryAccess([&] { d.getTable(key); });
  }
  tryAccess([&] { d.getScalarOr("absentKey", 1.0); });
  tryAccess([&] { d.checkAllRead(); });
}

// Includes resolve against an empty folder of our own, so a fuzzed '#include "x"' finds
// nothing (the missing-file path) instead of reading the working directory.
const std::string& baseDir() {
  static const std::string dir = [] {
    const auto p = std::filesystem::temp_directory_path() / "frictionFuzzDictionaryBase";
    std::filesystem::create_directories(p);
    return p.string();
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const friction::Dictionary d = friction::Dictionary::parse(text, "fuzz/dictionary", baseDir());
    exercise(d, 0);
  } catch (const friction::InputError&) {
  }
  return 0;
}
