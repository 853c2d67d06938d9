// Constant or tabulated loads: see TimeFunction.hpp.
#include "friction/time/TimeFunction.hpp"

#include <algorithm>

namespace friction {

TimeFunction::TimeFunction(std::vector<double> constant) : x_{0.0}, y_{std::move(constant)} {}

TimeFunction TimeFunction::read(const Dictionary& dict, const std::string& key, int components) {
  const std::vector<Value>& v = dict.values(key);
  const std::string expected = components == 1   ? "a number"
                               : components == 2 ? "a vector (x y)"
                                                 : "a vector (x y z)";
  TimeFunction f;
  if (!v.empty() && v[0].isWord() && v[0].text == "table") {
    // Re-read through the typed accessor, which checks the table's shape; it expects the
    // table as the whole value, so a dictionary holding just the list is built here.
    Dictionary tmp;
    tmp.set(key, std::vector<Value>(v.begin() + 1, v.end()), dict.location(key));
    Table t = tmp.getTable(key);
    for (const auto& row : t.y)
      if (static_cast<int>(row.size()) != components)
        dict.fail(key, "key '" + key + "': table rows must hold " + expected + " after the time");
    f.x_ = std::move(t.x);
    f.y_ = std::move(t.y);
    return f;
  }
  if (components == 1) return TimeFunction({dict.getScalar(key)});
  if (components == 2) {
    const Vector2 c = dict.getVector(key);
    return TimeFunction({c.x(), c.y()});
  }
  // (x y z), also written "uniform (x y z)" as OpenFOAM does.
  const Value* b = v.data();
  if (v.size() == 2 && b->isWord() && b->text == "uniform") ++b;
  const bool ok = b + 1 == v.data() + v.size() && b->isList() && b->items.size() == 3 &&
                  b->items[0].isNumber() && b->items[1].isNumber() && b->items[2].isNumber();
  if (!ok) {
    std::string got;
    for (const Value& x : v) got += (got.empty() ? "" : " ") + x.str();
    dict.fail(key, "key '" + key + "': expected " + expected + ", got " +
                       (got.empty() ? "nothing" : got));
  }
  return TimeFunction({b->items[0].number, b->items[1].number, b->items[2].number});
}

std::vector<double> TimeFunction::operator()(double t) const {
  if (x_.size() == 1 || t <= x_.front()) return y_.front();
  if (t >= x_.back()) return y_.back();
  const auto it = std::upper_bound(x_.begin(), x_.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - x_.begin());
  const double w = (t - x_[i - 1]) / (x_[i] - x_[i - 1]);
  std::vector<double> r(y_[i].size());
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = (1 - w) * y_[i - 1][k] + w * y_[i][k];
  return r;
}

}  // namespace friction
