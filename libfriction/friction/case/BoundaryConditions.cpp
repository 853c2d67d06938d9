// The case's boundary conditions: see BoundaryConditions.hpp.
#include "friction/case/BoundaryConditions.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <set>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/mesh/MeshTopology.hpp"

namespace friction {

std::vector<std::string> BoundaryConditions::typeNames() {
  return {"fixedDisplacement", "traction", "pressure", "free"};
}

namespace {

/// The unit normal of the mesh's labelled triangle e pointing out of the tetrahedron it bounds
/// (away from its opposite vertex; of the last tetrahedron, in mesh order, if two have it).
Point outwardTriangleNormal(const Mesh& mesh, const MeshTopology& topology, Index e,
                            const std::string& patch) {
  const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1), c = mesh.facetVertex(e, 2);
  const Point& xa = mesh.points[a];
  Point n = (mesh.points[b] - xa).cross(mesh.points[c] - xa);
  const Index f = topology.findFacet({a, b, c});
  if (f < 0 || !(n.norm() > 0))
    throw InputError(mesh.source, "the triangle " + formatPoint(xa, 3) + " " +
                                      formatPoint(mesh.points[b], 3) + " " +
                                      formatPoint(mesh.points[c], 3) + " of patch '" + patch +
                                      "' is not a face of any tetrahedron");
  n.normalize();
  const auto last = topology.cellOf(f, topology.numCellsOf(f) - 1);
  const Index o = topology.oppositeVertex(last.cell, last.local);
  if ((mesh.points[o] - xa).dot(n) > 0) n = -n;
  return n;
}

/// Patch types other codes have (OpenFOAM's solid solvers, GEOS, PyLith) refused with the form
/// they take here, before the list of valid types.
void foreignType(const Dictionary& p, int dim) {
  if (!p.found("type") || p.isDict("type")) return;
  const std::string type = p.getWord("type");
  const std::string zero = dim == 2 ? "(0 0)" : "(0 0 0)";
  const std::string roller =
      "a roller (or symmetry plane) is 'type fixedDisplacement; components (x); "
      "value " +
      zero + ";' with the held directions in components";
  std::string advice;
  if (type == "roller" || type == "slip" || type == "symmetryPlane" || type == "symmetry")
    advice = roller;
  else if (type == "fixedValue" || type == "displacement" || type == "dirichlet")
    advice = "a prescribed displacement is 'type fixedDisplacement; value " + zero + ";'";
  else if (type == "zeroGradient" || type == "tractionFree" || type == "neumann")
    advice = "a traction-free patch is 'type free;'";
  else if (type == "tractionDisplacement")
    advice =
        "OpenFOAM's tractionDisplacement is 'type traction; traction (...);' or "
        "'type pressure; pressure p;' here";
  if (!advice.empty())
    p.fail("type", "key 'type': unknown type '" + type + "': " + advice +
                       " (valid types are: " + joinWords(BoundaryConditions::typeNames()) + ")");
}

}  // namespace

BoundaryConditions::BoundaryConditions(const Dictionary& dict, const Mesh& mesh,
                                       const std::vector<int>& fractureLabels) {
  const int dim = mesh.dim;
  const Dictionary& field = dict.subDict("boundaryField");
  std::map<std::string, int> labelOf;
  for (const auto& [label, name] : mesh.labelNames)
    if (std::find(fractureLabels.begin(), fractureLabels.end(), label) == fractureLabels.end())
      labelOf[name] = label;
  std::vector<std::string> valid;
  for (const auto& [name, label] : labelOf) valid.push_back(name);

  for (const std::string& name : field.keys()) {
    auto it = labelOf.find(name);
    if (it == labelOf.end())
      field.fail(name, "'" + name + "' is not a boundary patch of the mesh" +
                           suggestionText(name, valid) + " (patches: " + joinWords(valid) + ")");
    const Dictionary& p = field.subDict(name);
    try {
      Patch patch;
      patch.name = name;
      patch.label = it->second;
      foreignType(p, dim);
      const std::string type = p.getChoice("type", typeNames());
      if (type == "fixedDisplacement") {
        patch.type = Type::fixedDisplacement;
        if (!p.found("value"))
          p.fail("value", std::string("missing key 'value' in ") + "patch '" + name +
                              "': the displacement [m] of the held components, e.g. value " +
                              (dim == 2 ? "(0 0)" : "(0 0 0)") +
                              "; (a roller: components (x) and value 0, which holds x at 0)");
        patch.value = TimeFunction::read(p, "value", dim);
        if (p.found("components")) {
          const std::vector<std::string> c = p.getWordList("components");
          const std::string expected = dim == 2 ? "expected (x), (y) or (x y)"
                                                : "expected a non-empty subset of (x y z), "
                                                  "e.g. (x z)";
          const char* const axis[3] = {"x", "y", "z"};
          const FixedComponents bit[3] = {FixedComponents::x, FixedComponents::y,
                                          FixedComponents::z};
          unsigned set = 0;
          std::size_t count = 0;
          for (int k = 0; k < 3; ++k)
            if (std::find(c.begin(), c.end(), axis[k]) != c.end()) {
              set |= static_cast<unsigned>(bit[k]);
              ++count;
            }
          if (dim == 2 && (set & static_cast<unsigned>(FixedComponents::z)))
            p.fail("components",
                   "key 'components': 'z' has no meaning on a 2D mesh (its "
                   "displacements have x and y only); " +
                       expected);
          // An unknown word or a repeated one leaves count short of the list's length.
          if (c.empty() || c.size() != count) p.fail("components", "key 'components': " + expected);
          // Every component of the dimension is `all` (the 2D (x y) as before).
          patch.components =
              set == (1u << dim) - 1 ? FixedComponents::all : static_cast<FixedComponents>(set);
        }
      } else if (type == "traction" || type == "pressure") {
        if (type == "traction") {
          patch.type = Type::traction;
          patch.value = TimeFunction::read(p, "traction", dim);
        } else {
          patch.type = Type::pressure;
          patch.value = TimeFunction::read(p, "pressure", 1);
        }
        // Outward normal of each edge: away from the third vertex of the triangle it bounds
        // (of the last triangle, in mesh order, if two have it). The pressure's traction uses
        // it; both types use it and the facets' centres to compare with an in-situ stress.
        const auto topology = mesh.topology();
        for (Index e = 0; e < mesh.numFacets(); ++e) {
          if (mesh.facetLabel[e] != patch.label) continue;
          Point centre = Point::Zero();
          for (int k = 0; k < dim; ++k) centre += mesh.points[mesh.facetVertex(e, k)];
          patch.facetCentre.push_back(centre / dim);
          if (dim == 3) {
            patch.outwardNormal.push_back(outwardTriangleNormal(mesh, *topology, e, name));
            continue;
          }
          const Index a = mesh.facetVertex(e, 0), b = mesh.facetVertex(e, 1);
          const Vector2 d = mesh.points[b].head<2>() - mesh.points[a].head<2>();
          Vector2 n = Vector2(d.y(), -d.x()).normalized();
          const Index f = topology->findFacet({a, b});
          if (f < 0)
            throw InputError(mesh.source, "the edge " + formatPoint(mesh.points[a], mesh.dim) +
                                              "-" + formatPoint(mesh.points[b], mesh.dim) +
                                              " of patch '" + name +
                                              "' is not a side of any triangle");
          const auto last = topology->cellOf(f, topology->numCellsOf(f) - 1);
          const Index c = topology->oppositeVertex(last.cell, last.local);
          if ((mesh.points[c].head<2>() - mesh.points[a].head<2>()).dot(n) > 0) n = -n;
          patch.outwardNormal.push_back(Point(n.x(), n.y(), 0.0));
        }
      }
      patches_.push_back(std::move(patch));
    } catch (const InputError& e) {
      // Say which patch: the same key ('value') appears once per patch.
      if (e.message().find("patch '") != std::string::npos) throw;
      throw InputError(e.location(), "patch '" + name + "': " + e.message());
    }
  }
  // Labelled lines inside the body (sides of two triangles) carry no boundary condition
  // unless one is given: only patches on the outer boundary must be listed.
  const auto topology = mesh.topology();
  std::set<int> onBoundary;
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const Index f = dim == 2 ? topology->findFacet({mesh.facetVertex(e, 0), mesh.facetVertex(e, 1)})
                             : topology->findFacet({mesh.facetVertex(e, 0), mesh.facetVertex(e, 1),
                                                    mesh.facetVertex(e, 2)});
    if (f >= 0 && topology->isBoundary(f)) onBoundary.insert(mesh.facetLabel[e]);
  }
  for (const auto& [name, label] : labelOf) {
    if (!onBoundary.count(label)) continue;
    bool listed = false;
    for (const Patch& p : patches_) listed |= p.label == label;
    if (!listed)
      throw InputError(field.location(),
                       "boundaryField has no entry for patch '" + name +
                           "'; every boundary patch needs one (use 'type free;' for a "
                           "traction-free side)");
  }
}

void BoundaryConditions::fix(DirichletConditions& dirichlet) const {
  for (const Patch& p : patches_)
    if (p.type == Type::fixedDisplacement) dirichlet.fixPatch(p.label, p.components);
}

void BoundaryConditions::setValues(DirichletConditions& dirichlet, double t) const {
  for (const Patch& p : patches_)
    if (p.type == Type::fixedDisplacement) {
      const std::vector<double> v = p.value(t);
      if (v.size() == 3)
        dirichlet.setPatchValue(p.label, Point(v[0], v[1], v[2]));
      else
        dirichlet.setPatchValue(p.label, Vector2(v[0], v[1]));
    }
}

bool BoundaryConditions::loadsChange(double t0, double t) const {
  for (const Patch& p : patches_)
    if (p.type != Type::free && p.value(t0) != p.value(t)) return true;
  return false;
}

Eigen::VectorXd BoundaryConditions::neumannLoad(const LagrangeSpace& space, double t) const {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(space.numDofs());
  const Mesh& mesh = space.mesh();
  for (const Patch& p : patches_) {
    if (p.type != Type::traction && p.type != Type::pressure) continue;
    const std::vector<double> v = p.value(t);
    if (mesh.dim == 3) {
      const std::vector<Index> facets = space.labelledFacets(p.label);
      for (std::size_t e = 0; e < facets.size(); ++e) {
        const auto x = mesh.facet(facets[e]);
        const Point& a = mesh.points[x[0]];
        const double area = 0.5 * (mesh.points[x[1]] - a).cross(mesh.points[x[2]] - a).norm();
        const Point g =
            p.type == Type::traction ? Point(v[0], v[1], v[2]) : Point(-v[0] * p.outwardNormal[e]);
        // ∫ φ_i dA on a flat triangle: A/3 at each vertex (P1); for P2, 0 at the vertices and
        // A/3 at the mid-edge nodes (facet order: the three vertices, then the midpoints).
        const NodeList nodes = space.labelledFacetNodes(facets[e]);
        for (int k = nodes.size == 3 ? 0 : 3; k < nodes.size; ++k)
          F.segment<3>(space.dof(nodes[k], 0)) += (area / 3) * g;
      }
      continue;
    }
    const auto edges = space.labelledEdges(p.label);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      const double length = (mesh.points[b].head<2>() - mesh.points[a].head<2>()).norm();
      const Vector2 g = p.type == Type::traction ? Vector2(v[0], v[1])
                                                 : Vector2(-v[0] * p.outwardNormal[e].head<2>());
      // ∫ φ_i ds on a straight edge: L/2 at the ends (P1); L/6, 2L/3, L/6 (P2).
      const NodeList nodes = space.edgeNodes(a, b);
      const double w1[2] = {0.5, 0.5}, w2[3] = {1.0 / 6, 2.0 / 3, 1.0 / 6};
      for (int k = 0; k < nodes.size; ++k) {
        const double w = (nodes.size == 2 ? w1[k] : w2[k]) * length;
        F.segment<2>(space.dof(nodes[k], 0)) += w * g;
      }
    }
  }
  return F;
}

std::vector<std::string> BoundaryConditions::tractionsOfInSitu(
    const std::function<Eigen::Matrix3d(const Point&)>& sigma0, double t) const {
  std::vector<std::string> doubled;
  for (const Patch& p : patches_) {
    if ((p.type != Type::traction && p.type != Type::pressure) || p.facetCentre.empty()) continue;
    const std::vector<double> v = p.value(t);
    bool same = true, loaded = false;
    for (std::size_t f = 0; f < p.facetCentre.size() && same; ++f) {
      const Point& n = p.outwardNormal[f];
      const Eigen::Vector3d inSitu = sigma0(p.facetCentre[f]) * n;
      Eigen::Vector3d applied = Eigen::Vector3d::Zero();
      if (p.type == Type::pressure)
        applied = -v[0] * n;
      else
        for (std::size_t k = 0; k < v.size() && k < 3; ++k)
          applied[static_cast<Eigen::Index>(k)] = v[k];
      const double scale = inSitu.norm();
      loaded |= scale > 0;
      // Equal to 1 %: the same load written twice, not a coincidence of two loads.
      same = scale > 0 && (applied - inSitu).norm() <= 0.01 * scale;
    }
    if (same && loaded) doubled.push_back(p.name);
  }
  return doubled;
}

}  // namespace friction
