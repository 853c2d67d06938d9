// Friction laws and their selection table.
#include "friction/law/FrictionLaw.hpp"

#include <algorithm>
#include <cmath>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"

namespace friction {

namespace {

/// What a law's keys are read with: the fracture's dictionary, the case folder, the dimension.
struct LawInput {
  const Dictionary& d;
  const std::string& caseDir;
  int dim;
  FrictionField field(const std::string& key, Bounds bounds) const {
    return FrictionField::read(d, key, bounds, caseDir, dim);
  }
  /// μ_f: frictionCoefficient (a number or a field), or frictionAngle φ [degrees] as other
  /// codes take it (a number in [0, 90): μ_f = tan φ).
  FrictionField mu() const {
    if (d.alternative({{"frictionCoefficient"}, {"frictionAngle"}}) == 0)
      return field("frictionCoefficient", Bounds::nonNegative());
    if (d.isDict("frictionAngle"))
      d.fail("frictionAngle",
             "key 'frictionAngle': expected a number of degrees in [0, 90); a field is given as "
             "frictionCoefficient (μ_f = tan φ)");
    const double phi = d.getScalar("frictionAngle", Bounds{0.0, 90.0, false, true});
    return FrictionField(std::tan(phi * M_PI / 180.0));
  }
};

struct LawEntry {
  const char* name;
  std::unique_ptr<FrictionLaw> (*make)(const LawInput&);
};

// The one table of friction laws: adding one is one line here.
const LawEntry lawTable[] = {
    {"frictionless",
     [](const LawInput&) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<Frictionless>();
     }},
    {"tresca",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       in.d.advise("cohesion",
                   "law tresca's bound is its 'threshold' g [Pa] (|τ| ≤ g); a cohesion with "
                   "friction is law coulombCohesion");
       return std::make_unique<Tresca>(in.field("threshold", Bounds::positive()));
     }},
    {"coulomb",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       // A cohesion needs the other law: say which, not "unknown key".
       in.d.advise("cohesion",
                   "law coulomb has no cohesion; use law coulombCohesion (|τ| ≤ c − μ_f σ'_n, "
                   "keys frictionCoefficient and cohesion)");
       return std::make_unique<Coulomb>(in.mu());
     }},
    {"coulombCohesion",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       return std::make_unique<CoulombCohesion>(in.mu(),
                                                in.field("cohesion", Bounds::nonNegative()));
     }},
    {"slipWeakening",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       in.d.advise("frictionCoefficient",
                   "law slipWeakening takes 'staticCoefficient' μ_s and 'dynamicCoefficient' "
                   "μ_d (μ falls from μ_s to μ_d over the slip path 'criticalSlip' D_c [m])");
       in.d.advise("frictionAngle",
                   "law slipWeakening takes 'staticCoefficient' μ_s and 'dynamicCoefficient' "
                   "μ_d, as numbers or fields (μ = tan φ)");
       FrictionField muS = in.field("staticCoefficient", Bounds::nonNegative());
       FrictionField muD = in.field("dynamicCoefficient", Bounds::nonNegative());
       // μ_d ≤ μ_s: here for numbers, node by node where the case evaluates fields.
       if (muS.isConstant() && muD.isConstant() && muD.value() > muS.value())
         in.d.fail("dynamicCoefficient", "key 'dynamicCoefficient': " + formatNumber(muD.value()) +
                                             " above staticCoefficient " +
                                             formatNumber(muS.value()) +
                                             ": slip-weakening needs mu_d <= mu_s");
       FrictionField dc = in.field("criticalSlip", Bounds::positive());
       const Weakening form =
           in.d.getChoiceOr("weakening", {"linear", "exponential"}, "linear") == "linear"
               ? Weakening::linear
               : Weakening::exponential;
       FrictionField c = in.d.found("cohesion") ? in.field("cohesion", Bounds::nonNegative())
                                                : FrictionField(0.0);
       return std::make_unique<SlipWeakening>(std::move(muS), std::move(muD), std::move(dc),
                                              std::move(c), form);
     }},
    {"rateState",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       in.d.advise("frictionCoefficient",
                   "law rateState takes 'referenceFriction' f0 (the friction at the reference "
                   "slip rate), 'a', 'b' and 'characteristicSlip'");
       RateStateLaw::Fields f;
       f.a = in.field("a", Bounds::positive());
       f.b = in.field("b", Bounds::positive());
       f.L = in.field("characteristicSlip", Bounds::positive());
       f.f0 = in.d.found("referenceFriction") ? in.field("referenceFriction", Bounds::positive())
                                              : FrictionField(0.6);
       f.V0 = in.d.found("referenceSlipRate") ? in.field("referenceSlipRate", Bounds::positive())
                                              : FrictionField(1e-6);
       f.initialV = in.field("initialSlipRate", Bounds::positive());
       f.aging = in.d.getChoiceOr("stateEvolution", {"aging", "slip"}, "aging") == "aging";
       if (in.d.found("creepSlipRate") || in.d.found("creepDirection")) {
         f.creepRate = in.field("creepSlipRate", Bounds::nonNegative());
         const std::vector<double> v = in.d.getScalarList("creepDirection");
         if (v.size() != static_cast<std::size_t>(in.dim))
           in.d.fail("creepDirection", in.dim == 2 ? "key 'creepDirection': expected (x y)"
                                                   : "key 'creepDirection': expected (x y z) on "
                                                     "a 3D mesh");
         f.creepDirection << v[0], v[1], in.dim == 3 ? v[2] : 0.0;
         if (!(f.creepDirection.norm() > 0) || !std::isfinite(f.creepDirection.norm()))
           in.d.fail("creepDirection",
                     "key 'creepDirection': expected a non-zero vector, the direction in which "
                     "the side Omega+ creeps relative to Omega-");
         f.creepDirection.normalize();
       }
       if (in.d.alternative({{"shearWaveSpeed"}, {"radiationDamping"}}) == 0)
         f.shearWaveSpeed = in.d.getScalar("shearWaveSpeed", Bounds::positive());
       else
         f.radiationDamping = in.d.getScalar("radiationDamping", Bounds::nonNegative());
       return std::make_unique<RateStateLaw>(std::move(f));
     }},
    {"creep",
     [](const LawInput& in) -> std::unique_ptr<FrictionLaw> {
       FrictionField rate = in.field("slipRate", Bounds::nonNegative());
       Eigen::Vector3d dir = Eigen::Vector3d::Zero();
       if (in.dim == 2) {
         const Vector2 v = in.d.getVector("direction");
         dir << v.x(), v.y(), 0.0;
       } else {
         const std::vector<double> v = in.d.getScalarList("direction");
         if (v.size() != 3)
           in.d.fail("direction",
                     "key 'direction': expected (x y z) on a 3D mesh, the direction "
                     "in which the side Omega+ slides relative to Omega-");
         dir << v[0], v[1], v[2];
       }
       if (!(dir.norm() > 0) || !std::isfinite(dir.norm()))
         in.d.fail("direction",
                   "key 'direction': expected a non-zero vector, the direction in which the side "
                   "Omega+ slides relative to Omega-");
       return std::make_unique<Creep>(std::move(rate), dir.normalized());
     }},
};

}  // namespace

double WeakeningNode::mu(double delta) const {
  switch (form) {
    case Weakening::none:
      return muStatic;
    case Weakening::linear:
      return muDynamic + (muStatic - muDynamic) * std::max(0.0, 1.0 - delta / criticalSlip);
    case Weakening::exponential:
      return muDynamic + (muStatic - muDynamic) * std::exp(-delta / criticalSlip);
  }
  return muStatic;
}

double WeakeningNode::slope(double delta) const {
  switch (form) {
    case Weakening::none:
      return 0;
    case Weakening::linear:
      return delta < criticalSlip ? -(muStatic - muDynamic) / criticalSlip : 0.0;
    case Weakening::exponential:
      return -(muStatic - muDynamic) / criticalSlip * std::exp(-delta / criticalSlip);
  }
  return 0;
}

std::vector<std::string> FrictionLaw::names() {
  std::vector<std::string> n;
  for (const auto& e : lawTable) n.push_back(e.name);
  return n;
}

std::unique_ptr<FrictionLaw> FrictionLaw::New(const Dictionary& dict, const std::string& caseDir,
                                              int dim) {
  const std::string type = dict.getChoice("law", names());
  for (const auto& e : lawTable)
    if (type == e.name) return e.make(LawInput{dict, caseDir, dim});
  return nullptr;  // unreachable: getChoice validated the name
}

}  // namespace friction
