// Dimension values named by the slot they sit in (parameter_provenance.hpp).
#include "lang/parameter_provenance.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/value.hpp"
#include "lang/walk_values.hpp"

namespace scenfuzz {
namespace {

bool reads(const Value& value, int parameter) {
  std::vector<int> read;
  collect_parameters(value, read);
  return std::find(read.begin(), read.end(), parameter) != read.end();
}

// The first slot at the parameter's path that reads it.
std::optional<Value> slot_of(const ScenarioTemplate& scenario, std::size_t index) {
  const Parameter& parameter = scenario.parameters[index];
  std::optional<Value> slot;
  for_each_value(scenario, [&](const Value& value, const std::string& path, const std::string&) {
    if (!slot && path == parameter.name && reads(value, static_cast<int>(index))) slot = value;
  });
  return slot;
}

// The range's text on one line: it is shown in a line comment, which a line break would end
// (`range(-3,\n 3)` would leave `3)` outside the comment, and the concrete file unreadable).
std::string one_line(std::string_view text) {
  std::string line;
  bool space = false;
  for (char c : text) {
    const bool blank = c == ' ' || c == '\t' || c == '\n' || c == '\r';
    if (blank && !line.empty()) space = true;
    if (blank) continue;
    if (space) line += ' ';
    space = false;
    line += c;
  }
  return line;
}

}  // namespace

std::optional<ParameterProvenance> parameter_provenance(const SourceFile& file,
                                                        const ScenarioTemplate& scenario,
                                                        std::span<const double> values,
                                                        std::size_t index) {
  SCENFUZZ_DEMAND(values.size() == scenario.parameters.size() && index < values.size());
  const Parameter& parameter = scenario.parameters[index];
  if (parameter.kind == ParameterKind::discrete || parameter.unit == "time of day") return {};
  const std::optional<Value> slot = slot_of(scenario, index);
  if (!slot || slot->op == ValueOp::parameter) return {};
  ParameterProvenance provenance;
  provenance.value = evaluate(*slot, values);
  provenance.drawn = values[index];
  provenance.location = parameter.location;
  if (parameter.location.end_offset() <= file.text().size())
    provenance.range_text = one_line(
        std::string_view(file.text()).substr(parameter.location.offset, parameter.location.length));
  return provenance;
}

std::string provenance_text(const SourceFile& file, const Parameter& parameter,
                            const ParameterProvenance& provenance) {
  const std::string unit = parameter.unit.empty() ? "" : " " + parameter.unit;
  std::string text = parameter.name + " = " + format_number(provenance.value) + unit + ", where " +
                     (provenance.range_text.empty() ? "its range" : provenance.range_text) +
                     " drew " + format_number(provenance.drawn);
  if (provenance.location.known())
    text += " (" + file.path() + ":" + std::to_string(provenance.location.line) + ":" +
            std::to_string(provenance.location.column) + ")";
  return text;
}

std::string parameter_value_text(const SourceFile& file, const ScenarioTemplate& scenario,
                                 std::span<const double> values, std::size_t index) {
  const Parameter& parameter = scenario.parameters[index];
  if (auto provenance = parameter_provenance(file, scenario, values, index))
    return provenance_text(file, parameter, *provenance);
  const bool time = parameter.unit == "time of day";
  return parameter.name + " = " +
         (time ? format_time_of_day(values[index]) : format_number(values[index])) +
         (parameter.unit.empty() || time ? "" : " " + parameter.unit);
}

}  // namespace scenfuzz
