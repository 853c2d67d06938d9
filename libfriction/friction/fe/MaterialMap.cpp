// MaterialMap: one material, or one per mesh region (docs/method.md §1).
#include "friction/fe/MaterialMap.hpp"

#include <algorithm>
#include <map>

#include "friction/core/Assert.hpp"
#include "friction/core/Suggest.hpp"
#include "friction/dict/Dictionary.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

namespace {

/// "reservoir (region 1, 120 triangles)" or "region 3 (40 tetrahedra)".
std::string describe(const MaterialMap::Region& r, int dim) {
  const std::string cells = std::to_string(r.cells) + (dim == 3 ? " tetrahedra" : " triangles");
  if (r.name.empty()) return "region " + std::to_string(r.number) + " (" + cells + ")";
  return "'" + r.name + "' (region " + std::to_string(r.number) + ", " + cells + ")";
}

/// "region<N>" (N an integer, as the mesh numbers its regions): N.
bool regionNumberOf(const std::string& word, int& value) {
  const std::string prefix = "region";
  if (word.rfind(prefix, 0) != 0) return false;
  const std::string digits = word.substr(prefix.size());
  if (digits.empty() || digits.size() > 9) return false;
  for (char ch : digits)
    if (ch < '0' || ch > '9') return false;
  value = std::stoi(digits);
  return true;
}

/// The regions of the mesh by number: those with cells, and those the mesh names (gmsh may
/// name a physical group that holds no cell).
std::map<int, MaterialMap::Region> regionsOf(const Mesh& mesh) {
  std::map<int, MaterialMap::Region> regions;
  for (int r : mesh.cellRegion) ++regions[r].cells;
  for (const auto& [number, name] : mesh.regionNames) regions[number].name = name;
  for (auto& [number, r] : regions) r.number = number;
  return regions;
}

/// "reservoir (region1)" or "region3", per region: the messages' list.
std::vector<std::string> availableRegions(const std::map<int, MaterialMap::Region>& regions) {
  std::vector<std::string> available;
  for (const auto& [number, r] : regions)
    available.push_back(r.name.empty() ? "region" + std::to_string(number)
                                       : r.name + " (region" + std::to_string(number) + ")");
  return available;
}

}  // namespace

int meshRegionOf(const std::string& key, const SourceLocation& where, const Mesh& mesh,
                 bool withDefault) {
  const std::map<int, MaterialMap::Region> regions = regionsOf(mesh);
  for (const auto& [number, r] : regions)
    if (r.name == key) return number;
  int number = 0;
  if (regionNumberOf(key, number) && regions.count(number)) return number;
  std::vector<std::string> candidates;
  if (withDefault) candidates.push_back("default");
  for (const auto& [n, r] : regions) {
    if (!r.name.empty()) candidates.push_back(r.name);
    candidates.push_back("region" + std::to_string(n));
  }
  throw InputError(
      where,
      "'" + key + "' is no region of the mesh " + mesh.source + suggestionText(key, candidates) +
          " (regions: " + joinWords(availableRegions(regions)) +
          (withDefault ? "; an entry is a region's name, region<number>, or 'default'"
                       : "; an entry is a region's name or region<number>") +
          (mesh.regionNames.empty() ? "; the mesh names no region (a split mesh keeps the names "
                                      "only when its cells lie in several regions): use "
                                      "region<number>)"
                                    : ")"));
}

MaterialMap::MaterialMap(const Material& material) : materials_{material} {}

MaterialMap MaterialMap::read(const Dictionary& dict, const Mesh& mesh) {
  if (!dict.found("regions")) return MaterialMap(Material::read(dict, mesh.dim));
  if (!dict.isDict("regions"))
    dict.fail("regions",
              "key 'regions': expected a sub-dictionary of one entry per mesh region, e.g. "
              "regions { reservoir { E 10e9; nu 0.25; } caprock { E 30e9; nu 0.3; } }");
  for (const char* key : {"E", "nu", "lambda", "mu", "K", "G"})
    if (dict.found(key))
      dict.fail(key,
                "key '" + std::string(key) +
                    "' together with 'regions': give the material once for the whole "
                    "body (E, nu or lambda, mu or K, G here) or per region inside 'regions', not "
                    "both");
  if (mesh.dim == 3 && dict.found("planeStress"))
    dict.fail("planeStress",
              "key 'planeStress' has no meaning in 3D (the mesh is 3D: every strain component is "
              "resolved, there is no plane); remove it");
  const bool planeStress = dict.getBoolOr("planeStress", false);
  const Dictionary& entries = dict.subDict("regions");

  // The regions of the mesh: those with cells, and those the mesh names (gmsh may name a
  // physical group that holds no cell).
  std::map<int, Region> regions = regionsOf(mesh);
  std::vector<std::string> available = availableRegions(regions);

  MaterialMap map;
  int defaultMaterial = -1;
  for (const std::string& key : entries.keys()) {
    if (!entries.isDict(key))
      entries.fail(key, "key '" + key +
                            "': expected a sub-dictionary with the region's material { E ..; "
                            "nu ..; } or { lambda ..; mu ..; }");
    const Dictionary& entry = entries.subDict(key);
    if (entry.found("planeStress"))
      entry.fail("planeStress",
                 "key 'planeStress' is one setting for the whole body: put it beside 'regions' "
                 "(in " +
                     dict.scope() + "), not inside a region's entry");
    Region* target = nullptr;
    if (key != "default") {
      target = &regions[meshRegionOf(key, entries.location(key), mesh, true)];
      if (!target->entry.empty())
        entries.fail(key, "region " + describe(*target, mesh.dim) + " has two entries, '" +
                              target->entry + "' and '" + key + "' (expected one per region)");
      target->entry = key;
    }
    map.materials_.push_back(Material::readConstants(entry, planeStress));
    const int index = static_cast<int>(map.materials_.size()) - 1;
    if (target)
      target->material = index;
    else
      defaultMaterial = index;
  }
  std::vector<std::string> missing;
  for (auto& [number, r] : regions) {
    if (!r.entry.empty()) continue;
    if (defaultMaterial >= 0) {
      r.entry = "default";
      r.material = defaultMaterial;
    } else if (r.cells > 0) {
      missing.push_back(describe(r, mesh.dim));
    }
  }
  if (!missing.empty())
    dict.fail("regions", "key 'regions': no material for " + joinWords(missing) +
                             " (expected an entry for every region of the mesh " + mesh.source +
                             ", by name or as region<number>, or a 'default' entry; regions: " +
                             joinWords(available) + ")");
  FRICTION_ASSERT(!map.materials_.empty(), "a mesh has cells, so some region has a material");
  std::map<int, int> indexOf;
  for (const auto& [number, r] : regions) {
    if (r.entry.empty()) continue;  // a named region without cells and without an entry
    indexOf[number] = r.material;
    map.regions_.push_back(r);
  }
  map.cellMaterial_.reserve(mesh.cellRegion.size());
  for (int r : mesh.cellRegion) map.cellMaterial_.push_back(indexOf.at(r));
  return map;
}

double MaterialMap::maxYoungModulus() const {
  if (uniform()) return materials_.front().youngModulus();
  double e = 0;
  for (const Region& r : regions_)
    if (r.cells > 0) e = std::max(e, materials_[r.material].youngModulus());
  return e;
}

double MaterialMap::maxPoissonRatio() const {
  if (uniform()) return materials_.front().poissonRatio();
  double nu = -1;
  for (const Region& r : regions_)
    if (r.cells > 0) nu = std::max(nu, materials_[r.material].poissonRatio());
  return nu;
}

double MaterialMap::maxYoungModulus(const std::vector<Index>& cells) const {
  if (uniform() || cells.empty()) return maxYoungModulus();
  double e = 0;
  for (Index c : cells) e = std::max(e, ofCell(c).youngModulus());
  return e;
}

}  // namespace friction
