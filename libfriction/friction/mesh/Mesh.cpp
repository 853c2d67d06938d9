// Mesh: triangle areas.
#include "friction/mesh/Mesh.hpp"

#include <cmath>

#include "friction/core/Assert.hpp"

namespace friction {

double Mesh::signedArea(Index t) const {
  FRICTION_ASSERT(t >= 0 && t < numTriangles(), "triangle index out of range");
  const auto& v = triangles[t];
  const Vector2 a = points[v[1]] - points[v[0]];
  const Vector2 b = points[v[2]] - points[v[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

double Mesh::totalArea() const {
  // Absolute values, so that a mesh built by hand with a clockwise triangle still gets its
  // geometric area (the readers never produce one).
  double sum = 0;
  for (Index t = 0; t < numTriangles(); ++t) sum += std::abs(signedArea(t));
  return sum;
}

}  // namespace friction
