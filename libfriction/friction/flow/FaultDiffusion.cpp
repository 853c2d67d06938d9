// Fluid pressure diffusing along a fault: see FaultDiffusion.hpp.
#include "friction/flow/FaultDiffusion.hpp"

#include <algorithm>
#include <cmath>

#include "friction/core/Assert.hpp"
#include "friction/core/Suggest.hpp"

namespace friction {

namespace {

const std::vector<std::string>& schemeNames() {
  static const std::vector<std::string> names = {"backwardEuler", "crankNicolson"};
  return names;
}

// Δt rounded to 40 bits of mantissa (FaultDiffusion.hpp, "Factorisation").
double quantiseStep(double dt) {
  int e = 0;
  const double m = std::frexp(dt, &e);
  return std::ldexp(std::round(std::ldexp(m, 40)), e - 40);
}

std::string pointText(const Point& p) {
  return "(" + formatNumber(p.x()) + " " + formatNumber(p.y()) + " " + formatNumber(p.z()) + ")";
}

void checkDistance(double maxDistance, const SourceLocation& where) {
  if (!(maxDistance >= 0.0))
    throw InputError(where, "the largest distance of a well from the fault must be >= 0, got " +
                                formatNumber(maxDistance));
}

}  // namespace

const char* toString(TimeScheme scheme) {
  return scheme == TimeScheme::backwardEuler ? "backwardEuler" : "crankNicolson";
}

TimeScheme timeSchemeNamed(const std::string& name, const SourceLocation& where) {
  if (name == "backwardEuler") return TimeScheme::backwardEuler;
  if (name == "crankNicolson") return TimeScheme::crankNicolson;
  throw InputError(where, "unknown time scheme '" + name +
                              "'; valid names are: backwardEuler crankNicolson" +
                              suggestionText(name, schemeNames()));
}

FaultDiffusion::FaultDiffusion(FaultFlowMesh mesh, FlowCoefficient storage,
                               FlowCoefficient transmissivity, FaultDiffusionOptions options,
                               SourceLocation where)
    : mesh_(std::move(mesh)), options_(options) {
  storage.check(mesh_, false, "the storage S [m/Pa]", where);
  transmissivity.check(mesh_, true, "the transmissivity kappa [m^3/(Pa s)]", where);
  if (!(options_.maxStep > 0.0))
    throw InputError(
        where, "the longest flow substep must be > 0 s, got " + formatNumber(options_.maxStep));
  if (options_.dampingSteps < 0)
    throw InputError(where, "the number of damping steps must be >= 0, got " +
                                std::to_string(options_.dampingSteps));
  if (options_.lumpedMass) {
    const Eigen::VectorXd m = mesh_.lumpedMass(storage);
    storageMass_.resize(mesh_.numNodes(), mesh_.numNodes());
    std::vector<Eigen::Triplet<double>> t;
    for (Index i = 0; i < mesh_.numNodes(); ++i) t.emplace_back(i, i, m[i]);
    storageMass_.setFromTriplets(t.begin(), t.end());
  } else {
    storageMass_ = mesh_.consistentMass(storage);
  }
  stiffness_ = mesh_.stiffness(transmissivity);
  heldBy_.assign(static_cast<std::size_t>(mesh_.numNodes()), -1);
  p_ = Eigen::VectorXd::Zero(mesh_.numNodes());
}

int FaultDiffusion::addRateWell(const Point& x, StepSchedule rate, double maxDistance,
                                SourceLocation where) {
  checkDistance(maxDistance, where);
  const FaultFlowMesh::Location at = mesh_.locate(x);
  if (!(at.distance <= maxDistance))
    throw InputError(where, "the well at " + pointText(x) + " is " + formatNumber(at.distance) +
                                " m from the nearest point of the fault " + pointText(at.closest) +
                                "; at most " + formatNumber(maxDistance) + " m is accepted");
  Well well;
  for (int k = 0; k < mesh_.nodesPerElement(); ++k) {
    const double w = at.weight[static_cast<std::size_t>(k)];
    if (w != 0.0)
      well.weights.emplace_back(mesh_.element(at.element)[static_cast<std::size_t>(k)], w);
  }
  well.rate = std::move(rate);
  wells_.push_back(std::move(well));
  return static_cast<int>(wells_.size()) - 1;
}

void FaultDiffusion::addHeldPressure(const Point& x, StepSchedule deltaP, double maxDistance,
                                     SourceLocation where) {
  checkDistance(maxDistance, where);
  double distance = 0.0;
  const Index node = mesh_.nearestNode(x, &distance);
  if (!(distance <= maxDistance))
    throw InputError(where, "the held pressure at " + pointText(x) + " is " +
                                formatNumber(distance) + " m from the nearest fault node " +
                                pointText(mesh_.point(node)) + "; at most " +
                                formatNumber(maxDistance) + " m is accepted");
  hold({node}, std::move(deltaP), where);
}

void FaultDiffusion::holdNodes(const std::vector<Index>& nodes, StepSchedule deltaP,
                               SourceLocation where) {
  hold(nodes, std::move(deltaP), where);
}

void FaultDiffusion::hold(const std::vector<Index>& nodes, StepSchedule deltaP,
                          const SourceLocation& where) {
  for (Index n : nodes) {
    if (n < 0 || n >= mesh_.numNodes())
      throw InputError(where, "fault node " + std::to_string(n) + " out of range [0, " +
                                  std::to_string(mesh_.numNodes()) + ")");
    if (heldBy_[static_cast<std::size_t>(n)] >= 0)
      throw InputError(where, "fault node " + std::to_string(n) + " at " +
                                  pointText(mesh_.point(n)) +
                                  " is held already (two held pressures on one node)");
  }
  const int group = static_cast<int>(held_.size());
  for (Index n : nodes) heldBy_[static_cast<std::size_t>(n)] = group;
  held_.push_back({nodes, std::move(deltaP)});
  factors_.clear();  // the held nodes are part of the factored matrix
}

void FaultDiffusion::setState(const Eigen::VectorXd& p, SourceLocation where) {
  if (p.size() != mesh_.numNodes())
    throw InputError(where, "fault pressure: expected " + std::to_string(mesh_.numNodes()) +
                                " nodal values, got " + std::to_string(p.size()));
  p_ = p;
}

double FaultDiffusion::storedVolume() const { return (storageMass_ * p_).sum(); }

double FaultDiffusion::injectedVolume(double t0, double t1) const {
  double v = 0.0;
  for (const Well& w : wells_) v += w.rate.integral(t0, t1);
  return v;
}

const FaultDiffusion::Factor& FaultDiffusion::factor(double dt, double theta) {
  for (const Factor& f : factors_)
    if (f.dt == dt && f.theta == theta) return f;
  Eigen::SparseMatrix<double> K = storageMass_ + (theta * dt) * stiffness_;
  // Held nodes: their rows and columns become those of the identity (the known values are
  // moved to the right-hand side), which keeps K symmetric positive definite. Every node has
  // a diagonal entry (its mass is positive).
  if (!held_.empty())
    for (int k = 0; k < K.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it)
        if (heldBy_[static_cast<std::size_t>(it.row())] >= 0 ||
            heldBy_[static_cast<std::size_t>(it.col())] >= 0)
          it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
  Factor f;
  f.dt = dt;
  f.theta = theta;
  f.ldlt = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(K);
  // S > 0 makes K positive definite; failure would be an internal error.
  FRICTION_ASSERT(f.ldlt->info() == Eigen::Success, "fault flow matrix not factored");
  ++numFactorisations_;
  // A few entries: backward Euler and Crank–Nicolson for one Δt, and a last step of another.
  if (factors_.size() >= 4) factors_.erase(factors_.begin());
  factors_.push_back(std::move(f));
  return factors_.back();
}

bool FaultDiffusion::damped(double t0, double t1, double dt) const {
  if (options_.dampingSteps == 0) return false;
  // The substep holding a change and the dampingSteps − 1 after it (half a step of margin
  // against round-off in the substep times).
  const double from = t0 - (options_.dampingSteps - 0.5) * dt;
  for (const Held& h : held_)
    if (h.value.changesIn(from, t1)) return true;
  return false;
}

void FaultDiffusion::substep(double t0, double t1, double dt) {
  const bool crank = options_.scheme == TimeScheme::crankNicolson && !damped(t0, t1, dt);
  const double theta = crank ? 0.5 : 1.0;
  const Factor& f = factor(dt, theta);
  Eigen::VectorXd rhs = storageMass_ * p_;
  if (crank) rhs -= (0.5 * dt) * (stiffness_ * p_);
  for (const Well& w : wells_) {
    const double v = w.rate.integral(t0, t1);
    if (v != 0.0)
      for (const auto& [node, weight] : w.weights) rhs[node] += weight * v;
  }
  if (!held_.empty()) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(p_.size());
    for (const Held& h : held_) {
      const double value = h.value.valueBefore(t1);
      for (Index n : h.nodes) g[n] = value;
    }
    rhs -= storageMass_ * g + (theta * dt) * (stiffness_ * g);
    for (const Held& h : held_)
      for (Index n : h.nodes) rhs[n] = g[n];
  }
  p_ = f.ldlt->solve(rhs);
  ++numSubsteps_;
}

void FaultDiffusion::advance(double tFrom, double tTo) {
  FRICTION_ASSERT(tTo >= tFrom, "FaultDiffusion::advance backwards in time");
  if (!(tTo > tFrom)) return;
  const double span = tTo - tFrom;
  // Equal substeps; the margin keeps a span that is a multiple of maxStep from taking one
  // more substep for round-off.
  const double ratio = span / options_.maxStep;
  const long n = std::max(1L, static_cast<long>(std::ceil(ratio * (1.0 - 1e-12))));
  const double dt = quantiseStep(span / static_cast<double>(n));
  for (long i = 0; i < n; ++i) {
    const double t0 = tFrom + span * static_cast<double>(i) / static_cast<double>(n);
    const double t1 =
        i + 1 == n ? tTo : tFrom + span * static_cast<double>(i + 1) / static_cast<double>(n);
    substep(t0, t1, dt);
  }
}

}  // namespace friction
