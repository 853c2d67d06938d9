// splitCase: what splitFractureNodes does to a case folder, for the command-line tool and the
// FreeFEM plug-in alike: read system/meshDict and the mesh it names, check the mesh, split
// the fracture nodes, print the checkMesh-style summary, write constant/splitMesh
// atomically.
#pragma once

#include <iosfwd>
#include <string>

#include "friction/fracture/SplitMesh.hpp"

namespace friction {

struct SplitCaseOptions {
  /// Split again over an existing constant/splitMesh (splitFractureNodes -overwrite).
  bool overwrite = false;
  /// The program, for the refusal of an existing split ("splitFractureNodes splits ...").
  std::string program = "splitFractureNodes";
  /// How the caller's user asks for `overwrite`, in that refusal.
  std::string overwriteHint = "Run with -overwrite";
};

/// Splits the case in caseDir and writes caseDir/constant/splitMesh; returns the split mesh
/// (with its madeFrom record). The summary goes to `log`. InputError (file:line or key, and
/// what was expected) on any problem; nothing is written then.
SplitMesh splitCase(const std::string& caseDir, const SplitCaseOptions& options, std::ostream& log);

}  // namespace friction
