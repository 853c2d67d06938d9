// TimeControl: system/controlDict — the quasi-static time loop in OpenFOAM's words.
//   startFrom   startTime | latestTime;   startTime 0;
//   stopAt      endTime | writeNow | noWriteNow | nextWrite;   (re-read while running)
//   endTime     1;                        deltaT    0.1;
//   writeControl timeStep | runTime;      writeInterval 1;
//   writePrecision 8;                     timePrecision 6;
//   writeVTK    yes;                      // also VTK/ files for ParaView (default yes)
// Time is a load parameter (quasi-static): only its ratios to the load tables matter.
#pragma once

#include <string>

#include "friction/dict/Dictionary.hpp"

namespace friction {

class TimeControl {
 public:
  /// Reads the keys above from dict (application, if present, is read and ignored).
  explicit TimeControl(const Dictionary& dict);
  TimeControl(double startTime, double endTime, double deltaT);

  double startTime() const { return startTime_; }
  double endTime() const { return endTime_; }
  double deltaT() const { return deltaT_; }
  bool startFromLatest() const { return startFromLatest_; }

  enum class StopAt { endTime, writeNow, noWriteNow, nextWrite };
  StopAt stopAt() const { return stopAt_; }
  /// Re-read 'stopAt' from the controlDict file (OpenFOAM lets a user stop a running job by
  /// editing it); other keys are not re-read. Returns true if it changed.
  bool rereadStopAt(const std::string& controlDictPath);
  /// The step whose end time is t (rounded: t is a time this control produced).
  int stepOf(double t) const;
  int writePrecision() const { return writePrecision_; }
  bool writeVTK() const { return writeVTK_; }

  /// Number of steps from startTime to endTime (the last one may be shorter).
  int numSteps() const;
  /// Time at the end of step k (1-based); step numSteps() ends exactly at endTime.
  double time(int k) const;
  /// Whether step k writes a time folder. The last step always writes (users expect the
  /// end state on disk even when endTime is not a multiple of writeInterval).
  bool writes(int k) const;
  /// Folder name of a time: OpenFOAM's general format with timePrecision significant digits.
  std::string timeName(double t) const;

 private:
  double startTime_ = 0, endTime_ = 1, deltaT_ = 1;
  bool startFromLatest_ = false;
  StopAt stopAt_ = StopAt::endTime;
  bool writeRunTime_ = false;
  double writeInterval_ = 1;
  int writePrecision_ = 8, timePrecision_ = 6;
  bool writeVTK_ = true;
};

}  // namespace friction
