// Piecewise-constant schedules: see StepSchedule.hpp.
#include "friction/flow/StepSchedule.hpp"

#include <algorithm>
#include <cmath>

#include "friction/core/Suggest.hpp"

namespace friction {

StepSchedule::StepSchedule(std::vector<double> times, std::vector<double> values,
                           SourceLocation where)
    : times_(std::move(times)), values_(std::move(values)) {
  if (times_.size() != values_.size())
    throw InputError(where, "a schedule needs one value per time; got " +
                                std::to_string(times_.size()) + " times and " +
                                std::to_string(values_.size()) + " values");
  if (times_.empty()) throw InputError(where, "a schedule needs at least one (time value) pair");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || !std::isfinite(values_[i]))
      throw InputError(where, "schedule entry " + std::to_string(i) + " (" +
                                  formatNumber(times_[i]) + " " + formatNumber(values_[i]) +
                                  "): expected finite numbers");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw InputError(where, "schedule times must increase strictly; entry " + std::to_string(i) +
                                  " has time " + formatNumber(times_[i]) + " after " +
                                  formatNumber(times_[i - 1]));
  }
}

StepSchedule StepSchedule::constant(double value, double from) {
  return StepSchedule({from}, {value});
}

double StepSchedule::value(double t) const {
  // The last listed time ≤ t.
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  return it == times_.begin() ? 0.0 : values_[static_cast<std::size_t>(it - times_.begin()) - 1];
}

double StepSchedule::valueBefore(double t) const {
  // The last listed time < t.
  const auto it = std::lower_bound(times_.begin(), times_.end(), t);
  return it == times_.begin() ? 0.0 : values_[static_cast<std::size_t>(it - times_.begin()) - 1];
}

double StepSchedule::integral(double a, double b) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < times_.size(); ++i) {
    const double lo = std::max(a, times_[i]);
    const double hi = i + 1 < times_.size() ? std::min(b, times_[i + 1]) : b;
    if (hi > lo) sum += values_[i] * (hi - lo);
  }
  return sum;
}

std::vector<std::pair<double, double>> StepSchedule::steps() const {
  std::vector<std::pair<double, double>> s;
  double previous = 0.0;
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (values_[i] != previous) s.emplace_back(times_[i], values_[i] - previous);
    previous = values_[i];
  }
  return s;
}

bool StepSchedule::changesIn(double a, double b) const {
  const auto it = std::lower_bound(times_.begin(), times_.end(), a);
  return it != times_.end() && *it < b;
}

}  // namespace friction
