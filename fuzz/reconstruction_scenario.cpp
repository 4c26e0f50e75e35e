// A reconstruction as a concrete AVUnit scenario (reconstruction_scenario.hpp).
#include "fuzz/reconstruction_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz {

namespace {

// Seconds between a replayed vehicle's waypoints: close enough that its path and speed between
// them stay the reconstruction's through a turn or a lane change.
constexpr double kWaypointInterval = 1.0;
// A vehicle that has moved less than this since its last waypoint has stopped: no new one.
constexpr double kStandingStill = 0.5;

// How far a replayed vehicle carries on along its lanes after its impact: out of the scene.
constexpr double kCarryOn = 60;

// How far past the accident the ego is sent: beyond the junction or the scene, into its lane.
constexpr double kTargetBeyond = 30;

// Rounded as a person reads them (1 / scale: centimetres, tenths of a degree, ...), to the double
// nearest the decimal, so that it prints as one.
double rounded(double value, double scale) { return std::round(value * scale) / scale; }

State state_at(const TraceActor& actor, std::size_t i) {
  State state;
  state.position.kind = PositionKind::coordinate;
  state.position.x = constant_value(rounded(actor.x[i], 100));
  state.position.y = constant_value(rounded(actor.y[i], 100));
  Heading heading;
  heading.angle = constant_value(rounded(actor.heading[i] * 180 / std::numbers::pi, 10));
  heading.unit = AngleUnit::degree;
  state.heading = heading;
  state.speed = constant_value(rounded(actor.speed[i], 100));
  return state;
}

ActorId trace_actor(const Trace& trace, const std::string& name) {
  const std::optional<ActorId> id = trace.find_actor(name);
  SCENFUZZ_DEMAND(id.has_value());
  return *id;
}

// The sample of the actor's first collision, or the trace's last.
std::size_t first_collision_sample(const Trace& trace, ActorId actor) {
  for (const Collision& collision : trace.collisions)
    if (collision.first == actor || collision.second == actor)
      return std::min(trace.sample_count() - 1,
                      static_cast<std::size_t>(std::lround(collision.time / trace.dt)));
  return trace.sample_count() - 1;
}

// The lane after `lane` a vehicle driving on takes: straight on where it can.
LaneIndex next_lane(const RoadMap& map, LaneIndex lane) {
  const std::vector<LaneIndex>& next = map.lane(lane).successors;
  const auto straight = std::find_if(
      next.begin(), next.end(), [&](LaneIndex k) { return map.lane(k).turn == LaneTurn::none; });
  return straight != next.end() ? *straight : next.front();
}

// Waypoints on from sample `impact`, as the vehicle would have gone had nobody been there: along
// its lane (straight on at a junction) at its speed then, kWaypointInterval apart, kCarryOn
// metres. None when it was on no lane or had stopped.
std::vector<State> carrying_on(const TraceActor& actor, std::size_t impact, const RoadMap& map) {
  std::vector<State> states;
  const double speed = actor.speed[impact];
  if (actor.lane[impact] < 0 || speed < kStandingStill) return states;
  LaneIndex lane = static_cast<LaneIndex>(actor.lane[impact]);
  double s = actor.s[impact];
  const double step = std::max(speed * kWaypointInterval, kStandingStill);
  for (double travelled = step; travelled <= kCarryOn; travelled += step) {
    s += step;
    while (s > map.lane(lane).length() && !map.lane(lane).successors.empty()) {
      s -= map.lane(lane).length();
      lane = next_lane(map, lane);
    }
    if (s > map.lane(lane).length()) break;  // the road ends
    const Polyline& line = map.lane(lane).centre_line;
    State state;
    state.position.kind = PositionKind::coordinate;
    const MapPoint point = line.point_at(s);
    state.position.x = constant_value(rounded(point.x, 100));
    state.position.y = constant_value(rounded(point.y, 100));
    Heading heading;
    heading.angle = constant_value(rounded(line.heading_at(s) * 180 / std::numbers::pi, 10));
    heading.unit = AngleUnit::degree;
    state.heading = heading;
    state.speed = constant_value(rounded(speed, 100));
    states.push_back(state);
  }
  return states;
}

// Its run up to its first collision as waypoints every kWaypointInterval, that moment included,
// then on as if nobody had been there: what it did before the impact is the accident's; what the
// impact made of it afterwards is not what a driver in the ego's place, who may avoid the impact,
// is to meet, and a vehicle stopped where the crash was would block that driver's way for ever.
Motion waypoints_of(const TraceActor& actor, ActorId id, const Trace& trace, const RoadMap& map) {
  Motion motion;
  motion.kind = MotionKind::waypoints;
  const std::size_t step =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kWaypointInterval / trace.dt)));
  const std::size_t last = first_collision_sample(trace, id);
  std::size_t previous = 0;
  // Every interval up to the last sample, which always ends the path.
  for (std::size_t i = std::min(step, last); i > previous; i = std::min(i + step, last)) {
    const bool moved = std::hypot(actor.x[i] - actor.x[previous], actor.y[i] - actor.y[previous]) >=
                       kStandingStill;
    if (moved) {
      motion.states.push_back(state_at(actor, i));
      previous = i;
    }
    if (i == last) break;
  }
  if (motion.states.empty()) motion.states.push_back(state_at(actor, last));
  if (last + 1 < trace.sample_count())
    for (State& state : carrying_on(actor, last, map)) motion.states.push_back(std::move(state));
  return motion;
}

// Where the ego was going: the lane it was in when it first collided (the last it was in before,
// if it was off every lane then), past the junction if it was in one, kTargetBeyond metres on or
// to the lane's end. An impact may throw it off the road, so where it ended is no target.
State ego_target(const Trace& trace, const RoadMap& map) {
  const TraceActor& ego = trace.actors[kEgo];
  std::size_t i = first_collision_sample(trace, kEgo);
  while (i > 0 && ego.lane[i] < 0) --i;
  State target;
  if (ego.lane[i] < 0) return state_at(ego, trace.sample_count() - 1);
  LaneIndex lane = static_cast<LaneIndex>(ego.lane[i]);
  double s = ego.s[i] + kTargetBeyond;
  for (int hops = 0; map.lane(lane).junction && !map.lane(lane).successors.empty() && hops < 8;
       ++hops) {
    lane = map.lane(lane).successors.front();
    s = kTargetBeyond;
  }
  target.position.kind = PositionKind::lane;
  target.position.lane = map.lane(lane).id;
  target.position.s = constant_value(rounded(std::min(s, map.lane(lane).length()), 100));
  return target;
}

Actor replayed(const Actor& described, const Trace& trace, const RoadMap& map) {
  const ActorId id = trace_actor(trace, described.name);
  const TraceActor& actor = trace.actors[id];
  Actor copy;
  copy.kind = described.kind;
  copy.name = described.name;
  copy.type = described.type;
  copy.initial = state_at(actor, 0);
  if (described.kind == ActorKind::ego) {
    copy.target = ego_target(trace, map);
    copy.motion.kind = MotionKind::follow_route;
  } else {
    copy.motion = waypoints_of(actor, id, trace, map);
  }
  return copy;
}

}  // namespace

std::string map_with_parameters(const MapReference& map) {
  std::string name = map.name;
  for (std::size_t i = 0; i < map.parameters.size(); ++i) {
    SCENFUZZ_DEMAND(is_constant(map.parameters[i].value));
    name += (i ? "&" : "?") + map.parameters[i].name + "=" +
            format_number(map.parameters[i].value.constant);
  }
  return name;
}

ScenarioTemplate replay_scenario(const ScenarioTemplate& accident, const Trace& trace,
                                 const RoadMap& map) {
  SCENFUZZ_DEMAND(trace.sample_count() > 0);
  ScenarioTemplate replay;
  replay.language = SourceLanguage::avunit;
  replay.has_scenario = true;
  replay.scenario_name = "accident";
  replay.trace_name = "trace";
  replay.map.name = map_with_parameters(accident.map);
  replay.ego = replayed(accident.ego, trace, map);
  for (const Actor& vehicle : accident.vehicles)
    replay.vehicles.push_back(replayed(vehicle, trace, map));
  replay.obstacles = accident.obstacles;
  // The lights show the described colours at the start, as in the reconstruction.
  replay.traffic.lights = accident.traffic.lights;
  // The others replay the accident whatever the ego does, as the reconstruction's vehicles did.
  replay.npc_behaviour = NpcBehaviour::scripted;
  return replay;
}

}  // namespace scenfuzz
