#include "friction/core/InputError.hpp"

#include "friction/core/VisibleText.hpp"

namespace friction {

std::string SourceLocation::str() const {
  if (file.empty()) return line > 0 ? "line " + std::to_string(line) : std::string("<input>");
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

// Messages quote what the user wrote; a control byte in it (a NUL in a key) would cut the
// message where it is printed as a C string, or garble the terminal. So they are escaped here,
// once for every message.
InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(escapeControl(where.str() + ": " + message)),
      where_(std::move(where)),
      message_(escapeControl(message)) {}

InputError::InputError(const std::string& file, const std::string& message)
    : InputError(SourceLocation{file, 0}, message) {}

}  // namespace friction
