// The complementarity function of Coulomb/Tresca friction at one fracture node
// (paper (26)–(31), docs/method.md §4) and its derivatives (docs/method.md §4).
//
// With N = τ − γβ and the projection P_ρ(N) onto [−ρ, ρ] (zero when ρ ≤ 0):
//   D = τ − P_ρ(N) = 0  ⇔  the friction law holds at the node (paper, Proposition 2.3).
// Signs: SignConventions.hpp; τ and β are scalars along t_Γ.
#pragma once

#include <cmath>

namespace friction {

enum class SlipState { open, stick, slip };
const char* toString(SlipState s);

struct NodeComplementarity {
  SlipState state = SlipState::open;
  double D = 0;       ///< τ − P_ρ(N) [Pa]
  double dPdN = 0;    ///< ∂P_ρ/∂N: 1 in stick, 0 otherwise
  double dPdRho = 0;  ///< ∂P_ρ/∂ρ: sign(N) in slip, 0 otherwise
};

/// tau: tangential traction τ [Pa]; beta: slip increment β [m]; rho: friction bound ρ [Pa];
/// gamma: γ > 0 [Pa/m].
inline NodeComplementarity complementarity(double tau, double beta, double rho, double gamma) {
  NodeComplementarity c;
  if (rho <= 0) {
    c.state = SlipState::open;
    c.D = tau;
    return c;
  }
  const double N = tau - gamma * beta;
  if (std::abs(N) <= rho) {
    c.state = SlipState::stick;
    c.D = gamma * beta;  // τ − N
    c.dPdN = 1;
    return c;
  }
  const double s = N > 0 ? 1.0 : -1.0;
  c.state = SlipState::slip;
  c.D = tau - rho * s;
  c.dPdRho = s;
  return c;
}

}  // namespace friction
