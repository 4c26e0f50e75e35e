// Gap acceptance on a left turn across oncoming traffic (left_turn_gap.hpp): finding the turns
// and their conflict areas once, from the map and the route; deciding at each step from what the
// driver perceives.
#include "physics/ego/left_turn_gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "physics/map/lane_conflicts.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kStep = 0.25;              // m between samples of the conflict areas
constexpr double kOncomingHalfWidth = 1.0;  // m: half a car's width, for the area on its lane
constexpr double kAtTheLine = 0.5;  // m short of the wait point that counts as at it (the driver
                                    // stops 1 m short: stop_line_gap)
constexpr double kDecisionReach = 100;  // m: farther from the turn, no need to decide yet
constexpr double kDecisionTime = 10;    // s of the ego's speed, if that is farther
constexpr double kOnLaneHeading = std::numbers::pi / 3;  // rad: moving along a lane, not across
constexpr double kOnLaneMargin = 0.5;  // m beyond a lane's half width still on it (perception)

bool turns_left(const Lane& lane) {
  if (lane.turn == LaneTurn::left || lane.turn == LaneTurn::u_turn) return true;
  if (lane.turn != LaneTurn::none) return false;
  const Polyline& line = lane.centre_line;
  return angle_difference(line.heading_at(line.length()), line.heading_at(0)) >
         std::numbers::pi / 4;
}

double half_width(const RoadMap& map, LaneIndex lane, double s) {
  return std::max(lane_left_width_at(map, lane, s), lane_right_width_at(map, lane, s));
}

// The lane and the lanes feeding it, back to `upstream` metres, with the offset that turns s on
// each into s on `lane` (negative behind its start).
std::vector<std::pair<LaneIndex, double>> approach_of(const RoadMap& map, LaneIndex lane,
                                                      double upstream) {
  std::vector<std::pair<LaneIndex, double>> found{{lane, 0.0}};
  for (std::size_t i = 0; i < found.size(); ++i) {
    const auto [at, offset] = found[i];
    if (-offset >= upstream) continue;
    for (LaneIndex before : map.lane(at).predecessors) {
      bool seen = std::any_of(found.begin(), found.end(),
                              [&](const auto& entry) { return entry.first == before; });
      if (!seen) found.emplace_back(before, offset - map.lane(before).length());
    }
  }
  return found;
}

// The route's path from `begin` to `end`, sampled: what an oncoming lane is measured against.
Polyline path_stretch(const RouteTracker& route, double begin, double end) {
  begin = std::max(begin, 0.0);
  end = std::min(end, route.length());
  std::vector<MapPoint> points;
  for (double s = begin; s < end; s += 0.5) points.push_back(route.path().point_at(s));
  points.push_back(route.path().point_at(end));
  return Polyline(points);
}

// Where the ego's body (its centre on the path from `begin` to `end`) reaches into `lane`, and
// where on `lane` a vehicle reaches the ego's path; nullopt when they never meet.
std::optional<OncomingConflict> conflict_with(const RoadMap& map, const RouteTracker& route,
                                              const ActorClass& vehicle,
                                              const LeftTurnGapSettings& settings, LaneIndex lane,
                                              double begin, double end) {
  const Polyline& line = map.lane(lane).centre_line;
  OncomingConflict conflict{lane, kInfinity, -kInfinity, kInfinity, -kInfinity, {}};
  for (double s = std::max(begin - vehicle.length, 0.0);
       s <= std::min(end + vehicle.length, route.length()); s += kStep) {
    PolylineProjection on = line.project(route.path().point_at(s));
    double relative = angle_difference(route.heading_at(s), line.heading_at(on.s));
    double extent = vehicle.length / 2 * std::abs(std::sin(relative)) +
                    vehicle.width / 2 * std::abs(std::cos(relative));
    if (on.distance < half_width(map, lane, on.s) + settings.lateral_margin + extent) {
      conflict.ego_enter = std::min(conflict.ego_enter, s);
      conflict.ego_exit = std::max(conflict.ego_exit, s + kStep);
    }
  }
  const Polyline stretch = path_stretch(route, begin - vehicle.length, end + vehicle.length);
  const double reach = vehicle.width / 2 + settings.lateral_margin + kOncomingHalfWidth;
  for (double s = 0; s <= line.length(); s += kStep) {
    if (stretch.project(line.point_at(s)).distance < reach) {
      conflict.lane_enter = std::min(conflict.lane_enter, s);
      conflict.lane_exit = std::max(conflict.lane_exit, s + kStep);
    }
  }
  if (conflict.ego_enter > conflict.ego_exit || conflict.lane_enter > conflict.lane_exit)
    return std::nullopt;
  conflict.approach = approach_of(map, lane, settings.upstream);
  return conflict;
}

// The oncoming lanes that the route's junction lane `turn` (on the path from `begin` to `end`)
// crosses: lanes of its junction starting against it whose centre lines cross its own.
LeftTurn left_turn_at(const RoadMap& map, const RouteTracker& route, const ActorClass& vehicle,
                      const LeftTurnGapSettings& settings, LaneIndex turn, double begin,
                      double end) {
  LeftTurn found;
  const Lane& mine = map.lane(turn);
  const double against = mine.centre_line.heading_at(0) + std::numbers::pi;
  for (LaneIndex other = 0; other < map.lanes().size(); ++other) {
    const Lane& lane = map.lane(other);
    if (other == turn || lane.junction != mine.junction) continue;
    if (std::abs(angle_difference(lane.centre_line.heading_at(0), against)) > std::numbers::pi / 4)
      continue;
    if (!lines_cross(mine.centre_line, lane.centre_line)) continue;
    if (auto conflict = conflict_with(map, route, vehicle, settings, other, begin, end))
      found.conflicts.push_back(std::move(*conflict));
  }
  found.wait = kInfinity;
  for (const OncomingConflict& conflict : found.conflicts)
    found.wait = std::min(found.wait, conflict.ego_enter);
  return found;
}

// Where a perceived vehicle is along the conflict's lane (s on it, negative on a lane feeding
// it), when it is on one of them moving along it.
std::optional<double> along_approach(const RoadMap& map, const OncomingConflict& conflict,
                                     const WorldObject& object) {
  if (object.kind == TraceActorKind::pedestrian || object.kind == TraceActorKind::obstacle ||
      object.reversing)
    return std::nullopt;
  std::optional<double> best;
  double nearest = kInfinity;
  for (const auto& [lane, offset] : conflict.approach) {
    const Polyline& line = map.lane(lane).centre_line;
    PolylineProjection on = line.project({object.x, object.y});
    if (on.distance > std::abs(on.lateral) + 1e-6) continue;  // beyond an end
    if (on.distance > half_width(map, lane, on.s) + kOnLaneMargin || on.distance >= nearest)
      continue;
    if (std::abs(angle_difference(object.heading, line.heading_at(on.s))) > kOnLaneHeading)
      continue;
    nearest = on.distance;
    best = on.s + offset;
  }
  return best;
}

}  // namespace

std::vector<LeftTurn> find_left_turns(const RoadMap& map, const RouteTracker& route,
                                      const ActorClass& vehicle,
                                      const LeftTurnGapSettings& settings) {
  std::vector<LeftTurn> turns;
  if (route.empty()) return turns;
  for (double s = 0; s < route.length();) {
    auto at = route.lane_at(s);
    if (!at) break;
    const double end = std::max(at->lane_end, s + kStep);
    const Lane& lane = map.lane(at->lane);
    if (lane.junction && turns_left(lane)) {
      LeftTurn turn = left_turn_at(map, route, vehicle, settings, at->lane, s, end);
      if (!turn.conflicts.empty()) turns.push_back(std::move(turn));
    }
    s = end + 1e-3;
  }
  return turns;
}

LeftTurnGap::LeftTurnGap(const RoadMap& map, const RouteTracker& route, const ActorClass& vehicle,
                         const LeftTurnGapSettings& settings)
    : map_(map),
      route_(route),
      vehicle_(vehicle),
      settings_(settings),
      turns_(find_left_turns(map, route, vehicle, settings)) {}

const LeftTurn* LeftTurnGap::current() const {
  for (const LeftTurn& turn : turns_)
    for (const OncomingConflict& conflict : turn.conflicts)
      if (conflict.ego_exit > route_.progress()) return &turn;
  return nullptr;
}

double LeftTurnGap::time_to_reach(double speed, double to, std::span<const double> desired,
                                  double speed_cap) const {
  constexpr double dt = 0.1, longest = 60;
  const auto& arc = route_.path().arc_lengths();
  double s = route_.progress(), v = std::max(speed, 0.0), t = 0;
  while (s < to && t < longest) {
    double wanted = speed_cap;
    if (desired.size() == arc.size() && arc.size() >= 2) {
      std::size_t i = route_.path().segment_at(s);
      wanted = std::min(wanted, std::min(desired[i], desired[i + 1]));
    }
    wanted = std::max(wanted, 0.1);
    double ratio = v / wanted;
    v = std::max(0.0, v + settings_.acceleration * (1 - ratio * ratio * ratio * ratio) * dt);
    s += v * dt;
    t += dt;
  }
  return s >= to ? t : kInfinity;
}

double LeftTurnGap::time_to_arrive(const OncomingConflict& conflict,
                                   const WorldObject& object) const {
  auto at = along_approach(map_, conflict, object);
  if (!at) return kInfinity;
  double front = *at + object.length / 2, rear = *at - object.length / 2;
  if (rear > conflict.lane_exit) return kInfinity;  // gone past
  if (front >= conflict.lane_enter) return 0;       // in it
  double distance = conflict.lane_enter - front;
  if (object.speed < settings_.moving_speed)
    return distance < settings_.standing_reach ? 0 : kInfinity;
  return distance / object.speed;
}

bool LeftTurnGap::is_oncoming(const WorldObject& object) const {
  const LeftTurn* turn = current();
  if (!turn) return false;
  return std::any_of(turn->conflicts.begin(), turn->conflicts.end(),
                     [&](const OncomingConflict& c) { return along_approach(map_, c, object); });
}

GapDecision LeftTurnGap::decide(const KinematicState& ego, std::span<const WorldObject> objects,
                                std::span<const double> desired, double speed_cap,
                                double max_deceleration) {
  GapDecision decision;
  const LeftTurn* turn = current();
  if (!turn) return decision;
  const auto index = static_cast<std::size_t>(turn - turns_.data());
  if (index != committed_turn_) {
    committed_turn_ = index;
    committed_ = false;
  }
  const double to_wait = turn->wait - route_.progress();
  if (committed_ || to_wait <= kAtTheLine) {
    committed_ = true;
    decision.committed = true;
    return decision;
  }
  if (to_wait > std::max(kDecisionReach, ego.speed * kDecisionTime)) return decision;
  bool blocked = false;
  for (const OncomingConflict& conflict : turn->conflicts) {
    double clear = time_to_reach(ego.speed, conflict.ego_exit, desired, speed_cap);
    double needed = std::max(settings_.critical_gap, clear + settings_.clearing_margin);
    blocked = std::any_of(objects.begin(), objects.end(), [&](const WorldObject& object) {
      return time_to_arrive(conflict, object) < needed;
    });
    if (blocked) break;
  }
  if (!blocked) return decision;
  // Too late to stop short of the area: stopping in it would be worse than going on.
  if (max_deceleration > 0 &&
      to_wait - kAtTheLine < ego.speed * ego.speed / (2 * max_deceleration)) {
    committed_ = true;
    decision.committed = true;
    return decision;
  }
  decision.wait_gap = to_wait;
  return decision;
}

}  // namespace scenfuzz
