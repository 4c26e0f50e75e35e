// Which lanes traffic entering from a stop- or yield-controlled lane merges into or crosses: the
// lane past the line, the lanes up to two successors on (a roundabout's entry and its ring, a
// junction connector and the lane it leads into), and the junction lanes that meet any of them.
// The responsibility oracle gives a sign's priority to a vehicle on one of them whatever the angle
// at which the two meet. Private to the responsibility oracle.
#pragma once

#include "physics/map/road_map.hpp"

namespace scenfuzz {

// Whether a vehicle on `lane` is in the traffic that one entering on `entry` has to give way to.
bool merges_with(const RoadMap& map, LaneIndex entry, LaneIndex lane);

}  // namespace scenfuzz
