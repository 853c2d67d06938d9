// Checked writes, for every writer of the project:
//  * writeTextAtomic: a reader, a crash or a kill sees either the old file or the complete
//    new one — a temporary file ".<name>.tmpXXXXXX" beside the target, flushed to disk,
//    renamed over it (and the rename made durable);
//  * AppendFile: a log-like file grown by whole records (postProcessing/convergence.dat);
//    a record that cannot be written whole is cut back off and the write throws.
// Failures throw OutputError naming the file (disk full, no permission, missing folder).
#pragma once

#include <sys/types.h>

#include <string>

#include "friction/core/OutputError.hpp"

namespace friction {

void writeTextAtomic(const std::string& path, const std::string& text);

/// Remove the temporary files writeTextAtomic leaves in `folder` when the process is killed
/// between creating and renaming them. Returns how many were removed.
int removeTemporaryFiles(const std::string& folder);

class AppendFile {
 public:
  /// Open (create) `path` for appending; `truncate` empties it first.
  AppendFile(const std::string& path, bool truncate);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Append `text` (whole records) or throw OutputError, leaving the file as it was.
  void append(const std::string& text);
  /// Flush what was appended to disk (before a time folder that depends on it is committed).
  void sync();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  off_t size_ = 0;
};

}  // namespace friction
