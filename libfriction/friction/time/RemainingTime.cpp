// RemainingTime: see RemainingTime.hpp.
#include "friction/time/RemainingTime.hpp"

#include <algorithm>
#include <limits>

namespace friction {

double RemainingTime::estimate(long remaining) const {
  if (remaining <= 0) return 0.0;
  if (!ready()) return std::numeric_limits<double>::quiet_NaN();
  // The latest steps, the first step of the run left out.
  const std::size_t count = std::min(window_, steps_.size() - 1);
  double sum = 0;
  for (std::size_t i = steps_.size() - count; i < steps_.size(); ++i) sum += steps_[i];
  return sum / static_cast<double>(count) * static_cast<double>(remaining);
}

}  // namespace friction
