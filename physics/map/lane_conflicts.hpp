// Where two lanes' traffic meets: centre lines that cross (a junction's crossing movements) or
// lanes that run into the same lane (merging movements). Reactive NPCs give way by it, and the
// responsibility oracle decides junction priority by it.
#pragma once

#include <vector>

#include "physics/map/polyline.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// Whether any segment of one polyline properly crosses any segment of the other.
bool lines_cross(const Polyline& first, const Polyline& second);

// Whether the two lanes have a successor in common.
bool shares_successor(const Lane& first, const Lane& second);

// The other lanes of junction lane `lane`'s junction that cross or merge with it (ascending).
std::vector<LaneIndex> conflicting_lanes(const RoadMap& map, LaneIndex lane);

}  // namespace scenfuzz
