// Which specs of a scenario the oracle can judge on simulated traces, found before any run: a
// spec that reads a law signal the oracle does not compute (`trafficLightAhead.isBlinking`, ...)
// cannot be judged. `scenfuzz check` lists every such place at once; `run` and the search judge
// the other specs and report these as not judged.
#pragma once

#include <string>
#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz {

// One place where a spec reads a signal the oracle does not compute.
struct UncomputedSignal {
  std::string spec;  // the spec's name
  std::string name;  // the signal's
  SourceLocation location;
  std::string message;  // "the oracle does not compute 'trafficLightAhead.isBlinking' ..."
};

// Every such place in `scenario`'s specs, in spec order, each place once per spec (a named
// formula used twice in a spec is one place).
std::vector<UncomputedSignal> uncomputed_signals(const ScenarioTemplate& scenario);

}  // namespace scenfuzz
