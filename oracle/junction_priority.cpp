// Junction lanes and their conflicts, as the reactive drivers give way (physics/simulation's lane
// follower has the same test; the oracle keeps its own so as not to reach into the simulator).
#include "oracle/junction_priority.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "oracle/pair_geometry.hpp"
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

namespace {

// Entry directions further apart than this are opposite (rad): arms of a skewed junction too.
constexpr double kOncoming = 3 * std::numbers::pi / 4;

// Owes the way by turning left; has priority going straight on or turning right.
bool gives_way(LaneTurn turn) { return turn == LaneTurn::left || turn == LaneTurn::u_turn; }
bool has_way(LaneTurn turn) { return turn == LaneTurn::none || turn == LaneTurn::right; }

}  // namespace

std::optional<LaneIndex> last_junction_lane(const Trace& trace, const RoadMap& map, ActorId actor,
                                            std::size_t first, std::size_t last) {
  const TraceActor& a = trace.actors[actor];
  for (std::size_t i = std::min(last + 1, trace.sample_count()); i-- > first;) {
    if (!present_at(a, i) || a.lane[i] < 0) continue;
    const auto lane = static_cast<LaneIndex>(a.lane[i]);
    if (lane < map.lanes().size() && map.lane(lane).junction) return lane;
  }
  return std::nullopt;
}

bool junction_lanes_conflict(const RoadMap& map, LaneIndex a, LaneIndex b) {
  const Lane& first = map.lane(a);
  const Lane& second = map.lane(b);
  if (a == b || !first.junction || first.junction != second.junction) return false;
  return lines_cross(first.centre_line, second.centre_line) || shares_successor(first, second);
}

bool junction_lanes_oncoming(const RoadMap& map, LaneIndex a, LaneIndex b) {
  return std::abs(wrap_angle(lane_heading_at(map, a, 0) - lane_heading_at(map, b, 0))) > kOncoming;
}

std::optional<TurnPriority> turn_priority(const Trace& trace, const RoadMap& map, ActorId other,
                                          std::size_t first, std::size_t last) {
  const std::optional<LaneIndex> ego = last_junction_lane(trace, map, kEgo, first, last);
  const std::optional<LaneIndex> them = last_junction_lane(trace, map, other, first, last);
  if (!ego || !them || !junction_lanes_conflict(map, *ego, *them) ||
      !junction_lanes_oncoming(map, *ego, *them))
    return std::nullopt;
  const LaneTurn ego_turn = map.lane(*ego).turn;
  const LaneTurn other_turn = map.lane(*them).turn;
  if (gives_way(ego_turn) && has_way(other_turn)) return TurnPriority{kEgo, other, *ego, *them};
  if (gives_way(other_turn) && has_way(ego_turn)) return TurnPriority{other, kEgo, *them, *ego};
  return std::nullopt;
}

}  // namespace scenfuzz
