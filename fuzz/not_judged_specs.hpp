// The specs of a file that the oracle cannot judge on simulated traces (they read a signal it
// does not compute, oracle/spec_judgeable.hpp): `check` lists every place at once, the search
// sets those specs aside and targets the others, saying which were not judged and why.
#pragma once

#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz {

struct NotJudgedSpec {
  std::string name;
  std::string reason;  // "file:9:3: the oracle does not compute 'hornOn' on simulated traces yet"
};

// A warning at every place a spec reads a signal the oracle does not compute.
Diagnostics uncomputed_signal_warnings(const ScenarioTemplate& scenario);

// Removes from `scenario` the specs that cannot be judged and returns them, each with its first
// reason placed in `path`.
std::vector<NotJudgedSpec> set_aside_unjudgeable_specs(ScenarioTemplate& scenario,
                                                       const std::string& path);

}  // namespace scenfuzz
