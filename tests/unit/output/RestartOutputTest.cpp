// What lies around the time folders when a run is restarted or fails to write: the .pvd and
// VTK files of times after the restart go, temporary files and folders of killed writes go,
// nothing else is touched; convergence.dat grows by whole lines or the run stops.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "friction/core/AtomicFile.hpp"
#include "friction/core/OutputError.hpp"
#include "friction/output/TimeFolder.hpp"
#include "friction/output/VtkWriter.hpp"

using namespace friction;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / (name + "-" + std::to_string(::getpid())) / "case";
  fs::remove_all(dir.parent_path());
  fs::create_directories(dir);
  return dir;
}

PvdTime pvdTime(double t, const std::string& name) {
  return {
      t,
      {"case_" + name + ".vtu", "fractures/f_" + name + ".vtp", "fractures/g&h_" + name + ".vtp"},
      {"mesh", "f", "g&h"}};
}

}  // namespace

TEST_CASE("VtkSeries::resume keeps the .pvd entries and files up to the restart time only",
          "[output]") {
  const fs::path dir = freshDir("friction-resume");
  const fs::path vtk = dir / "VTK";
  fs::create_directories(vtk / "fractures");
  const std::vector<std::string> names = {"0.1", "0.2", "0.3", "0.4"};
  std::vector<PvdTime> all;
  for (const std::string& n : names) {
    all.push_back(pvdTime(std::stod(n), n));
    for (const std::string& f : all.back().files) std::ofstream(vtk / f) << n;
  }
  // A killed run: the .pvd lists up to 0.3; 0.4's files are written, its entry is not.
  writePvd((vtk / "case.pvd").string(), {all[0], all[1], all[2]}, 12);
  std::ofstream(vtk / ".case_0.4.vtu.tmpAb3xYz") << "half";
  std::ofstream(vtk / "fractures" / ".f_0.4.vtp.tmpQ1w2E3") << "half";
  // Not the solver's: kept whatever their names.
  std::ofstream(vtk / "notes.txt") << "mine";
  std::ofstream(vtk / "other_0.4.vtu") << "mine";
  std::ofstream(vtk / "case_final.vtu") << "mine";

  VtkSeries series(dir.string());
  REQUIRE(series.caseName() == "case");
  const int removed = series.resume([](const std::string& name) { return std::stod(name) <= 0.2; },
                                    {"f", "g&h"}, 8);
  CHECK(removed == 6 + 2);  // 0.3 and 0.4: three files each; two temporary files
  for (const std::string n : {"0.1", "0.2"}) {
    CHECK(fs::exists(vtk / ("case_" + n + ".vtu")));
    CHECK(fs::exists(vtk / "fractures" / ("g&h_" + n + ".vtp")));
  }
  for (const std::string n : {"0.3", "0.4"}) {
    CHECK_FALSE(fs::exists(vtk / ("case_" + n + ".vtu")));
    CHECK_FALSE(fs::exists(vtk / "fractures" / ("f_" + n + ".vtp")));
    CHECK_FALSE(fs::exists(vtk / "fractures" / ("g&h_" + n + ".vtp")));
  }
  CHECK_FALSE(fs::exists(vtk / ".case_0.4.vtu.tmpAb3xYz"));
  CHECK_FALSE(fs::exists(vtk / "fractures" / ".f_0.4.vtp.tmpQ1w2E3"));
  for (const char* mine : {"notes.txt", "other_0.4.vtu", "case_final.vtu"})
    CHECK(fs::exists(vtk / mine));
  // The .pvd is the one an uninterrupted run had at 0.2, byte for byte.
  const fs::path expected = dir / "expected.pvd";
  writePvd(expected.string(), {all[0], all[1]}, 12);
  CHECK(readText(vtk / "case.pvd") == readText(expected));
  // So is each fracture's own collection: its files of the kept times, part 0.
  for (const std::string f : {"f", "g&h"}) {
    std::vector<PvdTime> own;
    for (const std::string n : {"0.1", "0.2"})
      own.push_back(PvdTime{std::stod(n), {f + "_" + n + ".vtp"}, {f}});
    writePvd(expected.string(), own, 12);
    CHECK(readText(vtk / "fractures" / (f + ".pvd")) == readText(expected));
  }
  fs::remove_all(dir.parent_path());
}

TEST_CASE("VtkSeries::resume with nothing kept removes the collection, and empty folders",
          "[output]") {
  const fs::path dir = freshDir("friction-resume-none");
  const fs::path vtk = dir / "VTK";
  fs::create_directories(vtk / "fractures");
  const PvdTime t = pvdTime(0.5, "0.5");
  for (const std::string& f : t.files) std::ofstream(vtk / f) << "x";
  writePvd((vtk / "case.pvd").string(), {t}, 12);
  writePvd((vtk / "fractures" / "f.pvd").string(), {PvdTime{0.5, {"f_0.5.vtp"}, {"f"}}}, 12);
  VtkSeries series(dir.string());
  // The three files of 0.5, the case's .pvd and fracture f's.
  CHECK(series.resume([](const std::string&) { return false; }, {"f", "g&h"}, 8) == 5);
  CHECK_FALSE(fs::exists(vtk));
  // And without any VTK folder it does nothing.
  CHECK(series.resume([](const std::string&) { return false; }, {"f"}, 8) == 0);
  fs::remove_all(dir.parent_path());
}

TEST_CASE("leftovers of killed writes are removed, nothing else", "[output]") {
  const fs::path dir = freshDir("friction-leftovers");
  fs::create_directories(dir / ".0.5.partial" / "uniform");
  fs::create_directories(dir / ".0.4.old");
  fs::create_directories(dir / "0.3");
  fs::create_directories(dir / ".git");
  std::ofstream(dir / ".convergence.dat.tmpAAAAAA") << "x";
  std::ofstream(dir / ".hidden") << "mine";
  std::ofstream(dir / ".x.tmp") << "mine";
  CHECK(TimeFolder::removeLeftovers(dir.string()) == 2);
  CHECK(removeTemporaryFiles(dir.string()) == 1);
  CHECK_FALSE(fs::exists(dir / ".0.5.partial"));
  CHECK_FALSE(fs::exists(dir / ".0.4.old"));
  CHECK_FALSE(fs::exists(dir / ".convergence.dat.tmpAAAAAA"));
  for (const char* kept : {"0.3", ".git", ".hidden", ".x.tmp"}) CHECK(fs::exists(dir / kept));
  fs::remove_all(dir.parent_path());
}

TEST_CASE("AppendFile grows a file by whole records or throws naming it", "[output]") {
  const fs::path dir = freshDir("friction-append");
  const fs::path path = dir / "convergence.dat";
  {
    AppendFile f(path.string(), true);
    f.append("# header\n");
    f.append("0.1 1 2 3 4\n");
    f.sync();
  }
  {
    AppendFile f(path.string(), false);
    f.append("0.2 1 2 3 4\n");
  }
  CHECK(readText(path) == "# header\n0.1 1 2 3 4\n0.2 1 2 3 4\n");
  { AppendFile f(path.string(), true); }
  CHECK(readText(path).empty());
  // A full device: /dev/full refuses every write with ENOSPC.
  if (fs::exists("/dev/full")) {
    AppendFile full("/dev/full", false);
    try {
      full.append("0.3 1 2 3 4\n");
      FAIL("no error on a full device");
    } catch (const OutputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("/dev/full") && Catch::Contains("No space left"));
    }
  }
  // A folder that is not there.
  CHECK_THROWS_AS(AppendFile((dir / "missing" / "x.dat").string(), false), OutputError);
  fs::remove_all(dir.parent_path());
}
