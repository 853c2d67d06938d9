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
    std::ofstream(f.file("uniform/frictionState")) << "state";  // a solver's folder
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

TEST_CASE("a folder the solver did not write is never replaced", "[output]") {
  const fs::path dir =
      fs::temp_directory_path() / ("friction-timefolder-user-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto solverFolder = [&dir](const std::string& name) {
    fs::create_directories(dir / name / "uniform");
    fs::create_directories(dir / name / "fractures");
    std::ofstream(dir / name / "uniform" / "frictionState") << "state";
    std::ofstream(dir / name / "D") << "D";
    std::ofstream(dir / name / "solverStatus") << "status";
    std::ofstream(dir / name / "fractures" / "fault.dat") << "table";
  };
  solverFolder("1");
  CHECK(TimeFolder::notWrittenBySolver((dir / "1").string()).empty());
  // What makes a folder the user's: no state file, or any file the solver does not write.
  fs::create_directories(dir / "2");
  std::ofstream(dir / "2" / "notes.txt") << "notes";
  solverFolder("3");
  std::ofstream(dir / "3" / "notes.txt") << "notes";
  solverFolder("4");
  std::ofstream(dir / "4" / "fractures" / "plot.png") << "png";
  fs::create_directories(dir / "5");
  solverFolder("6");
  fs::create_directories(dir / "6" / "uniform" / "mine");
  CHECK_THAT(TimeFolder::notWrittenBySolver((dir / "2").string()), Catch::Contains("notes.txt"));
  CHECK_THAT(TimeFolder::notWrittenBySolver((dir / "3").string()), Catch::Contains("notes.txt"));
  CHECK_THAT(TimeFolder::notWrittenBySolver((dir / "4").string()),
             Catch::Contains("fractures/plot.png"));
  CHECK_THAT(TimeFolder::notWrittenBySolver((dir / "5").string()),
             Catch::Contains("uniform/frictionState"));
  CHECK_THAT(TimeFolder::notWrittenBySolver((dir / "6").string()), Catch::Contains("uniform/mine"));
  for (const std::string name : {"2", "3", "4", "5", "6"}) {
    const auto before = fs::last_write_time(dir / name);
    TimeFolder f(dir.string(), name);
    std::ofstream(f.file("uniform/frictionState")) << "new state";
    try {
      f.commit();
      FAIL("folder " << name << " was replaced");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(),
                 Catch::Contains((dir / name).string()) && Catch::Contains("not replaced"));
    }
    CHECK(fs::last_write_time(dir / name) == before);
    CHECK_FALSE(fs::exists(dir / ("." + name + ".old")));
  }
  CHECK(fs::exists(dir / "2" / "notes.txt"));
  CHECK(fs::exists(dir / "3" / "notes.txt"));
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
