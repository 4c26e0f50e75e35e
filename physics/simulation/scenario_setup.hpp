// From a scenario to what the simulation runs: every actor placed on the map with its class and
// initial state, every scripted NPC's trajectory planned (lane routes, OMPL paths through
// waypoints, pedestrians' walks), the ego's target, obstacles, traffic-light settings, weather,
// the road's friction and duration, all evaluated at one point of the search space.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/actors/road_friction.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/collision/collision_world.hpp"
#include "physics/ego/perception.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/manoeuvre_script.hpp"

namespace scenfuzz {

// A lane-following NPC's plan for driving reactively (LaneFollower): its lane route, the path
// drawn along it, and the speed it aims for.
struct LaneDrive {
  LaneRoute route;
  Polyline path;
  std::vector<PathPlace> places;  // route_path's, of the path's points
  double desired_speed = 0;       // m/s
  double initial_speed = 0;       // m/s
};

// A background traffic flow (the scenario's Traffic::flows) ready to run: its lane route from the
// start of its source lane, the path drawn along it, its rate and its vehicles' desired speed.
// Its vehicles and when they arrive are drawn from `seed` (traffic_flows.hpp).
struct FlowPlan {
  std::string name;
  SourceLocation location;
  LaneRoute route;
  Polyline path;
  std::vector<PathPlace> places;  // route_path's, of the path's points
  double rate = 0;                // vehicles per hour
  double speed = 0;               // m/s
  std::uint64_t seed = 0;
  // Route distances where the route enters and leaves each junction it runs through: no vehicle
  // is pre-filled there or within its stopping distance before one (traffic_flows.cpp).
  std::vector<std::pair<double, double>> junctions;
  ActorClass body;  // every vehicle's: flow_vehicle_body() on the road's grip (road_friction.hpp)
};

// An NPC vehicle or pedestrian: it follows its trajectory and does not react; or, with
// `manoeuvres` (WMG SDL phases), it is driven online by a ManoeuvreDriver and its trajectory
// only stands at its initial pose; or, with `lane_drive` and reactive NPC behaviour, it is driven
// by a LaneFollower (its trajectory is what it would do scripted).
struct ScriptedActor {
  std::string name;
  TraceActorKind kind = TraceActorKind::vehicle;
  // Its class on the road's grip (a vehicle's limits, road_friction.hpp), a pedestrian with its
  // height from the scenario.
  ActorClass body;
  Trajectory trajectory;
  std::optional<ManoeuvreScript> manoeuvres;
  std::optional<LaneDrive> lane_drive;
};

struct StaticObstacle {
  std::string name;
  BodyGeometry geometry;
  MapPose pose;
};

// A scenario's setting of one of the map's traffic lights: it shows `colour` from t = 0 (when
// the light has a signal plan, the plan runs on from the start of that colour's phase).
struct LightSetting {
  std::uint32_t light = 0;  // index into RoadMap::traffic_lights()
  SignalColour colour = SignalColour::red;
};

struct SimulationSetup {
  std::string ego_name = "ego";
  ActorClass ego_body;  // its class on the road's grip (road_friction.hpp)
  KinematicState ego_initial;
  std::optional<MapPose> ego_target;
  // Over the lane graph to the target, or along the lanes ahead when there is none.
  LaneRoute ego_route;
  // The ego replays a script, as in an accident reconstruction, instead of being driven by the
  // reference driver or plugin (its phases resolved as the actors' are).
  std::optional<ManoeuvreScript> ego_script;
  std::vector<ScriptedActor> actors;  // vehicles first, then pedestrians, as in the scenario
  std::vector<StaticObstacle> obstacles;
  std::vector<LightSetting> lights;
  std::vector<std::pair<LaneIndex, double>> speed_limits;  // the scenario's, m/s
  Conditions conditions;
  // The road's grip as a share of dry asphalt's (road_friction.hpp): every body here is already
  // on it; the reference driver also plans with it (driver_on_road.hpp).
  double road_friction = kDryRoad;
  double duration = 30;  // s
  // WMG SDL timers: timer(T) reads seconds since the start plus the initial value.
  std::vector<std::string> timer_names;
  std::vector<double> timer_initial_values;
  // The run ends at the first step where one holds.
  std::vector<TriggerCondition> end_conditions;
  NpcBehaviour npc_behaviour = NpcBehaviour::reactive;  // as the scenario says
  // Background traffic, in the scenario's order; its vehicles are always reactive.
  std::vector<FlowPlan> flows;
};

// Evaluates `scenario` at `values` on `map`. Problems (an unknown lane, an unreachable target, a
// path that cannot be planned, an unsupported motion) are errors in `diagnostics` at the place
// in the file they come from, and give nullopt. `seed` seeds pedestrians' random walks and the
// sampling planner.
std::optional<SimulationSetup> prepare_simulation(const ScenarioTemplate& scenario,
                                                  std::span<const double> values,
                                                  const RoadMap& map, std::uint64_t seed,
                                                  Diagnostics& diagnostics);

}  // namespace scenfuzz
