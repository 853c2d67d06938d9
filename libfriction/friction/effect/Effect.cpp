// Effects and their selection table: see Effect.hpp.
#include "friction/effect/Effect.hpp"

#include <algorithm>
#include <sstream>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/NumberRows.hpp"
#include "friction/effect/FaultPressure.hpp"
#include "friction/effect/PorePressure.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/MaterialMap.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

namespace {

std::string vec(const Vector2& v) {
  std::ostringstream s;
  s << "(" << v.x() << " " << v.y() << ")";
  return s.str();
}

std::string vec(const Point& v) {
  std::ostringstream s;
  s << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
  return s.str();
}

/// Key `key`: a list of exactly n numbers, `form` naming them in the message otherwise.
std::vector<double> numbers(const Dictionary& d, const std::string& key, std::size_t n,
                            const std::string& form) {
  std::vector<double> v = d.getScalarList(key);
  if (v.size() != n)
    d.fail(key, "key '" + key + "': expected " + form + ", got " + std::to_string(v.size()) +
                    (v.size() == 1 ? " number" : " numbers"));
  return v;
}

/// The symmetric tensor of (xx yy zz xy yz xz).
Eigen::Matrix3d symmetricTensor(const std::vector<double>& s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return m;
}

class BodyForce : public Effect {
 public:
  BodyForce(const std::string& name, const Dictionary& d, int dim) : dim_(dim) {
    name_ = name;
    // The density: one for the body, or per mesh region (layers have their own) with
    // `density` then the one of the regions not listed.
    if (d.found("regions")) {
      if (!d.isDict("regions"))
        d.fail("regions",
               "key 'regions': expected a sub-dictionary of one entry per mesh region, e.g. "
               "regions { reservoir { density 2300; } caprock { density 2600; } }");
      const Dictionary& entries = d.subDict("regions");
      for (const std::string& key : entries.keys()) {
        if (!entries.isDict(key))
          entries.fail(key, "key '" + key + "': expected a sub-dictionary { density ..; }");
        regions_.push_back({key, entries.location(key),
                            entries.subDict(key).getScalar("density", Bounds::positive()), -1});
      }
      if (d.found("density")) density_ = d.getScalar("density", Bounds::positive());
    } else {
      density_ = d.getScalar("density", Bounds::positive());
    }
    where_ = d.location();
    if (dim == 2) {
      g_ = d.getVector("g");
    } else {
      const std::vector<double> g = numbers(d, "g", 3, "(gx gy gz) [m/s2] on a 3D mesh");
      g3_ = Point(g[0], g[1], g[2]);
    }
  }
  std::string type() const override { return "bodyForce"; }
  std::string describe() const override {
    std::ostringstream s;
    if (regions_.empty()) {
      s << "density " << density_ << " kg/m3";
    } else {
      s << "density";
      for (const Region& r : regions_) s << " " << r.key << " " << r.density;
      if (density_ > 0) s << ", elsewhere " << density_;
      s << " kg/m3";
    }
    s << ", g " << (dim_ == 2 ? vec(g_) : vec(g3_)) << " m/s2";
    return s.str();
  }
  void setMesh(const Mesh& mesh) override {
    if (regions_.empty()) return;
    for (std::size_t i = 0; i < regions_.size(); ++i) {
      regions_[i].number = meshRegionOf(regions_[i].key, regions_[i].where, mesh);
      for (std::size_t j = 0; j < i; ++j)
        if (regions_[j].number == regions_[i].number)
          throw InputError(regions_[i].where, "region " + std::to_string(regions_[i].number) +
                                                  " has two entries, '" + regions_[j].key +
                                                  "' and '" + regions_[i].key +
                                                  "' (expected one per region)");
    }
    cellDensity_.assign(mesh.cellRegion.size(), density_);
    for (std::size_t c = 0; c < mesh.cellRegion.size(); ++c)
      for (const Region& r : regions_)
        if (mesh.cellRegion[c] == r.number) cellDensity_[c] = r.density;
    if (density_ <= 0)
      for (std::size_t c = 0; c < cellDensity_.size(); ++c)
        if (cellDensity_[c] <= 0)
          throw InputError(where_, "region " + std::to_string(mesh.cellRegion[c]) +
                                       " has no density: list it under 'regions' or give "
                                       "'density' for the regions not listed");
  }
  void addLoad(const ElasticityAssembler& a, double, Eigen::VectorXd& F) const override {
    if (!regions_.empty()) {
      const Point g = dim_ == 2 ? Point(g_.x(), g_.y(), 0.0) : g3_;
      F += a.cellBodyForce([&](Index c) {
        const std::size_t k = static_cast<std::size_t>(c);
        return Point((k < cellDensity_.size() ? cellDensity_[k] : density_) * g);
      });
      return;
    }
    if (dim_ == 2)
      F += a.bodyForce(Vector2(density_ * g_));
    else
      F += a.bodyForce(Point(density_ * g3_));
  }

 private:
  struct Region {
    std::string key;
    SourceLocation where;
    double density = 0;
    int number = -1;  ///< the mesh's region number (setMesh)
  };
  int dim_ = 2;
  double density_ = 0;  ///< the body's, or the unlisted regions' (0: none given)
  std::vector<Region> regions_;
  std::vector<double> cellDensity_;
  SourceLocation where_;
  Vector2 g_ = Vector2::Zero();
  Point g3_ = Point::Zero();
};

class InitialStress : public Effect {
 public:
  InitialStress(const std::string& name, const Dictionary& d, int dim) : vertical_(dim - 1) {
    name_ = name;
    // σ⁰ linear in the vertical coordinate (stress, gradient), or piecewise linear: a profile
    // of rows (v (components)) at increasing heights v, for layers of their own densities.
    if (d.alternative({{"stress"}, {"profile"}}) == 1) {
      if (d.found("gradient"))
        d.fail("gradient",
               "key 'gradient' goes with 'stress' (σ⁰ linear in the height); a "
               "'profile' gives σ⁰ at heights itself: remove one");
      readProfile(d, dim);
      return;
    }
    if (dim == 2) {
      const std::vector<double> s = d.getScalarList("stress");
      if (s.size() != 3) d.fail("stress", "key 'stress': expected (sxx syy sxy) [Pa]");
      s0_.topLeftCorner<2, 2>() << s[0], s[2], s[2], s[1];
      if (d.found("gradient")) {
        const std::vector<double> g = d.getScalarList("gradient");
        if (g.size() != 3)
          d.fail("gradient", "key 'gradient': expected (dsxx/dy dsyy/dy dsxy/dy) [Pa/m]");
        grad_.topLeftCorner<2, 2>() << g[0], g[2], g[2], g[1];
      }
    } else {
      s0_ = symmetricTensor(numbers(d, "stress", 6, "(sxx syy szz sxy syz sxz) [Pa] on a 3D mesh"));
      if (d.found("gradient"))
        grad_ = symmetricTensor(
            numbers(d, "gradient", 6,
                    "(dsxx/dz dsyy/dz dszz/dz dsxy/dz dsyz/dz dsxz/dz) [Pa/m] on a 3D mesh"));
    }
  }
  std::string type() const override { return "initialStress"; }
  std::string describe() const override {
    std::ostringstream s;
    if (!heights_.empty()) {
      s << "sigma0 piecewise linear in " << (vertical_ == 1 ? "y" : "z") << ", " << heights_.size()
        << " rows from " << heights_.front() << " to " << heights_.back() << " m";
      return s.str();
    }
    if (vertical_ == 1) {
      s << "sigma0 (xx yy xy) = (" << s0_(0, 0) << " " << s0_(1, 1) << " " << s0_(0, 1) << ") Pa";
      if (!grad_.isZero())
        s << " + y (" << grad_(0, 0) << " " << grad_(1, 1) << " " << grad_(0, 1) << ") Pa/m";
      return s.str();
    }
    const auto six = [](const Eigen::Matrix3d& m) {
      std::ostringstream o;
      o << "(" << m(0, 0) << " " << m(1, 1) << " " << m(2, 2) << " " << m(0, 1) << " " << m(1, 2)
        << " " << m(0, 2) << ")";
      return o.str();
    };
    s << "sigma0 (xx yy zz xy yz xz) = " << six(s0_) << " Pa";
    if (!grad_.isZero()) s << " + z " << six(grad_) << " Pa/m";
    return s.str();
  }
  Eigen::Matrix3d initialStress(const Point& x) const override {
    if (!heights_.empty()) {
      const std::size_t k = interval(x[vertical_]);
      const double w = (x[vertical_] - heights_[k]) / (heights_[k + 1] - heights_[k]);
      return (1 - w) * rows_[k] + w * rows_[k + 1];
    }
    return s0_ + x[vertical_] * grad_;
  }
  void setMesh(const Mesh& mesh) override {
    if (heights_.empty() || mesh.points.empty()) return;
    double lo = mesh.points[0][vertical_], hi = lo;
    for (const Point& p : mesh.points)
      lo = std::min(lo, p[vertical_]), hi = std::max(hi, p[vertical_]);
    // The profile must span the body: beyond its rows σ⁰ would be a guess.
    const double slack = 1e-9 * std::max(1.0, hi - lo);
    if (heights_.front() > lo + slack || heights_.back() < hi - slack)
      throw InputError(where_, "key 'profile': its rows span " +
                                   std::string(vertical_ == 1 ? "y" : "z") + " from " +
                                   formatNumber(heights_.front()) + " to " +
                                   formatNumber(heights_.back()) + " m, the body from " +
                                   formatNumber(lo) + " to " + formatNumber(hi) +
                                   " m: give rows at (or beyond) the body's bottom and top");
    // The divergence of σ⁰ per cell: the slope of the interval holding the cell's centroid
    // (exact where the rows' heights are interfaces of the mesh, as layers are).
    cellForce_.assign(static_cast<std::size_t>(mesh.numCells()), Point::Zero());
    for (Index c = 0; c < mesh.numCells(); ++c) {
      double v = 0;
      const int n = mesh.dim + 1;
      for (int j = 0; j < n; ++j) v += mesh.points[mesh.cellVertex(c, j)][vertical_] / n;
      const std::size_t k = interval(v);
      const Eigen::Matrix3d slope = (rows_[k + 1] - rows_[k]) / (heights_[k + 1] - heights_[k]);
      cellForce_[static_cast<std::size_t>(c)] =
          vertical_ == 1 ? Point(slope(0, 1), slope(1, 1), 0.0) : Point(slope.col(2));
    }
  }
  bool givesStressOffset() const override { return true; }
  void addLoad(const ElasticityAssembler& a, double, Eigen::VectorXd& F) const override {
    if (!heights_.empty()) {
      F += a.cellBodyForce([this](Index c) { return cellForce_[static_cast<std::size_t>(c)]; });
      return;
    }
    // div σ⁰ = ∂σ⁰/∂v · e_v, v the vertical (σ⁰ varies with it only); zero for a uniform
    // in-situ stress, so the common case assembles nothing.
    if (grad_.isZero()) return;
    if (vertical_ == 1)
      F += a.bodyForce(Vector2(grad_(0, 1), grad_(1, 1)));
    else
      F += a.bodyForce(Point(grad_.col(2)));
  }
  void addFractureTraction(const std::vector<ControlNode>& nodes, double, Eigen::VectorXd& sigmaN,
                           Eigen::VectorXd& tau) const override {
    // τ has k components per node, on the node's tangent basis (SignConventions.hpp).
    const Eigen::Index n = sigmaN.size(), k = n > 0 ? tau.size() / n : 1;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (vertical_ == 1) {
        // 2D in 2D arithmetic (the numbers of the 2D code, bit for bit).
        const Vector2 normal = nodes[i].normal.head<2>();
        const Eigen::Matrix2d s = initialStress(nodes[i].position).topLeftCorner<2, 2>();
        const Vector2 t = s * normal;
        sigmaN[i] += t.dot(normal);
        for (Eigen::Index c = 0; c < k; ++c)
          tau[k * i + c] += t.dot(Vector2(nodes[i].tangent[c].head<2>()));
        continue;
      }
      const Eigen::Vector3d t = initialStress(nodes[i].position) * nodes[i].normal;
      sigmaN[i] += t.dot(nodes[i].normal);
      for (Eigen::Index c = 0; c < k && c < 2; ++c) tau[k * i + c] += t.dot(nodes[i].tangent[c]);
    }
  }

 private:
  /// profile ((v0 (components)) (v1 (...)) ...): heights strictly increasing, components
  /// (sxx syy sxy) in 2D, (sxx syy szz sxy syz sxz) in 3D.
  void readProfile(const Dictionary& d, int dim) {
    where_ = d.location("profile");
    const Table t = d.getTable("profile");
    const std::size_t n = dim == 2 ? 3 : 6;
    if (t.x.size() < 2)
      d.fail("profile", "key 'profile': expected two rows or more ((height (components)) ...)");
    for (std::size_t r = 0; r < t.x.size(); ++r) {
      if (t.y[r].size() != n)
        d.fail("profile",
               "key 'profile': expected rows (height " +
                   std::string(dim == 2 ? "(sxx syy sxy)" : "(sxx syy szz sxy syz sxz)") +
                   "), got " + std::to_string(t.y[r].size()) + " components");
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      if (dim == 2)
        m.topLeftCorner<2, 2>() << t.y[r][0], t.y[r][2], t.y[r][2], t.y[r][1];
      else
        m = symmetricTensor(t.y[r]);
      heights_.push_back(t.x[r]);
      rows_.push_back(m);
    }
  }
  /// The profile's interval [k, k + 1] holding height v (the first or last beyond its rows).
  std::size_t interval(double v) const {
    const std::size_t j = static_cast<std::size_t>(
        std::upper_bound(heights_.begin(), heights_.end(), v) - heights_.begin());
    return std::min(std::max<std::size_t>(j, 1), heights_.size() - 1) - 1;
  }

  int vertical_ = 1;  ///< the vertical axis: y (1) in 2D, z (2) in 3D
  Eigen::Matrix3d s0_ = Eigen::Matrix3d::Zero(), grad_ = Eigen::Matrix3d::Zero();
  std::vector<double> heights_;        ///< profile: the rows' heights [m], increasing
  std::vector<Eigen::Matrix3d> rows_;  ///< profile: σ⁰ at them [Pa]
  std::vector<Point> cellForce_;       ///< profile: div σ⁰ per cell [N/m³] (setMesh)
  SourceLocation where_;
};

class FracturePressure : public Effect {
 public:
  FracturePressure(const std::string& name, const Dictionary& d,
                   const std::vector<std::string>& fractures, const std::string& caseDir, int dim) {
    name_ = name;
    fracture_ = d.getWord("fracture");
    requireFracture(d, "fracture", fracture_, fractures);
    if (d.alternative({{"pressure"}, {"values"}}) == 1) {
      if (dim == 3)
        d.fail("values",
               "key 'values': a values file gives p along the arclength s of a fracture curve, "
               "which a fault surface of a 3D mesh does not have; give 'pressure' (a constant "
               "or a table) instead");
      const std::string text = readValuesFile(d, "values", caseDir, file_);
      const NumberRows rows = parseNumberRows(
          file_, text, 2, "expected two numbers 's p' (arclength [m], pressure [Pa])", true, "s",
          "no values: expected lines 's p'");
      for (const auto& r : rows.rows) {
        s_.push_back(r[0]);
        p_.push_back(r[1]);
      }
    } else {
      pressure_ = TimeFunction::read(d, "pressure", 1);
    }
  }
  std::string type() const override { return "fracturePressure"; }
  bool givesFracturePressure() const override { return true; }
  bool givesPressureOn(const std::string& name) const override { return name == fracture_; }
  std::string describe() const override {
    return "on fracture " + fracture_ + (file_.empty() ? "" : ", values from " + file_);
  }
  void addFracturePressure(const std::vector<ControlNode>& nodes,
                           const std::vector<std::string>& fractureNames, double t,
                           Eigen::VectorXd& p) const override {
    const double uniform = file_.empty() ? pressure_(t)[0] : 0.0;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (fractureNames[nodes[k].fracture] != fracture_) continue;
      p[k] += file_.empty() ? uniform : interpolate(nodes[k].arclength);
    }
  }

 private:
  /// The values file (NumberRows.hpp): per line "s p", s the arclength [m] (increasing), p
  /// [Pa]. The values are interpolated linearly, constant beyond the ends.
  double interpolate(double s) const {
    if (s <= s_.front()) return p_.front();
    if (s >= s_.back()) return p_.back();
    const std::size_t i = std::upper_bound(s_.begin(), s_.end(), s) - s_.begin();
    const double w = (s - s_[i - 1]) / (s_[i] - s_[i - 1]);
    return (1 - w) * p_[i - 1] + w * p_[i];
  }
  std::string fracture_, file_;
  TimeFunction pressure_;
  std::vector<double> s_, p_;
};

/// A prestress on one fracture given as fields along it (SEAS BP5's τ⁰(x, z), which varies
/// with a(x, z) and no in-situ stress tensor gives): σ_n += normal, and a shear of magnitude
/// `shear` that drives Ω⁺ along `direction` (projected on each node's tangent plane) relative
/// to Ω⁻, i.e. τ = −shear d̂ (φ = −τ drives the slip, docs/method.md §2). Constant in time; it
/// does not load the body.
class FaultTraction : public Effect {
 public:
  FaultTraction(const std::string& name, const Dictionary& d,
                const std::vector<std::string>& fractures, const std::string& caseDir, int dim)
      : where_(d.location()) {
    name_ = name;
    fracture_ = d.getWord("fracture");
    requireFracture(d, "fracture", fracture_, fractures);
    shear_ = FrictionField::read(d, "shear", Bounds::nonNegative(), caseDir, dim);
    normal_ = d.found("normal") ? FrictionField::read(d, "normal", Bounds{}, caseDir, dim)
                                : FrictionField(0.0);
    const std::vector<double> v = d.getScalarList("direction");
    if (v.size() != static_cast<std::size_t>(dim))
      d.fail("direction", dim == 2 ? "key 'direction': expected (x y) on a 2D mesh"
                                   : "key 'direction': expected (x y z) on a 3D mesh");
    direction_ << v[0], v[1], dim == 3 ? v[2] : 0.0;
    if (!(direction_.norm() > 0) || !std::isfinite(direction_.norm()))
      d.fail("direction",
             "key 'direction': expected a non-zero vector, the way the shear drives "
             "Omega+ relative to Omega-");
  }
  std::string type() const override { return "faultTraction"; }
  std::string describe() const override {
    return "on fracture " + fracture_ + ": shear " + shear_.describe() + " Pa along " +
           vec(direction_) + ", normal " + normal_.describe() + " Pa";
  }
  void bind(const EffectContext& c) override {
    const auto takes = [&](std::size_t f) { return c.fractureNames[f] == fracture_; };
    std::vector<char> on;
    fieldOnFractures(shear_, c, takes, "shear (" + name_ + ")", shearAt_, on);
    fieldOnFractures(normal_, c, takes, "normal stress (" + name_ + ")", normalAt_, on);
    on_ = on;
    for (std::size_t i = 0; i < c.nodes.size(); ++i) {
      if (!on_[i]) continue;
      const ControlNode& node = c.nodes[i];
      const Eigen::Vector3d d = direction_ - direction_.dot(node.normal) * node.normal;
      if (!(d.norm() > 1e-6 * direction_.norm()))
        throw InputError(where_, "effect '" + name_ + "': direction " + vec(direction_) +
                                     " is normal to fracture '" + fracture_ + "' at the node at " +
                                     vec(node.position) +
                                     ": it gives the shear no direction there");
    }
  }
  void addFractureTraction(const std::vector<ControlNode>& nodes, double, Eigen::VectorXd& sigmaN,
                           Eigen::VectorXd& tau) const override {
    const Eigen::Index n = sigmaN.size(), k = n > 0 ? tau.size() / n : 1;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!on_[static_cast<std::size_t>(i)]) continue;
      const ControlNode& node = nodes[static_cast<std::size_t>(i)];
      const Eigen::Vector3d d =
          (direction_ - direction_.dot(node.normal) * node.normal).normalized();
      sigmaN[i] += normalAt_[i];
      for (Eigen::Index c = 0; c < k && c < 2; ++c)
        tau[k * i + c] -= shearAt_[i] * d.dot(node.tangent[static_cast<std::size_t>(c)]);
    }
  }

 private:
  std::string fracture_;
  SourceLocation where_;
  FrictionField shear_, normal_;
  Eigen::Vector3d direction_ = Eigen::Vector3d::Zero();
  Eigen::VectorXd shearAt_, normalAt_;
  std::vector<char> on_;
};

struct EffectEntry {
  const char* name;
  std::unique_ptr<Effect> (*make)(const std::string&, const Dictionary&,
                                  const std::vector<std::string>&, const std::string&, int);
};

// The one table of effects: adding one is one line here.
const EffectEntry effectTable[] = {
    {"bodyForce",
     [](const std::string& n, const Dictionary& d, const std::vector<std::string>&,
        const std::string&,
        int dim) -> std::unique_ptr<Effect> { return std::make_unique<BodyForce>(n, d, dim); }},
    {"initialStress",
     [](const std::string& n, const Dictionary& d, const std::vector<std::string>&,
        const std::string&,
        int dim) -> std::unique_ptr<Effect> { return std::make_unique<InitialStress>(n, d, dim); }},
    {"fracturePressure",
     [](const std::string& n, const Dictionary& d, const std::vector<std::string>& f,
        const std::string& c, int dim) -> std::unique_ptr<Effect> {
       return std::make_unique<FracturePressure>(n, d, f, c, dim);
     }},
    {"faultTraction",
     [](const std::string& n, const Dictionary& d, const std::vector<std::string>& f,
        const std::string& c, int dim) -> std::unique_ptr<Effect> {
       return std::make_unique<FaultTraction>(n, d, f, c, dim);
     }},
    {"faultPressure", makeFaultPressure},
    {"porePressure", makePorePressure},
};

}  // namespace

std::vector<std::string> Effect::names() {
  std::vector<std::string> n;
  for (const auto& e : effectTable) n.push_back(e.name);
  return n;
}

std::unique_ptr<Effect> Effect::New(const std::string& name, const Dictionary& dict,
                                    const std::vector<std::string>& fractureNames,
                                    const std::string& caseDir, int dim) {
  const std::string type = dict.getChoice("type", names());
  for (const auto& e : effectTable)
    if (type == e.name) return e.make(name, dict, fractureNames, caseDir, dim);
  return nullptr;  // unreachable: getChoice validated the name
}

void requireFracture(const Dictionary& d, const std::string& key, const std::string& name,
                     const std::vector<std::string>& fractures) {
  if (std::find(fractures.begin(), fractures.end(), name) == fractures.end())
    d.fail(key, "key '" + key + "': '" + name + "' is not a fracture of the case" +
                    suggestionText(name, fractures) + " (fractures: " + joinWords(fractures) + ")");
}

void fieldOnFractures(const FrictionField& field, const EffectContext& c,
                      const std::function<bool(std::size_t)>& takes, const std::string& what,
                      Eigen::VectorXd& at, std::vector<char>& on) {
  on.assign(c.nodes.size(), 0);
  at = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(c.nodes.size()));
  for (std::size_t f = 0; f < c.fractureNames.size(); ++f) {
    if (!takes(f)) continue;
    std::vector<std::size_t> index;
    const Eigen::VectorXd v = field.evaluateOnFracture(c.nodes, static_cast<int>(f), index);
    for (std::size_t i = 0; i < index.size(); ++i) {
      at[static_cast<Eigen::Index>(index[i])] = v[static_cast<Eigen::Index>(i)];
      on[index[i]] = 1;
    }
    if (!field.isConstant() && !index.empty())
      c.log << "Fracture " << c.fractureNames[f] << ": " << what << " from min " << v.minCoeff()
            << " to max " << v.maxCoeff() << " Pa over " << v.size() << " nodes\n";
  }
}

}  // namespace friction
