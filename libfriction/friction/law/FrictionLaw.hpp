// FrictionLaw: the friction bound ρ of a fracture, in the one form every law shares,
//   ρ = c − μ σ_n   (σ_n < 0 in compression; ρ ≤ 0 means open: τ = 0),
// run-time selectable by name from the table in FrictionLaw.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace friction {

class Dictionary;

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// Names in the selection table (for messages, -listModels and the README).
  static std::vector<std::string> names();
  /// Reads 'law' and that law's keys from a fracture's dictionary.
  static std::unique_ptr<FrictionLaw> New(const Dictionary& dict);

  virtual std::string name() const = 0;
  /// μ in ρ = c − μ σ_n (dimensionless).
  virtual double mu() const = 0;
  /// c in ρ = c − μ σ_n [Pa].
  virtual double cohesion() const = 0;
};

/// τ = 0 on the fracture.
class Frictionless : public FrictionLaw {
 public:
  std::string name() const override { return "frictionless"; }
  double mu() const override { return 0; }
  double cohesion() const override { return 0; }
};

/// |τ| ≤ g, a fixed threshold g > 0 [Pa] ('threshold').
class Tresca : public FrictionLaw {
 public:
  explicit Tresca(double g) : g_(g) {}
  std::string name() const override { return "tresca"; }
  double mu() const override { return 0; }
  double cohesion() const override { return g_; }

 private:
  double g_;
};

/// |τ| ≤ −μ_f σ_n with μ_f ≥ 0 ('frictionCoefficient').
class Coulomb : public FrictionLaw {
 public:
  explicit Coulomb(double muF) : mu_(muF) {}
  std::string name() const override { return "coulomb"; }
  double mu() const override { return mu_; }
  double cohesion() const override { return 0; }

 private:
  double mu_;
};

/// |τ| ≤ c − μ_f σ_n: Coulomb with cohesion c ≥ 0 [Pa] ('frictionCoefficient', 'cohesion').
class CoulombCohesion : public FrictionLaw {
 public:
  CoulombCohesion(double muF, double c) : mu_(muF), c_(c) {}
  std::string name() const override { return "coulombCohesion"; }
  double mu() const override { return mu_; }
  double cohesion() const override { return c_; }

 private:
  double mu_, c_;
};

}  // namespace friction
