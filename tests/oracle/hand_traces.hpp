// Traces built by hand for the responsibility oracle's tests: two actors (the ego and a car,
// pedestrian or obstacle) moved by functions of time on a built-in map, their lanes read from the
// map, each trace cut at the first contact and that contact recorded, as a simulation does.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "oracle/responsibility.hpp"
#include "physics/collision/footprint.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/trace/trace_footprint.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz::test {

inline constexpr double kDt = 0.05;
inline constexpr double kCarLength = 4.6;
inline constexpr double kCarWidth = 1.85;

inline RoadMap builtin(const char* name) { return build_road_map(generate_builtin_map(name, {})); }

// Where an actor is at time t: position, and its velocity (heading and speed follow from it).
struct State {
  double x = 0;
  double y = 0;
  double vx = 0;
  double vy = 0;
};
using Motion = std::function<State(double t)>;

// Fills an actor's columns from `motion`: heading along the velocity (kept when standing),
// accelerations and yaw rates as the rates over the step ending at each sample, lanes from the
// map.
inline void move(const Trace& trace, const RoadMap& map, TraceActor& actor, const Motion& motion,
                 double standing_heading = 0) {
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    const State s = motion(trace.time[i]);
    actor.x[i] = s.x;
    actor.y[i] = s.y;
    actor.speed[i] = std::hypot(s.vx, s.vy);
    actor.heading[i] = actor.speed[i] > 1e-9 ? std::atan2(s.vy, s.vx)
                       : i > 0               ? actor.heading[i - 1]
                                             : standing_heading;
    if (i > 0) {
      actor.acceleration[i] = (actor.speed[i] - actor.speed[i - 1]) / trace.dt;
      actor.yaw_rate[i] = (actor.heading[i] - actor.heading[i - 1]) / trace.dt;
    }
    if (actor.kind == TraceActorKind::obstacle) continue;
    const auto lane = project_to_lane(map, {s.x, s.y}, actor.heading[i]);
    actor.lane[i] = lane && lane->inside ? static_cast<std::int32_t>(lane->lane) : -1;
    actor.s[i] = lane && lane->inside ? lane->s : 0;
  }
}

// Cuts the trace at the first contact of the ego with actor 1 and records it there.
inline void end_at_contact(Trace& trace) {
  std::size_t k = 0;
  while (k < trace.sample_count() &&
         signed_distance(footprint_at(trace, kEgo, k), footprint_at(trace, 1, k)) >= 0)
    ++k;
  ASSERT_LT(k, trace.sample_count()) << "the actors never touch";
  const std::size_t n = k + 1;
  trace.time.resize(n);
  for (TraceActor& actor : trace.actors) {
    for (auto* column : {&actor.x, &actor.y, &actor.heading, &actor.speed, &actor.acceleration,
                         &actor.yaw_rate, &actor.s})
      column->resize(n);
    actor.lane.resize(n);
  }
  for (TraceLight& light : trace.lights) light.colour.resize(n);
  const Footprint ego = footprint_at(trace, kEgo, k);
  const Footprint other = footprint_at(trace, 1, k);
  const MapPoint contact{(ego.centre.x + other.centre.x) / 2, (ego.centre.y + other.centre.y) / 2};
  trace.collisions.push_back(
      {trace.time[k], kEgo, 1, contact, side_of(ego, contact), side_of(other, contact)});
  trace.events.push_back({TraceEventKind::collision, trace.time[k], 0, ""});
  trace.end = EndReason::collision;
}

inline Trace two_actor_trace(double seconds, TraceActorKind other_kind = TraceActorKind::vehicle) {
  Trace trace = empty_trace(static_cast<std::size_t>(seconds / kDt) + 1, kDt);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, kCarLength, kCarWidth, 0, 0));
  if (other_kind == TraceActorKind::pedestrian) {
    trace.actors.push_back(
        still_actor(trace, "ped", other_kind, BodyShape::cylinder, 0.6, 0.6, 0, 0));
    trace.actors.back().category = ActorCategory::pedestrian;
  } else {
    trace.actors.push_back(
        still_actor(trace, "npc", other_kind, BodyShape::box, kCarLength, kCarWidth, 0, 0));
  }
  return trace;
}

// Arc length driven by time t.
using Distance = std::function<double(double t)>;

inline Distance steady(double speed) {
  return [=](double t) { return speed * t; };
}

// At `speed`, then braking at `decel` so as to stand still at `stop_at` metres.
inline Distance stopping_at(double speed, double decel, double stop_at) {
  const double brake_from = (stop_at - speed * speed / (2 * decel)) / speed;
  return [=](double t) {
    if (t <= brake_from) return speed * t;
    const double tb = std::min(t - brake_from, speed / decel);
    return speed * brake_from + speed * tb - decel * tb * tb / 2;
  };
}

// The point `d` metres along the centre lines of `lanes`, one after the other, from `s0` on the
// first.
inline MapPoint along(const RoadMap& map, const std::vector<std::string>& lanes, double s0,
                      double d) {
  double s = s0 + d;
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const Lane& lane = map.lane(*map.find_lane(lanes[i]));
    if (s <= lane.length() || i + 1 == lanes.size()) return lane.centre_line.point_at(s);
    s -= lane.length();
  }
  return {};
}

// Along `lanes` by `distance`; the velocity by a central difference.
inline Motion along_lanes(const RoadMap& map, std::vector<std::string> lanes, double s0,
                          Distance distance) {
  return [=, &map](double t) {
    constexpr double h = 1e-4;
    const MapPoint p = along(map, lanes, s0, distance(t));
    const MapPoint a = along(map, lanes, s0, distance(std::max(0.0, t - h)));
    const MapPoint b = along(map, lanes, s0, distance(t + h));
    const double span = t + h - std::max(0.0, t - h);
    return State{p.x, p.y, (b.x - a.x) / span, (b.y - a.y) / span};
  };
}

inline CollisionResponsibility judge(const Trace& trace, const RoadMap& map) {
  return collision_responsibility(trace, map, 0, RssParameters{});
}

}  // namespace scenfuzz::test
