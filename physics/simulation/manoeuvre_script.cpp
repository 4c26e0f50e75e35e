#include "physics/simulation/manoeuvre_script.hpp"

#include <cctype>

namespace scenfuzz {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

LaneSide named_side(std::string_view key, LaneSide otherwise) {
  if (key.find("left") != std::string_view::npos) return LaneSide::left;
  if (key.find("right") != std::string_view::npos) return LaneSide::right;
  return otherwise;
}

}  // namespace

std::optional<PrimitiveChoice> motion_primitive_named(std::string_view manoeuvre) {
  std::string key;
  for (char c : manoeuvre)
    if (std::isalnum(static_cast<unsigned char>(c)))
      key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // Before the cut-ins and cut-outs, which would otherwise claim Reverse_CutIn and _CutOut.
  if (starts_with(key, "reverse")) {
    if (ends_with(key, "cutin"))
      return PrimitiveChoice{MotionPrimitive::reverse_cut_in, LaneSide::towards_reference};
    if (ends_with(key, "cutout"))
      return PrimitiveChoice{MotionPrimitive::reverse_cut_out, LaneSide::left_else_right};
    if (ends_with(key, "away")) return PrimitiveChoice{MotionPrimitive::reverse_away, {}};
    return PrimitiveChoice{MotionPrimitive::reverse_towards, {}};
  }
  if (ends_with(key, "cutin"))
    return PrimitiveChoice{MotionPrimitive::cut_in, named_side(key, LaneSide::towards_reference)};
  if (ends_with(key, "cutout"))
    return PrimitiveChoice{MotionPrimitive::lane_change,
                           named_side(key, LaneSide::left_else_right)};
  if (starts_with(key, "lanechange"))
    return PrimitiveChoice{MotionPrimitive::lane_change,
                           named_side(key, LaneSide::left_else_right)};
  if (starts_with(key, "overtake"))
    return PrimitiveChoice{MotionPrimitive::overtake, LaneSide::left};
  if (starts_with(key, "stopped")) return PrimitiveChoice{MotionPrimitive::stopped, {}};
  if (starts_with(key, "stop")) return PrimitiveChoice{MotionPrimitive::stop, {}};
  if (starts_with(key, "turnleft")) return PrimitiveChoice{MotionPrimitive::turn_left, {}};
  if (starts_with(key, "turnright")) return PrimitiveChoice{MotionPrimitive::turn_right, {}};
  if (starts_with(key, "collide")) return PrimitiveChoice{MotionPrimitive::collide, {}};
  if (starts_with(key, "walk") || starts_with(key, "run") || starts_with(key, "slide")) {
    if (ends_with(key, "cross")) return PrimitiveChoice{MotionPrimitive::walk_cross, {}};
    if (ends_with(key, "towards")) return PrimitiveChoice{MotionPrimitive::walk_towards, {}};
    if (ends_with(key, "away")) return PrimitiveChoice{MotionPrimitive::walk_away, {}};
    return PrimitiveChoice{MotionPrimitive::walk, {}};
  }
  if (starts_with(key, "drive") || starts_with(key, "misc"))
    return PrimitiveChoice{MotionPrimitive::keep_lane, {}};
  return std::nullopt;
}

bool reverses(MotionPrimitive primitive) {
  return primitive == MotionPrimitive::reverse_towards ||
         primitive == MotionPrimitive::reverse_away ||
         primitive == MotionPrimitive::reverse_cut_in ||
         primitive == MotionPrimitive::reverse_cut_out;
}

}  // namespace scenfuzz
