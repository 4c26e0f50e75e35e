// The accident formalism's front end as the rest of scenfuzz sees it: a `.acc` description read
// and made a ScenarioTemplate whose search space is the accident's unknowns (each vehicle's speed,
// where it starts, when each of its events begins) and whose expected collisions are the
// described ones. docs/accident.md, "What a description means", is the contract.
#pragma once

#include <string>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::accident {

struct TranslateOptions {
  // The vehicle that is the scenario's ego; empty: the first collision's victim when it is a
  // vehicle, else that collision's actor.
  std::string ego;
};

struct ScenarioParse {
  ScenarioTemplate scenario;  // complete only when there are no errors
  Diagnostics diagnostics;

  bool ok() const { return !diagnostics.has_errors(); }
};

// Never throws on bad input: every problem is a diagnostic pointing into `file`.
ScenarioParse parse_scenario(const SourceFile& file, const TranslateOptions& options = {});

}  // namespace scenfuzz::accident
