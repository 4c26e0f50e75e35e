// A concrete scenario written back as WMG SDL level 2: every range's text replaced by its value.
#include <cmath>
#include <map>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/printer_parts.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz::wmg {

namespace {

// Level 2 writes times as HH:MM, so a time of day is rounded to the minute.
std::string time_text(double seconds) {
  const long minutes = std::lround(seconds / 60);
  auto two_digits = [](long value) { return (value < 10 ? "0" : "") + std::to_string(value); };
  return two_digits(minutes / 60) + ":" + two_digits(minutes % 60);
}

std::string value_text(const Parameter& parameter, double value) {
  if (parameter.unit == "time of day") return time_text(value);
  // The language has no exponent: fixed notation, shortest text that reads back.
  const std::string text = format_number(value);
  return text.find_first_of("eE") == std::string::npos ? text : detail::number_text(value);
}

// `text` with each parameter's span replaced by its value, after `#` lines naming the values.
std::string replace_ranges(std::string text, const std::string& heading,
                           const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values) {
  std::map<std::uint32_t, std::size_t> by_offset;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].location.known())
      by_offset.emplace(scenario.parameters[i].location.offset, i);
  for (auto it = by_offset.rbegin(); it != by_offset.rend(); ++it) {
    const Parameter& parameter = scenario.parameters[it->second];
    if (parameter.location.end_offset() <= text.size())
      text.replace(parameter.location.offset, parameter.location.length,
                   value_text(parameter, parameter_values[it->second]));
  }
  // Each line names the draw itself: WMG SDL has no arithmetic, so a range stands alone and its
  // draw, in the file's unit, is the value of what the user wrote. (The IR does wrap it in unit
  // conversions, oktas / 8, which are not the user's: no parameter_provenance here.)
  std::string header = heading;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i) {
    const Parameter& parameter = scenario.parameters[i];
    const bool time = parameter.unit == "time of day";
    header += "#   " + parameter.name + " = " + value_text(parameter, parameter_values[i]) +
              (parameter.unit.empty() || time ? "" : " " + parameter.unit) + "\n";
  }
  return header + text;
}

}  // namespace

std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values) {
  SCENFUZZ_DEMAND(parameter_values.size() == scenario.parameters.size());
  if (detect_wmg_level(file) == 2)
    return replace_ranges(file.text(),
                          "# concrete scenario of " + file.path() + " chosen by scenfuzz:\n",
                          scenario, parameter_values);
  // A level-1 file has no numbers: its level-2 conversion has the ranges, and translating that
  // text gives the same parameters in the same order, located in that text.
  const Level2Text converted = level2_text(file);
  const SourceFile level2(file.path(), converted.text);
  const ParseResult reparsed = parse(level2);
  const std::string heading = "# concrete scenario of the level-1 file " + file.path() +
                              " chosen by scenfuzz, written as the level-2 text it converts to\n"
                              "# (level 1 has no numbers to replace):\n";
  if (!reparsed.ok() || reparsed.scenario.parameters.size() != parameter_values.size())
    return replace_ranges(converted.text,
                          heading + "# (its ranges could not be matched with the values)\n",
                          ScenarioTemplate{}, {});
  return replace_ranges(converted.text, heading, reparsed.scenario, parameter_values);
}

}  // namespace scenfuzz::wmg
