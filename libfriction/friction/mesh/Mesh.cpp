// Mesh: cell measures, the shared topology.
#include "friction/mesh/Mesh.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include <Eigen/Geometry>

#include "friction/core/Assert.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

void Mesh::addCell(std::initializer_list<Index> vertices, int region) {
  FRICTION_ASSERT(static_cast<int>(vertices.size()) == dim + 1, "addCell: wrong vertex count");
  cellVertices.insert(cellVertices.end(), vertices.begin(), vertices.end());
  cellRegion.push_back(region);
}

void Mesh::addFacet(std::initializer_list<Index> vertices, int label) {
  FRICTION_ASSERT(static_cast<int>(vertices.size()) == dim, "addFacet: wrong vertex count");
  facetVertices.insert(facetVertices.end(), vertices.begin(), vertices.end());
  facetLabel.push_back(label);
}

double Mesh::signedMeasure(Index c) const {
  FRICTION_ASSERT(c >= 0 && c < numCells(), "cell index out of range");
  const auto v = cell(c);
  if (dim == 2) {
    // x and y only, in the order of the 2D code (results stay byte for byte).
    const Vector2 a = points[v[1]].head<2>() - points[v[0]].head<2>();
    const Vector2 b = points[v[2]].head<2>() - points[v[0]].head<2>();
    return 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  const Point a = points[v[1]] - points[v[0]];
  const Point b = points[v[2]] - points[v[0]];
  const Point d = points[v[3]] - points[v[0]];
  return a.cross(b).dot(d) / 6.0;
}

double Mesh::totalMeasure() const {
  // Absolute values, so that a mesh built by hand with a wrongly oriented cell still gets its
  // geometric measure (the readers never produce one).
  double sum = 0;
  for (Index c = 0; c < numCells(); ++c) sum += std::abs(signedMeasure(c));
  return sum;
}

std::shared_ptr<const MeshTopology> Mesh::topology() const {
  if (!topology_ || !topology_->describes(*this))
    topology_ = std::make_shared<const MeshTopology>(*this);
  return topology_;
}

std::string formatPoint(const Point& p, int dim) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << " " << p.y();
  if (dim == 3) s << " " << p.z();
  s << ")";
  return s.str();
}

const char* cellName(int dim) { return dim == 3 ? "tetrahedron" : "triangle"; }
const char* facetName(int dim) { return dim == 3 ? "triangle" : "edge"; }

std::uint64_t sideKey(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace friction
