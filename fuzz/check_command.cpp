// `scenfuzz check FILE...`: parse files and report what is wrong with them.
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/not_judged_specs.hpp"
#include "fuzz/scenario_language.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz {

std::optional<SourceFile> read_input(const std::string& path, std::ostream& err) {
  errno = 0;
  std::optional<SourceFile> file = read_source_file(path);
  if (!file) {
    const int error = errno;
    err << "scenfuzz: error: cannot read '" << path
        << "': " << (error != 0 ? std::strerror(error) : "read failed") << "\n";
  }
  return file;
}

std::optional<ScenarioFile> read_scenario(const std::string& path, const std::string& purpose,
                                          std::ostream& err, const ScenarioChoiceOptions& choice) {
  std::optional<SourceFile> file = read_input(path, err);
  if (!file) return std::nullopt;
  ScenarioParse parsed = parse_scenario_file(*file, avunit::ParseOptions{choice.scenario, false});
  err << format_diagnostics(*file, parsed.diagnostics);
  if (!parsed.ok()) return std::nullopt;
  if (!parsed.scenario.has_scenario) {
    err << "scenfuzz: error: '" << path << "' builds no scenario (no CreateScenario): nothing to "
        << purpose << "\n";
    return std::nullopt;
  }
  return ScenarioFile{std::move(*file), std::move(parsed.scenario)};
}

int run_check(const std::vector<std::string>& paths, const ScenarioChoiceOptions& choice,
              std::ostream& err) {
  bool failed = false;
  for (const std::string& path : paths) {
    std::optional<SourceFile> file = read_input(path, err);
    if (!file) {
      failed = true;
      continue;
    }
    // Without --scenario, a file executing several scenarios checks every one and lists them.
    const ScenarioParse result =
        parse_scenario_file(*file, avunit::ParseOptions{choice.scenario, /*survey=*/true});
    err << format_diagnostics(*file, result.diagnostics);
    if (!result.ok()) failed = true;
    // Every place a spec reads a signal the oracle does not compute, at once: the file is
    // good, but `run` and the search will not judge those specs.
    else
      err << format_diagnostics(*file, uncomputed_signal_warnings(result.scenario));
  }
  return failed ? kExitBadInput : kExitSuccess;
}

}  // namespace scenfuzz
