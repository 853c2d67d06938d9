// Basic numeric types shared by every module.
#pragma once

#include <Eigen/Core>

namespace friction {

using Scalar = double;
using Vector2 = Eigen::Vector2d;
/// A mesh point: (x, y, z), with z = 0 in a 2D mesh (whose arithmetic reads x and y only).
using Point = Eigen::Vector3d;
using Index = int;  // node / element numbers; meshes beyond 2^31 nodes are out of scope

}  // namespace friction
