// The time loop's settings: see TimeControl.hpp.
#include "friction/time/TimeControl.hpp"

#include "friction/core/Suggest.hpp"

#include <cmath>
#include <sstream>

namespace friction {

namespace {

std::vector<std::string> stopAtNames() { return {"endTime", "writeNow", "noWriteNow", "nextWrite"}; }

TimeControl::StopAt parseStopAt(const std::string& w) {
  if (w == "writeNow") return TimeControl::StopAt::writeNow;
  if (w == "noWriteNow") return TimeControl::StopAt::noWriteNow;
  if (w == "nextWrite") return TimeControl::StopAt::nextWrite;
  return TimeControl::StopAt::endTime;
}

}  // namespace

TimeControl::TimeControl(double startTime, double endTime, double deltaT)
    : startTime_(startTime), endTime_(endTime), deltaT_(deltaT) {}

TimeControl::TimeControl(const Dictionary& d) {
  if (d.found("application")) d.getWord("application");
  startFromLatest_ = d.getChoiceOr("startFrom", {"startTime", "latestTime"}, "startTime") ==
                     "latestTime";
  startTime_ = d.getScalarOr("startTime", 0.0);
  stopAt_ = parseStopAt(d.getChoiceOr("stopAt", stopAtNames(), "endTime"));
  endTime_ = d.getScalar("endTime");
  if (endTime_ <= startTime_)
    d.fail("endTime", "key 'endTime': expected a time after startTime (" +
                          formatNumber(startTime_) + "), got " + formatNumber(endTime_));
  deltaT_ = d.getScalar("deltaT", Bounds::positive());
  writeRunTime_ = d.getChoiceOr("writeControl", {"timeStep", "runTime"}, "timeStep") == "runTime";
  writeInterval_ = d.getScalarOr("writeInterval", 1.0, Bounds::positive());
  if (!writeRunTime_ && writeInterval_ != std::floor(writeInterval_))
    d.fail("writeInterval", "key 'writeInterval': with writeControl timeStep, expected a whole "
                            "number of steps");
  writePrecision_ = static_cast<int>(d.getIntOr("writePrecision", 8, {1, 17}));
  timePrecision_ = static_cast<int>(d.getIntOr("timePrecision", 6, {1, 17}));
  writeVTK_ = d.getBoolOr("writeVTK", true);
}

int TimeControl::numSteps() const {
  // A step shorter than 1e-9 deltaT at the end is round-off, not a step.
  return std::max(1, static_cast<int>(std::ceil((endTime_ - startTime_) / deltaT_ - 1e-9)));
}

double TimeControl::time(int k) const {
  return k >= numSteps() ? endTime_ : startTime_ + k * deltaT_;
}

bool TimeControl::writes(int k) const {
  if (k >= numSteps()) return true;
  if (!writeRunTime_) return k % static_cast<int>(writeInterval_) == 0;
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

}  // namespace friction

namespace friction {

bool TimeControl::rereadStopAt(const std::string& controlDictPath) {
  const Dictionary d = Dictionary::read(controlDictPath);
  const StopAt before = stopAt_;
  stopAt_ = parseStopAt(d.getChoiceOr("stopAt", stopAtNames(), "endTime"));
  d.markAllRead();
  return stopAt_ != before;
}

int TimeControl::stepOf(double t) const {
  if (t >= endTime_) return numSteps();
  return static_cast<int>(std::lround((t - startTime_) / deltaT_));
}

}  // namespace friction
