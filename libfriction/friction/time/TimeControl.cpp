// The time loop's settings: see TimeControl.hpp.
#include "friction/time/TimeControl.hpp"

#include "friction/core/Suggest.hpp"

#include <algorithm>
#include <cmath>
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
  endTime_ = d.getScalar("endTime");
  if (endTime_ <= startTime_)
    d.fail("endTime", "key 'endTime': expected a time after startTime (" +
                          formatNumber(startTime_) + "), got " + formatNumber(endTime_));
  deltaT_ = d.getScalar("deltaT", Bounds::positive());
  deltaTWhere_ = d.location("deltaT");
  writeRunTime_ = d.getChoiceOr("writeControl", {"timeStep", "runTime"}, "timeStep") == "runTime";
  writeInterval_ = d.getScalarOr("writeInterval", 1.0, Bounds::positive());
  if (!writeRunTime_ && writeInterval_ != std::floor(writeInterval_))
    d.fail("writeInterval",
           "key 'writeInterval': with writeControl timeStep, expected a whole "
           "number of steps");
  writePrecision_ = static_cast<int>(d.getIntOr("writePrecision", 8, {1, 17}));
  timePrecisionAsked_ = static_cast<int>(d.getIntOr("timePrecision", 6, {1, 17}));
  writeVTK_ = d.getBoolOr("writeVTK", true);
  origin_ = startTime_;
  plan();
}

void TimeControl::plan() {
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

std::string TimeControl::precisionNote() const {
  if (timePrecision_ == timePrecisionAsked_) return "";
  return "timePrecision raised to " + std::to_string(timePrecision_) + " (from " +
         std::to_string(timePrecisionAsked_) +
         ") so that every time of the run has its own "
         "folder name (steps of " +
         formatNumber(deltaT_) + " up to time " + formatNumber(endTime_) + ")";
}

long TimeControl::continueAfter(double t, long step) {
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
  return k >= numSteps_ ? endTime_ : origin_ + static_cast<double>(k - originStep_) * deltaT_;
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
