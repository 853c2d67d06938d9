// RemainingTime: the estimate of the wall time left that frictionSolver's step lines show
// (README.md, "frictionSolver"). The first step a run computes carries one-off costs (the
// first touch of the factor's pages, operators built once per run, the first active set
// found from nothing), and a step's cost drifts as the slipping zone grows: the mean over
// all steps so far (the estimate before this class) is dominated by the first step for a
// long while (a P2 3D run: ~82.6 s promised when 3.5 s remained). So the estimate is the
// mean of the last `window` steps after the first, times the steps left, and nothing until a
// second step is known.
#pragma once

#include <cstddef>
#include <vector>

namespace friction {

class RemainingTime {
 public:
  /// window: how many of the latest steps the mean takes (≥ 1).
  explicit RemainingTime(std::size_t window = 4) : window_(window < 1 ? 1 : window) {}
  /// One more step, computed in `seconds` [s] (its own wall time, not the run's).
  void add(double seconds) { steps_.push_back(seconds); }
  /// Steps added so far.
  std::size_t steps() const { return steps_.size(); }
  /// Whether estimate() has something to say: two steps are known.
  bool ready() const { return steps_.size() >= 2; }
  /// Wall time [s] that `remaining` more steps will take: the mean of the latest `window`
  /// steps other than the first, times `remaining`. 0 when nothing remains; NaN before
  /// ready() (one step says nothing of the next).
  double estimate(long remaining) const;

 private:
  std::size_t window_;
  std::vector<double> steps_;
};

}  // namespace friction
