// Junction lanes and their conflicts, as the reactive drivers give way (physics/simulation's lane
// follower has the same test; the oracle keeps its own so as not to reach into the simulator).
#include "oracle/junction_priority.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "oracle/pair_geometry.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

namespace {

// Entry directions further apart than this are opposite (rad): arms of a skewed junction too.
constexpr double kOncoming = 3 * std::numbers::pi / 4;

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool segments_cross(MapPoint a, MapPoint b, MapPoint c, MapPoint d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

bool lines_cross(const Polyline& first, const Polyline& second) {
  const auto& p = first.points();
  const auto& q = second.points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    for (std::size_t j = 0; j + 1 < q.size(); ++j)
      if (segments_cross(p[i], p[i + 1], q[j], q[j + 1])) return true;
  return false;
}

bool shares_successor(const Lane& first, const Lane& second) {
  return std::any_of(first.successors.begin(), first.successors.end(), [&](LaneIndex next) {
    return std::find(second.successors.begin(), second.successors.end(), next) !=
           second.successors.end();
  });
}

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
