// A fault's own P1 flow mesh: see FaultFlowMesh.hpp.
#include "friction/flow/FaultFlowMesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "friction/core/Suggest.hpp"

namespace friction {

namespace {

std::string pointText(const Point& p) {
  return "(" + formatNumber(p.x()) + " " + formatNumber(p.y()) + " " + formatNumber(p.z()) + ")";
}

// The closest point to x on segment ab: its weights (of a, of b).
std::array<double, 2> segmentWeights(const Point& x, const Point& a, const Point& b) {
  const Point d = b - a;
  const double l = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return {1.0 - l, l};
}

// The closest point to x on triangle abc: its barycentric weights. Inside the triangle's
// shadow, the projection onto its plane; else the closest point of its three edges.
std::array<double, 3> triangleWeights(const Point& x, const Point& a, const Point& b,
                                      const Point& c) {
  const Point e1 = b - a, e2 = c - a, r = x - a;
  const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
  const double r1 = r.dot(e1), r2 = r.dot(e2);
  const double det = g11 * g22 - g12 * g12;
  const double u = (g22 * r1 - g12 * r2) / det;
  const double v = (g11 * r2 - g12 * r1) / det;
  if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) return {1.0 - u - v, u, v};
  std::array<double, 3> best{};
  double bestDistance = std::numeric_limits<double>::infinity();
  const Point* p[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const auto w = segmentWeights(x, *p[i], *p[j]);
    const double d = (x - (w[0] * *p[i] + w[1] * *p[j])).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = {0.0, 0.0, 0.0};
      best[static_cast<std::size_t>(i)] = w[0];
      best[static_cast<std::size_t>(j)] = w[1];
    }
  }
  return best;
}

}  // namespace

FlowCoefficient FlowCoefficient::perNode(Eigen::VectorXd values) {
  FlowCoefficient c;
  c.kind_ = Kind::perNode;
  c.values_ = std::move(values);
  return c;
}

FlowCoefficient FlowCoefficient::perElement(Eigen::VectorXd values) {
  FlowCoefficient c;
  c.kind_ = Kind::perElement;
  c.values_ = std::move(values);
  return c;
}

double FlowCoefficient::onElement(const FaultFlowMesh& mesh, Index e) const {
  switch (kind_) {
    case Kind::constant:
      return constant_;
    case Kind::perElement:
      return values_[e];
    case Kind::perNode:
      break;
  }
  const auto& nodes = mesh.element(e);
  double sum = 0.0;
  for (int k = 0; k < mesh.nodesPerElement(); ++k)
    sum += values_[nodes[static_cast<std::size_t>(k)]];
  return sum / mesh.nodesPerElement();
}

void FlowCoefficient::check(const FaultFlowMesh& mesh, bool allowZero, const std::string& what,
                            const SourceLocation& where) const {
  const char* bound = allowZero ? ">= 0" : "> 0";
  const auto bad = [&](double x) { return !std::isfinite(x) || (allowZero ? x < 0.0 : x <= 0.0); };
  if (kind_ == Kind::constant) {
    if (bad(constant_))
      throw InputError(
          where, what + " must be a finite number " + bound + ", got " + formatNumber(constant_));
    return;
  }
  const bool nodes = kind_ == Kind::perNode;
  const Index expected = nodes ? mesh.numNodes() : mesh.numElements();
  const std::string item = nodes ? "node" : "element";
  if (values_.size() != expected)
    throw InputError(where, what + ": expected one value per " + item + " (" +
                                std::to_string(expected) + "), got " +
                                std::to_string(values_.size()));
  for (Index i = 0; i < expected; ++i)
    if (bad(values_[i]))
      throw InputError(where, what + " must be a finite number " + bound + " everywhere; " + item +
                                  " " + std::to_string(i) +
                                  (nodes ? " at " + pointText(mesh.point(i)) : std::string()) +
                                  " has " + formatNumber(values_[i]));
}

FaultFlowMesh::FaultFlowMesh(std::vector<Point> points, const std::vector<Segment>& segments,
                             SourceLocation where)
    : points_(std::move(points)) {
  for (const auto& s : segments) elements_.push_back({s[0], s[1], -1});
  build(2, where);
}

FaultFlowMesh::FaultFlowMesh(std::vector<Point> points, const std::vector<Triangle>& triangles,
                             SourceLocation where)
    : points_(std::move(points)), elements_(triangles) {
  build(3, where);
}

FaultFlowMesh FaultFlowMesh::fromCurves(const std::vector<Curve>& curves, SourceLocation where) {
  FaultFlowMesh mesh;
  // Size of the network, for the tolerance on the points of a shared id.
  Point lo = Point::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Curve& c : curves)
    for (const Point& p : c.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tolerance = 1e-9 * (curves.empty() ? 0.0 : (hi - lo).norm());
  std::map<long long, Index> local;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const Curve& curve = curves[c];
    const std::string name = "curve " + std::to_string(c);
    if (curve.id.size() != curve.points.size())
      throw InputError(where, name + ": " + std::to_string(curve.id.size()) + " ids for " +
                                  std::to_string(curve.points.size()) + " points");
    if (curve.id.size() < 2) throw InputError(where, name + ": a curve needs at least 2 nodes");
    std::vector<Index> nodes;
    for (std::size_t i = 0; i < curve.id.size(); ++i) {
      const auto [it, isNew] = local.emplace(curve.id[i], mesh.numNodes());
      if (isNew) {
        mesh.points_.push_back(curve.points[i]);
      } else if (!((mesh.point(it->second) - curve.points[i]).norm() <= tolerance)) {
        throw InputError(where, name + ": node id " + std::to_string(curve.id[i]) + " at " +
                                    pointText(curve.points[i]) + " was met before at " +
                                    pointText(mesh.point(it->second)));
      }
      nodes.push_back(it->second);
    }
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
      mesh.elements_.push_back({nodes[i], nodes[i + 1], -1});
    mesh.curveNodes_.push_back(std::move(nodes));
  }
  mesh.build(2, where);
  return mesh;
}

void FaultFlowMesh::build(int nodesPerElement, const SourceLocation& where) {
  nodesPerElement_ = nodesPerElement;
  const std::string kind = nodesPerElement == 2 ? "segment" : "triangle";
  if (elements_.empty()) throw InputError(where, "a fault flow mesh needs at least one " + kind);
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (!points_[i].allFinite())
      throw InputError(where, "point " + std::to_string(i) + " is not finite");
  // Degenerate elements: measure below round-off of the mesh's size.
  Point lo = points_.front(), hi = points_.front();
  for (const Point& p : points_) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double size = (hi - lo).norm();
  std::vector<int> used(points_.size(), 0);
  measure_.resize(elements_.size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const auto& n = elements_[e];
    for (int k = 0; k < nodesPerElement; ++k) {
      const Index i = n[static_cast<std::size_t>(k)];
      if (i < 0 || i >= numNodes())
        throw InputError(where, kind + " " + std::to_string(e) + ": point index " +
                                    std::to_string(i) + " out of range [0, " +
                                    std::to_string(numNodes()) + ")");
      ++used[static_cast<std::size_t>(i)];
    }
    const Point& a = point(n[0]);
    const Point& b = point(n[1]);
    double m = 0.0, scale = size;
    if (nodesPerElement == 2) {
      m = (b - a).norm();
    } else {
      m = 0.5 * (b - a).cross(point(n[2]) - a).norm();
      scale = size * size;
    }
    if (!(m > 1e-12 * scale))
      throw InputError(where, kind + " " + std::to_string(e) + " has " +
                                  (nodesPerElement == 2 ? "length " : "area ") + formatNumber(m) +
                                  " (its points coincide or are in a line)");
    measure_[e] = m;
  }
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i] == 0)
      throw InputError(where, "point " + std::to_string(i) + " at " + pointText(points_[i]) +
                                  " belongs to no " + kind);
}

double FaultFlowMesh::totalMeasure() const {
  double sum = 0.0;
  for (double m : measure_) sum += m;
  return sum;
}

double FaultFlowMesh::meanEdgeLength() const {
  double sum = 0.0;
  int count = 0;
  for (const auto& n : elements_)
    for (int k = 0; k < nodesPerElement_; ++k) {
      const int j = (k + 1) % nodesPerElement_;
      if (nodesPerElement_ == 2 && k == 1) break;
      sum += (point(n[static_cast<std::size_t>(j)]) - point(n[static_cast<std::size_t>(k)])).norm();
      ++count;
    }
  return sum / count;
}

std::vector<Index> FaultFlowMesh::edgeNodes() const {
  std::vector<char> edge(points_.size(), 0);
  if (nodesPerElement_ == 2) {
    std::vector<int> count(points_.size(), 0);
    for (const auto& n : elements_)
      ++count[static_cast<std::size_t>(n[0])], ++count[static_cast<std::size_t>(n[1])];
    for (std::size_t i = 0; i < count.size(); ++i) edge[i] = count[i] == 1;
  } else {
    std::map<std::pair<Index, Index>, int> count;
    for (const auto& n : elements_)
      for (int k = 0; k < 3; ++k) {
        const Index a = n[static_cast<std::size_t>(k)],
                    b = n[static_cast<std::size_t>((k + 1) % 3)];
        ++count[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [e, c] : count)
      if (c == 1)
        edge[static_cast<std::size_t>(e.first)] = edge[static_cast<std::size_t>(e.second)] = 1;
  }
  std::vector<Index> nodes;
  for (std::size_t i = 0; i < edge.size(); ++i)
    if (edge[i]) nodes.push_back(static_cast<Index>(i));
  return nodes;
}

Eigen::VectorXd FaultFlowMesh::lumpedMass(const FlowCoefficient& c) const {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(numNodes());
  for (Index e = 0; e < numElements(); ++e) {
    const double share = c.onElement(*this, e) * measure(e) / nodesPerElement_;
    for (int k = 0; k < nodesPerElement_; ++k) m[element(e)[static_cast<std::size_t>(k)]] += share;
  }
  return m;
}

Eigen::SparseMatrix<double> FaultFlowMesh::consistentMass(const FlowCoefficient& c) const {
  // ∫ φ_i φ_j = |e|/6 (1 + δ_ij) on a segment, |T|/12 (1 + δ_ij) on a triangle.
  const double denominator = nodesPerElement_ == 2 ? 6.0 : 12.0;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(elements_.size() * static_cast<std::size_t>(nodesPerElement_ * nodesPerElement_));
  for (Index e = 0; e < numElements(); ++e) {
    const double w = c.onElement(*this, e) * measure(e) / denominator;
    const auto& n = element(e);
    for (int i = 0; i < nodesPerElement_; ++i)
      for (int j = 0; j < nodesPerElement_; ++j)
        t.emplace_back(n[static_cast<std::size_t>(i)], n[static_cast<std::size_t>(j)],
                       i == j ? 2.0 * w : w);
  }
  Eigen::SparseMatrix<double> M(numNodes(), numNodes());
  M.setFromTriplets(t.begin(), t.end());
  return M;
}

Eigen::SparseMatrix<double> FaultFlowMesh::stiffness(const FlowCoefficient& kappa) const {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(elements_.size() * static_cast<std::size_t>(nodesPerElement_ * nodesPerElement_));
  for (Index e = 0; e < numElements(); ++e) {
    const double k = kappa.onElement(*this, e);
    const auto& n = element(e);
    if (nodesPerElement_ == 2) {
      const double w = k / measure(e);
      t.emplace_back(n[0], n[0], w);
      t.emplace_back(n[1], n[1], w);
      t.emplace_back(n[0], n[1], -w);
      t.emplace_back(n[1], n[0], -w);
      continue;
    }
    // P1 on a triangle: ∇φ_i·∇φ_j |T| = (d_i·d_j)/(4|T|), d_i the edge opposite node i taken
    // around the triangle in one sense (d_0 = x_2 − x_1, d_1 = x_0 − x_2, d_2 = x_1 − x_0);
    // the three d sum to zero, so rows sum to zero exactly as the dot products are taken.
    Point d[3];
    for (int i = 0; i < 3; ++i)
      d[i] = point(n[static_cast<std::size_t>((i + 2) % 3)]) -
             point(n[static_cast<std::size_t>((i + 1) % 3)]);
    const double w = k / (4.0 * measure(e));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        t.emplace_back(n[static_cast<std::size_t>(i)], n[static_cast<std::size_t>(j)],
                       w * d[i].dot(d[j]));
  }
  Eigen::SparseMatrix<double> A(numNodes(), numNodes());
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

FaultFlowMesh::Location FaultFlowMesh::locate(const Point& x) const {
  Location best;
  best.distance = std::numeric_limits<double>::infinity();
  for (Index e = 0; e < numElements(); ++e) {
    const auto& n = element(e);
    std::array<double, 3> w{};
    if (nodesPerElement_ == 2) {
      const auto s = segmentWeights(x, point(n[0]), point(n[1]));
      w = {s[0], s[1], 0.0};
    } else {
      w = triangleWeights(x, point(n[0]), point(n[1]), point(n[2]));
    }
    Point closest = Point::Zero();
    for (int k = 0; k < nodesPerElement_; ++k)
      closest += w[static_cast<std::size_t>(k)] * point(n[static_cast<std::size_t>(k)]);
    const double d = (x - closest).norm();
    if (d < best.distance) {
      best.element = e;
      best.weight = w;
      best.closest = closest;
      best.distance = d;
    }
  }
  return best;
}

Index FaultFlowMesh::nearestNode(const Point& x, double* distance) const {
  Index best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < numNodes(); ++i) {
    const double d = (point(i) - x).norm();
    if (d < bestDistance) best = i, bestDistance = d;
  }
  if (distance) *distance = bestDistance;
  return best;
}

}  // namespace friction
