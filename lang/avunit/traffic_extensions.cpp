#include "lang/avunit/traffic_extensions.hpp"

#include <cmath>

#include "lang/number_format.hpp"

namespace scenfuzz::avunit {

namespace {

const char* const kFlowForm =
    "Flow(\"source_lane\", rate, speed) or Flow(\"source_lane\", rate, speed, "
    "\"destination_lane\")";

std::string counted_arguments(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " argument" : " arguments");
}

// How an unevaluated argument is named in messages.
std::string describe_syntax(const Syntax& syntax) {
  switch (syntax.kind) {
    case SyntaxKind::identifier: return "'" + syntax.text + "'";
    case SyntaxKind::string: return "string \"" + syntax.text + "\"";
    case SyntaxKind::number: return "number '" + syntax.text + "'";
    case SyntaxKind::call: return "'" + syntax.text + "(...)'";
    case SyntaxKind::empty: return "nothing";
    default: return "an expression";
  }
}

std::optional<std::string> lane_argument(const Item& item, const std::string& what,
                                         Diagnostics& diagnostics) {
  if (item.kind != ItemKind::string) {
    diagnostics.error(item.location,
                      "expected " + what + " id in quotes in Flow(...), found " + describe(item));
    return std::nullopt;
  }
  if (item.word.empty()) {
    diagnostics.error(item.location, "a lane id cannot be empty");
    return std::nullopt;
  }
  return item.word;
}

// "found 5" for a constant, "but it can reach 5" for a value that reads a range.
std::string reaches(const Value& value, double extreme) {
  return (is_constant(value) ? "found " : "but it can reach ") + format_number(extreme);
}

// The flow's rate (vehicles per hour) or speed (m/s): a number, possibly read from ranges, that
// stays finite and within what each means over all the ranges' values.
std::optional<Value> flow_amount(const Item& item, bool is_rate,
                                 std::span<const Parameter> parameters, Diagnostics& diagnostics) {
  const std::string what = is_rate ? "a flow's rate" : "a flow's speed";
  if (item.kind != ItemKind::number) {
    diagnostics.error(item.location,
                      std::string("expected ") +
                          (is_rate ? "a rate in vehicles per hour" : "a speed in m/s") +
                          " in Flow(...), found " + describe(item));
    return std::nullopt;
  }
  const ValueRange range = value_range(item.value, parameters);
  std::string problem;
  if (!std::isfinite(range.lower) || !std::isfinite(range.upper))
    problem = what + " must be finite, but it is unbounded";
  else if (range.lower < 0.0)
    problem = what + " cannot be negative, " + reaches(item.value, range.lower);
  else if (!is_rate && range.lower == 0.0)
    problem =
        what + " must be above 0 m/s (its vehicles must move), " + reaches(item.value, range.lower);
  else if (is_rate && range.upper > kMostVehiclesPerHour)
    problem = what + " cannot be above " + format_number(kMostVehiclesPerHour) +
              " vehicles per hour (one vehicle per second per lane), " +
              reaches(item.value, range.upper);
  if (!problem.empty()) {
    diagnostics.error(item.location, problem);
    return std::nullopt;
  }
  return item.value;
}

}  // namespace

std::optional<NpcBehaviour> elaborate_npc_behaviour(const Syntax& call, Diagnostics& diagnostics) {
  const std::string accepted = "NPCBehaviour(scripted) or NPCBehaviour(reactive)";
  if (call.children.size() != 1 || call.children[0].kind == SyntaxKind::empty) {
    diagnostics.error(call.location, "NPCBehaviour(...) takes one word: " + accepted + ", found " +
                                         counted_arguments(call.children.size()));
    return std::nullopt;
  }
  const Syntax& argument = call.children[0];
  // The word is read as written, quoted or not: it names a behaviour, not a variable.
  if (argument.kind == SyntaxKind::identifier || argument.kind == SyntaxKind::string) {
    if (argument.text == "scripted") return NpcBehaviour::scripted;
    if (argument.text == "reactive") return NpcBehaviour::reactive;
  }
  diagnostics.error(argument.location,
                    "expected scripted or reactive in NPCBehaviour(...), found " +
                        describe_syntax(argument) + ": write " + accepted);
  return std::nullopt;
}

std::optional<TrafficLightSetting> elaborate_traffic_light(const Syntax& call,
                                                           Diagnostics& diagnostics) {
  const std::string form = "TrafficLight(\"light_id\", red), with red, yellow or green";
  if (call.children.size() != 2 || call.children[0].kind == SyntaxKind::empty ||
      call.children[1].kind == SyntaxKind::empty) {
    diagnostics.error(call.location, "TrafficLight(...) takes a light's id and a colour: " + form +
                                         ", found " + counted_arguments(call.children.size()));
    return std::nullopt;
  }
  const Syntax& id = call.children[0];
  if (id.kind != SyntaxKind::string || id.text.empty()) {
    diagnostics.error(id.location,
                      "expected the map's traffic-light id in quotes in "
                      "TrafficLight(...), found " +
                          describe_syntax(id));
    return std::nullopt;
  }
  const Syntax& colour = call.children[1];
  const bool word = colour.kind == SyntaxKind::identifier || colour.kind == SyntaxKind::string;
  if (!word || (colour.text != "red" && colour.text != "yellow" && colour.text != "green")) {
    diagnostics.error(
        colour.location,
        "expected red, yellow or green in TrafficLight(...), found " + describe_syntax(colour));
    return std::nullopt;
  }
  TrafficLightSetting light;
  light.id = id.text;
  light.color = colour.text;
  light.location = call.location;
  return light;
}

std::optional<TrafficFlow> elaborate_flow(const Syntax& call, const std::vector<Item>& arguments,
                                          std::span<const Parameter> parameters,
                                          Diagnostics& diagnostics) {
  if (arguments.size() < 3 || arguments.size() > 4) {
    diagnostics.error(call.location, std::string("Flow(...) expects ") + kFlowForm + ", found " +
                                         counted_arguments(arguments.size()));
    return std::nullopt;
  }
  TrafficFlow flow;
  flow.location = call.location;
  std::optional<std::string> source = lane_argument(arguments[0], "the source lane", diagnostics);
  if (!source) return std::nullopt;
  flow.source_lane = std::move(*source);
  std::optional<Value> rate = flow_amount(arguments[1], true, parameters, diagnostics);
  if (!rate) return std::nullopt;
  flow.rate = std::move(*rate);
  std::optional<Value> speed = flow_amount(arguments[2], false, parameters, diagnostics);
  if (!speed) return std::nullopt;
  flow.speed = std::move(*speed);
  // A left-out destination (`Flow("a", 600, 12, )`) is no destination, as for Vehicle(...).
  if (arguments.size() == 4 && arguments[3].kind != ItemKind::empty) {
    std::optional<std::string> destination =
        lane_argument(arguments[3], "the destination lane", diagnostics);
    if (!destination) return std::nullopt;
    flow.destination_lane = std::move(*destination);
  }
  return flow;
}

std::string npc_behaviour_word(NpcBehaviour behaviour) {
  return behaviour == NpcBehaviour::scripted ? "scripted" : "reactive";
}

}  // namespace scenfuzz::avunit
