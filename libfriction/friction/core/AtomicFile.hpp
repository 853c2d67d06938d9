// writeTextAtomic: write a file so that a reader, a crash or a kill sees either the old file
// or the complete new one — a temporary file beside the target, flushed to disk, renamed over
// it (and the rename made durable). Used by every writer of the project.
#pragma once

#include <string>

namespace friction {

/// Throws InputError naming the path when the folder is missing, not writable or full.
void writeTextAtomic(const std::string& path, const std::string& text);

}  // namespace friction
