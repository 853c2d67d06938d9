// system/meshDict: see MeshSettings.hpp.
#include "friction/case/MeshSettings.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/Geometry>

#include "friction/core/InputFile.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/mesh/MeshCheck.hpp"
#include "friction/mesh/MeshReader.hpp"

namespace friction {

namespace fs = std::filesystem;

MeshSettings MeshSettings::read(const std::string& caseDir, bool meshMustExist) {
  MeshSettings s;
  s.caseDir = caseDir;
  s.dictPath = (fs::path(caseDir) / "system" / "meshDict").lexically_normal().string();
  if (!fs::is_directory(caseDir))
    throw InputError(caseDir, fs::exists(caseDir)
                                  ? "is not a folder (expected a case folder holding "
                                    "system/meshDict; see -case)"
                                  : "the case folder does not exist (see -case)");
  if (!fs::exists(s.dictPath))
    throw InputError(s.dictPath,
                     "cannot open: the case has no system/meshDict (is -case "
                     "pointing at a case folder?)");
  const Dictionary dict = Dictionary::read(s.dictPath);

  const std::string mesh = dict.getFileName("mesh");
  s.meshWhere = dict.location("mesh");
  s.meshEntry = mesh;
  s.meshFile = (fs::path(caseDir) / mesh).lexically_normal().string();
  if (fs::exists(s.meshFile)) {
    // A FIFO, a device or a folder is refused here, at the key that names it (the reader would
    // refuse it too, naming only the path); and so is a file too large to read.
    InputFileRole role;
    role.what = "the mesh file; the path is relative to the case folder";
    role.maxBytes = kMaxMeshFileBytes;
    role.namedAt = s.meshWhere;
    role.namedBy = "key 'mesh'";
    openInputFile(s.meshFile, role);
  }
  if (meshMustExist && !fs::is_regular_file(s.meshFile))
    dict.fail("mesh", "key 'mesh': the mesh file '" + s.meshFile +
                          "' does not exist (the path is relative to the case folder)");

  if (const Dictionary* patches = dict.findDict("patches")) {
    std::map<long, std::string> byLabel;
    for (const std::string& name : patches->keys()) {
      const long label = patches->getInt(name, Bounds::nonNegative());
      auto [it, fresh] = byLabel.emplace(label, name);
      if (!fresh)
        patches->fail(name, "key '" + name + "': label " + std::to_string(label) +
                                " is already named '" + it->second +
                                "'; a label has one patch name");
      s.patches.push_back({name, static_cast<int>(label), patches->location(name)});
    }
  }

  const std::vector<std::string> fractures = dict.getWordList("fractures");
  std::set<std::string> seen;
  for (const std::string& f : fractures) {
    if (!seen.insert(f).second)
      dict.fail("fractures", "key 'fractures': '" + f + "' is listed twice");
    s.fractures.push_back({f, dict.location("fractures")});
  }

  if (dict.found("defaultPatch")) {
    s.defaultPatch = dict.getWord("defaultPatch");
    s.defaultPatchWhere = dict.location("defaultPatch");
    // It becomes a dictionary key (constant/splitMesh, 0/D): a word, as the patch names.
    const std::string& n = s.defaultPatch;
    const bool word = !n.empty() &&
                      (std::isalpha(static_cast<unsigned char>(n[0])) || n[0] == '_') &&
                      std::all_of(n.begin(), n.end(), [](char c) {
                        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
                      });
    if (!word)
      dict.fail("defaultPatch", "key 'defaultPatch': '" + n +
                                    "' is not a valid patch name (letters, digits, '_' and '.', "
                                    "starting with a letter)");
    if (seen.count(s.defaultPatch))
      dict.fail("defaultPatch", "key 'defaultPatch': '" + s.defaultPatch +
                                    "' is a fracture; the unlabelled boundary edges need a "
                                    "boundary patch (a new name, or a boundary patch's name)");
  }
  s.allowCoincidentNodes = dict.getBoolOr("allowCoincidentNodes", false);

  dict.checkAllRead();
  return s;
}

void MeshSettings::nameLabels(Mesh& mesh) const {
  const std::set<int> present(mesh.facetLabel.begin(), mesh.facetLabel.end());
  std::map<int, std::string> names;
  for (const PatchName& p : patches) {
    if (!present.count(p.label)) {
      std::string list;
      for (int l : present) list += " " + std::to_string(l);
      throw InputError(p.where, "patch '" + p.name + "': label " + std::to_string(p.label) +
                                    " does not occur among the " +
                                    std::string(facetName(mesh.dim)) + "s of " + mesh.source +
                                    " (labels present:" + list + ")");
    }
    names[p.label] = p.name;
  }
  std::map<std::string, int> labelOf;
  for (int l : present) {
    if (!names.count(l)) {
      auto it = mesh.labelNames.find(l);
      names[l] = it != mesh.labelNames.end() ? it->second : "patch" + std::to_string(l);
      // Patch names become dictionary keys (constant/splitMesh, 0/D): they must be words.
      const std::string& n = names[l];
      const bool word =
          !n.empty() && (std::isalpha(static_cast<unsigned char>(n[0])) || n[0] == '_') &&
          std::all_of(n.begin(), n.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
          });
      if (!word)
        throw InputError(mesh.source, "physical name '" + n + "' of label " + std::to_string(l) +
                                          " is not a valid patch name (letters, digits, '_' and "
                                          "'.', starting with a letter); name the label in " +
                                          dictPath + ", e.g. patches { myPatch " +
                                          std::to_string(l) + "; }");
    }
    auto [it, fresh] = labelOf.emplace(names[l], l);
    if (!fresh)
      throw InputError(dictPath, "patch name '" + names[l] + "' names two labels of " +
                                     mesh.source + " (" + std::to_string(it->second) + " and " +
                                     std::to_string(l) + "); rename one in 'patches'");
  }
  mesh.labelNames = names;
}

std::vector<FractureSpec> MeshSettings::fractureSpecs(const Mesh& mesh) const {
  std::vector<FractureSpec> specs;
  for (const FractureName& f : fractures) {
    int label = -1;
    std::vector<std::string> valid;
    for (const auto& [l, name] : mesh.labelNames) {
      valid.push_back(name);
      if (name == f.name) label = l;
    }
    if (label < 0)
      throw InputError(f.where, "key 'fractures': '" + f.name + "' is not a patch of " +
                                    mesh.source + suggestionText(f.name, valid) +
                                    " (patches: " + joinWords(valid) + ")");
    specs.push_back({f.name, label, f.where});
  }
  return specs;
}

MeshSettings::MeshFindings MeshSettings::checkMesh(Mesh& mesh) const {
  MeshFindings found;
  found.coincident = coincidentPoints(mesh);
  if (!found.coincident.empty() && !allowCoincidentNodes) {
    std::string where;
    const std::size_t shown = std::min<std::size_t>(found.coincident.size(), 5);
    for (std::size_t i = 0; i < shown; ++i)
      where += (i ? ", " : "") + formatPoint(mesh.points[found.coincident[i].first], mesh.dim);
    if (shown < found.coincident.size()) where += ", ...";
    throw InputError(
        mesh.source,
        std::to_string(found.coincident.size()) +
            " pairs of vertices lie at the same place without sharing " +
            (mesh.dim == 2 ? "a triangle side" : "a tetrahedron edge") + ", at " + where +
            ": a cut hidden in the mesh (e.g. two gmsh curves or points at one place that "
            "were not merged), which the solver would treat as a traction-free crack. Merge "
            "them (gmsh: Coherence, or embed the curve with Curve{c} In Surface{s}; for a "
            "fracture list its patch in 'fractures' of the unsplit mesh), or set "
            "'allowCoincidentNodes yes;' in " +
            dictPath + " if the cut is meant");
  }

  found.unlabelled = unlabelledBoundaryFacets(mesh);
  if (found.unlabelled.empty()) return found;
  const int nf = mesh.verticesPerFacet();
  const std::size_t count = found.unlabelled.size() / nf;
  if (defaultPatch.empty()) {
    // Total length (2D, x and y only as the 2D code always did) or area (3D).
    double measure = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const Index* v = &found.unlabelled[i * nf];
      if (nf == 2)
        measure += (mesh.points[v[1]].head<2>() - mesh.points[v[0]].head<2>()).norm();
      else
        measure += 0.5 * (mesh.points[v[1]] - mesh.points[v[0]])
                             .cross(mesh.points[v[2]] - mesh.points[v[0]])
                             .norm();
    }
    std::string where;
    const std::size_t shown = std::min<std::size_t>(count, 3);
    for (std::size_t i = 0; i < shown; ++i) {
      where += i ? ", " : "";
      for (int k = 0; k < nf; ++k)
        where += (k ? "-" : "") + formatPoint(mesh.points[found.unlabelled[i * nf + k]], mesh.dim);
    }
    if (shown < count) where += ", ...";
    std::ostringstream len;
    len.precision(6);
    len << measure;
    throw InputError(
        mesh.source,
        std::to_string(count) +
            (nf == 2 ? " boundary edges (total length " : " boundary triangles (total area ") +
            len.str() + ") have no label: " + where +
            ". Without one the solver would leave them traction-free unasked. Label them in "
            "the mesh (" +
            (nf == 2 ? "a gmsh Physical Curve, a FreeFEM border label"
                     : "a gmsh Physical Surface, a FreeFEM boundary label") +
            "), or set "
            "'defaultPatch <name>;' in " +
            dictPath + " and give that patch a condition in 0/D (type free for traction-free)");
  }

  // The patch that takes them: an existing boundary patch of that name, else a new label.
  int label = -1;
  int maxLabel = 0;
  for (const auto& [l, name] : mesh.labelNames) {
    maxLabel = std::max(maxLabel, l);
    if (name == defaultPatch) label = l;
  }
  if (label < 0) {
    label = maxLabel + 1;
    mesh.labelNames[label] = defaultPatch;
  }
  mesh.facetVertices.insert(mesh.facetVertices.end(), found.unlabelled.begin(),
                            found.unlabelled.end());
  mesh.facetLabel.insert(mesh.facetLabel.end(), count, label);
  found.defaultPatchLabel = label;
  return found;
}

}  // namespace friction
