// FaultPressure: the fluid pressure p_f(x, t) on faults (docs/method.md §11, "Fluid
// pressure"), an effect of constant/effects:
//
//   fluid
//   {
//       type       faultPressure;
//       fractures  (fault);        // optional: every fracture of the case by default
//                                  // (or 'fracture fault;' for one)
//       initial    { type depth; value 1e5; gradient -9810; }    // p₀(x) [Pa]: a number or
//                                  // a field (FrictionField's forms: depth, points,
//                                  // arclength); hydrostatic is the depth form, ρ_f g per m
//       change     table ((0 0) (3600 5e6));  // optional: Δp(t) [Pa], the same at every node
//       wells      { w { position (x y [z]); pressure SCHEDULE; | rate SCHEDULE; } }  // optional
//       data       "constant/p.dat";       // optional: rows "t x y [z] p", Δp at points in time
//   }
//
// p_f(x, t) = p₀(x) + Δp(t) at each control node of the listed fractures; it enters the
// friction law only through the effective normal stress σ'_n = σ_n + p_f (σ_n < 0 in
// compression), as fracturePressure does, and the tables and the fault's VTK then carry p and
// σ'_n. Several effects on one fracture add their pressures.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace friction {

class Dictionary;
class Effect;

/// The effect table's entry for type faultPressure (Effect.cpp).
std::unique_ptr<Effect> makeFaultPressure(const std::string& name, const Dictionary& dict,
                                          const std::vector<std::string>& fractureNames,
                                          const std::string& caseDir, int dim);

}  // namespace friction
