// TimeControl: system/controlDict — the quasi-static time loop in OpenFOAM's words.
//   startFrom   startTime | latestTime;   startTime 0;
//   stopAt      endTime | writeNow | noWriteNow | nextWrite;   (re-read while running)
//   endTime     1;                        deltaT    0.1;
//   writeControl timeStep | runTime;      writeInterval 1;
//   writePrecision 8;                     timePrecision 6;
//   writeVTK    yes;                      // also VTK/ files for ParaView (default yes)
// Time is a load parameter (quasi-static): only its ratios to the load tables matter.
//
// Steps are counted in 64 bits and limited to maxSteps; time-folder names get as many
// significant digits as it takes for every time of the run to have its own name that reads
// back as that time (OpenFOAM raises timePrecision the same way, and says so).
#pragma once

#include <string>

#include "friction/core/InputError.hpp"
#include "friction/dict/Dictionary.hpp"

namespace friction {

class TimeControl {
 public:
  /// More steps than this are refused (InputError on deltaT): each step writes a log line,
  /// so 10⁷ steps already mean ~2 GB of log and hours of run time, far beyond what a
  /// quasi-static load history needs; a larger count is a deltaT typed wrong.
  static constexpr long maxSteps = 10'000'000;

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
  int writePrecision() const { return writePrecision_; }
  bool writeVTK() const { return writeVTK_; }

  /// Continue a run whose state was saved at `time` as step `step` (a restart). Returns the
  /// first step to compute; numSteps() + 1 when `time` is already endTime. When `time` is a
  /// step end of this controlDict (startTime + k deltaT) the steps continue on that grid, so
  /// the times are the very numbers an uninterrupted run computes; otherwise (deltaT or
  /// startTime changed) they run from `time` in steps of deltaT, numbered on from `step`,
  /// the last one ending exactly at endTime. Throws InputError (deltaT) past maxSteps.
  long continueAfter(double time, long step);

  /// Number of the last step (it ends exactly at endTime; it may be shorter than deltaT).
  long numSteps() const { return numSteps_; }
  /// Time at the end of step k; step numSteps() ends exactly at endTime.
  double time(long k) const;
  /// Whether step k writes a time folder. The last step always writes (users expect the
  /// end state on disk even when endTime is not a multiple of writeInterval).
  bool writes(long k) const;
  /// Folder name of a time: OpenFOAM's general format with timePrecision() significant
  /// digits.
  std::string timeName(double t) const;
  /// The digits of time names: the controlDict's timePrecision, raised if the times of this
  /// run need more to stay distinct.
  int timePrecision() const { return timePrecision_; }
  /// "timePrecision raised to N ..." when it was raised, else "".
  std::string precisionNote() const;

 private:
  /// Count the steps from origin_ and choose timePrecision_ (InputError on deltaT).
  void plan();

  double startTime_ = 0, endTime_ = 1, deltaT_ = 1;
  double origin_ = 0;    ///< time at the end of step originStep_ (startTime, or a restart time)
  long originStep_ = 0;  ///< steps after it end at origin_ + (k − originStep_) deltaT
  long numSteps_ = 1;
  bool startFromLatest_ = false;
  StopAt stopAt_ = StopAt::endTime;
  bool writeRunTime_ = false;
  double writeInterval_ = 1;
  int writePrecision_ = 8, timePrecisionAsked_ = 6, timePrecision_ = 6;
  bool writeVTK_ = true;
  SourceLocation deltaTWhere_;  ///< for errors found after reading (a restart)
};

}  // namespace friction
