// A reconstruction as a concrete AVUnit scenario (reconstruction_scenario.hpp).
#include "fuzz/reconstruction_scenario.hpp"

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

// Rounded as a person reads them: centimetres, tenths of a degree, centimetres per second.
double rounded(double value, double unit) { return std::round(value / unit) * unit; }

State state_at(const TraceActor& actor, std::size_t i) {
  State state;
  state.position.kind = PositionKind::coordinate;
  state.position.x = constant_value(rounded(actor.x[i], 0.01));
  state.position.y = constant_value(rounded(actor.y[i], 0.01));
  Heading heading;
  heading.angle = constant_value(rounded(actor.heading[i] * 180 / std::numbers::pi, 0.1));
  heading.unit = AngleUnit::degree;
  state.heading = heading;
  state.speed = constant_value(rounded(actor.speed[i], 0.01));
  return state;
}

const TraceActor& trace_actor(const Trace& trace, const std::string& name) {
  const std::optional<ActorId> id = trace.find_actor(name);
  SCENFUZZ_DEMAND(id.has_value());
  return trace.actors[*id];
}

// Its run as waypoints every kWaypointInterval, the last sample included.
Motion waypoints_of(const TraceActor& actor, const Trace& trace) {
  Motion motion;
  motion.kind = MotionKind::waypoints;
  const std::size_t step =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kWaypointInterval / trace.dt)));
  const std::size_t last = trace.sample_count() - 1;
  std::size_t previous = 0;
  // Every interval up to the last sample, which always ends the path.
  for (std::size_t i = std::min(step, last); i > previous; i = std::min(i + step, last)) {
    const bool moved =
        std::hypot(actor.x[i] - actor.x[previous], actor.y[i] - actor.y[previous]) >=
        kStandingStill;
    if (moved) {
      motion.states.push_back(state_at(actor, i));
      previous = i;
    }
    if (i == last) break;
  }
  if (motion.states.empty()) motion.states.push_back(state_at(actor, last));
  return motion;
}

Actor replayed(const Actor& described, const Trace& trace) {
  const TraceActor& actor = trace_actor(trace, described.name);
  Actor copy;
  copy.kind = described.kind;
  copy.name = described.name;
  copy.type = described.type;
  copy.initial = state_at(actor, 0);
  if (described.kind == ActorKind::ego) {
    copy.target = state_at(actor, trace.sample_count() - 1);
    copy.motion.kind = MotionKind::follow_route;
  } else {
    copy.motion = waypoints_of(actor, trace);
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

ScenarioTemplate replay_scenario(const ScenarioTemplate& accident, const Trace& trace) {
  SCENFUZZ_DEMAND(trace.sample_count() > 0);
  ScenarioTemplate replay;
  replay.language = SourceLanguage::avunit;
  replay.has_scenario = true;
  replay.scenario_name = "accident";
  replay.trace_name = "trace";
  replay.map.name = map_with_parameters(accident.map);
  replay.ego = replayed(accident.ego, trace);
  for (const Actor& vehicle : accident.vehicles)
    replay.vehicles.push_back(replayed(vehicle, trace));
  replay.obstacles = accident.obstacles;
  // The others replay the accident whatever the ego does, as the reconstruction's vehicles did.
  replay.npc_behaviour = NpcBehaviour::scripted;
  return replay;
}

}  // namespace scenfuzz
