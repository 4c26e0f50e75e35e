// Where two lanes' traffic meets: centre lines that cross (a junction's crossing movements) or
// lanes that run into the same lane (merging movements). Reactive NPCs give way by it, and the
// responsibility oracle decides junction priority by it.
#pragma once

#include <span>
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

// Where a path through lanes `own` meets a conflicting lane: `s` along that lane.
struct ConflictPoint {
  LaneIndex lane = 0;
  double s = 0;
};

// Where lanes `own` (a route's junction lanes) meet each of `conflicts` (conflicting_lanes):
// where a centre line crosses one of them, or, merging, where one of them ends on it (a roundabout
// entry joins its ring part way round). A lane of `own` does not meet itself: a route round a
// ring has only the point where its entry joins it. Merging needs the lane's end on the other,
// within 1 m: two roundabout entries share the ring as successor but never meet, and an exit
// leaving the ring does not meet it either.
std::vector<ConflictPoint> conflict_points(const RoadMap& map, std::span<const LaneIndex> own,
                                           std::span<const LaneIndex> conflicts);

}  // namespace scenfuzz
