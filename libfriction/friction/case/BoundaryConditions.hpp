// BoundaryConditions: the case's 0/D — one entry per boundary patch in 'boundaryField', the
// way OpenFOAM cases give them (docs/method.md §1: Dirichlet displacement and Neumann traction,
// all functions of time):
//
//   boundaryField
//   {
//       bottom { type fixedDisplacement; value (0 0); }
//       top    { type fixedDisplacement; value table ((0 (0 0)) (1 (-0.02 -0.025))); }
//       left   { type fixedDisplacement; components (x); value (0 0); }   // roller
//       right  { type traction; traction (0 0); }                         // [Pa]
//       lid    { type pressure; pressure 1e7; }     // [Pa], pushes along −n (inward)
//       side   { type free; }
//   }
// Every boundary patch must be listed; an unknown patch or type is an error naming it.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/fe/DirichletConditions.hpp"
#include "friction/fe/LagrangeSpace.hpp"
#include "friction/mesh/Mesh.hpp"
#include "friction/time/TimeFunction.hpp"

namespace friction {

class Dictionary;

class BoundaryConditions {
 public:
  enum class Type { fixedDisplacement, traction, pressure, free };
  static std::vector<std::string> typeNames();

  struct Patch {
    std::string name;
    int label = 0;
    Type type = Type::free;
    FixedComponents components = FixedComponents::all;
    TimeFunction value;  ///< displacement [m], traction [Pa] or pressure [Pa]
    /// pressure: outward unit normal per edge of the patch, in mesh edge order.
    std::vector<Vector2> outwardNormal;
  };

  /// Read 0/D's boundaryField against the patches of the (split) mesh.
  BoundaryConditions(const Dictionary& dict, const Mesh& mesh,
                     const std::vector<int>& fractureLabels);

  const std::vector<Patch>& patches() const { return patches_; }

  /// Fix the Dirichlet dofs (once, before the factorisation).
  void fix(DirichletConditions& dirichlet) const;
  /// Set the Dirichlet values at time t.
  void setValues(DirichletConditions& dirichlet, double t) const;
  /// Whether the Neumann loads at t differ from those at t0 (tables only change in time).
  bool loadsChange(double t0, double t) const;
  /// Nodal force vector of the tractions and pressures at time t on `space` [N per m].
  Eigen::VectorXd neumannLoad(const LagrangeSpace& space, double t) const;

 private:
  std::vector<Patch> patches_;
};

}  // namespace friction
