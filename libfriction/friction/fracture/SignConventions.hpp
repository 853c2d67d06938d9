// The sign conventions of the whole project, stated once (docs/method.md §1). Every other file
// points here instead of restating them.
//
//  * n_Γ ("normal") points from Ω⁺ to Ω⁻.
//  * t_Γ ("tangent") = (−n_y, n_x), i.e. n_Γ = (t_y, −t_x): walking along t_Γ, Ω⁺ lies on
//    the left and n_Γ points to the right.
//  * Each fracture is walked from the end that is smallest in (x, then y) to the other, so
//    the arclength s grows along t_Γ. A horizontal fracture is walked left to right:
//    t_Γ = (1, 0), n_Γ = (0, −1), Ω⁺ is above.
//  * [[f]] = f⁺ − f⁻ (jump), {f} = (f⁺ + f⁻)/2 (average).
//  * σ_n = (σ n_Γ)·n_Γ, negative in compression; τ = (σ n_Γ)·t_Γ in 2D.
//  * Slip s = [[u]]·t_Γ, slip increment β; with Coulomb's law the slip increment is opposite
//    to τ (docs/method.md §2).
#pragma once

#include "friction/core/Types.hpp"

namespace friction {

/// n_Γ from t_Γ: n = (t_y, −t_x), the inverse of t_Γ = (−n_y, n_x).
inline Vector2 normalFromTangent(const Vector2& t) { return Vector2(t.y(), -t.x()); }

/// t_Γ from n_Γ: t = (−n_y, n_x).
inline Vector2 tangentFromNormal(const Vector2& n) { return Vector2(-n.y(), n.x()); }

}  // namespace friction
