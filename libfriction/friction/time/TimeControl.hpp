// TimeControl: system/controlDict — the quasi-static time loop in OpenFOAM's words.
//   startFrom   startTime | latestTime;   startTime 0;
//   stopAt      endTime | writeNow | noWriteNow | nextWrite;   (re-read while running)
//   endTime     1;                        deltaT    0.1;
//   deltaTGrowth 1.2;  maxDeltaT 10;      // steps growing geometrically (default 1: uniform)
//   times (0.1 1 10 100);                 // or the step ends listed (instead of deltaT)
//   writeControl timeStep | runTime;      writeInterval 1;
//   writePrecision 8;                     timePrecision 6;
//   writeVTK    yes;                      // also VTK/ files for ParaView (default yes)
//   vtkFormat   binary;                   // their data: binary (zlib, default) | ascii
// Time is a load parameter (quasi-static): only its ratios to the load tables matter.
//
// Steps are counted in 64 bits and limited to maxSteps; time-folder names get as many
// significant digits as it takes for every time of the run to have its own name that reads
// back as that time (OpenFOAM raises timePrecision the same way, and says so).
//
// The steps: uniform (deltaT, the last one ending exactly at endTime); geometric (step j is
// deltaT·g^(j−1) long, at most maxDeltaT, so the step ends from startTime form a geometric
// sequence: the √t growth of an injection's rupture is followed with as many steps per
// decade of time from milliseconds to years); or listed (the step ends given as such).
#pragma once

#include <limits>
#include <string>
#include <vector>

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
  /// The first step's length (with `times`: the first listed time − startTime).
  double deltaT() const { return deltaT_; }
  enum class Steps { uniform, geometric, listed };
  /// uniform: deltaTGrowth 1 (the default); geometric: deltaTGrowth > 1; listed: `times`.
  Steps steps() const { return mode_; }
  double deltaTGrowth() const { return growth_; }
  /// The cap on a geometric step (infinity when maxDeltaT is not given).
  double maxDeltaT() const { return maxDeltaT_; }
  bool startFromLatest() const { return startFromLatest_; }

  enum class StopAt { endTime, writeNow, noWriteNow, nextWrite };
  StopAt stopAt() const { return stopAt_; }
  /// Re-read 'stopAt' from the controlDict file (OpenFOAM lets a user stop a running job by
  /// editing it); other keys are not re-read. Returns true if it changed.
  bool rereadStopAt(const std::string& controlDictPath);
  int writePrecision() const { return writePrecision_; }
  bool writeVTK() const { return writeVTK_; }
  /// vtkFormat: the VTK files' data compressed binary (true, the default) or ASCII.
  bool vtkBinary() const { return vtkBinary_; }

  /// Continue a run whose state was saved at `time` as step `step` (a restart). Returns the
  /// first step to compute; numSteps() + 1 when `time` is already endTime. When `time` is a
  /// step end of this controlDict (startTime + k deltaT; with deltaTGrowth or times, the k-th
  /// end of that sequence) the steps continue on it, so the times are the very numbers an
  /// uninterrupted run computes. Otherwise (deltaT, deltaTGrowth, times, endTime or startTime
  /// changed) the steps are numbered on from `step` and, uniform, run from `time` in steps
  /// of deltaT, the last one ending exactly at endTime; geometric or listed, they end at the
  /// ends of this controlDict's sequence that lie after `time` (the first step may be
  /// shorter; steps do not start growing again from deltaT). Throws InputError (deltaT)
  /// past maxSteps.
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
  /// One line for the log: "steps: 40, deltaT 1 growing by 1.2 per step to 1.47e3 (last)".
  std::string describe() const;

 private:
  /// Count the steps from origin_ and choose timePrecision_ (InputError on deltaT).
  void plan();
  /// plan() of the geometric and listed steps: timePrecision_ from every step of the run.
  void planSequence();
  /// Geometric: the step after which steps are maxDeltaT long, and the sequence's last end.
  void setUpSequence();
  /// The j-th step end of the sequence from startTime (end(0) = startTime), not clamped to
  /// endTime; geometric or listed only.
  double end(long j) const;
  /// end(j), endTime from the last end on.
  double endClamped(long j) const { return j >= lastEnd_ ? endTime_ : end(j); }
  /// Length of step j of the sequence, j ≥ 1 (not clamped): the scale of round-off there.
  double stepLength(long j) const { return end(j) - end(j - 1); }
  /// Where time t falls in the sequence, as a real index (geometric: the inverse of end()).
  double index(double t) const;
  /// The smallest j in [0, lastEnd_] with endClamped(j) ≥ t (lastEnd_ if none).
  long firstEndFrom(double t) const;
  /// "key 'deltaT'" or "key 'times'": the key an error about the steps names.
  std::string stepsKey() const;

  static constexpr double never = std::numeric_limits<double>::infinity();

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
  bool vtkBinary_ = true;
  SourceLocation deltaTWhere_;  ///< for errors found after reading (a restart)

  Steps mode_ = Steps::uniform;
  double growth_ = 1, maxDeltaT_ = never;
  double lnGrowth_ = 0;        ///< log(deltaTGrowth), computed once
  std::vector<double> times_;  ///< listed: the step ends
  long capStep_ = 0;           ///< geometric: steps after this one are maxDeltaT long
  long lastEnd_ = 1;           ///< geometric or listed: the index of endTime in the sequence
  long offset_ = 0;            ///< geometric or listed: step k ends at end(k + offset_)
  double noteGap_ = 0, noteTime_ = 0;  ///< the step that raised timePrecision the most
};

}  // namespace friction
