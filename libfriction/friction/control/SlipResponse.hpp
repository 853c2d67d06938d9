// SlipResponse: what the control problem needs from the elastic body in one time step — the
// affine maps from a slip increment to the fracture tractions (docs/method.md §4). The finite
// element implementation does each call with one back-substitution of the one factor.
//
// Layout: each of the n fracture nodes carries a block of k tangential components (k = d − 1:
// 1 in 2D, 2 in 3D), on the node's tangent basis t₁ … t_k. Vectors of tangential quantities
// (β, τ, qt, a dual solve's τ) have k·n entries, node-major: node i's components at k·i …
// k·i + k − 1. Per-node scalars (σ_n, qn, weights, freeMask) have n entries.
#pragma once

#include <string>
#include <vector>

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

/// The interface operator in the fracture frames: column k·i + c holds τ (k·n entries) and
/// σ_n (n entries) caused by a unit jump along t_c at node i, with zero loads and zero
/// Dirichlet data.
struct InterfaceOperator {
  Eigen::MatrixXd Stt;  ///< k·n × k·n [Pa/m]; columns of held nodes (freeMask 0) are zero
  Eigen::MatrixXd Snt;  ///< n × k·n [Pa/m]; likewise
  /// Only when asked for (withOpening): τ (k·n × n) and σ_n (n × n) [Pa/m] caused by a unit
  /// opening g at node i (the jump −n_Γ); columns of held nodes are zero.
  Eigen::MatrixXd Stn, Snn;
  long solves = 0;                                       ///< back-substitutions spent forming it
  InterfaceMethod method = InterfaceMethod::dualSolves;  ///< how it was formed
};

class SlipResponse {
 public:
  virtual ~SlipResponse() = default;

  /// Number of fracture nodes n (all fractures, concatenated in arclength order).
  virtual Eigen::Index size() const = 0;
  /// Tangential components per node k (d − 1).
  virtual int blockSize() const = 0;
  /// Lumped mass of Γ per node [m]: the M of docs/method.md (J and norms are in this inner
  /// product).
  virtual const Eigen::VectorXd& weights() const = 0;
  /// 1 where β is an unknown, 0 where the jump is held (tips, nodes on Dirichlet patches).
  virtual const Eigen::VectorXd& freeMask() const = 0;
  /// Per tangential component (k·n): 1 where that component of β is an unknown. A roller
  /// holds only the jump's components it fixes, so a node may be free (freeMask 1) with some
  /// components held. This default holds a node's components together.
  virtual Eigen::VectorXd componentMask() const {
    const Eigen::Index n = size(), k = blockSize();
    Eigen::VectorXd m(k * n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index c = 0; c < k; ++c) m[k * i + c] = freeMask()[i];
    return m;
  }

  /// Primal solve: this step's loads, jump Σ_c (s_n + β)_c t_c − g n_Γ. beta: k·n entries, or
  /// k·n + n with the openings g [m] last (none: g = 0). Returns τ (k·n) and σ_n (n) [Pa].
  virtual void primal(const Eigen::VectorXd& beta, Eigen::VectorXd& tau,
                      Eigen::VectorXd& sigmaN) = 0;
  /// Dual solve: no loads, zero Dirichlet data, jump Σ_c qt_c t_c + qn n_Γ (qt: k·n, qn: n,
  /// in m). Returns the tangential traction τ(p) (k·n) [Pa], and σ_n(p) (n) if sigmaNDual is
  /// given.
  virtual void dual(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn, Eigen::VectorXd& tauDual,
                    Eigen::VectorXd* sigmaNDual = nullptr) = 0;
  /// Dual solves for m right-hand sides at once: column c of qt (k·n × m) and qn (n × m) gives
  /// column c of tauDual (k·n × m) and, if asked, of sigmaNDual (n × m), as dual() does, up to
  /// round-off. Counts m back-substitutions. This default makes m calls of dual(); the finite
  /// element implementation solves them as one block (SparseFactor's multi-column solve), which
  /// CHOLMOD's supernodal solve runs with matrix–matrix kernels: much cheaper per column.
  virtual void dualBlock(const Eigen::MatrixXd& qt, const Eigen::MatrixXd& qn,
                         Eigen::MatrixXd& tauDual, Eigen::MatrixXd* sigmaNDual = nullptr);

  /// The adjoint of β ↦ (τ, σ_n) in the M inner product of weights(): M⁻¹ (S_ttᵀ M qt +
  /// S_ntᵀ M qn) (qt: k·n, qn: n), zero at held nodes — what the exact gradient needs. Where
  /// M·S is symmetric (tractions recovered with the lumped M) it is the dual solve's τ, the
  /// default; an implementation that recovers with another mass overrides it. With
  /// normalAdjoint, also the adjoint's normal part M⁻¹ (S_tnᵀ M qt + S_nnᵀ M qn) on the jump
  /// +n_Γ (n entries; the opening's is its negative): the dual solve's σ_n by default.
  virtual void adjoint(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn,
                       Eigen::VectorXd& tauAdjoint, Eigen::VectorXd* normalAdjoint = nullptr) {
    dual(qt, qn, tauAdjoint, normalAdjoint);
  }

  /// The fracture's node graph: for each node, the nodes that share a fracture element with
  /// it (2D: its neighbours along the fracture; 3D: along the fault triangles' edges, all
  /// six nodes of a P2 triangle). What a preconditioner needs to sparsify S by distance;
  /// this default knows no graph and returns none.
  virtual std::vector<std::vector<Eigen::Index>> nodeGraph() const { return {}; }

  /// The interface operator, formed as `method` asks where the implementation can (the
  /// result says how it was formed); withOpening adds the opening's columns Stn, Snn. This
  /// default makes one dual solve per tangential component of each free node (k per node),
  /// and one more per node with withOpening.
  virtual InterfaceOperator interfaceOperator(InterfaceMethod method, bool withOpening = false);
};

}  // namespace friction
