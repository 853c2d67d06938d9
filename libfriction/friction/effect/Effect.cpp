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
#include "friction/fracture/FractureSystem.hpp"

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
    density_ = d.getScalar("density", Bounds::positive());
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
    s << "density " << density_ << " kg/m3, g " << (dim_ == 2 ? vec(g_) : vec(g3_)) << " m/s2";
    return s.str();
  }
  void addLoad(const ElasticityAssembler& a, double, Eigen::VectorXd& F) const override {
    if (dim_ == 2)
      F += a.bodyForce(Vector2(density_ * g_));
    else
      F += a.bodyForce(Point(density_ * g3_));
  }

 private:
  int dim_ = 2;
  double density_ = 0;
  Vector2 g_ = Vector2::Zero();
  Point g3_ = Point::Zero();
};

class InitialStress : public Effect {
 public:
  InitialStress(const std::string& name, const Dictionary& d, int dim) : vertical_(dim - 1) {
    name_ = name;
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
    return s0_ + x[vertical_] * grad_;
  }
  bool givesStressOffset() const override { return true; }
  void addLoad(const ElasticityAssembler& a, double, Eigen::VectorXd& F) const override {
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
  int vertical_ = 1;  ///< the vertical axis: y (1) in 2D, z (2) in 3D
  Eigen::Matrix3d s0_ = Eigen::Matrix3d::Zero(), grad_ = Eigen::Matrix3d::Zero();
};

class FracturePressure : public Effect {
 public:
  FracturePressure(const std::string& name, const Dictionary& d,
                   const std::vector<std::string>& fractures, const std::string& caseDir, int dim) {
    name_ = name;
    fracture_ = d.getWord("fracture");
    if (std::find(fractures.begin(), fractures.end(), fracture_) == fractures.end())
      d.fail("fracture", "key 'fracture': '" + fracture_ + "' is not a fracture of the case" +
                             suggestionText(fracture_, fractures) +
                             " (fractures: " + joinWords(fractures) + ")");
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

}  // namespace friction
