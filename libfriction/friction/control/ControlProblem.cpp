// Objective and exact gradient of the control problem (docs/method.md §4). Derivation, node by
// node with the k × k block P'_N = ∂P/∂N and the k-vector P'_ρ = ∂P/∂ρ:
//   dD/dβ = (I − P'_N) S_tt + γ P'_N + μ P'_ρ S_nt,   since N = τ − γβ and dρ = −μ dσ_n.
// With P'_N symmetric, the M-gradient of ½ DᵀMD is the adjoint (SlipResponse::adjoint) applied
// to (I − P'_N) D and μ P'_ρ·D, plus the local term γ P'_N D. Where M S is self-adjoint (S is
// the Steklov–Poincaré map of the dual problem) that is the tangential traction of one dual
// solve with jump q = Σ_c ((I − P'_N) D)_c t_c + μ (P'_ρ·D) n_Γ.
// The sums below keep the order of the scalar (k = 1) expressions, so that 2D is unchanged
// to the bit.
#include "friction/control/ControlProblem.hpp"

#include <cmath>

#include "friction/core/Assert.hpp"
#include "friction/core/StopRequest.hpp"

namespace friction {

ControlProblem::ControlProblem(SlipResponse& response, Eigen::VectorXd mu, Eigen::VectorXd cohesion,
                               double gamma, double zeta, GradientKind gradient,
                               const OpeningSettings* opening, const WeakeningSettings* weakening)
    : response_(response),
      mu_(std::move(mu)),
      cohesion_(std::move(cohesion)),
      gamma_(gamma),
      zeta_(zeta),
      gradientKind_(gradient),
      opening_(opening != nullptr),
      weakening_(weakening) {
  FRICTION_ASSERT(mu_.size() == response_.size(), "one μ per fracture node");
  FRICTION_ASSERT(cohesion_.size() == response_.size(), "one cohesion per fracture node");
  FRICTION_ASSERT(gamma_ > 0, "γ > 0");
  const Eigen::Index n = response_.size(), k = response_.blockSize();
  const Eigen::Index total = opening_ ? k * n + n : k * n;
  FRICTION_ASSERT(!(opening_ && weakening_), "slip-weakening is refused with openings");
  FRICTION_ASSERT(
      !weakening_ || (static_cast<Eigen::Index>(weakening_->nodes.size()) == n &&
                      weakening_->pathStart.size() == n && weakening_->cohesion.size() == n &&
                      weakening_->pressure.size() == n),
      "one weakening, path, cohesion and pressure per fracture node");
  componentMask_.resize(total);
  componentWeights_.resize(total);
  const Eigen::VectorXd components = response_.componentMask();
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index c = 0; c < k; ++c) {
      componentMask_[k * i + c] = components[k * i + c];
      componentWeights_[k * i + c] = response_.weights()[i];
    }
  if (opening_) {
    openingSettings_ = *opening;
    FRICTION_ASSERT(
        openingSettings_.unilateral.size() == n && openingSettings_.pressure.size() == n,
        "one opening flag and pressure per fracture node");
    FRICTION_ASSERT(openingSettings_.gammaN > 0, "γ_n > 0");
    for (Eigen::Index i = 0; i < n; ++i) {
      componentMask_[k * n + i] = openingSettings_.unilateral[i] * response_.freeMask()[i];
      componentWeights_[k * n + i] = response_.weights()[i];
    }
  }
}

double ControlProblem::relativeResidual(const ControlState& s) const {
  const double d = norm(s.D);
  if (d == 0) return 0;
  const Eigen::VectorXd& m = response_.freeMask();
  // τ has the k·n tangential entries alone, with or without openings.
  const Eigen::Index kn = blockSize() * numNodes();
  const Eigen::VectorXd tauFree = s.tau.cwiseProduct(componentMask_.head(kn));
  const double tangential =
      opening_ ? (tauFree.array() * tauFree.array() * componentWeights_.head(kn).array()).sum()
               : dot(tauFree, tauFree);
  const double scale =
      std::sqrt(tangential + nodeDot(s.sigmaN.cwiseProduct(m), s.sigmaN.cwiseProduct(m)));
  return scale > 0 ? d / scale : d;
}

double ControlProblem::dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  if (!opening_) return (a.array() * b.array() * componentWeights_.array()).sum();
  // The tangential part summed as without openings, then the openings': where every node is
  // in contact with g = 0, the sums (and so the stop rule) are those of the bilateral case.
  const Eigen::Index kn = blockSize() * numNodes(), n = numNodes();
  const double tangential =
      (a.head(kn).array() * b.head(kn).array() * componentWeights_.head(kn).array()).sum();
  return tangential +
         (a.tail(n).array() * b.tail(n).array() * componentWeights_.tail(n).array()).sum();
}

double ControlProblem::nodeDot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  return (a.array() * b.array() * response_.weights().array()).sum();
}

ControlState ControlProblem::evaluate(const Eigen::VectorXd& beta) {
  throwIfStopNow();  // a second SIGINT/SIGTERM abandons the step between two solves
  const Eigen::VectorXd b = beta.cwiseProduct(componentMask_);
  Eigen::VectorXd tau, sigmaN;
  response_.primal(b, tau, sigmaN);
  ++numPrimal_;
  ControlState s = stateFrom(b, std::move(tau), std::move(sigmaN));
  s.primalSolves = numPrimal_;
  return s;
}

ControlState ControlProblem::stateFrom(const Eigen::VectorXd& beta, Eigen::VectorXd tau,
                                       Eigen::VectorXd sigmaN) const {
  ControlState s;
  s.beta = beta.cwiseProduct(componentMask_);
  s.tau = std::move(tau);
  s.sigmaN = std::move(sigmaN);
  const Eigen::Index n = numNodes(), k = blockSize();
  s.rho = cohesion_ - mu_.cwiseProduct(s.sigmaN);
  s.D.resize(size());
  s.node.resize(n);
  if (opening_) {
    // The normal complementarity D_n = max(σ'_n, −γ_n g) (docs/method.md §4, "Fractures that
    // open"): in contact (σ'_n + γ_n g < 0) D_n = −γ_n g and the friction bound comes from the
    // augmented normal stress, ρ = c − μ(σ'_n + γ_n g); open, D_n = σ'_n and ρ = 0, so that τ = 0
    // is sought. cohesion_ holds c − μ p already. A fracture that may not open is always in
    // contact.
    s.contact.assign(n, 1);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (componentMask_[k * n + i] == 0) {
        s.D[k * n + i] = 0;
        continue;
      }
      const double g = s.beta[k * n + i];
      const double effective = s.sigmaN[i] + openingSettings_.pressure[i];
      const double augmented = effective + openingSettings_.gammaN * g;
      if (augmented < 0) {
        s.rho[i] = cohesion_[i] - mu_[i] * (s.sigmaN[i] + openingSettings_.gammaN * g);
        s.D[k * n + i] = -openingSettings_.gammaN * g;
      } else {
        s.contact[i] = 0;
        s.rho[i] = 0;
        s.D[k * n + i] = effective;
      }
    }
  }
  if (weakening_) {
    // ρ = c − μ(δ_n + |β|)(σ_n + p) where the friction weakens (docs/method.md §3).
    const WeakeningSettings& w = *weakening_;
    s.mu = mu_;
    s.dRhoDPath = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const WeakeningNode& node = w.nodes[static_cast<std::size_t>(i)];
      if (node.form == Weakening::none) continue;
      const double path = w.pathStart[i] + blockNorm(s.beta.segment(k * i, k));
      const double effective = s.sigmaN[i] + w.pressure[i];
      s.mu[i] = node.mu(path);
      s.rho[i] = w.cohesion[i] - s.mu[i] * effective;
      s.dRhoDPath[i] = -node.slope(path) * effective;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    s.node[i] =
        complementarity(s.tau.segment(k * i, k), s.beta.segment(k * i, k), s.rho[i], gamma_);
    s.D.segment(k * i, k) = s.node[i].D;
  }
  // Where the jump is held (tips, Dirichlet), the friction law is not asked of the node.
  s.D = s.D.cwiseProduct(componentMask_);
  if (!opening_) {
    s.J = 0.5 * dot(s.D, s.D) + 0.5 * zeta_ * dot(s.beta, s.beta);
    return s;
  }
  // ζ regularises the slip increment only: the opening is a state, not an increment.
  Eigen::VectorXd slip = s.beta;
  slip.tail(n).setZero();
  s.J = 0.5 * dot(s.D, s.D) + 0.5 * zeta_ * dot(slip, slip);
  return s;
}

Eigen::VectorXd ControlProblem::gradient(const ControlState& s) {
  throwIfStopNow();
  const Eigen::Index n = numNodes(), k = blockSize();
  Eigen::VectorXd qt(k * n), qn(n), local(k * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const NodeComplementarity& c = s.node[i];
    const double* D = s.D.data() + k * i;
    for (Eigen::Index r = 0; r < k; ++r) {
      // Row r of (I − P'_N) D and of γ P'_N D.
      double q = ((r == 0 ? 1.0 : 0.0) - c.dPdN(r, 0)) * D[0];
      double l = gamma_ * c.dPdN(r, 0) * D[0];
      for (Eigen::Index j = 1; j < k; ++j) {
        q += ((r == j ? 1.0 : 0.0) - c.dPdN(r, j)) * D[j];
        l += gamma_ * c.dPdN(r, j) * D[j];
      }
      qt[k * i + r] = q;
      local[k * i + r] = l;
    }
    double normal = 0.0;
    if (gradientKind_ == GradientKind::exact) {
      const double mu = muAt(s, i);
      normal = mu * c.dPdRho[0] * D[0];
      for (Eigen::Index j = 1; j < k; ++j) normal += mu * c.dPdRho[j] * D[j];
    }
    qn[i] = normal;
    // Weakening: the node's block gains −(∂ρ/∂|β|) β̂ P'_ρᵀ, whose transpose acts on D here.
    if (s.dRhoDPath.size() && s.dRhoDPath[i] != 0) {
      double pd = c.dPdRho[0] * D[0];
      for (Eigen::Index j = 1; j < k; ++j) pd += c.dPdRho[j] * D[j];
      const Block unit = slipDirection(s, i);
      for (Eigen::Index r = 0; r < k; ++r) local[k * i + r] -= pd * s.dRhoDPath[i] * unit[r];
    }
  }
  Eigen::VectorXd tauDual;
  if (!opening_) {
    response_.adjoint(qt, qn, tauDual);
    ++numDual_;
    Eigen::VectorXd g = tauDual + local + zeta_ * s.beta;
    return g.cwiseProduct(componentMask_);
  }
  // The openings' part: a normal row reads −γ_n g in contact (local) and σ'_n where open
  // (through σ_n: the adjoint's input qn); the friction bound ρ = c − μ(σ'_n + γ_n g) adds
  // μ γ_n P'_ρ·D locally in contact (with the exact gradient, as its σ_n part). A unit opening
  // is the jump −n_Γ: its adjoint is minus the adjoint's normal part.
  Eigen::VectorXd localN = Eigen::VectorXd::Zero(n);
  const double gammaN = openingSettings_.gammaN;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (componentMask_[k * n + i] == 0) continue;
    const double Dn = s.D[k * n + i];
    if (s.contact[i]) {
      localN[i] = -gammaN * Dn;
      if (gradientKind_ == GradientKind::exact) localN[i] += gammaN * qn[i];
    } else {
      qn[i] += Dn;
    }
  }
  Eigen::VectorXd normalAdjoint;
  response_.adjoint(qt, qn, tauDual, &normalAdjoint);
  ++numDual_;
  Eigen::VectorXd g(size());
  g.head(k * n) = tauDual + local + zeta_ * s.beta.head(k * n);
  g.tail(n) = -normalAdjoint + localN;
  return g.cwiseProduct(componentMask_);
}

Block ControlProblem::slipDirection(const ControlState& s, Eigen::Index i) const {
  const Eigen::Index k = blockSize();
  const Block b = s.beta.segment(k * i, k);
  const double norm = blockNorm(b);
  if (norm > 0) return b / norm;
  return -s.node[static_cast<std::size_t>(i)].dPdRho;  // N̂ in the slip state, 0 otherwise
}

double ControlProblem::jacobianEntryWithOpening(const ControlState& s, const InterfaceOperator& S,
                                                Eigen::Index row, Eigen::Index col) const {
  const Eigen::Index n = numNodes(), k = blockSize(), kn = k * n;
  if (row >= kn) {  // the normal row of node i
    const Eigen::Index i = row - kn;
    if (s.contact[i]) return col == row ? -openingSettings_.gammaN : 0.0;
    return col < kn ? S.Snt(i, col) : S.Snn(i, col - kn);
  }
  if (col < kn) return jacobianEntry(s, S.Stt, S.Snt, row, col);
  const Eigen::Index i = row / k, r = row % k, j = col - kn;
  const NodeComplementarity& c = s.node[i];
  double g = ((r == 0 ? 1.0 : 0.0) - c.dPdN(r, 0)) * S.Stn(k * i, j);
  for (Eigen::Index q = 1; q < k; ++q)
    g += ((r == q ? 1.0 : 0.0) - c.dPdN(r, q)) * S.Stn(k * i + q, j);
  g += mu_[i] * c.dPdRho[r] * S.Snn(i, j);
  if (i == j && s.contact[i]) g += mu_[i] * c.dPdRho[r] * openingSettings_.gammaN;
  return g;
}

}  // namespace friction
