// DirichletConditions and ReducedSystem: elimination of prescribed displacements with the
// reduced matrix built once (docs/method.md §4). See the header for the design.
#include "friction/fe/DirichletConditions.hpp"

#include "friction/core/Assert.hpp"
#include "friction/core/Parallel.hpp"

namespace friction {

DirichletConditions::DirichletConditions(const LagrangeSpace& space)
    : space_(&space),
      fixed_(static_cast<std::size_t>(space.numDofs()), 0),
      values_(Eigen::VectorXd::Zero(space.numDofs())) {
  renumber();
}

Index DirichletConditions::fixPatch(int label, FixedComponents components) {
  const std::vector<Index> nodes = space_->patchNodes(label);
  for (Index n : nodes)
    for (int c = 0; c < space_->dim(); ++c)
      if (fixesComponent(components, c)) fixed_[space_->dof(n, c)] = 1;
  // A label fixed twice with different components fixes their union.
  auto it = patchComponents_.find(label);
  if (it == patchComponents_.end())
    patchComponents_.emplace(label, components);
  else
    it->second = it->second | components;
  renumber();
  return static_cast<Index>(nodes.size());
}

void DirichletConditions::fixDof(Index dof) {
  fixed_[static_cast<std::size_t>(dof)] = 1;
  renumber();
}

void DirichletConditions::renumber() {
  freeDofs_.clear();
  fixedDofs_.clear();
  reducedIndex_.assign(fixed_.size(), -1);
  for (Index d = 0; d < numDofs(); ++d) {
    if (fixed_[d]) {
      fixedDofs_.push_back(d);
    } else {
      reducedIndex_[d] = static_cast<Index>(freeDofs_.size());
      freeDofs_.push_back(d);
    }
  }
}

void DirichletConditions::setPatchValue(int label, const Point& value) {
  setPatchValue(label, VectorField([value](const Point&) { return value; }));
}

void DirichletConditions::setPatchValue(int label, const Vector2& value) {
  setPatchValue(label, Point(value.x(), value.y(), 0.0));
}

void DirichletConditions::setPatchValue(int label, const VectorField& value) {
  const auto it = patchComponents_.find(label);
  FRICTION_ASSERT(it != patchComponents_.end(), "setPatchValue on a patch that is not fixed");
  if (it == patchComponents_.end()) return;
  for (Index n : space_->patchNodes(label)) {
    const Point v = value(space_->point(n));
    for (int c = 0; c < space_->dim(); ++c)
      if (fixesComponent(it->second, c)) values_[space_->dof(n, c)] = v[c];
  }
}

Eigen::VectorXd DirichletConditions::fixedValues() const {
  Eigen::VectorXd v(numFixed());
  for (Index k = 0; k < numFixed(); ++k) v[k] = values_[fixedDofs_[k]];
  return v;
}

ReducedSystem::ReducedSystem(const Eigen::SparseMatrix<double>& K,
                             const DirichletConditions& conditions)
    : freeDofs_(conditions.freeDofs()), fixedDofs_(conditions.fixedDofs()) {
  FRICTION_ASSERT(K.rows() == conditions.numDofs() && K.cols() == conditions.numDofs(),
                  "K does not match the conditions' space");
  FRICTION_ASSERT(K.isCompressed(), "K must be compressed");
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  const double* value = K.valuePtr();

  // Both blocks are written directly in compressed form: count, then fill. The map from full
  // to reduced row is increasing, so rows stay sorted.
  auto extract = [&](const std::vector<Index>& columns, Eigen::SparseMatrix<double>& out) {
    out.resize(static_cast<Eigen::Index>(freeDofs_.size()),
               static_cast<Eigen::Index>(columns.size()));
    Eigen::Index nnz = 0;
    for (Index col : columns)
      for (int p = outer[col]; p < outer[col + 1]; ++p)
        if (!conditions.isFixed(inner[p])) ++nnz;
    out.resizeNonZeros(nnz);
    int* oOuter = out.outerIndexPtr();
    int* oInner = out.innerIndexPtr();
    double* oValue = out.valuePtr();
    int pos = 0;
    for (std::size_t j = 0; j < columns.size(); ++j) {
      oOuter[j] = pos;
      const Index col = columns[j];
      for (int p = outer[col]; p < outer[col + 1]; ++p) {
        const Index row = conditions.reducedIndex(inner[p]);
        if (row < 0) continue;
        oInner[pos] = row;
        oValue[pos] = value[p];
        ++pos;
      }
    }
    oOuter[columns.size()] = pos;
  };
  extract(freeDofs_, Kff_);
  extract(fixedDofs_, Kfd_);
}

Eigen::VectorXd ReducedSystem::restrictToFree(const Eigen::VectorXd& full) const {
  Eigen::VectorXd r(numFree());
  for (Index k = 0; k < numFree(); ++k) r[k] = full[freeDofs_[k]];
  return r;
}

Eigen::VectorXd ReducedSystem::rhs(const Eigen::VectorXd& F,
                                   const DirichletConditions& conditions) const {
  FRICTION_ASSERT(conditions.fixedDofs() == fixedDofs_, "conditions changed their fixed dofs");
  return rhs(F, conditions.fixedValues());
}

Eigen::VectorXd ReducedSystem::rhs(const Eigen::VectorXd& F,
                                   const Eigen::VectorXd& fixedValues) const {
  FRICTION_ASSERT(fixedValues.size() == Kfd_.cols(), "one value per fixed dof");
  Eigen::VectorXd r = restrictToFree(F);
  if (summed_) {
    // Each rank holds its cells' part of K_fd: their products add up.
    Eigen::VectorXd lift = Kfd_ * fixedValues;
    parallel::sumOverRanks(lift.data(), lift.size());
    r -= lift;
  } else {
    r.noalias() -= Kfd_ * fixedValues;
  }
  return r;
}

Eigen::VectorXd ReducedSystem::apply(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Kff_ * x;
  if (summed_) parallel::sumOverRanks(y.data(), y.size());
  return y;
}

Eigen::VectorXd ReducedSystem::expand(const Eigen::VectorXd& uFree,
                                      const DirichletConditions& conditions) const {
  FRICTION_ASSERT(conditions.fixedDofs() == fixedDofs_, "conditions changed their fixed dofs");
  return expand(uFree, conditions.fixedValues());
}

Eigen::VectorXd ReducedSystem::expand(const Eigen::VectorXd& uFree,
                                      const Eigen::VectorXd& fixedValues) const {
  FRICTION_ASSERT(uFree.size() == numFree(), "one value per free dof");
  Eigen::VectorXd u(static_cast<Eigen::Index>(freeDofs_.size() + fixedDofs_.size()));
  for (Index k = 0; k < numFree(); ++k) u[freeDofs_[k]] = uFree[k];
  for (std::size_t k = 0; k < fixedDofs_.size(); ++k) u[fixedDofs_[k]] = fixedValues[k];
  return u;
}

}  // namespace friction
