// A synthetic SlipResponse with the structure of the real one (docs/method.md §4): S_tt = M⁻¹A
// with A symmetric positive definite, S_tn = M⁻¹ S_ntᵀ M, M S_nn symmetric; affine maps from
// random offsets (compression σ_n ≈ −4, shear τ ≈ ±3 per component). k tangential components
// per node (SlipResponse.hpp), M repeating each node's weight over its k components; σ_n
// depends on β through S_nt, so that Coulomb's ρ does too. For tests of the control layer that
// need no finite elements.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "friction/control/SlipResponse.hpp"

namespace friction::test {

using Eigen::MatrixXd;
using Eigen::VectorXd;

class SyntheticResponse : public SlipResponse {
 public:
  /// k = 1 draws the same numbers as before blocks existed: the tests keep their problems.
  SyntheticResponse(int n, unsigned seed, int k = 1) : k_(k), rng_(seed) {
    std::uniform_real_distribution<double> u(-1, 1);
    auto rnd = [&](int r, int c) { return MatrixXd::NullaryExpr(r, c, [&] { return u(rng_); }); };
    const int m = k * n;
    w_ = (VectorXd::Ones(n) + 0.5 * rnd(n, 1)) * 0.1;
    mask_ = VectorXd::Ones(n);
    const MatrixXd B = rnd(m, m);
    const MatrixXd A = B * B.transpose() + m * MatrixXd::Identity(m, m);
    Stt_ = componentWeights().cwiseInverse().asDiagonal() * A;
    Snt_ = rnd(n, m);
    const MatrixXd C = rnd(n, n);
    Snn_ = C * C.transpose();  // M S_nn symmetric, as for the real body
    tau0_ = 3 * rnd(m, 1);
    sigma0_ = -VectorXd::Ones(n) * 4 + rnd(n, 1);
    adjoint();
  }
  Eigen::Index size() const override { return w_.size(); }
  int blockSize() const override { return k_; }
  const VectorXd& weights() const override { return w_; }
  const VectorXd& freeMask() const override { return mask_; }
  void primal(const VectorXd& beta, VectorXd& tau, VectorXd& sigmaN) override {
    const Eigen::Index kn = k_ * size();
    if (beta.size() == kn) {
      tau = tau0_ + Stt_ * beta;
      sigmaN = sigma0_ + Snt_ * beta;
      return;
    }
    // With openings g after the slip: a unit opening is the jump −n_Γ (SlipResponse.hpp).
    const VectorXd b = beta.head(kn), g = beta.tail(size());
    tau = tau0_ + Stt_ * b - Stn_ * g;
    sigmaN = sigma0_ + Snt_ * b - w_.cwiseInverse().asDiagonal() * Snn_ * g;
  }
  /// Move σ_n's offsets by `shift` (n): e.g. to put some nodes in tension.
  void shiftSigmaN(const VectorXd& shift) { sigma0_ += shift; }
  void dual(const VectorXd& qt, const VectorXd& qn, VectorXd& tauDual,
            VectorXd* sigmaNDual) override {
    ++dualCalls;
    tauDual = Stt_ * qt + Stn_ * qn;
    if (sigmaNDual) *sigmaNDual = Snt_ * qt + w_.cwiseInverse().asDiagonal() * Snn_ * qn;
  }
  long dualCalls = 0;  ///< dual() calls so far (a product of the krylov variant is one)
  std::mt19937& rng() { return rng_; }
  const MatrixXd& Stt() const { return Stt_; }
  const MatrixXd& Snt() const { return Snt_; }

  /// The same body with node i's tangent basis turned by angle[i] (k = 2): components
  /// x' = Rᵀ x, so τ' = Rᵀ τ, S'_tt = Rᵀ S_tt R, S'_nt = S_nt R (R block-diagonal).
  void rotateBases(const std::vector<double>& angle) {
    const MatrixXd R = rotation(angle);
    Stt_ = R.transpose() * Stt_ * R;
    Snt_ = Snt_ * R;
    tau0_ = R.transpose() * tau0_;
    adjoint();
  }
  /// Block-diagonal rotation of the components by angle[i] at node i (k = 2).
  MatrixXd rotation(const std::vector<double>& angle) const {
    const Eigen::Index n = size();
    MatrixXd R = MatrixXd::Zero(2 * n, 2 * n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double c = std::cos(angle[i]), s = std::sin(angle[i]);
      R.block<2, 2>(2 * i, 2 * i) << c, -s, s, c;
    }
    return R;
  }

 private:
  VectorXd componentWeights() const {
    VectorXd w(k_ * w_.size());
    for (Eigen::Index i = 0; i < w_.size(); ++i) w.segment(k_ * i, k_).setConstant(w_[i]);
    return w;
  }
  void adjoint() {  // S_tn = M⁻¹ S_ntᵀ M: the adjoint of S_nt in the M inner products
    Stn_ = componentWeights().cwiseInverse().asDiagonal() * Snt_.transpose() * w_.asDiagonal();
  }

  int k_;
  std::mt19937 rng_;
  VectorXd w_, mask_, tau0_, sigma0_;
  MatrixXd Stt_, Snt_, Stn_, Snn_;
};

}  // namespace friction::test
