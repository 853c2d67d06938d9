// system/meshDict: see MeshSettings.hpp.
#include "friction/case/MeshSettings.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"

namespace friction {

namespace fs = std::filesystem;

MeshSettings MeshSettings::read(const std::string& caseDir) {
  MeshSettings s;
  s.caseDir = caseDir;
  s.dictPath = (fs::path(caseDir) / "system" / "meshDict").lexically_normal().string();
  if (!fs::is_directory(caseDir))
    throw InputError(caseDir, fs::exists(caseDir)
                                  ? "is not a folder (expected a case folder holding "
                                    "system/meshDict; see -case)"
                                  : "the case folder does not exist (see -case)");
  if (!fs::exists(s.dictPath))
    throw InputError(s.dictPath, "cannot open: the case has no system/meshDict (is -case "
                                 "pointing at a case folder?)");
  const Dictionary dict = Dictionary::read(s.dictPath);

  const std::string mesh = dict.getFileName("mesh");
  s.meshWhere = dict.location("mesh");
  s.meshFile = (fs::path(caseDir) / mesh).lexically_normal().string();
  if (!fs::is_regular_file(s.meshFile))
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

  dict.checkAllRead();
  return s;
}

void MeshSettings::nameLabels(Mesh& mesh) const {
  const std::set<int> present(mesh.edgeLabel.begin(), mesh.edgeLabel.end());
  std::map<int, std::string> names;
  for (const PatchName& p : patches) {
    if (!present.count(p.label)) {
      std::string list;
      for (int l : present) list += " " + std::to_string(l);
      throw InputError(p.where, "patch '" + p.name + "': label " + std::to_string(p.label) +
                                    " does not occur among the edges of " + mesh.source +
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
      const bool word = !n.empty() && (std::isalpha(static_cast<unsigned char>(n[0])) || n[0] == '_') &&
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

}  // namespace friction
