// derive_mutation_space: a walk over the actors, obstacles and environment that turns each
// mutable constant into a parameter around it (see the header for the rule).
#include "sampler/mutation_space.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

constexpr std::array<std::string_view, kMutationKindCount> kNames = {
    "position", "waypoint", "lateral", "heading", "speed", "weather", "time"};
constexpr std::array<std::string_view, kMutationKindCount> kUnits = {"m",   "m", "m", "deg",
                                                                     "m/s", "",  "h"};
constexpr double kLastSecondOfDay = 24 * 3600 - 1;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Replaces constants by derived parameters, one per place in the file.
class Deriver {
 public:
  Deriver(ScenarioTemplate& scenario, const MutationSizes& sizes)
      : scenario_(scenario), sizes_(sizes) {}

  void actor(Actor& actor) {
    const std::string prefix = actor.kind == ActorKind::ego ? "ego" : actor.name;
    Motion& motion = actor.motion;
    // Measured on the written path, before any of its numbers become parameters.
    std::vector<double> limits;
    for (std::size_t i = 0; i < motion.states.size(); ++i)
      limits.push_back(spacing_limit(actor, i));
    state(actor.initial, prefix + ".init");
    if (actor.kind == ActorKind::ego) return;  // the ego's route and target stay the user's
    for (std::size_t i = 0; i < motion.states.size(); ++i) {
      const std::string path = motion.kind == MotionKind::waypoints
                                   ? prefix + ".waypoint[" + std::to_string(i) + "]"
                                   : prefix + ".motion";
      state(motion.states[i], path, limits[i]);
    }
  }

  void obstacle(Obstacle& obstacle) {
    position(obstacle.position, obstacle.name + ".position");
    if (obstacle.heading) heading(*obstacle.heading, obstacle.name + ".heading");
  }

  void environment(Environment& environment) {
    if (environment.time_of_day)
      mutate(*environment.time_of_day, "environment.time", MutationKind::time_of_day, "time of day",
             0, kLastSecondOfDay);
    for (WeatherComponent& component : environment.weather)
      mutate(component.intensity, "environment." + component.kind, MutationKind::weather, "", 0, 1);
    // The road's friction is not mutated: an icy road is what the file's words make the
    // scenario, not a number to search around.
  }

 private:
  // A waypoint written as coordinates moves at most a quarter of the way to the nearest
  // coordinate point before or after it on the actor's path, so that a densely drawn path (a turn
  // through a junction) keeps its shape instead of zig-zagging.
  static double spacing_limit(const Actor& actor, std::size_t waypoint) {
    const std::vector<State>& states = actor.motion.states;
    const State* before = waypoint == 0 ? &actor.initial : &states[waypoint - 1];
    const State* after = waypoint + 1 < states.size() ? &states[waypoint + 1] : nullptr;
    double nearest = kUnbounded;
    for (const State* other : {before, after})
      if (other) nearest = std::min(nearest, distance(states[waypoint].position, other->position));
    return nearest / 4;
  }

  // Metres between two constant ENU/IMU coordinates; unbounded when either is not one.
  static double distance(const Position& a, const Position& b) {
    auto coordinate = [](const Position& p) {
      return p.kind == PositionKind::coordinate && p.frame != Frame::wgs84 &&
             p.x.op == ValueOp::constant && p.y.op == ValueOp::constant;
    };
    if (!coordinate(a) || !coordinate(b)) return kUnbounded;
    return std::hypot(a.x.constant - b.x.constant, a.y.constant - b.y.constant);
  }

  void state(State& state, const std::string& path, double position_limit = kUnbounded) {
    position_limit_ = position_limit;
    position_kind_ = path.ends_with(".init") ? MutationKind::position : MutationKind::waypoint;
    position(state.position, path + ".position");
    position_limit_ = kUnbounded;
    position_kind_ = MutationKind::position;
    if (state.heading) heading(*state.heading, path + ".heading");
    if (state.speed)
      mutate(*state.speed, path + ".speed", MutationKind::speed, "m/s", 0, kUnbounded);
  }

  void position(Position& position, const std::string& path) {
    switch (position.kind) {
      case PositionKind::coordinate:
        // WGS84 degrees and heights are left alone: metres of neighbourhood are not degrees.
        if (position.frame == Frame::wgs84) return;
        mutate(position.x, path + ".x", position_kind_, "m", -kUnbounded, kUnbounded,
               position_limit_);
        mutate(position.y, path + ".y", position_kind_, "m", -kUnbounded, kUnbounded,
               position_limit_);
        break;
      case PositionKind::lane:
      case PositionKind::relative: {
        // An arc length along a lane starts at 0; an offset from another actor may be negative.
        const double lowest = position.kind == PositionKind::lane ? 0 : -kUnbounded;
        mutate(position.s, path + ".s", position_kind_, "m", lowest, kUnbounded);
        if (position.lateral)
          mutate(*position.lateral, path + ".lateral", MutationKind::lateral, "m", -kUnbounded,
                 kUnbounded);
        break;
      }
    }
  }

  void heading(Heading& heading, const std::string& path) {
    const bool degrees = heading.unit == AngleUnit::degree;
    mutate(heading.angle, path, MutationKind::heading, degrees ? "deg" : "rad", -kUnbounded,
           kUnbounded);
  }

  // Half widths are in the --mutate unit; the parameter is in the value's own unit.
  double half_width(MutationKind kind, const std::string& unit) const {
    const double size = sizes_[kind];
    if (kind == MutationKind::time_of_day) return size * 3600;
    if (kind == MutationKind::heading && unit == "rad") return size * std::numbers::pi / 180;
    return size;
  }

  void mutate(Value& value, const std::string& path, MutationKind kind, const std::string& unit,
              double lowest, double highest, double width_limit = kUnbounded) {
    if (value.op != ValueOp::constant || !value.location.known() || value.location.length == 0)
      return;
    const double width = std::min(half_width(kind, unit), width_limit);
    if (!(width > 0)) return;
    const auto known = by_offset_.find(value.location.offset);
    if (known != by_offset_.end()) {
      value = parameter_value(known->second, value.location);
      return;
    }
    Parameter parameter;
    parameter.name = path;
    parameter.kind =
        kind == MutationKind::heading ? ParameterKind::angle : ParameterKind::continuous;
    parameter.unit = unit;
    parameter.origin = value.constant;
    parameter.lower = std::max(lowest, value.constant - width);
    parameter.upper = std::min(highest, value.constant + width);
    // A value written outside the kind's bounds (a negative speed) is the file's business.
    if (!(parameter.lower <= value.constant && value.constant <= parameter.upper)) return;
    parameter.location = value.location;
    const int index = static_cast<int>(scenario_.parameters.size());
    scenario_.parameters.push_back(std::move(parameter));
    by_offset_.emplace(value.location.offset, index);
    value = parameter_value(index, value.location);
  }

  ScenarioTemplate& scenario_;
  const MutationSizes& sizes_;
  std::map<std::uint32_t, int> by_offset_;  // a number's place in the file -> its parameter
  // For the coordinates of the state being derived: its kind, and how far they may move.
  MutationKind position_kind_ = MutationKind::position;
  double position_limit_ = kUnbounded;
};

}  // namespace

std::string_view mutation_kind_name(MutationKind kind) {
  return kNames[static_cast<std::size_t>(kind)];
}

std::string_view mutation_kind_unit(MutationKind kind) {
  return kUnits[static_cast<std::size_t>(kind)];
}

std::optional<MutationKind> mutation_kind_named(std::string_view name) {
  for (std::size_t k = 0; k < kNames.size(); ++k)
    if (kNames[k] == name) return static_cast<MutationKind>(k);
  return std::nullopt;
}

std::string mutation_sizes_text(const MutationSizes& sizes) {
  std::string text;
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    std::ostringstream size;
    size << sizes.half_width[k];
    text += (text.empty() ? "" : " ") + std::string(kNames[k]) + "=" + size.str();
  }
  return text;
}

std::optional<std::string> apply_mutation_option(const std::string& option, MutationSizes& sizes) {
  std::string kinds;
  for (std::string_view name : kNames) kinds += (kinds.empty() ? "" : ", ") + std::string(name);
  const std::size_t equals = option.find('=');
  const std::optional<MutationKind> kind =
      mutation_kind_named(std::string_view(option).substr(0, equals));
  if (equals == std::string::npos || !kind)
    return "--mutate: expected KIND=SIZE with KIND one of " + kinds + ", got '" + option + "'";
  const std::string size_text = option.substr(equals + 1);
  double size = 0;
  const char* last = size_text.data() + size_text.size();
  const auto [end, error] = std::from_chars(size_text.data(), last, size);
  if (error != std::errc() || end != last || !std::isfinite(size) || size < 0)
    return "--mutate " + option + ": the size must be a finite number >= 0 (in " +
           (mutation_kind_unit(*kind).empty() ? std::string("intensity, 0 to 1")
                                              : std::string(mutation_kind_unit(*kind))) +
           ")";
  sizes[*kind] = size;
  return std::nullopt;
}

namespace {

bool only_event_outcomes(const std::vector<Parameter>& parameters) {
  return std::all_of(parameters.begin(), parameters.end(),
                     [](const Parameter& parameter) { return parameter.event_outcome; });
}

}  // namespace

bool searched_by_mutation(const ScenarioTemplate& scenario) {
  return scenario.has_scenario && only_event_outcomes(scenario.parameters);
}

ScenarioTemplate derive_mutation_space(const ScenarioTemplate& scenario,
                                       const MutationSizes& sizes) {
  SCENFUZZ_DEMAND(only_event_outcomes(scenario.parameters));
  ScenarioTemplate derived = scenario;
  Deriver deriver(derived, sizes);
  if (derived.has_scenario) deriver.actor(derived.ego);
  for (Actor& actor : derived.vehicles) deriver.actor(actor);
  for (Actor& actor : derived.pedestrians) deriver.actor(actor);
  for (Obstacle& obstacle : derived.obstacles) deriver.obstacle(obstacle);
  if (derived.environment) deriver.environment(*derived.environment);
  return derived;
}

}  // namespace scenfuzz
