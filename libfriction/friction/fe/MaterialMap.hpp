// MaterialMap: the material of each cell (docs/method.md §1). Either one material for the
// whole body (constant/mechanicalProperties with E, nu or lambda, mu at the top level, as
// before regions existed) or one per mesh region (FreeFEM region, gmsh physical surface in 2D
// or volume in 3D): a 'regions' sub-dictionary keyed by the region's name or by region<N> (N
// its number), with an optional 'default' entry for the regions not listed. planeStress stays one
// key for the body.
#pragma once

#include <string>
#include <vector>

#include "friction/core/Types.hpp"
#include "friction/fe/Material.hpp"

namespace friction {

class Dictionary;
struct Mesh;
struct SourceLocation;

/// The number of the region of `mesh` that the dictionary key `key` (at `where`) names: the
/// mesh's name for the region, or region<N> with N its number. Otherwise an InputError at
/// `where` naming the key, with a suggestion and the regions available. `withDefault`: the
/// key may also be 'default' (MaterialMap's entries; the caller handles it), which the
/// message then offers.
int meshRegionOf(const std::string& key, const SourceLocation& where, const Mesh& mesh,
                 bool withDefault = false);

class MaterialMap {
 public:
  /// A region of the mesh and the material its cells take (regions form only).
  struct Region {
    int number = 0;     ///< the mesh's region number (FreeFEM region, gmsh physical tag)
    std::string name;   ///< the mesh's name for it ("" when the mesh names none)
    std::string entry;  ///< the key of 'regions' that gave its material (name, region<N>, default)
    Index cells = 0;    ///< how many cells of the mesh it holds
    int material = 0;   ///< index into materials()
  };

  /// One material for every cell. Implicit on purpose: wherever a map is asked for, one
  /// material serves as the map of a homogeneous body.
  MaterialMap(const Material& material);  // NOLINT(google-explicit-constructor)

  /// From constant/mechanicalProperties and the mesh whose cells it describes: the flat form
  /// (Material::read), or 'regions' { <name or region<N>> { E ..; nu ..; } ... default { .. } }.
  /// Every region with cells gets exactly one entry (or the default); InputErrors name the
  /// file, line and key: an entry that is no region of the mesh (with a suggestion and the
  /// regions available), a region given twice (by name and by number), regions without a
  /// material (listed, with the names available), the flat keys and 'regions' together.
  static MaterialMap read(const Dictionary& dict, const Mesh& mesh);

  /// True when one material serves every cell (the flat form).
  bool uniform() const { return cellMaterial_.empty(); }
  /// The material of cell c (any c when uniform()).
  const Material& ofCell(Index c) const {
    return cellMaterial_.empty() ? materials_.front() : materials_[cellMaterial_[c]];
  }
  /// The materials, one per 'regions' entry used (one in the flat form).
  const std::vector<Material>& materials() const { return materials_; }
  /// The mesh's regions in increasing number (empty in the flat form).
  const std::vector<Region>& regions() const { return regions_; }
  bool planeStress() const { return materials_.front().planeStress(); }

  /// Largest Young's modulus [Pa] and Poisson's ratio among the materials in use.
  double maxYoungModulus() const;
  double maxPoissonRatio() const;
  /// Largest Young's modulus [Pa] among the given cells (of maxYoungModulus() if none).
  double maxYoungModulus(const std::vector<Index>& cells) const;

 private:
  MaterialMap() = default;

  std::vector<Material> materials_;
  std::vector<int> cellMaterial_;  ///< empty when uniform
  std::vector<Region> regions_;
};

}  // namespace friction
