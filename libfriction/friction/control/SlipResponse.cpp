// The reference way of forming the interface operator: one dual solve per fracture node.
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

InterfaceOperator SlipResponse::interfaceOperator(InterfaceMethod /*method*/) {
  const Eigen::Index n = size();
  const Eigen::VectorXd& mask = freeMask();
  InterfaceOperator op;
  op.method = InterfaceMethod::dualSolves;
  op.Stt.setZero(n, n);
  op.Snt.setZero(n, n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(n), zero = Eigen::VectorXd::Zero(n), t, sn;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (mask[k] == 0) continue;
    throwIfStopNow();  // n solves: long on big fractures
    e[k] = 1;
    dual(e, zero, t, &sn);
    ++op.solves;  // one dual solve: one back-substitution
    e[k] = 0;
    op.Stt.col(k) = t;
    op.Snt.col(k) = sn;
  }
  return op;
}

}  // namespace friction
