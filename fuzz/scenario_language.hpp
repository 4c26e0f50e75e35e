// Which front end reads a scenario file, by its extension: WMG SDL for `.sdl`, CH-Scenario for
// `.chs`, AVUnit (which also reads scenest) for everything else; and how a concrete scenario is
// written back in that language.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {

bool is_wmg_file(const std::string& path);
// An accident description (`.acc`): reconstructed (`scenfuzz reconstruct`), not searched.
bool is_accident_file(const std::string& path);

struct ScenarioParse {
  ScenarioTemplate scenario;  // complete only when there are no errors
  Diagnostics diagnostics;
  std::vector<std::string> scenarios;  // the file's scenarios by name; `scenario` is one of them

  bool ok() const { return !diagnostics.has_errors(); }
};

// `choice` names the scenario to build (a WMG SDL file has one, named after its scenery).
ScenarioParse parse_scenario_file(const SourceFile& file, const avunit::ParseOptions& choice = {});

// The file with every range replaced by its value, in the file's language.
std::string print_concrete_scenario(const SourceFile& file, const ScenarioTemplate& scenario,
                                    std::span<const double> parameter_values);

// What starts a comment line in the file's language: "# " for WMG SDL and CH-Scenario, "// " for
// AVUnit.
std::string comment_prefix(const std::string& path);

// The extension a concrete scenario of `path` is written with: `.sdl`, `.chs` or `.avu`.
std::string concrete_extension(const std::string& path);

}  // namespace scenfuzz
