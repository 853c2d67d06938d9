// Values at points at listed times: see PointData.hpp.
#include "friction/flow/PointData.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "friction/core/InputError.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/NumberRows.hpp"

namespace friction {

namespace {
/// Ranges this short are scanned: a deeper tree would cost more than it saves.
constexpr std::size_t kLeaf = 8;
}  // namespace

NearestPoint::NearestPoint(std::vector<Point> points)
    : points_(std::move(points)), order_(points_.size()), axis_(points_.size(), 0) {
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  build(0, order_.size());
}

void NearestPoint::build(std::size_t lo, std::size_t hi) {
  if (hi - lo <= kLeaf) return;
  // Split along the axis of widest spread (a 2D set, z = 0, is never split along z).
  Point a = points_[order_[lo]], b = a;
  for (std::size_t i = lo; i < hi; ++i) {
    a = a.cwiseMin(points_[order_[i]]);
    b = b.cwiseMax(points_[order_[i]]);
  }
  int axis = 0;
  (b - a).maxCoeff(&axis);
  const std::size_t mid = lo + (hi - lo) / 2;
  std::nth_element(
      order_.begin() + static_cast<std::ptrdiff_t>(lo),
      order_.begin() + static_cast<std::ptrdiff_t>(mid),
      order_.begin() + static_cast<std::ptrdiff_t>(hi),
      [this, axis](std::size_t i, std::size_t j) { return points_[i][axis] < points_[j][axis]; });
  axis_[mid] = axis;
  build(lo, mid);
  build(mid + 1, hi);
}

void NearestPoint::search(const Point& x, std::size_t lo, std::size_t hi, std::size_t& best,
                          double& bestD2) const {
  const auto consider = [&](std::size_t i) {
    const double d2 = (points_[i] - x).squaredNorm();
    if (d2 < bestD2 || (d2 == bestD2 && i < best)) bestD2 = d2, best = i;
  };
  if (hi - lo <= kLeaf) {
    for (std::size_t k = lo; k < hi; ++k) consider(order_[k]);
    return;
  }
  const std::size_t mid = lo + (hi - lo) / 2;
  consider(order_[mid]);
  const double diff = x[axis_[mid]] - points_[order_[mid]][axis_[mid]];
  const bool left = diff < 0;
  if (left)
    search(x, lo, mid, best, bestD2);
  else
    search(x, mid + 1, hi, best, bestD2);
  // The other side lies at least |diff| away; "≤" keeps the equally near ones (ties go to the
  // lowest index).
  if (diff * diff <= bestD2) {
    if (left)
      search(x, mid + 1, hi, best, bestD2);
    else
      search(x, lo, mid, best, bestD2);
  }
}

std::size_t NearestPoint::nearest(const Point& x, double& squaredDistance) const {
  std::size_t best = points_.size();
  squaredDistance = std::numeric_limits<double>::infinity();
  search(x, 0, order_.size(), best, squaredDistance);
  return best;
}

PointData PointData::read(const Dictionary& d, const std::string& key, const std::string& caseDir,
                          int dim, const std::string& column, const std::string& value) {
  PointData data;
  const std::string text = readValuesFile(d, key, caseDir, data.file_);
  const std::string form = dim == 2 ? "'t x y " + column + "'" : "'t x y z " + column + "'";
  const NumberRows rows =
      parseNumberRows(data.file_, text, static_cast<std::size_t>(dim + 2),
                      std::string("expected ") + (dim == 2 ? "four" : "five") + " numbers " + form +
                          " (time [s], position [m], " + value + ")",
                      false, "t", "no rows: expected lines " + form);
  for (std::size_t r = 0; r < rows.rows.size(); ++r) {
    const auto& row = rows.rows[r];
    if (!data.times_.empty() && row[0] < data.times_.back())
      throw InputError(SourceLocation{data.file_, rows.lines[r]},
                       "time " + formatNumber(row[0]) + " before the previous row's " +
                           formatNumber(data.times_.back()) +
                           ": list the rows of each time together, times increasing");
    if (data.times_.empty() || row[0] > data.times_.back()) {
      data.times_.push_back(row[0]);
      data.rows_.emplace_back();
    }
    Row entry;
    for (int c = 0; c < dim; ++c) entry.x[c] = row[static_cast<std::size_t>(1 + c)];
    entry.value = row[static_cast<std::size_t>(dim + 1)];
    entry.line = rows.lines[r];
    data.rows_.back().push_back(entry);
  }
  return data;
}

std::string PointData::describe() const {
  return "data from " + file_ + " at " + std::to_string(times_.size()) +
         (times_.size() == 1 ? " time" : " times");
}

std::vector<Eigen::VectorXd> PointData::nearestValues(const std::vector<Point>& points) const {
  std::vector<Eigen::VectorXd> out;
  for (const std::vector<Row>& rows : rows_) {
    std::vector<Point> x;
    for (const Row& r : rows) x.push_back(r.x);
    const NearestPoint tree(std::move(x));
    Eigen::VectorXd v(static_cast<Eigen::Index>(points.size()));
    double d2 = 0;
    for (std::size_t k = 0; k < points.size(); ++k)
      v[static_cast<Eigen::Index>(k)] = rows[tree.nearest(points[k], d2)].value;
    out.push_back(std::move(v));
  }
  return out;
}

PointData::Bracket PointData::bracketOf(const std::vector<double>& times, double t) {
  Bracket b;
  if (times.empty() || t <= times.front()) return b;
  if (t >= times.back()) {
    b.lower = b.upper = times.size() - 1;
    return b;
  }
  b.upper =
      static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  b.lower = b.upper - 1;
  b.weight = (t - times[b.lower]) / (times[b.upper] - times[b.lower]);
  return b;
}

void PointData::fail(const Row& row, const std::string& what) const {
  throw InputError(SourceLocation{file_, row.line}, what);
}

}  // namespace friction
