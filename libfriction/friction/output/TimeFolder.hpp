// TimeFolder: writes one time folder atomically, never in place. Files go to
// <case>/.<name>.partial/; commit() renames it to <case>/<name>. A run that dies before commit()
// leaves earlier time folders untouched and no half-written <name>; the destructor removes an
// uncommitted partial folder. A folder of that name that the solver did not write (see
// notWrittenBySolver) is never replaced: commit() refuses it.
#pragma once

#include <string>

namespace friction {

class TimeFolder {
 public:
  /// Throws OutputError naming the folder if it cannot be created (unwritable case, full disk).
  TimeFolder(const std::string& caseDir, const std::string& name);
  ~TimeFolder();
  TimeFolder(const TimeFolder&) = delete;
  TimeFolder& operator=(const TimeFolder&) = delete;

  /// Path of a file inside the (partial) folder; creates its parent folders.
  std::string file(const std::string& relative) const;
  /// Make the folder appear under its final name, replacing an older folder of that name if
  /// the solver wrote it; one it did not write is left as it is (OutputError naming it and why).
  void commit();
  /// The final path <case>/<name>.
  const std::string& finalPath() const { return final_; }

  /// Remove what killed runs leave in caseDir: folders.<name>.partial (never committed) and
  ///.<name>.old (killed inside commit() while replacing a folder). Returns how many.
  static int removeLeftovers(const std::string& caseDir);

  /// Why the folder `path` is not a time folder frictionSolver wrote ("it has no
  /// uniform/frictionState", "it holds 'notes.txt', which frictionSolver does not write"), or
  /// "" when it is one: it holds uniform/frictionState and nothing but what
  /// FrictionCase::writeTimeFolder writes there (D, solverStatus, uniform/frictionState,
  /// fractures/<name>.dat). Such a folder is never removed or replaced.
  static std::string notWrittenBySolver(const std::string& path);

 private:
  std::string partial_, final_;
  bool committed_ = false;
};

}  // namespace friction
