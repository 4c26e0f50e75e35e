// The dynamic part (translation.hpp; docs/accident.md, "What a description means"): each vehicle
// starts heading its INITDIRECTION on that direction's way in, an unknown distance before the
// scene, at an unknown speed, and drives its chain of events as manoeuvre phases, each event
// after the first starting an unknown delay after the one before. Those unknowns are the search
// space a reconstruction explores, in the ranges below.
#include <cmath>
#include <limits>

#include "lang/accident/translation.hpp"
#include "lang/accident/vocabulary.hpp"
#include "lang/formula_builders.hpp"

namespace scenfuzz::accident {

namespace {

// The search ranges of the unknowns (docs/accident.md lists them with why).
constexpr double kSpeed[2] = {1, 25};           // m/s: a crawl to 90 km/h
constexpr double kStartDistance[2] = {0, 120};  // m before the scene's entry, within its arm
constexpr double kDelay[2] = {0, 10};           // s from one event's start to the next's
constexpr double kPass[2] = {1, 10};            // s an overtaking vehicle stays out
// The timer that event starts read: seconds since the start.
constexpr const char* kClock = "clock";

std::string directions_of(const SceneLayout& layout) {
  std::string list;
  for (const auto& [direction, way] : layout.approaches)
    list += (list.empty() ? "" : " or ") + direction_name(direction);
  return list;
}

// The heading a sign's place asks for: the way in whose line passes nearest it.
std::optional<Direction> heading_towards(const SceneLayout& layout, PlanePoint sign) {
  std::optional<Direction> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [direction, way] : layout.approaches) {
    // Only behind the entry: a sign further on is on another direction's way.
    const double along =
        (sign.x - way.entry.x) * way.direction.x + (sign.y - way.entry.y) * way.direction.y;
    const double across = std::abs((sign.x - way.entry.x) * way.direction.y -
                                   (sign.y - way.entry.y) * way.direction.x);
    const double distance = along <= 0 ? across : across + along;
    if (distance < nearest) {
      nearest = distance;
      best = direction;
    }
  }
  return best;
}

std::optional<PlanePoint> sign_place(const File& file, const SignReference& sign) {
  if (sign.kind == SignReference::Kind::point) return PlanePoint{sign.point.x, sign.point.y};
  for (const Light& light : file.lights)
    if (light.id.text == sign.name.text) return PlanePoint{light.coords.x, light.coords.y};
  for (const Tree& tree : file.trees)
    if (tree.id.text == sign.name.text) return PlanePoint{tree.coords.x, tree.coords.y};
  return std::nullopt;
}

// INITDIRECTION, else the way in nearest its STARTSIGN; an error when neither says.
std::optional<Direction> start_heading(Translation& translation, const Vehicle& vehicle) {
  const SceneLayout& layout = translation.layout;
  if (vehicle.init_direction) {
    const Direction heading = vehicle.init_direction->value;
    if (layout.approach(heading)) return heading;
    translation.diagnostics.error(
        vehicle.init_direction->location,
        vehicle.id.text + " cannot start heading " + direction_name(heading) + " on a " +
            std::string(spelling(road_kinds(), translation.file.road.kind.value)) +
            ": traffic there starts heading " + directions_of(layout));
    return std::nullopt;
  }
  if (vehicle.start_sign)
    if (auto place = sign_place(translation.file, *vehicle.start_sign))
      return heading_towards(layout, *place);
  translation.diagnostics.error(vehicle.id.location,
                                vehicle.id.text +
                                    " has neither an INITDIRECTION nor a STARTSIGN: say which way "
                                    "it heads at the start (INITDIRECTION = " +
                                    direction_name(layout.approaches.front().first) + ";)");
  return std::nullopt;
}

struct Builder {
  Translation& translation;
  const Vehicle& vehicle;
  SourceLocation at;

  int parameter(const std::string& what, double lower, double upper, const std::string& unit) {
    Parameter p;
    p.name = vehicle.id.text + "." + what;
    p.lower = lower;
    p.upper = upper;
    p.unit = unit;
    p.location = at;
    return add_parameter(translation.scenario, std::move(p));
  }
  Value value(int parameter) const { return parameter_value(parameter, at); }
};

// The lane a chain of events needs to start in: a turn from the lane that has the turn's
// connector, a move to the left from the kerb lane, to the right from the lane beside it.
std::optional<int> lane_for_chain(const Vehicle& vehicle, int lanes) {
  for (const Event& event : vehicle.chain) {
    switch (event.kind.value) {
      case EventKind::turn_left:
      case EventKind::change_lane_right: return lanes - 1;
      case EventKind::turn_right:
      case EventKind::change_lane_left:
      case EventKind::overtake: return 0;
      default: break;
    }
  }
  return std::nullopt;
}

// The lane a lane change goes to, when the vehicle changes lanes.
std::optional<int> lane_changed_to(const Vehicle& vehicle, int lanes) {
  for (const Event& event : vehicle.chain) {
    if (event.kind.value == EventKind::change_lane_left) return lanes - 1;
    if (event.kind.value == EventKind::change_lane_right) return 0;
  }
  return std::nullopt;
}

const Vehicle* vehicle_named(const File& file, const std::string& name) {
  for (const Vehicle& vehicle : file.vehicles)
    if (vehicle.id.text == name) return &vehicle;
  return nullptr;
}

// The lane a vehicle starts in, when the description fixes it: the one its chain needs, else the
// one a vehicle heading its way changes into to collide with it (a sideswipe's victim is in the
// lane the other moves to). None when the road has two lanes each way and nothing says which.
std::optional<int> start_lane(const File& file, const Vehicle& vehicle, int lanes) {
  if (lanes == 1) return 0;
  if (auto lane = lane_for_chain(vehicle, lanes)) return lane;
  for (const Collision& collision : file.collisions) {
    const bool actor = collision.actor.id.text == vehicle.id.text;
    if (!actor && collision.victim.id.text != vehicle.id.text) continue;
    const Vehicle* other =
        vehicle_named(file, actor ? collision.victim.id.text : collision.actor.id.text);
    if (!other || !other->init_direction || !vehicle.init_direction ||
        other->init_direction->value != vehicle.init_direction->value)
      continue;
    if (auto lane = lane_changed_to(*other, lanes)) return lane;
  }
  return std::nullopt;
}

// a + b * parameter, folded when the parameter is absent.
Value affine(double a, double b, std::optional<int> parameter, SourceLocation at) {
  if (!parameter || b == 0) return constant_value(a, at);
  return binary_value(
      ValueOp::add, constant_value(a, at),
      binary_value(ValueOp::multiply, constant_value(b, at), parameter_value(*parameter, at), at),
      at);
}

// Where the vehicle starts: `distance` before its way in's entry, in its lane.
State start_state(Builder& b, const Approach& way) {
  const SceneLayout& layout = b.translation.layout;
  const int distance = b.parameter("start_distance", kStartDistance[0], kStartDistance[1], "m");
  std::optional<int> lane = start_lane(b.translation.file, b.vehicle, layout.lanes);
  std::optional<int> lane_choice;
  if (!lane) {
    Parameter p;
    p.name = b.vehicle.id.text + ".lane";
    p.kind = ParameterKind::discrete;
    p.choices = {"kerb", "beside the kerb lane"};
    p.upper = 1;
    p.location = b.at;
    lane_choice = add_parameter(b.translation.scenario, std::move(p));
  }
  const double offset = layout.lane_offset(lane.value_or(0));
  const PlanePoint base =
      layout.on_map({way.entry.x + offset * way.right().x, way.entry.y + offset * way.right().y});
  // Lane 1 lies a lane width further left: towards -right.
  State state;
  state.position.kind = PositionKind::coordinate;
  state.position.x = affine(base.x, -way.direction.x, distance, b.at);
  state.position.y = affine(base.y, -way.direction.y, distance, b.at);
  if (lane_choice) {
    state.position.x =
        binary_value(ValueOp::add, state.position.x,
                     affine(0, -layout.lane_width * way.right().x, lane_choice, b.at), b.at);
    state.position.y =
        binary_value(ValueOp::add, state.position.y,
                     affine(0, -layout.lane_width * way.right().y, lane_choice, b.at), b.at);
  }
  state.position.location = b.at;
  state.speed = b.value(b.parameter("speed", kSpeed[0], kSpeed[1], "m/s"));
  state.location = b.at;
  return state;
}

ManoeuvrePhase phase_named(const char* manoeuvre, const Event& event) {
  ManoeuvrePhase phase;
  phase.manoeuvre = manoeuvre;
  phase.critical = event.critical;
  phase.location = event.location;
  return phase;
}

Formula clock_reaches(Value time, SourceLocation at) {
  return comparison(CompareOp::greater_equal, signal_term("timer", at, {word_term(kClock, at)}),
                    value_term(std::move(time), at), at);
}

// The phases of event k (from 1) of the chain; `start` is when it begins, none for the first.
std::vector<ManoeuvrePhase> event_phases(Builder& b, const Event& event, std::size_t k,
                                         const std::optional<Value>& start, const Value& speed) {
  const std::string prefix = "event" + std::to_string(k) + ".";
  std::vector<ManoeuvrePhase> phases;
  switch (event.kind.value) {
    case EventKind::driving_forward: {
      ManoeuvrePhase drive = phase_named("Drive", event);
      drive.parameters.push_back(
          {"speed",
           k == 1 ? speed : b.value(b.parameter(prefix + "speed", kSpeed[0], kSpeed[1], "m/s")),
           event.location});
      phases.push_back(std::move(drive));
      break;
    }
    case EventKind::turn_left: phases.push_back(phase_named("TurnLeft", event)); break;
    case EventKind::turn_right: phases.push_back(phase_named("TurnRight", event)); break;
    case EventKind::stop: phases.push_back(phase_named("Stop", event)); break;
    case EventKind::change_lane_left: phases.push_back(phase_named("LaneChangeLeft", event)); break;
    case EventKind::change_lane_right:
      phases.push_back(phase_named("LaneChangeRight", event));
      break;
    case EventKind::overtake: {
      // Out to the left (the oncoming lane on a road with one lane each way), past, and back.
      ManoeuvrePhase out = phase_named("Overtake", event);
      out.parameters.push_back({"speed",
                                b.value(b.parameter(prefix + "speed", kSpeed[0], kSpeed[1], "m/s")),
                                event.location});
      ManoeuvrePhase back = phase_named("LaneChangeRight", event);
      const Value pass = b.value(b.parameter(prefix + "pass", kPass[0], kPass[1], "s"));
      const Value out_at = start ? *start : constant_value(0, b.at);
      back.start_when = clock_reaches(binary_value(ValueOp::add, out_at, pass, b.at), b.at);
      phases.push_back(std::move(out));
      phases.push_back(std::move(back));
      break;
    }
  }
  if (start) phases.front().start_when = clock_reaches(*start, b.at);
  return phases;
}

Motion chain_motion(Builder& b, const Value& speed) {
  Motion motion;
  motion.kind = MotionKind::manoeuvres;
  motion.location = b.at;
  std::optional<Value> start;
  for (std::size_t k = 1; k <= b.vehicle.chain.size(); ++k) {
    const Event& event = b.vehicle.chain[k - 1];
    if (k > 1) {
      const std::string name = "event" + std::to_string(k) + ".delay";
      const Value delay = b.value(b.parameter(name, kDelay[0], kDelay[1], "s"));
      start = start ? binary_value(ValueOp::add, *start, delay, b.at) : delay;
    }
    for (ManoeuvrePhase& phase : event_phases(b, event, k, start, speed))
      motion.phases.push_back(std::move(phase));
  }
  // Without a chain a vehicle drives on at its speed.
  if (motion.phases.empty()) {
    ManoeuvrePhase drive;
    drive.manoeuvre = "Drive";
    drive.parameters.push_back({"speed", speed, b.at});
    drive.location = b.at;
    motion.phases.push_back(std::move(drive));
  }
  return motion;
}

std::optional<Actor> vehicle_actor(Translation& translation, const Vehicle& vehicle) {
  const std::optional<Direction> heading = start_heading(translation, vehicle);
  if (!heading) return std::nullopt;
  Builder b{translation, vehicle, vehicle.id.location};
  Actor actor;
  actor.name = vehicle.id.text;
  actor.kind = vehicle.id.text == translation.ego ? ActorKind::ego : ActorKind::vehicle;
  actor.location = vehicle.location;
  actor.initial = start_state(b, *translation.layout.approach(*heading));
  actor.motion = chain_motion(b, *actor.initial.speed);
  ActorType type;
  type.model = vehicle.kind.value == VehicleKind::truck ? "truck" : "car";
  type.general = true;
  type.location = vehicle.kind.location;
  actor.type = type;
  return actor;
}

}  // namespace

void translate_vehicles(Translation& translation) {
  ScenarioTemplate& scenario = translation.scenario;
  scenario.timers.push_back({kClock, constant_value(0), {}});
  for (const Vehicle& vehicle : translation.file.vehicles) {
    std::optional<Actor> actor = vehicle_actor(translation, vehicle);
    if (!actor) continue;
    if (actor->kind == ActorKind::ego)
      scenario.ego = std::move(*actor);
    else
      scenario.vehicles.push_back(std::move(*actor));
  }
}

}  // namespace scenfuzz::accident
