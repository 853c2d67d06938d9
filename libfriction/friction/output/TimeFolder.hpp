// TimeFolder: writes one time folder atomically, never in place. Files go to
// <case>/.<name>.partial/; commit() renames it to <case>/<name>. A run that dies before commit()
// leaves earlier time folders untouched and no half-written <name>; the destructor removes an
// uncommitted partial folder.
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
  /// Make the folder appear under its final name (replacing an older folder of that name).
  void commit();
  /// The final path <case>/<name>.
  const std::string& finalPath() const { return final_; }

  /// Remove what killed runs leave in caseDir: folders.<name>.partial (never committed) and
  ///.<name>.old (killed inside commit() while replacing a folder). Returns how many.
  static int removeLeftovers(const std::string& caseDir);

 private:
  std::string partial_, final_;
  bool committed_ = false;
};

}  // namespace friction
