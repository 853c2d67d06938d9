// StepSchedule: a value that is constant between listed times (METHOD.md §11: well rates and
// held pressures with schedules; a shut-in is a change to 0). Both the closed forms
// (flow/ClosedForms.hpp, by superposition of step-ons) and the computed diffusion
// (flow/FaultDiffusion.hpp) read their sources through it, so the two see the same history.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "friction/core/InputError.hpp"

namespace friction {

/// v(t) = 0 for t < t₀, v_i for t_i ≤ t < t_{i+1}, v_last for t ≥ t_last (right-continuous).
/// Times strictly increasing and finite, values finite; the unit of the values is the
/// caller's (a rate [m³/s] or [m²/s], a pressure change [Pa]).
class StepSchedule {
 public:
  /// Zero at all times.
  StepSchedule() = default;
  /// (times[i], values[i]) pairs; refuses (InputError at `where`) sizes that differ, an empty
  /// list, times not strictly increasing, or a value or time that is not finite.
  StepSchedule(std::vector<double> times, std::vector<double> values, SourceLocation where = {});
  /// `value` from time `from` on (0 before).
  static StepSchedule constant(double value, double from = 0.0);

  /// v(t), right-continuous: at a listed time, the new value.
  double value(double t) const;
  /// lim v(τ) as τ → t from below: at a listed time, the value before it.
  double valueBefore(double t) const;
  /// ∫_a^b v(t) dt (b ≥ a), exact for the steps.
  double integral(double a, double b) const;
  /// The step-ons (t_i, v_i − v_{i−1}), v_{−1} = 0: v(t) = Σ_{t_i ≤ t} Δv_i. Steps of size 0
  /// are left out.
  std::vector<std::pair<double, double>> steps() const;
  /// Whether a listed time lies in [a, b).
  bool changesIn(double a, double b) const;

  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> times_;
  std::vector<double> values_;
};

}  // namespace friction
