// The complementarity function of Coulomb/Tresca friction at one fracture node
// (paper (26)–(31), docs/method.md §4) and its derivatives (docs/method.md §4).
//
// Per node the tangential quantities are k-vectors (k = d − 1: 1 in 2D, 2 in 3D), components
// on the node's tangent basis t₁ … t_k. With N = τ − γβ and the projection P_ρ(N) onto the
// k-ball of radius ρ (zero when ρ ≤ 0; for k = 1 the interval [−ρ, ρ]):
//   D = τ − P_ρ(N) = 0  ⇔  the friction law holds at the node (paper, Proposition 2.3).
// Signs: SignConventions.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace friction {

enum class SlipState { open, stick, slip };
const char* toString(SlipState s);

/// Largest block of control unknowns per node: the d − 1 tangential components of 3D, plus
/// one for a normal component (fractures that open).
constexpr int maxBlockSize = 3;
/// A node's block of k components: fixed capacity, so no heap allocation per node.
using Block = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, maxBlockSize, 1>;
using BlockMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, maxBlockSize, maxBlockSize>;

/// Euclidean norm |v|, scaled against overflow and underflow of the squares. For k = 1 it is
/// exactly |v₀| (v₀/|v₀| = ±1). NaN if a component is NaN, +∞ if one is infinite.
inline double blockNorm(const Block& v) {
  double m = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (std::isnan(v[i])) return std::numeric_limits<double>::quiet_NaN();
    m = std::max(m, std::abs(v[i]));
  }
  if (m == 0 || std::isinf(m)) return m;
  double s = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (v[i] / m) * (v[i] / m);
  return m * std::sqrt(s);
}

struct NodeComplementarity {
  SlipState state = SlipState::open;
  Block D;           ///< τ − P_ρ(N) [Pa], k components
  BlockMatrix dPdN;  ///< ∂P_ρ/∂N (k × k): I in stick, (ρ/|N|)(I − N̂N̂ᵀ) in slip, 0 open
  Block dPdRho;      ///< ∂P_ρ/∂ρ (k): N̂ in slip, 0 otherwise
};

/// tau: tangential traction τ [Pa]; beta: slip increment β [m] (k components each); rho:
/// friction bound ρ [Pa]; gamma: γ > 0 [Pa/m].
inline NodeComplementarity complementarity(const Block& tau, const Block& beta, double rho,
                                           double gamma) {
  const Eigen::Index k = tau.size();
  NodeComplementarity c;
  c.dPdN.setZero(k, k);
  c.dPdRho.setZero(k);
  if (rho <= 0) {
    c.state = SlipState::open;
    c.D = tau;
    return c;
  }
  const Block N = tau - gamma * beta;
  const double normN = blockNorm(N);
  if (normN <= rho) {
    c.state = SlipState::stick;
    c.D = gamma * beta;  // τ − N
    c.dPdN.setIdentity(k, k);
    return c;
  }
  c.state = SlipState::slip;
  Block unit(k);
  if (normN > 0 && std::isfinite(normN)) {
    unit = N / normN;  // for k = 1 exactly ±1: D below is τ ∓ ρ, to the bit
  } else {
    // Tractions that overflow double (non-finite N or ρ; the step is judged diverged): the
    // component signs, as the scalar sign(N) of 2D did.
    for (Eigen::Index i = 0; i < k; ++i) unit[i] = N[i] > 0 ? 1.0 : -1.0;
    unit /= std::sqrt(static_cast<double>(k));
  }
  // For k = 1, (ρ/|N|)(1 − 1) = 0. A non-finite ratio (overflowed ρ) leaves 0 as well, its
  // limit when |N| grows without bound.
  const double ratio = rho / normN;
  if (std::isfinite(ratio))
    c.dPdN = ratio * (BlockMatrix::Identity(k, k) - unit * unit.transpose());
  c.D = tau - rho * unit;
  c.dPdRho = unit;
  return c;
}

}  // namespace friction
