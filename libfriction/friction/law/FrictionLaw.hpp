// FrictionLaw: the friction bound ρ of a fracture, in the one form every law shares,
//   ρ = c − μ σ_n   (σ_n < 0 in compression; ρ ≤ 0 means open: τ = 0),
// run-time selectable by name from the table in FrictionLaw.cpp. μ and c are fields along the
// fracture (FrictionField.hpp): a number, or a table in arclength, values at points, or a
// function of depth; the case evaluates them at its fracture nodes.
//
// slipWeakening (docs/method.md §3): μ falls with the slip path δ [m] a node has slid, from
// μ_s to μ_d over the critical slip D_c — linear, μ = μ_d + (μ_s − μ_d) max(0, 1 − δ/D_c), or
// exponential, μ = μ_d + (μ_s − μ_d) e^(−δ/D_c). Its state is δ per node (the case keeps it,
// writes it in uniform/frictionState and restarts from it); mu() is μ_s, the μ at δ = 0.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "friction/law/FrictionField.hpp"
#include "friction/law/Weakening.hpp"

namespace friction {

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// Names in the selection table (for messages, -listModels and the README).
  static std::vector<std::string> names();
  /// Reads 'law' and that law's keys from a fracture's dictionary. caseDir: the files a field
  /// names are relative to it; dim: the mesh's dimension (2 or 3).
  static std::unique_ptr<FrictionLaw> New(const Dictionary& dict, const std::string& caseDir,
                                          int dim);

  virtual std::string name() const = 0;
  /// μ in ρ = c − μ σ_n (dimensionless).
  virtual const FrictionField& mu() const { return zero_; }
  /// c in ρ = c − μ σ_n [Pa].
  virtual const FrictionField& cohesion() const { return zero_; }
  /// The dictionary key c is read from ('threshold' or 'cohesion'; "" when c = 0).
  virtual std::string cohesionKey() const { return ""; }
  /// Laws whose μ falls with the slip path (slipWeakening): the form; none for the others.
  virtual Weakening weakening() const { return Weakening::none; }
  /// slipWeakening: μ_d (–) and D_c [m] as fields along the fracture.
  virtual const FrictionField& dynamicCoefficient() const { return zero_; }
  virtual const FrictionField& criticalSlip() const { return zero_; }
  /// Rate-and-state friction (law rateState): integrated in time by timeIntegration
  /// quasiDynamic only (TimeIntegrator.hpp).
  virtual bool rateAndState() const { return false; }
  /// A slip rate imposed in time (law creep): also integrated by quasiDynamic only, beside
  /// rate-and-state faults (the deep creeping extension that loads them).
  virtual bool imposesSlipRate() const { return false; }

 private:
  FrictionField zero_;
};

/// τ = 0 on the fracture.
class Frictionless : public FrictionLaw {
 public:
  std::string name() const override { return "frictionless"; }
};

/// |τ| ≤ g, a fixed threshold g > 0 [Pa] ('threshold').
class Tresca : public FrictionLaw {
 public:
  explicit Tresca(FrictionField g) : g_(std::move(g)) {}
  std::string name() const override { return "tresca"; }
  const FrictionField& cohesion() const override { return g_; }
  std::string cohesionKey() const override { return "threshold"; }

 private:
  FrictionField g_;
};

/// |τ| ≤ −μ_f σ_n with μ_f ≥ 0 ('frictionCoefficient').
class Coulomb : public FrictionLaw {
 public:
  explicit Coulomb(FrictionField muF) : mu_(std::move(muF)) {}
  std::string name() const override { return "coulomb"; }
  const FrictionField& mu() const override { return mu_; }

 private:
  FrictionField mu_;
};

/// |τ| ≤ c − μ_f σ_n: Coulomb with cohesion c ≥ 0 [Pa] ('frictionCoefficient', 'cohesion').
class CoulombCohesion : public FrictionLaw {
 public:
  CoulombCohesion(FrictionField muF, FrictionField c) : mu_(std::move(muF)), c_(std::move(c)) {}
  std::string name() const override { return "coulombCohesion"; }
  const FrictionField& mu() const override { return mu_; }
  const FrictionField& cohesion() const override { return c_; }
  std::string cohesionKey() const override { return "cohesion"; }

 private:
  FrictionField mu_, c_;
};

/// |τ| ≤ c − μ(δ) σ_n with μ falling from μ_s to μ_d over the slip path D_c ('staticCoefficient',
/// 'dynamicCoefficient', 'criticalSlip', 'weakening' linear or exponential, 'cohesion' ≥ 0
/// optional).
class SlipWeakening : public FrictionLaw {
 public:
  SlipWeakening(FrictionField muS, FrictionField muD, FrictionField dc, FrictionField c,
                Weakening form)
      : muS_(std::move(muS)),
        muD_(std::move(muD)),
        dc_(std::move(dc)),
        c_(std::move(c)),
        form_(form) {}
  std::string name() const override { return "slipWeakening"; }
  const FrictionField& mu() const override { return muS_; }
  const FrictionField& cohesion() const override { return c_; }
  std::string cohesionKey() const override { return "cohesion"; }
  Weakening weakening() const override { return form_; }
  const FrictionField& dynamicCoefficient() const override { return muD_; }
  const FrictionField& criticalSlip() const override { return dc_; }

 private:
  FrictionField muS_, muD_, dc_, c_;
  Weakening form_;
};

/// Regularised rate-and-state friction (RateState.hpp; docs/method.md §3): keys 'a', 'b',
/// 'characteristicSlip' L [m], 'referenceFriction' f₀ (0.6), 'referenceSlipRate' V₀ [m/s]
/// (1e-6), 'initialSlipRate' V_init [m/s] (the slip rate the state ψ₀ gives under the initial
/// stress), 'stateEvolution' aging (default) or slip, and the radiation damping: 'shearWaveSpeed'
/// c_s [m/s] (η = G/(2 c_s), G of the rock at the fault) or 'radiationDamping' η [Pa s/m].
class RateStateLaw : public FrictionLaw {
 public:
  struct Fields {
    FrictionField a, b, L, f0, V0, initialV;
    bool aging = true;
    double shearWaveSpeed = 0, radiationDamping = -1;  ///< one of the two given (else < 0 / 0)
    /// Optional: where this field is > 0 a node creeps at that rate [m/s] along creepDirection
    /// (Ω⁺ relative to Ω⁻, projected on its tangent plane) as law creep's, the rest of the
    /// fracture obeying the law: the creeping region around a 3D fault (SEAS BP5), one surface.
    FrictionField creepRate{0.0};
    Eigen::Vector3d creepDirection = Eigen::Vector3d::Zero();  ///< zero: no creepSlipRate
  };
  explicit RateStateLaw(Fields f) : f_(std::move(f)) {}
  std::string name() const override { return "rateState"; }
  const FrictionField& mu() const override { return f_.f0; }
  bool rateAndState() const override { return true; }
  const Fields& fields() const { return f_; }

 private:
  Fields f_;
};

/// A slip rate imposed in time (docs/method.md §3): the fracture's faces slide steadily at
/// 'slipRate' V [m/s] (≥ 0, a number or a field) along 'direction', the direction in which
/// Ω⁺ moves relative to Ω⁻ ((x y) in 2D, (x y z) in 3D, projected on each node's tangent
/// plane), whatever the tractions: a creeping fault's extension below the seismogenic zone
/// (SEAS BP3's x_d ≥ W_f), loading the rate-and-state faults of a quasiDynamic run.
class Creep : public FrictionLaw {
 public:
  Creep(FrictionField rate, Eigen::Vector3d direction)
      : rate_(std::move(rate)), direction_(std::move(direction)) {}
  std::string name() const override { return "creep"; }
  bool imposesSlipRate() const override { return true; }
  const FrictionField& slipRate() const { return rate_; }
  const Eigen::Vector3d& direction() const { return direction_; }

 private:
  FrictionField rate_;
  Eigen::Vector3d direction_;
};

}  // namespace friction
