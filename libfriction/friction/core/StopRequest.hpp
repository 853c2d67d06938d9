// StopRequest: SIGINT/SIGTERM ask a run to stop cleanly — the time loop finishes the current
// step, writes it (atomically) and exits with a message, instead of dying mid-write.
#pragma once

namespace friction {

/// Install handlers for SIGINT and SIGTERM that only set a flag.
void installStopHandlers();
/// The signal that asked to stop, or 0.
int stopRequested();

}  // namespace friction
