#include "friction/core/InputError.hpp"

namespace friction {

std::string SourceLocation::str() const {
  if (file.empty()) return line > 0 ? "line " + std::to_string(line) : std::string("<input>");
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(where.str() + ": " + message),
      where_(std::move(where)),
      message_(message) {}

InputError::InputError(const std::string& file, const std::string& message)
    : InputError(SourceLocation{file, 0}, message) {}

}  // namespace friction
