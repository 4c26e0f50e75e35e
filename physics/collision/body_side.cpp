// Names of body sides, as traces and reports print them.
#include "physics/collision/body_side.hpp"

namespace scenfuzz {

std::string_view body_side_name(BodySide side) {
  switch (side) {
    case BodySide::front: return "front";
    case BodySide::rear: return "rear";
    case BodySide::left: return "left";
    case BodySide::right: return "right";
  }
  return "unknown";
}

}  // namespace scenfuzz
