// The case's boundary conditions: see BoundaryConditions.hpp.
#include "friction/case/BoundaryConditions.hpp"

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

BoundaryConditions::BoundaryConditions(const Dictionary& dict, const Mesh& mesh,
                                       const std::vector<int>& fractureLabels) {
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
      const std::string type = p.getChoice("type", typeNames());
      if (type == "fixedDisplacement") {
        patch.type = Type::fixedDisplacement;
        patch.value = TimeFunction::read(p, "value", 2);
        if (p.found("components")) {
          const std::vector<std::string> c = p.getWordList("components");
          const bool x = std::find(c.begin(), c.end(), "x") != c.end();
          const bool y = std::find(c.begin(), c.end(), "y") != c.end();
          if (c.empty() || c.size() != static_cast<std::size_t>(x + y))
            p.fail("components", "key 'components': expected (x), (y) or (x y)");
          patch.components = x && y ? FixedComponents::all
                             : x    ? FixedComponents::x
                                    : FixedComponents::y;
        }
      } else if (type == "traction") {
        patch.type = Type::traction;
        patch.value = TimeFunction::read(p, "traction", 2);
      } else if (type == "pressure") {
        patch.type = Type::pressure;
        patch.value = TimeFunction::read(p, "pressure", 1);
        // Outward normal of each edge: away from the third vertex of the triangle it bounds
        // (of the last triangle, in mesh order, if two have it).
        const auto topology = mesh.topology();
        for (Index e = 0; e < mesh.numFacets(); ++e) {
          if (mesh.facetLabel[e] != patch.label) continue;
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
          patch.outwardNormal.push_back(n);
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
    const Index f = topology->findFacet({mesh.facetVertex(e, 0), mesh.facetVertex(e, 1)});
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
    const auto edges = space.labelledEdges(p.label);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [a, b] = edges[e];
      const double length = (mesh.points[b].head<2>() - mesh.points[a].head<2>()).norm();
      const Vector2 g =
          p.type == Type::traction ? Vector2(v[0], v[1]) : Vector2(-v[0] * p.outwardNormal[e]);
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

}  // namespace friction
