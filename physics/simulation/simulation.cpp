// The simulation loop. Each step: place every body, record new collisions, write one sample per
// actor (state, lane, and how the ego perceived it), check the end conditions, then let the
// driver choose the ego's control and advance the ego with the bicycle model. Scripted actors
// are evaluated at each step's time directly, so they accumulate no integration error; actors
// with manoeuvre phases (WMG SDL) react to the world and are stepped by their ManoeuvreDriver,
// as is an ego that replays a script (an accident reconstruction) instead of being driven.
// Background traffic (flows) comes after the obstacles in actor order; its vehicles are actors
// throughout, present on the map only between their entry and exit (background_traffic.hpp).
#include "physics/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include "lang/demand.hpp"
#include "physics/collision/collision_world.hpp"
#include "physics/ego/driver_on_road.hpp"
#include "physics/ego/ego_indicators.hpp"
#include "physics/ego/observation_json.hpp"
#include "physics/ego/plugin_driver.hpp"
#include "physics/simulation/background_traffic.hpp"
#include "physics/simulation/impact_slide.hpp"
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

std::vector<std::optional<ManoeuvreDriver>> manoeuvre_drivers(const RoadMap& map,
                                                              const SimulationSetup& setup) {
  std::vector<std::optional<ManoeuvreDriver>> drivers(setup.actors.size());
  for (std::size_t i = 0; i < setup.actors.size(); ++i)
    if (setup.actors[i].manoeuvres)
      drivers[i].emplace(map, *setup.actors[i].manoeuvres, setup.actors[i].body,
                         setup.actors[i].kind == TraceActorKind::pedestrian);
  return drivers;
}

std::optional<ManoeuvreDriver> scripted_ego(const RoadMap& map, const SimulationSetup& setup) {
  if (!setup.ego_script) return std::nullopt;
  return std::optional<ManoeuvreDriver>(std::in_place, map, *setup.ego_script, setup.ego_body,
                                        false);
}

template <typename T>
bool any_present(const std::vector<std::optional<T>>& slots) {
  return std::any_of(slots.begin(), slots.end(), [](const auto& slot) { return slot.has_value(); });
}

// One run: everything the loop keeps from step to step, and the loop's steps (simulate below
// reads as the loop). Actor ids: the ego 0, the scripted actors, the obstacles, the flow
// vehicles; collision ids equal actor ids. It holds references into itself (the driver to the
// route, the recorder to the trace): neither copied nor moved.
class Run {
 public:
  Run(const RoadMap& map, const SimulationSetup& setup, const SimulationOptions& options);
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  // Starts the ego plugin, if any; false (the trace ended) when it failed to.
  bool start_plugin();
  // The steps of step `step`, at time t, in the loop's order.
  void move_actors(std::size_t step, double t);
  bool record_collisions(double t);  // whether the ego was hit this step
  void record_sample(double t);
  WorldSnapshot look(double t);
  bool ends(std::size_t step, double t, bool ego_hit, const WorldSnapshot& snapshot);
  void step_npcs(const WorldSnapshot& snapshot);
  bool drive_ego(double t);  // false: the plugin failed, the trace ended
  // The trace: finished (the recorder's last block, the lights' columns, the flows' and NPCs'
  // signals), or as it is when the plugin failed to start.
  Trace finish();
  Trace unfinished() { return std::move(trace_); }

 private:
  void add_bodies();
  void prepare_columns();
  // An impact between bodies a and b: both slide on with the pair's momentum, or a vehicle
  // stops at an obstacle (impact_slide.hpp).
  void start_slides(const Contact& contact);
  double braking_of(std::size_t k) const {
    return k == kEgo ? setup_.ego_body.max_deceleration
                     : setup_.actors[k - 1].body.max_deceleration;
  }
  std::span<const std::uint8_t> present_now() const {
    return traffic_.empty() ? std::span<const std::uint8_t>{}
                            : std::span<const std::uint8_t>(present_);
  }

  const RoadMap& map_;
  const SimulationSetup& setup_;
  const SimulationOptions& options_;
  const double dt_;
  const double duration_;
  Trace trace_;
  CollisionWorld world_;
  std::vector<KinematicState> states_;
  // WMG SDL actors with manoeuvre phases react to the world, so they are driven step by step;
  // drivers_[k - 1] belongs to actor k.
  std::vector<std::optional<ManoeuvreDriver>> drivers_;
  // An ego that replays its script: neither the reference driver nor a plugin drives it.
  std::optional<ManoeuvreDriver> scripted_ego_;
  // Lane-following NPCs drive reactively unless the scenario or the options say scripted;
  // followers_[k - 1] belongs to actor k.
  std::vector<std::optional<LaneFollower>> followers_;
  // Only triggers (end conditions and manoeuvre phases) read what manoeuvre each actor is making.
  const bool watches_manoeuvres_;
  const std::size_t first_obstacle_;
  const std::size_t first_flow_;
  BackgroundTraffic traffic_;
  const std::size_t actor_count_;
  const SignalWeather weather_;
  NpcSignals npc_signals_;
  const bool sees_world_;
  // By actor id: on the map now. Only flow vehicles come and go.
  std::vector<std::uint8_t> present_;
  std::vector<WorldObject> truth_;
  const PerceptionSettings sensing_;
  Perception perception_;
  RouteTracker route_;
  ReferenceDriver driver_;
  TrafficSignals signals_;
  EgoIndicators ego_indicators_;
  SignalMemory ego_memory_;
  bool ego_collided_ = false;
  // By actor id: the velocity of a vehicle sliding after an impact (slide_after_impact), which no
  // driver moves any more.
  std::vector<std::optional<MapPoint>> slides_;
  const VehicleSignals weather_lights_;
  // The ego's signals at the sample just written, until its driver decides at this step: what
  // the last sample keeps when the run ends before that.
  VehicleSignals ego_signals_now_;
  std::vector<LaneTracker> lanes_;
  std::vector<LaneFix> fixes_;
  std::vector<ObservedManoeuvre> manoeuvres_;
  std::vector<double> lengths_, widths_;
  std::vector<TraceActorKind> kinds_;
  std::vector<double> sequence_starts_;
  // Where every actor will be, shared by every lane follower's scan (worked out when asked for;
  // for all actors at once only for the grid).
  const double prediction_time_ = FollowerSettings{}.prediction_time;
  std::vector<MapPoint> predicted_;
  PointPredictor predictor_;
  JunctionArrivals arrivals_;  // the junction priority's "first come" (junction_arrivals.hpp)
  const bool uses_grid_;
  std::optional<LaneOccupancy> occupancy_;
  ActorGrid grid_;
  std::vector<WorldObject> on_map_;       // the objects of `truth_` present now, for perception
  std::vector<WorldObject> seen_on_map_;  // what perception reports of them
  const std::vector<WorldObject>* seen_ = nullptr;      // what the ego perceived at this step
  const std::vector<SignalColour>* colours_ = nullptr;  // the lights' at this step
  std::optional<PluginDriver> plugin_;
  const std::size_t last_step_;
  std::optional<SampleRecorder> recorder_;  // made once the trace has its actors
  scenfuzz_observation observation_{};
  ColourRuns colour_runs_;
};

// With many actors most are far from any one follower: a grid lets each scan skip them. With
// few, building it costs more than looking at them all (benchmarks: 30 actors on one road);
// there followers look by lane (lane_occupancy.hpp), which cost more than the grid saves with
// 100 actors or more (benchmarks: filing them every step, flows scanning at different steps).
constexpr std::size_t kGridFromActors = 48;

Run::Run(const RoadMap& map, const SimulationSetup& setup, const SimulationOptions& options)
    : map_(map),
      setup_(setup),
      options_(options),
      dt_(options.dt),
      duration_(options.duration.value_or(setup.duration)),
      drivers_(manoeuvre_drivers(map, setup)),
      scripted_ego_(scripted_ego(map, setup)),
      followers_(lane_followers(map, setup, options)),
      watches_manoeuvres_(!setup.end_conditions.empty() || any_present(drivers_) ||
                          scripted_ego_.has_value()),
      first_obstacle_(1 + setup.actors.size()),
      first_flow_(first_obstacle_ + setup.obstacles.size()),
      traffic_(map, setup, draw_flow_schedule(setup, duration_), first_flow_),
      actor_count_(first_flow_ + traffic_.size()),
      weather_(signal_weather(setup.conditions, options.perception)),
      npc_signals_(map, setup, followers_, traffic_.vehicles(), weather_),
      sees_world_(watches_manoeuvres_ || any_present(followers_) || !traffic_.empty()),
      present_(actor_count_, 1),
      truth_(actor_count_ - 1),
      sensing_(degraded(options.perception, setup.conditions)),
      perception_(sensing_, options.seed ^ kPerceptionStream, options.dt),
      route_(map, setup.ego_route, setup.speed_limits, options.driver.default_speed_limit),
      // The body is already on the road's grip; the driver's own settings learn of it here.
      driver_(map, route_, setup.ego_body, setup.ego_target.has_value(),
              on_road(options.driver, setup.road_friction), sensing_),
      signals_(map, setup.lights),
      ego_indicators_(map, route_),
      weather_lights_(weather_signals(weather_)),
      // At the start, the brake held while it stands, and for the reference driver (or a
      // script) the weather's lights (a plugin chooses its own).
      ego_signals_now_(
          (options.ego_plugin.empty() || setup.ego_script ? weather_lights_ : VehicleSignals{0}) |
          brake_lights(setup.ego_initial.acceleration, setup.ego_initial.speed, true)),
      lanes_(actor_count_, LaneTracker(map.widest_half_lane())),
      fixes_(actor_count_),
      manoeuvres_(actor_count_, ObservedManoeuvre::going_ahead),
      lengths_(actor_count_),
      widths_(actor_count_),
      kinds_(actor_count_),
      sequence_starts_(actor_count_, std::numeric_limits<double>::quiet_NaN()),
      uses_grid_(actor_count_ >= kGridFromActors),
      last_step_(static_cast<std::size_t>(std::floor(duration_ / dt_ + 1e-9))) {
  slides_.resize(actor_count_);
  trace_.map_name = map.name();
  trace_.seed = options.seed;
  trace_.dt = dt_;
  add_bodies();
  SCENFUZZ_DEMAND(trace_.actors.size() == actor_count_);
  prepare_columns();
  trace_.sensing = {sensing_.vehicle_range, sensing_.pedestrian_range,
                    sensing_.vehicle_range < options.perception.vehicle_range ||
                        sensing_.pedestrian_range < options.perception.pedestrian_range};
  if (setup.ego_target) trace_.ego_target = setup.ego_target->position;
  if (!uses_grid_ && (!traffic_.empty() || any_present(followers_))) occupancy_.emplace(map);
  observation_.environment = {setup.conditions.darkness, setup.conditions.fog,
                              setup.conditions.rain, setup.conditions.snow};
  recorder_.emplace(trace_, last_step_ + 1);
}

// The trace's actors, their bodies in the collision world and their first states.
void Run::add_bodies() {
  const BodyGeometry ego_geometry = body_geometry(setup_.ego_body);
  trace_.actors.push_back(
      describe(setup_.ego_name, TraceActorKind::ego, setup_.ego_body.category, ego_geometry));
  const KinematicState ego_start = scripted_ego_ ? scripted_ego_->state() : setup_.ego_initial;
  world_.add_body(ego_geometry, {{ego_start.x, ego_start.y}, ego_start.heading}, false);
  states_.push_back(ego_start);
  for (std::size_t i = 0; i < setup_.actors.size(); ++i) {
    const ScriptedActor& actor = setup_.actors[i];
    const BodyGeometry geometry = body_geometry(actor.body);
    trace_.actors.push_back(describe(actor.name, actor.kind, actor.body.category, geometry));
    const KinematicState start = drivers_[i]     ? drivers_[i]->state()
                                 : followers_[i] ? followers_[i]->state()
                                                 : actor.trajectory.state_at(0);
    world_.add_body(geometry, {{start.x, start.y}, start.heading}, false);
    states_.push_back(start);
  }
  for (const StaticObstacle& obstacle : setup_.obstacles) {
    trace_.actors.push_back(
        describe(obstacle.name, TraceActorKind::obstacle, ActorCategory::car, obstacle.geometry));
    world_.add_body(obstacle.geometry, obstacle.pose, true);
    KinematicState state;
    state.x = obstacle.pose.position.x;
    state.y = obstacle.pose.position.y;
    state.heading = obstacle.pose.heading;
    states_.push_back(state);
  }
  const BodyGeometry flow_geometry = body_geometry(flow_vehicle_body());
  for (std::size_t j = 0; j < traffic_.size(); ++j) {
    trace_.actors.push_back(describe(traffic_.vehicle(j).name, TraceActorKind::vehicle,
                                     flow_vehicle_body().category, flow_geometry));
    const KinematicState start = traffic_.initial_state(j);
    const BodyId body = world_.add_body(flow_geometry, {{start.x, start.y}, start.heading}, false);
    if (!traffic_.present_at_start(j)) {
      world_.set_enabled(body, false);
      present_[first_flow_ + j] = 0;
    }
    states_.push_back(start);
  }
}

// The per-actor columns the loop reads (sizes, kinds, the truth perception is handed) and the
// trace's perceived and light columns.
void Run::prepare_columns() {
  for (std::size_t k = 1; k < actor_count_; ++k)
    trace_.perceived.push_back({static_cast<ActorId>(k), {}, {}, {}, {}, {}, {}});
  for (const TrafficLight& light : map_.traffic_lights()) trace_.lights.push_back({light.id, {}});
  for (std::size_t k = 1; k < actor_count_; ++k) {
    truth_[k - 1].id = static_cast<ActorId>(k);
    truth_[k - 1].kind = trace_.actors[k].kind;
    truth_[k - 1].length = trace_.actors[k].length;
    truth_[k - 1].width = trace_.actors[k].width;
  }
  for (std::size_t k = 0; k < actor_count_; ++k) {
    lengths_[k] = trace_.actors[k].length;
    widths_[k] = trace_.actors[k].width;
    kinds_[k] = trace_.actors[k].kind;
  }
}

bool Run::start_plugin() {
  if (options_.ego_plugin.empty() || scripted_ego_) return true;
  try {
    plugin_.emplace(PluginOptions{options_.ego_plugin, options_.plugin_step_timeout,
                                  options_.plugin_start_timeout},
                    plugin_config(setup_, dt_, options_.seed));
  } catch (const EgoPluginError& error) {
    end_with_ego_failure(trace_, error, 0, nullptr);
    return false;
  }
  return true;
}

// Every actor to where it is at t, its body with it, and the ego's place on its route.
void Run::move_actors(std::size_t step, double t) {
  for (std::size_t k = 0; k < first_obstacle_; ++k)
    if (slides_[k]) states_[k] = slide_step(states_[k], *slides_[k], braking_of(k), dt_);
  if (scripted_ego_ && !slides_[kEgo]) states_[kEgo] = scripted_ego_->state();
  for (std::size_t k = 1; k <= setup_.actors.size(); ++k) {
    if (slides_[k]) continue;
    // Assigned in place: a conditional expression copied the state through the stack.
    if (drivers_[k - 1])
      states_[k] = drivers_[k - 1]->state();
    else if (followers_[k - 1])
      states_[k] = followers_[k - 1]->state();
    else
      states_[k] =
          scripted_state(setup_.actors[k - 1].trajectory, t, step > 0 ? &states_[k] : nullptr, dt_);
  }
  for (std::size_t k = 0; k < first_obstacle_; ++k)
    world_.set_pose(static_cast<BodyId>(k), {{states_[k].x, states_[k].y}, states_[k].heading});
  if (!traffic_.empty()) traffic_.update(step, t, states_, lengths_, widths_, present_, world_);
  route_.update({states_[kEgo].x, states_[kEgo].y});  // the ego's progress along its route
}

// Each pair's first contact only: after it the world stops testing the pair.
bool Run::record_collisions(double t) {
  bool ego_hit = false;
  for (const Contact& contact : world_.find_contacts()) {
    world_.ignore_pair(contact.first, contact.second);
    if (options_.slide_after_impact) start_slides(contact);
    trace_.collisions.push_back(
        {t, contact.first, contact.second, contact.point, contact.first_side, contact.second_side});
    trace_.events.push_back({TraceEventKind::collision,
                             t,
                             static_cast<std::int64_t>(trace_.collisions.size() - 1),
                             {}});
    ego_hit = ego_hit || contact.first == kEgo;
  }
  ego_collided_ = ego_collided_ || ego_hit;
  return ego_hit;
}

void Run::start_slides(const Contact& contact) {
  const ActorId a = contact.first, b = contact.second;
  auto movable = [&](ActorId k) {
    return k < first_obstacle_ && kinds_[k] != TraceActorKind::pedestrian;
  };
  auto obstacle = [&](ActorId k) { return k >= first_obstacle_ && k < first_flow_; };
  if (movable(a) && obstacle(b)) slides_[a] = MapPoint{0, 0};
  if (movable(b) && obstacle(a)) slides_[b] = MapPoint{0, 0};
  if (!movable(a) || !movable(b)) return;
  auto body = [&](ActorId k) {
    return ImpactBody{slides_[k] ? *slides_[k] : velocity_of(states_[k]),
                      impact_mass(trace_.actors[k].category)};
  };
  // The face struck broadside gives the normal: a's side face hit by b's front or rear (then it
  // points into b the other way), else b's face.
  const bool a_broadside =
      (contact.first_side == BodySide::left || contact.first_side == BodySide::right) &&
      (contact.second_side == BodySide::front || contact.second_side == BodySide::rear);
  MapPoint normal = a_broadside ? face_normal(states_[a].heading, contact.first_side)
                                : face_normal(states_[b].heading, contact.second_side);
  if (!a_broadside) normal = {-normal.x, -normal.y};
  const auto [after_a, after_b] = impact_velocities(body(a), body(b), normal);
  slides_[a] = after_a;
  slides_[b] = after_b;
}

// The step's sample of every actor, their signals and the lights', and what the ego perceives.
void Run::record_sample(double t) {
  trace_.time.push_back(t);
  for (std::size_t k = 0; k < actor_count_; ++k) {
    fixes_[k] = lane_fix_of(k, map_, states_[k], present_[k] != 0, followers_, traffic_,
                            first_flow_, lanes_[k]);
    recorder_->sample(k, states_[k], fixes_[k]);
  }
  // The ego's signals are what it decided at the last step, until its driver decides below.
  trace_.actors[kEgo].signals.push_back(ego_signals_now_);
  npc_signals_.record(t, states_, followers_, drivers_, traffic_, first_flow_,
                      plugin_ ? &truth_ : nullptr);
  colours_ = &signals_.colours_at(t);
  colour_runs_.add(*colours_);

  for (std::size_t k = 1; k < actor_count_; ++k) {
    WorldObject& object = truth_[k - 1];
    object.x = states_[k].x;
    object.y = states_[k].y;
    object.heading = states_[k].heading;
    object.speed = states_[k].speed;
    object.reversing = states_[k].reversing;
  }
  // Sensors sample only what is on the map, and a vehicle that has left is not reported late
  // (latency) nor coasted: it is gone, not missed.
  seen_ = traffic_.empty()
              ? &perception_.observe(states_[kEgo], truth_)
              : &present_objects(
                    perception_.observe(states_[kEgo], present_objects(truth_, present_, on_map_)),
                    present_, seen_on_map_);
  const std::vector<WorldObject>& seen = *seen_;
  for (std::size_t k = 1, next = 0; k < actor_count_; ++k) {
    while (next < seen.size() && seen[next].id < k) ++next;
    const bool detected = next < seen.size() && seen[next].id == k;
    recorder_->perceived(k, detected ? &seen[next] : nullptr);
  }
  recorder_->end_step();
}

// What the NPCs and the end conditions read of the world this step (empty when none of them
// looks at it).
WorldSnapshot Run::look(double t) {
  if (!sees_world_) return {};
  if (watches_manoeuvres_)
    for (std::size_t k = 0; k < first_obstacle_; ++k)
      manoeuvres_[k] = observe_manoeuvre(map_, states_[k], fixes_[k]);
  predictor_.set_step(states_, prediction_time_);
  arrivals_.update(map_, t, fixes_, kinds_, present_now());
  if (occupancy_)
    occupancy_->set_step(
        {states_, &predictor_, fixes_, lengths_, widths_, kinds_, present_now(), prediction_time_});
  if (uses_grid_) {
    predictor_.predict(states_, prediction_time_, predicted_);
    grid_.build(states_, predicted_, lengths_, widths_, present_now());
  }
  if (scripted_ego_) sequence_starts_[kEgo] = scripted_ego_->sequence_start();
  for (std::size_t k = 1; k <= drivers_.size(); ++k)
    if (drivers_[k - 1]) sequence_starts_[k] = drivers_[k - 1]->sequence_start();
  return {&map_,
          t,
          states_,
          fixes_,
          manoeuvres_,
          lengths_,
          *colours_,
          sequence_starts_,
          !trace_.collisions.empty(),
          widths_,
          kinds_,
          present_now(),
          &predictor_,
          prediction_time_,
          uses_grid_ ? &grid_ : nullptr,
          occupancy_ ? &*occupancy_ : nullptr,
          arrivals_.arrivals()};
}

// Whether the run ends at this step: a collision (when asked), an end condition, the target,
// the duration. The trace says why.
bool Run::ends(std::size_t step, double t, bool ego_hit, const WorldSnapshot& snapshot) {
  if (ego_hit && options_.stop_at_collision) {
    trace_.end = EndReason::collision;
    return true;
  }
  if (std::any_of(setup_.end_conditions.begin(), setup_.end_conditions.end(),
                  [&](const TriggerCondition& end) { return trigger_holds(end, snapshot); })) {
    end_with(trace_, EndReason::end_condition, TraceEventKind::end_condition, t);
    return true;
  }
  if (setup_.ego_target && route_.length() - route_.progress() <= options_.target_reach) {
    end_with(trace_, EndReason::target_reached, TraceEventKind::target_reached, t);
    return true;
  }
  if (step >= last_step_) {
    end_with(trace_, EndReason::duration, TraceEventKind::timeout, t);
    return true;
  }
  return false;
}

// Manoeuvre phases react to the world as it is now; they move on to t + dt with the ego (a
// scripted ego among them).
void Run::step_npcs(const WorldSnapshot& snapshot) {
  if (scripted_ego_) scripted_ego_->step(snapshot, kEgo, dt_);
  for (std::size_t k = 1; k <= drivers_.size(); ++k)
    if (drivers_[k - 1]) drivers_[k - 1]->step(snapshot, static_cast<std::uint32_t>(k), dt_);
  for (std::size_t k = 1; k <= followers_.size(); ++k)
    if (followers_[k - 1]) followers_[k - 1]->decide(snapshot, static_cast<std::uint32_t>(k), dt_);
  for (auto& follower : followers_)
    if (follower) follower->move(dt_);
  traffic_.step(snapshot, dt_);
}

// The ego's driver (the plugin, or the reference driver) chooses its control and signals, and
// the ego moves on to t + dt. A scripted ego has moved on with the NPCs: only its signals.
bool Run::drive_ego(double t) {
  // Sliding after an impact, it is no one's to drive (move_actors moves it).
  if (slides_[kEgo]) return true;
  if (scripted_ego_) {
    // Its script has moved it on (step_npcs): it shows what a scripted NPC shows.
    const KinematicState& next = scripted_ego_->state();
    ego_signals_now_ =
        static_cast<VehicleSignals>(scripted_ego_->indicator() | weather_lights_ |
                                    brake_lights(next.acceleration, next.speed, true));
    trace_.actors[kEgo].signals.back() = ego_signals_now_;
    return true;
  }
  VehicleControl control;
  if (plugin_) {
    fill_observation(route_, states_[kEgo], t, *seen_, *colours_, setup_.ego_target.has_value(),
                     observation_);
    try {
      scenfuzz_control answer = plugin_->step(observation_);
      control = {answer.acceleration, answer.steering_angle};
      ego_signals_now_ = plugin_signals(answer, states_[kEgo].speed);
    } catch (const EgoPluginError& error) {
      end_with_ego_failure(trace_, error, t, &observation_);
      return false;
    }
  } else {
    control = driver_.step({t, states_[kEgo], *seen_, *colours_});
    const VehicleSignals indicator =
        ego_indicators_.at(route_.progress(), states_[kEgo].speed, driver_.overtake());
    ego_signals_now_ = ego_signals(
        {t, states_[kEgo], control.acceleration, indicator, *seen_,
         driver_.last_reason() == DriverReason::emergency, ego_collided_, weather_lights_},
        weather_, ego_memory_);
  }
  trace_.actors[kEgo].signals.back() = ego_signals_now_;
  states_[kEgo] = step_bicycle(states_[kEgo], control, setup_.ego_body, dt_);
  return true;
}

Trace Run::finish() {
  recorder_->finish();
  colour_runs_.write(trace_.lights);
  traffic_.finish(trace_.actors, trace_.sample_count());
  npc_signals_.finish(trace_.actors, first_flow_);
  return std::move(trace_);
}

}  // namespace

Trace simulate(const RoadMap& map, const SimulationSetup& setup, const SimulationOptions& options) {
  // Before anything is allocated or started: 1e9 s would otherwise end in bad_alloc. Callers
  // check options with the same function and report them as bad input.
  if (auto problem = sample_count_problem(options.duration.value_or(setup.duration), options.dt))
    throw std::invalid_argument("simulate: " + *problem);
  Run run(map, setup, options);
  if (!run.start_plugin()) return run.unfinished();
  for (std::size_t step = 0;; ++step) {
    const double t = static_cast<double>(step) * options.dt;
    run.move_actors(step, t);
    const bool ego_hit = run.record_collisions(t);
    run.record_sample(t);
    const WorldSnapshot snapshot = run.look(t);
    if (run.ends(step, t, ego_hit, snapshot)) break;
    run.step_npcs(snapshot);
    if (!run.drive_ego(t)) break;
  }
  return run.finish();
}

}  // namespace scenfuzz
