// Evaluates a scenario's actors, obstacles, lights and environment at one point of the search
// space, and plans what the scripted actors will do.
#include "physics/simulation/scenario_setup.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "lang/number_format.hpp"
#include "lang/spec_horizon.hpp"
#include "physics/actors/friction_circle.hpp"
#include "physics/actors/path_pose.hpp"
#include "physics/actors/random_walk.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/scenario_position.hpp"
#include "physics/planning/path_planner.hpp"
#include "physics/simulation/default_duration.hpp"
#include "physics/simulation/lane_links.hpp"
#include "physics/simulation/relative_position.hpp"
#include "physics/simulation/scenario_checks.hpp"
#include "physics/simulation/shortfall_warnings.hpp"
#include "physics/simulation/simulation_limits.hpp"
#include "physics/simulation/traffic_flows.hpp"
#include "physics/simulation/waypoint_path.hpp"

namespace scenfuzz {
namespace {

constexpr double kDefaultPedestrianSpeed = 1.2;  // m/s, a typical walking pace
constexpr double kRandomWalkRadius = 10;         // m around the start
// Scripted NPCs stop at the end of their path as a calm driver would.
constexpr double kPathEndMargin = 50;  // m of lane beyond what the duration needs
// The ego changes lane this far along the lane it leaves (not at once, as find_route would), so
// that it can check the next lane and wait for a gap.
constexpr double kLaneChangePreparation = 40;

struct Context {
  const ScenarioTemplate& scenario;
  std::span<const double> values;
  const RoadMap& map;
  std::uint64_t seed;
  Diagnostics& diagnostics;
  std::optional<MapPose> ego_pose;
  std::unordered_map<std::string, double> initial_headings;  // by actor name
  std::unordered_map<std::string, MapPose> initial_poses;    // by actor name
  std::string actor;        // the actor being prepared, for messages
  bool pedestrian = false;  // whether it is one, for the bound on its speeds
  double duration = kDefaultDuration;
  double road_friction = kDryRoad;  // every vehicle's body is on it (body_of)
};

double heading_in_radians(const Heading& heading, std::span<const double> values) {
  double angle = evaluate(heading.angle, values);
  return heading.unit == AngleUnit::degree ? angle * std::numbers::pi / 180 : angle;
}

// The direction a heading is measured from, or nullopt after reporting why it is unknown.
std::optional<double> reference_heading(Context& context, const Direction& direction) {
  switch (direction.kind) {
    case Direction::Kind::lane: {
      auto lane = context.map.find_lane(direction.lane);
      if (!lane) {
        context.diagnostics.error(direction.location, "unknown lane '" + direction.lane +
                                                          "' on map '" + context.map.name() + "'");
        return std::nullopt;
      }
      double s =
          std::clamp(evaluate(direction.s, context.values), 0.0, context.map.lane(*lane).length());
      return lane_heading_at(context.map, *lane, s);
    }
    case Direction::Kind::ego:
      if (!context.ego_pose) {
        context.diagnostics.error(direction.location,
                                  "the ego's own heading cannot be related to the ego");
        return std::nullopt;
      }
      return context.ego_pose->heading;
    case Direction::Kind::actor: {
      auto known = context.initial_headings.find(direction.actor);
      if (known == context.initial_headings.end()) {
        context.diagnostics.error(direction.location,
                                  "the heading is related to '" + direction.actor +
                                      "', whose initial heading is not known here (only actors "
                                      "defined before this one, and the ego, can be referred to)");
        return std::nullopt;
      }
      return known->second;
    }
  }
  return std::nullopt;
}

// `pose` turned to the heading `state` gives.
std::optional<MapPose> with_heading(Context& context, const State& state, MapPose pose) {
  double angle = heading_in_radians(*state.heading, context.values);
  if (!std::isfinite(angle)) {
    context.diagnostics.error(state.heading->location, "the heading is not a finite number");
    return std::nullopt;
  }
  if (state.heading->relative_to) {
    auto reference = reference_heading(context, *state.heading->relative_to);
    if (!reference) return std::nullopt;
    angle += *reference;
  }
  pose.heading = angle;
  return pose;
}

// A vehicle placed on a lane with a heading that runs against the lane's direction (a relative
// heading read from the wrong side, say) would start across or against its own lane: it takes the
// lane's direction, with a warning. A pedestrian crosses as asked.
void keep_to_lane(Context& context, const Heading& written, double lane_heading, MapPose& pose) {
  constexpr double kAgainstTheLane = std::numbers::pi / 2;
  const double off = std::abs(angle_difference(pose.heading, lane_heading));
  if (!(off > kAgainstTheLane)) return;
  constexpr double kDegrees = 180 / std::numbers::pi;
  context.diagnostics.warning(
      written.location,
      context.actor + "'s heading (" + format_number(std::round(pose.heading * kDegrees)) +
          " deg) runs " + format_number(std::round(off * kDegrees)) +
          " deg against the direction of the lane it is placed on (" +
          format_number(std::round(lane_heading * kDegrees)) + " deg); it takes the lane's");
  pose.heading = lane_heading;
}

// A state's pose: its position, and its heading (the lane's direction when it gives none).
std::optional<MapPose> place_state_unchecked(Context& context, const State& state) {
  if (state.position.kind == PositionKind::relative) {
    const Position& position = state.position;
    auto reference = context.initial_poses.find(position.reference);
    if (reference == context.initial_poses.end()) {
      context.diagnostics.error(position.location,
                                context.actor + " is placed relative to '" + position.reference +
                                    "', whose initial position is not known here (only the ego "
                                    "and actors defined before " +
                                    context.actor + " can be referred to)");
      return std::nullopt;
    }
    auto pose = place_relative(context.map, position, context.values, reference->second,
                               context.pedestrian, context.actor, context.diagnostics);
    if (!pose || !state.heading) return pose;
    // The position is taken along the lane, and so is a heading measured from nothing else.
    double lane_heading = pose->heading;
    auto turned = with_heading(context, state, *pose);
    if (turned && !state.heading->relative_to) turned->heading += lane_heading;
    if (turned && !context.pedestrian) keep_to_lane(context, *state.heading, lane_heading, *turned);
    return turned;
  }
  auto placed = place_position(context.map, state.position, context.values, context.ego_pose,
                               context.diagnostics);
  if (!placed) return std::nullopt;
  if (placed->overshoot > 0.01)
    context.diagnostics.warning(state.position.location,
                                "s lies " + format_number(placed->overshoot) + " m outside lane '" +
                                    state.position.lane +
                                    "'; the lane's end is used, as Apollo does");
  MapPose pose = placed->pose;
  if (!state.heading) {
    if (!placed->lane) {
      auto lane = project_to_lane(context.map, pose.position);
      if (lane) pose.heading = lane_heading_at(context.map, lane->lane, lane->s);
    }
    return pose;
  }
  return with_heading(context, state, pose);
}

// As place_state_unchecked, and the position lies on some map: absurd coordinates (1e300 from a
// careless range) are an error here, not a non-finite pose in the collision world later.
std::optional<MapPose> place_state(Context& context, const State& state) {
  auto pose = place_state_unchecked(context, state);
  if (pose && !check_position(pose->position, state.position.location, context.diagnostics))
    return std::nullopt;
  return pose;
}

// A speed the scenario gives, checked; `fallback` when it gives none.
std::optional<double> speed_of(Context& context, const State& state, double fallback) {
  if (!state.speed) return fallback;
  double speed = evaluate(*state.speed, context.values);
  if (!check_speed(speed, context.pedestrian, context.actor, state.speed->location,
                   context.diagnostics))
    return std::nullopt;
  return speed;
}

ActorClass body_of(Context& context, const Actor& actor, ActorCategory fallback) {
  ActorCategory category = fallback;
  if (actor.type && !actor.type->model.empty()) {  // a pedestrian's type may give only a height
    auto known = category_for_model(actor.type->model);
    if (known) {
      category = *known;
    } else {
      context.diagnostics.warning(
          actor.type->location, "unknown vehicle model '" + actor.type->model +
                                    "'; simulated as a " + std::string(actor_class(fallback).name) +
                                    " (docs/simulation.md lists the known models)");
    }
  }
  ActorClass body = on_road(actor_class(category), context.road_friction);
  if (actor.type && actor.type->height) {
    double height = evaluate(*actor.type->height, context.values);
    if (std::isfinite(height) && height > 0) body.height = height;
  }
  return body;
}

std::uint64_t actor_seed(std::uint64_t seed, std::size_t actor) {
  // SplitMix64 of (seed, actor): neighbouring actors get unrelated streams.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (actor + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A vehicle that follows lanes: to its target over the lane graph, or along the lanes ahead.
// Scripted, it keeps `speed` along the path; reactive (`drive`), it aims for it.
std::optional<Trajectory> lane_following(Context& context, const Actor& actor, const MapPose& start,
                                         double initial_speed, double speed, const ActorClass& body,
                                         std::optional<LaneDrive>& drive) {
  // The lane the actor starts in, and how far off its centre line (kept along the way).
  auto start_lane = project_to_lane(context.map, start.position, start.heading);
  if (!start_lane) return Trajectory::standing(start);
  std::optional<LaneRoute> route;
  if (actor.target) {
    auto target = place_state(context, *actor.target);
    if (!target) return std::nullopt;
    route = find_route(context.map, start, *target);
    if (!route) {
      context.diagnostics.error(actor.target->location, "no route over the lanes of map '" +
                                                            context.map.name() + "' leads from " +
                                                            actor.name +
                                                            "'s initial position to this target");
      return std::nullopt;
    }
  } else {
    route = route_ahead(context.map, LanePosition{start_lane->lane, start_lane->s, 0},
                        speed * context.duration + kPathEndMargin);
  }
  if (route->segments.empty() || route->length < 0.5) return Trajectory::standing(start);
  double lateral = start_lane->lateral;
  std::vector<PathPlace> places;
  Polyline path = rounded_route_path(context.map, *route, lateral, planning_radius(body), places);
  drive = LaneDrive{*route, path, std::move(places), speed, initial_speed};
  if (context.scenario.npc_behaviour.value_or(NpcBehaviour::reactive) == NpcBehaviour::reactive)
    warn_reactive_start(path, body, initial_speed, actor.name, start_point(actor),
                        context.diagnostics);
  // A calm driver's bends, at the class's comfortable lateral acceleration: slowing for them is
  // what the scenario's speed means on a road that bends, so it is no shortfall to warn about.
  return Trajectory(std::move(path), {{0, speed}},
                    class_motion_limits(body, body.comfortable_lateral_acceleration));
}

// A pedestrian walks in straight lines: along its heading, or to its target.
std::optional<Trajectory> straight_walk(Context& context, const Actor& actor, const MapPose& start,
                                        double speed) {
  MapPoint end;
  if (actor.target) {
    auto target = place_state(context, *actor.target);
    if (!target) return std::nullopt;
    end = target->position;
  } else {
    double reach = std::max(speed * context.duration, 1.0);
    end = {start.position.x + reach * std::cos(start.heading),
           start.position.y + reach * std::sin(start.heading)};
  }
  if (speed <= 0 || distance(start.position, end) < 0.01) return Trajectory::standing(start);
  std::vector<MapPoint> points{start.position, end};
  return Trajectory(Polyline(points), {{0, speed}},
                    class_motion_limits(actor_class(ActorCategory::pedestrian), 0));
}

// Through the waypoints in order (then the target): for vehicles along the lanes where the
// waypoints lie on lanes, else OMPL paths (waypoint_path.hpp has the rules); straight legs for
// pedestrians. The speed given at each waypoint is reached there.
std::optional<Trajectory> through_waypoints(Context& context, const Actor& actor,
                                            const MapPose& start, double speed,
                                            const ActorClass& body, std::size_t actor_index,
                                            const CollisionWorld& obstacles,
                                            const BodyGeometry& geometry) {
  std::vector<MapPose> poses{start};
  std::vector<double> speeds{speed};
  std::vector<State> states = actor.motion.states;
  if (actor.target) states.push_back(*actor.target);
  for (const State& state : states) {
    auto pose = place_state(context, state);
    if (!pose) return std::nullopt;
    if (!state.heading)
      pose->heading =
          waypoint_heading(context.map, poses.back().position, pose->position, pose->heading);
    auto waypoint_speed = speed_of(context, state, speeds.back());
    if (!waypoint_speed) return std::nullopt;
    if (distance(pose->position, poses.back().position) < 0.01) {
      speeds.back() = *waypoint_speed;  // a waypoint where the actor already is: a new speed
      continue;
    }
    poses.push_back(*pose);
    speeds.push_back(*waypoint_speed);
  }
  if (poses.size() < 2) return Trajectory::standing(start);

  std::vector<MapPoint> points;
  std::vector<double> waypoint_s;
  if (body.category == ActorCategory::pedestrian) {
    double s = 0;
    for (std::size_t i = 0; i < poses.size(); ++i) {
      if (i > 0) s += distance(poses[i - 1].position, poses[i].position);
      points.push_back(poses[i].position);
      waypoint_s.push_back(s);
    }
  } else {
    WaypointPathRequest request{poses,
                                speeds,
                                planning_radius(body),
                                body.comfortable_lateral_acceleration,
                                {},
                                actor_seed(context.seed, actor_index)};
    if (obstacles.body_count() > 0)
      request.is_free = [&](const MapPose& pose) {
        return !obstacles.touches_static(geometry, pose);
      };
    try {
      WaypointPath path = waypoint_path(context.map, request);
      points = std::move(path.points);
      waypoint_s = std::move(path.waypoint_s);
    } catch (const PlanningError& error) {
      context.diagnostics.error(
          actor.motion.location.line > 0 ? actor.motion.location : actor.location,
          "cannot plan " + actor.name + "'s path through its waypoints: " + error.what());
      return std::nullopt;
    }
  }
  std::vector<SpeedPoint> profile;
  std::vector<std::size_t> profile_poses;  // the pose each speed point is at, for warnings
  for (std::size_t i = 0; i < waypoint_s.size(); ++i) {
    if (!profile.empty() && waypoint_s[i] <= profile.back().s) continue;
    profile.push_back({waypoint_s[i], speeds[i]});
    profile_poses.push_back(i);
  }
  // The actor stops at the path's end, which is the last waypoint. It keeps its script where its
  // class can: cornering up to nearly its grip (the audit's limit), not at a calm driver's.
  Trajectory trajectory(
      Polyline(points), std::move(profile),
      class_motion_limits(body, kScriptedGripShare * grip_lateral_acceleration(body)));
  warn_shortfalls(trajectory, actor.name,
                  waypoint_points(actor, states, poses.size(), profile_poses), context.diagnostics);
  return trajectory;
}

const SourceLocation& where(const SourceLocation& preferred, const SourceLocation& fallback) {
  return preferred.line > 0 ? preferred : fallback;
}

// An actor's manoeuvre phases with their primitives and arguments; references and conditions
// are resolved once every actor is known (resolve_phases).
std::optional<ManoeuvreScript> manoeuvre_script(Context& context, const Actor& actor,
                                                const MapPose& start, double speed,
                                                const ActorClass& body) {
  ManoeuvreScript script;
  script.initial.x = start.position.x;
  script.initial.y = start.position.y;
  script.initial.heading = start.heading;
  script.initial.speed = std::min(speed, body.max_speed);
  bool ok = true;
  for (const ManoeuvrePhase& phase : actor.motion.phases) {
    const SourceLocation& location = where(phase.location, actor.location);
    PhaseMotion motion;
    motion.manoeuvre = phase.manoeuvre;
    auto choice = motion_primitive_named(phase.manoeuvre);
    if (!choice) {
      context.diagnostics.error(location, actor.name + "'s manoeuvre '" + phase.manoeuvre +
                                              "' is not simulated (docs/simulation.md lists the "
                                              "motion primitives)");
      ok = false;
      continue;
    }
    motion.choice = *choice;
    for (const NamedValue& parameter : phase.parameters) {
      std::optional<double>* slot = parameter.name == "speed"      ? &motion.speed
                                    : parameter.name == "duration" ? &motion.duration
                                    : parameter.name == "gap"      ? &motion.gap
                                                                   : nullptr;
      if (!slot) continue;  // other arguments describe the phase but do not move the actor
      double value = evaluate(parameter.value, context.values);
      bool valid = std::isfinite(value) && (parameter.name == "gap" || value >= 0);
      if (!valid) {
        context.diagnostics.error(where(parameter.location, location),
                                  actor.name + "'s " + parameter.name + " must be a finite number" +
                                      (parameter.name == "gap" ? "" : " >= 0") + ", not " +
                                      format_number(value));
        ok = false;
        continue;
      }
      if (parameter.name == "speed" &&
          !check_speed(value, context.pedestrian, actor.name, where(parameter.location, location),
                       context.diagnostics)) {
        ok = false;
        continue;
      }
      *slot = value;
    }
    for (const std::string& id : phase.road_lanes) {
      if (const auto lane = context.map.find_lane(id)) {
        motion.road_lanes.push_back(*lane);
        continue;
      }
      context.diagnostics.error(location, actor.name + "'s '" + phase.manoeuvre + "' names lane '" +
                                              id + "', which map '" + context.map.name() +
                                              "' does not have");
      ok = false;
    }
    bool turn = choice->primitive == MotionPrimitive::turn_left ||
                choice->primitive == MotionPrimitive::turn_right;
    if (turn) {
      LaneTurn wanted =
          choice->primitive == MotionPrimitive::turn_left ? LaneTurn::left : LaneTurn::right;
      const auto& lanes = context.map.lanes();
      bool any = std::any_of(lanes.begin(), lanes.end(), [&](const Lane& lane) {
        return lane.junction && lane.turn == wanted;
      });
      if (!any)
        context.diagnostics.warning(location, "map '" + context.map.name() + "' has no " +
                                                  (wanted == LaneTurn::left ? "left" : "right") +
                                                  "-turn connector; " + actor.name +
                                                  " keeps its lane in '" + phase.manoeuvre + "'");
      if (const auto lane = project_to_lane(context.map, start.position, start.heading))
        warn_of_turn_against_links(context.map, context.scenario.map.links, lane->lane, wanted,
                                   actor.name + "'s '" + phase.manoeuvre + "'", location,
                                   context.diagnostics);
    }
    script.phases.push_back(std::move(motion));
  }
  if (!ok) return std::nullopt;
  return script;
}

// A script's phase references and conditions, resolved against `names` (by actor id: the ego,
// then the prepared actors); `actor` is the scenario's actor the script was made from.
void resolve_script(Context& context, const std::vector<std::string>& names,
                    const TriggerNames& trigger_names, const Actor& actor,
                    ManoeuvreScript& script) {
  auto compile = [&](const std::optional<Formula>& formula, std::optional<TriggerCondition>& to) {
    if (formula) to = compile_trigger(*formula, trigger_names, context.diagnostics);
  };
  auto& phases = script.phases;
  for (std::size_t p = 0; p < phases.size() && p < actor.motion.phases.size(); ++p) {
    const ManoeuvrePhase& phase = actor.motion.phases[p];
    if (!phase.reference.empty()) {
      auto found = std::find(names.begin(), names.end(), phase.reference);
      if (found == names.end())
        context.diagnostics.error(where(phase.location, actor.location),
                                  actor.name + "'s phase " + std::to_string(p + 1) +
                                      " refers to an unknown actor '" + phase.reference + "'");
      else
        phases[p].reference = static_cast<std::uint32_t>(found - names.begin());
    }
    compile(phase.start_when, phases[p].start_when);
    compile(phase.continue_while, phases[p].continue_while);
  }
}

// Each phase's reference actor and conditions (the ego's script's too), and the scenario's
// timers and end conditions, resolved against the prepared actors (`sources[i]` is the
// scenario's actor of setup.actors[i]).
void resolve_phases(Context& context, SimulationSetup& setup,
                    const std::vector<const Actor*>& sources) {
  std::vector<std::string> names{setup.ego_name};
  for (const ScriptedActor& actor : setup.actors) names.push_back(actor.name);
  for (const NamedValue& timer : context.scenario.timers) {
    double initial = evaluate(timer.value, context.values);
    if (!std::isfinite(initial)) {
      context.diagnostics.error(timer.location,
                                "timer " + timer.name + " starts at " + format_number(initial));
      continue;
    }
    setup.timer_names.push_back(timer.name);
    setup.timer_initial_values.push_back(initial);
  }
  TriggerNames trigger_names{context.map, names, setup.timer_names, setup.timer_initial_values,
                             context.values};
  if (setup.ego_script)
    resolve_script(context, names, trigger_names, context.scenario.ego, *setup.ego_script);
  for (std::size_t i = 0; i < setup.actors.size(); ++i)
    if (setup.actors[i].manoeuvres)
      resolve_script(context, names, trigger_names, *sources[i], *setup.actors[i].manoeuvres);
  for (const Formula& formula : context.scenario.end_conditions) {
    auto condition = compile_trigger(formula, trigger_names, context.diagnostics);
    if (condition) setup.end_conditions.push_back(std::move(*condition));
  }
}

// Whether the ego replays its phases as a script instead of being driven. Only an accident
// reconstruction asks that: WMG SDL gives the ego phases too when a sequence names it, and there
// the ego under test is still driven by its driver (the phases give at most its initial speed).
bool ego_replays_script(const ScenarioTemplate& scenario) {
  return scenario.ego.motion.kind == MotionKind::manoeuvres &&
         scenario.language == SourceLanguage::accident;
}

// Scripted NPC behaviour: every script, the ego's included, runs without looking. Otherwise a
// CH-Scenario vehicle's phases stop at red lights (ManoeuvreScript::heeds_lights).
void set_heedless(SimulationSetup& setup, SourceLanguage language) {
  const bool heedless = setup.npc_behaviour == NpcBehaviour::scripted;
  if (setup.ego_script) setup.ego_script->heedless = heedless;
  for (ScriptedActor& actor : setup.actors)
    if (actor.manoeuvres) {
      actor.manoeuvres->heedless = heedless;
      actor.manoeuvres->heeds_lights = !heedless && language == SourceLanguage::ch_scenario;
    }
}

// A vehicle that turns at no phase takes the lanes ahead through a junction: straight on, which
// the file's lane connections from its lane should allow (lane_links.hpp).
void warn_of_way_against_links(Context& context, const Actor& actor, const MapPose& start) {
  if (actor.motion.kind == MotionKind::waypoints) return;  // its path is its own
  for (const ManoeuvrePhase& phase : actor.motion.phases) {
    const auto choice = motion_primitive_named(phase.manoeuvre);
    if (choice && (choice->primitive == MotionPrimitive::turn_left ||
                   choice->primitive == MotionPrimitive::turn_right))
      return;  // its turn phase is checked as such
  }
  if (const auto lane = project_to_lane(context.map, start.position, start.heading))
    warn_of_turn_against_links(context.map, context.scenario.map.links, lane->lane, LaneTurn::none,
                               actor.name, actor.location, context.diagnostics);
}

std::optional<ScriptedActor> prepare_actor(Context& context, const Actor& actor,
                                           std::size_t actor_index,
                                           const CollisionWorld& obstacles) {
  bool pedestrian = actor.kind == ActorKind::pedestrian;
  ScriptedActor scripted;
  scripted.name = actor.name;
  scripted.kind = pedestrian ? TraceActorKind::pedestrian : TraceActorKind::vehicle;
  scripted.body = body_of(context, actor,
                          pedestrian                         ? ActorCategory::pedestrian
                          : actor.kind == ActorKind::cyclist ? ActorCategory::bicycle
                                                             : ActorCategory::car);
  context.actor = actor.name;
  context.pedestrian = pedestrian;
  auto start = place_state(context, actor.initial);
  if (!start) return std::nullopt;
  context.initial_headings[actor.name] = start->heading;
  context.initial_poses[actor.name] = *start;
  auto initial_speed = speed_of(context, actor.initial, 0.0);
  if (!initial_speed) return std::nullopt;
  BodyGeometry geometry{BodyShape::box, scripted.body.length, scripted.body.width,
                        scripted.body.height};

  std::optional<Trajectory> trajectory;
  switch (actor.motion.kind) {
    case MotionKind::follow_route:
    case MotionKind::uniform: {
      double speed = *initial_speed;
      if (actor.motion.kind == MotionKind::uniform && !actor.motion.states.empty()) {
        auto uniform = speed_of(context, actor.motion.states.front(), speed);
        if (!uniform) return std::nullopt;
        speed = *uniform;
      }
      if (pedestrian && speed == 0 && actor.motion.kind == MotionKind::uniform)
        speed = kDefaultPedestrianSpeed;
      trajectory = pedestrian ? straight_walk(context, actor, *start, speed)
                              : lane_following(context, actor, *start,
                                               actor.initial.speed ? *initial_speed : speed, speed,
                                               scripted.body, scripted.lane_drive);
      break;
    }
    case MotionKind::waypoints:
      trajectory = through_waypoints(context, actor, *start, *initial_speed, scripted.body,
                                     actor_index, obstacles, geometry);
      break;
    case MotionKind::random_walk: {
      double speed = *initial_speed;
      if (!actor.motion.states.empty()) {
        auto walk = speed_of(context, actor.motion.states.front(), speed);
        if (!walk) return std::nullopt;
        speed = *walk;
      }
      if (speed <= 0) speed = kDefaultPedestrianSpeed;
      Polyline walk = random_walk_path(*start, speed, context.duration, kRandomWalkRadius,
                                       actor_seed(context.seed, actor_index));
      trajectory = Trajectory(std::move(walk), {{0, speed}}, class_motion_limits(scripted.body, 0));
      break;
    }
    case MotionKind::manoeuvres: {
      auto script = manoeuvre_script(context, actor, *start, *initial_speed, scripted.body);
      if (!script) return std::nullopt;
      scripted.manoeuvres = std::move(*script);
      trajectory = Trajectory::standing(*start);
      break;
    }
  }
  if (!trajectory) return std::nullopt;
  scripted.trajectory = std::move(*trajectory);
  if (!pedestrian) warn_of_way_against_links(context, actor, *start);
  return scripted;
}

// Where the scenario's vehicles (cyclists included) start, placed with their messages discarded:
// they are placed again, and reported, when they are prepared. A vehicle starting on the ego's
// route is one it may follow and pass, so the default duration allows it a wait.
std::vector<MapPoint> vehicle_starts(const Context& context) {
  Diagnostics discarded;
  Context quiet{context.scenario,
                context.values,
                context.map,
                context.seed,
                discarded,
                context.ego_pose,
                context.initial_headings,
                context.initial_poses,
                context.actor,
                context.pedestrian,
                context.duration,
                context.road_friction};
  std::vector<MapPoint> starts;
  for (const Actor& actor : context.scenario.vehicles)
    if (auto pose = place_state_unchecked(quiet, actor.initial)) starts.push_back(pose->position);
  return starts;
}

BodyGeometry obstacle_geometry(Context& context, const Obstacle& obstacle) {
  // Without a shape, an obstacle is a 1 m cube: about a pallet or a large box on the road.
  if (!obstacle.shape) return {BodyShape::box, 1, 1, 1};
  std::vector<double> d;
  for (const Value& value : obstacle.shape->dimensions)
    d.push_back(evaluate(value, context.values));
  auto at = [&](std::size_t i, double fallback) {
    return i < d.size() && std::isfinite(d[i]) && d[i] > 0 ? d[i] : fallback;
  };
  switch (obstacle.shape->kind) {
    case ShapeKind::sphere: {
      double diameter = 2 * at(0, 0.5);
      return {BodyShape::sphere, diameter, diameter, diameter};
    }
    case ShapeKind::box: return {BodyShape::box, at(0, 1), at(1, 1), at(2, 1)};
    case ShapeKind::cone: return {BodyShape::cone, 2 * at(0, 0.5), 2 * at(0, 0.5), at(1, 1)};
    case ShapeKind::cylinder:
      return {BodyShape::cylinder, 2 * at(0, 0.5), 2 * at(0, 0.5), at(1, 1)};
  }
  return {BodyShape::box, 1, 1, 1};
}

std::optional<SignalColour> colour_named(const std::string& name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "red") return SignalColour::red;
  if (lower == "yellow" || lower == "amber") return SignalColour::yellow;
  if (lower == "green") return SignalColour::green;
  return std::nullopt;
}

void prepare_lights(Context& context, SimulationSetup& setup) {
  for (const TrafficLightSetting& setting : context.scenario.traffic.lights) {
    auto colour = colour_named(setting.color);
    if (!colour) {
      context.diagnostics.error(setting.location, "unknown traffic-light colour '" + setting.color +
                                                      "' (expected red, yellow or green)");
      continue;
    }
    const auto& lights = context.map.traffic_lights();
    auto light = std::find_if(lights.begin(), lights.end(),
                              [&](const TrafficLight& l) { return l.id == setting.id; });
    if (light == lights.end()) {
      context.diagnostics.error(
          setting.location,
          "map '" + context.map.name() + "' has no traffic light '" + setting.id + "'");
      continue;
    }
    setup.lights.push_back({static_cast<std::uint32_t>(light - lights.begin()), *colour});
  }
}

Conditions conditions_of(Context& context) {
  Conditions conditions;
  const auto& environment = context.scenario.environment;
  double time_of_day = 12 * 3600;
  if (environment && environment->time_of_day) {
    time_of_day = evaluate(*environment->time_of_day, context.values);
    if (!std::isfinite(time_of_day)) {
      context.diagnostics.error(environment->time_of_day->location,
                                "the time of day is not a finite number");
      time_of_day = 12 * 3600;
    }
  }
  conditions.darkness = darkness_at(time_of_day);
  if (!environment) return conditions;
  for (const WeatherComponent& component : environment->weather) {
    double intensity = std::clamp(evaluate(component.intensity, context.values), 0.0, 1.0);
    if (std::isnan(intensity)) intensity = 0;
    if (component.kind == "fog")
      conditions.fog = intensity;
    else if (component.kind == "rain")
      conditions.rain = intensity;
    else if (component.kind == "snow")
      conditions.snow = intensity;
  }
  return conditions;
}

// The road's friction the environment gives, checked; dry when it gives none, nullopt after an
// error. Known before any body is made: every vehicle's limits depend on it.
std::optional<double> road_friction_of(const ScenarioTemplate& scenario,
                                       std::span<const double> values, Diagnostics& diagnostics) {
  const auto& environment = scenario.environment;
  if (!environment || !environment->road_friction) return kDryRoad;
  const double friction = evaluate(*environment->road_friction, values);
  if (!check_road_friction(friction,
                           where(environment->road_friction->location, environment->location),
                           diagnostics))
    return std::nullopt;
  return friction;
}

// A duration the file gives that ends before a spec can be decided.
void warn_of_short_duration(const ScenarioTemplate& scenario, double duration,
                            Diagnostics& diagnostics) {
  for (const SpecHorizon& short_of : horizons_beyond(scenario.specs, duration))
    diagnostics.warning(scenario.duration->location,
                        "the scenario's duration of " + format_number(duration) +
                            " s is shorter than spec '" + short_of.spec + "' reads (" +
                            format_number(short_of.seconds) +
                            " s): its verdict may be a time-out (docs/search.md)");
}

}  // namespace

std::optional<SimulationSetup> prepare_simulation(const ScenarioTemplate& scenario,
                                                  std::span<const double> values,
                                                  const RoadMap& map, std::uint64_t seed,
                                                  Diagnostics& diagnostics) {
  std::size_t errors_before = diagnostics.error_count();
  Context context{scenario, values, map, seed,  diagnostics,     std::nullopt,
                  {},       {},     {},  false, kDefaultDuration};
  SimulationSetup setup;
  // The scenario's own duration, else the default (default_duration.hpp), which grows below
  // once the ego's route is known.
  bool own_duration = false;
  context.duration = default_duration(scenario.specs, std::nullopt);
  if (scenario.duration) {
    double duration = evaluate(*scenario.duration, values);
    if (!check_duration(duration, scenario.duration->location, diagnostics)) return std::nullopt;
    if (duration > 0) {
      context.duration = duration;
      own_duration = true;
      warn_of_short_duration(scenario, duration, diagnostics);
    }
  }

  const auto road_friction = road_friction_of(scenario, values, diagnostics);
  if (!road_friction) return std::nullopt;
  context.road_friction = setup.road_friction = *road_friction;

  if (!check_lane_links(map, scenario.map.links, diagnostics)) return std::nullopt;
  const Actor& ego = scenario.ego;
  if (!ego.name.empty()) setup.ego_name = ego.name;
  setup.ego_body = body_of(context, ego, ActorCategory::car);
  context.actor = setup.ego_name;
  auto ego_pose = place_state(context, ego.initial);
  if (!ego_pose) return std::nullopt;
  warn_if_far_from_lanes(map, ego_pose->position, ego.initial.position.location, diagnostics);
  context.ego_pose = ego_pose;
  context.initial_headings[setup.ego_name] = ego_pose->heading;
  context.initial_poses[setup.ego_name] = *ego_pose;
  auto ego_speed = speed_of(context, ego.initial, 0.0);
  if (!ego_speed) return std::nullopt;
  setup.ego_initial.x = ego_pose->position.x;
  setup.ego_initial.y = ego_pose->position.y;
  setup.ego_initial.heading = ego_pose->heading;
  setup.ego_initial.speed = std::min(*ego_speed, setup.ego_body.max_speed);
  if (ego.target) {
    auto target = place_state(context, *ego.target);
    if (!target) return std::nullopt;
    setup.ego_target = target;
    auto route = find_route(map, *ego_pose, *target);
    if (!route) {
      diagnostics.error(ego.target->location, "no route over the lanes of map '" + map.name() +
                                                  "' leads from the ego's initial position to its "
                                                  "target");
      return std::nullopt;
    }
    if (route->length < kMinimumEgoRoute) {
      report_empty_ego_route(map, ego_pose->position, target->position, ego.target->location,
                             diagnostics);
      return std::nullopt;
    }
    setup.ego_route = defer_lane_changes(map, std::move(*route), kLaneChangePreparation);
  } else {
    auto lane = project_to_lane(map, ego_pose->position, ego_pose->heading);
    if (lane)
      setup.ego_route = route_ahead(map, LanePosition{lane->lane, lane->s, 0},
                                    setup.ego_body.max_speed * context.duration + kPathEndMargin);
    // At the end of a lane that leads nowhere (or off the map beyond one) the ego has no lanes
    // ahead: it drives without a route, as off the lanes.
    if (setup.ego_route.length < kMinimumEgoRoute) setup.ego_route = {};
  }
  if (ego_replays_script(scenario)) {
    setup.ego_script = manoeuvre_script(context, ego, *ego_pose, *ego_speed, setup.ego_body);
    if (!setup.ego_script) return std::nullopt;
  }

  for (const SpeedLimit& limit : scenario.traffic.speed_limits) {
    auto lane = map.find_lane(limit.lane);
    if (!lane) {
      diagnostics.error(limit.location,
                        "unknown lane '" + limit.lane + "' on map '" + map.name() + "'");
      continue;
    }
    setup.speed_limits.emplace_back(*lane, evaluate(limit.upper, values));
  }
  // Obstacles first: vehicles' paths are planned around them, and the default duration waits
  // for those in the ego's way.
  CollisionWorld obstacles;
  for (const Obstacle& obstacle : scenario.obstacles) {
    State state;
    state.position = obstacle.position;
    state.heading = obstacle.heading;
    auto pose = place_state(context, state);
    if (!pose) continue;
    StaticObstacle placed{obstacle.name, obstacle_geometry(context, obstacle), *pose};
    obstacles.add_body(placed.geometry, placed.pose, true);
    setup.obstacles.push_back(std::move(placed));
  }

  if (!own_duration && setup.ego_target) {
    std::vector<MapPoint> in_the_way;
    for (const StaticObstacle& obstacle : setup.obstacles)
      in_the_way.push_back(obstacle.pose.position);
    for (const MapPoint& start : vehicle_starts(context)) in_the_way.push_back(start);
    context.duration = default_duration(
        scenario.specs,
        route_time_at_limits(map, setup.ego_route, setup.speed_limits, setup.ego_body.max_speed),
        route_waits(map, setup.ego_route, in_the_way));
  }
  setup.duration = context.duration;

  std::size_t index = 0;
  std::vector<const Actor*> sources;
  for (const auto* group : {&scenario.vehicles, &scenario.pedestrians}) {
    for (const Actor& actor : *group) {
      try {
        auto scripted = prepare_actor(context, actor, ++index, obstacles);
        if (scripted) {
          setup.actors.push_back(std::move(*scripted));
          sources.push_back(&actor);
        }
      } catch (const std::exception& error) {
        // Inputs are checked above; this is the net under what they missed, so that one odd
        // scenario costs its evaluation, not the run.
        diagnostics.error(actor.location, "cannot prepare " + actor.name + ": " + error.what());
      }
    }
  }

  resolve_phases(context, setup, sources);
  // After the actors and obstacles: the road is pre-filled around them.
  prepare_flows(scenario, values, map, seed, setup, diagnostics);
  prepare_lights(context, setup);
  setup.conditions = conditions_of(context);
  setup.npc_behaviour = scenario.npc_behaviour.value_or(NpcBehaviour::reactive);
  set_heedless(setup, scenario.language);
  if (diagnostics.error_count() > errors_before) return std::nullopt;
  return setup;
}

}  // namespace scenfuzz
