// Mesh: triangle areas, the shared topology.
#include "friction/mesh/Mesh.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "friction/core/Assert.hpp"
#include "friction/mesh/MeshTopology.hpp"

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

std::shared_ptr<const MeshTopology> Mesh::topology() const {
  if (!topology_ || !topology_->describes(*this))
    topology_ = std::make_shared<const MeshTopology>(*this);
  return topology_;
}

std::string formatPoint(const Vector2& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << " " << p.y() << ")";
  return s.str();
}

std::uint64_t sideKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace friction
