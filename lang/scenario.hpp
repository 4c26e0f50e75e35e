// The scenario IR: one ScenarioTemplate for every language (AVUnit, scenest, WMG SDL, CH-Scenario,
// the accident formalism). A template is a logical scenario: its numeric slots are Values that may
// read the search parameters listed in `parameters`. Fixing every parameter gives a concrete one.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "lang/parameter.hpp"
#include "lang/position.hpp"
#include "lang/spec.hpp"
#include "lang/value.hpp"

namespace scenfuzz {

enum class SourceLanguage { avunit, scenest, wmg_sdl, ch_scenario, accident };

// A numeric fact with a name: a map parameter ("R1.length"), a manoeuvre argument, a timer.
struct NamedValue {
  std::string name;
  Value value;
  SourceLocation location;

  bool operator==(const NamedValue&) const = default;
};

// A descriptive fact with no number to search over ("surface" = "wet", "illumination" = "Night").
struct Attribute {
  std::string key;
  std::string value;
  SourceLocation location;

  bool operator==(const Attribute&) const = default;
};

struct Point {
  Value x, y;

  bool operator==(const Point&) const = default;
};

// A road drawn as polylines (CH-Scenario road networks).
struct RoadOutline {
  std::string name;
  std::vector<Point> left_boundary, centre_line, right_boundary;
  std::optional<Value> speed_limit;  // m/s, every lane of the road; none: no limit
  SourceLocation location;

  bool operator==(const RoadOutline&) const = default;
};

// A way through a junction the scenario says the map has (WMG's `Road lane connections`): from a
// lane into the junction to a lane out of it, as the map's lane ids.
struct LaneLink {
  std::string from, to;
  SourceLocation location;  // the lane `to`, as written

  bool operator==(const LaneLink&) const = default;
};

// A traffic light on a drawn road network's junction (CH-Scenario's light entities): the
// junction nearest (x, y) gets fixed-time lights, road `road` showing `colour` (red, yellow,
// green) at the start of that phase and the crossing road the opposite (physics/map/
// outline_signals.hpp).
struct JunctionSignal {
  std::string name;
  double x = 0, y = 0;
  std::string road;
  std::string colour;
  SourceLocation location;

  bool operator==(const JunctionSignal&) const = default;
};

// The map: a name (built-in parametric map, Apollo map, or path) and, for languages that describe
// roads by ranges, parameters that make the map itself part of the search space.
struct MapReference {
  std::string name;
  std::vector<NamedValue> parameters;
  std::vector<Attribute> attributes;
  std::vector<RoadOutline> roads;
  std::vector<LaneLink> links;
  std::vector<JunctionSignal> signals;  // only with roads
  SourceLocation location;

  bool operator==(const MapReference&) const = default;
};

struct Color {
  std::string name;                       // red, green, blue, black, white; empty for RGB
  std::optional<std::array<int, 3>> rgb;  // 0..255 each

  bool operator==(const Color&) const = default;
};

struct ActorType {
  std::string model;            // "Lincoln2017MKZ", or a general kind such as car, truck
  bool general = false;         // model is a general kind, not a specific model
  std::optional<Color> color;   // vehicle paint or pedestrian clothing
  std::optional<Value> height;  // pedestrians, metres
  SourceLocation location;

  bool operator==(const ActorType&) const = default;
};

// One phase of a manoeuvre sequence (WMG SDL, accident event chains): what the actor does, with
// its arguments, when it starts and while it lasts.
struct ManoeuvrePhase {
  std::string manoeuvre;               // e.g. "Drive_CutIn", "turn_left", "stop"
  std::vector<NamedValue> parameters;  // docs/wmg-semantics.md: speed, duration, gap
  std::string reference;               // the actor the manoeuvre is relative to, if any
  std::string relative_location;       // WMG sector F, FSR, SR, RSR, R, RSL, SL, FSL
  // The lanes of the road the phase names (WMG `[Walk_Cross] [R3, ...]`): what a crossing crosses.
  std::vector<std::string> road_lanes;
  std::optional<Formula> start_when;
  std::optional<Formula> continue_while;
  bool critical = false;
  SourceLocation location;

  bool operator==(const ManoeuvrePhase&) const = default;
};

enum class MotionKind {
  follow_route,  // along the lanes from the initial to the target state at the initial speed
  uniform,       // constant speed given by states[0]
  waypoints,     // through states, in order
  random_walk,   // random motion around states[0] (pedestrians)
  manoeuvres,    // phases
};

struct Motion {
  MotionKind kind = MotionKind::follow_route;
  std::vector<State> states;
  std::vector<ManoeuvrePhase> phases;
  SourceLocation location;

  bool operator==(const Motion&) const = default;
};

enum class ActorKind { ego, vehicle, pedestrian, cyclist };

struct Actor {
  ActorKind kind = ActorKind::vehicle;
  std::string name;  // the identifier specs use to refer to it
  State initial;
  Motion motion;
  std::optional<State> target;
  std::optional<ActorType> type;
  SourceLocation location;

  bool operator==(const Actor&) const = default;
};

// Exactly FCL's primitives. Dimensions: sphere {radius}; box {length, width, height};
// cone and cylinder {radius, height, third value as written}.
enum class ShapeKind { sphere, box, cone, cylinder };

struct Shape {
  ShapeKind kind = ShapeKind::box;
  std::vector<Value> dimensions;
  SourceLocation location;

  bool operator==(const Shape&) const = default;
};

struct Obstacle {
  std::string name;
  Position position;
  std::optional<Heading> heading;
  std::optional<Shape> shape;  // none: the simulator's default obstacle
  SourceLocation location;

  bool operator==(const Obstacle&) const = default;
};

enum class WeatherLevel { light, middle, heavy };

struct WeatherComponent {
  std::string kind;  // sunny, rain, snow, fog, wetness, cloudiness, wind, visibility, ...
  Value intensity;   // in [0, 1]
  std::optional<WeatherLevel> level;  // written as a level; intensity is the level's value
  SourceLocation location;

  bool operator==(const WeatherComponent&) const = default;
};

struct Environment {
  std::optional<Value> time_of_day;  // seconds since midnight
  std::vector<WeatherComponent> weather;
  // The road's grip as a share of dry asphalt's, in (0, 1]; none: dry (docs/simulation.md).
  std::optional<Value> road_friction;
  std::vector<Attribute> attributes;
  SourceLocation location;

  bool operator==(const Environment&) const = default;
};

// scenest: `Intersection(id, light, stop sign, crosswalk)`.
struct IntersectionControl {
  std::string id;
  bool traffic_light = false;
  bool stop_sign = false;
  bool crosswalk = false;
  SourceLocation location;

  bool operator==(const IntersectionControl&) const = default;
};

struct SpeedLimit {
  std::string lane;
  Value lower, upper;  // m/s
  SourceLocation location;

  bool operator==(const SpeedLimit&) const = default;
};

// A scenario's setting of a traffic light: its initial colour and the lanes it controls.
struct TrafficLightSetting {
  std::string id;
  std::string color;  // initial colour
  std::optional<Position> position;
  std::vector<std::string> controlled_lanes;
  SourceLocation location;

  bool operator==(const TrafficLightSetting&) const = default;
};

// Background traffic between two places (WMG SDL traffic model).
struct TrafficFlow {
  std::string name;
  std::string source_lane, destination_lane;
  Value rate;  // vehicles per hour
  std::optional<Value> speed;
  SourceLocation location;

  bool operator==(const TrafficFlow&) const = default;
};

struct Traffic {
  std::vector<IntersectionControl> intersections;
  std::vector<SpeedLimit> speed_limits;
  std::vector<TrafficLightSetting> lights;
  std::vector<Position> stop_signs;
  std::vector<Position> level_crossings;
  std::vector<TrafficFlow> flows;

  bool operator==(const Traffic&) const = default;
};

enum class VehiclePart { front, rear, left_side, right_side, unknown };

// A collision the scenario is meant to reproduce (accident formalism).
struct ExpectedCollision {
  std::string striker, victim;
  VehiclePart striker_part = VehiclePart::unknown;
  VehiclePart victim_part = VehiclePart::unknown;
  std::optional<Position> position;
  SourceLocation location;

  bool operator==(const ExpectedCollision&) const = default;
};

// A guarded event with an optional probability (CH-Scenario constraints).
struct ScenarioEvent {
  std::vector<std::string> actors;
  std::optional<Formula> guard;
  std::vector<std::string> actions;
  std::optional<Value> probability;
  SourceLocation location;

  bool operator==(const ScenarioEvent&) const = default;
};

// How lane-following NPCs drive: reacting to traffic (IDM car following, lights, signs, giving
// way) as simulator NPCs do, or along their script without looking (docs/simulation.md).
enum class NpcBehaviour { reactive, scripted };

struct ScenarioTemplate {
  SourceLanguage language = SourceLanguage::avunit;
  std::vector<Parameter> parameters;
  // False for a fragment: a file of definitions that builds no scenario.
  bool has_scenario = false;
  MapReference map;
  Actor ego;
  std::vector<Actor> vehicles;
  std::vector<Actor> pedestrians;
  std::vector<Obstacle> obstacles;
  std::optional<Environment> environment;
  Traffic traffic;
  std::vector<Spec> specs;
  std::vector<ExpectedCollision> expected_collisions;
  std::vector<ScenarioEvent> events;
  std::vector<NamedValue> timers;
  std::vector<Formula> end_conditions;
  std::optional<Value> duration;  // seconds
  // As the file sets it; unset means reactive unless the command line says otherwise.
  std::optional<NpcBehaviour> npc_behaviour;
  std::string trace_name;     // the trace variable the specs are asserted on
  std::string scenario_name;  // the variable the scenario was bound to

  bool operator==(const ScenarioTemplate&) const = default;
};

// The actor named `name` (the ego, a vehicle or a pedestrian), or null.
const Actor* find_actor(const ScenarioTemplate& scenario, const std::string& name);

}  // namespace scenfuzz
