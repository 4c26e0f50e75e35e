#include "fuzz/scenario_language.hpp"

#include <filesystem>

#include "lang/avunit/avunit.hpp"
#include "lang/avunit/scenario_choice.hpp"
#include "lang/chs/parser.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz {

bool is_wmg_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".sdl";
}

namespace {

std::string extension_of(const std::string& path) {
  return std::filesystem::path(path).extension().string();
}

// CH-Scenario is read but not yet translated (docs/ch-scenario.md): its mistakes are reported,
// and a file without one is an error too, so that no command takes it for a scenario.
ScenarioParse not_yet_simulated(const SourceFile& file) {
  ScenarioParse result;
  if (extension_of(file.path()) == ".acc") {
    result.diagnostics.error({1, 1, 0, 0},
                             "scenfuzz does not read the accident formalism "
                             "(.acc) yet");
    return result;
  }
  chs::ParseResult parsed = chs::parse(file);
  result.diagnostics = std::move(parsed.diagnostics);
  if (parsed.file)
    result.diagnostics.error({1, 1, 0, 0},
                             "this CH-Scenario file reads without a mistake, but "
                             "scenfuzz cannot simulate CH-Scenario yet "
                             "(docs/ch-scenario.md)");
  return result;
}

}  // namespace

ScenarioParse parse_scenario_file(const SourceFile& file, const avunit::ParseOptions& choice) {
  if (const std::string extension = extension_of(file.path());
      extension == ".chs" || extension == ".acc")
    return not_yet_simulated(file);
  if (is_wmg_file(file.path())) {
    wmg::ParseResult parsed = wmg::parse(file);
    ScenarioParse result{std::move(parsed.scenario), std::move(parsed.diagnostics), {}};
    if (!result.scenario.has_scenario) return result;
    // One scenery, one scenario: a name given must be its own.
    const std::vector<avunit::ScenarioCandidate> only{
        {result.scenario.scenario_name, {}, SourceLocation{1, 1, 0, 0}}};
    result.scenarios.push_back(result.scenario.scenario_name);
    avunit::choose_scenario(only, {choice.scenario, choice.survey, true}, result.diagnostics);
    return result;
  }
  avunit::ParseResult parsed = avunit::parse(file, choice);
  return ScenarioParse{std::move(parsed.scenario), std::move(parsed.diagnostics),
                       std::move(parsed.scenarios)};
}

std::string print_concrete_scenario(const SourceFile& file, const ScenarioTemplate& scenario,
                                    std::span<const double> parameter_values) {
  if (is_wmg_file(file.path())) return wmg::print_concrete(file, scenario, parameter_values);
  return avunit::print_concrete(file, scenario, parameter_values);
}

std::string comment_prefix(const std::string& path) { return is_wmg_file(path) ? "# " : "// "; }

std::string concrete_extension(const std::string& path) {
  return is_wmg_file(path) ? ".sdl" : ".avu";
}

}  // namespace scenfuzz
