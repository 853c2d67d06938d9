// Time arithmetic of system/controlDict: step counts, time-folder names, restarts.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/time/TimeControl.hpp"

using namespace friction;

namespace {

TimeControl control(const std::string& entries) {
  const Dictionary d = Dictionary::parse(entries, "system/controlDict");
  TimeControl t(d);
  d.checkAllRead();
  return t;
}

// Every time the run computes from step `first` on has a name of its own, and that name
// reads back nearer its time than any other step's (so a folder, a restart and a history line
// name one step). Also: times strictly increase, the last is endTime exactly.
void checkTimes(const TimeControl& t, long first, double before) {
  REQUIRE(first <= t.numSteps());
  std::set<std::string> names;
  double previous = before;
  for (long k = first; k <= t.numSteps(); ++k) {
    const double time = t.time(k);
    INFO("step " << k << " time " << time);
    REQUIRE(time > previous);
    const std::string name = t.timeName(time);
    INFO("name " << name);
    CHECK(names.insert(name).second);
    const double back = std::strtod(name.c_str(), nullptr);
    const double next = k < t.numSteps() ? t.time(k + 1) : INFINITY;
    CHECK(std::abs(back - time) < (time - previous) / 2);
    CHECK(std::abs(back - time) < (next - time) / 2);
    previous = time;
  }
  CHECK(t.time(t.numSteps()) == t.endTime());
  CHECK(t.timeName(t.time(t.numSteps())) == t.timeName(t.endTime()));
}

}  // namespace

TEST_CASE("a deltaT that makes absurdly many steps is refused, naming deltaT", "[time]") {
  // 1e10 steps overflowed a 32-bit counter into "one step" (exit 0).
  for (const char* dt : {"1e-10", "1e-300", "4.9e-324"}) {
    INFO("deltaT " << dt);
    try {
      control(std::string("endTime 1; deltaT ") + dt + ";");
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("system/controlDict:1") && Catch::Contains("deltaT") &&
                               Catch::Contains("at most 10000000"));
    }
  }
  // The limit itself is run, every step of it counted.
  const TimeControl t = control("endTime 1; deltaT 1e-7;");
  CHECK(t.numSteps() == TimeControl::maxSteps);
  CHECK(t.time(t.numSteps()) == 1.0);
  CHECK(t.time(t.numSteps() - 1) < 1.0);
  // Beyond int: 64-bit counts in the step arithmetic (a restart numbered on from a large step).
  TimeControl big(0, 1, 0.25);
  const long far = 5'000'000'000L;
  CHECK(big.continueAfter(0.1, far) == far + 1);
  CHECK(big.numSteps() == far + 4);
  CHECK(big.time(far + 1) == Approx(0.35));
}

TEST_CASE("time-folder names stay distinct: timePrecision is raised and says so", "[time]") {
  SECTION("timePrecision 1, deltaT 0.05") {
    const TimeControl t = control("endTime 1; deltaT 0.05; timePrecision 1;");
    CHECK(t.timePrecision() == 2);
    CHECK_THAT(t.precisionNote(), Catch::Contains("timePrecision raised to 2"));
    checkTimes(t, 1, 0);
    CHECK(t.timeName(t.time(3)) == "0.15");
  }
  SECTION("startTime 100000, deltaT 0.1") {
    const TimeControl t = control("startTime 100000; endTime 100002; deltaT 0.1;");
    CHECK(t.timePrecision() > 6);
    CHECK_THAT(t.precisionNote(), Catch::Contains("timePrecision raised to"));
    checkTimes(t, 1, 100000);
    CHECK(t.timeName(t.time(1)) == "100000.1");
  }
  SECTION("the default precision is kept when it is enough") {
    const TimeControl t = control("endTime 1; deltaT 0.001;");
    CHECK(t.timePrecision() == 6);
    CHECK(t.precisionNote().empty());
    checkTimes(t, 1, 0);
  }
  SECTION("a sweep of intervals, steps, signs and asked precisions") {
    for (const char* entries :
         {"startTime -1; endTime 1; deltaT 0.001; timePrecision 2;",
          "startTime 0; endTime 1; deltaT 0.333333333; timePrecision 3;",  // last step 1e-9
          "startTime 1e5; endTime 100001; deltaT 0.0001; timePrecision 6;",
          "startTime 0; endTime 1e-6; deltaT 1e-9; timePrecision 1;",
          "startTime 1e9; endTime 1000000010; deltaT 0.25; timePrecision 6;",
          "startTime 0.05; endTime 3.05; deltaT 0.1; timePrecision 1;"}) {
      INFO(entries);
      checkTimes(control(entries), 1, control(entries).startTime());
    }
  }
  SECTION("a deltaT below what a double resolves at that time is refused") {
    try {
      control("startTime 1e10; endTime 10000000001; deltaT 1e-7;");
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("deltaT"));
    }
  }
}

TEST_CASE("a restart continues from the saved time, with the current deltaT", "[time]") {
  // Saved at time 0.5 as step 5 of deltaT 0.1.
  SECTION("the same deltaT and a later endTime: the grid of an uninterrupted run") {
    TimeControl t(0, 2, 0.1);
    const long first = t.continueAfter(0.5, 5);
    CHECK(first == 6);
    TimeControl whole(0, 2, 0.1);
    for (long k = first; k <= t.numSteps(); ++k) CHECK(t.time(k) == whole.time(k));  // bit for bit
    checkTimes(t, first, 0.5);
  }
  SECTION("a smaller deltaT") {
    TimeControl t(0, 1, 0.03);
    const long first = t.continueAfter(0.5, 5);
    CHECK(t.time(first) == Approx(0.53));
    CHECK(t.numSteps() - first + 1 == 17);  // 0.53, ..., 0.98, 1
    checkTimes(t, first, 0.5);
  }
  SECTION("a larger deltaT") {
    TimeControl t(0, 1, 0.3);
    const long first = t.continueAfter(0.5, 5);
    CHECK(first == 6);  // numbered on from the saved step
    CHECK(t.time(first) == Approx(0.8));
    CHECK(t.numSteps() == 7);
    checkTimes(t, first, 0.5);
  }
  SECTION("a deltaT whose grid passes through the saved time continues on that grid") {
    TimeControl t(0, 1, 0.25);
    const long first = t.continueAfter(0.5, 5);
    CHECK(first == 3);
    CHECK(t.time(first) == 0.75);
    checkTimes(t, first, 0.5);
  }
  SECTION("saved at endTime: nothing to compute") {
    TimeControl t(0, 1, 0.1);
    CHECK(t.continueAfter(1.0, 10) == t.numSteps() + 1);
  }
  SECTION("steps of a restart count against the limit") {
    TimeControl t(0, 1, 1e-7);
    CHECK_THROWS_AS(t.continueAfter(-1.0, 0), InputError);
  }
}

TEST_CASE("writes: every writeInterval steps, by step or by time, and always the last", "[time]") {
  const TimeControl steps = control("endTime 1; deltaT 0.1; writeInterval 3;");
  std::string written;
  for (long k = 1; k <= steps.numSteps(); ++k)
    if (steps.writes(k)) written += steps.timeName(steps.time(k)) + " ";
  CHECK(written == "0.3 0.6 0.9 1 ");
  const TimeControl runTime =
      control("endTime 1; deltaT 0.1; writeControl runTime; writeInterval 0.25;");
  written.clear();
  for (long k = 1; k <= runTime.numSteps(); ++k)
    if (runTime.writes(k)) written += runTime.timeName(runTime.time(k)) + " ";
  CHECK(written == "0.3 0.5 0.8 1 ");
}
