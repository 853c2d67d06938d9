// InputFile: the one way the library opens a file that a case names (a dictionary and what it
// #includes, a values or field file, a mesh, the split mesh and the time folders' state).
//
// Only a regular file is read. A FIFO would block the reader until some other process writes
// to it, a device such as /dev/zero never ends (or reads as empty), a folder or a socket is no
// text at all: each is refused with a message that names the file and where it was named (the
// key or #include and its file:line). The check is made on the open descriptor (fstat), and
// the file is opened with O_NONBLOCK, so that neither opening nor checking can block. A file
// larger than the bound its caller gives is refused before it is read, naming the bound: what
// a reader holds in memory is a multiple of what it reads.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "friction/core/InputError.hpp"

namespace friction {

/// What a file is to the reader that opens it, and who named it, for the messages.
struct InputFileRole {
  /// What the file should be, for "(expected ...)": "a dictionary", "the mesh file ...".
  std::string what;
  /// The largest size read, in bytes; a larger file is refused with this bound in the message.
  std::uint64_t maxBytes = UINT64_MAX;
  /// Where the file is named: the file:line of the key or the #include. Empty file: the path
  /// was given directly (the case's layout, the command line) and messages are located at it.
  SourceLocation namedAt;
  /// How it is named there, the start of the message: "key 'values'", "#include".
  std::string namedBy;
  /// Added to the message of a file above maxBytes: where such data belongs instead.
  std::string tooLargeHint;
};

using InputFileHandle = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

/// Opens path for reading (binary), or throws InputError: the file does not exist, is not a
/// regular file (a folder, a FIFO, a character or block device, a socket), cannot be opened,
/// or is larger than role.maxBytes. Never blocks.
InputFileHandle openInputFile(const std::string& path, const InputFileRole& role);

/// The whole file, after the checks of openInputFile; InputError as there, or on a read error,
/// or when the file grew beyond role.maxBytes while it was read.
std::string readInputFile(const std::string& path, const InputFileRole& role);

/// "8 MiB", "64 MiB", "1.5 GiB", "123 bytes": a size for messages.
std::string formatBytes(std::uint64_t bytes);

}  // namespace friction
