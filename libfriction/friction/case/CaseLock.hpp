// CaseLock: one run at a time writes a case folder. Two runs in one folder would rename time
// folders over each other's and remove each other's leftovers (issue 26: a time folder lost).
// The run that writes a case holds <case>/.frictionSolver.lock, a file naming its process and
// host ("<pid> <host> <program>"), locked with flock(2) while the run lasts:
//  * taking it is atomic: open (create) the file, then flock(LOCK_EX | LOCK_NB); the kernel
//    lets one process through, and releases it when that process ends, however it ends;
//  * a run that finds it held is refused, naming the owner (InputError, exit status 1);
//  * a file whose owner is gone (a killed run: its pid no longer exists on this host) is taken
//    over, and the log says so; a file naming a living process of this host is honoured even
//    without the flock (a lock written by hand, or a file system without flock), and one of
//    another host is refused, since its process cannot be checked from here;
//  * the destructor removes the file; so do SIGINT, SIGTERM and SIGHUP arriving while no other
//    handler is installed (outside the time loop, whose own handlers stop the run cleanly and
//    return through the destructor).
#pragma once

#include <iosfwd>
#include <string>

namespace friction {

class CaseLock {
 public:
  /// The lock file's name in a case folder.
  static constexpr const char* fileName = ".frictionSolver.lock";

  /// Take the lock of `caseDir` for this process; `program` (frictionSolver, frictionSolve)
  /// is written in the file for whoever finds it. Throws InputError naming the lock file when
  /// another run holds it (its process, its host and what to do), OutputError when the file
  /// cannot be created (a read-only case folder). A stale lock taken over is said in `log`.
  CaseLock(const std::string& caseDir, const std::string& program, std::ostream& log);
  /// Removes the lock file and restores the signal handlers it replaced.
  ~CaseLock();
  CaseLock(const CaseLock&) = delete;
  CaseLock& operator=(const CaseLock&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace friction
