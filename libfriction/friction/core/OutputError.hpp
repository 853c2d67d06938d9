// OutputError: a file or folder the program writes cannot be written (disk full, no
// permission, a folder that vanished). It names the file, like every InputError, and is one
// (so every main that reports input errors reports it too); frictionSolver tells it apart
// and exits with status 6 rather than 1.
#pragma once

#include "friction/core/InputError.hpp"

namespace friction {

class OutputError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace friction
