// Reactive cruising along the lanes (see lane_cruise.hpp): the lanes ahead are walked once per
// step up to the distance that matters at the present speed.
#include "physics/simulation/lane_cruise.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "physics/map/lane_route.hpp"
#include "physics/simulation/lanes_ahead.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTimeGap = 1.5;              // s, IDM's T (as the lane follower's)
constexpr double kStandstillGap = 2.0;        // m, IDM's s0
constexpr double kStopLineGap = 1.0;          // m before a stop line
constexpr double kComfortAcceleration = 1.5;  // m/s^2, IDM's a (at most the class's)
constexpr double kStandingCruise = 0.5;       // m/s: cruising slower than this is standing
constexpr double kDeadEndMargin = 0.5;        // m short of a dead end where an actor aims to stop
constexpr double kPhaseSideMargin = 0.3;      // m beside a body leaving a lane that must stay clear
constexpr double kPhaseTimeGap = 0.5;         // s behind its leader a scripted phase keeps at least
// The share of its full braking from which a scripted phase brakes for what is ahead.
constexpr double kPhaseBrakingShare = 0.6;

double fourth_power(double x) {
  double squared = x * x;
  return squared * squared;
}

// The nearest actor ahead (bumper to bumper along the lanes) and its speed along the follower's
// heading; gap +infinity when there is none.
struct Leader {
  double gap = kInfinity;
  double speed = 0;
};

// The actor's speed along `me`'s heading, 0 when it comes the other way (as a standing obstacle).
double speed_along(const KinematicState& me, const KinematicState& other) {
  const double relative = angle_difference(other.heading, me.heading);
  return std::max(0.0, longitudinal_velocity(other) * std::cos(relative));
}

// The nearest actor ahead of `self` on `lanes` (by the lane tracker's lane) for which `counts`
// holds.
template <typename Counts>
Leader nearest_ahead(const WorldSnapshot& world, std::uint32_t self,
                     const std::vector<LaneAhead>& lanes, double half_length,
                     const Counts& counts) {
  const KinematicState& me = world.states[self];
  Leader leader;
  for (std::uint32_t k = 0; k < world.states.size(); ++k) {
    if (k == self || world.lanes[k].lane < 0 || !present_in(world, k) || !counts(k)) continue;
    for (const LaneAhead& lane : lanes) {
      if (static_cast<LaneIndex>(world.lanes[k].lane) != lane.lane) continue;
      double along = lane.offset + world.lanes[k].s;
      double gap = along - half_length - world.lengths[k] / 2;
      if (along > 0 && gap < leader.gap) leader = {gap, speed_along(me, world.states[k])};
    }
  }
  return leader;
}

// The nearest actor ahead of `self` whose body overlaps the band of road self's covers, `lateral`
// m left of the centre lines of `lanes`, `width` wide and kPhaseSideMargin either side, for which
// `counts` holds: by where its centre projects onto those lanes, whichever lane it is in (the
// oncoming lane's traffic is in no lane of self's route).
template <typename Counts>
Leader nearest_in_corridor(const WorldSnapshot& world, std::uint32_t self,
                           const std::vector<LaneAhead>& lanes, double lateral, double width,
                           double half_length, const Counts& counts) {
  // m: a foot of a perpendicular within this of a lane's end is on the lane (rounding).
  constexpr double kEndTolerance = 1e-6;
  const RoadMap& map = *world.map;
  const KinematicState& me = world.states[self];
  // Nothing farther than the lanes walked, plus the band's reach sideways, is on them.
  const Lane& last = map.lane(lanes.back().lane);
  const double reach = lanes.back().offset + last.length() + std::abs(lateral) + width;
  Leader leader;
  for (std::uint32_t k = 0; k < world.states.size(); ++k) {
    if (k == self || world.lanes[k].lane < 0 || !present_in(world, k) || !counts(k)) continue;
    const KinematicState& other = world.states[k];
    const double dx = other.x - me.x, dy = other.y - me.y;
    if (dx * dx + dy * dy > (reach + world.lengths[k]) * (reach + world.lengths[k])) continue;
    const double beside = (width + world.widths[k]) / 2 + kPhaseSideMargin;
    for (const LaneAhead& lane : lanes) {
      const Lane& on = map.lane(lane.lane);
      const PolylineProjection there = on.centre_line.project({other.x, other.y});
      // Before the lane's start or past its end: on another lane of the route, or on none.
      const bool at_end = there.s <= kEndTolerance || there.s >= on.length() - kEndTolerance;
      if (at_end && there.distance > std::abs(there.lateral) + kEndTolerance) continue;
      if (std::abs(there.lateral - lateral) >= beside) continue;
      const double along = lane.offset + there.s;
      const double gap = along - half_length - world.lengths[k] / 2;
      if (along > 0 && gap < leader.gap) leader = {gap, speed_along(me, other)};
    }
  }
  return leader;
}

// The nearest actor ahead that `scope` names, for which `counts` holds.
template <typename Counts>
Leader scoped_leader(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                     const std::vector<LaneAhead>& lanes, const ActorClass& body, LeaderScope scope,
                     const Counts& counts) {
  if (scope == LeaderScope::corridor)
    return nearest_in_corridor(world, self, lanes, at.lateral, body.width, body.length / 2, counts);
  return nearest_ahead(world, self, lanes, body.length / 2, counts);
}

// Calls `stop_at(gap)` for each red light on `lanes` (and each yellow one the actor can stop for
// at comfortable braking) that it can still stop for at full braking, `gap` from its front to the
// stop line.
template <typename StopAt>
void for_each_light_to_stop_at(const WorldSnapshot& world, const std::vector<LaneAhead>& lanes,
                               double v, const ActorClass& body, StopAt stop_at) {
  const double half = body.length / 2;
  const double b = body.comfortable_deceleration;
  for (const LaneAhead& lane : lanes)
    for (const LaneFeature& feature : world.map->lane(lane.lane).features) {
      if (feature.kind != FeatureKind::traffic_light) continue;
      const double gap = lane.offset + feature.s_begin - half;
      if (gap < 0 || feature.index >= world.lights.size()) continue;
      const SignalColour colour = world.lights[feature.index];
      const bool stop =
          colour == SignalColour::red || (colour == SignalColour::yellow && gap >= v * v / (2 * b));
      if (stop && gap >= v * v / (2 * body.max_deceleration)) stop_at(gap);
    }
}

}  // namespace

double cruise_acceleration(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                           const NextLane& next_lane, const ActorClass& body, double cruise_speed,
                           LeaderScope scope) {
  const RoadMap& map = *world.map;
  const KinematicState& me = world.states[self];
  const double v = me.speed;
  const double a = std::min(kComfortAcceleration, body.max_acceleration);
  const double b = body.comfortable_deceleration;
  bool dead_end = false;
  std::vector<LaneAhead> lanes = lanes_ahead(map, at, next_lane, lane_lookahead(v), dead_end);
  // A phase that ended at a standstill (or nearly: a stop reaches 0 within a step) leaves it
  // standing.
  if (cruise_speed < kStandingCruise) return v > 0 ? -body.comfortable_deceleration : 0;
  const double desired = cruise_speed;
  double best = a * (1 - fourth_power(v / desired));
  auto follow = [&](double gap, double lead_speed, double clearance) {
    double wanted = clearance + v * kTimeGap + v * (v - lead_speed) / (2 * std::sqrt(a * b));
    double ratio = std::max(wanted, 0.0) / std::max(gap, 0.1);
    best = std::min(best, a * (1 - fourth_power(v / desired) - ratio * ratio));
  };
  // The nearest actor ahead on these lanes, or in its band of road along them.
  const Leader leader =
      scoped_leader(world, self, at, lanes, body, scope, [](std::uint32_t) { return true; });
  const double nearest = leader.gap, lead_speed = leader.speed;
  if (std::isfinite(nearest)) follow(nearest, lead_speed, kStandstillGap);
  for_each_light_to_stop_at(world, lanes, v, body,
                            [&](double gap) { follow(gap, 0, kStopLineGap); });
  return std::clamp(best, -body.max_deceleration, body.max_acceleration);
}

double red_light_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                       const NextLane& next_lane, const ActorClass& body) {
  const double v = world.states[self].speed;
  bool dead_end = false;
  const std::vector<LaneAhead> lanes =
      lanes_ahead(*world.map, at, next_lane, lane_lookahead(v), dead_end);
  double limit = kInfinity;
  for_each_light_to_stop_at(world, lanes, v, body, [&](double gap) {
    limit = std::min(limit, stop_line_limit(v, gap, body));
  });
  return limit;
}

double stop_line_limit(double speed, double gap, const ActorClass& body) {
  const double a = std::min(kComfortAcceleration, body.max_acceleration);
  const double b = body.comfortable_deceleration;
  // IDM's interaction term alone, as cruise_acceleration's for a stop line: a phase keeps its own
  // speed until the stop needs braking.
  const double wanted = kStopLineGap + speed * kTimeGap + speed * speed / (2 * std::sqrt(a * b));
  const double ratio = wanted / std::max(gap, 0.1);
  return std::max(-a * ratio * ratio, -body.max_deceleration);
}

namespace {

// The leader a manoeuvre phase keeps from running into (phase_leader_limit).
Leader phase_leader(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                    const NextLane& next_lane, const ActorClass& body, LeaderScope scope) {
  const RoadMap& map = *world.map;
  const KinematicState& me = world.states[self];
  const double v = me.speed;
  const double half = body.length / 2;
  bool dead_end = false;
  const std::vector<LaneAhead> lanes = lanes_ahead(map, at, next_lane, lane_lookahead(v), dead_end);
  auto not_ego = [](std::uint32_t k) { return k != kEgo; };
  Leader leader = scoped_leader(world, self, at, lanes, body, scope, not_ego);
  // Its band of road already covers every lane its body is in.
  if (scope == LeaderScope::corridor) return leader;
  // Changing lanes, the actor is still partly in the lane it leaves (the lane tracker's, while its
  // centre is there): what is ahead there counts while the bodies overlap sideways.
  const LaneFix& own = world.lanes[self];
  if (own.lane >= 0 && static_cast<LaneIndex>(own.lane) != at.lane) {
    const std::vector<LaneAhead> leaving =
        lanes_ahead(map, LanePosition{static_cast<LaneIndex>(own.lane), own.s, 0}, next_lane,
                    lane_lookahead(v), dead_end);
    auto beside = [&](std::uint32_t k) {
      const double dx = world.states[k].x - me.x, dy = world.states[k].y - me.y;
      const double lateral = -std::sin(me.heading) * dx + std::cos(me.heading) * dy;
      return not_ego(k) &&
             std::abs(lateral) < (body.width + world.widths[k]) / 2 + kPhaseSideMargin;
    };
    const Leader there = nearest_ahead(world, self, leaving, half, beside);
    if (there.gap < leader.gap) leader = there;
  }
  return leader;
}

}  // namespace

double phase_leader_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                          const NextLane& next_lane, const ActorClass& body, LeaderScope scope) {
  const Leader leader = phase_leader(world, self, at, next_lane, body, scope);
  if (!std::isfinite(leader.gap)) return kInfinity;
  const double v = world.states[self].speed;
  // Close behind its leader, it drops back as IDM would, to a brisk driver's gap.
  const double safe = kStandstillGap + v * kPhaseTimeGap;
  double limit = kInfinity;
  if (leader.gap < safe) {
    const double ratio = safe / std::max(leader.gap, 0.1);
    limit = body.max_acceleration * (1 - ratio * ratio);
  }
  // Closing in, it brakes at the last moment firm braking still stops it at that gap behind its
  // leader's speed: a script that cuts out late around a stopped car is not slowed before.
  const double closing = v - leader.speed;
  if (closing > 0) {
    const double needed = closing * closing / (2 * std::max(leader.gap - safe, 0.1));
    if (needed >= kPhaseBrakingShare * body.max_deceleration) limit = std::min(limit, -needed);
  }
  return std::isfinite(limit) ? std::max(limit, -body.max_deceleration) : kInfinity;
}

double dead_end_braking(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                        const ActorClass& body, double speed, double dt) {
  const double stopping = speed * speed / (2 * body.comfortable_deceleration);
  bool dead_end = false;
  std::vector<LaneAhead> lanes =
      lanes_ahead(map, at, next_lane, stopping + speed * dt + 1, dead_end);
  if (!dead_end) return kInfinity;
  const LaneAhead& last = lanes.back();
  // Aiming short of the very end: the lane's end would stop the actor in one step.
  double to_end = last.offset + map.lane(last.lane).length() - kDeadEndMargin;
  if (to_end > stopping + speed * dt) return kInfinity;
  return -std::min(speed * speed / (2 * std::max(to_end, 0.05)), body.max_deceleration);
}

double bend_braking(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                    const ActorClass& body, double speed, double lateral_acceleration) {
  constexpr double kStep = 1;  // m between the headings compared
  const double b = body.comfortable_deceleration;
  const double reach = speed * speed / (2 * b) + 2 * kStep;
  bool dead_end = false;
  const std::vector<LaneAhead> lanes = lanes_ahead(map, at, next_lane, reach, dead_end);
  auto heading_at = [&](double d) -> std::optional<double> {
    for (const LaneAhead& lane : lanes) {
      double s = d - lane.offset;
      if (s >= 0 && s <= map.lane(lane.lane).length()) return lane_heading_at(map, lane.lane, s);
    }
    return std::nullopt;
  };
  double needed = kInfinity;
  std::optional<double> before = heading_at(0);
  for (double d = kStep; d <= reach && before; d += kStep) {
    std::optional<double> after = heading_at(d);
    if (!after) break;
    const double curvature = std::abs(angle_difference(*after, *before)) / kStep;
    before = after;
    if (curvature < 1e-6) continue;
    const double bend_speed2 = lateral_acceleration / curvature;
    const double distance = std::max(d - kStep, 0.5);
    if (speed * speed <= bend_speed2 + 2 * b * distance) continue;
    needed = std::min(needed, (bend_speed2 - speed * speed) / (2 * distance));
  }
  return std::isfinite(needed) ? std::max(needed, -body.max_deceleration) : kInfinity;
}

}  // namespace scenfuzz
