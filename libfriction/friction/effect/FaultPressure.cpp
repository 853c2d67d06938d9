// The faultPressure effect: see FaultPressure.hpp.
#include "friction/effect/FaultPressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/dict/DictionaryWriter.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/flow/ClosedForms.hpp"
#include "friction/flow/FaultDiffusion.hpp"
#include "friction/flow/FaultFlowMesh.hpp"
#include "friction/flow/PointData.hpp"
#include "friction/flow/StepSchedule.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/time/TimeFunction.hpp"

namespace friction {

namespace {

/// A schedule key: a number (that value from t = 0) or rows ((t0 v0) (t1 v1) ...), the value
/// held from each time to the next (StepSchedule.hpp).
StepSchedule readSchedule(const Dictionary& d, const std::string& key) {
  const auto& v = d.values(key);
  if (v.size() == 1 && v[0].isNumber()) return StepSchedule::constant(d.getScalar(key), 0.0);
  const Table t = d.getTable(key);
  std::vector<double> values;
  for (const auto& y : t.y) {
    if (y.size() != 1)
      d.fail(key,
             "key '" + key + "': expected a number or rows ((time value) ...), a value per row");
    values.push_back(y[0]);
  }
  return StepSchedule(t.x, values, d.location(key));
}

/// A well of faultPressure's `wells`: a pressure change held at a point, or a volume rate.
struct Well {
  std::string name;
  Point position = Point::Zero();
  bool held = false;  ///< pressure (held Δp) or rate
  StepSchedule schedule;
  SourceLocation where;
  // Closed forms: where the well is on the fault.
  int fracture = -1;              ///< 2D: the fracture it lies on
  double s0 = 0;                  ///< 2D: its arclength there [m]
  Point onFault = Point::Zero();  ///< its closest point on the fault [m]
};

class FaultPressure : public Effect {
 public:
  FaultPressure(const std::string& name, const Dictionary& d,
                const std::vector<std::string>& fractures, const std::string& caseDir, int dim) {
    name_ = name;
    switch (d.alternative({{"fracture"}, {"fractures"}}, 2)) {
      case 0:
        fractures_ = {d.getWord("fracture")};
        break;
      case 1:
        fractures_ = d.getWordList("fractures");
        if (fractures_.empty())
          d.fail("fractures",
                 "key 'fractures': an empty list (name at least one fracture, or "
                 "leave the key out for every fracture)");
        break;
      default:
        fractures_ = fractures;  // every fracture of the case
    }
    for (const std::string& f : fractures_)
      requireFracture(d, d.found("fracture") ? "fracture" : "fractures", f, fractures);
    // p₀ may be any sign: a case may give pressures as changes from a state of its own.
    initial_ = d.found("initial") ? FrictionField::read(d, "initial", Bounds{}, caseDir, dim)
                                  : FrictionField(0.0);
    if (d.found("change")) change_ = TimeFunction::read(d, "change", 1);
    dim_ = dim;
    where_ = d.location();
    if (const Dictionary* wells = d.findDict("wells")) {
      for (const std::string& key : wells->keys()) {
        if (!wells->isDict(key))
          wells->fail(key, "key '" + key +
                               "': expected a well { position (...); pressure ...; } "
                               "or { position (...); rate ...; }");
        const Dictionary& w = wells->subDict(key);
        Well well;
        well.name = key;
        well.where = w.location();
        const std::vector<double> x = w.getScalarList("position");
        if (static_cast<int>(x.size()) != dim)
          w.fail("position", "key 'position': expected " +
                                 std::string(dim == 2 ? "(x y)" : "(x y z)") + " [m], got " +
                                 std::to_string(x.size()) + " numbers");
        for (int c = 0; c < dim; ++c) well.position[c] = x[static_cast<std::size_t>(c)];
        well.held = w.alternative({{"pressure"}, {"rate"}}) == 0;
        well.schedule = readSchedule(w, well.held ? "pressure" : "rate");
        w.checkAllRead();
        wells_.push_back(std::move(well));
      }
      if (wells_.empty())
        d.fail("wells", "key 'wells': no well (a sub-dictionary per well, or leave the key out)");
    }
    // The fault's hydraulic properties: the closed forms need α (held pressures) or S and κ
    // (rates); the computed diffusion needs S and κ.
    diffusion_ = d.getChoiceOr("model", {"closedForm", "diffusion"}, "closedForm") == "diffusion";
    bool rates = false;
    for (const Well& w : wells_) rates |= !w.held;
    if (d.found("diffusivity") && (diffusion_ || rates))
      d.fail("diffusivity",
             "key 'diffusivity': " +
                 std::string(diffusion_ ? "the computed diffusion" : "a rate well") +
                 " needs the storage and the transmissivity (α = transmissivity/storage): give "
                 "'storage' [m/Pa] and 'transmissivity' [m3/(Pa s)] instead");
    if (d.found("diffusivity")) {
      alpha_ = d.getScalar("diffusivity", Bounds::positive());
    } else if (!wells_.empty() || diffusion_) {
      storage_ = d.getScalar("storage", Bounds::positive());
      transmissivity_ = d.getScalar("transmissivity", Bounds::positive());
      alpha_ = transmissivity_ / storage_;
    }
    if (!diffusion_ && dim == 3)
      for (const Well& w : wells_)
        if (w.held)
          throw InputError(w.where,
                           "well '" + w.name +
                               "': a pressure held at a point of a fault surface has no closed "
                               "form (its flux depends on the well's radius): give its 'rate', "
                               "or compute the diffusion ('model diffusion;')");
    if (!wells_.empty() || diffusion_)
      radius_ = d.getScalarOr("wellRadius", -1.0, Bounds::positive());
    maxDistance_ = d.getScalarOr("maxDistance", -1.0, Bounds::positive());
    if (d.found("data"))
      data_ = PointData::read(d, "data", caseDir, dim, "p", "pressure change [Pa]");
    if (diffusion_) {
      options_.scheme = timeSchemeNamed(
          d.getChoiceOr("scheme", {"backwardEuler", "crankNicolson"}, "backwardEuler"));
      options_.maxStep =
          d.getScalarOr("maxStep", std::numeric_limits<double>::infinity(), Bounds::positive());
    }
  }

  std::string type() const override { return "faultPressure"; }
  bool givesFracturePressure() const override { return true; }
  bool givesPressureOn(const std::string& name) const override {
    return std::find(fractures_.begin(), fractures_.end(), name) != fractures_.end();
  }
  std::string describe() const override {
    std::ostringstream s;
    s << "on " << (fractures_.size() == 1 ? "fracture " : "fractures ") << joinWords(fractures_)
      << ": initial " << initial_.describe();
    if (change_.components() > 0)
      s << ", plus " << (change_.isConstant() ? "a constant change" : "a change in time (table)");
    if (!wells_.empty()) s << ", " << wells_.size() << (wells_.size() == 1 ? " well" : " wells");
    if (!data_.empty()) s << ", " << data_.describe();
    if (diffusion_)
      s << ", diffusion computed on the fault (storage " << storage_ << " m/Pa, transmissivity "
        << transmissivity_ << " m3/(Pa s), diffusivity " << alpha_ << " m2/s, "
        << toString(options_.scheme) << ")";
    else if (!wells_.empty())
      s << ", closed forms (diffusivity " << alpha_ << " m2/s)";
    return s.str();
  }
  bool hasState() const override { return diffusion_; }

  void bind(const EffectContext& c) override {
    // p₀ per control node of the listed fractures, evaluated once (it does not change in time).
    fieldOnFractures(
        initial_, c,
        [this, &c](std::size_t f) {
          return std::find(fractures_.begin(), fractures_.end(), c.fractureNames[f]) !=
                 fractures_.end();
        },
        "initial pressure (" + name_ + ")", initialAt_, on_);
    if (wells_.empty() && !diffusion_ && data_.empty()) return;
    bindFlow(c);
  }

  void advance(double t) override {
    if (!diffusion_) return;
    if (t > time_) flow_->advance(time_, t);
    time_ = std::max(time_, t);
  }

  void writeState(DictionaryWriter& out) const override {
    const Eigen::VectorXd& p = flow_->state();
    out.entry("time", time_);
    out.entry("pressureChange", std::vector<double>(p.data(), p.data() + p.size()));
  }

  void readState(const Dictionary& in, double t) override {
    const double recorded = in.getScalar("time");
    if (recorded != t)
      in.fail("time", "key 'time': " + formatNumber(recorded) + ", not the folder's time " +
                          formatNumber(t) + ": the state belongs to another time");
    const std::vector<double> p = in.getScalarList("pressureChange");
    if (static_cast<Index>(p.size()) != flow_->mesh().numNodes())
      in.fail("pressureChange", "key 'pressureChange': " + std::to_string(p.size()) +
                                    " values, expected one per node of the fault's flow mesh (" +
                                    std::to_string(flow_->mesh().numNodes()) +
                                    "): the mesh or the fractures changed since");
    flow_->setState(
        Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())),
        in.location("pressureChange"));
    time_ = t;
  }

  void addFracturePressure(const std::vector<ControlNode>& nodes, const std::vector<std::string>&,
                           double t, Eigen::VectorXd& p) const override {
    const double change = change_.components() > 0 ? change_(t)[0] : 0.0;
    for (std::size_t k = 0; k < nodes.size() && k < on_.size(); ++k) {
      if (!on_[k]) continue;
      double v = initialAt_[static_cast<Eigen::Index>(k)] + change;
      if (diffusion_) {
        const FaultFlowMesh::Location& at = at_[k];
        const auto& element = flow_->mesh().element(at.element);
        for (int j = 0; j < flow_->mesh().nodesPerElement(); ++j)
          v += at.weight[static_cast<std::size_t>(j)] *
               flow_->state()[element[static_cast<std::size_t>(j)]];
      } else {
        for (const Well& w : wells_) v += closedForm(w, nodes[k], t);
      }
      if (!data_.empty()) v += dataAt(k, t);
      p[static_cast<Eigen::Index>(k)] += v;
    }
  }

 private:
  std::vector<std::string> fractures_;
  FrictionField initial_;
  TimeFunction change_;
  /// The closed-form Δp of well w at control node n at time t [Pa] (docs/method.md §11):
  /// 2D along the well's fracture only (the arclength from the well), 3D by the distance from
  /// the well in space (a plane fault), at least the well's radius.
  double closedForm(const Well& w, const ControlNode& n, double t) const {
    if (dim_ == 2) {
      if (n.fracture != w.fracture) return 0.0;
      return w.held ? heldPressure2d(n.arclength, w.s0, t, w.schedule, alpha_)
                    : ratePressure2d(n.arclength, w.s0, t, w.schedule, storage_, alpha_);
    }
    const double r = std::max((Point(n.position) - w.onFault).norm(), radius_);
    return ratePressure3d(r, t, w.schedule, transmissivity_, alpha_);
  }

  /// The fault's own flow mesh (2D: the listed fractures' curves, joined at junctions; 3D:
  /// their triangles), where each well lies on it, and (diffusion) each control node's place.
  void bindFlow(const EffectContext& c) {
    const SplitMesh& split = c.split;
    std::vector<int> listed;
    for (std::size_t f = 0; f < split.fractures.size(); ++f)
      if (std::find(fractures_.begin(), fractures_.end(), split.fractures[f].name) !=
          fractures_.end())
        listed.push_back(static_cast<int>(f));
    // The Ω⁺ copy keeps the unsplit node's number and position (SplitMesh.hpp).
    const auto pointOf = [&split](Index unsplit) {
      return Point(split.mesh.points[static_cast<std::size_t>(unsplit)]);
    };
    std::unique_ptr<FaultFlowMesh> mesh;
    if (dim_ == 2) {
      std::vector<FaultFlowMesh::Curve> curves;
      for (int f : listed) {
        const FractureGeometry& g = split.fractures[static_cast<std::size_t>(f)];
        FaultFlowMesh::Curve curve;
        for (Index i = 0; i < g.numNodes(); ++i) {
          curve.id.push_back(g.node[static_cast<std::size_t>(i)]);
          curve.points.push_back(pointOf(g.node[static_cast<std::size_t>(i)]));
        }
        curves.push_back(std::move(curve));
      }
      mesh = std::make_unique<FaultFlowMesh>(FaultFlowMesh::fromCurves(curves, where_));
    } else {
      std::vector<Point> points;
      std::vector<FaultFlowMesh::Triangle> triangles;
      std::map<Index, Index> local;
      for (int f : listed)
        for (const auto& t : split.fractures[static_cast<std::size_t>(f)].triangles) {
          FaultFlowMesh::Triangle tri{};
          for (std::size_t j = 0; j < 3; ++j) {
            const auto [it, added] = local.emplace(t[j], static_cast<Index>(points.size()));
            if (added) points.push_back(pointOf(t[j]));
            tri[j] = it->second;
          }
          triangles.push_back(tri);
        }
      mesh = std::make_unique<FaultFlowMesh>(std::move(points), triangles, where_);
    }
    const double h = mesh->meanEdgeLength();
    if (radius_ < 0) radius_ = h / 4;
    const double maxDistance = maxDistance_ > 0 ? maxDistance_ : h / 2;
    // Where each well is: its closest point on the listed fractures, within maxDistance.
    for (Well& w : wells_) {
      const FaultFlowMesh::Location at = mesh->locate(w.position);
      if (at.distance > maxDistance)
        throw InputError(
            w.where, "well '" + w.name + "': its position is " + formatNumber(at.distance) +
                         " m from the nearest listed fracture (at " + describePoint(at.closest) +
                         "); a well must lie on a fault, within maxDistance " +
                         formatNumber(maxDistance) +
                         " m (default: half the fault's mean edge length)");
      w.onFault = at.closest;
      if (dim_ != 2) continue;
      // 2D: the arclength of the closest point, on the fracture whose curve holds it.
      double best = std::numeric_limits<double>::infinity();
      for (int f : listed) {
        const FractureGeometry& g = split.fractures[static_cast<std::size_t>(f)];
        for (std::size_t i = 0; i + 1 < g.node.size(); ++i) {
          const Point a = pointOf(g.node[i]), b = pointOf(g.node[i + 1]);
          const double u =
              std::clamp((w.position - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          const double d = (a + u * (b - a) - w.position).norm();
          if (d < best) {
            best = d;
            w.fracture = f;
            w.s0 = g.arclength[i] + u * (g.arclength[i + 1] - g.arclength[i]);
          }
        }
      }
    }
    if (!data_.empty()) bindData(c, *mesh, maxDistance);
    if (!diffusion_) return;
    flow_ = std::make_unique<FaultDiffusion>(*mesh, FlowCoefficient(storage_),
                                             FlowCoefficient(transmissivity_), options_, where_);
    for (const Well& w : wells_) {
      if (w.held)
        flow_->addHeldPressure(w.position, w.schedule, maxDistance, w.where);
      else
        flow_->addRateWell(w.position, w.schedule, maxDistance, w.where);
    }
    // Each control node's place on the flow mesh: a P1 vertex is one of its nodes, a P2
    // midpoint the middle of an element's edge (P1 interpolation there).
    at_.assign(c.nodes.size(), FaultFlowMesh::Location{});
    for (std::size_t k = 0; k < c.nodes.size(); ++k)
      if (on_[k]) at_[k] = flow_->mesh().locate(c.nodes[k].position);
    c.log << "Effect " << name_ << ": the fault's flow mesh has " << flow_->mesh().numNodes()
          << " nodes and " << flow_->mesh().numElements()
          << (dim_ == 2 ? " segments" : " triangles") << "\n";
  }

  /// Every data row must lie on a listed fracture (within maxDistance: a row far from every
  /// fault is a file of another place or unit); each control node then takes, per time, the
  /// value of the nearest row of that time.
  void bindData(const EffectContext& c, const FaultFlowMesh& mesh, double maxDistance) {
    for (std::size_t j = 0; j < data_.times().size(); ++j)
      for (const PointData::Row& r : data_.rows(j)) {
        const FaultFlowMesh::Location at = mesh.locate(r.x);
        if (at.distance > maxDistance)
          data_.fail(r, "the point " + describePoint(r.x) + " is " + formatNumber(at.distance) +
                            " m from the nearest listed fracture (at " + describePoint(at.closest) +
                            "): data rows must lie on a fault, " + "within maxDistance " +
                            formatNumber(maxDistance) +
                            " m (default: half the fault's mean edge length)");
      }
    std::vector<Point> x;
    for (const ControlNode& n : c.nodes) x.push_back(n.position);
    dataAt_ = data_.nearestValues(x);
  }

  /// Node k's data at time t: linear between the listed times, constant beyond them.
  double dataAt(std::size_t k, double t) const {
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    const PointData::Bracket b = data_.bracket(t);
    const double lower = dataAt_[b.lower][i], upper = dataAt_[b.upper][i];
    return b.weight == 0.0 ? lower : lower + b.weight * (upper - lower);
  }

  PointData data_;                       ///< `data "file";`: Δp at points at listed times
  std::vector<Eigen::VectorXd> dataAt_;  ///< per listed time, per control node [Pa]

  static std::string describePoint(const Point& x) {
    std::ostringstream s;
    s << "(" << x.x() << " " << x.y() << " " << x.z() << ")";
    return s.str();
  }

  std::vector<char> on_;       ///< per control node: on a listed fracture
  Eigen::VectorXd initialAt_;  ///< p₀ per control node [Pa]
  int dim_ = 2;
  SourceLocation where_;
  std::vector<Well> wells_;
  bool diffusion_ = false;
  double alpha_ = 0, storage_ = 0, transmissivity_ = 0;  ///< [m²/s], [m/Pa], [m³/(Pa s)]
  double radius_ = -1, maxDistance_ = -1;                ///< [m]; < 0: from the mesh
  FaultDiffusionOptions options_;
  std::unique_ptr<FaultDiffusion> flow_;
  std::vector<FaultFlowMesh::Location> at_;  ///< per control node (diffusion)
  double time_ = 0;                          ///< the time of flow_'s state [s]
};

}  // namespace

std::unique_ptr<Effect> makeFaultPressure(const std::string& name, const Dictionary& dict,
                                          const std::vector<std::string>& fractureNames,
                                          const std::string& caseDir, int dim) {
  return std::make_unique<FaultPressure>(name, dict, fractureNames, caseDir, dim);
}

}  // namespace friction
