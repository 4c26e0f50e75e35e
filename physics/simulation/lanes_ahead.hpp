// The lanes an actor that knows only its lane position will drive next, walked from where it is
// along the lanes its driver picks at each fork: what lane cruising, a manoeuvre phase's limits
// and the junction rule for phases look along.
#pragma once

#include <functional>
#include <vector>

#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

// The lane an actor takes after `lane` (itself at a dead end).
using NextLane = std::function<LaneIndex(LaneIndex)>;

struct LaneAhead {
  LaneIndex lane = 0;
  double offset = 0;  // route distance from the actor to the lane's s = 0 (negative for its own)
};

// The lanes from `at` on (its own first) until one ends beyond `reach` m; `dead_end` says whether
// the walk stopped at a lane leading nowhere.
std::vector<LaneAhead> lanes_ahead(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                                   double reach, bool& dead_end);

// How far ahead (m) an actor moving at `speed` watches: 6 s of travel, and at least 40 m.
double lane_lookahead(double speed);

}  // namespace scenfuzz
