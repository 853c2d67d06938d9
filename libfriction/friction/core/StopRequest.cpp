#include "friction/core/StopRequest.hpp"

#include <unistd.h>

#include <signal.h>

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

struct StopHandlerScope::Saved {
  struct sigaction interrupt, terminate;
};

StopHandlerScope::StopHandlerScope() : saved_(new Saved) {
  first = 0;
  second = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &saved_->interrupt);
  sigaction(SIGTERM, &action, &saved_->terminate);
}

StopHandlerScope::~StopHandlerScope() {
  sigaction(SIGINT, &saved_->interrupt, nullptr);
  sigaction(SIGTERM, &saved_->terminate, nullptr);
  delete saved_;
}

int stopRequested() { return first; }
int stopNowRequested() { return second; }

StopNow::StopNow(int signal)
    : std::runtime_error(signal == SIGINT ? "SIGINT" : "SIGTERM"), signal_(signal) {}

void throwIfStopNow() {
  if (second != 0) throw StopNow(second);
}

}  // namespace friction
