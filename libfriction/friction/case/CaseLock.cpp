// The lock of a case folder: see CaseLock.hpp.
#include "friction/case/CaseLock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <signal.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <thread>

#include "friction/core/OutputError.hpp"

namespace friction {

namespace fs = std::filesystem;

namespace {

// What the signal handler needs, in storage it may read: the path of the lock this process
// holds (one at a time) and the handlers it replaced.
char lockPath[4096];
volatile std::sig_atomic_t holding = 0;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction previous[3];
bool replaced[3] = {false, false, false};

// Async-signal-safe only: unlink(2), then the default action (the process ends of the signal).
extern "C" void onSignalWhileLocked(int sig) {
  if (holding) ::unlink(lockPath);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "localhost";
  return name;
}

struct Owner {
  bool valid = false;  ///< the file names a process
  long pid = 0;
  std::string host, program;
  bool empty = true;  ///< the file holds nothing yet
};

Owner readOwner(int fd) {
  Owner o;
  char buffer[1024] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  if (n <= 0) return o;
  o.empty = false;
  std::istringstream in(std::string(buffer, static_cast<std::size_t>(n)));
  if (in >> o.pid >> o.host && o.pid > 0) o.valid = true;
  in >> o.program;
  return o;
}

// A process that has ended but that its parent has not reaped yet (a zombie: state Z in
// /proc/<pid>/stat, e.g. a rank mpirun killed a moment ago) still answers kill(pid, 0); it
// runs nothing and holds nothing, so it counts as gone.
bool zombie(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');  // the state follows the command's name in parentheses
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

bool alive(long pid) {
  return (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM) && !zombie(pid);
}

std::string describe(const Owner& o) {
  return (o.program.empty() ? std::string("a run") : o.program) + " (process " +
         std::to_string(o.pid) + " on host " + o.host + ")";
}

}  // namespace

CaseLock::CaseLock(const std::string& caseDir, const std::string& program, std::ostream& log)
    : path_((fs::path(caseDir) / fileName).string()) {
  const std::string host = hostName();
  const std::string twoRuns =
      ": two runs in one case folder would write over each other's time folders";
  for (int attempt = 0;; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0)
      throw OutputError(path_, std::string("cannot create the lock file of the case (") +
                                   std::strerror(errno) + "); expected a writable case folder");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
      // Held: its owner may be between taking the flock and writing its name.
      Owner o = readOwner(fd_);
      for (int i = 0; i < 50 && o.empty; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        o = readOwner(fd_);
      }
      ::close(fd_);
      fd_ = -1;
      throw InputError(
          path_, "the case is in use: " + (o.valid ? describe(o) : std::string("another run")) +
                     " is running in it" + twoRuns + "; wait until it ends, or stop it" +
                     (o.valid ? " (kill -TERM " + std::to_string(o.pid) + ")" : ""));
    }
    // (Another error of flock, e.g. a file system without locks: the owner's pid alone decides.)
    // The file locked must still be the one of that name: its owner removes it on leaving, and
    // a file removed after this open is nobody's lock.
    struct stat mine {
    }, named{};
    if (::fstat(fd_, &mine) != 0 || ::stat(path_.c_str(), &named) != 0 ||
        mine.st_ino != named.st_ino || mine.st_dev != named.st_dev) {
      ::close(fd_);
      fd_ = -1;
      if (attempt < 100) continue;
      throw OutputError(path_,
                        "the lock file of the case keeps being replaced: another run is "
                        "starting in it");
    }
    const Owner o = readOwner(fd_);
    const bool self = o.valid && o.pid == static_cast<long>(::getpid()) && o.host == host;
    if (o.valid && !self) {
      const std::string remove = "; if no run uses this case, remove " + path_;
      if (o.host != host) {
        ::close(fd_);
        fd_ = -1;
        throw InputError(path_, "the case is locked by " + describe(o) +
                                    ", which cannot be checked from host " + host + twoRuns +
                                    remove);
      }
      if (alive(o.pid)) {
        ::close(fd_);
        fd_ = -1;
        throw InputError(path_, "the case is in use: " + describe(o) + " is running in it" +
                                    twoRuns + "; wait until it ends, or stop it (kill -TERM " +
                                    std::to_string(o.pid) + ")" + remove +
                                    " (a killed run's number may have gone to another process)");
      }
      log << "Lock: " << path_ << " was left by " << describe(o)
          << ", which is gone (a killed run): taken over\n";
    } else if (!o.empty && !o.valid) {
      log << "Lock: " << path_ << " names no process: taken over\n";
    }
    const std::string text =
        std::to_string(::getpid()) + " " + host + " " + (program.empty() ? "run" : program) + "\n";
    if (::ftruncate(fd_, 0) != 0 ||
        ::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
      const int err = errno;
      ::close(fd_);
      fd_ = -1;
      ::unlink(path_.c_str());
      throw OutputError(path_, std::string("cannot write the lock file of the case (") +
                                   std::strerror(err) + ")");
    }
    break;
  }
  // Signals that would end the process (no handler yet) remove the file on the way.
  if (path_.size() < sizeof lockPath) {
    std::memcpy(lockPath, path_.c_str(), path_.size() + 1);
    holding = 1;
    for (int i = 0; i < 3; ++i) {
      struct sigaction current {};
      replaced[i] = false;
      if (::sigaction(kSignals[i], nullptr, &current) != 0 || current.sa_handler != SIG_DFL)
        continue;
      struct sigaction action {};
      action.sa_handler = onSignalWhileLocked;
      sigemptyset(&action.sa_mask);
      replaced[i] = ::sigaction(kSignals[i], &action, &previous[i]) == 0;
    }
  }
}

CaseLock::~CaseLock() {
  for (int i = 0; i < 3; ++i)
    if (replaced[i]) ::sigaction(kSignals[i], &previous[i], nullptr);
  holding = 0;
  // Removed while still locked: a run that opened it meanwhile finds it gone and starts over.
  struct stat mine {
  }, named{};
  if (::fstat(fd_, &mine) == 0 && ::stat(path_.c_str(), &named) == 0 &&
      mine.st_ino == named.st_ino && mine.st_dev == named.st_dev)
    ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace friction
