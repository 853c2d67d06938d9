#include "friction/control/Complementarity.hpp"

namespace friction {

const char* toString(SlipState s) {
  switch (s) {
    case SlipState::open:
      return "open";
    case SlipState::stick:
      return "stick";
    case SlipState::slip:
      return "slip";
  }
  return "?";
}

}  // namespace friction
