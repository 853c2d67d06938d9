// PointData: a value given at points at listed times, the rows "t x y [z] v" [s, m, unit of v]
// of a values file (a reservoir simulator's export), as faultPressure's and porePressure's
// `data` read it (docs/method.md §11, §12): the rows of one time together, times
// non-decreasing, any order within a time. Each place takes, per listed time, the value of the
// nearest row of that time; in time the value is linear between the listed times and constant
// beyond them. NearestPoint finds the nearest of many points (a k-d tree), so that matching a
// large export to a large mesh does not cost rows × cells.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "friction/core/Types.hpp"

namespace friction {

class Dictionary;

/// The nearest of a fixed set of points, in O(log n) per query for well spread points.
class NearestPoint {
 public:
  explicit NearestPoint(std::vector<Point> points);
  /// The index of the point nearest x (the lowest index among equally near ones, as a scan in
  /// order finds it) and its squared distance [m²]; the set must not be empty.
  std::size_t nearest(const Point& x, double& squaredDistance) const;

 private:
  void build(std::size_t lo, std::size_t hi);
  void search(const Point& x, std::size_t lo, std::size_t hi, std::size_t& best,
              double& bestD2) const;
  std::vector<Point> points_;
  std::vector<std::size_t> order_;  ///< the tree: order_[mid] splits [lo, hi) along axis_[mid]
  std::vector<int> axis_;
};

class PointData {
 public:
  struct Row {
    Point x = Point::Zero();  ///< [m] (z = 0 in 2D)
    double value = 0;
    int line = 0;  ///< in the file
  };
  /// The place of a time t among the listed ones: the value at t is
  /// v[lower] + weight (v[upper] − v[lower]), weight in [0, 1] (lower = upper, weight 0 at or
  /// before the first time and at or after the last).
  struct Bracket {
    std::size_t lower = 0, upper = 0;
    double weight = 0;
  };

  PointData() = default;
  /// Read the file named by key `key` of d (relative to caseDir) as rows of dim + 2 numbers,
  /// the last one `value` (its meaning and unit, e.g. "pressure change [Pa]", named `column`
  /// in the expected form 't x y column'). InputError at the key when the file is missing,
  /// at file:line for a row that is not dim + 2 numbers or whose time is before the previous
  /// row's.
  static PointData read(const Dictionary& d, const std::string& key, const std::string& caseDir,
                        int dim, const std::string& column, const std::string& value);

  bool empty() const { return times_.empty(); }
  const std::string& file() const { return file_; }
  /// The listed times [s], increasing.
  const std::vector<double>& times() const { return times_; }
  /// The rows of listed time j.
  const std::vector<Row>& rows(std::size_t j) const { return rows_[j]; }
  /// "data from FILE at N times", for the effects' log lines.
  std::string describe() const;

  /// Per listed time, the value of its nearest row at each of `points`.
  std::vector<Eigen::VectorXd> nearestValues(const std::vector<Point>& points) const;
  /// Where t lies among the listed times (see Bracket).
  Bracket bracket(double t) const { return bracketOf(times_, t); }
  /// Where t lies among `times` (increasing; values given at them from elsewhere, e.g. a
  /// GivenField's).
  static Bracket bracketOf(const std::vector<double>& times, double t);

  /// An InputError at the row's file:line.
  [[noreturn]] void fail(const Row& row, const std::string& what) const;

 private:
  std::string file_;
  std::vector<double> times_;
  std::vector<std::vector<Row>> rows_;  ///< per listed time, in the file's order
};

}  // namespace friction
