// The faultPressure effect: see FaultPressure.hpp.
#include "friction/effect/FaultPressure.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/effect/Effect.hpp"
#include "friction/fracture/FractureSystem.hpp"
#include "friction/law/FrictionField.hpp"
#include "friction/time/TimeFunction.hpp"

namespace friction {

namespace {

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
    for (const std::string& f : fractures_) {
      const std::string key = d.found("fracture") ? "fracture" : "fractures";
      if (std::find(fractures.begin(), fractures.end(), f) == fractures.end())
        d.fail(key, "key '" + key + "': '" + f + "' is not a fracture of the case" +
                        suggestionText(f, fractures) + " (fractures: " + joinWords(fractures) +
                        ")");
    }
    // p₀ may be any sign: a case may give pressures as changes from a state of its own.
    initial_ = d.found("initial") ? FrictionField::read(d, "initial", Bounds{}, caseDir, dim)
                                  : FrictionField(0.0);
    if (d.found("change")) change_ = TimeFunction::read(d, "change", 1);
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
    return s.str();
  }

  void bind(const EffectContext& c) override {
    // p₀ per control node of the listed fractures, evaluated once (it does not change in time).
    on_.assign(c.nodes.size(), 0);
    initialAt_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(c.nodes.size()));
    for (std::size_t f = 0; f < c.fractureNames.size(); ++f) {
      if (std::find(fractures_.begin(), fractures_.end(), c.fractureNames[f]) == fractures_.end())
        continue;
      std::vector<const ControlNode*> nodes;
      std::vector<std::size_t> index;
      for (std::size_t k = 0; k < c.nodes.size(); ++k)
        if (c.nodes[k].fracture == static_cast<int>(f))
          nodes.push_back(&c.nodes[k]), index.push_back(k);
      const Eigen::VectorXd v = initial_.evaluate(nodes);
      for (std::size_t i = 0; i < index.size(); ++i) {
        initialAt_[static_cast<Eigen::Index>(index[i])] = v[static_cast<Eigen::Index>(i)];
        on_[index[i]] = 1;
      }
      if (!initial_.isConstant() && !nodes.empty())
        c.log << "Fracture " << c.fractureNames[f] << ": initial pressure (" << name_
              << ") from min " << v.minCoeff() << " to max " << v.maxCoeff() << " Pa over "
              << v.size() << " nodes\n";
    }
  }

  void addFracturePressure(const std::vector<ControlNode>& nodes, const std::vector<std::string>&,
                           double t, Eigen::VectorXd& p) const override {
    const double change = change_.components() > 0 ? change_(t)[0] : 0.0;
    for (std::size_t k = 0; k < nodes.size() && k < on_.size(); ++k)
      if (on_[k])
        p[static_cast<Eigen::Index>(k)] += initialAt_[static_cast<Eigen::Index>(k)] + change;
  }

 private:
  std::vector<std::string> fractures_;
  FrictionField initial_;
  TimeFunction change_;
  std::vector<char> on_;       ///< per control node: on a listed fracture
  Eigen::VectorXd initialAt_;  ///< p₀ per control node [Pa]
};

}  // namespace

std::unique_ptr<Effect> makeFaultPressure(const std::string& name, const Dictionary& dict,
                                          const std::vector<std::string>& fractureNames,
                                          const std::string& caseDir, int dim) {
  return std::make_unique<FaultPressure>(name, dict, fractureNames, caseDir, dim);
}

}  // namespace friction
