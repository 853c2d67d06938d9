// Field and table files of a time folder (issue: frictionSolver output):
//  * writeDisplacementField: <time>/D, an OpenFOAM pointVectorField (3 components, z = 0 in
//    2D) on the points of the split mesh, so the jump across a fracture is visible;
//    foamDictionary reads it.
//  * writeFractureTable: <time>/fractures/<name>.dat, whitespace-separated, one row per control
//    node; line 2 gives the step's solver status (2D: then one comment per junction node, see
//    junctionNotes). state is stick, slip, open, tip or junction; every value is finite: a
//    tip (and a junction end) has no jump and no recovered traction, and its traction columns
//    hold the body's stress at the node instead (FrictionCase::fractureRows), its residual 0.
//    2D: line 1 "# s x y slip slipIncrement sigmaN tau ST residual nx ny tx ty slipX slipY
//    state" (n_Γ, t_Γ and the slip vector slip·t_Γ [m]), rows in arclength order.
//    3D: line 1 "# x y z nx ny nz slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1
//    slipIncrement2 sigmaN tau1 tau2 tauMagnitude ST residual state" (components on the node's
//    t₁, t₂ and, for the slip, in x y z; residual = |D|); line 3 the frame: "# frame n (..)
//    t1 (..) t2 (..)" when every node has the same one (a flat fault), else "# frame per
//    node: ...". Rows in the control-node order of FractureSystem.
//    With fractures that open (contact unilateral), a column "opening" (g = −[[u]]·n_Γ [m])
//    comes after "residual", in 2D and 3D; with a fluid pressure (fracturePressure,
//    faultPressure), "pressure sigmaNEffective deltaCFS" (p, σ'_n = σ_n + p and the Coulomb
//    failure stress change [Pa]) come after it, and in 3D "slipStrike slipDip tauStrike
//    tauDip" (strikeDipValues()); with friction that weakens (slipWeakening), "slipPath
//    frictionCoefficient" (δ [m] and μ(δ)) after those. 2D: "nx ny tx ty slipX slipY" come
//    after all of them, just before "state", so that the earlier columns keep their places.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/core/Types.hpp"

namespace friction {

/// u: the displacement [m] at each split-mesh point (z = 0 in 2D, written as 0).
void writeDisplacementField(const std::string& path, const std::vector<Point>& u, int precision);

/// One control node of a fracture table. Tangential quantities have k = d − 1 components on
/// the node's tangent basis (2D: [0] only, on t_Γ). Signs: fracture/SignConventions.hpp.
struct FractureRow {
  double s = 0;                                      ///< 2D arclength [m]; 0 in 3D
  Point position = Point::Zero();                    ///< [m], z = 0 in 2D
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< n_Γ, from Ω⁺ to Ω⁻
  std::array<Eigen::Vector3d, 2> tangent{Eigen::Vector3d::Zero(),
                                         Eigen::Vector3d::Zero()};  ///< t₁, t₂ (2D: t₁ = t_Γ)
  /// Accumulated slip [m], the step's slip increment β [m], the tangential traction τ [Pa] and
  /// the friction law's complementarity residual D [Pa], on t₁ … t_k.
  std::array<double, 2> slip{}, slipIncrement{}, tau{}, residual{};
  double sigmaN = 0;        ///< [Pa]
  double ST = 0;            ///< slip tendency |τ| / −σ'_n [-]
  bool hasOpening = false;  ///< the case has fractures that open: the opening column is written
  double opening = 0;       ///< g = −[[u]]·n_Γ [m], 0 where the faces touch
  /// The case has a fluid pressure on its fractures: the columns pressure and sigmaNEffective
  /// are written (after opening, before state).
  bool hasPressure = false;
  double pressure = 0;         ///< p [Pa] (fluid, positive)
  double sigmaNEffective = 0;  ///< σ'_n = σ_n + p [Pa]
  /// Coulomb failure stress change against the initial state, Δ|τ| + μ_f Δσ'_n [Pa] (positive
  /// towards failure); written with the pressure columns.
  double deltaCFS = 0;
  /// The fracture's friction weakens with slip (law slipWeakening on some fracture of the
  /// case): the columns slipPath and frictionCoefficient are written (after the pressure
  /// columns, before state).
  /// Rate-and-state faults (law rateState): the columns slipRate (|V| [m/s]) and psi (the
  /// state ψ) are written (after the pressure columns, before slipPath's).
  bool hasRateState = false;
  double slipRate = 0, psi = 0;
  bool hasWeakening = false;
  double slipPath = 0;             ///< δ, the length of the path slid [m]
  double frictionCoefficient = 0;  ///< μ at δ (the law's μ where the friction does not weaken)
  std::string state;
};

/// The fault's strike and down-dip unit vectors at a node of normal n (z up), whichever side n
/// points to: dip is the steepest way down the fault plane (−e_z projected on it), strike the
/// horizontal direction in it with the fault dipping to its right (seen from above, dip is
/// strike turned clockwise by 90°). A vertical fault (|n_z| ≤ 1e-12) dips neither way: dip =
/// −e_z and strike the horizontal direction with x > 0 (or +e_y): (−90°, 90°] from x. A horizontal
/// fault (|n_z| ≥ 1 − 1e-12) has neither: strike = e_x and dip = −e_y (rules stated in the
/// README).
void strikeDipBasis(const Eigen::Vector3d& n, Eigen::Vector3d& strike, Eigen::Vector3d& dip);

/// The slip and τ of a 3D row on strikeDipBasis(row.normal): {slipStrike, slipDip, tauStrike,
/// tauDip}, those of the hanging wall, whichever side n_Γ points to. The row's jump is Ω⁺
/// minus Ω⁻ and its τ the traction on Ω⁺ (n_Γ points from Ω⁺ to Ω⁻), so they change sign with
/// the side the splitting's orientation rule picks (which a rotation of the body can change);
/// here they are the slip of the hanging wall relative to the footwall and the traction on
/// the hanging wall. The hanging wall is the side dip × strike points to: the one above a
/// dipping or horizontal fault, the one to the right of strike (seen from above) of a vertical
/// fault.
std::array<double, 4> strikeDipValues(const FractureRow& row);

/// The numbers of a fracture table's row, in the file's order (the header comment above),
/// without the state: 2D s x y slip slipIncrement sigmaN tau ST residual; 3D x y z nx ny nz
/// slip1 slip2 slipX slipY slipZ slipMagnitude slipIncrement1 slipIncrement2 sigmaN tau1
/// tau2 tauMagnitude ST residual; then opening if the row has one, then pressure,
/// sigmaNEffective and deltaCFS if it has them (3D: also slipStrike slipDip tauStrike tauDip);
/// 2D then nx ny tx ty slipX slipY.
std::vector<double> fractureTableValues(const FractureRow& row, int dim);

/// dim: 2 or 3, the layout of the file comment (2D: components [0]; 3D: both, the magnitudes
/// and slipX.. = slip[0] t₁ + slip[1] t₂ derived here; 2D: slipX slipY = slip[0] t₁).
/// `notes`: more comment lines after the status line (2D: the fracture's junctions; 3D: where
/// it meets other fault surfaces, after the frame line), each written as "# " + note.
void writeFractureTable(const std::string& path, const std::vector<FractureRow>& rows,
                        const std::string& statusLine, int precision, int dim,
                        const std::vector<std::string>& notes = {});

}  // namespace friction
