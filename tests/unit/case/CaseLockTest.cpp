// The lock of a case folder (CaseLock.hpp): one run at a time. Held while the owner lives
// (by its flock, or by its pid when a file names a living process of this host), refused with
// the owner named; taken over when the owner is gone; removed at the end and on a signal.
#include <catch2/catch.hpp>
#include <chrono>
#include <iterator>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "friction/case/CaseLock.hpp"
#include "friction/core/OutputError.hpp"

using namespace friction;
namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string host() {
  char name[256] = {};
  ::gethostname(name, sizeof name - 1);
  return name;
}

// A fresh folder per test.
struct Folder {
  fs::path dir;
  explicit Folder(const std::string& name)
      : dir(fs::temp_directory_path() /
            ("friction-lock-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Folder() { fs::remove_all(dir); }
  fs::path lock() const { return dir / CaseLock::fileName; }
};

// The message of the InputError (not an OutputError) that taking the lock throws.
std::string refusal(const Folder& f) {
  std::ostringstream log;
  try {
    CaseLock again(f.dir.string(), "frictionSolver", log);
  } catch (const OutputError& e) {
    FAIL("an output error, expected a refusal: " << e.what());
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("the lock was taken twice");
  return "";
}

}  // namespace

TEST_CASE("a case lock names its owner while held and is gone after", "[case][lock]") {
  Folder f("held");
  std::ostringstream log;
  {
    CaseLock lock(f.dir.string(), "frictionSolver", log);
    REQUIRE(fs::exists(f.lock()));
    CHECK(readAll(f.lock()) == std::to_string(::getpid()) + " " + host() + " frictionSolver\n");
    // A second run (here: a second lock of this process, which flock tells apart) is refused.
    const std::string why = refusal(f);
    CHECK_THAT(why, Catch::Contains(f.lock().string()) && Catch::Contains("in use") &&
                        Catch::Contains("process " + std::to_string(::getpid())));
  }
  CHECK_FALSE(fs::exists(f.lock()));
  CHECK(log.str().empty());
}

TEST_CASE("a lock file naming a living process of this host is honoured", "[case][lock]") {
  Folder f("living");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::pause();  // lives until killed
    ::_exit(0);
  }
  const std::string text = std::to_string(child) + " " + host() + "\n";
  std::ofstream(f.lock()) << text;
  const std::string why = refusal(f);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  CHECK_THAT(why, Catch::Contains("in use") && Catch::Contains(std::to_string(child)) &&
                      Catch::Contains("remove " + f.lock().string()));
  CHECK(readAll(f.lock()) == text);  // the refused run left it as it was
}

TEST_CASE("a lock of another host is refused", "[case][lock]") {
  Folder f("host");
  std::ofstream(f.lock()) << "1 some-other-host frictionSolver\n";
  const std::string why = refusal(f);
  CHECK_THAT(why, Catch::Contains("some-other-host") && Catch::Contains("remove"));
}

TEST_CASE("a lock left by a process that is gone is taken over", "[case][lock]") {
  Folder f("stale");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);  // reaped: its pid names no process now
  std::ofstream(f.lock()) << child << " " << host() << " frictionSolver\n";
  std::ostringstream log;
  {
    CaseLock lock(f.dir.string(), "frictionSolver", log);
    CHECK(readAll(f.lock()).rfind(std::to_string(::getpid()) + " ", 0) == 0);
  }
  CHECK_THAT(log.str(), Catch::Contains("taken over") && Catch::Contains(std::to_string(child)));
  CHECK_FALSE(fs::exists(f.lock()));
}

TEST_CASE("a lock left by a process that has ended but is not reaped is taken over",
          "[case][lock]") {
  // A rank mpirun has just killed may linger as a zombie until its parent reaps it: it still
  // answers kill(pid, 0), runs nothing and holds nothing.
  Folder f("zombie");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) ::_exit(0);
  // Until the child has ended (state Z), it is a living holder.
  for (int i = 0; i < 2000; ++i) {
    std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
    const std::string text((std::istreambuf_iterator<char>(stat)),
                           std::istreambuf_iterator<char>());
    if (text.find(") Z ") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::ofstream(f.lock()) << child << " " << host() << " frictionSolver\n";
  std::ostringstream log;
  {
    CaseLock lock(f.dir.string(), "frictionSolver", log);
    CHECK(readAll(f.lock()).rfind(std::to_string(::getpid()) + " ", 0) == 0);
  }
  ::waitpid(child, nullptr, 0);
  CHECK_THAT(log.str(), Catch::Contains("taken over") && Catch::Contains(std::to_string(child)));
}

TEST_CASE("SIGTERM outside the time loop removes the lock", "[case][lock]") {
  Folder f("signal");
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::signal(SIGTERM, SIG_DFL);
    std::ostringstream log;
    CaseLock lock(f.dir.string(), "frictionSolver", log);
    (void)!::write(fds[1], "x", 1);
    ::pause();  // killed here, the lock held
    ::_exit(0);
  }
  char c = 0;
  REQUIRE(::read(fds[0], &c, 1) == 1);
  REQUIRE(fs::exists(f.lock()));
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  ::close(fds[0]);
  ::close(fds[1]);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);  // it still dies of the signal
  CHECK_FALSE(fs::exists(f.lock()));
}

TEST_CASE("a case folder where the lock cannot be created is an output error", "[case][lock]") {
  const fs::path missing = fs::temp_directory_path() / "friction-lock-missing" / "case";
  fs::remove_all(missing.parent_path());
  std::ostringstream log;
  CHECK_THROWS_AS(CaseLock(missing.string(), "frictionSolver", log), OutputError);
}
