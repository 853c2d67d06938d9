// Closed forms of METHOD.md §11 for the pressure on a fault of constant hydraulic diffusivity:
// the known answers that the computed diffusion (flow/FaultDiffusion.hpp) is checked against,
// and the "wells with closed forms" of issue 27. Every function returns Δp [Pa] over the
// initial state p₀, positive for injection (a rise in pore pressure); times in s from the
// start of the first step-on, distances in m.
//
// The equation behind them (flow/FaultDiffusion.hpp states it in full):
//   S ∂p/∂t − ∇_Γ·(κ ∇_Γ p) = q,   α = κ/S,
// S [m/Pa] storage per unit fault area, κ = k w_h/η [m³/(Pa·s)] transmissivity, q the volume
// rate injected per unit fault area [m/s]. A well is q = Q δ(x − x₀):
//   2D (a fault line of a plane-strain section): Q = Q₀ [m²/s], the volume rate per metre
//      out of the plane; half of it flows to each side: −κ ∂p/∂s(s₀±) = ±Q₀/2.
//   3D (a fault surface): Q [m³/s]; far from the well the flux through a circle of radius r
//      is Q: −2πr κ ∂p/∂r → Q as r → 0.
//
// Mapping of the SEAS BP6 parameters (G as in the benchmark's description, eq. 27, and in
// tandem's BP6 input, p = q₀/(βφ√α)·G): that closed form solves ∂p/∂t = α ∂²p/∂s² with
// −αβφ ∂p/∂s(0±) = ±q₀/2, i.e. a Darcy flux q₀ [m/s] into the fault zone at s = 0, half to
// each side (αβφ = k/η), storage βφ [1/Pa] (compressibility × porosity). Over a fault zone
// of width w, S = βφ·w and Q₀ = q₀·w; only Q₀/S = q₀/(βφ) enters, so BP6 is S = βφ, Q₀ = q₀
// (w = 1 m) in this library's terms.
#pragma once

#include <limits>

#include "friction/flow/StepSchedule.hpp"

namespace friction {

/// The exponential integral E₁(x) = ∫_x^∞ e^{−u}/u du for x ≥ 0 (+∞ at 0, 0 once e^{−x}
/// underflows), to full double precision: its power series for x ≤ 1, its continued fraction
/// beyond. Throws std::domain_error for x < 0 or NaN.
double exponentialIntegralE1(double x);

/// 2D, a pressure change Δp held at s₀ from t = 0: Δp · erfc(|s − s₀| / √(4αt)); 0 for t ≤ 0.
/// s, s₀ [m] along the fault, t [s], deltaP [Pa], alpha [m²/s] > 0.
double heldPressure2d(double s, double s0, double t, double deltaP, double alpha);
/// The same for a held-pressure schedule, by superposition of step-ons (a change to 0 holds
/// p₀ at s₀ again: the well then drains what it had injected; it is not a no-flow shut-in).
double heldPressure2d(double s, double s0, double t, const StepSchedule& deltaP, double alpha);

/// BP6's G(s, t) = √t [e^{−s²/4αt}/√π − (|s|/√(4αt)) erfc(|s|/√(4αt))], 0 for t ≤ 0
/// [√s, the unit of √t]: √t times the integrated complementary error function of |s|/√(4αt).
double bp6G(double s, double t, double alpha);

/// 2D, a constant injection flux from t = 0 to tOff (SEAS BP6 form):
/// Δp = q₀/(βφ√α) · [G(s, t) − G(s, t − tOff)], s [m] from the injection point, q0 [m/s] the
/// Darcy flux into the fault (half to each side), betaPhi [1/Pa] the storage, alpha [m²/s].
/// tOff = +∞: no shut-in. In this library's terms q0/betaPhi = Q₀/S (file comment).
double bp6Pressure2d(double s, double t, double q0, double betaPhi, double alpha,
                     double tOff = std::numeric_limits<double>::infinity());

/// 2D, a well of rate schedule Q₀(t) [m²/s, per metre out of the plane] at s₀ on a fault of
/// storage S [m/Pa] and diffusivity α [m²/s]: Σ_i ΔQ₀_i/(S√α) · G(s − s₀, t − t_i) over the
/// schedule's step-ons (a shut-in is a change to 0).
double ratePressure2d(double s, double s0, double t, const StepSchedule& rate, double storage,
                      double alpha);

/// 3D, a constant volume rate Q [m³/s] at a point of a fault plane from t = 0:
/// Δp(r, t) = Q/(4πκ) · E₁(r²/(4αt)), r [m] > 0 from the well, kappa [m³/(Pa·s)] the
/// transmissivity k w_h/η (so Q/(4πκ) = Qη/(4π k w_h) = Δp*), alpha [m²/s]; 0 for t ≤ 0.
double ratePressure3d(double r, double t, double Q, double kappa, double alpha);
/// The same for a rate schedule, by superposition of step-ons (shut-in: a change to 0).
double ratePressure3d(double r, double t, const StepSchedule& rate, double kappa, double alpha);

}  // namespace friction
