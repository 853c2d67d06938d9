// TimeFunction: a load value as a function of (quasi-static) time — a constant, or a table
// interpolated linearly and held constant outside its range (OpenFOAM's 'clamp').
// Dictionary forms (any number of components):
//   value  (0 -0.025);                          // constant (also: value uniform (0 -0.025);)
//   value  (0 0 -0.025);                        // three components (a 3D mesh)
//   value  1e7;                                 // scalar constant
//   value  table ((0 (0 0)) (1 (-0.02 -0.025)));
#pragma once

#include <string>
#include <vector>

#include "friction/dict/Dictionary.hpp"

namespace friction {

class TimeFunction {
 public:
  TimeFunction() = default;
  /// A constant.
  explicit TimeFunction(std::vector<double> constant);
  /// Read entry 'key' of dict; components = expected number of components (1, 2 or 3).
  static TimeFunction read(const Dictionary& dict, const std::string& key, int components);

  /// Value at time t.
  std::vector<double> operator()(double t) const;
  bool isConstant() const { return x_.size() <= 1; }
  int components() const { return static_cast<int>(y_.empty() ? 0 : y_.front().size()); }

 private:
  std::vector<double> x_;
  std::vector<std::vector<double>> y_;
};

}  // namespace friction
