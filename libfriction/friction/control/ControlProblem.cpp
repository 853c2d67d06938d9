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
                               double gamma, double zeta, GradientKind gradient)
    : response_(response),
      mu_(std::move(mu)),
      cohesion_(std::move(cohesion)),
      gamma_(gamma),
      zeta_(zeta),
      gradientKind_(gradient) {
  FRICTION_ASSERT(mu_.size() == response_.size(), "one μ per fracture node");
  FRICTION_ASSERT(cohesion_.size() == response_.size(), "one cohesion per fracture node");
  FRICTION_ASSERT(gamma_ > 0, "γ > 0");
  const Eigen::Index n = response_.size(), k = response_.blockSize();
  componentMask_.resize(k * n);
  componentWeights_.resize(k * n);
  const Eigen::VectorXd components = response_.componentMask();
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index c = 0; c < k; ++c) {
      componentMask_[k * i + c] = components[k * i + c];
      componentWeights_[k * i + c] = response_.weights()[i];
    }
}

double ControlProblem::relativeResidual(const ControlState& s) const {
  const double d = norm(s.D);
  if (d == 0) return 0;
  const Eigen::VectorXd &m = response_.freeMask(), &mk = componentMask_;
  const double scale = std::sqrt(dot(s.tau.cwiseProduct(mk), s.tau.cwiseProduct(mk)) +
                                 nodeDot(s.sigmaN.cwiseProduct(m), s.sigmaN.cwiseProduct(m)));
  return scale > 0 ? d / scale : d;
}

double ControlProblem::dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  return (a.array() * b.array() * componentWeights_.array()).sum();
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
  s.D.resize(k * n);
  s.node.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    s.node[i] =
        complementarity(s.tau.segment(k * i, k), s.beta.segment(k * i, k), s.rho[i], gamma_);
    s.D.segment(k * i, k) = s.node[i].D;
  }
  // Where the jump is held (tips, Dirichlet), the friction law is not asked of the node.
  s.D = s.D.cwiseProduct(componentMask_);
  s.J = 0.5 * dot(s.D, s.D) + 0.5 * zeta_ * dot(s.beta, s.beta);
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
      normal = mu_[i] * c.dPdRho[0] * D[0];
      for (Eigen::Index j = 1; j < k; ++j) normal += mu_[i] * c.dPdRho[j] * D[j];
    }
    qn[i] = normal;
  }
  Eigen::VectorXd tauDual;
  response_.adjoint(qt, qn, tauDual);
  ++numDual_;
  Eigen::VectorXd g = tauDual + local + zeta_ * s.beta;
  return g.cwiseProduct(componentMask_);
}

}  // namespace friction
