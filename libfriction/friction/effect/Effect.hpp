// Effect: a physical effect a case switches on by name in constant/effects (issue: simulate
// only the effects a scene calls for). What a case does not list costs nothing: no
// allocation, no assembly, no solve. Run-time selectable from the table in Effect.cpp:
//
//   gravity  { type bodyForce;        density 2500; g (0 -9.81); }        // f = ρ g [N/m³]
//   inSitu   { type initialStress;    stress (sxx syy sxy);               // σ⁰ [Pa]
//                                     gradient (gxx gyy gxy); }           // optional, ∂σ⁰/∂y
//                                     [Pa/m]
//   pore     { type fracturePressure; fracture crack; pressure 1e6; }     // p [Pa], or a table,
//                                     // or values "constant/p.dat" (s p per line, interpolated)
//   fluid    { type faultPressure; fractures (fault);                      // p_f(x, t) [Pa]
//              initial { type depth; value 0; gradient -9810; } change table (...); }
//              (FaultPressure.hpp: the initial state as a field, wells, diffusion, data)
//   rock     { type porePressure; biotCoefficient 1;                      // p_b(x, t) [Pa] of
//              initial { type depth; value 0; gradient -9810; }          // the rock, one way
//              regions { reservoir { change table (...); } } }           // (PorePressure.hpp)
// Any entry may say `active no;` to be switched off without deleting it.
//
// The dimension comes from the mesh. On a 3D mesh: g (gx gy gz); stress
// (sxx syy szz sxy syz sxz) and gradient (six values) = ∂σ⁰/∂z (the vertical is z in 3D, y
// in 2D); fracturePressure takes a constant or a table, not a values file (its s is an
// arclength along a fracture curve, which a fault surface does not have).
//
// Physics (docs/method.md §1, extended):
//  * bodyForce adds ∫ f·φ to the load.
//  * initialStress is an in-situ stress σ⁰(y) = σ⁰ + y ∂σ⁰/∂y (3D: σ⁰ + z ∂σ⁰/∂z) in
//    equilibrium with the surroundings: the boundary conditions act on the perturbation (a
//    "free" side keeps its in-situ traction), its divergence div σ⁰ = ∂σ⁰/∂y·e_y (3D:
//    ∂σ⁰/∂z·e_z) loads the body, and σ⁰ is added to the fracture tractions (σ_n += n·σ⁰n,
//    τ_c += t_c·σ⁰n on each tangent t_c) and to every stress written.
//  * fracturePressure p on a fracture: the friction bound uses the effective normal stress,
//    ρ = c − μ(σ_n + p) (the paper's poroelastic remark).
#pragma once

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/core/Types.hpp"
#include "friction/effect/GivenField.hpp"
#include "friction/time/TimeFunction.hpp"

namespace friction {

class FrictionField;

class Dictionary;
class DictionaryWriter;
class ElasticityAssembler;
struct ControlNode;
struct Mesh;
struct SplitMesh;

/// What an effect may look at once the fracture system exists (FrictionCase::setup): the
/// control nodes (their positions, fractures and frames) and the split mesh they come from.
struct EffectContext {
  const SplitMesh& split;
  const std::vector<ControlNode>& nodes;
  const std::vector<std::string>& fractureNames;
  std::ostream& log;
  /// The split space's assembler (loads that are assembled once), if the caller has one.
  const ElasticityAssembler* assembler = nullptr;
  /// Per fracture (fractureNames' order): 1 where some effect gives it a fluid pressure of its
  /// own (givesPressureOn); empty: none does.
  std::vector<char> ownPressure = {};
};

/// A field (FrictionField: a number, depth, points, arclength) at the control nodes of the
/// fractures `takes` accepts (index into context.fractureNames): `at` its value per control
/// node (0 elsewhere), `on` 1 where set. A field that is not constant logs its range per
/// fracture: "Fracture <f>: <what> from min .. to max .. Pa over N nodes".
void fieldOnFractures(const FrictionField& field, const EffectContext& context,
                      const std::function<bool(std::size_t)>& takes, const std::string& what,
                      Eigen::VectorXd& at, std::vector<char>& on);

/// Fails at `key` of d unless `name` is one of `fractures` (the case's fractures): "key
/// 'fracture': 'x' is not a fracture of the case; did you mean …? (fractures: …)".
void requireFracture(const Dictionary& d, const std::string& key, const std::string& name,
                     const std::vector<std::string>& fractures);

class Effect {
 public:
  virtual ~Effect() = default;

  static std::vector<std::string> names();
  /// Reads 'type' and that type's keys. fractureNames: to check 'fracture' entries; caseDir:
  /// files named in the dictionary are relative to it; dim: the mesh's dimension (2 or 3),
  /// which sets the number of components the keys take.
  static std::unique_ptr<Effect> New(const std::string& name, const Dictionary& dict,
                                     const std::vector<std::string>& fractureNames,
                                     const std::string& caseDir, int dim);

  const std::string& name() const { return name_; }
  virtual std::string type() const = 0;
  /// One line for the log: what the effect does with which values.
  virtual std::string describe() const = 0;

  /// Called once, after the fracture system is built and before the first step: an effect
  /// that varies along the fractures evaluates its fields at the control nodes here (and
  /// checks them: InputError naming the key and the node). `nodes` of later calls are these.
  virtual void bind(const EffectContext& /*context*/) {}
  /// Called once when the case is read, before any work: an effect that names parts of the
  /// mesh (regions) resolves and checks them here (InputError naming the key).
  virtual void setMesh(const Mesh& /*mesh*/) {}
  /// Called once when the case is read, after setMesh: the fields the program running the
  /// case gives it (GivenField.hpp; rows per vertex of `mesh`, the split mesh), maybe none. An
  /// effect whose entry says its values come from the caller (porePressure's `data script;`)
  /// takes its field here and returns the field's key; InputError naming its own key when the
  /// field is not given. The default takes none: the case refuses a field no effect takes.
  virtual std::vector<std::string> takeGivenFields(const GivenFields& /*given*/,
                                                   const Mesh& /*mesh*/) {
    return {};
  }
  /// True if the effect gives a fluid pressure on the fractures: the tables and the fault's
  /// VTK then carry p and σ'_n.
  virtual bool givesFracturePressure() const { return false; }
  /// True if the effect gives fracture `name` a fluid pressure of its own (faultPressure,
  /// fracturePressure): the rock's pore pressure then leaves that fracture alone.
  virtual bool givesPressureOn(const std::string& /*name*/) const { return false; }

  /// Effects with a state of their own (faultPressure's computed diffusion): advance it to
  /// time t [s], once per step before the step's loads and pressures are asked for (t grows
  /// from step to step; the first call after bind() or readState() starts from their time).
  virtual void advance(double /*t*/) {}
  /// Whether the effect has a state that a restart needs (written in uniform/frictionState,
  /// sub-dictionary effects/<name>).
  virtual bool hasState() const { return false; }
  /// Write the state, at full precision, into the writer's open sub-dictionary.
  virtual void writeState(DictionaryWriter& /*out*/) const {}
  /// Read it back (a restart from a time folder of time t): InputError naming the key when it
  /// does not fit (another mesh, another effect).
  virtual void readState(const Dictionary& /*in*/, double /*t*/) {}

  /// Add this effect's nodal forces at time t (split space) [N per m in 2D, N in 3D].
  virtual void addLoad(const ElasticityAssembler& /*split*/, double /*t*/,
                       Eigen::VectorXd& /*F*/) const {}
  /// Add to the fracture tractions at the control nodes at time t [Pa]: σ_n one per node,
  /// τ k per node (SlipResponse.hpp).
  virtual void addFractureTraction(const std::vector<ControlNode>& /*nodes*/, double /*t*/,
                                   Eigen::VectorXd& /*sigmaN*/, Eigen::VectorXd& /*tau*/) const {}
  /// Add the fluid pressure p at the control nodes at time t [Pa].
  virtual void addFracturePressure(const std::vector<ControlNode>& /*nodes*/,
                                   const std::vector<std::string>& /*fractureNames*/, double /*t*/,
                                   Eigen::VectorXd& /*p*/) const {}
  /// In-situ stress at x (zero unless initialStress) [Pa], symmetric: added to written
  /// stresses. In 2D the in-plane σ⁰ in the upper-left 2 × 2 block, the rest 0 (σ⁰_zz = 0).
  virtual Eigen::Matrix3d initialStress(const Point& /*x*/) const {
    return Eigen::Matrix3d::Zero();
  }
  /// True if stressOffset() is not zero: the written stresses then add it.
  virtual bool givesStressOffset() const { return false; }
  /// What the effect adds at time t to the stress C:ε(u) of cell `cell` at x to make the total
  /// stress written [Pa], symmetric: initialStress(x) unless the effect says otherwise
  /// (porePressure: −α_B Δp_b I). 2D: the in-plane block in the upper-left 2 × 2, and σ_zz.
  virtual Eigen::Matrix3d stressOffset(Index /*cell*/, const Point& x, double /*t*/) const {
    return initialStress(x);
  }

 protected:
  std::string name_;
};

}  // namespace friction
