// TraceSignals: AVUnit's signal functions `dis vel spd acc diff` and the columns of trace
// projections over a simulated trace. The scenest traffic-law signals are in law_signals.cpp.
#include "oracle/trace_signals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/builtins.hpp"
#include "lang/number_format.hpp"
#include "oracle/law_signals.hpp"
#include "physics/map/scenario_position.hpp"
#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

// LawBreaker's value for a quantity involving an agent the ego does not perceive: far beyond what
// specs compare with, so `dis(ego, seen) >= 2` holds where the agent is unseen.
constexpr double kUnperceived = 1000;
// diff(...) counts an undetected agent as a perception error only within this distance (m) of the
// ego, as LawBreaker does: missing an agent far away is no fault of the perception.
constexpr double kDiffRange = 100;
// diff(...)'s weights: LawBreaker's (position, velocity, heading, size) = (2, 2, 1, 2) over 7.
constexpr double kPositionWeight = 2, kVelocityWeight = 2, kHeadingWeight = 1, kSizeWeight = 2;
constexpr double kWeightSum = kPositionWeight + kVelocityWeight + kHeadingWeight + kSizeWeight;

struct PlaneVector {
  double x = 0;
  double y = 0;
};

PlaneVector operator-(PlaneVector a, PlaneVector b) { return {a.x - b.x, a.y - b.y}; }
double norm(PlaneVector v) { return std::sqrt(v.x * v.x + v.y * v.y); }

PlaneVector along(double heading, double length) {
  return {length * std::cos(heading), length * std::sin(heading)};
}

// The acceleration of a perceived agent, which the perception does not report: central
// differences of its perceived velocity, one-sided next to a gap in detection; unknown at an
// isolated detection.
struct PerceivedAcceleration {
  std::vector<PlaneVector> value;
  std::vector<std::uint8_t> known;
};

PerceivedAcceleration perceived_acceleration(const Trace& trace, const PerceivedActor& seen) {
  const std::size_t count = trace.sample_count();
  PerceivedAcceleration result{std::vector<PlaneVector>(count), std::vector<std::uint8_t>(count)};
  auto velocity = [&](std::size_t i) {
    return along(seen.heading[i], longitudinal_velocity_at(seen.speed, seen.reversing, i));
  };
  for (std::size_t i = 0; i < count; ++i) {
    if (!seen.detected[i]) continue;
    std::size_t before = i, after = i;
    if (i > 0 && seen.detected[i - 1]) before = i - 1;
    if (i + 1 < count && seen.detected[i + 1]) after = i + 1;
    if (before == after) continue;
    const PlaneVector change = velocity(after) - velocity(before);
    const double elapsed = trace.time[after] - trace.time[before];
    result.value[i] = {change.x / elapsed, change.y / elapsed};
    result.known[i] = 1;
  }
  return result;
}

// A signal function's argument resolved against the trace.
struct Argument {
  enum class Kind { body, point, vector, speed };
  Kind kind = Kind::body;
  ActorId actor = kEgo;                       // body: whose true size, and true state
  const PerceivedActor* perceived = nullptr;  // body: seen through the ego's perception
  MapPoint point;                             // point
  std::vector<double> first, second;          // vector: x and y per sample; speed: first
  std::vector<double> up;                     // vector: z per sample, if written (x, y, z)
  PerceivedAcceleration acceleration;         // perceived bodies, for acc(...)
};

// The vertical component: a written vector's z, else 0 (simulated actors move in the plane).
double up_at(const Argument& argument, std::size_t i) {
  return argument.up.empty() ? 0.0 : argument.up[i];
}

bool perceived_at(const Argument& argument, std::size_t i) {
  return argument.perceived == nullptr || argument.perceived->detected[i];
}

Footprint footprint(const Trace& trace, const Argument& argument, std::size_t i) {
  if (argument.kind == Argument::Kind::point) return {argument.point, 0, 0, 0, true};
  Footprint body = footprint_at(trace, argument.actor, i);
  if (argument.perceived) {
    // The perception reports where the agent is, not how big: the footprint keeps the true size.
    body.centre = {argument.perceived->x[i], argument.perceived->y[i]};
    body.heading = argument.perceived->heading[i];
  }
  return body;
}

double speed(const Trace& trace, const Argument& argument, std::size_t i) {
  if (argument.kind == Argument::Kind::speed) return argument.first[i];
  if (argument.perceived) return argument.perceived->speed[i];
  return trace.actors[argument.actor].speed[i];
}

PlaneVector velocity(const Trace& trace, const Argument& argument, std::size_t i) {
  if (argument.kind == Argument::Kind::vector) return {argument.first[i], argument.second[i]};
  if (argument.perceived) {
    const PerceivedActor& seen = *argument.perceived;
    return along(seen.heading[i], longitudinal_velocity_at(seen.speed, seen.reversing, i));
  }
  const TraceActor& actor = trace.actors[argument.actor];
  return along(actor.heading[i], longitudinal_velocity_at(actor.speed, actor.reversing, i));
}

// Longitudinal acceleration along the heading plus the centripetal speed * yaw rate across it;
// a reversing actor's velocity points backwards, and so do both (the trace's acceleration is the
// rate of change of the speed, a magnitude).
PlaneVector acceleration(const Trace& trace, const Argument& argument, std::size_t i) {
  if (argument.kind == Argument::Kind::vector) return {argument.first[i], argument.second[i]};
  if (argument.perceived) return argument.acceleration.value[i];
  const TraceActor& actor = trace.actors[argument.actor];
  const double direction = reversing_at(actor.reversing, i) ? -1 : 1;
  const PlaneVector forward = along(actor.heading[i], direction * actor.acceleration[i]);
  const PlaneVector sideways =
      along(actor.heading[i], direction * actor.speed[i] * actor.yaw_rate[i]);
  return {forward.x - sideways.y, forward.y + sideways.x};
}

std::string trace_name(const ScenarioTemplate& scenario) {
  return scenario.trace_name.empty() ? "trace" : scenario.trace_name;
}

std::string describe_object(const ScenarioTemplate& scenario, ObjectSource source,
                            const std::string& name) {
  switch (source) {
    case ObjectSource::ego: return trace_name(scenario) + "[ego]";
    case ObjectSource::truth: return trace_name(scenario) + "[truth][" + name + "]";
    case ObjectSource::perception: return trace_name(scenario) + "[perception][" + name + "]";
  }
  return name;
}

// What leaf() needs besides the term: the object it belongs to, passed down explicitly so that
// the helpers stay free functions.
struct Context {
  const Trace& trace;
  const ScenarioTemplate& scenario;
  const RoadMap& map;
  SignalSource source;
};

ActorId object_actor(const Context& context, const SpecTerm& object) {
  if (object.source == ObjectSource::ego) return kEgo;
  std::optional<ActorId> actor = context.trace.find_actor(object.name);
  if (!actor) throw OracleError(object.location, "the trace has no actor '" + object.name + "'");
  return *actor;
}

const PerceivedActor& perceived_actor(const Context& context, const SpecTerm& object,
                                      ActorId actor) {
  if (actor == kEgo)
    throw OracleError(object.location, "the ego does not perceive itself: use " +
                                           trace_name(context.scenario) + "[ego]");
  for (const PerceivedActor& seen : context.trace.perceived)
    if (seen.actor == actor) return seen;
  throw OracleError(object.location, "the trace holds no perception of '" + object.name + "'");
}

MapPoint placed_point(const Context& context, const SpecTerm& term) {
  if (!term.position) throw OracleError(term.location, "this position term holds no position");
  const Trace& trace = context.trace;
  std::optional<MapPose> ego;
  if (trace.sample_count() > 0 && !trace.actors.empty())
    ego =
        MapPose{{trace.actors[kEgo].x[0], trace.actors[kEgo].y[0]}, trace.actors[kEgo].heading[0]};
  Diagnostics diagnostics;
  std::optional<PlacedPosition> placed =
      place_position(context.map, *term.position, context.source.parameters, ego, diagnostics);
  if (!placed) {
    std::string message = "this position cannot be placed on the map";
    for (const Diagnostic& diagnostic : diagnostics.all())
      if (diagnostic.severity == Severity::error) {
        message = diagnostic.message;
        break;
      }
    throw OracleError(term.location, message);
  }
  return placed->pose.position;
}

std::vector<double> number_values(const Context& context, const SpecTerm& term) {
  std::vector<double> values = term_signal(term, context.source).values;
  for (double value : values)
    if (!std::isfinite(value))
      throw OracleError(term.location, "this number is not finite: " + format_number(value));
  return values;
}

Argument resolve_argument(const Context& context, const std::string& function,
                          const SpecTerm& term) {
  Argument argument;
  switch (term.kind) {
    case TermKind::object:
      argument.kind = Argument::Kind::body;
      argument.actor = object_actor(context, term);
      if (term.source == ObjectSource::perception) {
        argument.perceived = &perceived_actor(context, term, argument.actor);
        if (function == "acc")
          argument.acceleration = perceived_acceleration(context.trace, *argument.perceived);
      }
      return argument;
    case TermKind::position:
      if (function != "dis") break;
      argument.kind = Argument::Kind::point;
      argument.point = placed_point(context, term);
      return argument;
    case TermKind::vector:
      if ((function != "vel" && function != "acc") || term.operands.size() < 2 ||
          term.operands.size() > 3)
        break;
      argument.kind = Argument::Kind::vector;
      argument.first = number_values(context, term.operands[0]);
      argument.second = number_values(context, term.operands[1]);
      if (term.operands.size() == 3) argument.up = number_values(context, term.operands[2]);
      return argument;
    default:
      if (function != "spd") break;
      argument.kind = Argument::Kind::speed;
      argument.first = number_values(context, term);
      return argument;
  }
  const std::string expected = function == "dis"   ? "a trace projection or a position"
                               : function == "spd" ? "a trace projection or a speed"
                               : function == "diff"
                                   ? "a trace projection"
                                   : "a trace projection or a vector (x, y) or (x, y, z)";
  throw OracleError(term.location, function + "(...) takes " + expected + " here");
}

SignalValues distance_signal(const Context& context, const Argument& a, const Argument& b) {
  const Trace& trace = context.trace;
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!perceived_at(a, i) || !perceived_at(b, i)) {
      values[i] = kUnperceived;
    } else if (a.kind == Argument::Kind::point && b.kind == Argument::Kind::point) {
      values[i] = distance(a.point, b.point);
    } else {
      values[i] = std::max(0.0, signed_distance(footprint(trace, a, i), footprint(trace, b, i)));
    }
  }
  return {std::move(values), false};
}

SignalValues velocity_signal(const Context& context, const Argument& a, const Argument& b) {
  std::vector<double> values(context.trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] =
        perceived_at(a, i) && perceived_at(b, i)
            ? std::hypot(norm(velocity(context.trace, a, i) - velocity(context.trace, b, i)),
                         up_at(a, i) - up_at(b, i))
            : kUnperceived;
  return {std::move(values), false};
}

SignalValues speed_signal(const Context& context, const Argument& a, const Argument& b) {
  std::vector<double> values(context.trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = perceived_at(a, i) && perceived_at(b, i)
                    ? speed(context.trace, a, i) - speed(context.trace, b, i)
                    : kUnperceived;
  return {std::move(values), false};
}

bool acceleration_known(const Argument& argument, std::size_t i) {
  return argument.perceived == nullptr || argument.acceleration.known[i];
}

SignalValues acceleration_signal(const Context& context, const Argument& a, const Argument& b) {
  std::vector<double> values(context.trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = acceleration_known(a, i) && acceleration_known(b, i)
                    ? std::hypot(norm(acceleration(context.trace, a, i) -
                                      acceleration(context.trace, b, i)),
                                 up_at(a, i) - up_at(b, i))
                    : kUnperceived;
  return {std::move(values), false};
}

SignalValues perception_error_signal(const Context& context, const SpecTerm& term,
                                     const Argument& seen, const Argument& truth) {
  if (!seen.perceived || truth.perceived || seen.actor != truth.actor)
    throw OracleError(term.location,
                      "diff(...) compares an agent's perceived and true states: "
                      "diff(trace[perception][a], trace[truth][a])");
  const Trace& trace = context.trace;
  const TraceActor& actual = trace.actors[truth.actor];
  constexpr double kMissed =
      (kPositionWeight + kVelocityWeight + kHeadingWeight) * kUnperceived / kWeightSum;
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!seen.perceived->detected[i]) {
      const double from_ego =
          signed_distance(footprint_at(trace, kEgo, i), footprint_at(trace, truth.actor, i));
      values[i] = from_ego < kDiffRange ? kMissed : 0;
      continue;
    }
    const double position_error =
        distance({seen.perceived->x[i], seen.perceived->y[i]}, {actual.x[i], actual.y[i]});
    const double velocity_error = norm(velocity(trace, seen, i) - velocity(trace, truth, i));
    const double heading_error =
        std::abs(angle_difference(seen.perceived->heading[i], actual.heading[i]));
    // The perception reports the true size, so the size error is 0.
    const double size_error = 0;
    values[i] = (kPositionWeight * position_error + kVelocityWeight * velocity_error +
                 kHeadingWeight * heading_error + kSizeWeight * size_error) /
                kWeightSum;
  }
  return {std::move(values), false};
}

SignalValues function_signal(const Context& context, const SpecTerm& term) {
  const Argument a = resolve_argument(context, term.name, term.operands[0]);
  const Argument b = resolve_argument(context, term.name, term.operands[1]);
  if (term.name == "dis") return distance_signal(context, a, b);
  if (term.name == "vel") return velocity_signal(context, a, b);
  if (term.name == "spd") return speed_signal(context, a, b);
  if (term.name == "acc") return acceleration_signal(context, a, b);
  return perception_error_signal(context, term, a, b);
}

SignalValues column_signal(const Context& context, const SpecTerm& term) {
  if (term.operands.size() != 1 || term.operands[0].kind != TermKind::object)
    throw OracleError(term.location, "'." + term.name + "' can only follow a trace projection");
  const SpecTerm& object = term.operands[0];
  const ActorId id = object_actor(context, object);
  if (object.source == ObjectSource::perception) {
    const PerceivedActor& seen = perceived_actor(context, object, id);
    const std::vector<double>* column = term.name == "x"         ? &seen.x
                                        : term.name == "y"       ? &seen.y
                                        : term.name == "heading" ? &seen.heading
                                        : term.name == "speed"   ? &seen.speed
                                                                 : nullptr;
    if (!column)
      throw OracleError(term.location,
                        "the perception gives x, y, heading and speed, not '" + term.name + "'; " +
                            describe_object(context.scenario, ObjectSource::truth, object.name) +
                            "." + term.name + " is the true value");
    auto missed = std::find(seen.detected.begin(), seen.detected.end(), std::uint8_t{0});
    if (missed != seen.detected.end()) {
      const auto sample = static_cast<std::size_t>(missed - seen.detected.begin());
      const std::string text =
          describe_object(context.scenario, object.source, object.name) + "." + term.name;
      throw OracleError(term.location, "'" + text + "' is undefined where " + object.name +
                                           " is not detected (first at t = " +
                                           format_number(context.trace.time[sample]) +
                                           " s); dis(...) and diff(...) have values there");
    }
    return {*column, false};
  }
  const TraceActor& actor = context.trace.actors[id];
  const std::vector<double>* column = term.name == "x"              ? &actor.x
                                      : term.name == "y"            ? &actor.y
                                      : term.name == "heading"      ? &actor.heading
                                      : term.name == "speed"        ? &actor.speed
                                      : term.name == "acceleration" ? &actor.acceleration
                                      : term.name == "yaw_rate"     ? &actor.yaw_rate
                                      : term.name == "s"            ? &actor.s
                                                                    : nullptr;
  if (!column)
    throw OracleError(term.location, "a trace projection has no column '" + term.name +
                                         "'; its columns are " + avunit::trace_column_list());
  return {*column, false};
}

}  // namespace

TraceSignals::TraceSignals(const Trace& trace, const ScenarioTemplate& scenario,
                           std::span<const double> parameters, const RoadMap& map)
    : trace_(trace), scenario_(scenario), parameters_(parameters), map_(map) {}

SignalSource TraceSignals::source() const {
  return {trace_.time, [this](const SpecTerm& term) { return leaf(term); }, parameters_};
}

SignalValues TraceSignals::leaf(const SpecTerm& term) const {
  if (trace_.actors.empty()) throw OracleError(term.location, "the trace has no ego");
  const Context context{trace_, scenario_, map_, source()};
  switch (term.kind) {
    case TermKind::column: return column_signal(context, term);
    case TermKind::signal: {
      const avunit::SignalClass kind = avunit::signal_class(term.name);
      if (kind == avunit::SignalClass::function) {
        if (term.operands.size() == 2) return function_signal(context, term);
        // Without arguments `acc` is scenest's ego acceleration.
        if (term.name == "acc" && term.operands.empty())
          return law_signal(term, trace_, scenario_, parameters_, map_);
        throw OracleError(term.location,
                          term.name + "(...) takes two arguments: " + term.name + "(a, b)");
      }
      if (kind != avunit::SignalClass::none)
        return law_signal(term, trace_, scenario_, parameters_, map_);
      throw OracleError(term.location, "'" + term.name + "' is not a signal of a simulated trace");
    }
    case TermKind::object:
      throw OracleError(term.location,
                        "a trace projection is not a number: use one of its columns (" +
                            describe_object(scenario_, term.source, term.name) +
                            ".speed) or a function such as dis(a, b)");
    default: throw OracleError(term.location, "this is not a signal of a simulated trace");
  }
}

}  // namespace scenfuzz
