// Which side of a body a contact touches, in the body's own frame (front = its heading).
#pragma once

#include <string_view>

namespace scenfuzz {

enum class BodySide { front, rear, left, right };

std::string_view body_side_name(BodySide side);

}  // namespace scenfuzz
