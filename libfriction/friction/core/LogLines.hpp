// What makes the log talk as things happen (docs: README.md, "frictionSolver"): a stream buffer
// that passes each line on as soon as it ends, so that a log redirected to a file or a pipe
// shows a phase when it finishes and not when the C library's buffer happens to fill; the
// wall clock of a phase; and the date a run started.
#pragma once

#include <chrono>
#include <functional>
#include <ostream>
#include <streambuf>
#include <string>

namespace friction {

/// A phase of a long computation has ended: what it was ("numeric factorisation") and its wall
/// time [s]. The log prints it as it comes.
using PhaseReport = std::function<void(const std::string& phase, double seconds)>;

/// Forwards every character to `target` and flushes it after each '\n'.
class LineFlushBuffer : public std::streambuf {
 public:
  explicit LineFlushBuffer(std::streambuf* target) : target_(target) {}

 protected:
  int overflow(int c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;
  int sync() override { return target_->pubsync(); }

 private:
  std::streambuf* target_;
};

/// For its life, `stream` flushes each line as it ends (a LineFlushBuffer in front of its
/// buffer); the stream's own buffer is put back at the end of the scope.
class FlushEachLine {
 public:
  explicit FlushEachLine(std::ostream& stream);
  ~FlushEachLine();
  FlushEachLine(const FlushEachLine&) = delete;
  FlushEachLine& operator=(const FlushEachLine&) = delete;

 private:
  std::ostream& stream_;
  std::streambuf* previous_;
  LineFlushBuffer buffer_;
};

/// Wall time since construction or the last restart() [s].
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  /// The seconds so far, and start again.
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// The local date and time, "2025-03-14 09:26:53".
std::string localDateTime();

/// A duration for the log with 3 significant digits: "0.0123 s", "12.3 s", "1234 s".
std::string formatSeconds(double seconds);

}  // namespace friction
