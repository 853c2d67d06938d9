// Basic numeric types shared by every module.
#pragma once

#include <Eigen/Core>

namespace friction {

using Scalar = double;
using Vector2 = Eigen::Vector2d;
using Index = int;  // node / element numbers; meshes beyond 2^31 nodes are out of scope

}  // namespace friction
