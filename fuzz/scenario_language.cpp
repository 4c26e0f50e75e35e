#include "fuzz/scenario_language.hpp"

#include <filesystem>

#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz {

bool is_wmg_file(const std::string& path) {
  return std::filesystem::path(path).extension() == ".sdl";
}

ScenarioParse parse_scenario_file(const SourceFile& file) {
  if (is_wmg_file(file.path())) {
    wmg::ParseResult parsed = wmg::parse(file);
    return ScenarioParse{std::move(parsed.scenario), std::move(parsed.diagnostics)};
  }
  avunit::ParseResult parsed = avunit::parse(file);
  return ScenarioParse{std::move(parsed.scenario), std::move(parsed.diagnostics)};
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
