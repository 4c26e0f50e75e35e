// A concrete CH-Scenario (chs.hpp): the user's text with each searched number replaced. The IR
// holds SI values, so each number is written back in the unit of the field it sits in, found by
// reading the file again.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "lang/chs/chs.hpp"
#include "lang/chs/parser.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::chs {

namespace {

enum class Unit { as_written, kilometres_per_hour, visibility, time_of_day };

// The fields whose number the IR holds in another unit, by the number's byte offset.
std::map<std::uint32_t, Unit> units_by_offset(const SourceFile& file) {
  std::map<std::uint32_t, Unit> units;
  const ParseResult parsed = parse(file);
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

}  // namespace

std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values) {
  SCENFUZZ_DEMAND(parameter_values.size() == scenario.parameters.size());
  const std::map<std::uint32_t, Unit> units = units_by_offset(file);
  auto unit_at = [&](const Parameter& parameter) {
    auto found = units.find(parameter.location.offset);
    return found == units.end() ? Unit::as_written : found->second;
  };
  std::map<std::uint32_t, std::size_t> by_offset;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].location.known())
      by_offset.emplace(scenario.parameters[i].location.offset, i);
  std::string text = file.text();
  for (auto it = by_offset.rbegin(); it != by_offset.rend(); ++it) {
    const Parameter& parameter = scenario.parameters[it->second];
    if (parameter.location.end_offset() <= text.size())
      text.replace(parameter.location.offset, parameter.location.length,
                   value_text(parameter, parameter_values[it->second], unit_at(parameter)));
  }
  std::string header = "# concrete scenario of " + file.path() + " chosen by scenfuzz:\n";
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i) {
    const Parameter& parameter = scenario.parameters[i];
    header +=
        "#   " + parameter.name + " = " +
        value_text(parameter, parameter_values[i], Unit::as_written) +
        (parameter.unit.empty() || parameter.unit == "time of day" ? "" : " " + parameter.unit) +
        "\n";
  }
  return header + text;
}

}  // namespace scenfuzz::chs
