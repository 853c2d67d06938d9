// The reference way of forming the interface operator: one dual solve per fracture node and
// tangential component.
#include "friction/control/SlipResponse.hpp"

#include "friction/core/StopRequest.hpp"

namespace friction {

const char* toString(InterfaceMethod method) {
  switch (method) {
    case InterfaceMethod::factorisation:
      return "factorisation";
    case InterfaceMethod::blockSolves:
      return "blockSolves";
    case InterfaceMethod::dualSolves:
      return "dualSolves";
  }
  return "unknown";
}

void SlipResponse::dualBlock(const Eigen::MatrixXd& qt, const Eigen::MatrixXd& qn,
                             Eigen::MatrixXd& tauDual, Eigen::MatrixXd* sigmaNDual) {
  const Eigen::Index m = qt.cols();
  tauDual.resize(blockSize() * size(), m);
  if (sigmaNDual) sigmaNDual->resize(size(), m);
  Eigen::VectorXd t, sn;
  for (Eigen::Index c = 0; c < m; ++c) {
    throwIfStopNow();
    dual(qt.col(c), qn.col(c), t, sigmaNDual ? &sn : nullptr);
    tauDual.col(c) = t;
    if (sigmaNDual) sigmaNDual->col(c) = sn;
  }
}

InterfaceOperator SlipResponse::interfaceOperator(InterfaceMethod /*method*/, bool withOpening) {
  const Eigen::Index n = size(), k = blockSize();
  const Eigen::VectorXd& mask = freeMask();
  InterfaceOperator op;
  op.method = InterfaceMethod::dualSolves;
  op.Stt.setZero(k * n, k * n);
  op.Snt.setZero(n, k * n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(k * n), zero = Eigen::VectorXd::Zero(n), t, sn;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (mask[i] == 0) continue;
    for (Eigen::Index c = 0; c < k; ++c) {
      throwIfStopNow();  // k·n solves: long on big fractures
      const Eigen::Index col = k * i + c;
      e[col] = 1;
      dual(e, zero, t, &sn);
      ++op.solves;  // one dual solve: one back-substitution
      e[col] = 0;
      op.Stt.col(col) = t;
      op.Snt.col(col) = sn;
    }
  }
  if (!withOpening) return op;
  op.Stn.setZero(k * n, n);
  op.Snn.setZero(n, n);
  const Eigen::VectorXd zeroT = Eigen::VectorXd::Zero(k * n);
  Eigen::VectorXd open = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (mask[i] == 0) continue;
    throwIfStopNow();
    open[i] = -1;  // a unit opening is the jump −n_Γ
    dual(zeroT, open, t, &sn);
    ++op.solves;
    open[i] = 0;
    op.Stn.col(i) = t;
    op.Snn.col(i) = sn;
  }
  return op;
}

}  // namespace friction
