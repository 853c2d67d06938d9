#include "friction/core/StopRequest.hpp"

#include <unistd.h>

#include <csignal>

namespace friction {

namespace {
volatile std::sig_atomic_t first = 0, second = 0;

// Only async-signal-safe calls here: the flags and write(2).
extern "C" void onStopSignal(int sig) {
  static const char finish[] =
      "\nfrictionSolver: stop requested: finishing and writing the current step "
      "(send SIGINT or SIGTERM again to stop at once, without writing it)\n";
  static const char now[] = "\nfrictionSolver: second stop request: stopping at once\n";
  if (first == 0) {
    first = sig;
    (void)!::write(STDERR_FILENO, finish, sizeof finish - 1);
  } else if (second == 0) {
    second = sig;
    (void)!::write(STDERR_FILENO, now, sizeof now - 1);
  }
}
}  // namespace

void installStopHandlers() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
}

int stopRequested() { return first; }
int stopNowRequested() { return second; }

StopNow::StopNow(int signal)
    : std::runtime_error(signal == SIGINT ? "SIGINT" : "SIGTERM"), signal_(signal) {}

void throwIfStopNow() {
  if (second != 0) throw StopNow(second);
}

}  // namespace friction
