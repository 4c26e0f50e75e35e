// Priority to the right at a junction no light or sign controls: of two vehicles whose junction
// lanes cross or merge, the one coming from the other's right has priority (the default rule in
// continental Europe and China; in the US, at an uncontrolled intersection, the one on the right
// when they arrive together). Read from the junction lanes the trace records each vehicle on and
// the lights and signs on those lanes and their approaches. Private to the responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Whose way it was: `priority` came from `yielder`'s right.
struct RightPriority {
  ActorId yielder = kEgo;
  ActorId priority = kEgo;
};

// Whether a light or a stop or yield sign stands on junction lane `lane` or on a lane leading into
// it: its approach is controlled and priority to the right is not the rule there.
bool approach_controlled(const RoadMap& map, LaneIndex lane);

// The priority to the right between the ego and `other` (both vehicles) over samples
// [first, last]: their last junction lanes lie in one junction, meet (cross or merge), neither
// approach is controlled, and one entered from the other's right (its direction at the start of
// its junction lane 45 to 135 degrees counter-clockwise of the other's). nullopt otherwise.
std::optional<RightPriority> right_priority(const Trace& trace, const RoadMap& map, ActorId other,
                                            std::size_t first, std::size_t last);

}  // namespace scenfuzz
