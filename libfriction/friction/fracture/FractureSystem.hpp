// FractureSystem: the elastic body with imposed jumps on its fractures, discretised as in
// docs/method.md §4 — the finite-element SlipResponse of the control problem.
//
//  * Unknowns x are the dofs of the UNSPLIT mesh (interior dofs and the average ū on Γ); the
//    split displacement is u_split = P x + L j, with L putting ±j/2 on the ⁺/⁻ copies.
//  * K x = Pᵀ(f_split − K_split L j)  (52), where K = Pᵀ K_split P is the unsplit stiffness:
//    it is assembled and factored once per run; every primal and dual solve is one
//    back-substitution.
//  * Traction recovery (53): with r = K_split u_split − f_split, Σ = M⁻¹(r⁺ − r⁻)/2 at the
//    control nodes (M the lumped mass of Γ), σ_n = Σ·n_Γ, τ_c = Σ·t_c on the node's tangent
//    basis t₁ … t_k (k = d − 1; 2D: t₁ = t_Γ). 3D P2: M is the consistent mass of Γ instead
//    (the lumped weights are not the integrals of the P2 shape functions; see factor()).
//  * The imposed jump at a node is Σ_c (s + β)_c t_c (primal) or Σ_c qt_c t_c + qn n_Γ (dual):
//    d jump dofs per node, from k tangential components and one normal.
// Control nodes: 2D, the fracture vertices (P1) and, for P2, also the midpoints of the
// fracture edges, in arclength order. 3D (d from the mesh), per fracture: its nodes in the
// splitter's order (ascending unsplit number), then for P2 the midpoints of its triangles'
// edges, each edge once, by ascending (smaller, larger) unsplit end numbers. The jump is held at
// zero at tips (single nodes: the tip line in 3D) and at nodes on Dirichlet patches. Signs and
// the 3D frame: SignConventions.hpp. Where fractures meet (2D junctions, 3D intersection
// curves, P1 and P2) the jumps of the fractures passing through a node move its sectors, a
// fracture ending on another is held, and two ending together (joined) share the first's
// control node (controlNodes2D, controlNodes3D).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "friction/control/SlipResponse.hpp"
#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/fe/MaterialMap.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/linalg/SparseFactor.hpp"

namespace friction {

/// One node where β is defined.
struct ControlNode {
  int fracture = 0;                ///< index into SplitMesh::fractures
  Index plus = 0;                  ///< node of the split space on the Ω⁺ side
  Index minus = 0;                 ///< node on the Ω⁻ side (== plus at a tip)
  Vector2 x = Vector2::Zero();     ///< the position's first two coordinates (2D callers)
  Point position = Point::Zero();  ///< [m]
  /// The node's frame (SignConventions.hpp) as 3-vectors, z = 0 in 2D: n_Γ and the tangent
  /// basis t₁ … t_k (k = d − 1; in 2D tangent[0] = t_Γ and tangent[1] is unused). 3D: n_Γ
  /// of a vertex is the splitter's area-weighted normal; of a P2 mid-edge node, the normalised
  /// area-weighted sum of the (one or two) fault triangles on its edge — the vertex rule
  /// applied to the midpoint, and the triangles its Γ weight (A/4 from each) comes from, so
  /// that on a flat piece it is that piece's exact normal; t₁, t₂ = tangentBasis(n_Γ).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 2> tangent{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double arclength = 0;  ///< [m] (2D; 0 in 3D)
  double weight = 0;     ///< lumped mass of Γ [m^(d−1)]
  bool tip = false;      ///< single node, or held at a junction (junction): no jump
  /// The fracture ends on a junction (FractureNodeKind::abutting; 2D, and 3D where fault
  /// surfaces meet): its jump there is held at zero, and tip is true too (no jump, no traction
  /// recovered).
  bool junction = false;
  bool onDirichlet = false;  ///< on a Dirichlet patch: jump held at zero
  /// 3D: the tangential component (0 or 1) a roller holds, the slip going on along the other;
  /// −1 if none. It is the component of tangentBasis(n_Γ) along the roller's constraint
  /// direction p when there is one (e.g. p = e_z on a vertical fault), else the basis is
  /// turned (t₂ ∥ p) and it is 1.
  int heldComponent = -1;
};

class FractureSystem : public SlipResponse {
 public:
  /// degree: 1 or 2. The split mesh must outlive the system; the materials (one Material, or
  /// a MaterialMap of one per region of the split mesh's cells) are copied.
  FractureSystem(const SplitMesh& split, int degree, const MaterialMap& materials);

  /// Dirichlet conditions live on the unsplit space: fix patches here, before factor().
  DirichletConditions& dirichlet() { return *dirichlet_; }
  const LagrangeSpace& splitSpace() const { return *splitSpace_; }
  const LagrangeSpace& unsplitSpace() const { return *unsplitSpace_; }
  const ElasticityAssembler& splitAssembler() const { return *splitAssembler_; }

  /// Assemble the unsplit stiffness, eliminate the Dirichlet dofs and factor — once. With
  /// withInterfaceOperator, the factorisation also delivers the interface operator M·S
  /// (docs/method.md §4): the stiffness in the variables (free dofs, jumps) is factored
  /// with the jumps last, and the Schur complement on the jumps is M·S.
  /// `phases` is told each part of the work as it ends (assemblies, the factorisation's
  /// phases), for the log. `ordering`: the fill-reducing ordering (SparseFactor::setOrdering;
  /// automatic decides by the mesh's dimension and the size). `memory`: mumps's low-rank or
  /// out-of-core factor (SparseFactor::setMumpsMemory; none by default).
  FactorStatus factor(const std::string& backend = "cholmod", bool withInterfaceOperator = false,
                      const PhaseReport& phases = {}, Ordering ordering = Ordering::automatic,
                      const MumpsMemory& memory = {});
  /// factor() in two halves, for a caller that decides between them (linearSolver auto):
  /// assemble() does every assembly and takes the Dirichlet conditions out (false: it failed,
  /// and factorAssembled() then says `failed`); predictFactor() is SparseFactor::predict of
  /// the assembled matrix with `backend` (cholmod; false where it cannot tell); useBackend()
  /// replaces the backend before factorAssembled() factors.
  bool assemble(const std::string& backend, const PhaseReport& phases = {},
                Ordering ordering = Ordering::automatic, const MumpsMemory& memory = {});
  bool predictFactor(FactorAnalysis& predicted);
  void useBackend(const std::string& backend, const MumpsMemory& memory = {});
  FactorStatus factorAssembled(bool withInterfaceOperator);
  const SparseFactor& factorization() const { return *factor_; }
  /// The relative residual at which an iterative linear solver's solves stop (linearSolver
  /// amg, key iterativeTolerance); before factor().
  void setIterativeTolerance(double tolerance) { iterativeTolerance_ = tolerance; }

  /// This step's data: the load vector on the SPLIT space (tractions, body force) [N], and
  /// the accumulated slip s_n per control node [m] (k per node, SlipResponse.hpp). Dirichlet
  /// values: set them on dirichlet() before the solves.
  void setStep(const Eigen::VectorXd& loadSplit, const Eigen::VectorXd& accumulatedSlip);

  /// Tractions added to every primal solve's σ_n (n) and τ (k·n) at the control nodes [Pa]
  /// (an in-situ stress); zero by default.
  void setTractionOffset(const Eigen::VectorXd& sigmaN, const Eigen::VectorXd& tau);

  /// Stiffness matrices assembled so far (the unsplit one, plus the split one when there is
  /// a fracture): a counter that shows skipped work in the log.
  int numAssemblies() const { return numAssemblies_; }
  /// With several ranks and a backend that takes summands (mumps): the cells of the unsplit
  /// mesh whose stiffness this rank assembled (its own block); 0 when every rank assembles all.
  Index ownCells() const { return ownCells_; }

  const std::vector<ControlNode>& controlNodes() const { return nodes_; }
  /// 3D: fracture f's triangles (its order) by control node: the three vertices, then for P2
  /// the mid-edge nodes of (0 1), (1 2), (2 0) (−1 in P1). A joined node is the first-listed
  /// fracture's control node, in the other's triangles too.
  const std::vector<std::array<Index, 6>>& triangleNodes(std::size_t f) const {
    return triangleNodes_.at(f);
  }
  /// 3D: the control node of fracture f's node i (SplitMesh order).
  const std::vector<Index>& vertexControl(std::size_t f) const { return vertexControl_.at(f); }
  /// 3D P2: per control node, for a mid-edge node on an intersection curve what its fracture
  /// does there (intersectionCodes' numbers: 1 passes, 2 held, 3 joined), else 0.
  int edgeIntersectionCode(Index k) const {
    return edgeCode_.empty() ? 0 : edgeCode_[static_cast<std::size_t>(k)];
  }
  /// 3D: replace node i's tangent basis by (t₁, n_Γ × t₁), t₁ a unit vector normal to n_Γ —
  /// another choice than tangentBasis()'s. Tangential components (β, τ, S) are then on the new
  /// basis; the physics does not change (the laws are isotropic in the tangent plane).
  void setTangentBasis(Index node, const Eigen::Vector3d& t1);
  /// Control nodes where the jump is held although the fracture is there (Dirichlet).
  int numHeldOnDirichlet() const;
  /// 3D: control nodes where a roller holds one tangential component of the jump.
  int numPartlyHeldOnDirichlet() const;

  // SlipResponse
  Eigen::Index size() const override { return static_cast<Eigen::Index>(nodes_.size()); }
  int blockSize() const override { return dim_ - 1; }
  /// Dimension d of the body: jump and traction dofs per node.
  int dimension() const { return dim_; }
  const Eigen::VectorXd& weights() const override { return weights_; }
  const Eigen::VectorXd& freeMask() const override { return mask_; }
  Eigen::VectorXd componentMask() const override { return componentMask_; }
  void primal(const Eigen::VectorXd& beta, Eigen::VectorXd& tau, Eigen::VectorXd& sigmaN) override;
  void dual(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn, Eigen::VectorXd& tauDual,
            Eigen::VectorXd* sigmaNDual = nullptr) override;
  /// One block back-substitution for all columns (SlipResponse::dualBlock), in blocks of at
  /// most 64 columns (a dense block of a 10⁶-unknown mesh: 0.5 GB).
  void dualBlock(const Eigen::MatrixXd& qt, const Eigen::MatrixXd& qn, Eigen::MatrixXd& tauDual,
                 Eigen::MatrixXd* sigmaNDual = nullptr) override;
  /// 3D P2: with the consistent recovery S = M_c⁻¹ (M·S), and W S is not symmetric (W =
  /// weights()): the adjoint applies M_c⁻ᵀ W to the input before the symmetric M·S. Else the
  /// dual solve.
  void adjoint(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn, Eigen::VectorXd& tauAdjoint,
               Eigen::VectorXd* normalAdjoint = nullptr) override;
  std::vector<std::vector<Eigen::Index>> nodeGraph() const override;
  /// True where Σ is recovered with the consistent mass of Γ (3D P2).
  bool consistentRecovery() const { return consistent_; }
  /// factorisation: the complement the factorisation delivered (factor() with
  /// withInterfaceOperator), else as blockSolves; blockSolves: C − Bᵀ K⁻¹ B by blocks of
  /// right-hand sides; dualSolves: one dual solve per node and tangential component
  /// (SlipResponse's default).
  InterfaceOperator interfaceOperator(InterfaceMethod method, bool withOpening = false) override;
  /// M·S on the jump dofs (d per node that is not a tip, x, y (, z) components, node order),
  /// with the dofs of jumpDofs(): symmetric [N/m]. Empty unless factor() formed it. (3D P2:
  /// the M here is the consistent recovery operator of factor(), not weights().)
  const Eigen::MatrixXd& jumpOperator() const { return factor_->schurComplement(); }
  const std::vector<Index>& jumpDofs() const { return jumpDofs_; }

  /// ‖K_ff x_f − b‖ / ‖b‖ of the last primal solve: how well the discrete equilibrium holds
  /// (round-off of the factorisation; large values flag an ill-conditioned problem).
  double equilibriumResidual() const;
  /// The split displacement [m] of the last primal solve (all split-space dofs).
  Eigen::VectorXd lastSplitDisplacement() const;
  /// W ∂u/∂β (W.rows() × k·n): what W sees of the split displacement per unit slip of each
  /// free component, under no load and zero Dirichlet values. By the adjoint: one
  /// back-substitution per row of W (a few per surface station), not one per slip component.
  /// Collective with a distributed factor (every rank calls it alike).
  Eigen::MatrixXd displacementResponse(const Eigen::SparseMatrix<double>& W);
  /// The unsplit dofs x of the last primal solve (for tests: equal to the unsplit linear
  /// solve when no jump is imposed).
  const Eigen::VectorXd& lastUnsplitSolution() const { return x_; }

 private:
  // nodes_ and weights_ (constructor): 2D along each curve, 3D from the fault triangles.
  /// Fracture f's node i as a control node: its copies and position (the frame is the caller's).
  ControlNode vertexNode(int f, const FractureGeometry& g, Index i) const;
  void controlNodes2D(int degree);
  // Junctions (2D) and intersection nodes (3D: vertices, and P2 mid-edge nodes on the curves):
  // the lifting L and recovery E at nodes where several fractures meet.
  struct JunctionBranch {
    Index plusCopy, minusCopy;  ///< the sectors on either side of a fracture edge at the node
    Index node;                 ///< the control node whose jump it carries, −1 if held
    double sign;  ///< +1, or −1 where the edge's Ω⁺ side is the node's Ω⁻ side
  };
  /// Per copy of the node, the coefficient of each control node's jump in its displacement
  /// (the mean over the copies is zero).
  std::map<Index, std::map<Index, double>> junctionLifting(
      const std::vector<JunctionBranch>& branches) const;
  /// The lifting at junction nodes: copy `copy` moves by coefficient × the jump of `node`.
  struct LiftEntry {
    Index copy, node;
    double coefficient;
  };
  std::vector<LiftEntry> junctionLift_;
  std::vector<char> atJunction_;  ///< per control node: a vertex where fractures meet
  void controlNodes3D(int degree);
  // x and Σ (d per control node, interleaved) for jump vector j (d per control node); with
  // recover false (3D P2), Σ̃ = (r⁺ − r⁻)/2 instead, before the mass solve.
  void solve(const Eigen::VectorXd& j, bool withLoads, Eigen::VectorXd& sigma, bool recover = true);
  // The jump (d per control node) of a dual solve's qt, qn (dual()).
  Eigen::VectorXd dualJump(const Eigen::Ref<const Eigen::VectorXd>& qt,
                           const Eigen::Ref<const Eigen::VectorXd>& qn) const;
  // 3D P2: the consistent recovery operator on the columns of x (d·n rows, interleaved):
  // Σ = X G⁻¹ Σ̃_R per component (transpose: Σ̃ = Rᵀ G⁻ᵀ Xᵀ Σ), see factor().
  void applyRecovery(Eigen::MatrixXd& x, bool transpose) const;
  bool buildRecovery();
  struct Recovery;
  bool buildRecovery(Recovery& rec, const std::vector<Index>& recovered);
  // Σ·direction at a node of sigma (d entries per node), summed in component order.
  double project(const Eigen::VectorXd& sigma, Index node, const Eigen::Vector3d& direction) const;

  const SplitMesh& split_;
  const MaterialMap materials_;
  int dim_ = 2;  ///< the dimension of the split mesh (2: triangles, 3: tetrahedra)
  Mesh unsplitMesh_;
  std::unique_ptr<LagrangeSpace> splitSpace_, unsplitSpace_;
  std::unique_ptr<ElasticityAssembler> splitAssembler_, unsplitAssembler_;
  std::unique_ptr<DirichletConditions> dirichlet_;
  std::unique_ptr<ReducedSystem> reduced_;
  std::unique_ptr<SparseFactor> factor_;
  double iterativeTolerance_ = 1e-10;
  Index ownCells_ = 0;
  // assemble()'s: whether it succeeded, each rank's summand given (own cells), the ordering
  // and the phase report, for factorAssembled() and useBackend().
  bool assembled_ = false;
  bool summands_ = false;
  Ordering ordering_ = Ordering::automatic;
  PhaseReport phases_;
  // After each factorisation: the products' solves restricted to the fractures' reach in the
  // factor (SparseFactor::restrictSolves), and the log's line saying how much of it they read.
  void restrictProducts();

  std::vector<ControlNode> nodes_;
  Eigen::VectorXd weights_, mask_, componentMask_;
  Eigen::SparseMatrix<double> P_;   ///< split dofs × unsplit dofs
  Eigen::SparseMatrix<double> L_;   ///< split dofs × d·control nodes
  Eigen::SparseMatrix<double> B_;   ///< Pᵀ K_split L
  Eigen::SparseMatrix<double> Tx_;  ///< Σ from x: W⁻¹ (R⁺ − R⁻)/2 P
  Eigen::SparseMatrix<double> Tj_;  ///< Σ from j: W⁻¹ (R⁺ − R⁻)/2 L
  Eigen::SparseMatrix<double> Tf_;  ///< Σ from f_split: −W⁻¹ (E⁺ − E⁻)/2 (row selection)
  std::vector<Index> jumpDofs_;     ///< entries d·k + c of j for the nodes that are not tips
  Eigen::SparseMatrix<double> borderB_;  ///< Pᵀ K_split L: free rows × jumpDofs_
  Eigen::SparseMatrix<double> borderC_;  ///< Lᵀ K_split L on jumpDofs_

  Eigen::VectorXd loadUnsplit_, sigmaLoad_, slip_;
  Eigen::VectorXd x_, lastJump_, lastRhs_, lastFree_;
  Eigen::VectorXd offsetSigmaN_, offsetTau_;
  int numAssemblies_ = 0;

  // 3D P2 recovery (factor()): R the recovered nodes (free: neither tip nor held), G the
  // consistent mass on R with the other nodes' columns extended from R, X: Σ_R to all nodes.
  bool consistent_ = false;
  std::vector<std::array<Index, 6>> faultTriangles_;  ///< control nodes of each P2 fault triangle
  std::vector<double> faultTriangleArea_;             ///< [m²], per faultTriangles_
  /// Per faultTriangles_ node: −1 at a joined node owned by a fracture oriented against the
  /// triangle's (its Σ is the opposite of the triangle's field), else +1.
  std::vector<std::array<double, 6>> faultTriangleSign_;
  /// 3D: fault surfaces meet (some node of several fractures): weights and the P2 mass from
  /// each fracture's triangles on its control nodes.
  bool meet_ = false;
  std::vector<std::vector<Index>> vertexControl_;  ///< 3D: per fracture node, its control node
  std::vector<std::vector<std::array<Index, 6>>> triangleNodes_;  ///< 3D: triangleNodes()
  std::vector<int> edgeCode_;                                     ///< 3D P2: edgeIntersectionCode
  /// The recovery of one Cartesian component of Σ (buildRecovery()): its rows R, extension X
  /// and G's factors. A node held by a roller has that component's row only where the roller
  /// does not hold it, so the components may differ; equal ones share one recovery.
  struct Recovery {
    std::vector<Index> recovered;                          ///< R: control node of each row of G
    Eigen::SparseMatrix<double> extend;                    ///< X: n × |R|
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu, lut;  ///< G and Gᵀ
  };
  std::vector<std::unique_ptr<Recovery>> recoveries_;  ///< the distinct ones
  std::array<int, 3> recoveryOf_{0, 0, 0};             ///< per Cartesian component
};

}  // namespace friction
