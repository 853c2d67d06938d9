// MeshSettings: the case's system/meshDict — which mesh file the case uses, the names of its
// numeric labels, and which patches are fractures. Validated completely (unknown keys are
// errors) before any work is done.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "friction/core/InputError.hpp"
#include "friction/fracture/SplitMesh.hpp"
#include "friction/mesh/Mesh.hpp"

namespace friction {

struct MeshSettings {
  std::string caseDir;
  std::string dictPath;   ///< caseDir/system/meshDict, as used in messages
  std::string meshFile;   ///< path of the mesh file (caseDir joined with the 'mesh' entry)
  std::string meshEntry;  ///< the 'mesh' entry as written (relative to the case folder)
  SourceLocation meshWhere;

  /// 'defaultPatch': the patch that collects the boundary edges no label covers; empty
  /// (the default) refuses such edges.
  std::string defaultPatch;
  SourceLocation defaultPatchWhere;
  /// 'allowCoincidentNodes': accept vertices at one place that share no edge (a cut the
  /// mesh hides); default no.
  bool allowCoincidentNodes = false;

  struct PatchName {
    std::string name;
    int label = 0;
    SourceLocation where;
  };
  /// Entries of the optional 'patches' block: name -> numeric label.
  std::vector<PatchName> patches;

  struct FractureName {
    std::string name;
    SourceLocation where;
  };
  /// Entries of 'fractures': patch names whose nodes are split.
  std::vector<FractureName> fractures;

  /// Read and validate caseDir/system/meshDict. Throws InputError (file:line:key) on any
  /// problem, including a mesh file that does not exist (unless meshMustExist is false: the
  /// FreeFEM plug-in writes it) or a 'mesh' entry that names a folder.
  static MeshSettings read(const std::string& caseDir, bool meshMustExist = true);

  /// Give every label that occurs in the mesh a name: the 'patches' block first, then the
  /// names the mesh file carries (gmsh physical names), else "patch<label>". Errors: a
  /// 'patches' label absent from the mesh, one label with two names, one name for two labels.
  void nameLabels(Mesh& mesh) const;

  /// The fractures as labels of the (named) mesh. Error if a name is not a patch of the mesh
  /// (the message lists the patches and suggests the nearest).
  std::vector<FractureSpec> fractureSpecs(const Mesh& mesh) const;

  /// What checkMesh found, for the split summary.
  struct MeshFindings {
    std::vector<std::pair<Index, Index>> coincident;  ///< see coincidentPoints
    std::vector<Index> unlabelled;  ///< mesh.dim vertices each: see unlabelledBoundaryFacets
    int defaultPatchLabel = -1;     ///< label that took the unlabelled edges, -1 if none
  };

  /// After nameLabels: find coincident vertices and unlabelled boundary edges (MeshCheck.hpp)
  /// and refuse them (InputError naming the mesh file, counts and a few coordinates, and the
  /// meshDict key that accepts them) unless allowCoincidentNodes / defaultPatch accept them.
  /// The unlabelled edges join the patch 'defaultPatch': a new label, or the label of the
  /// boundary patch of that name if the mesh has one (never a fracture).
  MeshFindings checkMesh(Mesh& mesh) const;
};

}  // namespace friction
