// LogLines: each line of the log is handed on and flushed when it ends (README.md,
// "frictionSolver"), whatever the pieces it is written in.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "friction/core/LogLines.hpp"

using namespace friction;

namespace {

// A target that records what it has received at each flush.
class Recorder : public std::streambuf {
 public:
  std::string received;
  std::vector<std::string> atFlush;

 protected:
  int overflow(int c) override {
    if (c != traits_type::eof()) received.push_back(static_cast<char>(c));
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    received.append(s, static_cast<std::size_t>(n));
    return n;
  }
  int sync() override {
    atFlush.push_back(received);
    return 0;
  }
};

}  // namespace

TEST_CASE("log lines: flushed as each ends, not before", "[unit][core]") {
  Recorder target;
  std::ostream log(&target);
  {
    const FlushEachLine lines(log);
    log << "Setup: numeric " << 22.5 << " s";
    CHECK(target.atFlush.empty());  // no line has ended yet
    log << "\nSetup: complement 0.3 s\nTime = 1";
    REQUIRE(target.atFlush.size() == 2);
    CHECK(target.atFlush[0] == "Setup: numeric 22.5 s\n");
    CHECK(target.atFlush[1] == "Setup: numeric 22.5 s\nSetup: complement 0.3 s\n");
    log.put('\n');  // a character alone ends a line too
    REQUIRE(target.atFlush.size() == 3);
    CHECK(target.atFlush[2] == target.received);
    log << "tail";
  }
  // The scope's end flushes the rest and gives the stream its own buffer back.
  CHECK(target.atFlush.back() == target.received);
  CHECK(target.received.substr(target.received.size() - 4) == "tail");
  CHECK(log.rdbuf() == &target);
  log << "after";
  CHECK(target.received.substr(target.received.size() - 5) == "after");
}

TEST_CASE("log lines: durations with three digits", "[unit][core]") {
  CHECK(formatSeconds(22.4567) == "22.5 s");
  CHECK(formatSeconds(0.012345) == "0.0123 s");
  CHECK(localDateTime().size() == 19);  // "2025-03-14 09:26:53"
}
