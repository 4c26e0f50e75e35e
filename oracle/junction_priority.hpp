// Priority between vehicles at a junction that no light or sign decides: a vehicle turning left
// across the oncoming lanes gives way to oncoming traffic going straight on or turning right. Read
// from the junction lanes (their `turn`) the trace records each vehicle on. Private to the
// responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Whose way it was: `yielder` turned left and owed the way to `priority`, oncoming.
struct TurnPriority {
  ActorId yielder = kEgo;
  ActorId priority = kEgo;
  LaneIndex yielder_lane = 0;   // the junction lane it turned on
  LaneIndex priority_lane = 0;  // the one the oncoming vehicle drove
};

// The last junction lane `actor` was recorded on in samples [first, last]; nullopt when none.
std::optional<LaneIndex> last_junction_lane(const Trace& trace, const RoadMap& map, ActorId actor,
                                            std::size_t first, std::size_t last);

// Whether two lanes of one junction meet: their centre lines cross or they merge into one lane.
bool junction_lanes_conflict(const RoadMap& map, LaneIndex a, LaneIndex b);

// Whether `a` and `b` enter their junction from opposite directions.
bool junction_lanes_oncoming(const RoadMap& map, LaneIndex a, LaneIndex b);

// The priority between the ego and `other` (both vehicles) over samples [first, last]: one turned
// left on a junction lane whose path meets the other's, oncoming, going straight or turning right.
// nullopt when neither owed the other the way by this rule.
std::optional<TurnPriority> turn_priority(const Trace& trace, const RoadMap& map, ActorId other,
                                          std::size_t first, std::size_t last);

}  // namespace scenfuzz
