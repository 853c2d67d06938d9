// StopRequest: SIGINT/SIGTERM ask a run to stop cleanly — the time loop finishes the current
// step, writes it (atomically) and exits with a message, instead of dying mid-write. A second
// signal asks to stop at once: the solve of the current step is abandoned at its next
// back-substitution (throwIfStopNow) and that step is not written.
#pragma once

#include <stdexcept>

namespace friction {

/// For its lifetime, SIGINT and SIGTERM only set a flag (and say so on stderr): the flags start
/// clear, and the handlers that were there before come back at the end. So a process that
/// runs several cases (the FreeFEM plug-in, the fuzz harness) starts each with no stop
/// request, and is interrupted as usual between them. With several ranks a watchdog thread
/// makes sure a second signal ends the run even on a rank that waits in a shared call for
/// another rank that cannot come (parallel::abort(5) after a grace of 2 s).
class StopHandlerScope {
 public:
  StopHandlerScope();
  ~StopHandlerScope();
  StopHandlerScope(const StopHandlerScope&) = delete;
  StopHandlerScope& operator=(const StopHandlerScope&) = delete;

 private:
  struct Saved;
  Saved* saved_;
};
/// The first signal that asked to stop, or 0.
int stopRequested();
/// The signal that asked to stop at once (the second one), or 0.
int stopNowRequested();

/// Thrown by throwIfStopNow(): the current step is abandoned, nothing of it is written.
class StopNow : public std::runtime_error {
 public:
  explicit StopNow(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Throws StopNow once a second SIGINT/SIGTERM arrived. Cheap: call it per solve.
void throwIfStopNow();

}  // namespace friction
