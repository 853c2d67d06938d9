// KrylovPreconditioner: a sparse stand-in for the interface operator S, for the GMRES of
// semismoothNewton's krylov variant (docs/method.md §4), on fractures too large for a dense S.
//
// S is probed (Chan & Mathew's probing of interface operators): the fracture nodes are coloured
// so that two nodes of one colour are at least `separation` hops apart on the node graph
// (SlipResponse::nodeGraph), one dual solve per colour and tangential component applies S to
// the colour's indicator, and of each response only the entries of node pairs within
// `distance` hops are kept. With separation ≥ 2·distance + 1, a node has at most one node of
// each colour within `distance` hops, so every kept entry is S's own plus the contributions
// of that colour's farther nodes: exact where S is zero beyond `distance` hops. Each Newton
// iteration the sparse Jacobian on the active components (ControlProblem::jacobianEntry's
// formula with the probed S) is factored by a sparse LU and applied as a right preconditioner.
// Its columns are ordered by nested dissection of the Jacobian's symmetric pattern (METIS, as
// CHOLMOD holds it; COLAMD where CHOLMOD cannot order): the fault is a surface, whose graph
// nested dissection orders with the least fill (measured in README "The fault operator's
// memory, counted": at 15 996 nodes 46.7 MB against COLAMD's 83.9 MB).
#pragma once

#include <vector>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "friction/control/ControlProblem.hpp"

namespace friction {

/// Colours for the nodes of `graph` (adjacency lists): two nodes of one colour are at least
/// `separation` ≥ 1 hops apart (nodes in different components of the graph: any distance).
/// Greedy, in node order: deterministic. Returns the colour of each node, 0 … numColours − 1.
std::vector<int> colourByDistance(const std::vector<std::vector<Eigen::Index>>& graph,
                                  int separation, int& numColours);

/// The nodes within `distance` hops of each node (itself first).
std::vector<std::vector<Eigen::Index>> nodesWithin(
    const std::vector<std::vector<Eigen::Index>>& graph, int distance);

/// The colouring's separation for a kept distance: 2·distance + 1, and 3 for the block
/// diagonal.
int probingSeparation(int distance);

/// S_tt (k·n × k·n) and S_nt (n × k·n) probed as the header says; columns of held components
/// are zero, as in InterfaceOperator.
struct ProbedInterfaceOperator {
  Eigen::SparseMatrix<double, Eigen::RowMajor> Stt, Snt;
  long solves = 0;  ///< dual solves spent (one per colour and tangential component)
  int colours = 0;
};

/// Probes resp's S on the graph (which must have one list per node) by dual solves.
ProbedInterfaceOperator probeInterfaceOperator(SlipResponse& resp,
                                               const std::vector<std::vector<Eigen::Index>>& graph,
                                               int distance, int separation);

/// S_tt's diagonal (k·n) at the nodes of one colour (the one with the most unknowns) of a
/// colouring with `separation` hops,
/// zero elsewhere (k dual solves, added to `solves`): where no S is formed, enough for the
/// mean interface stiffness of newtonGamma.
Eigen::VectorXd sampledDiagonal(SlipResponse& resp,
                                const std::vector<std::vector<Eigen::Index>>& graph, int separation,
                                long& solves);

/// The γ semismoothNewton iterates with, given S_tt's diagonal (k·n, the tangential
/// components; entries ≤ 0 are not known and left out): in 3D (k ≥ 2) the mean of the
/// diagonal over the unknown components where the case's γ is below 1e-2 × that mean or above
/// 10 × it, else the case's γ (see SemismoothNewton::minimize for why).
double newtonGamma(const ControlProblem& p, const Eigen::VectorXd& diagonalStt);

/// The column ordering of the preconditioner's SparseLU (Eigen's OrderingType): nested
/// dissection of the pattern of A + Aᵀ by CHOLMOD's METIS (metisOrdering), or COLAMD where
/// CHOLMOD cannot order. perm.indices()(old column) = new position, the convention SparseLU
/// applies.
struct NestedDissectionOrdering {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  void operator()(const Eigen::SparseMatrix<double>& A, PermutationType& perm) const;
};

/// The right preconditioner: the sparse Jacobian with the probed S on the active components.
class KrylovPreconditioner {
 public:
  explicit KrylovPreconditioner(ProbedInterfaceOperator op) : S_(std::move(op)) {}
  const ProbedInterfaceOperator& probed() const { return S_; }
  /// Factors G̃ = (I − P'_N) S̃_tt + γ P'_N + μ P'_ρ S̃_nt on the rows and columns `active`
  /// (components k·i + c) at s. False when the sparse LU fails (then apply() is the identity).
  bool factor(const ControlProblem& p, const ControlState& s,
              const std::vector<Eigen::Index>& active);
  /// G̃⁻¹ v (v on the active components).
  Eigen::VectorXd apply(const Eigen::VectorXd& v) const;
  /// Bytes held by the probed S (values and indices), counted from its arrays.
  double probedBytes() const;
  /// Bytes of the largest sparse LU factored so far (values and row indices of L and U).
  double largestFactorBytes() const { return largestFactorBytes_; }

 private:
  ProbedInterfaceOperator S_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, NestedDissectionOrdering> lu_;
  bool ok_ = false;
  double largestFactorBytes_ = 0;
};

}  // namespace friction
