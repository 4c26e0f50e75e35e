// A concrete CH-Scenario (chs.hpp): the user's text with each searched number replaced. The IR
// holds SI values, so each number is written back in the unit of the field it sits in, found by
// reading the file again; a vehicle's point the translation read as a lane place (lane_places.hpp)
// is written back as the point of the place the search chose.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "lang/chs/chs.hpp"
#include "lang/chs/lane_places.hpp"
#include "lang/chs/parser.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::chs {

namespace {

enum class Unit { as_written, kilometres_per_hour, visibility, time_of_day };

// The fields whose number the IR holds in another unit, by the number's byte offset.
std::map<std::uint32_t, Unit> units_by_offset(const ParseResult& parsed) {
  std::map<std::uint32_t, Unit> units;
  if (!parsed.file) return units;
  for (const DynamicEntity& entity : parsed.file->dynamic_entities)
    units[entity.speed.location.offset] = Unit::kilometres_per_hour;
  units[parsed.file->weather.visibility.location.offset] = Unit::visibility;
  return units;
}

// Fixed notation, shortest text that reads back: the reader takes no exponent.
std::string plain_number(double value) {
  const std::string text = format_number(value);
  if (text.find_first_of("eE") == std::string::npos) return text;
  char buffer[400];
  auto [end, error] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  return error == std::errc() ? std::string(buffer, end) : "0";
}

std::string time_text(double seconds) {
  const long total = std::lround(std::clamp(seconds, 0.0, 86399.0));
  auto two = [](long v) { return (v < 10 ? "0" : "") + std::to_string(v); };
  return two(total / 3600) + ":" + two(total / 60 % 60) + ":" + two(total % 60);
}

std::string value_text(const Parameter& parameter, double value, Unit unit) {
  if (parameter.unit == "time of day") return time_text(value);
  switch (unit) {
    case Unit::kilometres_per_hour: return plain_number(value * 3.6);
    case Unit::visibility: return plain_number(1 - value);
    default: return plain_number(value);
  }
}

// The text that replaces the number at each byte offset, and how long the number is.
using Replacements = std::map<std::uint32_t, std::pair<std::uint32_t, std::string>>;

// The written points of `file` that stand for a vehicle's lane place in `scenario`, by the offset
// of their x (where the place's arc length stands).
std::map<std::uint32_t, const Position*> lane_places_by_x(const ScenarioTemplate& scenario) {
  std::map<std::uint32_t, const Position*> places;
  auto add = [&](const Actor& actor) {
    const Position& position = actor.initial.position;
    if (position.kind == PositionKind::lane && position.lateral && position.s.location.known())
      places.emplace(position.s.location.offset, &position);
  };
  add(scenario.ego);
  for (const Actor& vehicle : scenario.vehicles) add(vehicle);
  return places;
}

// Each point read as a lane place whose arc length or offset the search chose, written back as
// the point of the place chosen.
void replace_lane_points(const File& file, const ScenarioTemplate& scenario,
                         std::span<const double> values, Replacements& replacements) {
  const std::map<std::uint32_t, const Position*> places = lane_places_by_x(scenario);
  auto replace_point = [&](const Point& point) {
    const auto found = places.find(point.x_at.offset);
    if (found == places.end() || !point.x_at.known()) return;
    const Position& position = *found->second;
    std::optional<LanePlace> place = lane_place_at(file.roads, point.x, point.y);
    if (!place || (is_constant(position.s) && is_constant(*position.lateral))) return;
    place->s = evaluate(position.s, values);
    place->lateral = evaluate(*position.lateral, values);
    const PlanePoint moved = point_of(*place);
    replacements[point.x_at.offset] = {point.x_at.length, plain_number(moved.x)};
    replacements[point.y_at.offset] = {point.y_at.length, plain_number(moved.y)};
  };
  for (const DynamicEntity& entity : file.dynamic_entities)
    if (entity.position) replace_point(*entity.position);
  for (const StaticEntity& entity : file.static_entities)
    if (entity.position) replace_point(*entity.position);
}

// The `#` lines naming each value chosen; an event's outcome with its probability, and the
// probability of all the outcomes chosen together.
std::string header(const SourceFile& file, const ParseResult& parsed,
                   const ScenarioTemplate& scenario, std::span<const double> values) {
  std::map<std::uint32_t, double> probabilities;  // by the offset of the probability's number
  if (parsed.file)
    for (const Constraint& constraint : parsed.file->constraints)
      for (const Event& event : constraint.events)
        probabilities[event.probability.location.offset] = event.probability.value;
  std::string text = "# concrete scenario of " + file.path() + " chosen by scenfuzz:\n";
  double together = 1;
  bool any_event = false;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i) {
    const Parameter& parameter = scenario.parameters[i];
    const auto p = probabilities.find(parameter.location.offset);
    if (parameter.event_outcome && p != probabilities.end()) {
      const bool fires = values[i] >= 0.5;
      text += "#   " + parameter.name + " = " + (fires ? "fires" : "does not fire") +
              " (probability " + format_number(fires ? p->second : 1 - p->second) + ")\n";
      together *= fires ? p->second : 1 - p->second;
      any_event = true;
      continue;
    }
    text +=
        "#   " + parameter.name + " = " + value_text(parameter, values[i], Unit::as_written) +
        (parameter.unit.empty() || parameter.unit == "time of day" ? "" : " " + parameter.unit) +
        "\n";
  }
  if (any_event)
    text += "# the events' outcomes chosen have probability " + format_number(together) +
            " together: at least the failure's, if it needs them\n";
  return text;
}

}  // namespace

std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values) {
  SCENFUZZ_DEMAND(parameter_values.size() == scenario.parameters.size());
  const ParseResult parsed = parse(file);
  const std::map<std::uint32_t, Unit> units = units_by_offset(parsed);
  auto unit_at = [&](const Parameter& parameter) {
    auto found = units.find(parameter.location.offset);
    return found == units.end() ? Unit::as_written : found->second;
  };
  Replacements replacements;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i) {
    const Parameter& parameter = scenario.parameters[i];
    if (parameter.location.known())
      replacements.emplace(
          parameter.location.offset,
          std::pair{parameter.location.length,
                    value_text(parameter, parameter_values[i], unit_at(parameter))});
  }
  if (parsed.file) replace_lane_points(*parsed.file, scenario, parameter_values, replacements);
  std::string text = file.text();
  for (auto it = replacements.rbegin(); it != replacements.rend(); ++it)
    if (it->first + it->second.first <= text.size())
      text.replace(it->first, it->second.first, it->second.second);
  return header(file, parsed, scenario, parameter_values) + text;
}

}  // namespace scenfuzz::chs
