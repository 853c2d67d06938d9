// Friction parameters as fields along a fracture: see FrictionField.hpp.
#include "friction/law/FrictionField.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "friction/core/Suggest.hpp"
#include "friction/dict/NumberRows.hpp"
#include "friction/fracture/FractureSystem.hpp"

namespace friction {

namespace {

std::string where(const ControlNode& n, int dim) {
  std::ostringstream s;
  s << "the fracture node at (" << formatNumber(n.position.x()) << " "
    << formatNumber(n.position.y());
  if (dim == 3) s << " " << formatNumber(n.position.z());
  s << ")";
  if (dim == 2) s << ", s = " << formatNumber(n.arclength) << " m";
  return s.str();
}

}  // namespace

std::vector<std::string> FrictionField::typeNames() { return {"arclength", "points", "depth"}; }

FrictionField FrictionField::read(const Dictionary& d, const std::string& key, Bounds bounds,
                                  const std::string& caseDir, int dim) {
  if (!d.isDict(key)) return FrictionField(d.getScalar(key, bounds));
  const Dictionary& f = d.subDict(key);
  FrictionField field;
  field.key_ = key;
  field.where_ = d.location(key);
  field.bounds_ = bounds;
  field.dim_ = dim;
  const std::string type = f.getChoice("type", typeNames());
  if (type == "arclength") {
    field.kind_ = Kind::arclength;
    if (dim == 3)
      f.fail("type",
             "key 'type': an arclength field follows a fracture curve, which a fault surface of "
             "a 3D mesh does not have; give type points or depth instead");
    if (f.alternative({{"table"}, {"file"}}) == 0) {
      const Table t = f.getTable("table");
      for (std::size_t i = 0; i < t.x.size(); ++i) {
        if (t.y[i].size() != 1)
          f.fail("table", "key 'table': expected rows (s value), one number per s");
        field.rows_.push_back({t.x[i], t.y[i][0]});
      }
    } else {
      const std::string text = readValuesFile(f, "file", caseDir, field.file_);
      const NumberRows r = parseNumberRows(
          field.file_, text, 2, "expected two numbers 's value' (arclength [m], " + key + ")", true,
          "s", "no values: expected lines 's value'");
      field.rows_ = r.rows;
    }
  } else if (type == "points") {
    field.kind_ = Kind::points;
    const std::string text = readValuesFile(f, "file", caseDir, field.file_);
    const std::string form = dim == 2 ? "'x y value'" : "'x y z value'";
    const NumberRows r = parseNumberRows(field.file_, text, static_cast<std::size_t>(dim) + 1,
                                         "expected " + std::string(dim == 2 ? "three" : "four") +
                                             " numbers " + form + " (coordinates [m], " + key + ")",
                                         false, "", "no values: expected lines " + form);
    field.rows_ = r.rows;
    field.lines_ = r.lines;
    // Two rows at one point with different values: which one a node takes would depend on the
    // rows' order, so the file is refused.
    std::vector<std::size_t> order(r.rows.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto point = [&](std::size_t i) {
      return std::vector<double>(r.rows[i].begin(), r.rows[i].begin() + dim);
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return point(a) != point(b) ? point(a) < point(b) : a < b;
    });
    for (std::size_t i = 1; i < order.size(); ++i) {
      const std::size_t a = order[i - 1], b = order[i];
      if (point(a) == point(b) && r.rows[a][dim] != r.rows[b][dim])
        throw InputError(SourceLocation{field.file_, r.lines[b]},
                         "the same point as line " + std::to_string(r.lines[a]) +
                             " with another value (" + formatNumber(r.rows[b][dim]) + ", not " +
                             formatNumber(r.rows[a][dim]) + ")");
    }
    if (f.found("maxDistance")) field.maxDistance_ = f.getScalar("maxDistance", Bounds::positive());
  } else {
    field.kind_ = Kind::depth;
    field.value_ = f.getScalar("value");
    field.gradient_ = f.getScalar("gradient");
    field.reference_ = f.getScalarOr("reference", 0.0);
  }
  f.checkAllRead();
  return field;
}

void FrictionField::failAt(const ControlNode& node, const std::string& what) const {
  throw InputError(where_, "key '" + key_ + "': " + what + " at " + where(node, dim_));
}

Eigen::VectorXd FrictionField::evaluate(const std::vector<const ControlNode*>& nodes) const {
  const Eigen::Index n = static_cast<Eigen::Index>(nodes.size());
  Eigen::VectorXd v(n);
  if (kind_ == Kind::constant) return v.setConstant(value_);
  const int vertical = dim_ - 1;
  double diagonal = 0;
  if (kind_ == Kind::points && maxDistance_ < 0 && n > 0) {
    Eigen::Vector3d lo = nodes[0]->position, hi = lo;
    for (const ControlNode* c : nodes) {
      lo = lo.cwiseMin(Eigen::Vector3d(c->position));
      hi = hi.cwiseMax(Eigen::Vector3d(c->position));
    }
    diagonal = (hi - lo).norm();
  }
  const double maxDistance = maxDistance_ >= 0 ? maxDistance_ : 1e-6 * diagonal;
  for (Eigen::Index i = 0; i < n; ++i) {
    const ControlNode& c = *nodes[i];
    switch (kind_) {
      case Kind::arclength: {
        // Covering: the rows' ends may miss the fracture's ends by round-off of the arclength
        // (summed edge lengths), 1e-9 of the table's span, no more.
        const double s = c.arclength, s0 = rows_.front()[0], s1 = rows_.back()[0];
        const double slack = 1e-9 * std::max(s1 - s0, std::abs(s1));
        if (s < s0 - slack || s > s1 + slack)
          failAt(c, "the table covers s in [" + formatNumber(s0) + ", " + formatNumber(s1) +
                        "] m, not s = " + formatNumber(s) + " m" +
                        (file_.empty() ? "" : " (" + file_ + ")"));
        if (s <= s0) {
          v[i] = rows_.front()[1];
        } else if (s >= s1) {
          v[i] = rows_.back()[1];
        } else {
          const auto it = std::upper_bound(rows_.begin(), rows_.end(), s,
                                           [](double x, const auto& r) { return x < r[0]; });
          const auto& a = *(it - 1);
          const auto& b = *it;
          // a + w (b − a): exactly a where the two rows agree, so a constant table gives the
          // number's results to the last bit.
          v[i] = a[1] + (s - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
        }
        break;
      }
      case Kind::points: {
        double best = std::numeric_limits<double>::infinity();
        std::size_t bestRow = 0;
        for (std::size_t r = 0; r < rows_.size(); ++r) {
          double d2 = 0;
          for (int k = 0; k < dim_; ++k) d2 += std::pow(rows_[r][k] - c.position[k], 2);
          if (d2 < best) best = d2, bestRow = r;
        }
        const double distance = std::sqrt(best);
        if (distance > maxDistance)
          failAt(c, "no row of " + file_ + " within maxDistance " + formatNumber(maxDistance) +
                        " m (the nearest, line " + std::to_string(lines_[bestRow]) + ", is " +
                        formatNumber(distance) +
                        " m away; list every fracture node or set maxDistance)");
        v[i] = rows_[bestRow][dim_];
        break;
      }
      case Kind::depth:
        v[i] = value_ + gradient_ * (c.position[vertical] - reference_);
        break;
      case Kind::constant:
        break;
    }
    if (!bounds_.contains(v[i]))
      failAt(c, "the value " + formatNumber(v[i]) + " is not " + bounds_.str() +
                    (file_.empty() ? "" : " (" + file_ + ")"));
  }
  return v;
}

Eigen::VectorXd FrictionField::evaluateOnFracture(const std::vector<ControlNode>& nodes, int f,
                                                  std::vector<std::size_t>& index) const {
  std::vector<const ControlNode*> on;
  index.clear();
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (nodes[k].fracture == f) on.push_back(&nodes[k]), index.push_back(k);
  return evaluate(on);
}

std::string FrictionField::describe() const {
  std::ostringstream s;
  const std::string rows =
      " (" + std::to_string(rows_.size()) + (rows_.size() == 1 ? " row)" : " rows)");
  switch (kind_) {
    case Kind::constant:
      s << value_;
      break;
    case Kind::arclength:
      s << "arclength " << (file_.empty() ? "table" : "file " + file_) << rows;
      break;
    case Kind::points:
      s << "points from " << file_ << rows;
      break;
    case Kind::depth:
      s << "depth: " << value_ << " at " << (dim_ == 2 ? "y" : "z") << " = " << reference_
        << " m, gradient " << gradient_ << " per m";
      break;
  }
  return s.str();
}

}  // namespace friction
