// A synthetic SlipResponse with the structure of the real one (docs/method.md §4): S_tt = M⁻¹A
// with A symmetric positive definite, S_tn = M⁻¹ S_ntᵀ M, M S_nn symmetric; affine maps from
// random offsets (compression σ_n ≈ −4, shear τ ≈ ±3). For tests of the control layer that
// need no finite elements.
#pragma once

#include <random>

#include <Eigen/Core>

#include "friction/control/SlipResponse.hpp"

namespace friction::test {

using Eigen::MatrixXd;
using Eigen::VectorXd;

class SyntheticResponse : public SlipResponse {
 public:
  SyntheticResponse(int n, unsigned seed) : rng_(seed) {
    std::uniform_real_distribution<double> u(-1, 1);
    auto rnd = [&](int r, int c) { return MatrixXd::NullaryExpr(r, c, [&] { return u(rng_); }); };
    w_ = (VectorXd::Ones(n) + 0.5 * rnd(n, 1)) * 0.1;
    mask_ = VectorXd::Ones(n);
    const MatrixXd B = rnd(n, n);
    const MatrixXd A = B * B.transpose() + n * MatrixXd::Identity(n, n);
    Stt_ = w_.cwiseInverse().asDiagonal() * A;
    Snt_ = rnd(n, n);
    Stn_ = w_.cwiseInverse().asDiagonal() * Snt_.transpose() * w_.asDiagonal();
    const MatrixXd C = rnd(n, n);
    Snn_ = C * C.transpose();  // M S_nn symmetric, as for the real body
    tau0_ = 3 * rnd(n, 1);
    sigma0_ = -VectorXd::Ones(n) * 4 + rnd(n, 1);
  }
  Eigen::Index size() const override { return w_.size(); }
  const VectorXd& weights() const override { return w_; }
  const VectorXd& freeMask() const override { return mask_; }
  void primal(const VectorXd& beta, VectorXd& tau, VectorXd& sigmaN) override {
    tau = tau0_ + Stt_ * beta;
    sigmaN = sigma0_ + Snt_ * beta;
  }
  void dual(const VectorXd& qt, const VectorXd& qn, VectorXd& tauDual,
            VectorXd* sigmaNDual) override {
    tauDual = Stt_ * qt + Stn_ * qn;
    if (sigmaNDual) *sigmaNDual = Snt_ * qt + w_.cwiseInverse().asDiagonal() * Snn_ * qn;
  }
  std::mt19937& rng() { return rng_; }

 private:
  std::mt19937 rng_;
  VectorXd w_, mask_, tau0_, sigma0_;
  MatrixXd Stt_, Snt_, Stn_, Snn_;
};

}  // namespace friction::test
