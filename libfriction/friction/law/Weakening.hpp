// The slip-weakening of one fracture node (law slipWeakening, FrictionLaw.hpp): μ as a
// function of the slip path δ [m], linear or exponential from μ_s to μ_d over D_c. Apart from
// FrictionLaw.hpp so that the control problem takes it without the dictionaries.
#pragma once

namespace friction {

/// How μ weakens with the slip path δ at one node (WeakeningNode), per law.
enum class Weakening { none, linear, exponential };

/// The slip-weakening of one control node: μ(δ) and dμ/dδ.
struct WeakeningNode {
  Weakening form = Weakening::none;
  double muStatic = 0, muDynamic = 0, criticalSlip = 1;  ///< μ_s, μ_d (–), D_c [m]
  /// μ at slip path δ ≥ 0 [m].
  double mu(double delta) const;
  /// dμ/dδ [1/m] (≤ 0); the linear form's kink at D_c takes the side of larger δ (0 there).
  double slope(double delta) const;
};

}  // namespace friction
