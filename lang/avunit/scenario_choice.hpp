// Which scenario a file's template is built from when the file has several: LawBreaker's scenest
// files may create and execute several (`Trace trace1 = EXE(scenario1);` beside
// `Trace trace2 = EXE(scenario2);`, each with its own specs), and a search, a run or a mutation
// space is about one of them. The caller chooses it by name (`--scenario NAME`).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz::avunit {

// One scenario the file executes (or, in a file that executes none, creates).
struct ScenarioCandidate {
  std::string name;                 // the variable it is bound to, else its first trace's name
  std::vector<std::string> traces;  // the traces that execute it, in file order
  SourceLocation location;          // its first trace's declaration (or its CreateScenario)
};

// What the caller asks for.
struct ScenarioRequest {
  std::string name;      // the scenario to build; empty: the file must have only one
  bool survey = false;   // several without a name are fine (`check`): build the first, and say so
  bool executed = true;  // the candidates are executed ones (false: created, none executed)
};

// The candidates as a user reads them: "scenario1 (trace1), scenario2 (trace2, trace3)".
std::string candidate_list(const std::vector<ScenarioCandidate>& candidates);

// The index of the candidate to build, or nullopt (with an error) when the name is unknown or the
// file has several and none was named. No candidates: nullopt, and an error only if one was named.
std::optional<std::size_t> choose_scenario(const std::vector<ScenarioCandidate>& candidates,
                                           const ScenarioRequest& request,
                                           Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit
