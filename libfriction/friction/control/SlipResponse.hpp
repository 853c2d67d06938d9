// SlipResponse: what the control problem needs from the elastic body in one time step — the
// affine maps from a slip increment to the fracture tractions (docs/method.md §4). The finite
// element implementation does each call with one back-substitution of the one factor.
#pragma once

#include <string>

#include <Eigen/Core>

namespace friction {

/// How the interface operator S is formed (docs/method.md §4, "The interface operator").
enum class InterfaceMethod {
  factorisation,  ///< from the one factorisation (the bordered matrix's Schur complement)
  blockSolves,    ///< from blocks of right-hand sides with the factor (one solve per jump dof)
  dualSolves      ///< one dual solve per fracture node (the reference)
};
/// "factorisation", "blockSolves", "dualSolves".
const char* toString(InterfaceMethod method);

/// The interface operator in the fracture frames: column k holds τ and σ_n at every node
/// caused by a unit tangential jump at node k, with zero loads and zero Dirichlet data.
struct InterfaceOperator {
  Eigen::MatrixXd Stt, Snt;  ///< n × n [Pa/m]; columns of held nodes (freeMask 0) are zero
  long solves = 0;           ///< back-substitutions spent forming it
  InterfaceMethod method = InterfaceMethod::dualSolves;  ///< how it was formed
};

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

  /// The interface operator, formed as `method` asks where the implementation can (the
  /// result says how it was formed). This default makes one dual solve per free node.
  virtual InterfaceOperator interfaceOperator(InterfaceMethod method);
};

}  // namespace friction
