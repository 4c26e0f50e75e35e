#include "lang/walk_values.hpp"

namespace scenfuzz {

namespace {

using Visit = ValueVisitor;

void walk(Value& value, const std::string& path, const std::string& unit, const Visit& visit) {
  visit(value, path, unit);
}

void walk_optional(std::optional<Value>& value, const std::string& path, const std::string& unit,
                   const Visit& visit) {
  if (value) visit(*value, path, unit);
}

void walk_term(SpecTerm& term, const std::string& path, const Visit& visit);

void walk_position(Position& position, const std::string& path, const Visit& visit) {
  switch (position.kind) {
    case PositionKind::coordinate: {
      std::string unit = position.frame == Frame::wgs84 ? "deg" : "m";
      walk(position.x, path + ".x", unit, visit);
      walk(position.y, path + ".y", unit, visit);
      walk_optional(position.z, path + ".z", "m", visit);
      break;
    }
    case PositionKind::lane:
    case PositionKind::relative:
      walk(position.s, path + ".s", "m", visit);
      walk_optional(position.lateral, path + ".lateral", "m", visit);
      break;
  }
}

void walk_heading(Heading& heading, const std::string& path, const Visit& visit) {
  walk(heading.angle, path, heading.unit == AngleUnit::degree ? "deg" : "rad", visit);
  if (heading.relative_to && heading.relative_to->kind == Direction::Kind::lane)
    walk(heading.relative_to->s, path + ".reference.s", "m", visit);
}

void walk_state(State& state, const std::string& path, const Visit& visit) {
  walk_position(state.position, path + ".position", visit);
  if (state.heading) walk_heading(*state.heading, path + ".heading", visit);
  walk_optional(state.speed, path + ".speed", "m/s", visit);
  walk_optional(state.acceleration, path + ".acceleration", "m/s^2", visit);
}

void walk_formula(Formula& formula, const std::string& path, const Visit& visit) {
  for (SpecTerm& term : formula.terms) walk_term(term, path, visit);
  for (Formula& operand : formula.operands) walk_formula(operand, path, visit);
}

void walk_term(SpecTerm& term, const std::string& path, const Visit& visit) {
  if (term.kind == TermKind::number) walk(term.value, path, "", visit);
  if (term.kind == TermKind::time_of_day) walk(term.value, path, "time of day", visit);
  if (term.position) walk_position(*term.position, path + ".position", visit);
  for (SpecTerm& operand : term.operands) walk_term(operand, path, visit);
}

void walk_actor(Actor& actor, const Visit& visit) {
  std::string prefix = actor.kind == ActorKind::ego ? "ego" : actor.name;
  walk_state(actor.initial, prefix + ".init", visit);
  Motion& motion = actor.motion;
  if (motion.kind == MotionKind::waypoints) {
    for (std::size_t i = 0; i < motion.states.size(); ++i)
      walk_state(motion.states[i], prefix + ".waypoint[" + std::to_string(i) + "]", visit);
  } else {
    for (State& state : motion.states) walk_state(state, prefix + ".motion", visit);
  }
  for (std::size_t i = 0; i < motion.phases.size(); ++i) {
    ManoeuvrePhase& phase = motion.phases[i];
    std::string phase_path = prefix + ".phase[" + std::to_string(i) + "]";
    for (NamedValue& parameter : phase.parameters)
      walk(parameter.value, phase_path + "." + parameter.name, "", visit);
    if (phase.start_when) walk_formula(*phase.start_when, phase_path + ".start", visit);
    if (phase.continue_while) walk_formula(*phase.continue_while, phase_path + ".while", visit);
  }
  if (actor.target) walk_state(*actor.target, prefix + ".target", visit);
  if (actor.type) walk_optional(actor.type->height, prefix + ".type.height", "m", visit);
}

void walk_points(std::vector<Point>& points, const std::string& path, const Visit& visit) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::string point_path = path + "[" + std::to_string(i) + "]";
    walk(points[i].x, point_path + ".x", "m", visit);
    walk(points[i].y, point_path + ".y", "m", visit);
  }
}

void walk_scenario(ScenarioTemplate& scenario, const Visit& visit) {
  for (NamedValue& parameter : scenario.map.parameters)
    walk(parameter.value, "map." + parameter.name, "", visit);
  for (RoadOutline& road : scenario.map.roads) {
    walk_points(road.left_boundary, "map." + road.name + ".left", visit);
    walk_points(road.centre_line, "map." + road.name + ".centre", visit);
    walk_points(road.right_boundary, "map." + road.name + ".right", visit);
  }
  if (scenario.has_scenario) walk_actor(scenario.ego, visit);
  for (Actor& actor : scenario.vehicles) walk_actor(actor, visit);
  for (Actor& actor : scenario.pedestrians) walk_actor(actor, visit);
  for (Obstacle& obstacle : scenario.obstacles) {
    walk_position(obstacle.position, obstacle.name + ".position", visit);
    if (obstacle.heading) walk_heading(*obstacle.heading, obstacle.name + ".heading", visit);
    if (obstacle.shape)
      for (std::size_t i = 0; i < obstacle.shape->dimensions.size(); ++i)
        walk(obstacle.shape->dimensions[i], obstacle.name + ".shape[" + std::to_string(i) + "]",
             "m", visit);
  }
  if (scenario.environment) {
    walk_optional(scenario.environment->time_of_day, "environment.time", "time of day", visit);
    for (WeatherComponent& component : scenario.environment->weather)
      walk(component.intensity, "environment." + component.kind, "", visit);
    walk_optional(scenario.environment->road_friction, "environment.road_friction", "", visit);
  }
  Traffic& traffic = scenario.traffic;
  for (SpeedLimit& limit : traffic.speed_limits) {
    walk(limit.lower, "traffic.speed_limit." + limit.lane + ".lower", "m/s", visit);
    walk(limit.upper, "traffic.speed_limit." + limit.lane + ".upper", "m/s", visit);
  }
  for (TrafficLightSetting& light : traffic.lights)
    if (light.position) walk_position(*light.position, "traffic." + light.id + ".position", visit);
  for (Position& position : traffic.stop_signs) walk_position(position, "traffic.stop_sign", visit);
  for (Position& position : traffic.level_crossings)
    walk_position(position, "traffic.level_crossing", visit);
  // Flows are named like actors (`flow1.rate`); the WMG front end names its own parameters.
  for (TrafficFlow& flow : traffic.flows) {
    walk(flow.rate, flow.name + ".rate", "veh/h", visit);
    walk_optional(flow.speed, flow.name + ".speed", "m/s", visit);
  }
  for (Spec& spec : scenario.specs) walk_formula(spec.formula, spec.name, visit);
  for (ExpectedCollision& collision : scenario.expected_collisions)
    if (collision.position) walk_position(*collision.position, "collision.position", visit);
  for (std::size_t i = 0; i < scenario.events.size(); ++i) {
    ScenarioEvent& event = scenario.events[i];
    std::string path = "event[" + std::to_string(i) + "]";
    if (event.guard) walk_formula(*event.guard, path + ".guard", visit);
    walk_optional(event.probability, path + ".probability", "", visit);
  }
  for (NamedValue& timer : scenario.timers) walk(timer.value, "timer." + timer.name, "s", visit);
  for (Formula& condition : scenario.end_conditions) walk_formula(condition, "end", visit);
  walk_optional(scenario.duration, "duration", "s", visit);
}

}  // namespace

void for_each_value(ScenarioTemplate& scenario, const ValueVisitor& visit) {
  walk_scenario(scenario, visit);
}

void for_each_value(const ScenarioTemplate& scenario, const ConstValueVisitor& visit) {
  // The walk never changes anything itself; only a mutable visitor could.
  walk_scenario(const_cast<ScenarioTemplate&>(scenario),
                [&](Value& value, const std::string& path, const std::string& unit) {
                  visit(value, path, unit);
                });
}

void for_each_value(State& state, const std::string& path, const ValueVisitor& visit) {
  walk_state(state, path, visit);
}
void for_each_value(Position& position, const std::string& path, const ValueVisitor& visit) {
  walk_position(position, path, visit);
}
void for_each_value(Heading& heading, const std::string& path, const ValueVisitor& visit) {
  walk_heading(heading, path, visit);
}
void for_each_value(Formula& formula, const std::string& path, const ValueVisitor& visit) {
  walk_formula(formula, path, visit);
}

}  // namespace scenfuzz
