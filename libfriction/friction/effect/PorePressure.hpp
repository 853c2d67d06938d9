// PorePressure: the pore pressure p_b(x, t) of the rock, acting through a Biot coefficient
// (docs/method.md §12, "Pore pressure in the rock"), an effect of constant/effects:
//
//   rock
//   {
//       type            porePressure;
//       biotCoefficient 1;                                   // α_B in [0, 1]
//       initial         { type depth; value 0; gradient -9810; }   // p_b0(x) [Pa]: a number
//                                            // or a field (FrictionField's forms depth, points)
//       regions         { reservoir { change table ((0 0) (1 -10e6)); } }  // optional: Δp_b(t)
//                                            // [Pa] per mesh region (name or region<N>)
//       change          table ((0 0) (1 -1e6));             // optional: Δp_b(t) everywhere
//       data            "constant/pb.dat";   // optional: rows "t x y [z] p" [s, m, Pa], Δp_b at
//                                            // points at listed times (flow/PointData.hpp)
//       maxDistance     50;                  // data: farthest row from a cell centroid [m]
//                                            // (default: the mesh's largest cell diameter)
//       // or: data script;  (the word, unquoted): Δp_b at the mesh's vertices at listed times,
//       //   given by the program running the case (GivenField.hpp; the FreeFEM plug-in's
//       //   frictionSolve("case", pressure = P, pressureTimes = T)); each cell takes the mean of
//       //   its vertices' values; a run given none (frictionSolver) is refused naming the key
//   }
//
// One way: the pressure is given, the deformation does not change it.
// p_b(x, t) = p_b0(x) + Δp_b(x, t), Δp_b = change(t) + the change of the cell's region (0 in
// regions not listed) + the data's, constant in each cell. The data: each cell takes, per
// listed time, the value of the row of that time nearest its centroid (data script: the mean
// of its vertices' values), linear in time between the listed times and constant beyond; a row
// farther than maxDistance from every centroid lies outside the body (wrong units or coordinates)
// and is refused naming its line. Its load is assembled once per listed time (the load is linear in
// Δp_b) and two are combined per step.
//
// The initial state is in equilibrium with the in-situ stress (as initialStress: the boundary
// conditions act on the perturbation; σ⁰ of initialStress is the total in-situ stress, so it
// holds −α_B p_b0 already). Hence only the change loads the body: the total stress is
// σ = σ⁰ + C:ε(u) − α_B Δp_b I, the load gains ∫_Ω α_B Δp_b div v (ElasticityAssembler::
// pressureLoad; plane stress: see there), and the written stresses add −α_B Δp_b I. The
// tractions recovered on the fractures are then total tractions, and a fracture that has no
// fluid pressure of its own (no faultPressure or fracturePressure names it) takes the rock's
// total pressure p_f = p_b0 + Δp_b: its effective normal stress is σ'_n = σ_n + p_b. At a
// fracture node Δp_b is the mean over the cells around it (both sides), weighted by their
// measure; p_b0 is the field evaluated at the node (points: the nearest row within
// maxDistance).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace friction {

class Dictionary;
class Effect;

/// The effect table's entry for type porePressure (Effect.cpp).
std::unique_ptr<Effect> makePorePressure(const std::string& name, const Dictionary& dict,
                                         const std::vector<std::string>& fractureNames,
                                         const std::string& caseDir, int dim);

}  // namespace friction
