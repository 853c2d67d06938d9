// RateState: regularised rate-and-state friction at one fault node, the numerical core of the
// quasi-dynamic integration on the interface operator (docs/method.md §3, ../shared/METHOD.md
// §12; the SEAS benchmarks' form, Erickson et al. 2020 and Rice & Ben-Zion 1996's
// regularisation) [beyond]:
//
//   friction coefficient   f(V, ψ) = a asinh[(V / 2V₀) e^{ψ/a}]          (odd in V)
//   aging law              dψ/dt = (b V₀ / L) (e^{(f₀ − ψ)/b} − |V|/V₀)
//   slip law               dψ/dt = −(|V| / L) (ψ − ψ_ss(V))
//   steady state           ψ_ss(V) = f₀ − b ln(|V|/V₀)          (both laws)
//   per node, at each RHS  φ − η V = σ̄ f(V, ψ)                   (solved for V)
//
// ψ is the state in the form of a friction coefficient: with θ the classical state,
// ψ = f₀ + b ln(V₀θ/L); the aging law is then dθ/dt = 1 − Vθ/L and the slip law
// dθ/dt = −(Vθ/L) ln(Vθ/L) (Ruina 1983). Steady state of the aging law: dψ/dt = 0 ⇔
// e^{(f₀−ψ)/b} = |V|/V₀ ⇔ ψ = f₀ − b ln(|V|/V₀); the slip law's right-hand side vanishes at
// the same ψ by construction. For the unregularised f = a ln(V/V₀) + ψ and
// f_ss = f₀ + (a − b) ln(V/V₀), ψ − ψ_ss = f − f_ss: the slip law is the familiar
// dψ/dt = −(V/L)(f − f_ss), written in ψ so that it stays defined where the regularisation
// matters (V → 0; this is Tandem's DieterichRuinaSlip form).
//
// φ is the elastic shear stress on the node (signed, along the node's slip direction; in 3D
// the modulus of the traction vector, V then along it), η = μ/(2c_s) the radiation damping
// and σ̄ > 0 the effective normal compression. Sign convention: V has the sign of φ.
#pragma once

#include <optional>
#include <string>

namespace friction {

/// How ψ evolves (RateState::stateRate).
enum class StateEvolution { aging, slip };

/// Outcome of the solve for V (RateState::slipRate).
enum class SlipRateStatus {
  converged,     ///< |ΔV| ≤ 1e-13 |V| at the last Newton step, or V = 0 exactly (φ = 0)
  invalidInput,  ///< φ or ψ not finite, or the parameters invalid (RateState::invalid())
  overflow,      ///< the solution exceeds the largest double (η = 0 and φ ≫ σ̄ f): no bracket
  maxIterations,  ///< not converged within 200 iterations (not met in the unit tests)
};

/// A word for the log: "converged", "invalidInput", "overflow", "maxIterations".
const char* toString(SlipRateStatus status);

/// The slip rate V [m/s] that balances φ − ηV = σ̄ f(V, ψ).
struct SlipRate {
  double V = 0;  ///< [m/s], sign of φ; NaN unless converged
  SlipRateStatus status = SlipRateStatus::invalidInput;
  int iterations = 0;  ///< Newton (or bisection) iterations
  bool converged() const { return status == SlipRateStatus::converged; }
};

/// The regularised rate-and-state law at one node: its parameters and everything a
/// quasi-dynamic right-hand side needs from it.
struct RateState {
  double a = 0.01;         ///< direct-effect parameter (–), > 0
  double b = 0.015;        ///< evolution-effect parameter (–), > 0
  double L = 0.008;        ///< characteristic slip distance [m], > 0
  double f0 = 0.6;         ///< reference friction coefficient at V₀ (–)
  double V0 = 1e-6;        ///< reference slip rate [m/s], > 0
  double sigmaBar = 50e6;  ///< effective normal compression σ̄ = −σ'_n [Pa], > 0
  double eta = 0;          ///< radiation damping η = μ/(2 c_s) [Pa s/m], ≥ 0
  StateEvolution evolution = StateEvolution::aging;

  /// "" when the parameters are valid, else which one is wrong and what was expected
  /// (for the caller's InputError, which names the file and key).
  std::string invalid() const;
  /// invalid().empty(), without forming a message.
  bool valid() const;

  /// f(V, ψ) = a asinh[(V/2V₀) e^{ψ/a}] (–), odd in V [m/s]; no overflow for any finite ψ.
  double friction(double V, double psi) const;
  /// ∂f/∂V [s/m] (even in V, > 0; at V = 0 it is a e^{ψ/a}/(2V₀), possibly +inf).
  double frictionDerivativeV(double V, double psi) const;
  /// ∂f/∂ψ (–), in [−1, 1], sign of V.
  double frictionDerivativePsi(double V, double psi) const;

  /// dψ/dt [1/s] of the chosen evolution law at slip rate V [m/s] (only |V| enters).
  double stateRate(double V, double psi) const;
  /// ψ_ss(V) = f₀ − b ln(|V|/V₀): the steady state of both laws at slip rate V ≠ 0.
  double steadyState(double V) const;
  /// f_ss(V) = f(V, ψ_ss(V)) = a asinh[½ (|V|/V₀)^{1 − b/a} e^{f₀/a}] sign(V): the steady-state
  /// friction coefficient, regularised.
  double steadyStateFriction(double V) const;
  /// The steady slip rate V_ss [m/s] under the frictional stress τ [Pa] (= φ − ηV, signed):
  /// σ̄ f_ss(V_ss) = τ, i.e. ln(V_ss/V₀) = [a ln(2 sinh(|τ|/(aσ̄))) − f₀] / (a − b). Empty when
  /// a = b (f_ss independent of V) or when V_ss is not a finite number (τ = 0 with a < b).
  std::optional<double> steadyStateSlipRate(double tau) const;
  /// The ψ at which the node slides at V [m/s] under the driving stress φ [Pa]: the inverse of
  /// slipRate, ψ = a ln[(2V₀/V) sinh((φ − ηV)/(aσ̄))] (the SEAS initial state). Empty unless
  /// V ≠ 0 and φ − ηV has V's sign.
  std::optional<double> stateFor(double V, double phi) const;

  /// Solves φ − ηV = σ̄ f(V, ψ) for V (φ [Pa], ψ (–)). The residual is monotone in V, so the
  /// root is unique and has φ's sign. Solved in the unknown u = |f| ∈ (0, |φ|/σ̄], where
  /// h(u) = σ̄u + η V(u) − |φ| is increasing and convex (V(u) = 2V₀ e^{−ψ/a} sinh(u/a)):
  /// Newton from the bracket's upper end, min(|φ|/σ̄, f(|φ|/η)), converges monotonically
  /// (a bisection step if rounding ever leaves the bracket); V is evaluated in logarithms, so
  /// no intermediate overflows. Converged: relative change of V ≤ 1e-13 (the next Newton
  /// step would be ~1e-26: the result is accurate to rounding, ~|ln V|·ε relative).
  SlipRate slipRate(double phi, double psi) const;
};

}  // namespace friction
