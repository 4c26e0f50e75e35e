// The simulation loop. Each step: place every body, record new collisions, write one sample per
// actor (state, lane, and how the ego perceived it), check the end conditions, then let the
// driver choose the ego's control and advance the ego with the bicycle model. Scripted actors
// are evaluated at each step's time directly, so they accumulate no integration error; actors
// with manoeuvre phases (WMG SDL) react to the world and are stepped by their ManoeuvreDriver.
// Background traffic (flows) comes after the obstacles in actor order; its vehicles are actors
// throughout, present on the map only between their entry and exit (background_traffic.hpp).
#include "physics/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

#include "physics/collision/collision_world.hpp"
#include "physics/ego/ego_indicators.hpp"
#include "physics/ego/observation_json.hpp"
#include "physics/ego/plugin_driver.hpp"
#include "physics/simulation/background_traffic.hpp"
#include "physics/simulation/junction_arrivals.hpp"
#include "physics/simulation/lane_follower.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/manoeuvre_driver.hpp"
#include "physics/simulation/npc_signals.hpp"
#include "physics/simulation/observed_manoeuvre.hpp"
#include "physics/simulation/plugin_observation.hpp"
#include "physics/simulation/predicted_points.hpp"
#include "physics/simulation/sample_columns.hpp"
#include "physics/simulation/simulation_limits.hpp"
#include "physics/simulation/traffic_flows.hpp"
#include "physics/simulation/traffic_signals.hpp"

namespace scenfuzz {
namespace {

// Perception draws from its own stream, so adding randomness elsewhere does not change it.
constexpr std::uint64_t kPerceptionStream = 0x70657263657074ull;

TraceActor describe(const std::string& name, TraceActorKind kind, ActorCategory category,
                    const BodyGeometry& geometry) {
  TraceActor actor;
  actor.name = name;
  actor.kind = kind;
  actor.category = category;
  actor.shape = geometry.shape;
  actor.length = geometry.length;
  actor.width = geometry.width;
  actor.height = geometry.height;
  return actor;
}

BodyGeometry body_geometry(const ActorClass& body) {
  if (body.category == ActorCategory::pedestrian)
    return {BodyShape::cylinder, body.length, body.length, body.height};
  return {BodyShape::box, body.length, body.width, body.height};
}

// A scripted actor's state at t, one step of dt after `before` (null at the first sample, which
// has no step before it). Trajectory::state_at gives the path's instantaneous turn rate, speed x
// curvature; the trace records the heading's change over the step instead (step_yaw_rate), as the
// bicycle model does: they differ wherever the curvature changes within a step (a path's heading
// blends at its vertices, a pedestrian's walk turns at its corners).
KinematicState scripted_state(const Trajectory& trajectory, double t, const KinematicState* before,
                              double dt) {
  KinematicState state = trajectory.state_at(t);
  if (before) state.yaw_rate = step_yaw_rate(before->heading, state.heading, dt);
  return state;
}

// The objects of `truth` (actors 1, 2, ... in order) that are on the map, in `out`: the ego
// perceives nothing of a flow vehicle before it enters or after it leaves.
const std::vector<WorldObject>& present_objects(const std::vector<WorldObject>& truth,
                                                const std::vector<std::uint8_t>& present,
                                                std::vector<WorldObject>& out) {
  out.clear();
  for (const WorldObject& object : truth)
    if (present[object.id]) out.push_back(object);
  return out;
}

// The ego's signals from a plugin's control: its word when it speaks version 2 or later (an
// older plugin leaves the zero-filled fields: all off), and brake lights as its acceleration
// has them, whatever it says (they follow the brake pedal, not a switch).
VehicleSignals plugin_signals(const scenfuzz_control& control, double speed) {
  const VehicleSignals said =
      control.version >= 2 ? static_cast<VehicleSignals>(control.signals & vehicle_signal::all)
                           : VehicleSignals{0};
  return said | brake_lights(control.acceleration, speed, true);
}

// The lights' colours as runs of equal steps, written into the trace's columns when the run
// ends: a colour per light per step reached into every one of a city map's hundreds of lights'
// columns at every step, which cost more than the rest of recording.
struct ColourRuns {
  std::vector<std::vector<SignalColour>> colours;  // of every light, in each run
  std::vector<std::size_t> steps;                  // in each run

  void add(const std::vector<SignalColour>& now) {
    // Compared as bytes: vector's == compares enum elements one at a time, and a city map has
    // hundreds of lights at every step.
    if (!colours.empty() && colours.back().size() == now.size() &&
        (now.empty() ||
         std::memcmp(colours.back().data(), now.data(), now.size() * sizeof(SignalColour)) == 0)) {
      ++steps.back();
      return;
    }
    colours.push_back(now);
    steps.push_back(1);
  }

  void write(std::vector<TraceLight>& lights) const {
    for (std::size_t light = 0; light < lights.size(); ++light)
      for (std::size_t run = 0; run < colours.size(); ++run)
        lights[light].colour.insert(lights[light].colour.end(), steps[run], colours[run][light]);
  }
};

void end_with(Trace& trace, EndReason reason, TraceEventKind kind, double time,
              std::string message = {}) {
  trace.end = reason;
  trace.events.push_back({kind, time, -1, std::move(message)});
}

// The run ends because the plugin failed: the event, and what a finding about it needs.
// `last_observation` is what the failing step was handed; null when the plugin failed to start.
void end_with_ego_failure(Trace& trace, const EgoPluginError& error, double time,
                          const scenfuzz_observation* last_observation) {
  end_with(trace, EndReason::ego_failure, TraceEventKind::ego_failure, time, error.what());
  trace.ego_failure = EgoFailure{
      error.kind(), error.what(), error.signal(),
      error.step(), time,         last_observation ? observation_json(*last_observation) : ""};
}

std::vector<std::optional<LaneFollower>> lane_followers(const RoadMap& map,
                                                        const SimulationSetup& setup,
                                                        const SimulationOptions& options) {
  std::vector<std::optional<LaneFollower>> followers(setup.actors.size());
  if (options.npc_behaviour.value_or(setup.npc_behaviour) != NpcBehaviour::reactive)
    return followers;
  for (std::size_t i = 0; i < setup.actors.size(); ++i) {
    const ScriptedActor& actor = setup.actors[i];
    if (!actor.lane_drive || actor.manoeuvres) continue;
    const LaneDrive& drive = *actor.lane_drive;
    followers[i].emplace(map, drive.route, drive.path, drive.places, actor.body,
                         drive.desired_speed, drive.initial_speed, false);
  }
  return followers;
}

// Actor k's lane this step: a lane follower knows it from its route (the tracker is told, for
// when it leaves the centre lines to change lane); every other actor's tracker looks. An absent
// flow vehicle is on no lane; its tracker starts afresh when it enters.
LaneFix lane_fix_of(std::size_t k, const RoadMap& map, const KinematicState& state, bool present,
                    const std::vector<std::optional<LaneFollower>>& followers,
                    const BackgroundTraffic& traffic, std::size_t first_flow,
                    LaneTracker& tracker) {
  if (!present) return {};
  const LaneFollower* follower = nullptr;
  if (k >= 1 && k <= followers.size() && followers[k - 1]) follower = &*followers[k - 1];
  if (k >= first_flow) follower = traffic.follower(k - first_flow);
  if (follower != nullptr)
    if (std::optional<LaneFix> fix = follower->lane_fix()) {
      tracker.assume(*fix);
      return *fix;
    }
  return tracker.update(map, {state.x, state.y}, state.heading);
}

}  // namespace

Trace simulate(const RoadMap& map, const SimulationSetup& setup, const SimulationOptions& options) {
  const double dt = options.dt;
  const double duration = options.duration.value_or(setup.duration);
  // Before anything is allocated or started: 1e9 s would otherwise end in bad_alloc. Callers
  // check options with the same function and report them as bad input.
  if (auto problem = sample_count_problem(duration, dt))
    throw std::invalid_argument("simulate: " + *problem);
  Trace trace;
  trace.map_name = map.name();
  trace.seed = options.seed;
  trace.dt = dt;

  // Bodies: the ego, the scripted actors, the obstacles, the flow vehicles; collision ids equal
  // actor ids.
  CollisionWorld world;
  std::vector<KinematicState> states;
  BodyGeometry ego_geometry = body_geometry(setup.ego_body);
  trace.actors.push_back(
      describe(setup.ego_name, TraceActorKind::ego, setup.ego_body.category, ego_geometry));
  world.add_body(ego_geometry,
                 {{setup.ego_initial.x, setup.ego_initial.y}, setup.ego_initial.heading}, false);
  states.push_back(setup.ego_initial);
  // WMG SDL actors with manoeuvre phases react to the world, so they are driven step by step;
  // drivers[k - 1] belongs to actor k.
  std::vector<std::optional<ManoeuvreDriver>> drivers(setup.actors.size());
  for (std::size_t i = 0; i < setup.actors.size(); ++i)
    if (setup.actors[i].manoeuvres)
      drivers[i].emplace(map, *setup.actors[i].manoeuvres, setup.actors[i].body,
                         setup.actors[i].kind == TraceActorKind::pedestrian);
  // Lane-following NPCs drive reactively unless the scenario or the options say scripted;
  // followers[k - 1] belongs to actor k.
  std::vector<std::optional<LaneFollower>> followers = lane_followers(map, setup, options);
  // Only triggers (end conditions and manoeuvre phases) read what manoeuvre each actor is making.
  const bool watches_manoeuvres =
      !setup.end_conditions.empty() ||
      std::any_of(drivers.begin(), drivers.end(), [](const auto& d) { return d.has_value(); });
  const bool watches_world =
      watches_manoeuvres ||
      std::any_of(followers.begin(), followers.end(), [](const auto& f) { return f.has_value(); });
  for (std::size_t i = 0; i < setup.actors.size(); ++i) {
    const ScriptedActor& actor = setup.actors[i];
    BodyGeometry geometry = body_geometry(actor.body);
    trace.actors.push_back(describe(actor.name, actor.kind, actor.body.category, geometry));
    KinematicState start = drivers[i]     ? drivers[i]->state()
                           : followers[i] ? followers[i]->state()
                                          : actor.trajectory.state_at(0);
    world.add_body(geometry, {{start.x, start.y}, start.heading}, false);
    states.push_back(start);
  }
  std::size_t first_obstacle = trace.actors.size();
  for (const StaticObstacle& obstacle : setup.obstacles) {
    trace.actors.push_back(
        describe(obstacle.name, TraceActorKind::obstacle, ActorCategory::car, obstacle.geometry));
    world.add_body(obstacle.geometry, obstacle.pose, true);
    KinematicState state;
    state.x = obstacle.pose.position.x;
    state.y = obstacle.pose.position.y;
    state.heading = obstacle.pose.heading;
    states.push_back(state);
  }
  const std::size_t first_flow = trace.actors.size();
  BackgroundTraffic traffic(map, setup, draw_flow_schedule(setup, duration), first_flow);
  const BodyGeometry flow_geometry = body_geometry(flow_vehicle_body());
  for (std::size_t j = 0; j < traffic.size(); ++j) {
    trace.actors.push_back(describe(traffic.vehicle(j).name, TraceActorKind::vehicle,
                                    flow_vehicle_body().category, flow_geometry));
    KinematicState start = traffic.initial_state(j);
    BodyId body = world.add_body(flow_geometry, {{start.x, start.y}, start.heading}, false);
    if (!traffic.present_at_start(j)) world.set_enabled(body, false);
    states.push_back(start);
  }
  const std::size_t actor_count = trace.actors.size();
  const SignalWeather weather = signal_weather(setup.conditions, options.perception);
  NpcSignals npc_signals(map, setup, followers, traffic.vehicles(), weather);
  const bool sees_world = watches_world || !traffic.empty();
  // By actor id: on the map now. Only flow vehicles come and go.
  std::vector<std::uint8_t> present(actor_count, 1);
  for (std::size_t j = 0; j < traffic.size(); ++j)
    present[first_flow + j] = traffic.present_at_start(j) ? 1 : 0;
  for (std::size_t k = 1; k < actor_count; ++k)
    trace.perceived.push_back({static_cast<ActorId>(k), {}, {}, {}, {}, {}, {}});
  for (const TrafficLight& light : map.traffic_lights()) trace.lights.push_back({light.id, {}});

  std::vector<WorldObject> truth(actor_count - 1);
  for (std::size_t k = 1; k < actor_count; ++k) {
    truth[k - 1].id = static_cast<ActorId>(k);
    truth[k - 1].kind = trace.actors[k].kind;
    truth[k - 1].length = trace.actors[k].length;
    truth[k - 1].width = trace.actors[k].width;
  }

  const PerceptionSettings sensing = degraded(options.perception, setup.conditions);
  Perception perception(sensing, options.seed ^ kPerceptionStream, dt);
  trace.sensing = {sensing.vehicle_range, sensing.pedestrian_range,
                   sensing.vehicle_range < options.perception.vehicle_range ||
                       sensing.pedestrian_range < options.perception.pedestrian_range};
  if (setup.ego_target) trace.ego_target = setup.ego_target->position;
  RouteTracker route(map, setup.ego_route, setup.speed_limits, options.driver.default_speed_limit);
  ReferenceDriver driver(map, route, setup.ego_body, setup.ego_target.has_value(), options.driver,
                         sensing);
  TrafficSignals signals(map, setup.lights);
  EgoIndicators ego_indicators(map, route);
  SignalMemory ego_memory;
  bool ego_collided = false;
  // The ego's signals at the sample just written, until its driver decides at this step: what
  // the last sample keeps when the run ends before that. At the start, the brake held while it
  // stands, and for the reference driver the weather's lights (a plugin chooses its own).
  const VehicleSignals weather_lights = weather_signals(weather);
  VehicleSignals ego_signals_now =
      (options.ego_plugin.empty() ? weather_lights : VehicleSignals{0}) |
      brake_lights(setup.ego_initial.acceleration, setup.ego_initial.speed, true);
  std::vector<LaneTracker> lanes(actor_count, LaneTracker(map.widest_half_lane()));
  std::vector<LaneFix> fixes(actor_count);
  std::vector<ObservedManoeuvre> manoeuvres(actor_count, ObservedManoeuvre::going_ahead);
  std::vector<double> lengths(actor_count), widths(actor_count);
  std::vector<TraceActorKind> kinds(actor_count);
  std::vector<double> sequence_starts(actor_count, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < actor_count; ++k) {
    lengths[k] = trace.actors[k].length;
    widths[k] = trace.actors[k].width;
    kinds[k] = trace.actors[k].kind;
  }

  // Where every actor will be, shared by every lane follower's scan (worked out when asked for;
  // for all actors at once only for the grid).
  const double prediction_time = FollowerSettings{}.prediction_time;
  std::vector<MapPoint> predicted;
  PointPredictor predictor;
  JunctionArrivals arrivals;  // the junction priority's "first come" (junction_arrivals.hpp)
  // With many actors most are far from any one follower: a grid lets each scan skip them. With
  // few, building it costs more than looking at them all (benchmarks: 30 actors on one road);
  // there followers look by lane (lane_occupancy.hpp), which cost more than the grid saves with
  // 100 actors or more (benchmarks: filing them every step, flows scanning at different steps).
  constexpr std::size_t kGridFromActors = 48;
  const bool uses_grid = actor_count >= kGridFromActors;
  std::optional<LaneOccupancy> occupancy;
  if (!uses_grid && (!traffic.empty() || std::any_of(followers.begin(), followers.end(),
                                                     [](const auto& f) { return f.has_value(); })))
    occupancy.emplace(map);
  ActorGrid grid;
  std::vector<WorldObject> on_map;       // the objects of `truth` present now, for perception
  std::vector<WorldObject> seen_on_map;  // what perception reports of them

  std::optional<PluginDriver> plugin;
  if (!options.ego_plugin.empty()) {
    try {
      plugin.emplace(PluginOptions{options.ego_plugin, options.plugin_step_timeout,
                                   options.plugin_start_timeout},
                     plugin_config(setup, dt, options.seed));
    } catch (const EgoPluginError& error) {
      end_with_ego_failure(trace, error, 0, nullptr);
      return trace;
    }
  }

  const auto last_step = static_cast<std::size_t>(std::floor(duration / dt + 1e-9));
  SampleRecorder recorder(trace, last_step + 1);
  scenfuzz_observation observation{};
  observation.environment = {setup.conditions.darkness, setup.conditions.fog, setup.conditions.rain,
                             setup.conditions.snow};
  ColourRuns colour_runs;

  for (std::size_t step = 0;; ++step) {
    const double t = static_cast<double>(step) * dt;
    for (std::size_t k = 1; k <= setup.actors.size(); ++k) {
      // Assigned in place: a conditional expression copied the state through the stack.
      if (drivers[k - 1])
        states[k] = drivers[k - 1]->state();
      else if (followers[k - 1])
        states[k] = followers[k - 1]->state();
      else
        states[k] =
            scripted_state(setup.actors[k - 1].trajectory, t, step > 0 ? &states[k] : nullptr, dt);
    }
    for (std::size_t k = 0; k < first_obstacle; ++k)
      world.set_pose(static_cast<BodyId>(k), {{states[k].x, states[k].y}, states[k].heading});
    if (!traffic.empty()) traffic.update(step, t, states, lengths, widths, present, world);

    bool ego_hit = false;
    // Each pair's first contact only: after it the world stops testing the pair.
    for (const Contact& contact : world.find_contacts()) {
      world.ignore_pair(contact.first, contact.second);
      trace.collisions.push_back({t, contact.first, contact.second, contact.point,
                                  contact.first_side, contact.second_side});
      trace.events.push_back({TraceEventKind::collision,
                              t,
                              static_cast<std::int64_t>(trace.collisions.size() - 1),
                              {}});
      ego_hit = ego_hit || contact.first == kEgo;
    }
    ego_collided = ego_collided || ego_hit;

    trace.time.push_back(t);
    for (std::size_t k = 0; k < actor_count; ++k) {
      fixes[k] =
          lane_fix_of(k, map, states[k], present[k] != 0, followers, traffic, first_flow, lanes[k]);
      recorder.sample(k, states[k], fixes[k]);
    }
    // The ego's signals are what it decided at the last step, until its driver decides below.
    trace.actors[kEgo].signals.push_back(ego_signals_now);
    npc_signals.record(t, states, followers, drivers, traffic, first_flow,
                       plugin ? &truth : nullptr);
    const std::vector<SignalColour>& colours = signals.colours_at(t);
    colour_runs.add(colours);

    for (std::size_t k = 1; k < actor_count; ++k) {
      WorldObject& object = truth[k - 1];
      object.x = states[k].x;
      object.y = states[k].y;
      object.heading = states[k].heading;
      object.speed = states[k].speed;
      object.reversing = states[k].reversing;
    }
    // Sensors sample only what is on the map, and a vehicle that has left is not reported late
    // (latency) nor coasted: it is gone, not missed.
    const std::vector<WorldObject>& seen =
        traffic.empty()
            ? perception.observe(states[kEgo], truth)
            : present_objects(
                  perception.observe(states[kEgo], present_objects(truth, present, on_map)),
                  present, seen_on_map);
    for (std::size_t k = 1, next = 0; k < actor_count; ++k) {
      while (next < seen.size() && seen[next].id < k) ++next;
      bool detected = next < seen.size() && seen[next].id == k;
      recorder.perceived(k, detected ? &seen[next] : nullptr);
    }
    recorder.end_step();

    WorldSnapshot snapshot;
    if (sees_world) {
      if (watches_manoeuvres)
        for (std::size_t k = 0; k < first_obstacle; ++k)
          manoeuvres[k] = observe_manoeuvre(map, states[k], fixes[k]);
      predictor.set_step(states, prediction_time);
      arrivals.update(map, t, fixes, kinds,
                      traffic.empty() ? std::span<const std::uint8_t>{}
                                      : std::span<const std::uint8_t>(present));
      const std::span<const std::uint8_t> present_now =
          traffic.empty() ? std::span<const std::uint8_t>{}
                          : std::span<const std::uint8_t>(present);
      if (occupancy)
        occupancy->set_step(
            {states, &predictor, fixes, lengths, widths, kinds, present_now, prediction_time});
      if (uses_grid) {
        predictor.predict(states, prediction_time, predicted);
        grid.build(states, predicted, lengths, widths,
                   traffic.empty() ? std::span<const std::uint8_t>{}
                                   : std::span<const std::uint8_t>(present));
      }
      for (std::size_t k = 1; k <= drivers.size(); ++k)
        if (drivers[k - 1]) sequence_starts[k] = drivers[k - 1]->sequence_start();
      snapshot = {&map,
                  t,
                  states,
                  fixes,
                  manoeuvres,
                  lengths,
                  colours,
                  sequence_starts,
                  !trace.collisions.empty(),
                  widths,
                  kinds,
                  traffic.empty() ? std::span<const std::uint8_t>{}
                                  : std::span<const std::uint8_t>(present),
                  &predictor,
                  prediction_time,
                  uses_grid ? &grid : nullptr,
                  occupancy ? &*occupancy : nullptr,
                  arrivals.arrivals()};
    }

    route.update({states[kEgo].x, states[kEgo].y});
    if (ego_hit && options.stop_at_collision) {
      trace.end = EndReason::collision;
      break;
    }
    if (std::any_of(setup.end_conditions.begin(), setup.end_conditions.end(),
                    [&](const TriggerCondition& end) { return trigger_holds(end, snapshot); })) {
      end_with(trace, EndReason::end_condition, TraceEventKind::end_condition, t);
      break;
    }
    if (setup.ego_target && route.length() - route.progress() <= options.target_reach) {
      end_with(trace, EndReason::target_reached, TraceEventKind::target_reached, t);
      break;
    }
    if (step >= last_step) {
      end_with(trace, EndReason::duration, TraceEventKind::timeout, t);
      break;
    }

    // Manoeuvre phases react to the world as it is now; they move on to t + dt with the ego.
    for (std::size_t k = 1; k <= drivers.size(); ++k)
      if (drivers[k - 1]) drivers[k - 1]->step(snapshot, static_cast<std::uint32_t>(k), dt);
    for (std::size_t k = 1; k <= followers.size(); ++k)
      if (followers[k - 1]) followers[k - 1]->step(snapshot, static_cast<std::uint32_t>(k), dt);
    traffic.step(snapshot, dt);

    VehicleControl control;
    if (plugin) {
      fill_observation(route, states[kEgo], t, seen, colours, setup.ego_target.has_value(),
                       observation);
      try {
        scenfuzz_control answer = plugin->step(observation);
        control = {answer.acceleration, answer.steering_angle};
        ego_signals_now = plugin_signals(answer, states[kEgo].speed);
      } catch (const EgoPluginError& error) {
        end_with_ego_failure(trace, error, t, &observation);
        break;
      }
    } else {
      control = driver.step({t, states[kEgo], seen, colours});
      const VehicleSignals indicator =
          ego_indicators.at(route.progress(), states[kEgo].speed, driver.overtake());
      ego_signals_now = ego_signals(
          {t, states[kEgo], control.acceleration, indicator, seen,
           driver.last_reason() == DriverReason::emergency, ego_collided, weather_lights},
          weather, ego_memory);
    }
    trace.actors[kEgo].signals.back() = ego_signals_now;
    states[kEgo] = step_bicycle(states[kEgo], control, setup.ego_body, dt);
  }
  recorder.finish();
  colour_runs.write(trace.lights);
  traffic.finish(trace.actors, trace.sample_count());
  npc_signals.finish(trace.actors, first_flow);
  return trace;
}

}  // namespace scenfuzz
