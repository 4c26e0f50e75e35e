// Dimension values named by the slot they sit in (parameter_provenance.hpp).
#include "fuzz/parameter_provenance.hpp"

#include <algorithm>
#include <vector>

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

}  // namespace

std::optional<ParameterProvenance> parameter_provenance(const SourceFile& file,
                                                        const ScenarioTemplate& scenario,
                                                        std::span<const double> values,
                                                        std::size_t index) {
  const Parameter& parameter = scenario.parameters[index];
  if (parameter.kind == ParameterKind::discrete || parameter.unit == "time of day") return {};
  const std::optional<Value> slot = slot_of(scenario, index);
  if (!slot || slot->op == ValueOp::parameter) return {};
  ParameterProvenance provenance;
  provenance.value = evaluate(*slot, values);
  provenance.drawn = values[index];
  provenance.location = parameter.location;
  if (parameter.location.end_offset() <= file.text().size())
    provenance.range_text =
        file.text().substr(parameter.location.offset, parameter.location.length);
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

namespace {

// Where the header's dimension lines ("//   name = value") end: the user's text follows, which may
// hold lines that look like them.
std::size_t header_end(const std::string& text) {
  std::size_t at = text.find('\n');
  while (at != std::string::npos && text.compare(at + 1, 5, "//   ") == 0)
    at = text.find('\n', at + 1);
  return at == std::string::npos ? text.size() : at;
}

}  // namespace

std::string with_parameter_provenance(const std::string& concrete, const SourceFile& file,
                                      const ScenarioTemplate& scenario,
                                      std::span<const double> values) {
  std::string text = concrete;
  std::size_t from = 0, end_of_header = header_end(text);
  // The header lists the dimensions in order: search on from the previous one.
  for (std::size_t i = 0; i < scenario.parameters.size() && i < values.size(); ++i) {
    const Parameter& parameter = scenario.parameters[i];
    const std::size_t at = text.find("\n//   " + parameter.name + " = ", from);
    if (at == std::string::npos || at >= end_of_header) break;
    const std::size_t begin = at + 6, end = text.find('\n', begin);
    from = end;
    const std::optional<ParameterProvenance> provenance =
        parameter_provenance(file, scenario, values, i);
    if (!provenance || end == std::string::npos) continue;
    const std::string line = provenance_text(file, parameter, *provenance);
    text.replace(begin, end - begin, line);
    end_of_header = end_of_header + line.size() - (end - begin);
    from = begin + line.size();
  }
  return text;
}

}  // namespace scenfuzz
