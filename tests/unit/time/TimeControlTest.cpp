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

// ---- Steps that grow geometrically (deltaTGrowth, maxDeltaT) or are listed (times) ----

namespace {

std::string writtenNames(const TimeControl& t, long first = 1) {
  std::string written;
  for (long k = first; k <= t.numSteps(); ++k)
    if (t.writes(k)) written += t.timeName(t.time(k)) + " ";
  return written;
}

void checkRefused(const std::string& entries, const std::vector<std::string>& words) {
  INFO(entries);
  try {
    control(entries);
    FAIL("accepted");
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK_THAT(e.what(), Catch::Contains("system/controlDict:"));
    for (const std::string& w : words) CHECK_THAT(e.what(), Catch::Contains(w));
  }
}

}  // namespace

TEST_CASE("deltaTGrowth: the step ends are a geometric sequence, the last exactly endTime",
          "[time]") {
  SECTION("growth 2: ends 2^k - 1, the last step cut at endTime") {
    const TimeControl t = control("endTime 100; deltaT 1; deltaTGrowth 2;");
    CHECK(t.steps() == TimeControl::Steps::geometric);
    REQUIRE(t.numSteps() == 7);  // 1 3 7 15 31 63, then 100 (127 would pass it)
    for (long k = 1; k < 7; ++k) CHECK(t.time(k) == std::ldexp(1.0, int(k)) - 1);
    CHECK(t.time(1) == 1.0);
    CHECK(t.time(7) == 100.0);
    checkTimes(t, 1, 0);
    CHECK(t.describe() == "steps: 7, deltaT 1 growing by 2 per step to 37 (last)");
  }
  SECTION("growth 1.2 from startTime 5: step k is deltaT 1.2^(k-1)") {
    const TimeControl t = control("startTime 5; endTime 1005; deltaT 0.5; deltaTGrowth 1.2;");
    const long n = t.numSteps();
    // 0.5 (1.2^n - 1) / 0.2 >= 1000, 1.2^n >= 401, first at n = 33 (1.2^32 = 340.3).
    CHECK(n == 33);
    for (long k = 1; k < n; ++k) {
      INFO("step " << k);
      CHECK(t.time(k) == Approx(5 + 0.5 * (std::pow(1.2, double(k)) - 1) / 0.2).epsilon(1e-13));
      if (k > 1)
        CHECK((t.time(k) - t.time(k - 1)) / (t.time(k - 1) - t.time(k - 2)) ==
              Approx(1.2).epsilon(1e-10));
    }
    CHECK(t.time(n) == 1005.0);
    checkTimes(t, 1, 5);
  }
  SECTION("maxDeltaT caps the steps: 1 2 4 8, then 10s") {
    const TimeControl t = control("endTime 100; deltaT 1; deltaTGrowth 2; maxDeltaT 10;");
    // 1 3 7 15, then 25 35 ... 95, then 100.
    REQUIRE(t.numSteps() == 13);
    CHECK(t.time(4) == Approx(15));
    for (long k = 5; k <= 12; ++k) CHECK(t.time(k) == Approx(15 + 10 * (k - 4)));
    CHECK(t.time(13) == 100.0);
    checkTimes(t, 1, 0);
    CHECK(t.describe() ==
          "steps: 13, deltaT 1 growing by 2 per step up to maxDeltaT 10 (from step 5) to 10, "
          "the last 5 (cut at endTime)");
  }
  SECTION("deltaTGrowth 1 is the uniform steps, time for time and name for name") {
    const TimeControl a = control("endTime 1; deltaT 0.03; timePrecision 1;");
    const TimeControl b = control("endTime 1; deltaT 0.03; timePrecision 1; deltaTGrowth 1;");
    CHECK(b.steps() == TimeControl::Steps::uniform);
    REQUIRE(a.numSteps() == b.numSteps());
    for (long k = 0; k <= a.numSteps(); ++k) {
      CHECK(a.time(k) == b.time(k));
      CHECK(a.timeName(a.time(k)) == b.timeName(b.time(k)));
    }
    CHECK(a.precisionNote() == b.precisionNote());
    CHECK(a.describe() == "steps: 34, deltaT 0.03, the last 0.01");
  }
  SECTION("a growth whose sums overflow: two steps, and a restart between them") {
    // (g² − 1)/(g − 1) overflows to infinity; the step count and a restart must not hang
    // on it or take infinity for a step length.
    TimeControl t(control("endTime 1e10; deltaT 1e-300; deltaTGrowth 1e300;"));
    REQUIRE(t.numSteps() == 2);
    CHECK(t.time(1) == 1e-300);
    CHECK(t.time(2) == 1e10);
    CHECK(t.continueAfter(0.37, 1) == 2);
    CHECK(t.time(2) == 1e10);
  }
  SECTION("deltaT 1e-300 doubling reaches 1 in about a thousand steps") {
    const TimeControl t = control("endTime 1; deltaT 1e-300; deltaTGrowth 2;");
    CHECK(t.numSteps() > 990);
    CHECK(t.numSteps() < 1000);
    checkTimes(t, 1, 0);
  }
}

TEST_CASE("times: the step ends listed", "[time]") {
  const TimeControl t = control("startTime 0.05; times (0.1 1 10 100);");
  CHECK(t.steps() == TimeControl::Steps::listed);
  REQUIRE(t.numSteps() == 4);
  CHECK(t.endTime() == 100);
  CHECK(t.deltaT() == Approx(0.05));
  CHECK(t.time(0) == 0.05);
  CHECK(t.time(1) == 0.1);
  CHECK(t.time(2) == 1.0);
  CHECK(t.time(3) == 10.0);
  CHECK(t.time(4) == 100.0);
  checkTimes(t, 1, 0.05);
  CHECK(t.describe() == "steps: 4 at the listed times (to endTime 100), from 0.05 to 90 long");
  // endTime may be given if it is the last time.
  CHECK(control("endTime 100; times (0.1 1 10 100);").numSteps() == 4);
  // One time is one step.
  const TimeControl one = control("times (2);");
  CHECK(one.numSteps() == 1);
  CHECK(one.time(1) == 2.0);
}

TEST_CASE("geometric and listed steps: names distinct and reading back from 1e-3 s to years",
          "[time]") {
  SECTION("1e-3 s growing by 1.2 to 3e7 s (a year)") {
    const TimeControl t = control("endTime 3e7; deltaT 1e-3; deltaTGrowth 1.2;");
    CHECK(t.time(1) == 1e-3);
    CHECK(t.numSteps() < 150);                                         // not 3e10 uniform steps
    CHECK(t.time(t.numSteps() - 1) - t.time(t.numSteps() - 2) > 1e6);  // steps of weeks
    CHECK(t.timePrecision() == 6);
    checkTimes(t, 1, 0);
  }
  SECTION("capped at a year, to ten years") {
    const TimeControl t =
        control("endTime 3.2e8; deltaT 1e-3; deltaTGrowth 1.5; maxDeltaT 3.15e7;");
    CHECK(t.time(t.numSteps() - 1) - t.time(t.numSteps() - 2) == Approx(3.15e7));
    checkTimes(t, 1, 0);
  }
  SECTION("from startTime 1e5: the first steps need more digits, and the note says which") {
    const TimeControl t =
        control("startTime 1e5; endTime 3e7; deltaT 1e-3; deltaTGrowth 1.5; timePrecision 3;");
    CHECK(t.timePrecision() == 9);  // 100000.001
    CHECK(t.timeName(t.time(1)) == "100000.001");
    CHECK_THAT(t.precisionNote(), Catch::Contains("timePrecision raised to 9 (from 3)") &&
                                      Catch::Contains("the step of 0.001"));
    checkTimes(t, 1, 1e5);
  }
  SECTION("listed from milliseconds to a year") {
    const TimeControl t =
        control("times (1e-3 2e-3 1e-2 1 60 3600 86400 2592000 31536000); timePrecision 1;");
    CHECK(t.timePrecision() == 2);  // 1e-3 and 2e-3 differ in the 1st digit; 3600 and 86400 ...
    checkTimes(t, 1, 0);
  }
  SECTION("a last step cut to round-off is no step; a short one is named apart") {
    checkTimes(control("endTime 7.000001; deltaT 1; deltaTGrowth 2;"), 1, 0);
    CHECK(control("endTime 7.000000000001; deltaT 1; deltaTGrowth 2;").numSteps() == 3);
  }
}

TEST_CASE("geometric and listed steps: writes by step and by time, always the last", "[time]") {
  // Ends 1 3 7 15 31 63 100.
  CHECK(writtenNames(control("endTime 100; deltaT 1; deltaTGrowth 2; writeInterval 3;")) ==
        "7 63 100 ");
  CHECK(writtenNames(control("endTime 100; deltaT 1; deltaTGrowth 2; writeControl runTime; "
                             "writeInterval 10;")) == "15 31 63 100 ");
  CHECK(writtenNames(control("times (1 2 5 12 20 21); writeInterval 2;")) == "2 12 21 ");
  CHECK(writtenNames(control("times (1 2 5 12 20 21); writeControl runTime; writeInterval 10;")) ==
        "12 20 21 ");
}

TEST_CASE("geometric and listed steps: a restart continues on the sequence or after it", "[time]") {
  SECTION("saved on the sequence, with a later endTime: the very numbers of a whole run") {
    TimeControl t(control("endTime 1000; deltaT 1; deltaTGrowth 1.3;"));
    const TimeControl whole = control("endTime 1000; deltaT 1; deltaTGrowth 1.3;");
    const TimeControl before = control("endTime 100; deltaT 1; deltaTGrowth 1.3;");
    const long first = t.continueAfter(before.time(5), 5);
    CHECK(first == 6);
    CHECK(t.numSteps() == whole.numSteps());
    for (long k = first; k <= t.numSteps(); ++k) CHECK(t.time(k) == whole.time(k));  // bit for bit
    checkTimes(t, first, before.time(5));
  }
  SECTION("saved at the old endTime, off the sequence: the rest of the sequence") {
    // Ends of endTime 1000: 1 3 7 15 31 63 127 255 511 1000; the old run ended at 100 (step 7).
    TimeControl t(control("endTime 1000; deltaT 1; deltaTGrowth 2;"));
    const long first = t.continueAfter(100, 7);
    CHECK(first == 8);  // numbered on
    CHECK(t.time(first) == 127);
    CHECK(t.time(first + 1) == 255);
    CHECK(t.time(first + 2) == 511);
    CHECK(t.numSteps() == first + 3);
    CHECK(t.time(t.numSteps()) == 1000);
    checkTimes(t, first, 100);
    // By time, the step to 127 crosses 100 only where it starts: it writes nothing at 100.
    TimeControl runTime(control(
        "endTime 1000; deltaT 1; deltaTGrowth 2; writeControl runTime; writeInterval 200;"));
    CHECK(writtenNames(runTime, runTime.continueAfter(100, 7)) == "255 511 1000 ");
  }
  SECTION("another growth: on to the new sequence's ends after the saved time") {
    // Saved at 15 (step 4 of growth 2); growth 3 ends at 1 4 13 40 121 364 1000.
    TimeControl t(control("endTime 1000; deltaT 1; deltaTGrowth 3;"));
    const long first = t.continueAfter(15, 4);
    CHECK(first == 5);
    CHECK(t.time(first) == Approx(40));
    CHECK(t.numSteps() == 8);
    checkTimes(t, first, 15);
  }
  SECTION("a time just past a step end by round-off is on it") {
    TimeControl t(control("endTime 100; deltaT 1; deltaTGrowth 2;"));
    CHECK(t.continueAfter(15 * (1 + 1e-15), 4) == 5);
    CHECK(t.time(5) == Approx(31));
  }
  SECTION("listed: on a listed time, or off the list") {
    TimeControl on(control("times (0.1 1 10 100);"));
    CHECK(on.continueAfter(10, 3) == 4);
    CHECK(on.time(4) == 100);
    TimeControl off(control("times (5 20 50 100);"));
    const long first = off.continueAfter(10, 3);
    CHECK(first == 4);
    CHECK(off.time(first) == 20);
    CHECK(off.numSteps() == 6);
    checkTimes(off, first, 10);
  }
  SECTION("saved at endTime: nothing to compute") {
    TimeControl t(control("endTime 100; deltaT 1; deltaTGrowth 2;"));
    CHECK(t.continueAfter(100, 7) == t.numSteps() + 1);
    TimeControl l(control("times (1 2);"));
    CHECK(l.continueAfter(2, 2) == l.numSteps() + 1);
  }
}

TEST_CASE("deltaTGrowth, maxDeltaT and times refuse what they cannot run, naming the key",
          "[time]") {
  checkRefused("endTime 1; deltaT 0.1; deltaTGrowth 0.9;", {"deltaTGrowth", ">= 1", "0.9"});
  checkRefused("endTime 1; deltaT 0.1; deltaTGrowth 2; maxDeltaT 0.01;",
               {"maxDeltaT", "at least deltaT"});
  checkRefused("times (1 3 2);",
               {"times", "strictly increasing", "item 2 (2) not after item 1 (3)"});
  checkRefused("times (1 1);", {"times", "strictly increasing"});
  checkRefused("startTime 1; times (1 2);", {"times", "item 0 (1) not after startTime"});
  checkRefused("times ();", {"times", "at least one time"});
  checkRefused("times (1 a);", {"times"});
  checkRefused("deltaT 1;\ntimes (1 2);",
               {"controlDict:2", "'deltaT' (line 1) and 'times'", "not both"});
  checkRefused("times (1 2);\ndeltaTGrowth 2;",
               {"controlDict:2", "'times' (line 1) and 'deltaTGrowth'", "not both"});
  checkRefused("times (1 2); maxDeltaT 2;", {"maxDeltaT", "times", "not both"});
  checkRefused("endTime 5; times (1 2 3);",
               {"endTime", "expected the last of 'times' (3)", "got 5"});
  // Too many steps (a deltaT or a growth typed wrong), and steps a double cannot resolve.
  checkRefused("endTime 1; deltaT 1e-300; deltaTGrowth 1.0000001;",
               {"deltaT", "deltaTGrowth", "at most 10000000"});
  checkRefused("endTime 1e8; deltaT 1e-3; deltaTGrowth 1.0001; maxDeltaT 1;",
               {"deltaT", "maxDeltaT", "at most 10000000"});
  checkRefused("startTime 1e10; endTime 1e11; deltaT 1e-7; deltaTGrowth 2;",
               {"deltaT", "cannot be told apart"});
}
