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
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct PriorityTrafficSettings {
  double critical_gap = 6.5;  // s until a vehicle with the way reaches the ego's path
  double moving_speed = 1.0;  // m/s: slower, a vehicle waits at its own line (first come, first go)
  double watch = 100;         // m from the ego within which vehicles are looked at
};

// Whether the ego must still give way to one of `objects`: a moving vehicle on a conflicting lane
// within a body length of a conflict point, or short of it and reaching it within the critical
// gap (a lane that runs round into itself, a roundabout's ring, counts the way round), or one on a
// lane leading there that reaches that conflicting lane within it. Traffic that gives way itself
// (a stop or yield sign on its lane or one leading into it) has no priority over the ego. A vehicle
// past the point has gone; a standing one is first come, first go.
// Whether a vehicle of `length` at `s` on `lane` is short of, or still on, one of the conflict
// points on that lane (a lane without one counts as short of it): not yet past the ego's path.
// On a lane that runs round into itself (a roundabout's ring) every point lies ahead the way
// round, so only one within `reach` metres ahead counts.
bool short_of_conflict(const RoadMap& map, std::span<const ConflictPoint> points, LaneIndex lane,
                       double s, double length, double reach);

bool priority_traffic(const RoadMap& map, std::span<const ConflictPoint> points,
                      std::span<const WorldObject> objects, MapPoint ego,
                      const PriorityTrafficSettings& settings = {});

}  // namespace scenfuzz
