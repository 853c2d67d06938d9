// The porePressure effect: see PorePressure.hpp.
#include "friction/effect/PorePressure.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "friction/core/Assert.hpp"
#include "friction/core/InputError.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/MaterialMap.hpp"
#include "friction/flow/PointData.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/mesh/Mesh.hpp"
#include "friction/time/TimeFunction.hpp"

namespace friction {

namespace {

class PorePressure : public Effect {
 public:
  PorePressure(const std::string& name, const Dictionary& d, const std::string& caseDir, int dim)
      : dim_(dim) {
    name_ = name;
    alpha_ = d.getScalar("biotCoefficient", Bounds::closed(0.0, 1.0));
    if (d.found("initial")) {
      // An arclength runs along one fracture curve: the rock has none.
      if (d.isDict("initial") && d.subDict("initial").found("type") &&
          d.subDict("initial").getWord("type") == "arclength")
        d.subDict("initial").fail(
            "type",
            "key 'type': the rock's pore pressure is a field of the body, which has no "
            "arclength; give type depth or points (or a number)");
      // p_b0 may be any sign: a case may give pressures as changes from a state of its own.
      initial_ = FrictionField::read(d, "initial", Bounds{}, caseDir, dim);
    }
    if (d.found("change")) change_ = TimeFunction::read(d, "change", 1);
    if (d.found("regions")) {
      if (!d.isDict("regions"))
        d.fail("regions",
               "key 'regions': expected a sub-dictionary of one entry per mesh region, e.g. "
               "regions { reservoir { change table ((0 0) (1 -10e6)); } }");
      const Dictionary& entries = d.subDict("regions");
      for (const std::string& key : entries.keys()) {
        if (!entries.isDict(key))
          entries.fail(key, "key '" + key +
                                "': expected a sub-dictionary with the region's change, e.g. " +
                                key + " { change table ((0 0) (1 -10e6)); }");
        regions_.push_back({key, entries.location(key),
                            TimeFunction::read(entries.subDict(key), "change", 1), -1});
      }
    }
    if (d.found("data")) {
      dataWhere_ = d.location("data");
      // The word script (unquoted) says the program running the case gives the values
      // (GivenField.hpp); a file of that name is "./script".
      const auto& v = d.values("data");
      script_ = v.size() == 1 && v[0].isWord() && v[0].text == "script";
      if (!script_) {
        data_ = PointData::read(d, "data", caseDir, dim, "p", "pressure change [Pa]");
        maxDistance_ = d.getScalarOr("maxDistance", -1.0, Bounds::positive());
      } else if (d.found("maxDistance")) {
        d.fail("maxDistance",
               "key 'maxDistance': applies to a data file only (data script gives the values "
               "at the mesh's vertices); remove it");
      }
    }
  }
  std::string type() const override { return "porePressure"; }
  bool givesFracturePressure() const override { return true; }
  bool givesStressOffset() const override {
    return change_.components() > 0 || !regions_.empty() || !data_.empty() || script_;
  }

  std::string describe() const override {
    std::ostringstream s;
    s << "biotCoefficient " << alpha_ << ", initial p_b " << initial_.describe()
      << (initial_.isConstant() ? " Pa" : "");
    const auto form = [](const TimeFunction& f) {
      return f.isConstant() ? "a constant change" : "a change in time (table)";
    };
    if (change_.components() > 0) s << ", everywhere " << form(change_);
    for (const RegionChange& r : regions_) s << ", in region " << r.key << " " << form(r.change);
    if (!data_.empty()) s << ", " << data_.describe();
    if (script_) s << ", data from " << (given_.empty() ? "the script" : given_);
    s << "; one way (the pressure is given); the fractures without a pressure of their own "
         "take p_b";
    return s.str();
  }

  void setMesh(const Mesh& mesh) override {
    meshSet_ = true;
    for (std::size_t i = 0; i < regions_.size(); ++i) {
      RegionChange& r = regions_[i];
      r.number = meshRegionOf(r.key, r.where, mesh);
      for (std::size_t j = 0; j < i; ++j)
        if (regions_[j].number == r.number)
          throw InputError(r.where, "region " + std::to_string(r.number) + " has two entries, '" +
                                        regions_[j].key + "' and '" + r.key +
                                        "' (expected one per region)");
    }
    cellChange_.assign(mesh.cellRegion.size(), -1);
    for (std::size_t c = 0; c < mesh.cellRegion.size(); ++c)
      for (std::size_t i = 0; i < regions_.size(); ++i)
        if (mesh.cellRegion[c] == regions_[i].number) cellChange_[c] = static_cast<int>(i);
    if (!data_.empty()) setData(mesh);
  }

  std::vector<std::string> takeGivenFields(const GivenFields& given, const Mesh& mesh) override {
    if (!script_) return {};
    const auto at = given.find(kPorePressureChange);
    if (at == given.end()) throw scriptMissing();
    const GivenField& f = at->second;
    f.check();
    FRICTION_ASSERT(f.values.rows() == mesh.numPoints(), "a given field per split-mesh vertex");
    dataTimes_ = f.times;
    cellData_ = f.cellMeans(mesh);
    given_ = f.describe();
    return {kPorePressureChange};
  }

  void bind(const EffectContext& c) override {
    if (!meshSet_) setMesh(c.split.mesh);
    if (script_ && cellData_.empty()) throw scriptMissing();
    assembler_ = c.assembler;
    FRICTION_ASSERT(assembler_ || !givesStressOffset(), "porePressure needs the split assembler");
    // The loads of a unit change, assembled once: a step scales and adds them.
    if (assembler_) {
      if (change_.components() > 0)
        uniformLoad_ = assembler_->pressureLoad([this](Index, const Point&) { return alpha_; });
      regionLoad_.clear();
      for (std::size_t i = 0; i < regions_.size(); ++i)
        regionLoad_.push_back(assembler_->pressureLoad([this, i](Index cell, const Point&) {
          return cellChange_[static_cast<std::size_t>(cell)] == static_cast<int>(i) ? alpha_ : 0.0;
        }));
      // The data's loads, one per listed time (the load is linear in Δp_b).
      dataLoad_.clear();
      for (const Eigen::VectorXd& v : cellData_)
        dataLoad_.push_back(assembler_->pressureLoad(
            [this, &v](Index cell, const Point&) { return alpha_ * v[cell]; }));
    }
    bindFractures(c);
  }

  void addLoad(const ElasticityAssembler&, double t, Eigen::VectorXd& F) const override {
    if (change_.components() > 0) {
      const double dp = change_(t)[0];
      if (dp != 0.0) F += dp * uniformLoad_;
    }
    for (std::size_t i = 0; i < regions_.size() && i < regionLoad_.size(); ++i) {
      const double dp = regions_[i].change(t)[0];
      if (dp != 0.0) F += dp * regionLoad_[i];
    }
    if (!dataLoad_.empty()) {
      const PointData::Bracket b = PointData::bracketOf(dataTimes_, t);
      const Eigen::VectorXd& lower = dataLoad_[b.lower];
      if (b.weight == 0.0)
        F += lower;
      else
        F += lower + b.weight * (dataLoad_[b.upper] - lower);
    }
  }

  void addFracturePressure(const std::vector<ControlNode>& nodes, const std::vector<std::string>&,
                           double t, Eigen::VectorXd& p) const override {
    const double everywhere = change_.components() > 0 ? change_(t)[0] : 0.0;
    Eigen::VectorXd region(static_cast<Eigen::Index>(regions_.size()));
    for (std::size_t i = 0; i < regions_.size(); ++i)
      region[static_cast<Eigen::Index>(i)] = regions_[i].change(t)[0];
    const PointData::Bracket b = PointData::bracketOf(dataTimes_, t);
    for (std::size_t k = 0; k < nodes.size() && k < on_.size(); ++k) {
      if (!on_[k]) continue;
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      p[i] += initialAt_[i] + everywhere;
      if (regions_.size()) p[i] += regionWeight_.row(i).dot(region);
      if (!nodeData_.empty()) {
        const double lower = nodeData_[b.lower][i], upper = nodeData_[b.upper][i];
        p[i] += lower + b.weight * (upper - lower);
      }
    }
  }

  Eigen::Matrix3d stressOffset(Index cell, const Point&, double t) const override {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    const double value = -alpha_ * change(cell, t);
    if (value == 0.0) return s;
    if (dim_ == 3) return value * Eigen::Matrix3d::Identity();
    // 2D: plane strain keeps −α_B Δp_b in σ_zz (ε_zz = 0); plane stress has σ_zz = 0 and the
    // in-plane part b · (−α_B Δp_b) (ElasticityAssembler::pressureFactor).
    const double b = assembler_ ? assembler_->pressureFactor(cell) : 1.0;
    s(0, 0) = s(1, 1) = b * value;
    const bool planeStress = assembler_ && assembler_->material(cell).planeStress();
    s(2, 2) = planeStress ? 0.0 : value;
    return s;
  }

 private:
  struct RegionChange {
    std::string key;
    SourceLocation where;
    TimeFunction change;
    int number = -1;  ///< the mesh's region number (setMesh)
  };

  /// Δp_b of a cell at t [Pa].
  double change(Index cell, double t) const {
    double dp = change_.components() > 0 ? change_(t)[0] : 0.0;
    const std::size_t c = static_cast<std::size_t>(cell);
    if (c < cellChange_.size() && cellChange_[c] >= 0)
      dp += regions_[static_cast<std::size_t>(cellChange_[c])].change(t)[0];
    if (!cellData_.empty()) {
      const PointData::Bracket b = PointData::bracketOf(dataTimes_, t);
      const double lower = cellData_[b.lower][cell], upper = cellData_[b.upper][cell];
      dp += lower + b.weight * (upper - lower);
    }
    return dp;
  }

  /// The data's Δp_b per cell and listed time: the value of the nearest row to the cell's
  /// centroid. A row farther than maxDistance from every centroid lies outside the body (a file
  /// in other units or coordinates): refused naming its line.
  void setData(const Mesh& mesh) {
    std::vector<Point> centroid(static_cast<std::size_t>(mesh.numCells()), Point::Zero());
    double diameter = 0;  // the largest cell's: its longest edge
    for (Index c = 0; c < mesh.numCells(); ++c) {
      const auto v = mesh.cell(c);
      for (Index a : v) {
        const Point& x = mesh.points[static_cast<std::size_t>(a)];
        centroid[static_cast<std::size_t>(c)] += x / static_cast<double>(v.size());
        for (Index b : v)
          diameter = std::max(diameter, (x - mesh.points[static_cast<std::size_t>(b)]).norm());
      }
    }
    // Every point of a cell lies within its diameter of its centroid, so a row inside the body
    // is never refused by the default.
    const double maxDistance = maxDistance_ > 0 ? maxDistance_ : diameter;
    const NearestPoint cells(centroid);
    for (std::size_t j = 0; j < data_.times().size(); ++j)
      for (const PointData::Row& r : data_.rows(j)) {
        double d2 = 0;
        const std::size_t c = cells.nearest(r.x, d2);
        if (std::sqrt(d2) > maxDistance)
          data_.fail(r, "the point " + pointText(r.x) + " is " + formatNumber(std::sqrt(d2)) +
                            " m from the nearest cell centroid (at " + pointText(centroid[c]) +
                            "): data rows must lie in the body, within maxDistance " +
                            formatNumber(maxDistance) +
                            " m (default: the mesh's largest cell diameter); check the file's "
                            "units and coordinates");
      }
    dataTimes_ = data_.times();
    cellData_ = data_.nearestValues(centroid);
  }

  /// `data script;` in a run the caller gave no values (frictionSolver on the command line).
  InputError scriptMissing() const {
    return InputError(dataWhere_,
                      "key 'data': 'script' says the program running the case gives the rock's "
                      "pore-pressure change, and this run was given none; run the case from its "
                      "FreeFEM script with frictionSolve(\"case\", pressure = P, pressureTimes "
                      "= T), or give the change by a file (data \"file\"), change or regions");
  }

  static std::string pointText(const Point& x) {
    std::ostringstream s;
    s << "(" << x.x() << " " << x.y() << " " << x.z() << ")";
    return s.str();
  }

  /// p_b0 at the control nodes of the fractures without a pressure of their own, the weights of
  /// the regions' changes there, and the data's Δp_b there per listed time.
  void bindFractures(const EffectContext& c) {
    const std::size_t n = c.nodes.size();
    fieldOnFractures(
        initial_, c,
        [this, &c](std::size_t f) {
          if (f < c.ownPressure.size() && c.ownPressure[f]) {
            c.log << "Fracture " << c.fractureNames[f] << ": a fluid pressure of its own, not the "
                  << "rock's pore pressure (" << name_ << ")\n";
            return false;
          }
          return true;
        },
        "initial pore pressure of the rock (" + name_ + ")", initialAt_, on_);
    // Weights: the share of each region's cells in the measure of the cells around a node (on
    // either side: the Ω⁺ and Ω⁻ copies); the data's Δp_b is the mean over them by measure.
    regionWeight_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n),
                                          static_cast<Eigen::Index>(regions_.size()));
    nodeData_.assign(cellData_.size(), Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n)));
    if ((regions_.empty() && cellData_.empty()) || !assembler_) return;
    const LagrangeSpace& V = assembler_->space();
    std::vector<Index> control(static_cast<std::size_t>(V.numNodes()), -1);
    for (std::size_t k = 0; k < n; ++k)
      if (on_[k]) {
        control[static_cast<std::size_t>(c.nodes[k].plus)] = static_cast<Index>(k);
        control[static_cast<std::size_t>(c.nodes[k].minus)] = static_cast<Index>(k);
      }
    Eigen::VectorXd total = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    const Mesh& mesh = V.mesh();
    for (Index cell = 0; cell < V.numCells(); ++cell) {
      const double measure = std::abs(mesh.signedMeasure(cell));
      const int r = cellChange_[static_cast<std::size_t>(cell)];
      for (Index node : V.cellNodes(cell)) {
        const Index k = control[static_cast<std::size_t>(node)];
        if (k < 0) continue;
        total[k] += measure;
        if (r >= 0) regionWeight_(k, r) += measure;
        for (std::size_t j = 0; j < cellData_.size(); ++j)
          nodeData_[j][k] += measure * cellData_[j][cell];
      }
    }
    for (Eigen::Index k = 0; k < regionWeight_.rows(); ++k)
      if (total[k] > 0) {
        regionWeight_.row(k) /= total[k];
        for (Eigen::VectorXd& v : nodeData_) v[k] /= total[k];
      }
  }

  int dim_ = 2;
  double alpha_ = 1;
  FrictionField initial_;
  TimeFunction change_;
  std::vector<RegionChange> regions_;
  bool meshSet_ = false;
  std::vector<int> cellChange_;  ///< per cell: its entry of regions_, −1 if none
  const ElasticityAssembler* assembler_ = nullptr;
  Eigen::VectorXd uniformLoad_;              ///< ∫ α_B div φ_i (a unit change everywhere)
  std::vector<Eigen::VectorXd> regionLoad_;  ///< the same over each region's cells
  std::vector<char> on_;                     ///< per control node: it takes p_b
  Eigen::VectorXd initialAt_;                ///< p_b0 per control node [Pa]
  Eigen::MatrixXd regionWeight_;             ///< per control node and region entry
  PointData data_;                           ///< `data "file";`: Δp_b at points at listed times
  bool script_ = false;                      ///< `data script;`: Δp_b given by the caller
  SourceLocation dataWhere_;                 ///< where the case says `data`
  std::string given_;                        ///< the given field, for the log
  double maxDistance_ = -1;                  ///< [m]; < 0: the largest cell diameter
  std::vector<double> dataTimes_;            ///< the data's listed times [s] (file or caller)
  std::vector<Eigen::VectorXd> cellData_;    ///< per listed time, Δp_b per cell [Pa]
  std::vector<Eigen::VectorXd> dataLoad_;    ///< per listed time, ∫ α_B Δp_b div φ_i
  std::vector<Eigen::VectorXd> nodeData_;    ///< per listed time, Δp_b per control node [Pa]
};

}  // namespace

std::unique_ptr<Effect> makePorePressure(const std::string& name, const Dictionary& dict,
                                         const std::vector<std::string>&,
                                         const std::string& caseDir, int dim) {
  return std::make_unique<PorePressure>(name, dict, caseDir, dim);
}

}  // namespace friction
