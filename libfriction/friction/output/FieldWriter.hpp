// Field and table files of a time folder (issue: frictionSolver output):
//  * writeDisplacementField: <time>/D, an OpenFOAM pointVectorField (3 components, z = 0) on
//    the points of the split mesh, so the jump across a fracture is visible; foamDictionary
//    reads it.
//  * writeFractureTable: <time>/fractures/<name>.dat, whitespace-separated, first line
//    "# s x y slip slipIncrement sigmaN tau ST residual state", one row per control node in
//    arclength order; a second comment line gives the step's solver status. state is stick,
//    slip, open or tip; a tip has no traction: sigmaN, tau, ST and residual are "nan" there
//    (numpy.loadtxt, pandas and VTK read it as NaN), every other value is finite.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "friction/core/Types.hpp"

namespace friction {

/// points: split-mesh points; u: 2 values per point [m].
void writeDisplacementField(const std::string& path, const std::vector<Vector2>& u, int precision);

struct FractureRow {
  /// residual: the friction law's residual D of the complementarity function [Pa].
  double s, x, y, slip, slipIncrement, sigmaN, tau, ST, residual;
  std::string state;
};

void writeFractureTable(const std::string& path, const std::vector<FractureRow>& rows,
                        const std::string& statusLine, int precision);

}  // namespace friction
