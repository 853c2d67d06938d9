// splitCase: see SplitCase.hpp. The summary printed here is splitFractureNodes' (README.md,
// "splitFractureNodes").
#include "friction/case/SplitCase.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

#include "friction/case/MeshSettings.hpp"
#include "friction/core/InputError.hpp"
#include "friction/fracture/SplitMeshIO.hpp"
#include "friction/mesh/MeshCheck.hpp"
#include "friction/mesh/MeshReader.hpp"

namespace fs = std::filesystem;

namespace friction {

namespace {

std::string point(const Vector2& p) {
  std::ostringstream s;
  s << "(" << p.x() << " " << p.y() << ")";
  return s.str();
}

// The boundary patches that contain a node (for the summary of fracture ends).
std::string patchesAt(const Mesh& mesh, Index v, const std::set<int>& fractureLabels) {
  std::set<std::string> names;
  for (Index e = 0; e < mesh.numFacets(); ++e) {
    const auto f = mesh.facet(e);
    if (std::find(f.begin(), f.end(), v) != f.end() && !fractureLabels.count(mesh.facetLabel[e]))
      names.insert(mesh.labelNames.at(mesh.facetLabel[e]));
  }
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "no patch" : "patch " + s;
}

// Up to `max` items as "a, b, c, ..." (the summary names a few, the counts say how many).
template <typename T, typename F>
std::string few(const std::vector<T>& items, F text, std::size_t max = 3) {
  std::string s;
  for (std::size_t i = 0; i < items.size() && i < max; ++i) s += (i ? ", " : "") + text(items[i]);
  return items.size() > max ? s + ", ..." : s;
}

void printChecks(std::ostream& out, const Mesh& mesh, const MeshSettings& settings,
                 const MeshSettings::MeshFindings& found) {
  out << "Checks\n    unused vertices:           " << mesh.droppedPoints.size();
  if (!mesh.droppedPoints.empty())
    out << " dropped from " << mesh.source << " (used by no " << cellName(mesh.dim)
        << ", e.g. a gmsh "
        << "Physical Point): " << few(mesh.droppedPoints, [&](const Mesh::DroppedPoint& p) {
             return "vertex " + std::to_string(p.number) + " at " + formatPoint(p.x, mesh.dim);
           });
  out << "\n    coincident nodes:          " << found.coincident.size();
  if (!found.coincident.empty())
    out << " pairs, allowed by allowCoincidentNodes (a traction-free cut): "
        << few(found.coincident, [&](const std::pair<Index, Index>& p) {
             return formatPoint(mesh.points[p.first], mesh.dim);
           });
  // One entry per unlabelled facet, for few().
  const int nf = mesh.verticesPerFacet();
  std::vector<const Index*> unlabelled;
  for (std::size_t i = 0; i < found.unlabelled.size(); i += nf)
    unlabelled.push_back(&found.unlabelled[i]);
  // "faces" in 3D: as long as 2D's "edges", so that the column stays aligned.
  out << "\n    unlabelled boundary " << (mesh.dim == 3 ? "faces" : "edges") << ": "
      << unlabelled.size();
  if (!unlabelled.empty())
    out << ", in patch " << settings.defaultPatch
        << " (defaultPatch): " << few(unlabelled, [&](const Index* f) {
             std::string s;
             for (int k = 0; k < nf; ++k)
               s += (k ? "-" : "") + formatPoint(mesh.points[f[k]], mesh.dim);
             return s;
           });
  out << "\n\n";
}

// 3D: the curves where fault surfaces meet (as 2D's junctions), with their kind, length and
// nodes, and the nodes where surfaces touch without sharing an edge.
void printIntersections(std::ostream& out, const Mesh& mesh, const SplitMesh& split) {
  const std::vector<IntersectionCurve> curves = intersectionCurves(split, mesh);
  std::map<Index, int> fracturesAt;
  for (const FractureGeometry& g : split.fractures)
    for (Index v : g.node) ++fracturesAt[v];
  std::set<Index> onCurves;
  for (const IntersectionCurve& c : curves) onCurves.insert(c.nodes.begin(), c.nodes.end());
  std::vector<Index> points;
  for (const auto& [v, count] : fracturesAt)
    if (count > 1 && !onCurves.count(v)) points.push_back(v);
  if (curves.empty() && points.empty()) return;
  const auto names = [&](const std::vector<std::size_t>& list) {
    return quotedFractureNames(split, list);
  };
  out << "Intersections: " << curves.size() << "\n";
  for (const IntersectionCurve& c : curves) {
    std::vector<std::size_t> all = c.passing;
    all.insert(all.end(), c.ending.begin(), c.ending.end());
    std::sort(all.begin(), all.end());
    out << "    " << c.kind() << ": ";
    if (c.passing.size() == 1 && !c.onOuterBoundary)
      out << names(c.ending) << " " << (c.ending.size() == 1 ? "ends" : "end") << " on "
          << names(c.passing);
    else if (c.passing.empty() && !c.onOuterBoundary)
      out << names(all) << " end together";
    else
      out << names(all);
    out << "; length " << c.length << ", " << c.nodes.size() << " nodes, ";
    if (c.ends.empty())
      out << "closed";
    else
      out << "from " << formatPoint(mesh.points[c.ends.front()], 3) << " to "
          << formatPoint(mesh.points[c.ends.back()], 3);
    out << "\n";
  }
  if (!points.empty())
    out << "    touching at a point only: " << points.size() << " nodes, e.g. "
        << formatPoint(mesh.points[points.front()], 3) << "\n";
  out << "\n";
}

// 3D, after the split: per fault surface its area, tip-line length and nodes; the split mesh.
void printFractures3D(std::ostream& out, const Mesh& mesh, const SplitMesh& split) {
  for (const FractureGeometry& g : split.fractures) {
    Point mean = Point::Zero();
    for (const auto& t : g.triangles)
      mean += (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]);
    out << "Fracture " << g.name << " (label " << g.label << ")\n"
        << "    triangles:    " << g.triangles.size() << "\n"
        << "    area:         " << g.area(mesh.points) << "\n"
        << "    tip line:     " << g.tipLineLength(mesh)
        << " (length of its edge inside the body)\n"
        << "    nodes:        " << g.numNodes() << " (duplicated " << g.numDuplicated()
        << ": interior " << g.numOfKind(FractureNodeKind::interior) << ", boundary "
        << g.numOfKind(FractureNodeKind::boundary) << "; tips " << g.numTips() << ")\n";
    const Index crossing = g.numOfKind(FractureNodeKind::crossing),
                abutting = g.numOfKind(FractureNodeKind::abutting),
                joined = g.numOfKind(FractureNodeKind::joined);
    if (crossing + abutting + joined > 0)
      out << "    meeting:      " << crossing << " nodes passing through, " << abutting
          << " ending on another fault (held), " << joined
          << " ending together with another (joined)\n";
    out << "    glued:        " << g.numGluedTriangles()
        << " triangles with all three vertices on the tip line (no jump there)\n"
        << "    normal:       " << formatPoint(mean.normalized(), 3)
        << " area-weighted mean (from Omega+ to Omega-)\n\n";
  }

  printIntersections(out, mesh, split);
  const SplitMesh& s = split;
  out << "Split mesh\n"
      << "    points:     " << s.mesh.numPoints() << " (+" << s.mesh.numPoints() - mesh.numPoints()
      << ")\n"
      << "    tetrahedra: " << s.mesh.numCells() << "\n"
      << "    volume:     " << s.mesh.totalMeasure() << "\n\n";
}

// 3D: what was read (sizes, patches), before the fault surfaces.
void printSummary3(std::ostream& out, const Mesh& mesh) {
  const CellSizes sizes = cellSizes(mesh);
  const auto centroid = [&](Index c) {
    Point x = Point::Zero();
    for (Index v : mesh.cell(c)) x += mesh.points[v] / 4.0;
    return formatPoint(x, 3);
  };
  out << std::setprecision(6);
  out << "Mesh: " << mesh.source << " (" << mesh.format << ", 3D)\n"
      << "    points:      " << mesh.numPoints() << "\n"
      << "    tetrahedra:  " << mesh.numCells() << "\n"
      << "    volume:      " << sizes.total << "\n"
      << "    smallest:    " << sizes.smallest << " at " << centroid(sizes.smallestCell) << "\n"
      << "    largest:     " << sizes.largest << " at " << centroid(sizes.largestCell) << "\n\n";
  out << "Patches\n    " << std::left << std::setw(16) << "name" << std::setw(8) << "label"
      << std::setw(11) << "triangles"
      << "area\n";
  for (const auto& [label, name] : mesh.labelNames) {
    int count = 0;
    double area = 0;
    for (Index e = 0; e < mesh.numFacets(); ++e)
      if (mesh.facetLabel[e] == label) {
        ++count;
        const auto v = mesh.facet(e);
        area += 0.5 * (mesh.points[v[1]] - mesh.points[v[0]])
                          .cross(mesh.points[v[2]] - mesh.points[v[0]])
                          .norm();
      }
    out << "    " << std::setw(16) << name << std::setw(8) << label << std::setw(11) << count
        << area << "\n";
  }
  out << std::right << "\n";
}

// 2D: each node where fractures meet, with each fracture's role there and the copies made.
void printJunctions(std::ostream& out, const Mesh& mesh, const SplitMesh& split) {
  std::map<Index, std::vector<std::pair<const FractureGeometry*, FractureNodeKind>>> at;
  for (const FractureGeometry& g : split.fractures)
    for (Index i = 0; i < g.numNodes(); ++i) at[g.node[i]].push_back({&g, g.kind[i]});
  std::vector<Index> junctions;
  for (const auto& [v, list] : at)
    if (list.size() > 1) junctions.push_back(v);
  if (junctions.empty()) return;
  out << "Junctions: " << junctions.size() << "\n";
  for (Index v : junctions) {
    Index copies = 0;
    for (Index o : split.origin) copies += o == v;
    out << "    " << formatPoint(mesh.points[v], mesh.dim) << " " << copies << " copies:";
    const auto& list = at[v];
    for (std::size_t k = 0; k < list.size(); ++k) {
      const char* role = list[k].second == FractureNodeKind::crossing   ? "passes through"
                         : list[k].second == FractureNodeKind::abutting ? "ends (held)"
                         : list[k].second == FractureNodeKind::joined   ? "joined"
                                                                        : "ends on the boundary";
      out << (k ? ", " : " ") << "'" << list[k].first->name << "' " << role;
    }
    out << "\n";
  }
  out << "\n";
}

void printSummary(std::ostream& out, const Mesh& mesh, const SplitMesh& split,
                  const std::set<int>& fractureLabels) {
  if (mesh.dim == 3) {
    printSummary3(out, mesh);
    return printFractures3D(out, mesh, split);
  }
  out << std::setprecision(6);
  out << "Mesh: " << mesh.source << " (" << mesh.format << ")\n"
      << "    points:    " << mesh.numPoints() << "\n"
      << "    triangles: " << mesh.numCells() << "\n"
      << "    area:      " << mesh.totalMeasure() << "\n\n";

  out << "Patches\n    " << std::left << std::setw(16) << "name" << std::setw(8) << "label"
      << std::setw(8) << "edges" << std::setw(14) << "length"
      << "type\n";
  for (const auto& [label, name] : mesh.labelNames) {
    int count = 0;
    double length = 0;
    for (Index e = 0; e < mesh.numFacets(); ++e)
      if (mesh.facetLabel[e] == label) {
        ++count;
        length += (mesh.points[mesh.facetVertex(e, 1)].head<2>() -
                   mesh.points[mesh.facetVertex(e, 0)].head<2>())
                      .norm();
      }
    out << "    " << std::setw(16) << name << std::setw(8) << label << std::setw(8) << count
        << std::setw(14) << length << (fractureLabels.count(label) ? "fracture" : "boundary")
        << "\n";
  }
  out << std::right << "\n";

  for (std::size_t f = 0; f < split.fractures.size(); ++f) {
    const FractureGeometry& g = split.fractures[f];
    const Index n = g.numNodes();
    out << "Fracture " << g.name << " (label " << g.label << ")\n"
        << "    edges:        " << n - 1 << "\n"
        << "    nodes:        " << n << " (duplicated " << g.numDuplicated() << ", tips "
        << g.numTips() << ")\n"
        << "    length:       " << g.length() << "\n";
    for (Index i : {Index(0), n - 1}) {
      const Point& p = mesh.points[g.node[i]];
      std::string what;
      switch (g.kind[i]) {
        case FractureNodeKind::tip:
          what = "tip inside the body (single node)";
          break;
        case FractureNodeKind::abutting:
          what = "ends on the junction with " + othersAt(split, f, g.node[i]) +
                 " (its jump held there)";
          break;
        case FractureNodeKind::joined:
          what = "joined end to end with " + othersAt(split, f, g.node[i]) + " (one node of both)";
          break;
        default:
          what = "on the outer boundary, " + patchesAt(mesh, g.node[i], fractureLabels) +
                 " (duplicated)";
      }
      out << "    " << (i == 0 ? "start:        " : "end:          ") << formatPoint(p, mesh.dim)
          << " " << what << "\n";
    }
    if (g.numOfKind(FractureNodeKind::crossing) > 0)
      out << "    crossings:    " << g.numOfKind(FractureNodeKind::crossing)
          << " (junctions it passes through)\n";
    out << "    normal:       " << point(g.normal[0].head<2>()) << " at the start (from Omega+ to "
        << "Omega-; tangent " << point(g.tangent[0]) << ")\n\n";
  }

  printJunctions(out, mesh, split);
  const SplitMesh& s = split;
  out << "Split mesh\n"
      << "    points:    " << s.mesh.numPoints() << " (+" << s.mesh.numPoints() - mesh.numPoints()
      << ")\n"
      << "    triangles: " << s.mesh.numCells() << "\n"
      << "    area:      " << s.mesh.totalMeasure() << "\n\n";
}

}  // namespace

SplitMesh splitCase(const std::string& caseDir, const SplitCaseOptions& options,
                    std::ostream& log) {
  // 2. Read and validate the case's mesh dictionary before any work.
  const MeshSettings settings = MeshSettings::read(caseDir);

  // 3. Never split twice: the output exists unless the user asks to redo it.
  const fs::path output = fs::path(caseDir) / "constant" / "splitMesh";
  if (fs::exists(output) && !options.overwrite)
    throw InputError(output.string(), "the case is already split; " + options.program +
                                          " splits the mesh of system/meshDict once. " +
                                          options.overwriteHint + " to split it again (from '" +
                                          settings.meshFile + "'), or ./Allclean the case");

  // 4. Read the mesh and name its patches; record what the split is made from (hashed
  //    before reading, so that a mesh changed meanwhile makes the record stale, not wrong).
  SplitMeshRecord madeFrom{settings.meshEntry, fileHash(settings.meshFile),
                           fileHash(settings.dictPath)};
  Mesh mesh = readMesh(settings.meshFile);
  settings.nameLabels(mesh);
  const std::vector<FractureSpec> specs = settings.fractureSpecs(mesh);

  // 5. What the file does not say but the result depends on: hidden cuts and unlabelled
  //    boundary edges (refused unless meshDict accepts them).
  const MeshSettings::MeshFindings findings = settings.checkMesh(mesh);

  // 6. Split, summarise, write (atomically: a failed run leaves no output). A 3D mesh is
  //    summarised and checked; splitFractures then refuses it (not supported yet).
  SplitMesh split = splitFractures(mesh, specs);
  split.madeFrom = std::move(madeFrom);
  std::set<int> fractureLabels;
  for (const auto& s : specs) fractureLabels.insert(s.label);
  printSummary(log, mesh, split, fractureLabels);
  printChecks(log, mesh, settings, findings);

  std::error_code ec;
  fs::create_directories(output.parent_path(), ec);
  if (ec)
    throw InputError(output.parent_path().string(),
                     "cannot create the output folder (" + ec.message() +
                         "); expected a writable folder for constant/splitMesh");
  writeSplitMesh(split, output.string());
  log << "Wrote " << output.string() << "\n";
  return split;
}

}  // namespace friction
