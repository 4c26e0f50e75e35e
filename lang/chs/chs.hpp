// The CH-Scenario front end as the rest of scenfuzz sees it: a `.chs` file read into a
// ScenarioTemplate, and a concrete scenario written back as the user's file with the numbers the
// search chose. What every construct means is the contract in docs/ch-scenario.md.
#pragma once

#include <span>
#include <string>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::chs {

struct ScenarioParse {
  ScenarioTemplate scenario;  // complete only when there are no errors
  Diagnostics diagnostics;

  bool ok() const { return !diagnostics.has_errors(); }
};

// Never throws on bad input: every problem is a diagnostic pointing into `file`.
ScenarioParse parse_scenario(const SourceFile& file);

// The user's file with each parameter's number replaced by its value in the file's own unit
// (km/h for speeds, the visibility for the fog it stands for, `HH:MM:SS` for a timestamp's time),
// after `#` lines naming the values. `scenario` must come from parse_scenario(file), possibly
// with a mutation space derived from it (sampler/mutation_space.hpp).
std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values);

}  // namespace scenfuzz::chs
