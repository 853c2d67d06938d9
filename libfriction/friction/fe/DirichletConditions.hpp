// DirichletConditions and ReducedSystem: prescribed displacements by elimination
// (docs/method.md §4, "factor once").
//
// The set of fixed dofs decides the reduced matrix K_ff; the prescribed values u_d only enter
// the right-hand side f_f − K_fd u_d. So the two are kept apart: fix dofs once, build one
// ReducedSystem (K_ff to factor once, K_fd kept for later), and afterwards change values
// and loads as often as needed — each new right-hand side is one sparse product with K_fd.
// K_ff is a principal submatrix of K, hence symmetric, and positive definite as soon as the
// fixed dofs remove the rigid-body modes.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <map>
#include <vector>

#include "friction/core/Types.hpp"
#include "friction/fe/ElasticityAssembler.hpp"
#include "friction/fe/LagrangeSpace.hpp"

namespace friction {

/// Which displacement components a condition prescribes: a set of x, y, z (combine with |);
/// `all` is every component of the mesh's dimension.
enum class FixedComponents : unsigned { x = 1, y = 2, z = 4, all = 7 };

inline FixedComponents operator|(FixedComponents a, FixedComponents b) {
  return static_cast<FixedComponents>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
/// Whether the set fixes component c (0 = x, 1 = y, 2 = z).
inline bool fixesComponent(FixedComponents set, int c) {
  return (static_cast<unsigned>(set) >> c) & 1u;
}

class DirichletConditions {
 public:
  /// No dof fixed, every value 0. Keeps a reference to the space (must outlive this).
  explicit DirichletConditions(const LagrangeSpace& space);

  // --- which dofs are fixed (decides K_ff; do this before building a ReducedSystem) ---

  /// Fix the given components of every node on the facets with this label (vertices and, for
  /// P2, midpoints); components beyond the mesh's dimension are ignored. Returns the number
  /// of nodes on the patch: 0 means the label has no facets, which the caller (who knows the
  /// file and line) reports.
  Index fixPatch(int label, FixedComponents components);
  /// Fix one dof.
  void fixDof(Index dof);

  bool isFixed(Index dof) const { return fixed_[static_cast<std::size_t>(dof)] != 0; }
  Index numDofs() const { return static_cast<Index>(fixed_.size()); }
  Index numFixed() const { return static_cast<Index>(fixedDofs_.size()); }
  Index numFree() const { return static_cast<Index>(freeDofs_.size()); }
  /// Free dofs in increasing order: reduced index → full dof.
  const std::vector<Index>& freeDofs() const { return freeDofs_; }
  /// Fixed dofs in increasing order.
  const std::vector<Index>& fixedDofs() const { return fixedDofs_; }
  /// Full dof → reduced index, −1 for a fixed dof.
  Index reducedIndex(Index dof) const { return reducedIndex_[static_cast<std::size_t>(dof)]; }

  // --- prescribed values [m] (may change every time step; K_ff does not) ---

  /// Set the prescribed value of every node on the patch, for the components this patch
  /// fixes (fixPatch); the other components are left alone. A node on two patches that fix
  /// the same component keeps the value set last. The patch must have been fixed (debug
  /// assert). Any dimension (z ignored in 2D), and the same for 2D code.
  void setPatchValue(int label, const Point& value);
  void setPatchValue(int label, const Vector2& value);
  /// Same with a value depending on the node position.
  void setPatchValue(int label, const VectorField& value);
  /// Value of one dof (meaningful only if the dof is fixed).
  void setValue(Index dof, double value) { values_[dof] = value; }
  /// Full-length vector whose entries at fixed dofs are the prescribed values (others 0).
  const Eigen::VectorXd& values() const { return values_; }
  /// The prescribed values in fixedDofs() order.
  Eigen::VectorXd fixedValues() const;

 private:
  void renumber();

  const LagrangeSpace* space_;
  std::map<int, FixedComponents> patchComponents_;
  std::vector<char> fixed_;
  std::vector<Index> freeDofs_;
  std::vector<Index> fixedDofs_;
  std::vector<Index> reducedIndex_;
  Eigen::VectorXd values_;
};

/// K split by DirichletConditions into K_ff (to factor) and K_fd (for right-hand sides).
/// It copies the dof maps, so the conditions may change their values afterwards — but fixing
/// more dofs needs a new ReducedSystem (and a new factorisation).
class ReducedSystem {
 public:
  ReducedSystem(const Eigen::SparseMatrix<double>& K, const DirichletConditions& conditions);

  /// K here is this rank's summand of the stiffness (its own cells; the distributed engine):
  /// rhs() and apply() then sum the ranks' parts (collective calls: every rank makes them).
  void setSummedOverRanks(bool summed) { summed_ = summed; }
  bool summedOverRanks() const { return summed_; }
  /// K_ff x, summed over the ranks when K is a summand.
  Eigen::VectorXd apply(const Eigen::VectorXd& x) const;

  /// K_ff: numFree × numFree, symmetric, full storage. Factor this once.
  const Eigen::SparseMatrix<double>& matrix() const { return Kff_; }
  /// K_fd: numFree × numFixed, the coupling to the prescribed values.
  const Eigen::SparseMatrix<double>& coupling() const { return Kfd_; }
  Index numFree() const { return static_cast<Index>(freeDofs_.size()); }

  /// f_f − K_fd u_d, with F the full load vector [N] and the conditions' current values.
  Eigen::VectorXd rhs(const Eigen::VectorXd& F, const DirichletConditions& conditions) const;
  /// f_f − K_fd u_d with explicit prescribed values in fixedDofs() order.
  Eigen::VectorXd rhs(const Eigen::VectorXd& F, const Eigen::VectorXd& fixedValues) const;
  /// The free entries of a full vector.
  Eigen::VectorXd restrictToFree(const Eigen::VectorXd& full) const;
  /// Full displacement: the free part from uFree, the fixed part from the conditions' values.
  Eigen::VectorXd expand(const Eigen::VectorXd& uFree, const DirichletConditions& conditions) const;
  /// Full displacement with explicit prescribed values in fixedDofs() order.
  Eigen::VectorXd expand(const Eigen::VectorXd& uFree, const Eigen::VectorXd& fixedValues) const;

 private:
  std::vector<Index> freeDofs_;
  std::vector<Index> fixedDofs_;
  Eigen::SparseMatrix<double> Kff_;
  Eigen::SparseMatrix<double> Kfd_;
  bool summed_ = false;
};

}  // namespace friction
