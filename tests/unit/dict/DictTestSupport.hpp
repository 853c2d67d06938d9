// Helpers for the dictionary tests: a temporary folder outside the source tree, and the
// message of the InputError an action throws.
#pragma once

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <atomic>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "friction/core/InputError.hpp"

namespace friction::dicttest {

/// A fresh folder under the system's temporary folder, removed with its contents at the end.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("friction-dict-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  /// Writes text to the file name (relative to the folder, sub-folders created); returns its
  /// path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

 private:
  std::filesystem::path path_;
};

/// what() of the InputError that f throws; the test fails if f throws nothing or another type.
template <typename F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("expected an InputError, none was thrown");
  return "";
}

/// What f did, run in a child process that an alarm kills after `seconds`: "InputError: <what>",
/// "no error", "other exception: <what>", or "killed by signal N" (SIGALRM: the read blocked or
/// never ended). A reader that waits on a FIFO or reads /dev/zero for ever then fails the test
/// instead of hanging the suite. f must not use Catch2's macros (it runs in the child).
template <typename F>
std::string outcomeInChild(F&& f, unsigned seconds = 10) {
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    ::alarm(seconds);
#if !defined(__SANITIZE_ADDRESS__)
    // A reader that reads /dev/zero into memory stops at 2 GB here rather than at the machine's
    // end (not under ASan, which reserves far more address space).
    struct rlimit limit {
      std::uint64_t{2} << 30, std::uint64_t{2} << 30
    };
    ::setrlimit(RLIMIT_AS, &limit);
#endif
    std::string outcome;
    try {
      f();
      outcome = "no error";
    } catch (const InputError& e) {
      outcome = std::string("InputError: ") + e.what();
    } catch (const std::exception& e) {
      outcome = std::string("other exception: ") + e.what();
    }
    for (std::size_t done = 0; done < outcome.size();) {
      const ssize_t n = ::write(fds[1], outcome.data() + done, outcome.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::_exit(0);
  }
  REQUIRE(pid > 0);
  ::close(fds[1]);
  std::string outcome;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
    outcome.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) +
           (WTERMSIG(status) == SIGALRM ? " (SIGALRM: the read blocked or never ended)" : "");
  return outcome;
}

}  // namespace friction::dicttest
