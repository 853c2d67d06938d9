// InputError: the one exception type for anything the user supplied (case dictionaries,
// meshes, command-line options, output folders).
//
// The message always says where (file, and line when known), what (the key or item) and
// what was expected, so that a user can fix the input without reading the code.
#pragma once

#include <stdexcept>
#include <string>

namespace friction {

/// Where a piece of user input came from. line == 0 means "the file as a whole".
struct SourceLocation {
  std::string file;
  int line = 0;

  /// "file:line" (or "file" when the line is unknown).
  std::string str() const;
};

/// Error in user input. what() is "file:line: message"; location() and message() give the
/// parts separately for tests and for callers that want to re-wrap the message. Control bytes
/// in what() and message() are escaped (\0, \x01: VisibleText.hpp), so that a NUL the user
/// wrote cannot cut the message short.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  /// Error about a file as a whole (no line), e.g. "cannot open".
  InputError(const std::string& file, const std::string& message);

  const SourceLocation& location() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace friction
