// Time folders appear whole or not at all (a crash never leaves a half-written time folder).
#include <catch2/catch.hpp>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "friction/core/InputError.hpp"
#include "friction/output/TimeFolder.hpp"

using namespace friction;
namespace fs = std::filesystem;

TEST_CASE("a time folder is invisible until committed and replaces an older one whole",
          "[output]") {
  const fs::path dir =
      fs::temp_directory_path() / ("friction-timefolder-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    TimeFolder f(dir.string(), "1");
    std::ofstream(f.file("fractures/a.dat")) << "x";
    CHECK_FALSE(fs::exists(dir / "1"));  // not visible while being written
  }                                      // destroyed uncommitted: as if the run died here
  CHECK_FALSE(fs::exists(dir / "1"));
  CHECK(fs::is_empty(dir));  // and no partial folder left behind

  {
    TimeFolder f(dir.string(), "1");
    std::ofstream(f.file("D")) << "old";
    f.commit();
  }
  CHECK(fs::exists(dir / "1" / "D"));
  {
    TimeFolder f(dir.string(), "1");
    std::ofstream(f.file("D")) << "new";
    std::string meanwhile;
    std::ifstream(dir / "1" / "D") >> meanwhile;
    CHECK(meanwhile == "old");  // the old folder stays whole while the new one is written
    f.commit();
  }
  std::string text;
  std::ifstream(dir / "1" / "D") >> text;
  CHECK(text == "new");
  CHECK_FALSE(fs::exists(dir / ".1.old"));
  CHECK_FALSE(fs::exists(dir / "1.old"));
  fs::remove_all(dir);
}

TEST_CASE("an unwritable case folder is a clear error", "[output]") {
  const fs::path file =
      fs::temp_directory_path() / ("friction-notadir-" + std::to_string(::getpid()));
  std::ofstream(file) << "a file where a case folder should be";
  try {
    TimeFolder f(file.string(), "1");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains(file.string()) && Catch::Contains("writable"));
  }
  fs::remove(file);
}
