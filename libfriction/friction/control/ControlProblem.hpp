// ControlProblem: the discrete objective J(β) = ½ DᵀMD + (ζ/2) βᵀMβ of one time step and its
// gradient in the M inner product (docs/method.md §4), on top of a SlipResponse.
//
// Friction enters node by node through ρ = c − μ σ_n (Coulomb: c = 0, μ = μ_f; Tresca:
// μ = 0, c = g; frictionless: μ = c = 0), so every law shares one code path.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "friction/control/Complementarity.hpp"
#include "friction/control/SlipResponse.hpp"

namespace friction {

enum class GradientKind {
  exact,     ///< [beyond] includes the normal part μ P'_ρ D n_Γ of the dual jump
  frozenRho  ///< the paper's (46)–(47), (54): ρ treated as fixed (Tresca-like)
};

/// Everything known at one β.
struct ControlState {
  Eigen::VectorXd beta, tau, sigmaN, rho, D;
  std::vector<NodeComplementarity> node;
  double J = 0;
  long primalSolves = 0;  ///< running count, for the report
};

class ControlProblem {
 public:
  /// mu, cohesion: per node μ (–) and c [Pa]; gamma [Pa/m] > 0; zeta [Pa/m] ≥ 0.
  ControlProblem(SlipResponse& response, Eigen::VectorXd mu, Eigen::VectorXd cohesion, double gamma,
                 double zeta, GradientKind gradient);

  /// Primal solve at β, then D, J. (One back-substitution.)
  ControlState evaluate(const Eigen::VectorXd& beta);
  /// D and J from tractions already known for β (no solve): for optimizers that model the
  /// affine maps themselves (semismoothNewton).
  ControlState stateFrom(const Eigen::VectorXd& beta, Eigen::VectorXd tau,
                         Eigen::VectorXd sigmaN) const;
  /// Gradient of J at an evaluated state, in the M inner product (one back-substitution).
  Eigen::VectorXd gradient(const ControlState& s);

  /// ‖D‖_M / ‖Σ‖_M on the free nodes, Σ = (τ, σ_n) the traction on Γ: the relative
  /// residual of the friction law. The scale is the whole traction, not ‖τ‖ alone, because
  /// the answer may be τ = 0 (frictionless, or open in tension), where ‖D‖/‖τ‖ stays 1.
  /// Zero when D = 0 (e.g. zero load).
  double relativeResidual(const ControlState& s) const;
  /// ⟨a, b⟩_M
  double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  double norm(const Eigen::VectorXd& a) const { return std::sqrt(dot(a, a)); }

  Eigen::Index size() const { return response_.size(); }
  const Eigen::VectorXd& freeMask() const { return response_.freeMask(); }
  const Eigen::VectorXd& mu() const { return mu_; }
  double gamma() const { return gamma_; }
  double zeta() const { return zeta_; }
  SlipResponse& response() { return response_; }
  long numPrimal() const { return numPrimal_; }
  long numDual() const { return numDual_; }

 private:
  SlipResponse& response_;
  Eigen::VectorXd mu_, cohesion_;
  double gamma_, zeta_;
  GradientKind gradientKind_;
  long numPrimal_ = 0, numDual_ = 0;
};

}  // namespace friction
