// Where a vehicle driving a path drawn before the run (a waypoint NPC, waypoint_path.hpp: lane
// legs and OMPL legs alike) shows its indicators: the path's lane changes and junction turns as
// indication stretches in path arc length, which indicator_at (route_indications.hpp) then reads
// with the same notice as for a lane route. The path is read as the map sees it, so the rule does
// not depend on how a leg was made:
//   - a lane change is where the lane under the path (as LaneTracker finds it) becomes a
//     neighbour of the one before (or of a lane following it); it lasts while the path moves
//     sideways towards that neighbour around the crossing, and indicates towards it;
//   - a junction turn is a run of path points on one junction's lanes; it indicates as the lane
//     the path lies on most of the way through turns (junction_lane_indicator), from kTurnNotice
//     before the entry; round a roundabout (a run through a ring lane) only the exit is
//     indicated, from where the exit lane leaves the ring, as for a lane route.
#pragma once

#include <vector>

#include "physics/ego/route_indications.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// The stretches of `path` (empty for an empty path), sorted by begin. `widest_half_lane` is the
// map's (lane_tracker.hpp), worked out once for all the paths on it.
std::vector<IndicationStretch> path_indications(const RoadMap& map, const Polyline& path,
                                                double widest_half_lane);

}  // namespace scenfuzz
