#include "friction/core/StopRequest.hpp"

#include <csignal>

namespace friction {

namespace {
volatile std::sig_atomic_t requested = 0;
extern "C" void onStopSignal(int sig) { requested = sig; }
}  // namespace

void installStopHandlers() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
}

int stopRequested() { return requested; }

}  // namespace friction
