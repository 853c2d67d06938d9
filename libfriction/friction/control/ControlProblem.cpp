// Objective and exact gradient of the control problem (docs/method.md §4). Derivation, node by
// node with P'_N = ∂P/∂N and P'_ρ = ∂P/∂ρ:
//   dD/dβ = (1 − P'_N) S_tt + γ P'_N + μ P'_ρ S_nt,   since N = τ − γβ and dρ = −μ dσ_n.
// With M S self-adjoint (S is the Steklov–Poincaré map of the dual problem), the M-gradient
// of ½ DᵀMD is the tangential traction of one dual solve with jump
//   q = (1 − P'_N) D t_Γ + μ P'_ρ D n_Γ,  plus the local term γ P'_N D.
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
}

double ControlProblem::relativeResidual(const ControlState& s) const {
  const double d = norm(s.D);
  if (d == 0) return 0;
  const Eigen::VectorXd& m = response_.freeMask();
  const double scale = std::sqrt(dot(s.tau.cwiseProduct(m), s.tau.cwiseProduct(m)) +
                                 dot(s.sigmaN.cwiseProduct(m), s.sigmaN.cwiseProduct(m)));
  return scale > 0 ? d / scale : d;
}

double ControlProblem::dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  return (a.array() * b.array() * response_.weights().array()).sum();
}

ControlState ControlProblem::evaluate(const Eigen::VectorXd& beta) {
  throwIfStopNow();  // a second SIGINT/SIGTERM abandons the step between two solves
  const Eigen::VectorXd b = beta.cwiseProduct(response_.freeMask());
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
  s.beta = beta.cwiseProduct(response_.freeMask());
  s.tau = std::move(tau);
  s.sigmaN = std::move(sigmaN);
  const Eigen::Index n = size();
  s.rho = cohesion_ - mu_.cwiseProduct(s.sigmaN);
  s.D.resize(n);
  s.node.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    s.node[i] = complementarity(s.tau[i], s.beta[i], s.rho[i], gamma_);
    s.D[i] = s.node[i].D;
  }
  // Where the jump is held (tips, Dirichlet), the friction law is not asked of the node.
  s.D = s.D.cwiseProduct(response_.freeMask());
  s.J = 0.5 * dot(s.D, s.D) + 0.5 * zeta_ * dot(s.beta, s.beta);
  return s;
}

Eigen::VectorXd ControlProblem::gradient(const ControlState& s) {
  throwIfStopNow();
  const Eigen::Index n = size();
  Eigen::VectorXd qt(n), qn(n), local(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const NodeComplementarity& c = s.node[i];
    qt[i] = (1 - c.dPdN) * s.D[i];
    qn[i] = gradientKind_ == GradientKind::exact ? mu_[i] * c.dPdRho * s.D[i] : 0.0;
    local[i] = gamma_ * c.dPdN * s.D[i];
  }
  Eigen::VectorXd tauDual;
  response_.dual(qt, qn, tauDual);
  ++numDual_;
  Eigen::VectorXd g = tauDual + local + zeta_ * s.beta;
  return g.cwiseProduct(response_.freeMask());
}

}  // namespace friction
