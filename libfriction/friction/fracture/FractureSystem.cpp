// The finite-element SlipResponse: lifting of the imposed jump (52), one factorisation, and
// traction recovery from the split residual (53). See FractureSystem.hpp.
#include "friction/fracture/FractureSystem.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "friction/core/Assert.hpp"
#include "friction/core/Parallel.hpp"
#include "friction/core/StopRequest.hpp"
#include "friction/fe/Simplex.hpp"
#include "friction/fracture/SignConventions.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// A frame vector as a 3-vector: z = 0 for a 2D one.
template <class V>
Eigen::Vector3d frameVector(const V& v) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (Eigen::Index c = 0; c < v.size(); ++c) w[c] = v[c];
  return w;
}

Eigen::SparseMatrix<double> fromTriplets(Index rows, Index cols, const Triplets& t) {
  Eigen::SparseMatrix<double> m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

// The unsplit mesh: the original points, triangles and boundary patches renumbered through
// the split mesh's origin map. Its stiffness is K = Pᵀ K_split P (docs/method.md §4).
Mesh unsplitMeshOf(const SplitMesh& s) {
  Mesh m;
  m.source = s.mesh.source;
  m.format = s.mesh.format;
  const Index n = s.numOriginalPoints();
  m.dim = s.mesh.dim;
  m.points.assign(s.mesh.points.begin(), s.mesh.points.begin() + n);
  m.cellVertices = s.mesh.cellVertices;
  for (Index& v : m.cellVertices) v = s.origin[v];
  m.cellRegion = s.mesh.cellRegion;
  m.facetVertices = s.mesh.facetVertices;
  for (Index& v : m.facetVertices) v = s.origin[v];
  m.facetLabel = s.mesh.facetLabel;
  m.labelNames = s.mesh.labelNames;
  m.regionNames = s.mesh.regionNames;
  return m;
}

}  // namespace

FractureSystem::FractureSystem(const SplitMesh& split, int degree, const MaterialMap& materials)
    : split_(split),
      materials_(materials),
      dim_(split.mesh.dim),
      unsplitMesh_(unsplitMeshOf(split)) {
  FRICTION_ASSERT(dim_ == 2 || dim_ == 3, "a 2D or 3D split mesh");
  splitSpace_ = std::make_unique<LagrangeSpace>(split_.mesh, degree);
  unsplitSpace_ = std::make_unique<LagrangeSpace>(unsplitMesh_, degree);
  splitAssembler_ = std::make_unique<ElasticityAssembler>(*splitSpace_, materials_);
  unsplitAssembler_ = std::make_unique<ElasticityAssembler>(*unsplitSpace_, materials_);
  dirichlet_ = std::make_unique<DirichletConditions>(*unsplitSpace_);

  // P: split node -> unsplit node, read off cell by cell (same cells, same local order).
  std::vector<Index> toUnsplit(splitSpace_->numNodes(), -1);
  for (Index c = 0; c < splitSpace_->numCells(); ++c) {
    const NodeList s = splitSpace_->cellNodes(c), u = unsplitSpace_->cellNodes(c);
    for (int k = 0; k < s.size; ++k) toUnsplit[s[k]] = u[k];
  }
  Triplets pt;
  for (Index i = 0; i < splitSpace_->numNodes(); ++i) {
    FRICTION_ASSERT(toUnsplit[i] >= 0, "every split node belongs to a cell");
    for (int c = 0; c < dim_; ++c)
      pt.emplace_back(splitSpace_->dof(i, c), unsplitSpace_->dof(toUnsplit[i], c), 1.0);
  }
  P_ = fromTriplets(splitSpace_->numDofs(), unsplitSpace_->numDofs(), pt);

  if (dim_ == 2)
    controlNodes2D(degree);
  else
    controlNodes3D(degree);
  consistent_ = dim_ == 3 && degree == 2;
  const Index n = size();

  // L: ±j/2 on the copies; at junctions, the sectors' coefficients (controlNodes2D).
  Triplets lt;
  for (const LiftEntry& e : junctionLift_)
    for (int c = 0; c < dim_; ++c)
      lt.emplace_back(splitSpace_->dof(e.copy, c), dim_ * e.node + c, e.coefficient);
  for (Index k = 0; k < n; ++k) {
    if (nodes_[k].tip || (!atJunction_.empty() && atJunction_[k])) continue;
    for (int c = 0; c < dim_; ++c) {
      lt.emplace_back(splitSpace_->dof(nodes_[k].plus, c), dim_ * k + c, 0.5);
      lt.emplace_back(splitSpace_->dof(nodes_[k].minus, c), dim_ * k + c, -0.5);
    }
  }
  L_ = fromTriplets(splitSpace_->numDofs(), dim_ * n, lt);
  slip_ = Eigen::VectorXd::Zero(blockSize() * n);
  loadUnsplit_ = Eigen::VectorXd::Zero(unsplitSpace_->numDofs());
  sigmaLoad_ = Eigen::VectorXd::Zero(dim_ * n);
}

ControlNode FractureSystem::vertexNode(int f, const FractureGeometry& g, Index i) const {
  ControlNode v;
  v.fracture = f;
  v.plus = g.plus[i];
  v.minus = g.minus[i];
  v.position = split_.mesh.points[g.plus[i]];
  v.x = v.position.head<2>();
  return v;
}

void FractureSystem::controlNodes2D(int degree) {
  const int nf = static_cast<int>(split_.fractures.size());
  // The copies the two triangles at each fracture edge (i, i + 1) use: plus of i, plus of
  // i + 1, minus of i, minus of i + 1. Away from junctions they are the nodes' plus and minus;
  // at a crossing they depend on the edge (a sector of each side).
  const auto topology = unsplitMesh_.topology();
  std::vector<std::vector<std::array<Index, 4>>> edgeCopies(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const FractureGeometry& g = split_.fractures[f];
    for (Index i = 0; i + 1 < g.numNodes(); ++i) {
      const Index v = g.node[i], w = g.node[i + 1];
      std::array<Index, 4> copies{g.plus[i], g.plus[i + 1], g.minus[i], g.minus[i + 1]};
      const Index side = topology->findFacet({v, w});
      const Vector2 normal =
          normalFromTangent(unsplitMesh_.points[w].head<2>() - unsplitMesh_.points[v].head<2>());
      for (int c = 0; side >= 0 && c < topology->numCellsOf(side); ++c) {
        const Index t = topology->cellOf(side, c).cell;
        const auto unsplit = unsplitMesh_.cell(t);
        const auto splitCell = split_.mesh.cell(t);
        for (int k = 0; k < 3; ++k) {
          const Index x = unsplit[k];
          if (x == v || x == w) continue;
          const bool plus =
              (unsplitMesh_.points[x].head<2>() - unsplitMesh_.points[v].head<2>()).dot(normal) < 0;
          for (int l = 0; l < 3; ++l) {
            if (unsplit[l] == v) copies[plus ? 0 : 2] = splitCell[l];
            if (unsplit[l] == w) copies[plus ? 1 : 3] = splitCell[l];
          }
        }
      }
      edgeCopies[f].push_back(copies);
    }
  }
  // Fractures through each node: a node of several is a junction.
  std::map<Index, std::vector<std::pair<int, Index>>> fracturesAt;
  for (int f = 0; f < nf; ++f)
    for (Index i = 0; i < split_.fractures[f].numNodes(); ++i)
      fracturesAt[split_.fractures[f].node[i]].push_back({f, i});

  // Control nodes in arclength order: vertices, and for P2 the edge midpoints between them. A
  // node joined to an earlier fracture is that fracture's control node.
  std::vector<std::vector<Index>> controlOf(static_cast<std::size_t>(nf));
  std::vector<std::vector<std::pair<int, Index>>> weightFrom;  // (fracture, copy) per node
  std::vector<std::vector<std::array<Index, 2>>> plusEdges(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const FractureGeometry& g = split_.fractures[f];
    controlOf[f].assign(static_cast<std::size_t>(g.numNodes()), -1);
    for (Index i = 0; i < g.numNodes(); ++i) {
      std::vector<std::pair<int, Index>> from;
      if (i > 0) from.push_back({f, edgeCopies[f][i - 1][1]});
      if (i + 1 < g.numNodes() && (i == 0 || edgeCopies[f][i][0] != edgeCopies[f][i - 1][1]))
        from.push_back({f, edgeCopies[f][i][0]});
      bool skip = false;
      if (g.kind[i] == FractureNodeKind::joined)
        for (const auto& [other, j] : fracturesAt[g.node[i]]) {
          if (other == f) continue;
          if (other < f) {
            controlOf[f][i] = controlOf[other][j];
            skip = true;
          } else {  // the other's edge at the node adds its share of Γ's weight here
            const auto& e = edgeCopies[other];
            from.push_back({other, j == 0 ? e[0][0] : e[static_cast<std::size_t>(j) - 1][1]});
          }
        }
      if (!skip) {
        ControlNode v = vertexNode(f, g, i);
        v.normal = frameVector(g.normal[i]);
        v.tangent[0] = frameVector(g.tangent[i]);
        v.arclength = g.arclength[i];
        v.junction = g.kind[i] == FractureNodeKind::abutting;
        v.tip = g.kind[i] == FractureNodeKind::tip || v.junction;
        controlOf[f][i] = static_cast<Index>(nodes_.size());
        nodes_.push_back(v);
        weightFrom.push_back(from);
      }
      if (i + 1 == g.numNodes()) break;
      const std::array<Index, 4>& e = edgeCopies[f][i];
      plusEdges[f].push_back({e[0], e[1]});
      if (degree == 2) {
        ControlNode m;
        m.fracture = f;
        m.plus = splitSpace_->midpointNode(e[0], e[1]);
        m.minus = splitSpace_->midpointNode(e[2], e[3]);
        m.position = splitSpace_->point(m.plus);
        m.x = m.position.head<2>();
        const Vector2 d =
            (split_.mesh.points[g.plus[i + 1]].head<2>() - split_.mesh.points[g.plus[i]].head<2>());
        const Vector2 t = d.normalized();
        m.tangent[0] = frameVector(t);
        m.normal = frameVector(normalFromTangent(t));
        m.arclength = 0.5 * (g.arclength[i] + g.arclength[i + 1]);
        nodes_.push_back(m);
        weightFrom.push_back({{f, m.plus}});
      }
    }
  }
  // Lumped mass of Γ: trapezoid (P1) or Simpson (P2) weights of each fracture's ⁺-side edges,
  // summed at a node over the copies its edges use (one away from junctions).
  std::vector<Eigen::VectorXd> w;
  for (int f = 0; f < nf; ++f) w.push_back(splitAssembler_->lumpedEdgeMass(plusEdges[f]));
  weights_.resize(size());
  for (Index k = 0; k < size(); ++k) {
    weights_[k] = 0;
    for (const auto& [f, copy] : weightFrom[k]) weights_[k] += w[f][copy];
  }

  // Junctions: each fracture edge at the node separates two sectors, by the jump of its
  // fracture's control node there (none where that node is held).
  atJunction_.assign(static_cast<std::size_t>(size()), 0);
  for (const auto& [node, list] : fracturesAt) {
    if (list.size() < 2) continue;
    std::vector<JunctionBranch> branches;
    for (const auto& [f, i] : list) {
      const Index k = controlOf[f][i];
      atJunction_[k] = 1;
      const bool held = nodes_[k].tip;
      // The control node's own Ω⁺ copy at this node (its first edge's), to orient the edges.
      const FractureGeometry& g = split_.fractures[f];
      for (int side = 0; side < 2; ++side) {
        const Index e = side == 0 ? i - 1 : i;  // the edge (i − 1, i) or (i, i + 1)
        if (e < 0 || e + 1 >= g.numNodes()) continue;
        const std::array<Index, 4>& c = edgeCopies[f][e];
        const Index plusCopy = side == 0 ? c[1] : c[0], minusCopy = side == 0 ? c[3] : c[2];
        const double sign = nodes_[k].fracture == f || held
                                ? 1.0
                                : (std::find_if(branches.begin(), branches.end(),
                                                [&](const JunctionBranch& b) {
                                                  return b.node == k && b.plusCopy == plusCopy;
                                                }) != branches.end()
                                       ? 1.0
                                       : -1.0);
        branches.push_back({plusCopy, minusCopy, held ? Index(-1) : k, sign});
      }
    }
    const auto lifting = junctionLifting(branches);
    if (lifting.empty())
      throw InputError(split_.mesh.source,
                       "the split mesh's junction at " + formatPoint(split_.mesh.points[node], 2) +
                           " is not consistent (its fractures' jumps do not add up to zero "
                           "around it); split the mesh again with splitFractureNodes");
    for (const auto& [copy, terms] : lifting)
      for (const auto& [k, coefficient] : terms)
        if (coefficient != 0) junctionLift_.push_back({copy, k, coefficient});
  }
}

std::map<Index, std::map<Index, double>> FractureSystem::junctionLifting(
    const std::vector<JunctionBranch>& branches) const {
  // Potentials of the sectors, from the first one (0): crossing a branch from its minus to
  // its plus sector adds its jump. Around an inner node the branches close a cycle, and the
  // jumps must add up to zero: they do when each jump is carried by a fracture through the
  // node (both of its edges, with opposite roles) and the others are held — the splitter's
  // kinds guarantee it, and it is checked here.
  std::map<Index, std::map<Index, double>> potential;
  potential[branches.front().minusCopy];
  auto add = [](std::map<Index, double> p, Index k, double s) {
    if (k >= 0) p[k] += s;
    return p;
  };
  auto same = [](const std::map<Index, double>& a, const std::map<Index, double>& b) {
    std::map<Index, double> d = a;
    for (const auto& [k, v] : b) d[k] -= v;
    for (const auto& [k, v] : d)
      if (v != 0) return false;
    return true;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (const JunctionBranch& b : branches) {
      const bool hasPlus = potential.count(b.plusCopy), hasMinus = potential.count(b.minusCopy);
      if (hasMinus && !hasPlus) {
        potential[b.plusCopy] = add(potential[b.minusCopy], b.node, b.sign);
        changed = true;
      } else if (hasPlus && !hasMinus) {
        potential[b.minusCopy] = add(potential[b.plusCopy], b.node, -b.sign);
        changed = true;
      } else if (hasPlus && hasMinus &&
                 !same(potential[b.plusCopy], add(potential[b.minusCopy], b.node, b.sign))) {
        return {};  // the jumps around the node do not add up to zero
      }
    }
  }
  // Mean zero over the copies: away from junctions this is ±j/2 on the two sides.
  std::map<Index, double> mean;
  for (const auto& [copy, p] : potential)
    for (const auto& [k, v] : p) mean[k] += v / static_cast<double>(potential.size());
  for (auto& [copy, p] : potential)
    for (const auto& [k, m] : mean) p[k] -= m;
  return potential;
}

void FractureSystem::controlNodes3D(int degree) {
  // Where fault surfaces meet (a node of several fractures; in P2 also the mid-edge node of an
  // edge of several): the rules of 2D junctions per node. A fracture passing through keeps a
  // free control node whose jump moves the sectors on its ⁺ side against those on its ⁻ side;
  // one ending where another passes, or with two or more others, is held at zero; two ending
  // together (joined, no other there) share one control node, the first-listed fracture's,
  // with the normal of the two as one surface (README "Intersections (3D)").
  const int nf = static_cast<int>(split_.fractures.size());
  std::map<Index, std::vector<std::pair<int, Index>>> fracturesAt;  // node -> (fracture, its node)
  for (int f = 0; f < nf; ++f)
    for (Index i = 0; i < split_.fractures[f].numNodes(); ++i)
      fracturesAt[split_.fractures[f].node[i]].push_back({f, i});
  for (auto it = fracturesAt.begin(); it != fracturesAt.end();)
    it = it->second.size() > 1 ? std::next(it) : fracturesAt.erase(it);
  meet_ = !fracturesAt.empty();
  const auto topology = unsplitMesh_.topology();

  // The right-hand normal (b − a) × (c − a) of an oriented triangle: twice its area times n_Γ.
  const auto cross = [&](const std::array<Index, 3>& t) {
    const Point& a = unsplitMesh_.points[t[0]];
    return Point((unsplitMesh_.points[t[1]] - a).cross(unsplitMesh_.points[t[2]] - a));
  };
  // The copies of node p (q == p) or of the mid-edge node of p–q in the tetrahedra on the Ω⁺
  // (first) and Ω⁻ side of fracture f's triangle t; −1 where a side has none.
  const auto copiesAcross = [&](const std::array<Index, 3>& t, Index p, Index q) {
    const Point& a = unsplitMesh_.points[t[0]];
    const Point normal = cross(t);
    const Index side = topology->findFacet({t[0], t[1], t[2]});
    std::array<Index, 2> pm{-1, -1};
    for (int c = 0; side >= 0 && c < topology->numCellsOf(side); ++c) {
      const Index cell = topology->cellOf(side, c).cell;
      const auto unsplit = unsplitMesh_.cell(cell);
      const auto splitCell = split_.mesh.cell(cell);
      Index cp = -1, cq = -1;
      bool plus = false;
      for (int l = 0; l < 4; ++l) {
        if (unsplit[l] == p) cp = splitCell[l];
        if (unsplit[l] == q) cq = splitCell[l];
        if (unsplit[l] != t[0] && unsplit[l] != t[1] && unsplit[l] != t[2])
          plus = (unsplitMesh_.points[unsplit[l]] - a).dot(normal) < 0;
      }
      (plus ? pm[0] : pm[1]) = p == q ? cp : splitSpace_->midpointNode(cp, cq);
    }
    return pm;
  };

  // P2: the edges of several fractures' triangles (the intersection curves' edges), per
  // fracture the number of its triangles there; and the edges on the outer boundary.
  using Edge = std::array<Index, 2>;
  const auto edgeOf = [](Index p, Index q) { return Edge{std::min(p, q), std::max(p, q)}; };
  std::map<Edge, std::map<int, int>> curveEdges;
  std::map<Edge, std::map<int, int>> runs;  // per fracture, +1 if a triangle runs it low to high
  std::set<Edge> outer;
  if (meet_) {
    for (int f = 0; f < nf; ++f)
      for (const auto& t : split_.fractures[f].triangles)
        for (int e = 0; e < 3; ++e) {
          const Edge edge = edgeOf(t[e], t[(e + 1) % 3]);
          ++curveEdges[edge][f];
          runs[edge][f] = t[e] < t[(e + 1) % 3] ? 1 : -1;
        }
    for (auto it = curveEdges.begin(); it != curveEdges.end();)
      it = it->second.size() > 1 ? std::next(it) : curveEdges.erase(it);
    for (Index s = 0; s < topology->numFacets(); ++s)
      if (topology->isBoundary(s))
        for (int k = 0; k < 3; ++k)
          outer.insert(edgeOf(topology->facetVertex(s, k), topology->facetVertex(s, (k + 1) % 3)));
  }
  // The ends of the lines where two fractures end together (joined) inside the body: on the
  // common tip line of the two, their tips are one node too.
  // Along such a line the two are one surface oriented alike where their triangles run the
  // common edge in opposite directions (orientedAlike: +1, else −1).
  std::map<Index, Edge> joinedLine;  // node -> an edge of the line there
  for (const auto& [edge, uses] : curveEdges)
    if (uses.size() == 2 && uses.begin()->second == 1 && uses.rbegin()->second == 1 &&
        !outer.count(edge))
      for (Index v : edge) joinedLine.emplace(v, edge);
  const auto orientedAlike = [&](const Edge& edge) {
    const auto& r = runs.at(edge);
    return r.begin()->second == r.rbegin()->second ? -1.0 : 1.0;
  };
  // What fracture f does on curve edge e, as the splitter's kinds at a vertex: passes (two of
  // its triangles there, or an edge on the outer boundary: free), joined (it ends there with
  // exactly one other fracture, which ends there too) or held (abutting).
  enum class Role { passes, joined, held };
  const auto roleOn = [&](const Edge& e, int f) {
    const auto& uses = curveEdges.at(e);
    const auto passes = [&](int o) { return uses.at(o) == 2 || outer.count(e) > 0; };
    if (passes(f)) return Role::passes;
    bool anotherPasses = false;
    for (const auto& [o, count] : uses) anotherPasses = anotherPasses || (o != f && passes(o));
    return !anotherPasses && uses.size() == 2 ? Role::joined : Role::held;
  };

  // The control nodes. A node joined to an earlier fracture's is that one's (joinedTo: the
  // node, the sum of this fracture's right-hand normals there, its ⁺ copy).
  struct Joined {
    Index node;
    Point normalSum;
    double sign;  ///< orientedAlike
  };
  std::vector<Joined> joinedTo;
  std::map<Index, Point> normalSum;  // of the joined nodes' owners
  vertexControl_.assign(static_cast<std::size_t>(nf), {});
  std::vector<std::map<Edge, Index>> midControl(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const FractureGeometry& g = split_.fractures[f];
    std::vector<Index> local(static_cast<std::size_t>(split_.numOriginalPoints()), -1);
    // Per node of g (and mid-edge node), −1 where it is an earlier fracture's joined node
    // oriented against g: its Σ there is the opposite of g's (the P2 mass, buildRecovery).
    std::vector<double> vertexSign(static_cast<std::size_t>(g.numNodes()), 1.0);
    std::map<Edge, double> midSign;
    for (Index i = 0; i < g.numNodes(); ++i) local[g.node[i]] = i;
    const auto vertexSum = [&](Index v) {
      Point s = Point::Zero();
      for (const auto& t : g.triangles)
        if (t[0] == v || t[1] == v || t[2] == v) s += cross(t);
      return s;
    };
    std::vector<Index>& controlOf = vertexControl_[f];
    for (Index i = 0; i < g.numNodes(); ++i) {
      const auto at = fracturesAt.find(g.node[i]);
      const bool sharedTip = g.kind[i] == FractureNodeKind::tip && at != fracturesAt.end() &&
                             at->second.size() == 2 && joinedLine.count(g.node[i]) > 0 &&
                             split_.fractures[at->second[0].first].kind[at->second[0].second] ==
                                 split_.fractures[at->second[1].first].kind[at->second[1].second];
      if (g.kind[i] == FractureNodeKind::joined || sharedTip) {
        const auto& [owner, j] = at->second.front();
        if (owner != f) {
          const Index k = vertexControl_[owner][j];
          controlOf.push_back(k);
          const auto line = joinedLine.find(g.node[i]);
          vertexSign[i] = line == joinedLine.end() ? 1.0 : orientedAlike(line->second);
          joinedTo.push_back({k, vertexSum(g.node[i]), vertexSign[i]});
          continue;
        }
        normalSum[static_cast<Index>(nodes_.size())] = vertexSum(g.node[i]);
      }
      ControlNode v = vertexNode(f, g, i);
      v.normal = g.normal[i];
      v.tangent = tangentBasis(v.normal);
      v.junction = g.kind[i] == FractureNodeKind::abutting;
      v.tip = g.kind[i] == FractureNodeKind::tip || v.junction;
      controlOf.push_back(static_cast<Index>(nodes_.size()));
      nodes_.push_back(v);
    }
    triangleNodes_.emplace_back();
    if (degree != 2) {
      for (const auto& t : g.triangles)
        triangleNodes_.back().push_back(
            {controlOf[local[t[0]]], controlOf[local[t[1]]], controlOf[local[t[2]]], -1, -1, -1});
      continue;
    }
    // Each edge once, by ascending (smaller, larger) end: its midpoint's normal sums the
    // right-hand normals (b − a) × (c − a) (twice the area times n_Γ) of its triangles.
    std::map<Edge, Point> edgeNormal;
    std::map<Edge, std::size_t> firstTriangle;
    for (std::size_t ti = 0; ti < g.triangles.size(); ++ti) {
      const auto& t = g.triangles[ti];
      const Point& a = split_.mesh.points[t[0]];
      const Point an = (split_.mesh.points[t[1]] - a).cross(split_.mesh.points[t[2]] - a);
      for (int e = 0; e < 3; ++e) {
        const Edge edge = edgeOf(t[e], t[(e + 1) % 3]);
        edgeNormal.emplace(edge, Point::Zero()).first->second += an;
        firstTriangle.emplace(edge, ti);
      }
    }
    for (const auto& [edge, sum] : edgeNormal) {
      const Index a = local[edge[0]], b = local[edge[1]];
      FRICTION_ASSERT(a >= 0 && b >= 0, "a fault triangle's vertices are fracture nodes");
      ControlNode m;
      m.fracture = f;
      if (meet_ && (fracturesAt.count(edge[0]) || fracturesAt.count(edge[1]))) {
        // Next to an intersection the sectors of its ends depend on the triangle: the copies
        // of the tetrahedra on either side of one of the fracture's triangles at the edge.
        const auto pm = copiesAcross(g.triangles[firstTriangle.at(edge)], edge[0], edge[1]);
        m.plus = pm[0];
        m.minus = pm[1];
      } else {
        m.plus = splitSpace_->midpointNode(g.plus[a], g.plus[b]);
        m.minus = splitSpace_->midpointNode(g.minus[a], g.minus[b]);
      }
      FRICTION_ASSERT(m.plus >= 0 && m.minus >= 0, "a fault edge's mid-edge node on each side");
      const Role role = curveEdges.count(edge) ? roleOn(edge, f) : Role::passes;
      if (role == Role::joined) {
        int owner = f;
        for (const auto& [o, count] : curveEdges.at(edge)) owner = std::min(owner, o);
        if (owner != f) {
          const Index k = midControl[owner].at(edge);
          midControl[f][edge] = k;
          midSign[edge] = orientedAlike(edge);
          joinedTo.push_back({k, sum, midSign[edge]});
          continue;
        }
        normalSum[static_cast<Index>(nodes_.size())] = sum;
      }
      m.position = splitSpace_->point(m.plus);
      m.x = m.position.head<2>();
      m.normal = sum.normalized();
      m.tangent = tangentBasis(m.normal);
      // Single where both sides share the edge: on the tip line. Held where the fracture
      // ends on another.
      m.junction = role == Role::held;
      m.tip = m.plus == m.minus || m.junction;
      midControl[f][edge] = static_cast<Index>(nodes_.size());
      nodes_.push_back(m);
      if (curveEdges.count(edge)) {
        edgeCode_.resize(nodes_.size(), 0);
        edgeCode_.back() = role == Role::passes ? 1 : role == Role::held ? 2 : 3;
      }
    }
    // The six control nodes of each triangle (for the recovery's extension, factor()).
    for (const auto& t : g.triangles) {
      std::array<Index, 6> c{};
      std::array<double, 6> sign{1, 1, 1, 1, 1, 1};
      for (int e = 0; e < 3; ++e) {
        const Edge edge = edgeOf(t[e], t[(e + 1) % 3]);
        c[e] = controlOf[local[t[e]]];
        c[3 + e] = midControl[f].at(edge);
        sign[e] = vertexSign[local[t[e]]];
        const auto it = midSign.find(edge);
        if (it != midSign.end()) sign[3 + e] = it->second;
      }
      faultTriangles_.push_back(c);
      faultTriangleSign_.push_back(sign);
      triangleNodes_.back().push_back(c);
      faultTriangleArea_.push_back(0.5 * cross(t).norm());
    }
  }
  if (!edgeCode_.empty()) edgeCode_.resize(nodes_.size(), 0);
  // A joined node's frame is that of the two fractures as one surface: the sum of both
  // fractures' right-hand normals, the second's turned where its Ω⁺ is the first's Ω⁻.
  for (const Joined& j : joinedTo) normalSum.at(j.node) += j.sign * j.normalSum;
  for (const auto& [k, sum] : normalSum) {
    nodes_[k].normal = sum.normalized();
    nodes_[k].tangent = tangentBasis(nodes_[k].normal);
  }

  // Lumped mass of Γ from the ⁺-side triangles (the ⁺ copies keep the unsplit numbers):
  // 1/3 of the area per vertex (P1); A/12 per vertex and A/4 per mid-edge node (P2,
  // P1-iso-P2 nodal quadrature: positive, so M⁻¹ exists and the law holds node by node).
  weights_.resize(size());
  if (!meet_) {
    std::vector<Index> facets;
    for (const FractureGeometry& g : split_.fractures)
      for (const auto& t : g.triangles) facets.insert(facets.end(), t.begin(), t.end());
    const Eigen::VectorXd w = splitAssembler_->lumpedFacetMass(facets);
    for (Index k = 0; k < size(); ++k) weights_[k] = w[nodes_[k].plus];
    return;
  }
  // Fault surfaces meet: each fracture's weights from its own triangles (a joined node: both
  // fractures'), P1 at the unsplit node numbers (the triangles' vertices; a ⁺ copy there may
  // be another sector's number), P2 on the control nodes of each triangle.
  weights_.setZero();
  if (degree == 1) {
    for (int f = 0; f < nf; ++f) {
      const FractureGeometry& g = split_.fractures[f];
      std::vector<Index> facets;
      for (const auto& t : g.triangles) facets.insert(facets.end(), t.begin(), t.end());
      const Eigen::VectorXd w = splitAssembler_->lumpedFacetMass(facets);
      for (Index i = 0; i < g.numNodes(); ++i) weights_[vertexControl_[f][i]] += w[g.node[i]];
    }
  } else {
    const double* w = facetLumpedMass<3>(2);
    for (std::size_t t = 0; t < faultTriangles_.size(); ++t)
      for (int i = 0; i < 6; ++i) weights_[faultTriangles_[t][i]] += w[i] * faultTriangleArea_[t];
  }

  // Each fault triangle through an intersection node separates two of its sectors: the copies
  // of the node in the tetrahedra on the triangle's Ω⁺ and Ω⁻ sides; in P2 likewise the
  // mid-edge nodes of its edges on the curves. The jumps of the fractures' control nodes
  // there (none where held) give the sectors' displacements; a joined node's second fracture
  // carries the first's jump, turned where its Ω⁺ is the first's Ω⁻.
  atJunction_.assign(static_cast<std::size_t>(size()), 0);
  const auto branch = [&](int f, Index k, const std::array<Index, 2>& pm,
                          const std::string& where) {
    if (pm[0] < 0 || pm[1] < 0)
      throw InputError(split_.mesh.source,
                       "the split mesh's fault '" + split_.fractures[f].name + "' at " + where +
                           " has a triangle without a tetrahedron on each side; split the "
                           "mesh again with splitFractureNodes");
    atJunction_[k] = 1;
    const double sign = nodes_[k].fracture == f || pm[0] == nodes_[k].plus ? 1.0 : -1.0;
    return JunctionBranch{pm[0], pm[1], nodes_[k].tip ? Index(-1) : k, sign};
  };
  std::map<Index, std::vector<JunctionBranch>> branchesAt;
  std::map<Edge, std::vector<JunctionBranch>> branchesOn;
  for (int f = 0; f < nf; ++f) {
    const FractureGeometry& g = split_.fractures[f];
    std::map<Index, Index> local;
    for (Index i = 0; i < g.numNodes(); ++i)
      if (fracturesAt.count(g.node[i])) local[g.node[i]] = i;
    for (const auto& t : g.triangles) {
      for (Index v : t) {
        const auto at = local.find(v);
        if (at == local.end()) continue;
        branchesAt[v].push_back(branch(f, vertexControl_[f][at->second], copiesAcross(t, v, v),
                                       formatPoint(unsplitMesh_.points[v], 3)));
      }
      for (int e = 0; e < 3 && degree == 2; ++e) {
        const Edge edge = edgeOf(t[e], t[(e + 1) % 3]);
        if (!curveEdges.count(edge)) continue;
        branchesOn[edge].push_back(
            branch(f, midControl[f].at(edge), copiesAcross(t, edge[0], edge[1]),
                   "the midpoint of " + formatPoint(unsplitMesh_.points[edge[0]], 3) + "-" +
                       formatPoint(unsplitMesh_.points[edge[1]], 3)));
      }
    }
  }
  const auto lift = [&](const std::vector<JunctionBranch>& branches, const std::string& where) {
    const auto lifting = junctionLifting(branches);
    if (lifting.empty())
      throw InputError(split_.mesh.source,
                       "the split mesh's intersection node " + where +
                           " is not consistent (its fractures' jumps do not add up to zero "
                           "around it); split the mesh again with splitFractureNodes");
    for (const auto& [copy, terms] : lifting)
      for (const auto& [k, coefficient] : terms)
        if (coefficient != 0) junctionLift_.push_back({copy, k, coefficient});
  };
  for (const auto& [node, branches] : branchesAt)
    lift(branches, formatPoint(split_.mesh.points[node], 3));
  for (const auto& [edge, branches] : branchesOn)
    lift(branches, "at the midpoint of " + formatPoint(split_.mesh.points[edge[0]], 3) + "-" +
                       formatPoint(split_.mesh.points[edge[1]], 3));
}

std::vector<std::vector<Eigen::Index>> FractureSystem::nodeGraph() const {
  const Index n = size();
  std::vector<std::vector<Eigen::Index>> graph(static_cast<std::size_t>(n));
  const auto link = [&graph](Index a, Index b) {
    if (a == b) return;
    auto& ga = graph[static_cast<std::size_t>(a)];
    if (std::find(ga.begin(), ga.end(), b) != ga.end()) return;
    ga.push_back(b);
    graph[static_cast<std::size_t>(b)].push_back(a);
  };
  if (dim_ == 2) {  // arclength order along each fracture
    for (Index i = 0; i + 1 < n; ++i)
      if (nodes_[i].fracture == nodes_[i + 1].fracture) link(i, i + 1);
  } else if (!faultTriangles_.empty()) {  // P2: the six nodes of a triangle
    for (const auto& t : faultTriangles_)
      for (int a = 0; a < 6; ++a)
        for (int b = a + 1; b < 6; ++b) link(t[a], t[b]);
  } else {  // P1: each fracture's vertices (controlNodes3D)
    for (std::size_t f = 0; f < split_.fractures.size(); ++f) {
      const FractureGeometry& g = split_.fractures[f];
      std::map<Index, Index> local;
      for (Index i = 0; i < g.numNodes(); ++i) local[g.node[i]] = vertexControl_[f][i];
      for (const auto& t : g.triangles)
        for (int e = 0; e < 3; ++e) link(local.at(t[e]), local.at(t[(e + 1) % 3]));
    }
  }
  return graph;
}

void FractureSystem::setTangentBasis(Index node, const Eigen::Vector3d& t1) {
  FRICTION_ASSERT(dim_ == 3, "a choice of tangent basis exists in 3D only");
  ControlNode& v = nodes_[static_cast<std::size_t>(node)];
  FRICTION_ASSERT(std::abs(t1.norm() - 1) < 1e-12 && std::abs(t1.dot(v.normal)) < 1e-12,
                  "t1 is a unit vector of the tangent plane");
  v.tangent = {t1, v.normal.cross(t1)};
}

int FractureSystem::numHeldOnDirichlet() const {
  int c = 0;
  // A tip has no jump to hold (in 3D the tip line may run on a Dirichlet face).
  for (const auto& v : nodes_) c += v.onDirichlet && !v.tip;
  return c;
}

int FractureSystem::numPartlyHeldOnDirichlet() const {
  int c = 0;
  for (const auto& v : nodes_) c += v.heldComponent >= 0;
  return c;
}

FactorStatus FractureSystem::factor(const std::string& backend, bool withInterfaceOperator,
                                    const PhaseReport& phases, Ordering ordering,
                                    const MumpsMemory& memory) {
  assemble(backend, phases, ordering, memory);
  return factorAssembled(withInterfaceOperator);
}

bool FractureSystem::assemble(const std::string& backend, const PhaseReport& phases,
                              Ordering ordering, const MumpsMemory& memory) {
  assembled_ = false;
  phases_ = phases;
  ordering_ = ordering;
  Stopwatch clock;
  const auto report = [&](const std::string& phase) {
    const double seconds = clock.lap();
    if (phases) phases(phase, seconds);
  };
  const Index n = size();
  // A Dirichlet condition at a copy's unsplit node fixing the Cartesian component c forbids
  // the jump's component along e_c: the jump, tangential, is held along the projection of e_c
  // on the tangent plane (none if e_c is along n_Γ). Constraint directions spanning the
  // tangent plane (2D: any) hold the whole jump; in 3D directions all along one p (rollers)
  // hold only that component: the basis is turned so that t₂ ∥ p and the slip goes on along
  // t₁.
  const int kb = blockSize();
  mask_ = Eigen::VectorXd::Ones(n);
  componentMask_ = Eigen::VectorXd::Ones(kb * n);
  {
    // Row i of P holds one entry, at the unsplit dof of split dof i.
    const Eigen::SparseMatrix<double, Eigen::RowMajor> Pr = P_;
    for (Index i = 0; i < n; ++i) {
      ControlNode& v = nodes_[i];
      v.onDirichlet = false;
      v.heldComponent = -1;
      std::vector<Eigen::Vector3d> held;  // unit constraint directions in the tangent plane
      for (int c = 0; c < dim_; ++c) {
        Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(Pr,
                                                                       splitSpace_->dof(v.plus, c));
        if (!it || !dirichlet_->isFixed(static_cast<Index>(it.col()))) continue;
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        p[c] = 1;
        p -= p.dot(v.normal) * v.normal;
        if (p.norm() >= 1e-12) held.push_back(p.normalized());
      }
      bool spanning = dim_ == 2 && !held.empty();
      for (std::size_t a = 1; a < held.size() && !spanning; ++a)
        spanning = held[a].cross(held[0]).norm() >= 1e-12;
      if (spanning) {
        v.onDirichlet = true;
      } else if (!held.empty() && !v.tip) {
        for (int c = 0; c < kb && v.heldComponent < 0; ++c)
          if (std::abs(v.tangent[c].dot(held[0])) >= 1 - 1e-12) v.heldComponent = c;
        if (v.heldComponent < 0) {
          setTangentBasis(i, held[0].cross(v.normal).normalized());
          v.heldComponent = 1;
        }
        componentMask_[kb * i + v.heldComponent] = 0;
      }
      if (v.tip || v.onDirichlet) {
        mask_[i] = 0;
        for (int c = 0; c < kb; ++c) componentMask_[kb * i + c] = 0;
      }
    }
  }

  if (n > 0) {
    // The split stiffness is needed only for the lifting and the traction recovery: a case
    // without fractures never assembles it. And only its rows and columns at the fracture
    // copies are read (K_split L, E K_split): the cells that touch a copy give them whole, in
    // the order the whole assembly adds them, so the band of those cells is assembled.
    std::vector<char> copy(static_cast<std::size_t>(splitSpace_->numNodes()), 0);
    for (const ControlNode& v : nodes_) copy[v.plus] = copy[v.minus] = 1;
    for (const LiftEntry& e : junctionLift_) copy[e.copy] = 1;
    std::vector<char> band(static_cast<std::size_t>(splitSpace_->numCells()), 0);
    for (Index c = 0; c < splitSpace_->numCells(); ++c)
      for (Index node : splitSpace_->cellNodes(c))
        if (copy[node]) band[c] = 1;
    const Eigen::SparseMatrix<double> Ksplit = splitAssembler_->stiffness(band);
    ++numAssemblies_;
    B_ = P_.transpose() * (Ksplit * L_);
    // Rows of K_split at the copies, scaled: Σ_k = (r⁺_k − r⁻_k) / (2 w_k); 3D P2: Σ̃_k =
    // (r⁺_k − r⁻_k) / 2, and Σ from the consistent mass (solve()).
    // At junctions, E = W⁻¹ Lᵀ on the sectors: (R⁺ − R⁻) / (2 w) with R± the residuals summed
    // over the sectors on either side of a fracture through the node (its traction is the
    // same on both of its edges there; the other fractures' faces between those sectors
    // cancel in the sum).
    Triplets et;
    for (const LiftEntry& e : junctionLift_) {
      const double s = consistent_ ? 1.0 : 1.0 / weights_[e.node];
      for (int c = 0; c < dim_; ++c)
        et.emplace_back(dim_ * e.node + c, splitSpace_->dof(e.copy, c), s * e.coefficient);
    }
    for (Index k = 0; k < n; ++k) {
      // A single node has no two sides to compare.
      if (nodes_[k].tip || (!atJunction_.empty() && atJunction_[k])) continue;
      const double s = consistent_ ? 0.5 : 0.5 / weights_[k];
      for (int c = 0; c < dim_; ++c) {
        et.emplace_back(dim_ * k + c, splitSpace_->dof(nodes_[k].plus, c), s);
        et.emplace_back(dim_ * k + c, splitSpace_->dof(nodes_[k].minus, c), -s);
      }
    }
    const Eigen::SparseMatrix<double> E = fromTriplets(dim_ * n, splitSpace_->numDofs(), et);
    const Eigen::SparseMatrix<double> EK = E * Ksplit;
    Tx_ = EK * P_;
    Tj_ = EK * L_;
    Tf_ = -E;
    // The border of the stiffness in the variables (x, j): B = Pᵀ K_split L and
    // C = Lᵀ K_split L, on the jump dofs of the nodes that have two sides. Then
    // Σ = W⁻¹ (Bᵀ x + C j) (E = W⁻¹ Lᵀ), and with zero loads x_f = −K_ff⁻¹ B_f j, so
    // M Σ = (C − B_fᵀ K_ff⁻¹ B_f) j: the Schur complement is M·S.
    jumpDofs_.clear();
    for (Index k = 0; k < n; ++k)
      if (!nodes_[k].tip)
        for (int c = 0; c < dim_; ++c) jumpDofs_.push_back(dim_ * k + c);
    Triplets st;
    for (std::size_t a = 0; a < jumpDofs_.size(); ++a) st.emplace_back(jumpDofs_[a], a, 1.0);
    const Eigen::SparseMatrix<double> select =
        fromTriplets(dim_ * n, static_cast<Index>(jumpDofs_.size()), st);
    const Eigen::SparseMatrix<double> Lj = L_ * select;
    borderC_ = Lj.transpose() * (Ksplit * Lj);
    const Eigen::SparseMatrix<double> Bj = B_ * select;
    Triplets ft;
    Index row = 0;
    for (Index d = 0; d < unsplitSpace_->numDofs(); ++d)
      if (!dirichlet_->isFixed(d)) ft.emplace_back(row++, d, 1.0);
    borderB_ = fromTriplets(row, unsplitSpace_->numDofs(), ft) * Bj;
    report("assembly of the split stiffness at the fractures and the traction operators");
  } else {
    B_.resize(unsplitSpace_->numDofs(), 0);
    Tx_.resize(0, unsplitSpace_->numDofs());
    Tj_.resize(0, 0);
    Tf_.resize(0, splitSpace_->numDofs());
  }

  if (consistent_) {
    if (!buildRecovery()) return false;
    report("P2 fault tractions: the consistent mass of the fractures factored");
  }

  factor_ = std::make_unique<SparseFactor>(backend);
  factor_->setOrdering(ordering, dim_);
  if (memory.any()) factor_->setMumpsMemory(memory);
  // Several ranks sharing a backend that takes summands: each rank assembles its own cells (a
  // contiguous block of the mesh's numbering) and the backend adds the ranks' parts; the
  // products with K (the Dirichlet lifting, the equilibrium check) add them too.
  const bool own = parallel::size() > 1 && factor_->takesSummands();
  Eigen::SparseMatrix<double> K;
  if (own) {
    const Index cells = unsplitSpace_->numCells();
    const Index first = cells * parallel::rank() / parallel::size(),
                last = cells * (parallel::rank() + 1) / parallel::size();
    std::vector<char> mine(static_cast<std::size_t>(cells), 0);
    std::fill(mine.begin() + first, mine.begin() + last, 1);
    ownCells_ = last - first;
    K = unsplitAssembler_->stiffness(mine);
  } else {
    K = unsplitAssembler_->stiffness();
  }
  ++numAssemblies_;
  reduced_ = std::make_unique<ReducedSystem>(K, *dirichlet_);
  K = Eigen::SparseMatrix<double>();  // the reduced blocks hold what the run needs
  reduced_->setSummedOverRanks(own);
  report("assembly of the stiffness (" + std::to_string(unsplitSpace_->numDofs()) +
         " dofs) and the Dirichlet conditions taken out");
  summands_ = own;
  factor_->setSummedOverRanks(own);
  factor_->setPhaseReport(phases);
  assembled_ = true;
  return true;
}

bool FractureSystem::predictFactor(FactorAnalysis& predicted) {
  FRICTION_ASSERT(assembled_ && factor_, "predictFactor() after assemble()");
  return factor_->predict(reduced_->matrix(), predicted);
}

void FractureSystem::useBackend(const std::string& backend, const MumpsMemory& memory) {
  FRICTION_ASSERT(assembled_, "useBackend() after assemble()");
  if (factor_ && factor_->backend() == backend) return;
  factor_ = std::make_unique<SparseFactor>(backend);
  FRICTION_ASSERT(!summands_ || factor_->takesSummands(), "useBackend: the summands need one");
  factor_->setOrdering(factor_->takesOrdering() ? ordering_ : Ordering::automatic, dim_);
  if (memory.any()) factor_->setMumpsMemory(memory);
  factor_->setSummedOverRanks(summands_);
  factor_->setPhaseReport(phases_);
}

FactorStatus FractureSystem::factorAssembled(bool withInterfaceOperator) {
  if (!assembled_) return FactorStatus::failed;
  if (factor_->iterative()) {
    // The component of each free dof (interleaved: dof = dim · node + component), for a vector
    // multigrid hierarchy.
    std::vector<int> components;
    components.reserve(static_cast<std::size_t>(reduced_->matrix().rows()));
    for (Index d = 0; d < unsplitSpace_->numDofs(); ++d)
      if (!dirichlet_->isFixed(d)) components.push_back(static_cast<int>(d % dim_));
    factor_->setComponents(components, dim_);
    factor_->setIterativeTolerance(iterativeTolerance_);
  }
  const FactorStatus status = withInterfaceOperator && !jumpDofs_.empty()
                                  ? factor_->factorWithSchur(reduced_->matrix(), borderB_, borderC_)
                                  : factor_->factor(reduced_->matrix());
  if (status == FactorStatus::ok) restrictProducts();
  return status;
}

void FractureSystem::restrictProducts() {
  if (B_.cols() == 0 || factor_->iterative()) return;
  Stopwatch clock;
  // A product's right-hand side lives on B's rows, and its tractions read x on Tx's columns:
  // the band of unknowns at the fractures.
  Eigen::VectorXd band = Eigen::VectorXd::Zero(unsplitSpace_->numDofs());
  for (Index c = 0; c < B_.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B_, c); it; ++it) band[it.row()] = 1;
  for (Index c = 0; c < Tx_.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Tx_, c); it; ++it) band[it.col()] = 1;
  const Eigen::VectorXd onFree = reduced_->restrictToFree(band);
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < onFree.size(); ++i)
    if (onFree[i] != 0) rows.push_back(i);
  const SolveReach reach = factor_->restrictSolves(rows);
  if (reach.share < 0 || !phases_) return;
  std::ostringstream line;
  line << "the fractures' reach in the factor (" << rows.size()
       << " unknowns at the fractures; a product's back-substitution reads " << std::fixed
       << std::setprecision(1) << 100 * reach.share << " % of the factor's values, "
       << reach.supernodes << " of its " << reach.ofSupernodes << " supernodes)";
  phases_(line.str(), clock.lap());
}

void FractureSystem::setTractionOffset(const Eigen::VectorXd& sigmaN, const Eigen::VectorXd& tau) {
  offsetSigmaN_ = sigmaN;
  offsetTau_ = tau;
}

void FractureSystem::setStep(const Eigen::VectorXd& loadSplit,
                             const Eigen::VectorXd& accumulatedSlip) {
  loadUnsplit_ = P_.transpose() * loadSplit;
  sigmaLoad_ = Tf_ * loadSplit;
  slip_ = accumulatedSlip;
}

void FractureSystem::solve(const Eigen::VectorXd& j, bool withLoads, Eigen::VectorXd& sigma,
                           bool recover) {
  FRICTION_ASSERT(factor_ && factor_->ok(), "factor() before solving");
  const Eigen::VectorXd Bj = B_ * j;
  if (withLoads) {
    lastRhs_ = reduced_->rhs(Eigen::VectorXd(loadUnsplit_ - Bj), *dirichlet_);
    lastFree_ = factor_->solve(lastRhs_);
    x_ = reduced_->expand(lastFree_, *dirichlet_);
    lastJump_ = j;
    sigma = Tx_ * x_ + Tj_ * j;
    sigma += sigmaLoad_;
  } else {
    // The jump's own response: read on the fault only, so solved on the fault's reach where
    // the factor allows (restrictProducts()). x_ and lastJump_ stay the last primal solve's.
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dirichlet_->numFixed());
    const Eigen::VectorXd rhs = reduced_->rhs(Eigen::VectorXd(-Bj), zero);
    const Eigen::VectorXd x = reduced_->expand(factor_->solveRestricted(rhs), zero);
    sigma = Tx_ * x + Tj_ * j;
  }
  if (consistent_ && recover) {
    Eigen::MatrixXd s = sigma;
    applyRecovery(s, false);
    sigma = s.col(0);
  }
}

// 3D P2. Nodal values Σ_j of a traction field Σ_h = Σ_j Σ_j φ_j on Γ give
// (r⁺ − r⁻)_i / 2 = ∫_Γ Σ_h φ_i = Σ_j M_ij Σ_j, M the consistent mass of the P2 triangles.
// Lumping M (A/12 per vertex, A/4 per midpoint) does not invert this: the rows of M sum to
// ∫ φ_i = 0 at a vertex and A/3 at a midpoint, so a uniform Σ came back as 0 and 4/3 Σ. The
// equations are solved instead, on the rows R where (r⁺ − r⁻)/2 is the traction's moment
// alone: the free nodes. A tip has no two sides (r⁺ − r⁻ = 0 says nothing), and at a node
// held on a Dirichlet patch each copy's residual carries its share of the reaction on ∂Ω,
// which does not cancel in the difference. The values at those nodes are still unknowns of
// the rows of R next to them: each is extended from R (the mean of the nodes of R on its
// triangles), so that G = M_RR + M_R,¬R E is square. E's rows sum to one, hence a uniform Σ
// solves G Σ_R = (r⁺ − r⁻)_R / 2 exactly at every node of R (a node of ¬R with no node of R on
// its triangles has no M entry in a row of R: its column is dropped without harm). Held nodes
// report the extended value; tips report zero, as before. G is not symmetric: it is factored
// by LU, once, and Gᵀ for the adjoint. Each Cartesian component has its own R (a roller holds
// one component: its node is a row of the others), so up to d factorisations; components with
// the same R share one.
bool FractureSystem::buildRecovery() {
  const Index n = size();
  // Per Cartesian component c the rows R_c: the free nodes, but for a node held by a roller
  // not the component the roller holds. A roller fixes a Cartesian component (fixedDisplacement
  // `components`), its reaction is along that axis alone, so the node's other components of
  // (r⁺ − r⁻)/2 are still the traction's moments: the node keeps its own traction there
  // instead of the mean of its neighbours' (which, measured on a fault extruded between two
  // rollers in P2, left the nodes on the rollers cycling between stick and slip).
  std::vector<std::vector<Index>> rows(static_cast<std::size_t>(dim_));
  for (Index k = 0; k < n; ++k) {
    if (mask_[k] <= 0) continue;
    const int held = nodes_[k].heldComponent;
    int axis = -1;  // the Cartesian axis the roller holds (-1: none, or not along an axis)
    if (held >= 0)
      for (int a = 0; a < dim_; ++a)
        if (std::abs(std::abs(nodes_[k].tangent[held][a]) - 1) <= 1e-9) axis = a;
    if (held >= 0 && axis < 0) continue;  // held along no single axis: no row (as before)
    for (int c = 0; c < dim_; ++c)
      if (c != axis) rows[static_cast<std::size_t>(c)].push_back(k);
  }
  recoveries_.clear();
  for (int c = 0; c < dim_; ++c) {
    int same = -1;
    for (int b = 0; b < c; ++b)
      if (rows[static_cast<std::size_t>(b)] == rows[static_cast<std::size_t>(c)])
        same = recoveryOf_[static_cast<std::size_t>(b)];
    if (same >= 0) {
      recoveryOf_[static_cast<std::size_t>(c)] = same;
      continue;
    }
    recoveryOf_[static_cast<std::size_t>(c)] = static_cast<int>(recoveries_.size());
    recoveries_.push_back(std::make_unique<Recovery>());
    if (!buildRecovery(*recoveries_.back(), rows[static_cast<std::size_t>(c)])) return false;
  }
  return true;
}

bool FractureSystem::buildRecovery(Recovery& rec, const std::vector<Index>& recovered) {
  const Index n = size();
  rec.recovered = recovered;
  std::vector<Index> row(static_cast<std::size_t>(n), -1);
  for (std::size_t a = 0; a < recovered.size(); ++a) row[recovered[a]] = static_cast<Index>(a);
  const Index r = static_cast<Index>(recovered.size());
  // (triangle, its local node) per control node. A triangle's sign of a node (faultTriangleSign_)
  // is −1 where the node is a joined node of a fracture oriented against the triangle's: Σ there
  // is the opposite of the triangle's field, in M and in the extension.
  std::vector<std::vector<std::pair<Index, int>>> trianglesOf(static_cast<std::size_t>(n));
  for (std::size_t t = 0; t < faultTriangles_.size(); ++t)
    for (int a = 0; a < 6; ++a)
      trianglesOf[faultTriangles_[t][a]].push_back({static_cast<Index>(t), a});
  Triplets full, out;  // E on every node; X: E without the tip rows (tips report zero)
  for (Index k = 0; k < n; ++k) {
    if (row[k] >= 0) {
      full.emplace_back(k, row[k], 1.0);
      out.emplace_back(k, row[k], 1.0);
      continue;
    }
    std::map<Index, double> from;  // row of R -> its sign against node k
    for (const auto& [t, a] : trianglesOf[k])
      for (int b = 0; b < 6; ++b) {
        const Index j = faultTriangles_[t][b];
        if (row[j] >= 0) from.emplace(row[j], faultTriangleSign_[t][a] * faultTriangleSign_[t][b]);
      }
    for (const auto& [j, sign] : from) {
      full.emplace_back(k, j, sign / static_cast<double>(from.size()));
      if (!nodes_[k].tip) out.emplace_back(k, j, sign / static_cast<double>(from.size()));
    }
  }
  rec.extend = fromTriplets(n, r, out);
  if (r == 0) return true;
  Triplets mt;
  if (meet_) {
    // Where fault surfaces meet, a node's ⁺ copy is not that of every triangle around it: M
    // from each fracture's triangles on their control nodes (a joined node: both fractures',
    // turned where one is oriented against the node's owner).
    for (std::size_t t = 0; t < faultTriangles_.size(); ++t)
      for (int a = 0; a < 6; ++a) {
        const Index i = faultTriangles_[t][a];
        if (row[i] < 0) continue;
        for (int b = 0; b < 6; ++b)
          mt.emplace_back(row[i], faultTriangles_[t][b],
                          faultTriangleSign_[t][a] * faultTriangleSign_[t][b] *
                              faultTriangleArea_[t] * facetConsistentMass<3>(2, a, b));
      }
  }
  // M on the control nodes: the ⁺ copies are the split-space nodes of the ⁺-side triangles.
  std::vector<Index> facets, control(static_cast<std::size_t>(splitSpace_->numNodes()), -1);
  for (const FractureGeometry& g : split_.fractures)
    for (const auto& t : g.triangles) facets.insert(facets.end(), t.begin(), t.end());
  for (Index k = 0; k < n; ++k) control[nodes_[k].plus] = k;
  const Eigen::SparseMatrix<double> Msplit =
      meet_ ? Eigen::SparseMatrix<double>() : splitAssembler_->consistentFacetMass(facets);
  for (Index c = 0; c < Msplit.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Msplit, c); it; ++it) {
      const Index i = control[it.row()], j = control[it.col()];
      FRICTION_ASSERT(i >= 0 && j >= 0, "the fault triangles' nodes are control nodes");
      if (row[i] >= 0) mt.emplace_back(row[i], j, it.value());
    }
  Eigen::SparseMatrix<double> G = fromTriplets(r, n, mt) * fromTriplets(n, r, full);
  G.makeCompressed();
  rec.lu.compute(G);
  Eigen::SparseMatrix<double> Gt = G.transpose();
  Gt.makeCompressed();
  rec.lut.compute(Gt);
  return rec.lu.info() == Eigen::Success && rec.lut.info() == Eigen::Success;
}

void FractureSystem::applyRecovery(Eigen::MatrixXd& x, bool transpose) const {
  const Index n = size();
  for (int c = 0; c < dim_; ++c) {
    const Recovery& rec =
        *recoveries_[static_cast<std::size_t>(recoveryOf_[static_cast<std::size_t>(c)])];
    const Index r = static_cast<Index>(rec.recovered.size());
    Eigen::MatrixXd part(n, x.cols());
    for (Index i = 0; i < n; ++i) part.row(i) = x.row(dim_ * i + c);
    Eigen::MatrixXd result;
    if (r == 0) {
      result = Eigen::MatrixXd::Zero(n, x.cols());
    } else if (!transpose) {
      Eigen::MatrixXd onR(r, x.cols());
      for (Index a = 0; a < r; ++a) onR.row(a) = part.row(rec.recovered[a]);
      result = rec.extend * Eigen::MatrixXd(rec.lu.solve(onR));
    } else {
      const Eigen::MatrixXd onR = rec.lut.solve(Eigen::MatrixXd(rec.extend.transpose() * part));
      result = Eigen::MatrixXd::Zero(n, x.cols());
      for (Index a = 0; a < r; ++a) result.row(rec.recovered[a]) = onR.row(a);
    }
    for (Index i = 0; i < n; ++i) x.row(dim_ * i + c) = result.row(i);
  }
}

void FractureSystem::primal(const Eigen::VectorXd& beta, Eigen::VectorXd& tau,
                            Eigen::VectorXd& sigmaN) {
  const Index n = size(), k = blockSize(), d = dim_;
  FRICTION_ASSERT((beta.size() == k * n || beta.size() == k * n + n) && slip_.size() == k * n,
                  "k slip components per node, then the openings");
  const bool opening = beta.size() == k * n + n;
  // Each sum over a frame runs in component order, term by term: in 2D (k = 1) exactly the
  // arithmetic of s t_Γ and Σ·t_Γ = Σ_x t_x + Σ_y t_y.
  Eigen::VectorXd j(d * n);
  for (Index i = 0; i < n; ++i) {
    const ControlNode& v = nodes_[i];
    for (int a = 0; a < d; ++a) {
      double ja = componentMask_[k * i] * (slip_[k * i] + beta[k * i]) * v.tangent[0][a];
      for (int c = 1; c < k; ++c)
        ja += componentMask_[k * i + c] * (slip_[k * i + c] + beta[k * i + c]) * v.tangent[c][a];
      if (opening) ja -= mask_[i] * beta[k * n + i] * v.normal[a];  // g = −[[u]]·n_Γ
      j[d * i + a] = ja;
    }
  }
  Eigen::VectorXd sigma;
  solve(j, true, sigma);
  tau.resize(k * n);
  sigmaN.resize(n);
  for (Index i = 0; i < n; ++i) {
    for (int c = 0; c < k; ++c) tau[k * i + c] = project(sigma, i, nodes_[i].tangent[c]);
    // A partly held node's traction along its held direction is the roller's reaction, not a
    // friction traction: the law acts on the free component alone (docs/method.md §4).
    if (nodes_[i].heldComponent >= 0) tau[k * i + nodes_[i].heldComponent] = 0;
    sigmaN[i] = project(sigma, i, nodes_[i].normal);
  }
  if (offsetSigmaN_.size() == n) {
    sigmaN += offsetSigmaN_;
    tau += offsetTau_;
    for (Index i = 0; i < n; ++i)
      if (nodes_[i].heldComponent >= 0) tau[k * i + nodes_[i].heldComponent] = 0;
  }
}

double FractureSystem::project(const Eigen::VectorXd& sigma, Index node,
                               const Eigen::Vector3d& direction) const {
  const double* S = sigma.data() + dim_ * node;
  double p = S[0] * direction[0];
  for (int a = 1; a < dim_; ++a) p += S[a] * direction[a];
  return p;
}

Eigen::VectorXd FractureSystem::dualJump(const Eigen::Ref<const Eigen::VectorXd>& qt,
                                         const Eigen::Ref<const Eigen::VectorXd>& qn) const {
  const Index n = size(), k = blockSize(), d = dim_;
  FRICTION_ASSERT(qt.size() == k * n && qn.size() == n, "k tangential + 1 normal per node");
  Eigen::VectorXd j(d * n);
  for (Index i = 0; i < n; ++i) {
    const ControlNode& v = nodes_[i];
    for (int a = 0; a < d; ++a) {
      double ja = v.heldComponent == 0 ? 0.0 : qt[k * i] * v.tangent[0][a];
      for (int c = 1; c < k; ++c)
        if (v.heldComponent != c) ja += qt[k * i + c] * v.tangent[c][a];
      j[d * i + a] = mask_[i] * (ja + qn[i] * v.normal[a]);
    }
  }
  return j;
}

void FractureSystem::dualBlock(const Eigen::MatrixXd& qt, const Eigen::MatrixXd& qn,
                               Eigen::MatrixXd& tauDual, Eigen::MatrixXd* sigmaNDual) {
  FRICTION_ASSERT(factor_ && factor_->ok(), "factor() before solving");
  const Index n = size(), k = blockSize(), d = dim_, m = qt.cols();
  FRICTION_ASSERT(qn.cols() == m, "as many normal as tangential right-hand sides");
  tauDual.resize(k * n, m);
  if (sigmaNDual) sigmaNDual->resize(n, m);
  // As solve(j, false, ·) column by column, but one back-substitution for the block: the
  // right-hand sides' and the expansions' own work is O(unknowns) per column.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dirichlet_->numFixed());
  const Index block = 64;
  for (Index c0 = 0; c0 < m; c0 += block) {
    throwIfStopNow();
    const Index nc = std::min(block, m - c0);
    Eigen::MatrixXd J(d * n, nc), rhs;
    for (Index c = 0; c < nc; ++c) {
      J.col(c) = dualJump(qt.col(c0 + c), qn.col(c0 + c));
      const Eigen::VectorXd r = reduced_->rhs(Eigen::VectorXd(-(B_ * J.col(c))), zero);
      if (c == 0) rhs.resize(r.size(), nc);
      rhs.col(c) = r;
    }
    const Eigen::MatrixXd X = factor_->solveRestricted(rhs);
    Eigen::MatrixXd sigma(d * n, nc);
    for (Index c = 0; c < nc; ++c) {
      const Eigen::VectorXd x = reduced_->expand(Eigen::VectorXd(X.col(c)), zero);
      sigma.col(c) = Tx_ * x + Tj_ * J.col(c);
    }
    if (consistent_) applyRecovery(sigma, false);
    for (Index c = 0; c < nc; ++c) {
      const Eigen::VectorXd s = sigma.col(c);
      for (Index i = 0; i < n; ++i) {
        for (int r = 0; r < k; ++r)
          tauDual(k * i + r, c0 + c) = project(s, i, nodes_[i].tangent[r]);
        if (nodes_[i].heldComponent >= 0) tauDual(k * i + nodes_[i].heldComponent, c0 + c) = 0;
        if (sigmaNDual) (*sigmaNDual)(i, c0 + c) = project(s, i, nodes_[i].normal);
      }
    }
  }
}

void FractureSystem::dual(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn,
                          Eigen::VectorXd& tauDual, Eigen::VectorXd* sigmaNDual) {
  const Index n = size(), k = blockSize();
  const Eigen::VectorXd j = dualJump(qt, qn);
  Eigen::VectorXd sigma;
  solve(j, false, sigma);
  tauDual.resize(k * n);
  for (Index i = 0; i < n; ++i) {
    for (int c = 0; c < k; ++c) tauDual[k * i + c] = project(sigma, i, nodes_[i].tangent[c]);
    if (nodes_[i].heldComponent >= 0) tauDual[k * i + nodes_[i].heldComponent] = 0;
  }
  if (sigmaNDual) {
    sigmaNDual->resize(n);
    for (Index i = 0; i < n; ++i) (*sigmaNDual)[i] = project(sigma, i, nodes_[i].normal);
  }
}

void FractureSystem::adjoint(const Eigen::VectorXd& qt, const Eigen::VectorXd& qn,
                             Eigen::VectorXd& tauAdjoint, Eigen::VectorXd* normalAdjoint) {
  if (!consistent_) {
    dual(qt, qn, tauAdjoint, normalAdjoint);
    return;
  }
  // τ = Tᵀ X G⁻¹ R (M·S) mask T β (T: the frames): its W-adjoint is
  // W⁻¹ mask Tᵀ (M·S) Rᵀ G⁻ᵀ Xᵀ T W q, M·S symmetric.
  const Index n = size(), k = blockSize(), d = dim_;
  FRICTION_ASSERT(qt.size() == k * n && qn.size() == n, "k tangential + 1 normal per node");
  Eigen::MatrixXd y(d * n, 1);
  for (Index i = 0; i < n; ++i) {
    const ControlNode& v = nodes_[i];
    for (int a = 0; a < d; ++a) {
      // τ's held component at a partly held node is 0 whatever β: its q does not enter.
      double ya = v.heldComponent == 0 ? 0.0 : qt[k * i] * v.tangent[0][a];
      for (int c = 1; c < k; ++c)
        if (v.heldComponent != c) ya += qt[k * i + c] * v.tangent[c][a];
      y(d * i + a, 0) = weights_[i] * (ya + qn[i] * v.normal[a]);
    }
  }
  applyRecovery(y, true);
  Eigen::VectorXd sigma;
  solve(y.col(0), false, sigma, false);
  tauAdjoint.resize(k * n);
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < k; ++c)
      tauAdjoint[k * i + c] =
          componentMask_[k * i + c] * project(sigma, i, nodes_[i].tangent[c]) / weights_[i];
  if (normalAdjoint) {
    normalAdjoint->resize(n);
    for (Index i = 0; i < n; ++i)
      (*normalAdjoint)[i] = mask_[i] * project(sigma, i, nodes_[i].normal) / weights_[i];
  }
}

InterfaceOperator FractureSystem::interfaceOperator(InterfaceMethod method, bool withOpening) {
  FRICTION_ASSERT(factor_ && factor_->ok(), "factor() before the interface operator");
  if (method == InterfaceMethod::dualSolves)
    return SlipResponse::interfaceOperator(method, withOpening);
  const Index n = size(), k = blockSize(), d = dim_;
  InterfaceOperator op;
  op.Stt.setZero(k * n, k * n);
  op.Snt.setZero(n, k * n);
  if (withOpening) {
    op.Stn.setZero(k * n, n);
    op.Snn.setZero(n, n);
  }
  if (jumpDofs_.empty()) {
    op.method = method;
    return op;
  }
  Eigen::MatrixXd blocked;
  const bool fromFactor =
      method == InterfaceMethod::factorisation &&
      factor_->schurComplement().rows() == static_cast<Eigen::Index>(jumpDofs_.size());
  if (!fromFactor) {
    const long solves0 = factor_->numSolves();
    blocked = factor_->schurBySolves(borderB_, borderC_);
    op.solves = factor_->numSolves() - solves0;
  }
  const Eigen::MatrixXd& MS = fromFactor ? factor_->schurComplement() : blocked;
  op.method = fromFactor && factor_->schurSolves() == 0 ? InterfaceMethod::factorisation
                                                        : InterfaceMethod::blockSolves;
  // Frame projection: S_tt(k·i + r, k·j + c) = t_r,iᵀ (M·S)_ij t_c,j / w_i and
  // S_nt(i, k·j + c) = n_iᵀ (M·S)_ij t_c,j / w_i, over the nodes with two sides (jumpDofs_
  // holds their d entries in node order). The opening's columns (withOpening) take −n_j
  // for t_c,j: a unit opening is the jump −n_Γ.
  const Index m = static_cast<Index>(jumpDofs_.size()) / d;
  const int kc = withOpening ? k + 1 : k;  // columns per node
  std::vector<Index> node(m);
  for (Index a = 0; a < m; ++a) node[a] = jumpDofs_[d * a] / d;
  Eigen::MatrixXd columns(d * m, kc * m);  // (M·S) t_c,j for each node j, zero where held
  for (Index a = 0; a < m; ++a)
    for (int c = 0; c < kc; ++c) {
      const Eigen::Vector3d t =
          c < k ? Eigen::Vector3d(nodes_[node[a]].tangent[c] * componentMask_[k * node[a] + c])
                : Eigen::Vector3d(-nodes_[node[a]].normal * mask_[node[a]]);
      Eigen::VectorXd col = MS.col(d * a) * t[0];
      for (int e = 1; e < d; ++e) col += MS.col(d * a + e) * t[e];
      columns.col(kc * a + c) = col;
    }
  // 3D P2: S = X G⁻¹ R (M·S), on all d·n rows, instead of the division by w_i.
  Eigen::MatrixXd recovered;
  if (consistent_) {
    recovered.setZero(d * n, kc * m);
    for (Index b = 0; b < m; ++b)
      for (int e = 0; e < d; ++e) recovered.row(d * node[b] + e) = columns.row(d * b + e);
    applyRecovery(recovered, false);
  }
  Eigen::VectorXd s(d);
  for (Index a = 0; a < kc * m; ++a)  // column by column: both matrices are column-major
    for (Index b = 0; b < m; ++b) {
      const ControlNode& v = nodes_[node[b]];
      const bool openingColumn = a % kc == k;
      for (int e = 0; e < d; ++e)
        s[e] =
            consistent_ ? recovered(d * node[b] + e, a) : columns(d * b + e, a) / weights_[node[b]];
      if (openingColumn) {
        const Index col = node[a / kc];
        for (int r = 0; r < k; ++r) op.Stn(k * node[b] + r, col) = project(s, 0, v.tangent[r]);
        if (v.heldComponent >= 0) op.Stn(k * node[b] + v.heldComponent, col) = 0;
        op.Snn(node[b], col) = project(s, 0, v.normal);
        continue;
      }
      const Index col = k * node[a / kc] + a % kc;
      for (int r = 0; r < k; ++r) op.Stt(k * node[b] + r, col) = project(s, 0, v.tangent[r]);
      if (v.heldComponent >= 0)  // the roller's reaction: 0 in τ (primal)
        op.Stt(k * node[b] + v.heldComponent, col) = 0;
      op.Snt(node[b], col) = project(s, 0, v.normal);
    }
  return op;
}

double FractureSystem::equilibriumResidual() const {
  if (lastRhs_.size() == 0) return 0;
  const double scale = lastRhs_.norm();
  const double r = (reduced_->apply(lastFree_) - lastRhs_).norm();
  return scale > 0 ? r / scale : r;
}

Eigen::VectorXd FractureSystem::lastSplitDisplacement() const { return P_ * x_ + L_ * lastJump_; }

Eigen::MatrixXd FractureSystem::displacementResponse(const Eigen::SparseMatrix<double>& W) {
  FRICTION_ASSERT(factor_ && factor_->ok(), "factor() before solving");
  // The primal map with no load and zero Dirichlet values: j = T β (the frames, componentMask),
  // x = Rᵀ A⁻¹ R (−B j) (R: the free dofs), u = P x + L j. So wᵀ u = gᵀ β with
  // g = Tᵀ (Lᵀ w − Bᵀ Rᵀ A⁻¹ R Pᵀ w): one solve per row w of W.
  const Index n = size(), k = blockSize(), d = dim_;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dirichlet_->numFixed());
  const Eigen::SparseMatrix<double> Wt = W.transpose();
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(W.rows(), k * n);
  for (Index r = 0; r < W.rows(); ++r) {
    const Eigen::VectorXd w = Wt.col(r);
    const Eigen::VectorXd Ptw = P_.transpose() * w;
    const Eigen::VectorXd s = factor_->solve(reduced_->rhs(Ptw, zero));
    const Eigen::VectorXd v = L_.transpose() * w - B_.transpose() * reduced_->expand(s, zero);
    for (Index i = 0; i < n; ++i)
      for (int c = 0; c < k; ++c) {
        double g = 0;
        for (int a = 0; a < d; ++a) g += nodes_[i].tangent[c][a] * v[d * i + a];
        G(r, k * i + c) = componentMask_[k * i + c] * g;
      }
  }
  return G;
}

}  // namespace friction
