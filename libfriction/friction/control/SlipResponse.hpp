// SlipResponse: what the control problem needs from the elastic body in one time step — the
// affine maps from a slip increment to the fracture tractions (docs/method.md §4). The finite
// element implementation does each call with one back-substitution of the one factor.
#pragma once

#include <Eigen/Core>

namespace friction {

class SlipResponse {
 public:
  virtual ~SlipResponse() = default;

  /// Number of fracture nodes (all fractures, concatenated in arclength order).
  virtual Eigen::Index size() const = 0;
  /// Lumped mass of Γ per node [m]: the M of docs/method.md (J and norms are in this inner
  /// product).
  virtual const Eigen::VectorXd& weights() const = 0;
  /// 1 where β is an unknown, 0 where the jump is held (tips, nodes on Dirichlet patches).
  virtual const Eigen::VectorXd& freeMask() const = 0;

  /// Primal solve: this step's loads, jump (s_n + β) t_Γ. Returns τ and σ_n per node [Pa].
  virtual void primal(const Eigen::VectorXd& beta, Eigen::VectorXd& tau,
                      Eigen::VectorXd& sigmaN) = 0;
  /// Dual solve: no loads, zero Dirichlet data, jump qt t_Γ + qn n_Γ. Returns the
  /// tangential traction τ(p) per node [Pa] (qt, qn in m), and σ_n(p) if sigmaNDual is given.
  virtual void dual(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn, Eigen::VectorXd& tauDual,
                    Eigen::VectorXd* sigmaNDual = nullptr) = 0;
};

}  // namespace friction
