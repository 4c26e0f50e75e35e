// `scenfuzz space FILE [--json]`: show the search space a logical scenario defines, or the one the
// search derives around a concrete scenario's values.
#include <algorithm>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/options.hpp"
#include "fuzz/scenario_language.hpp"
#include "lang/diagnostic.hpp"
#include "lang/number_format.hpp"
#include "sampler/mutation_space.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {

namespace {

// Times of day read best as times, every other bound as the shortest exact number.
std::string format_bound(const Dimension& dimension, double value) {
  return dimension.unit == "time of day" ? format_time_of_day(value) : format_number(value);
}

std::string format_location(const SourceLocation& location) {
  if (!location.known()) return "-";
  return std::to_string(location.line) + ":" + std::to_string(location.column);
}

std::string join_choices(const std::vector<std::string>& choices) {
  std::string text;
  for (const std::string& choice : choices) {
    if (!text.empty()) text += ", ";
    text += choice;
  }
  return text;
}

// Derived around a concrete file's values; an event's outcome (CH-Scenario) has no such value.
bool is_derived(const ParameterSpace& space) {
  return std::any_of(space.dimensions.begin(), space.dimensions.end(),
                     [](const Dimension& d) { return d.origin.has_value(); });
}

void print_table(const ScenarioTemplate& scenario, const ParameterSpace& space, std::ostream& out) {
  if (!scenario.has_scenario) {
    out << "no scenario: the file only defines values (no CreateScenario), so there is nothing "
           "to search\n";
    return;
  }
  if (space.dimensions.empty()) {
    out << "no parameters: the scenario is concrete and none of its values is mutated (--mutate)\n";
    return;
  }
  const bool derived = is_derived(space);
  if (derived)
    out << "derived: the file has no ranges, so the search mutates its values within these "
           "bounds (--mutate; docs/search.md)\n";
  bool any_discrete = false;
  for (const Dimension& d : space.dimensions)
    any_discrete = any_discrete || d.kind == ParameterKind::discrete;

  using Row = std::vector<std::string>;
  std::vector<Row> rows;
  Row header = {"name", "kind", "lower", "upper", "unit", "line"};
  if (derived) header.insert(header.begin() + 2, "value");
  if (any_discrete) header.push_back("choices");
  rows.push_back(header);
  for (const Dimension& d : space.dimensions) {
    Row row = {d.name,
               std::string(kind_name(d.kind)),
               format_bound(d, d.lower),
               format_bound(d, d.upper),
               d.unit.empty() ? "-" : d.unit,
               format_location(d.location)};
    if (derived) row.insert(row.begin() + 2, d.origin ? format_bound(d, *d.origin) : "-");
    if (any_discrete) row.push_back(join_choices(d.choices));
    rows.push_back(std::move(row));
  }

  std::vector<std::size_t> widths(header.size(), 0);
  for (const Row& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());

  // Numbers (value, lower, upper) are right-aligned, text left-aligned; no trailing blanks.
  const std::size_t first_number = 2, last_number = derived ? 4 : 3;
  for (const Row& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string padding(widths[c] - row[c].size(), ' ');
      if (c > 0) line += "  ";
      if (c >= first_number && c <= last_number)
        line += padding + row[c];
      else
        line += row[c] + (c + 1 < row.size() ? padding : "");
    }
    out << line << "\n";
  }
}

void print_json(const std::string& path, const ParameterSpace& space, std::ostream& out) {
  nlohmann::ordered_json dimensions = nlohmann::ordered_json::array();
  for (const Dimension& d : space.dimensions) {
    nlohmann::ordered_json entry;
    entry["name"] = d.name;
    entry["kind"] = std::string(kind_name(d.kind));
    if (d.origin) entry["value"] = *d.origin;
    entry["lower"] = d.lower;
    entry["upper"] = d.upper;
    entry["unit"] = d.unit;
    if (d.kind == ParameterKind::discrete) entry["choices"] = d.choices;
    if (d.location.known()) {
      entry["line"] = d.location.line;
      entry["column"] = d.location.column;
    } else {
      entry["line"] = nullptr;
      entry["column"] = nullptr;
    }
    dimensions.push_back(std::move(entry));
  }
  nlohmann::ordered_json document;
  document["file"] = path;
  document["derived"] = is_derived(space);
  document["dimensions"] = std::move(dimensions);
  // Invalid UTF-8 (a file name, a choice) is replaced rather than thrown on.
  out << document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
}

}  // namespace

int run_space(const std::string& path, bool json, const MutationCommandOptions& mutation,
              const ScenarioChoiceOptions& choice, std::ostream& out, std::ostream& err) {
  const MutationSizesOrError sizes = mutation_sizes(mutation);
  if (!sizes.error.empty()) {
    err << "scenfuzz: error: " << sizes.error << "\n";
    return kExitUsage;
  }
  std::optional<SourceFile> file = read_input(path, err);
  if (!file) return kExitBadInput;
  ScenarioParse result = parse_scenario_file(*file, avunit::ParseOptions{choice.scenario, false});
  err << format_diagnostics(*file, result.diagnostics);
  if (!result.ok()) return kExitBadInput;
  if (searched_by_mutation(result.scenario))
    result.scenario = derive_mutation_space(result.scenario, sizes.sizes);

  const ParameterSpace space = parameter_space(result.scenario);
  if (json)
    print_json(path, space, out);
  else
    print_table(result.scenario, space, out);
  return kExitSuccess;
}

}  // namespace scenfuzz
