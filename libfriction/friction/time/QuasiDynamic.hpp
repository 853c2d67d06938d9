// QuasiDynamic: rate-and-state faults integrated in time on the fault alone (TimeIntegrator.hpp;
// docs/method.md §3; ../shared/METHOD.md §12).
//
// Between two times t_A, t_B of the case's grid the state y = (slip s, ψ) of every control node
// advances by an adaptive embedded Runge–Kutta method (EmbeddedRungeKutta.hpp). Its right-hand
// side is fault-only work: the elastic tractions
//   τ(s, t) = τ_A + θ (τ_B − τ_A) + S_tt (s − s_A),   σ_n likewise with S_nt,   θ = (t − t_A)/(t_B
//   − t_A),
// (τ_A, τ_B: one back-substitution each, the loads of t_A and t_B at the slip s_A; exact for
// loads linear in time between the two), then per node the slip rate from the quasi-dynamic
// balance φ − ηV = σ̄ f(V, ψ) with φ = −τ (the shear that drives the slip: the traction on Ω⁺
// opposes it, docs/method.md §2) and σ̄ = −(σ_n + p), and dψ/dt of the evolution law
// (RateState.hpp). In 3D V is along φ. At t_B one more back-substitution gives the body's
// state for the outputs.
//
// Settings (timeIntegration { type quasiDynamic; ... } in system/frictionSolution):
//   relativeTolerance (1e-8), absoluteSlipTolerance [m] (1e-9), absoluteStateTolerance (1e-9)
//   of the error control, scheme dormandPrince54 (default) or bogackiShampine32, maxStep [s]
//   (none), faultOperator (the S_tt, S_nt of the right-hand side: `auto`, the default, is
//   `hierarchical` where S_tt has autoHierarchicalFrom rows or more and `dense` below;
//   `dense`; or `{ type hierarchical; tolerance 1e-8; eta 2; leafSize 32; }`, compressed as an
//   H-matrix, HierarchicalMatrix.hpp: a product then costs about (k+1)·n·r·log n instead of
//   (k+1)·k·n², within `tolerance` of the dense one block by block; a dense S takes `precision
//   auto|double|single`: auto stores it as floats from autoSingleFrom entries, the sums in double).
//   Each interval starts from the step size the last one proposed (the integrator's state,
//   restarted from uniform/frictionState), so a restarted run steps as an uninterrupted one.
#pragma once

#include <memory>
#include <string>

#include "friction/linalg/HierarchicalMatrix.hpp"
#include "friction/time/EmbeddedRungeKutta.hpp"
#include "friction/time/TimeIntegrator.hpp"

namespace friction {

class QuasiDynamic : public TimeIntegrator {
 public:
  /// settings: the timeIntegration sub-dictionary (nullptr: the defaults).
  explicit QuasiDynamic(const Dictionary* settings);
  std::string name() const override { return "quasiDynamic"; }
  std::string describe() const override;
  std::string prepare(StepHost& host) override;
  void advance(StepHost& host, StepResult& r, const StepResult* previous) override;
  bool hasState() const override { return true; }
  void writeState(DictionaryWriter& out) const override;
  void readState(const Dictionary& in) override;
  bool takesRateState() const override { return true; }
  std::string summary() const override;
  double balanceTolerance(double controlTolerance) const override;
  std::string balanceNote() const override;

 private:
  double relTol_ = 1e-8, absSlip_ = 1e-9, absState_ = 1e-9, maxStep_ = 0;
  RungeKuttaScheme scheme_ = RungeKuttaScheme::dormandPrince54;
  double nextStep_ = 0;  ///< the step size the last interval proposed [s] (0: choose)
  long accepted_ = 0, rejected_ = 0, evaluations_ = 0;  ///< over this run, for the log
  double seconds_ = 0;      ///< wall time in the Runge-Kutta integrations (fault-only work) [s]
  long faultUnknowns_ = 0;  ///< k·n, the size of S_tt
  /// faultOperator hierarchical: [S_tt; S_nt] compressed (formed in prepare(), from the S the
  /// case holds; rebuilt alike by a restarted run, so that it steps as an uninterrupted one).
  enum class OperatorChoice { automatic, dense, hierarchical };
  OperatorChoice choice_ = OperatorChoice::automatic;
  /// faultOperator auto compresses S where S_tt has this many rows or more (k·n): measured on
  /// BP3 (utilities/frictionStudy/faultOperatorStudy.sh, README), below it a product by the
  /// H-matrix saves little and the right-hand side's other work dominates.
  static constexpr long autoHierarchicalFrom = 1000;
  /// ... and keeps it only where it stores at most this share of S's entries (BP3 at 1 000
  /// rows and more: 20-32 %; BP5 at 2 km, a 3D fault of 1 522 nodes: 95 %, and a product
  /// slower than the dense one).
  static constexpr double autoHierarchicalShare = 0.5;
  bool hierarchical_ = false;  ///< decided in prepare() for auto
  HierarchicalSettings hSettings_;
  std::unique_ptr<HierarchicalMatrix> H_;
  /// faultOperator's precision, for a dense S of the right-hand side: auto (single from
  /// autoSingleFrom entries), double, or single. In single precision [S_tt; S_nt] on the moved
  /// nodes is held as floats (Ssingle_) and multiplied with double sums (DenseProduct.hpp): the
  /// product reads half the bytes, and it is bound by memory bandwidth from a few MB on.
  enum class Precision { automatic, full, single };
  Precision precision_ = Precision::automatic;
  /// auto stores S in single precision from this many entries (2²² = 4.2·10⁶, 33.5 MB in
  /// double: beyond the processor's caches, where a product waits on memory). Measured in the
  /// README ("S in single precision"): BP5 at 2 and 1 km.
  static constexpr long autoSingleFrom = 1L << 22;
  /// With S in single precision the written state's balance (tractions from a solve of the
  /// body) is judged against this bound, not tighter: the rounding of S's entries to float
  /// (6e-8 each) moves the integration's tractions by about 1e-7 of their sum's terms.
  static constexpr double singleBalanceTolerance = 1e-6;
  bool single_ = false;      ///< decided in prepare()
  Eigen::MatrixXf Ssingle_;  ///< [S_tt; S_nt] on the moved nodes, in single precision
  /// Decides single_ for a dense S of the right-hand side and stores it so; what it did, for
  /// prepare()'s line (empty in double).
  std::string storeDense(const InterfaceOperator& S);
  /// The nodes the integration moves (prepare()): free, and not creeping. A creeping node's
  /// slip over an interval is its imposed rate times the time, so its columns of S enter the
  /// right-hand side as one vector per interval (creepResponse) and its rows are never read
  /// there. Where some node is not moved (`reduced_`), the right-hand side multiplies by
  /// S_solved = [S_tt; S_nt] on those rows and columns only (dense, or the H-matrix made from
  /// it): BP5 at 2 km moves 1 071 of 1 522 nodes, half the product.
  bool reduced_ = false;
  std::vector<Eigen::Index> solved_;       ///< the moved nodes, ascending
  std::vector<Eigen::Index> solvedIndex_;  ///< per node: its index in solved_, or −1
  Eigen::MatrixXd Ssolved_;  ///< (k+1)·ns × k·ns (empty when H_ holds it compressed)
  /// [S_tt; S_nt] on the moved nodes' rows times the creeping nodes' imposed rates: the
  /// tractions' rate of change from creep [Pa/s], for the interval's rates (advance()).
  Eigen::VectorXd creepResponse(const InterfaceOperator& S, const RateStateFault& f) const;
};

}  // namespace friction
