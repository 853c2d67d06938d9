// FrictionLaw: the friction bound ρ of a fracture, in the one form every law shares,
//   ρ = c − μ σ_n   (σ_n < 0 in compression; ρ ≤ 0 means open: τ = 0),
// run-time selectable by name from the table in FrictionLaw.cpp. μ and c are fields along the
// fracture (FrictionField.hpp): a number, or a table in arclength, values at points, or a
// function of depth; the case evaluates them at its fracture nodes.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "friction/law/FrictionField.hpp"

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

}  // namespace friction
