#include "friction/core/StopRequest.hpp"

#include <unistd.h>

#include <signal.h>

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <mutex>
#include <thread>

#include "friction/core/Parallel.hpp"

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
  // Several ranks: the watchdog (see watch()).
  std::thread watchdog;
  std::mutex mutex;
  std::condition_variable wake;
  bool done = false;

  // A second signal is acted on by the time loop at this rank's next back-substitution, which
  // ends every rank (FrictionCase::run). But a rank can wait inside a shared call for another
  // that does not come (stopped, or stuck in the kernel writing to a dead disk), where no flag
  // is ever looked at: then, after a grace that lets the time loop say what it abandoned, the
  // watchdog ends every rank itself, with the same exit status 5.
  void watch() {
    sigset_t stops;
    sigemptyset(&stops);
    sigaddset(&stops, SIGINT);
    sigaddset(&stops, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stops, nullptr);  // the signals stay the time loop's
    const auto grace = std::chrono::seconds(2);
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
      if (second != 0) {
        if (wake.wait_for(lock, grace, [this] { return done; })) return;
        static const char message[] =
            "\nfrictionSolver: second stop request: this rank is waiting for another one in a "
            "shared call; ending every rank now, not writing the current step\n";
        (void)!::write(STDERR_FILENO, message, sizeof message - 1);
        parallel::abort(5);
      }
      // Polled: a signal handler cannot notify a condition variable.
      wake.wait_for(lock, std::chrono::milliseconds(100), [this] { return done; });
    }
  }
};

StopHandlerScope::StopHandlerScope() : saved_(new Saved) {
  first = 0;
  second = 0;
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &saved_->interrupt);
  sigaction(SIGTERM, &action, &saved_->terminate);
  if (parallel::size() > 1) saved_->watchdog = std::thread([s = saved_] { s->watch(); });
}

StopHandlerScope::~StopHandlerScope() {
  if (saved_->watchdog.joinable()) {
    {
      std::lock_guard<std::mutex> lock(saved_->mutex);
      saved_->done = true;
    }
    saved_->wake.notify_all();
    saved_->watchdog.join();
  }
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
