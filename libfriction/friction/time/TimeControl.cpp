// The time loop's settings: see TimeControl.hpp.
#include "friction/time/TimeControl.hpp"

#include "friction/core/Suggest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace friction {

namespace {

std::vector<std::string> stopAtNames() {
  return {"endTime", "writeNow", "noWriteNow", "nextWrite"};
}

TimeControl::StopAt parseStopAt(const std::string& w) {
  if (w == "writeNow") return TimeControl::StopAt::writeNow;
  if (w == "noWriteNow") return TimeControl::StopAt::noWriteNow;
  if (w == "nextWrite") return TimeControl::StopAt::nextWrite;
  return TimeControl::StopAt::endTime;
}

constexpr long noCap = std::numeric_limits<long>::max();

/// Three significant digits for the log, exponents without padding: 1.47e3, 2.5e-5.
std::string brief(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  std::string s = buffer;
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  return s.substr(0, e) + "e" + std::to_string(std::atoi(s.c_str() + e + 1));
}

}  // namespace

TimeControl::TimeControl(double startTime, double endTime, double deltaT)
    : startTime_(startTime), endTime_(endTime), deltaT_(deltaT), origin_(startTime) {
  plan();
}

TimeControl::TimeControl(const Dictionary& d) {
  if (d.found("application")) d.getWord("application");
  startFromLatest_ =
      d.getChoiceOr("startFrom", {"startTime", "latestTime"}, "startTime") == "latestTime";
  startTime_ = d.getScalarOr("startTime", 0.0);
  stopAt_ = parseStopAt(d.getChoiceOr("stopAt", stopAtNames(), "endTime"));
  if (d.found("times")) {
    // The step ends listed: deltaT and its companions describe steps another way.
    times_ = d.getScalarList("times");
    deltaTWhere_ = d.location("times");
    for (const std::string key : {"deltaT", "deltaTGrowth", "maxDeltaT"})
      if (d.found(key)) {
        const SourceLocation other = d.location(key);
        const bool timesFirst = deltaTWhere_.line < other.line;
        throw InputError(timesFirst ? other : deltaTWhere_,
                         "keys '" + (timesFirst ? std::string("times") : key) + "' (line " +
                             std::to_string(std::min(deltaTWhere_.line, other.line)) + ") and '" +
                             (timesFirst ? key : std::string("times")) + "' in " + d.scope() +
                             " are alternatives: give the step ends as times, or the steps as "
                             "deltaT (with deltaTGrowth, maxDeltaT), not both");
      }
    if (times_.empty())
      d.fail("times", "key 'times': expected at least one time (the step ends), e.g. (1 10 100)");
    if (times_.size() > static_cast<std::size_t>(maxSteps))
      d.fail("times", "key 'times': " + std::to_string(times_.size()) + " times; at most " +
                          std::to_string(maxSteps) + " steps are run (one log line each)");
    for (std::size_t i = 0; i < times_.size(); ++i) {
      const double before = i == 0 ? startTime_ : times_[i - 1];
      if (!(times_[i] > before))
        d.fail("times",
               "key 'times': expected strictly increasing times after startTime (" +
                   formatNumber(startTime_) + "), got item " + std::to_string(i) + " (" +
                   formatNumber(times_[i]) + ") not after " +
                   (i == 0 ? std::string("startTime")
                           : "item " + std::to_string(i - 1) + " (" + formatNumber(before) + ")"));
    }
    endTime_ = times_.back();
    if (d.found("endTime") && d.getScalar("endTime") != endTime_)
      d.fail("endTime", "key 'endTime': expected the last of 'times' (" + formatNumber(endTime_) +
                            ") or no endTime, got " + formatNumber(d.getScalar("endTime")));
    deltaT_ = times_.front() - startTime_;
    mode_ = Steps::listed;
  } else {
    endTime_ = d.getScalar("endTime");
    if (endTime_ <= startTime_)
      d.fail("endTime", "key 'endTime': expected a time after startTime (" +
                            formatNumber(startTime_) + "), got " + formatNumber(endTime_));
    deltaT_ = d.getScalar("deltaT", Bounds::positive());
    deltaTWhere_ = d.location("deltaT");
    growth_ = d.getScalarOr("deltaTGrowth", 1.0, {1.0, never});
    if (d.found("maxDeltaT")) {
      maxDeltaT_ = d.getScalar("maxDeltaT", Bounds::positive());
      if (maxDeltaT_ < deltaT_)
        d.fail("maxDeltaT", "key 'maxDeltaT': expected at least deltaT (" + formatNumber(deltaT_) +
                                "), got " + formatNumber(maxDeltaT_));
    }
    if (growth_ > 1) mode_ = Steps::geometric;
  }
  writeRunTime_ = d.getChoiceOr("writeControl", {"timeStep", "runTime"}, "timeStep") == "runTime";
  writeInterval_ = d.getScalarOr("writeInterval", 1.0, Bounds::positive());
  if (!writeRunTime_ && writeInterval_ != std::floor(writeInterval_))
    d.fail("writeInterval",
           "key 'writeInterval': with writeControl timeStep, expected a whole "
           "number of steps");
  writePrecision_ = static_cast<int>(d.getIntOr("writePrecision", 8, {1, 17}));
  timePrecisionAsked_ = static_cast<int>(d.getIntOr("timePrecision", 6, {1, 17}));
  writeVTK_ = d.getBoolOr("writeVTK", true);
  vtkBinary_ = d.getChoiceOr("vtkFormat", {"binary", "ascii"}, "binary") == "binary";
  origin_ = startTime_;
  if (mode_ != Steps::uniform) setUpSequence();
  plan();
}

void TimeControl::plan() {
  if (mode_ != Steps::uniform) return planSequence();
  // A step shorter than 1e-9 deltaT at the end is round-off, not a step. The count is
  // judged as a double: a deltaT typed wrong must not wrap a counter into "one step".
  const double count = std::max(1.0, std::ceil((endTime_ - origin_) / deltaT_ - 1e-9));
  if (!(count <= static_cast<double>(maxSteps)))
    throw InputError(deltaTWhere_,
                     "key 'deltaT': " + formatNumber(deltaT_) + " makes " + formatNumber(count) +
                         " steps from time " + formatNumber(origin_) + " to endTime " +
                         formatNumber(endTime_) + "; at most " + std::to_string(maxSteps) +
                         " are run (one log line each): expected a larger deltaT");
  numSteps_ = originStep_ + static_cast<long>(count);

  // A name with p significant digits is off by at most half a unit in its p-th digit; below
  // half the smallest gap between two step ends, every name is distinct and reads back
  // nearer its own time than any other. (The last step may be the shortest.) Times before
  // the last step are bounded by the larger of its start and the step before it; endTime,
  // often a round number, is checked as it is.
  double gap = deltaT_;
  const double beforeLast = time(numSteps_ - 1);
  if (endTime_ - beforeLast > 0) gap = std::min(gap, endTime_ - beforeLast);
  const double inner = std::max(std::abs(origin_), std::abs(beforeLast));
  const auto distinct = [&](int p) {
    if (inner > 0 && std::pow(10.0, std::floor(std::log10(inner)) - p + 1) >= gap) return false;
    std::ostringstream name;
    name.precision(p);
    name << endTime_;
    return std::abs(std::strtod(name.str().c_str(), nullptr) - endTime_) < gap / 2;
  };
  int needed = 1;
  while (needed <= 17 && !distinct(needed)) ++needed;
  if (needed > 17)
    throw InputError(deltaTWhere_,
                     "key 'deltaT': steps of " + formatNumber(gap) + " at times up to " +
                         formatNumber(std::max(inner, std::abs(endTime_))) +
                         " cannot be told apart (a double has about 16 significant digits): "
                         "expected a larger deltaT");
  timePrecision_ = std::max(timePrecisionAsked_, needed);
}

std::string TimeControl::stepsKey() const {
  return mode_ == Steps::listed ? "key 'times'" : "key 'deltaT'";
}

double TimeControl::end(long j) const {
  if (j <= 0) return startTime_;
  if (mode_ == Steps::listed)
    return times_[static_cast<std::size_t>(std::min(j, static_cast<long>(times_.size()))) - 1];
  // Σ_{i<j} deltaT g^i = deltaT (g^j − 1)/(g − 1), every end computed afresh (no running
  // sum), so a restart on the sequence gets the same numbers. While g^j < 2, expm1 avoids the
  // cancellation in g^j − 1 (g near 1); beyond, pow is the more accurate (a few ulps, and
  // exact for g = 2: ends 1 3 7 15 ...).
  if (j == 1) return startTime_ + deltaT_;
  const long grown = std::min(j, capStep_);
  const double power = static_cast<double>(grown) * lnGrowth_;
  double sum = grown == 1 ? deltaT_
               : power < std::log(2.0)
                   ? deltaT_ * std::expm1(power) / (growth_ - 1)
                   : deltaT_ * (std::pow(growth_, static_cast<double>(grown)) - 1) / (growth_ - 1);
  if (j > capStep_) sum += static_cast<double>(j - capStep_) * maxDeltaT_;
  return startTime_ + sum;
}

double TimeControl::index(double t) const {
  const double u = t - startTime_;
  if (!(u > 0)) return 0;
  const double capped = capStep_ == noCap ? never : end(capStep_) - startTime_;
  if (u <= capped) {
    const double r = u / deltaT_ * (growth_ - 1);  // in logarithms where it overflows
    return (r < never ? std::log1p(r) : std::log(u) - std::log(deltaT_) + std::log(growth_ - 1)) /
           lnGrowth_;
  }
  return static_cast<double>(capStep_) + (u - capped) / maxDeltaT_;
}

long TimeControl::firstEndFrom(double t) const {
  if (mode_ == Steps::listed) {
    if (t <= startTime_) return 0;
    const auto at = std::lower_bound(times_.begin(), times_.end(), t);
    return std::min(static_cast<long>(at - times_.begin()) + 1, lastEnd_);
  }
  const double x = index(t);
  long j = !(x < static_cast<double>(lastEnd_)) ? lastEnd_
                                                : std::max(0L, static_cast<long>(std::ceil(x)));
  while (j > 0 && endClamped(j - 1) >= t) --j;
  while (j < lastEnd_ && endClamped(j) < t) ++j;
  return j;
}

void TimeControl::setUpSequence() {
  if (mode_ == Steps::listed) {
    lastEnd_ = static_cast<long>(times_.size());
    return;
  }
  lnGrowth_ = std::log1p(growth_ - 1);
  capStep_ = noCap;
  if (maxDeltaT_ < never) {
    // Step j is deltaT g^(j−1) long while that is at most maxDeltaT.
    const double x = 1 + std::log(maxDeltaT_ / deltaT_) / lnGrowth_;
    if (x < 1e15) {
      long c = std::max(1L, static_cast<long>(std::floor(x)));
      while (deltaT_ * std::pow(growth_, static_cast<double>(c)) <= maxDeltaT_) ++c;
      while (c > 1 && deltaT_ * std::pow(growth_, static_cast<double>(c - 1)) > maxDeltaT_) --c;
      capStep_ = c;
    }
  }
  // The last step ends at endTime: the first end within round-off of it (as for uniform
  // steps, a last step shorter than 1e-9 of its step is round-off). The count is judged as a
  // double first: settings typed wrong must not overflow a counter.
  const double x = index(endTime_);
  const auto refuse = [&](double count) {
    const bool capped = capStep_ != noCap && static_cast<double>(capStep_) < count;
    throw InputError(deltaTWhere_,
                     "key 'deltaT': " + formatNumber(deltaT_) + " growing by " +
                         formatNumber(growth_) + " per step (deltaTGrowth)" +
                         (capped ? " up to maxDeltaT " + formatNumber(maxDeltaT_) : "") +
                         " makes " + formatNumber(std::ceil(count)) + " steps from time " +
                         formatNumber(startTime_) + " to endTime " + formatNumber(endTime_) +
                         "; at most " + std::to_string(maxSteps) +
                         " are run (one log line each): expected a larger deltaT" +
                         (capped ? ", deltaTGrowth or maxDeltaT" : " or deltaTGrowth"));
  };
  if (!(x <= 2.0 * static_cast<double>(maxSteps))) refuse(x);
  const auto reaches = [&](long j) {
    const double e = end(j);  // may overflow to infinity for a huge growth: then it reaches
    return e >= endTime_ || e >= endTime_ - 1e-9 * stepLength(j);
  };
  long last = std::max(1L, static_cast<long>(std::ceil(x)));
  while (last > 1 && reaches(last - 1)) --last;
  while (last <= maxSteps && !reaches(last)) ++last;
  if (last > maxSteps) refuse(static_cast<double>(last));
  lastEnd_ = last;
}

void TimeControl::planSequence() {
  numSteps_ = lastEnd_ - offset_;
  // As plan(): a name with p significant digits is off by at most half a unit in its p-th
  // digit, so each step's length must exceed that unit at both of its ends; step by step,
  // for the steps differ. endTime, often a round number, is checked by its name.
  int needed = 1;
  double previous = time(originStep_);
  const auto tooClose = [&](long k, double from) {
    // The step's own length: a computed gap may have vanished in round-off.
    const long j = k + offset_;
    const double step = mode_ == Steps::listed ? time(k) - from
                        : j > capStep_         ? maxDeltaT_
                                       : deltaT_ * std::pow(growth_, static_cast<double>(j - 1));
    return InputError(
        deltaTWhere_,
        stepsKey() + ": the step of " + formatNumber(step) + " after time " + formatNumber(from) +
            " cannot be told apart from its start (a double has about 16 "
            "significant digits): " +
            (mode_ == Steps::listed ? "expected times further apart" : "expected a larger deltaT"));
  };
  for (long k = originStep_ + 1; k <= numSteps_; ++k) {
    const double current = time(k), gap = current - previous;
    const double size =
        k < numSteps_ ? std::max(std::abs(previous), std::abs(current)) : std::abs(previous);
    const auto distinct = [&](int p) {
      return gap > 0 && (size == 0 || std::pow(10.0, std::floor(std::log10(size)) - p + 1) < gap);
    };
    bool raised = false;
    for (; needed <= 17 && !distinct(needed); raised = true) ++needed;
    if (needed > 17) throw tooClose(k, previous);
    if (raised) noteGap_ = gap, noteTime_ = current;
    if (k < numSteps_) previous = current;
  }
  const double lastGap = endTime_ - previous;
  const auto endNamed = [&](int p) {
    std::ostringstream name;
    name.precision(p);
    name << endTime_;
    return std::abs(std::strtod(name.str().c_str(), nullptr) - endTime_) < lastGap / 2;
  };
  bool raised = false;
  for (; needed <= 17 && !endNamed(needed); raised = true) ++needed;
  if (needed > 17) throw tooClose(numSteps_, previous);
  if (raised) noteGap_ = lastGap, noteTime_ = endTime_;
  timePrecision_ = std::max(timePrecisionAsked_, needed);
}

std::string TimeControl::precisionNote() const {
  if (timePrecision_ == timePrecisionAsked_) return "";
  if (mode_ != Steps::uniform)
    return "timePrecision raised to " + std::to_string(timePrecision_) + " (from " +
           std::to_string(timePrecisionAsked_) +
           ") so that every time of the run has its own folder name (the step of " +
           brief(noteGap_) + " to time " + formatNumber(noteTime_) + ")";
  return "timePrecision raised to " + std::to_string(timePrecision_) + " (from " +
         std::to_string(timePrecisionAsked_) +
         ") so that every time of the run has its own "
         "folder name (steps of " +
         formatNumber(deltaT_) + " up to time " + formatNumber(endTime_) + ")";
}

long TimeControl::continueAfter(double t, long step) {
  if (mode_ != Steps::uniform) {
    if (t >= endTime_ - 1e-9 * (endTime_ - endClamped(lastEnd_ - 1))) return numSteps_ + 1;
    const long j = firstEndFrom(t);
    // On the sequence (to round-off of the step there): continue on it, numbered as it is.
    for (const long i : {j, j - 1})
      if (i >= 0 && std::abs(endClamped(i) - t) <=
                        1e-9 * (endClamped(std::max(i, 1L)) - endClamped(std::max(i, 1L) - 1)))
        return i + 1 - offset_;
    // Off it: the sequence's ends after t, numbered on from step.
    origin_ = t;
    originStep_ = step;
    offset_ = std::max(j, 1L) - step - 1;
    plan();
    return step + 1;
  }
  if (t >= endTime_ - 1e-9 * deltaT_) return numSteps_ + 1;
  const double k = std::round((t - startTime_) / deltaT_);
  if (k >= 0 && std::abs(startTime_ + k * deltaT_ - t) <= 1e-9 * deltaT_)
    return static_cast<long>(k) + 1;
  origin_ = t;
  originStep_ = step;
  plan();
  return step + 1;
}

double TimeControl::time(long k) const {
  if (mode_ != Steps::uniform && k < numSteps_)
    return k <= originStep_ ? origin_ : end(k + offset_);
  return k >= numSteps_ ? endTime_ : origin_ + static_cast<double>(k - originStep_) * deltaT_;
}

std::string TimeControl::describe() const {
  const long first = originStep_ + 1;
  const double last = endTime_ - time(numSteps_ - 1);
  std::string s = "steps: " + std::to_string(numSteps_);
  switch (mode_) {
    case Steps::uniform:
      s += ", deltaT " + formatNumber(deltaT_);
      if (std::abs(last - deltaT_) > 1e-9 * deltaT_) s += ", the last " + brief(last);
      break;
    case Steps::geometric: {
      s += ", deltaT " + formatNumber(deltaT_) + " growing by " + formatNumber(growth_) +
           " per step";
      if (capStep_ < lastEnd_)
        s += " up to maxDeltaT " + formatNumber(maxDeltaT_) + " (from step " +
             std::to_string(capStep_ + 1 - offset_) + ")";
      // The last step is cut at endTime: when that makes it shorter, it is not the largest,
      // and the line says both.
      const double before = time(numSteps_ - 1) - time(numSteps_ - 2);
      if (last >= before)
        s += " to " + brief(last) + " (last)";
      else
        s += " to " + brief(before) + ", the last " + brief(last) + " (cut at endTime)";
      break;
    }
    case Steps::listed: {
      double shortest = never, longest = 0;
      for (long k = first; k <= numSteps_; ++k) {
        shortest = std::min(shortest, time(k) - time(k - 1));
        longest = std::max(longest, time(k) - time(k - 1));
      }
      s += " at the listed times (to endTime " + formatNumber(endTime_) + "), from " +
           brief(shortest) + " to " + brief(longest) + " long";
      break;
    }
  }
  return s;
}

bool TimeControl::writes(long k) const {
  if (k >= numSteps_) return true;
  if (!writeRunTime_) return k % static_cast<long>(writeInterval_) == 0;
  // runTime: write when this step crosses a multiple of writeInterval.
  const double before = (time(k - 1) - startTime_) / writeInterval_;
  const double after = (time(k) - startTime_) / writeInterval_;
  return std::floor(after + 1e-9) > std::floor(before + 1e-9);
}

std::string TimeControl::timeName(double t) const {
  std::ostringstream s;
  s.precision(timePrecision_);
  s << t;  // general format, like OpenFOAM's default timeFormat
  return s.str();
}

bool TimeControl::rereadStopAt(const std::string& controlDictPath) {
  const Dictionary d = Dictionary::read(controlDictPath);
  const StopAt before = stopAt_;
  stopAt_ = parseStopAt(d.getChoiceOr("stopAt", stopAtNames(), "endTime"));
  d.markAllRead();
  return stopAt_ != before;
}

}  // namespace friction
