#include "fuzz/scenario_language.hpp"

#include <filesystem>

#include "lang/accident/accident.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/avunit/scenario_choice.hpp"
#include "lang/chs/chs.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz {

bool is_wmg_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".sdl";
}

bool is_accident_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".acc";
}

namespace {

std::string extension_of(const std::string& path) {
  return std::filesystem::path(path).extension().string();
}

bool is_chs_file(const std::string& path) { return extension_of(path) == ".chs"; }

}  // namespace

ScenarioParse parse_scenario_file(const SourceFile& file, const avunit::ParseOptions& choice) {
  if (is_accident_file(file.path())) {
    accident::ScenarioParse parsed = accident::parse_scenario(file);
    ScenarioParse result{std::move(parsed.scenario), std::move(parsed.diagnostics), {}};
    result.scenarios.push_back(result.scenario.scenario_name);
    return result;
  }
  if (is_chs_file(file.path())) {
    chs::ScenarioParse parsed = chs::parse_scenario(file);
    ScenarioParse result{std::move(parsed.scenario), std::move(parsed.diagnostics), {}};
    result.scenarios.push_back(result.scenario.scenario_name);
    return result;
  }
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
  if (is_chs_file(file.path())) return chs::print_concrete(file, scenario, parameter_values);
  return avunit::print_concrete(file, scenario, parameter_values);
}

std::string comment_prefix(const std::string& path) {
  return is_wmg_file(path) || is_chs_file(path) ? "# " : "// ";
}

std::string concrete_extension(const std::string& path) {
  if (is_chs_file(path)) return ".chs";
  return is_wmg_file(path) ? ".sdl" : ".avu";
}

}  // namespace scenfuzz
