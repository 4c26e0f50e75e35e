// Priority to the right from the junction lanes' entry directions: in right-hand traffic a vehicle
// coming from the right drives in a direction a quarter turn counter-clockwise of one's own.
#include "oracle/right_priority.hpp"

#include <cmath>
#include <numbers>

#include "oracle/junction_priority.hpp"
#include "oracle/pair_geometry.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

namespace {

// Entry directions this far either side of a quarter turn count as coming from the side (rad).
constexpr double kSideTolerance = std::numbers::pi / 4;

bool has_control(const Lane& lane) {
  for (const LaneFeature& feature : lane.features)
    if (feature.kind != FeatureKind::crosswalk) return true;
  return false;
}

// Whether a vehicle entering on `lane` comes from the right of one entering on `of`.
bool from_right_of(const RoadMap& map, LaneIndex lane, LaneIndex of) {
  const double turn = wrap_angle(lane_heading_at(map, lane, 0) - lane_heading_at(map, of, 0));
  return std::abs(turn - std::numbers::pi / 2) < kSideTolerance;
}

}  // namespace

bool approach_controlled(const RoadMap& map, LaneIndex lane) {
  const Lane& junction_lane = map.lane(lane);
  if (has_control(junction_lane)) return true;
  for (const LaneIndex before : junction_lane.predecessors)
    if (has_control(map.lane(before))) return true;
  return false;
}

std::optional<RightPriority> right_priority(const Trace& trace, const RoadMap& map, ActorId other,
                                            std::size_t first, std::size_t last) {
  const std::optional<LaneIndex> ego = last_junction_lane(trace, map, kEgo, first, last);
  const std::optional<LaneIndex> them = last_junction_lane(trace, map, other, first, last);
  if (!ego || !them || !junction_lanes_conflict(map, *ego, *them)) return std::nullopt;
  if (approach_controlled(map, *ego) || approach_controlled(map, *them)) return std::nullopt;
  if (from_right_of(map, *them, *ego)) return RightPriority{kEgo, other};
  if (from_right_of(map, *ego, *them)) return RightPriority{other, kEgo};
  return std::nullopt;
}

}  // namespace scenfuzz
