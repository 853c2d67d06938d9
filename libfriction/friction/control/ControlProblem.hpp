// ControlProblem: the discrete objective J(β) = ½ DᵀMD + (ζ/2) βᵀMβ of one time step and its
// gradient in the M inner product (docs/method.md §4), on top of a SlipResponse.
//
// Friction enters node by node through ρ = c − μ σ_n (Coulomb: c = 0, μ = μ_f; Tresca:
// μ = 0, c = g; frictionless: μ = c = 0), so every law shares one code path. β, τ, D and the
// gradient have k components per node (SlipResponse.hpp); σ_n, ρ, μ, c one per node.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "friction/control/Complementarity.hpp"
#include "friction/control/SlipResponse.hpp"
#include "friction/law/Weakening.hpp"

namespace friction {

enum class GradientKind {
  exact,     ///< [beyond] includes the normal part μ P'_ρ D n_Γ of the dual jump
  frozenRho  ///< the paper's (46)–(47), (54): ρ treated as fixed (Tresca-like)
};

/// Fractures that open (docs/method.md §4, "Fractures that open"): which nodes may, the fluid
/// pressure, and γ_n.
struct OpeningSettings {
  Eigen::VectorXd unilateral;  ///< n: 1 where the node's fracture may open, 0 where it may not
  Eigen::VectorXd pressure;    ///< n: the fracture pressure p [Pa] (σ'_n = σ_n + p)
  double gammaN = 1;           ///< γ_n > 0 [Pa/m] of the normal complementarity
};

/// Friction that weakens with the slip path δ (slipWeakening, FrictionLaw.hpp): per node its
/// weakening, the path δ_n at the step's start [m], the cohesion c [Pa] and the fluid pressure
/// p [Pa]. At a node that weakens, ρ = c − μ(δ_n + |β|)(σ_n + p) replaces ρ = c − μ σ_n with
/// the constructor's cohesion and μ; the others keep those.
struct WeakeningSettings {
  std::vector<WeakeningNode> nodes;  ///< n (form none: the node does not weaken)
  Eigen::VectorXd pathStart, cohesion, pressure;
};

/// Everything known at one β.
struct ControlState {
  /// The control (k·n tangential entries, node-major, then n openings g with OpeningSettings)
  /// and the residual D in the same layout; τ k·n.
  Eigen::VectorXd beta, tau, D;
  Eigen::VectorXd sigmaN, rho;            ///< n
  std::vector<NodeComplementarity> node;  ///< n
  /// With openings: per node 1 where the faces are in contact (σ'_n + γ_n g < 0, or the
  /// fracture may not open), 0 where open (τ = 0, σ'_n = 0 sought).
  std::vector<char> contact;
  /// With weakening: per node μ at δ_n + |β| (the constructor's μ where the node does not
  /// weaken) and ∂ρ/∂|β| = −μ'(δ)(σ_n + p) [Pa/m] (0 there); empty without.
  Eigen::VectorXd mu, dRhoDPath;
  double J = 0;
  long primalSolves = 0;  ///< running count, for the report
};

class ControlProblem {
 public:
  /// mu, cohesion: per node μ (–) and c [Pa]; gamma [Pa/m] > 0; zeta [Pa/m] ≥ 0.
  /// opening: fractures that may open (the control gains the n openings); none: bilateral.
  /// cohesion holds c − μ p where a fracture pressure p acts.
  /// weakening: friction that weakens with the slip path (refused with openings).
  ControlProblem(SlipResponse& response, Eigen::VectorXd mu, Eigen::VectorXd cohesion, double gamma,
                 double zeta, GradientKind gradient, const OpeningSettings* opening = nullptr,
                 const WeakeningSettings* weakening = nullptr);

  /// Primal solve at β, then D, J. (One back-substitution.)
  ControlState evaluate(const Eigen::VectorXd& beta);
  /// D and J from tractions already known for β (no solve): for optimizers that model the
  /// affine maps themselves (semismoothNewton).
  ControlState stateFrom(const Eigen::VectorXd& beta, Eigen::VectorXd tau,
                         Eigen::VectorXd sigmaN) const;
  /// Gradient of J at an evaluated state, in the M inner product (one back-substitution).
  Eigen::VectorXd gradient(const ControlState& s);

  /// Entry (row, col) of the generalised Jacobian dD/dβ = (I − P'_N) S_tt + γ P'_N + μ P'_ρ S_nt
  /// at s (docs/method.md §4), rows and columns in the k·n layout (row: component r of node
  /// i). Its sums keep the order of the scalar (k = 1) expression S_tt + μ P'_ρ S_nt, where
  /// the rows that Newton solves have 1 − P'_N = 1 and P'_N = 0.
  double jacobianEntry(const ControlState& s, const Eigen::MatrixXd& Stt,
                       const Eigen::MatrixXd& Snt, Eigen::Index row, Eigen::Index col) const {
    const Eigen::Index k = blockSize(), i = row / k, r = row % k;
    const NodeComplementarity& c = s.node[i];
    double g = ((r == 0 ? 1.0 : 0.0) - c.dPdN(r, 0)) * Stt(k * i, col);
    for (Eigen::Index j = 1; j < k; ++j)
      g += ((r == j ? 1.0 : 0.0) - c.dPdN(r, j)) * Stt(k * i + j, col);
    g += muAt(s, i) * c.dPdRho[r] * Snt(i, col);
    if (col / k == i && c.dPdN(r, col % k) != 0) g += gamma_ * c.dPdN(r, col % k);
    // Weakening: ρ falls with |β_i|, ∂ρ/∂β_i = (∂ρ/∂|β|) β̂_i, so −P'_ρ ∂ρ/∂β_i joins the node's
    // own block.
    if (col / k == i && s.dRhoDPath.size() && s.dRhoDPath[i] != 0)
      g -= c.dPdRho[r] * s.dRhoDPath[i] * slipDirection(s, i)[col % k];
    return g;
  }
  /// μ of node i at state s: the weakened one where the friction weakens.
  double muAt(const ControlState& s, Eigen::Index i) const {
    return s.mu.size() ? s.mu[i] : mu_[i];
  }
  /// The unit direction of node i's slip increment, β_i/|β_i|; at β_i = 0 the one the slip
  /// takes from there, −N̂ (β is opposite to N in the slip state, docs/method.md §3).
  Block slipDirection(const ControlState& s, Eigen::Index i) const;
  bool weakens() const { return weakening_ != nullptr; }
  const WeakeningSettings* weakening() const { return weakening_; }

  /// Entry (row, col) of dD/dx for the whole control x = (β, g) (with openings): the
  /// tangential block is jacobianEntry's; a column of g_j adds (I − P'_N) S_tn + μ P'_ρ (S_nn
  /// + γ_n δ_ij) in contact; a normal row reads −γ_n δ in contact, (S_nt, S_nn) where open.
  double jacobianEntryWithOpening(const ControlState& s, const InterfaceOperator& S,
                                  Eigen::Index row, Eigen::Index col) const;

  /// ‖D‖_M / ‖Σ‖_M on the free nodes, Σ = (τ, σ_n) the traction on Γ: the relative
  /// residual of the friction law. The scale is the whole traction, not ‖τ‖ alone, because
  /// the answer may be τ = 0 (frictionless, or open in tension), where ‖D‖/‖τ‖ stays 1.
  /// Zero when D = 0 (e.g. zero load).
  double relativeResidual(const ControlState& s) const;
  /// ⟨a, b⟩_M of two k·n vectors: every component of node i weighs weights[i].
  double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  double norm(const Eigen::VectorXd& a) const { return std::sqrt(dot(a, a)); }

  /// Length of the control: k·n, or k·n + n with openings.
  Eigen::Index size() const { return componentMask_.size(); }
  /// True when the control holds the openings g after the k·n tangential entries.
  bool hasOpening() const { return opening_; }
  const OpeningSettings& openingSettings() const { return openingSettings_; }
  Eigen::Index numNodes() const { return response_.size(); }
  int blockSize() const { return response_.blockSize(); }
  /// 1 where the node's jump is free, per node (n).
  const Eigen::VectorXd& freeMask() const { return response_.freeMask(); }
  /// 1 where a component of the control is an unknown: the response's componentMask, then
  /// with openings 1 at the free nodes of fractures that may open.
  const Eigen::VectorXd& componentMask() const { return componentMask_; }
  const Eigen::VectorXd& mu() const { return mu_; }
  double gamma() const { return gamma_; }
  /// The γ of D from now on (semismoothNewton iterates with its own where the case's is far
  /// below the interface stiffness: D = 0 does not depend on γ, the path does).
  void setGamma(double gamma) { gamma_ = gamma; }
  /// The γ_n of D_n from now on (semismoothNewton's own where the case's is far above the
  /// interface's normal stiffness: D = 0 does not depend on γ_n either).
  void setGammaNormal(double gammaN) { openingSettings_.gammaN = gammaN; }
  double zeta() const { return zeta_; }
  SlipResponse& response() { return response_; }
  long numPrimal() const { return numPrimal_; }
  long numDual() const { return numDual_; }

 private:
  /// ⟨a, b⟩ weighted per node (n-vectors).
  double nodeDot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;

  SlipResponse& response_;
  Eigen::VectorXd mu_, cohesion_;
  Eigen::VectorXd componentMask_, componentWeights_;  ///< componentMask; weights repeated k times
  double gamma_, zeta_;
  GradientKind gradientKind_;
  bool opening_ = false;
  OpeningSettings openingSettings_;
  const WeakeningSettings* weakening_ = nullptr;
  long numPrimal_ = 0, numDual_ = 0;
};

}  // namespace friction
