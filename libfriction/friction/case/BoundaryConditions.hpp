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
//
// The dimension comes from the mesh: on a 3D mesh (tetrahedra, labelled boundary triangles)
// vectors have three components, e.g. value (0 0 -0.01); traction (0 0 -1e6);
// components (x z) (any non-empty subset of x y z; z is refused on a 2D mesh), and a pressure
// pushes along −n of each triangle of the patch (n pointing away from the tetrahedron's
// opposite vertex).
#pragma once

#include <functional>
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
    /// pressure: outward unit normal per facet of the patch (edge in 2D, z = 0; triangle in
    /// 3D), in mesh facet order.
    std::vector<Point> outwardNormal;
    std::vector<Point> facetCentre;  ///< traction and pressure patches: per facet
  };

  /// Read 0/D's boundaryField against the patches of the (split) mesh; vectors have
  /// mesh.dim components.
  BoundaryConditions(const Dictionary& dict, const Mesh& mesh,
                     const std::vector<int>& fractureLabels);

  const std::vector<Patch>& patches() const { return patches_; }

  /// Fix the Dirichlet dofs (once, before the factorisation).
  void fix(DirichletConditions& dirichlet) const;
  /// Set the Dirichlet values at time t.
  void setValues(DirichletConditions& dirichlet, double t) const;
  /// The traction and pressure patches whose load at time t equals the in-situ traction
  /// σ⁰(x)·n at every facet (to 1 %, σ⁰·n ≠ 0): the boundary conditions act on the change from
  /// the in-situ state, so such a patch applies the in-situ load a second time.
  std::vector<std::string> tractionsOfInSitu(
      const std::function<Eigen::Matrix3d(const Point&)>& sigma0, double t) const;
  /// Whether the Neumann loads at t differ from those at t0 (tables only change in time).
  bool loadsChange(double t0, double t) const;
  /// Nodal force vector of the tractions and pressures at time t on `space` [N per m in 2D,
  /// N in 3D]; `space` is on the mesh the conditions were read against.
  Eigen::VectorXd neumannLoad(const LagrangeSpace& space, double t) const;

 private:
  std::vector<Patch> patches_;
};

}  // namespace friction
