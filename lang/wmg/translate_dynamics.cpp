// DYNAMIC_ELEMENTS to actors (docs/wmg-semantics.md, "Actors" and "Manoeuvre phases"): where each
// actor starts, which one is the ego, the manoeuvre phases of the others, timers, END.
#include <map>
#include <string>
#include <vector>

#include "lang/wmg/parser_cursor.hpp"
#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {

namespace {

constexpr double kKilometresPerHour = 3.6;
// Where an actor without `at [x, y]` stands along its lane (the contract's default).
constexpr double kDefaultLanePosition = 30.0;

bool is_rear(RelativeLocation sector) {
  return sector == RelativeLocation::rear || sector == RelativeLocation::rear_side_left ||
         sector == RelativeLocation::rear_side_right;
}

bool is_right(RelativeLocation sector) {
  return sector == RelativeLocation::front_side_right || sector == RelativeLocation::side_right ||
         sector == RelativeLocation::rear_side_right;
}

ActorKind actor_kind(ActorType type) {
  switch (type) {
    case ActorType::pedestrian: return ActorKind::pedestrian;
    case ActorType::cyclist: return ActorKind::cyclist;
    case ActorType::vehicle: return ActorKind::vehicle;
  }
  return ActorKind::vehicle;
}

std::optional<scenfuzz::ActorType> ir_type(ActorKind kind, SourceLocation location) {
  if (kind == ActorKind::pedestrian) return std::nullopt;
  scenfuzz::ActorType type;
  type.model = kind == ActorKind::cyclist ? "bicycle" : "car";
  type.general = true;
  type.location = location;
  return type;
}

Heading lane_heading(Value angle, const std::string& lane, SourceLocation location) {
  Heading heading;
  heading.angle = std::move(angle);
  heading.unit = AngleUnit::degree;
  heading.relative_to =
      Direction{Direction::Kind::lane, lane, constant_value(kDefaultLanePosition), {}, location};
  heading.location = location;
  return heading;
}

Actor absolute_actor(const AbsoluteActorInit& init, Translation& translation) {
  Actor actor;
  actor.name = init.actor.name;
  actor.kind = actor_kind(init.type.value);
  actor.location = init.location;
  actor.initial.location = init.location;
  const std::string prefix = actor.name + ".init.";
  const std::string lane = translation.lane_id(init.lane).value_or("");
  Position& position = actor.initial.position;
  position.location = init.location;
  if (init.position) {
    position.kind = PositionKind::coordinate;
    position.frame = Frame::enu;
    position.x = translation.number(init.position->x, prefix + "x", "m");
    position.y = translation.number(init.position->y, prefix + "y", "m");
  } else {
    position.kind = PositionKind::lane;
    position.lane = lane;
    position.s = constant_value(kDefaultLanePosition, init.lane.location);
  }
  if (init.heading)
    actor.initial.heading = lane_heading(
        translation.number(*init.heading, prefix + "heading", "deg", 1.0, ParameterKind::angle),
        lane, init.heading->location);
  return actor;
}

Actor relative_actor(const RelativeActorInit& init, Translation& translation) {
  Actor actor;
  actor.name = init.actor.name;
  actor.kind = actor_kind(init.type.value);
  actor.location = init.location;
  actor.initial.location = init.location;
  const std::string prefix = actor.name + ".init.";
  const RelativeLocation sector = init.relative_position.value;
  Position& position = actor.initial.position;
  position.kind = PositionKind::relative;
  position.location = init.location;
  position.lane = translation.lane_id(init.lane).value_or("");
  position.reference = init.reference.name;
  position.relative_location = sector_text(sector);
  position.s = constant_value(0.0, init.location);
  // The file writes distances; the sector says on which side they lie (ahead / left positive).
  for (const OffsetRelation& offset : init.offsets) {
    if (offset.relation.value == PositionRelation::longitudinal) {
      Value s = translation.number(offset.offset, prefix + "longitudinal_offset", "m");
      position.s = is_rear(sector) ? negated_value(s, offset.offset.location) : s;
    } else {
      Value lateral = translation.number(offset.offset, prefix + "lateral_offset", "m");
      // A pavement lies beyond the kerb, right of the generated (right-handed) road's kerb-side
      // lane, so an actor on one is offset towards it whatever side the sector names.
      const bool towards_kerb = is_right(sector) || init.lane.lane.name.starts_with("P");
      position.lateral = towards_kerb ? negated_value(lateral, offset.offset.location) : lateral;
    }
  }
  Heading heading;
  heading.angle = translation.number(init.relative_heading, prefix + "relative_heading", "deg", 1.0,
                                     ParameterKind::angle);
  heading.unit = AngleUnit::degree;
  heading.relative_to =
      Direction{Direction::Kind::actor, "", {}, init.reference.name, init.reference.location};
  heading.location = init.relative_heading.location;
  actor.initial.heading = heading;
  return actor;
}

scenfuzz::ManoeuvrePhase translate_phase(const wmg::ManoeuvrePhase& phase, const std::string& actor,
                                         const std::string& prefix, Translation& translation) {
  scenfuzz::ManoeuvrePhase result;
  result.manoeuvre = phase.type.text;
  result.location = phase.location;
  result.parameters.push_back(NamedValue{
      "speed", translation.number(phase.agent.first, prefix + "speed", "km/h", kKilometresPerHour),
      phase.agent.first.location});
  result.parameters.push_back(
      NamedValue{"duration", translation.number(phase.agent.second, prefix + "duration", "s"),
                 phase.agent.second.location});
  result.parameters.push_back(
      NamedValue{"gap", translation.number(phase.relative.distance, prefix + "gap", "m"),
                 phase.relative.distance.location});
  if (translation.check_actor(phase.relative.reference))
    result.reference = phase.relative.reference.name;
  // A road named in the agent parameters is the one a crossing crosses.
  if (phase.agent.agent && detail::is_road_id(phase.agent.agent->name)) {
    const auto road = translation.roads.find(phase.agent.agent->name);
    if (road != translation.roads.end())
      result.road_lanes = road->second.map_lanes();
    else
      translation.diagnostics.error(
          phase.agent.agent->location,
          "the phase names road '" + phase.agent.agent->name + "', which is not in the scenery");
  }
  result.relative_location = sector_text(phase.relative.relative_location.value);
  if (phase.while_constraint)
    result.continue_while =
        while_formula(*phase.while_constraint, prefix + "while.", translation, actor);
  return result;
}

}  // namespace

// The ego: the actor whose condition guards a `DO: AUTO`, else the first initialised.
std::string ego_name(const Dynamics& dynamics) {
  for (const Ssms& ssms : dynamics.sequences) {
    if (!ssms.autonomous) continue;
    for (const WhenCondition& condition : ssms.conditions)
      if (const auto* actor = std::get_if<ActorCondition>(&condition)) return actor->actor.name;
  }
  return dynamics.initialisation.first.actor.name;
}

void translate_dynamics(const Dynamics& dynamics, Translation& translation) {
  const Initialisation& init = dynamics.initialisation;
  std::vector<Actor> actors;
  actors.push_back(absolute_actor(init.first, translation));
  translation.actors[init.first.actor.name] = actors.back().kind;
  for (const RelativeActorInit& relative : init.relative) {
    if (translation.actors.contains(relative.actor.name)) {
      translation.diagnostics.error(relative.actor.location,
                                    "actor '" + relative.actor.name + "' is initialised twice");
      continue;
    }
    if (!translation.actors.contains(relative.reference.name)) {
      translation.diagnostics.error(relative.reference.location,
                                    "'" + relative.actor.name + "' is placed relative to '" +
                                        relative.reference.name +
                                        "', which is not initialised before it");
      continue;
    }
    actors.push_back(relative_actor(relative, translation));
    translation.actors[relative.actor.name] = actors.back().kind;
  }
  for (const TimerInit& timer : init.timers) {
    translation.timers.insert(timer.timer.name);
    if (timer.scope.value == TimerScope::local) translation.local_timers.insert(timer.timer.name);
    translation.scenario.timers.push_back(NamedValue{
        timer.timer.name, translation.number(timer.value, "timer." + timer.timer.name, "s"),
        timer.location});
  }

  const std::string ego = ego_name(dynamics);
  if (!translation.actors.contains(ego)) {
    translation.diagnostics.error(dynamics.location,
                                  "the ego '" + ego + "' is referenced but not initialised");
    return;
  }
  std::optional<Value> initial_ego_speed;
  for (std::size_t s = 0; s < dynamics.sequences.size(); ++s) {
    const Ssms& ssms = dynamics.sequences[s];
    const std::string when_prefix = "when" + std::to_string(s + 1) + ".";
    std::optional<Formula> start_when;
    std::map<std::string, Value> speeds;
    if (!ssms.conditions.empty())
      start_when = when_formula(ssms.conditions, when_prefix, translation, speeds);
    // The speed the ego is seen at when a sequence starts is the speed it starts with.
    if (!initial_ego_speed && speeds.contains(ego)) initial_ego_speed = speeds.at(ego);
    for (const ManoeuvreSequence& sequence : ssms.sequences) {
      if (!translation.check_actor(sequence.actor)) continue;
      Actor* actor = nullptr;
      for (Actor& candidate : actors)
        if (candidate.name == sequence.actor.name) actor = &candidate;
      actor->motion.kind = MotionKind::manoeuvres;
      actor->motion.location = sequence.location;
      for (std::size_t p = 0; p < sequence.phases.size(); ++p) {
        const wmg::ManoeuvrePhase& phase = sequence.phases[p];
        scenfuzz::ManoeuvrePhase translated = translate_phase(
            phase, actor->name, actor->name + ".phase" + std::to_string(phase.number.value) + ".",
            translation);
        if (p == 0) translated.start_when = start_when;
        actor->motion.phases.push_back(std::move(translated));
      }
    }
  }

  for (std::size_t e = 0; e < dynamics.end_conditions.size(); ++e)
    translation.scenario.end_conditions.push_back(
        end_formula(dynamics.end_conditions[e], "end" + std::to_string(e + 1) + ".", translation));
  if (dynamics.end_conditions.empty()) translation.scenario.duration = constant_value(30.0);

  for (Actor& actor : actors) {
    actor.type = ir_type(actor.kind, actor.location);
    // A car about to reverse stands still: it sets off backwards when its phase starts, rather
    // than arriving forwards at its reversing speed.
    const bool reverses_first = !actor.motion.phases.empty() &&
                                actor.motion.phases.front().manoeuvre.starts_with("Reverse");
    if (!actor.motion.phases.empty() && !reverses_first)
      for (const NamedValue& parameter : actor.motion.phases.front().parameters)
        if (parameter.name == "speed") actor.initial.speed = parameter.value;
    if (actor.name == ego) {
      if (actor.kind != ActorKind::vehicle) {
        translation.diagnostics.error(actor.location, "the ego '" + ego + "' must be a vehicle");
        continue;
      }
      if (initial_ego_speed) actor.initial.speed = initial_ego_speed;
      actor.kind = ActorKind::ego;
      translation.scenario.ego = std::move(actor);
    } else if (actor.kind == ActorKind::pedestrian) {
      translation.scenario.pedestrians.push_back(std::move(actor));
    } else {
      translation.scenario.vehicles.push_back(std::move(actor));
    }
  }
}

}  // namespace scenfuzz::wmg
