// Giving way at a stop or yield sign, as a driver entering a priority road does: whether a
// vehicle with the way is inside the junction on a lane that crosses or merges with the ego's, or
// will reach such a lane sooner than a critical gap, the least time gap a driver accepts to pull
// out into or across traffic (the Highway Capacity Manual's critical headways for a minor-road
// movement at a two-way stop are 6.2 s turning right, 6.5 s going straight, 7.1 s turning left;
// at a roundabout entry 4.1-5.2 s). The reactive NPCs give way by the same reading of the map
// (lane_follower.cpp, crossing_traffic), from their true state; the driver reads what it perceives.
#pragma once

#include <span>
#include <vector>

#include "physics/ego/perception.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct PriorityTrafficSettings {
  double critical_gap = 6.5;  // s until a vehicle with the way reaches a conflicting lane
  double moving_speed = 1.0;  // m/s: slower, a vehicle waits at its own line (first come, first go)
  double watch = 100;         // m from the ego within which vehicles are looked at
};

// Whether the ego, about to enter the junction lanes whose conflicting lanes are `conflicts`
// (ascending, as conflicting_lanes gives them), must still give way to one of `objects`.
bool priority_traffic(const RoadMap& map, const std::vector<LaneIndex>& conflicts,
                      std::span<const WorldObject> objects, MapPoint ego,
                      const PriorityTrafficSettings& settings = {});

}  // namespace scenfuzz
