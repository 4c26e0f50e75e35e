// The dynamic part (translation.hpp; docs/accident.md, "What a description means"): each vehicle
// starts heading its INITDIRECTION on that direction's way in, an unknown distance before the
// scene, at an unknown speed, and drives its chain of events as manoeuvre phases, each event
// after the first starting an unknown delay after the one before. An overtaker starts an unknown
// gap behind the vehicle it overtakes (overtaken.hpp), faster by an unknown difference; a stop
// aims at its vehicle's ENDSIGN (stop_place.hpp). Those unknowns are the search space a
// reconstruction explores, in the ranges below.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/accident/overtaken.hpp"
#include "lang/accident/stop_place.hpp"
#include "lang/accident/translation.hpp"
#include "lang/accident/vocabulary.hpp"
#include "lang/accident/way_in.hpp"
#include "lang/formula_builders.hpp"

namespace scenfuzz::accident {

namespace {

// The search ranges of the unknowns (docs/accident.md lists them with why).
constexpr double kSpeed[2] = {1, 25};           // m/s: a crawl to 90 km/h
constexpr double kStartDistance[2] = {0, 120};  // m before the scene's entry, within its arm
constexpr double kDelay[2] = {0, 10};           // s from one event's start to the next's
constexpr double kPass[2] = {1, 10};            // s an overtaking vehicle stays out
// A vehicle another overtakes: slow, and near enough the entry for the overtaker behind it to
// start within kStartDistance.
constexpr double kOvertakenSpeed[2] = {1, 20};          // m/s: up to 72 km/h
constexpr double kOvertakenStartDistance[2] = {0, 60};  // m: kStartDistance less the widest gap
// Its overtaker: behind it, centre to centre (body lengths included: a truck behind a truck
// still has 1.5 m), faster by a difference.
constexpr double kGap[2] = {10, 60};             // m
constexpr double kSpeedDifference[2] = {1, 10};  // m/s
// It pulls out this long before it would reach the overtaken vehicle's rear at the difference
// (a lane change clears the other's width within about 2.5 s of its 4), and moves back in once
// its rear is this far ahead of the other's front.
constexpr double kPullOut[2] = {3, 8};     // s
constexpr double kPassAhead[2] = {2, 20};  // m
// A stop that aims at the ENDSIGN: its front stops this far before the sign's place, braking
// evenly at this rate (comfortable to firm).
constexpr double kShortOfSign[2] = {0, 10};  // m
constexpr double kBraking[2] = {2, 5};       // m/s^2
// The timer that event starts read: seconds since the start.
constexpr const char* kClock = "clock";

// Half the body length of the simulator's car and truck (physics/actors/actor_class.cpp).
double half_length(const Vehicle& vehicle) {
  return vehicle.kind.value == VehicleKind::truck ? 8.5 / 2 : 4.7 / 2;
}

std::string directions_of(const SceneLayout& layout) {
  std::string list;
  for (const auto& [direction, way] : layout.approaches)
    list += (list.empty() ? "" : " or ") + direction_name(direction);
  return list;
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
  if (auto heading = way_in_heading(translation.file, layout, vehicle)) return heading;
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

// a + b * x, folded when b is 0.
Value affine(double a, double b, const Value& x, SourceLocation at) {
  if (b == 0) return constant_value(a, at);
  return binary_value(ValueOp::add, constant_value(a, at),
                      binary_value(ValueOp::multiply, constant_value(b, at), x, at), at);
}

Value sum(Value a, Value b, SourceLocation at) {
  return binary_value(ValueOp::add, std::move(a), std::move(b), at);
}

// The unknowns of a vehicle that an overtaker starts behind, made when the first of the two is
// translated (the overtaker may be written first): by the overtaken vehicle's ID.
struct Overtaken {
  Value start_distance, speed;
};
using OvertakenStarts = std::map<std::string, Overtaken>;

const Overtaken& overtaken_start(Translation& translation, const Vehicle& vehicle,
                                 OvertakenStarts& starts) {
  auto found = starts.find(vehicle.id.text);
  if (found != starts.end()) return found->second;
  Builder b{translation, vehicle, vehicle.id.location};
  Overtaken start;
  start.start_distance = b.value(
      b.parameter("start_distance", kOvertakenStartDistance[0], kOvertakenStartDistance[1], "m"));
  start.speed = b.value(b.parameter("speed", kOvertakenSpeed[0], kOvertakenSpeed[1], "m/s"));
  return starts.emplace(vehicle.id.text, std::move(start)).first->second;
}

// What a vehicle's start and chain read: how far before its way in's entry it starts, how fast,
// and, for an overtaker, the vehicle ahead and how much faster than it it drives.
struct Start {
  Value distance, speed;
  const Vehicle* ahead = nullptr;  // the vehicle its overtake overtakes
  std::optional<Value> difference;
};

// Where the vehicle starts: `distance` before its way in's entry, in its lane.
State start_state(Builder& b, const Approach& way, Start& start, OvertakenStarts& starts) {
  Translation& translation = b.translation;
  const SceneLayout& layout = translation.layout;
  const File& file = translation.file;
  const Overtaken* own = nullptr;  // when an overtaker starts behind this vehicle
  if (start.ahead) {
    const Overtaken& ahead = overtaken_start(translation, *start.ahead, starts);
    const Value gap = b.value(b.parameter("gap", kGap[0], kGap[1], "m"));
    start.distance = sum(ahead.start_distance, gap, b.at);
  } else if (overtaker_of(file, layout, b.vehicle)) {
    own = &overtaken_start(translation, b.vehicle, starts);
    start.distance = own->start_distance;
  } else {
    start.distance =
        b.value(b.parameter("start_distance", kStartDistance[0], kStartDistance[1], "m"));
  }
  std::optional<int> lane = fixed_start_lane(file, b.vehicle, layout.lanes);
  // An overtaken vehicle nothing else places is in its overtaker's lane (which its chain fixes).
  if (const Vehicle* overtaker = overtaker_of(file, layout, b.vehicle); !lane && overtaker)
    lane = fixed_start_lane(file, *overtaker, layout.lanes);
  std::optional<int> lane_choice;
  if (!lane) {
    Parameter p;
    p.name = b.vehicle.id.text + ".lane";
    p.kind = ParameterKind::discrete;
    p.choices = {"kerb", "beside the kerb lane"};
    p.upper = 1;
    p.location = b.at;
    lane_choice = add_parameter(translation.scenario, std::move(p));
  }
  const double offset = layout.lane_offset(lane.value_or(0));
  const PlanePoint base =
      layout.on_map({way.entry.x + offset * way.right().x, way.entry.y + offset * way.right().y});
  // Lane 1 lies a lane width further left: towards -right.
  State state;
  state.position.kind = PositionKind::coordinate;
  state.position.x = affine(base.x, -way.direction.x, start.distance, b.at);
  state.position.y = affine(base.y, -way.direction.y, start.distance, b.at);
  if (lane_choice) {
    const Value choice = b.value(*lane_choice);
    state.position.x =
        sum(state.position.x, affine(0, -layout.lane_width * way.right().x, choice, b.at), b.at);
    state.position.y =
        sum(state.position.y, affine(0, -layout.lane_width * way.right().y, choice, b.at), b.at);
  }
  state.position.location = b.at;
  if (start.ahead) {
    const Value ahead_speed = overtaken_start(translation, *start.ahead, starts).speed;
    start.difference =
        b.value(b.parameter("speed_difference", kSpeedDifference[0], kSpeedDifference[1], "m/s"));
    start.speed = sum(ahead_speed, *start.difference, b.at);
  } else if (own) {
    start.speed = own->speed;
  } else {
    start.speed = b.value(b.parameter("speed", kSpeed[0], kSpeed[1], "m/s"));
  }
  state.speed = start.speed;
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

// longitudinal_offset(vehicle, other) >= metres: its centre that far ahead of the other's.
Formula ahead_of(const Vehicle& vehicle, const Vehicle& other, Value metres, SourceLocation at) {
  return comparison(CompareOp::greater_equal,
                    signal_term("longitudinal_offset", at,
                                {word_term(vehicle.id.text, at), word_term(other.id.text, at)}),
                    value_term(std::move(metres), at), at);
}

// The phases of an overtake of `start.ahead`: out to the left at the overtaker's speed once it
// is `pull_out` seconds from the other's rear (and not before `start`), back in once its rear is
// `pass` metres ahead of the other's front.
std::vector<ManoeuvrePhase> overtake_ahead(Builder& b, const Event& event,
                                           const std::string& prefix,
                                           const std::optional<Value>& start, const Start& from) {
  const Vehicle& ahead = *from.ahead;
  const double contact = half_length(b.vehicle) + half_length(ahead);
  ManoeuvrePhase out = phase_named("Overtake", event);
  out.parameters.push_back({"speed", from.speed, event.location});
  const Value pull_out = b.value(b.parameter(prefix + "pull_out", kPullOut[0], kPullOut[1], "s"));
  const Value behind = binary_value(ValueOp::multiply, *from.difference, pull_out, b.at);
  Formula close =
      ahead_of(b.vehicle, ahead,
               binary_value(ValueOp::subtract, constant_value(-contact, b.at), behind, b.at), b.at);
  out.start_when = start ? combined(FormulaKind::conjunction, clock_reaches(*start, b.at),
                                    std::move(close), b.at)
                         : std::move(close);
  ManoeuvrePhase back = phase_named("LaneChangeRight", event);
  const Value pass = b.value(b.parameter(prefix + "pass", kPassAhead[0], kPassAhead[1], "m"));
  back.start_when =
      ahead_of(b.vehicle, ahead, sum(constant_value(contact, b.at), pass, b.at), b.at);
  std::vector<ManoeuvrePhase> phases;
  phases.push_back(std::move(out));
  phases.push_back(std::move(back));
  return phases;
}

// When a stop that aims at the sign `along` metres past the way in's entry begins, for the
// vehicle to brake evenly at `braking` from its start speed to a standstill with its front
// `short_of` before the sign: the time its front takes to reach the point where braking begins.
Value aimed_stop_time(const Builder& b, const Start& from, double along, const Value& short_of,
                      const Value& braking_time) {
  const SourceLocation at = b.at;
  const Value to_sign = sum(from.distance, constant_value(along - half_length(b.vehicle), at), at);
  const Value to_stop = binary_value(ValueOp::subtract, to_sign, short_of, at);
  return binary_value(ValueOp::subtract, binary_value(ValueOp::divide, to_stop, from.speed, at),
                      binary_value(ValueOp::multiply, constant_value(0.5, at), braking_time, at),
                      at);
}

// The phases of event k (from 1) of the chain; `start` is when it begins, none for the first.
std::vector<ManoeuvrePhase> event_phases(Builder& b, const Event& event, std::size_t k,
                                         const std::optional<Value>& start, const Start& from,
                                         const std::optional<Value>& stop_duration) {
  const std::string prefix = "event" + std::to_string(k) + ".";
  std::vector<ManoeuvrePhase> phases;
  switch (event.kind.value) {
    case EventKind::driving_forward: {
      ManoeuvrePhase drive = phase_named("Drive", event);
      drive.parameters.push_back(
          {"speed",
           k == 1 ? from.speed
                  : b.value(b.parameter(prefix + "speed", kSpeed[0], kSpeed[1], "m/s")),
           event.location});
      phases.push_back(std::move(drive));
      break;
    }
    case EventKind::turn_left: phases.push_back(phase_named("TurnLeft", event)); break;
    case EventKind::turn_right: phases.push_back(phase_named("TurnRight", event)); break;
    case EventKind::stop: {
      ManoeuvrePhase stop = phase_named("Stop", event);
      if (stop_duration) stop.parameters.push_back({"duration", *stop_duration, event.location});
      phases.push_back(std::move(stop));
      break;
    }
    case EventKind::change_lane_left: phases.push_back(phase_named("LaneChangeLeft", event)); break;
    case EventKind::change_lane_right:
      phases.push_back(phase_named("LaneChangeRight", event));
      break;
    case EventKind::overtake: {
      if (from.ahead) return overtake_ahead(b, event, prefix, start, from);
      // Out to the left (the oncoming lane on a road with one lane each way), past, and back.
      ManoeuvrePhase out = phase_named("Overtake", event);
      out.parameters.push_back({"speed",
                                b.value(b.parameter(prefix + "speed", kSpeed[0], kSpeed[1], "m/s")),
                                event.location});
      ManoeuvrePhase back = phase_named("LaneChangeRight", event);
      const Value pass = b.value(b.parameter(prefix + "pass", kPass[0], kPass[1], "s"));
      const Value out_at = start ? *start : constant_value(0, b.at);
      back.start_when = clock_reaches(sum(out_at, pass, b.at), b.at);
      phases.push_back(std::move(out));
      phases.push_back(std::move(back));
      break;
    }
  }
  if (start) phases.front().start_when = clock_reaches(*start, b.at);
  return phases;
}

Motion chain_motion(Builder& b, const Start& from, const std::optional<StopAim>& aim) {
  Motion motion;
  motion.kind = MotionKind::manoeuvres;
  motion.location = b.at;
  std::optional<Value> start;
  for (std::size_t k = 1; k <= b.vehicle.chain.size(); ++k) {
    const Event& event = b.vehicle.chain[k - 1];
    const std::string prefix = "event" + std::to_string(k) + ".";
    std::optional<Value> stop_duration;
    if (aim && aim->event == k - 1) {
      // It begins when braking then stops it short of the sign, not after a delay.
      const Value short_of =
          b.value(b.parameter(prefix + "short_of_sign", kShortOfSign[0], kShortOfSign[1], "m"));
      const Value braking =
          b.value(b.parameter(prefix + "deceleration", kBraking[0], kBraking[1], "m/s^2"));
      stop_duration = binary_value(ValueOp::divide, from.speed, braking, b.at);
      start = aimed_stop_time(b, from, aim->along, short_of, *stop_duration);
    } else if (k > 1) {
      const Value delay = b.value(b.parameter(prefix + "delay", kDelay[0], kDelay[1], "s"));
      start = start ? sum(*start, delay, b.at) : delay;
    }
    for (ManoeuvrePhase& phase : event_phases(b, event, k, start, from, stop_duration))
      motion.phases.push_back(std::move(phase));
  }
  // Without a chain a vehicle drives on at its speed.
  if (motion.phases.empty()) {
    ManoeuvrePhase drive;
    drive.manoeuvre = "Drive";
    drive.parameters.push_back({"speed", from.speed, b.at});
    drive.location = b.at;
    motion.phases.push_back(std::move(drive));
  }
  return motion;
}

// The location of the vehicle's first overtake.
SourceLocation first_overtake(const Vehicle& vehicle) {
  for (const Event& event : vehicle.chain)
    if (event.kind.value == EventKind::overtake) return event.location;
  return vehicle.location;
}

std::optional<Actor> vehicle_actor(Translation& translation, const Vehicle& vehicle,
                                   OvertakenStarts& starts) {
  const std::optional<Direction> heading = start_heading(translation, vehicle);
  if (!heading) return std::nullopt;
  Builder b{translation, vehicle, vehicle.id.location};
  Start start;
  start.ahead = overtaken_vehicle(translation.file, translation.layout, vehicle);
  if (overtakes(vehicle) && !start.ahead)
    translation.diagnostics.warning(
        first_overtake(vehicle),
        vehicle.id.text + " overtakes, but no other vehicle starts heading " +
            direction_name(*heading) +
            " in its lane without overtaking itself: there is nothing to overtake, so it starts "
            "wherever the search puts it and pulls out after its delay");
  Actor actor;
  actor.name = vehicle.id.text;
  actor.kind = vehicle.id.text == translation.ego ? ActorKind::ego : ActorKind::vehicle;
  actor.location = vehicle.location;
  actor.initial = start_state(b, *translation.layout.approach(*heading), start, starts);
  const std::optional<StopAim> aim =
      stop_aim(translation.file, translation.layout, vehicle, *heading, translation.diagnostics);
  actor.motion = chain_motion(b, start, aim);
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
  OvertakenStarts starts;
  for (const Vehicle& vehicle : translation.file.vehicles) {
    std::optional<Actor> actor = vehicle_actor(translation, vehicle, starts);
    if (!actor) continue;
    if (actor->kind == ActorKind::ego)
      scenario.ego = std::move(*actor);
    else
      scenario.vehicles.push_back(std::move(*actor));
  }
}

}  // namespace scenfuzz::accident
