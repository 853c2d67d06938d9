// The sign conventions of the whole project, stated once (docs/method.md §1). Every other file
// points here instead of restating them.
//
//  * n_Γ ("normal") points from Ω⁺ to Ω⁻.
//  * t_Γ ("tangent") = (−n_y, n_x), i.e. n_Γ = (t_y, −t_x): walking along t_Γ, Ω⁺ lies on
//    the left and n_Γ points to the right.
//  * Each fracture is walked from the end that is smallest in (x, then y) to the other, so
//    the arclength s grows along t_Γ. A horizontal fracture is walked left to right:
//    t_Γ = (1, 0), n_Γ = (0, −1), Ω⁺ is above.
//  * 3D (fault surfaces): the surface's triangles are oriented consistently (across shared
//    edges), then globally so that the component of largest magnitude of their area-weighted
//    mean normal Σ (b − a) × (c − a) is negative (a tie goes to the earlier axis, x before y
//    before z). n_Γ at a node is the normalised sum of its triangles' (b − a) × (c − a) (an
//    area-weighted mean). A horizontal fault has n_Γ = (0, 0, −1) and Ω⁺ above it, as a
//    horizontal 2D fracture has n_Γ = (0, −1) and Ω⁺ above it. The Ω⁺ copy of a node keeps
//    its number, in 2D and 3D.
//  * [[f]] = f⁺ − f⁻ (jump), {f} = (f⁺ + f⁻)/2 (average).
//  * σ_n = (σ n_Γ)·n_Γ, negative in compression; τ = (σ n_Γ)·t_Γ in 2D.
//  * Slip s = [[u]]·t_Γ, slip increment β; with Coulomb's law the slip increment is opposite
//    to τ (docs/method.md §2).
//  * Tangential quantities are k-vectors per node (k = d − 1), components on the node's
//    tangent basis t₁ … t_k: in 2D t₁ = t_Γ; in 3D the basis of tangentBasis() below, and
//    τ_c = (σ n_Γ)·t_c, s_c = [[u]]·t_c.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "friction/core/Types.hpp"

namespace friction {

/// n_Γ from t_Γ: n = (t_y, −t_x), the inverse of t_Γ = (−n_y, n_x).
inline Vector2 normalFromTangent(const Vector2& t) { return Vector2(t.y(), -t.x()); }

/// t_Γ from n_Γ: t = (−n_y, n_x).
inline Vector2 tangentFromNormal(const Vector2& n) { return Vector2(-n.y(), n.x()); }

/// The tangent basis of a 3D fracture node from its unit normal n_Γ (docs/method.md §7):
/// t₁ = the normalised projection onto the tangent plane of the coordinate axis least aligned
/// with n_Γ (smallest |n_i|; a tie goes to the earlier axis, x before y before z), and
/// t₂ = n_Γ × t₁, so that (t₁, t₂, n_Γ) is right-handed (t₁ × t₂ = n_Γ). The friction laws are
/// isotropic in the tangent plane, so results do not depend on this choice.
inline std::array<Eigen::Vector3d, 2> tangentBasis(const Eigen::Vector3d& n) {
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
  const Eigen::Vector3d t1 = (e - e.dot(n) * n).normalized();
  return {t1, n.cross(t1)};
}

}  // namespace friction
