// Specs set aside before a search because the oracle cannot judge them.
#include "fuzz/not_judged_specs.hpp"

#include <algorithm>

#include "oracle/spec_judgeable.hpp"

namespace scenfuzz {

Diagnostics uncomputed_signal_warnings(const ScenarioTemplate& scenario) {
  Diagnostics warnings;
  for (const UncomputedSignal& place : uncomputed_signals(scenario))
    warnings.warning(place.location,
                     place.message + ": spec '" + place.spec + "' will not be judged");
  return warnings;
}

std::vector<NotJudgedSpec> set_aside_unjudgeable_specs(ScenarioTemplate& scenario,
                                                       const std::string& path) {
  const std::vector<UncomputedSignal> places = uncomputed_signals(scenario);
  std::vector<NotJudgedSpec> aside;
  for (const UncomputedSignal& place : places) {
    if (std::any_of(aside.begin(), aside.end(),
                    [&](const NotJudgedSpec& spec) { return spec.name == place.spec; }))
      continue;
    aside.push_back({place.spec, path + ":" + std::to_string(place.location.line) + ":" +
                                     std::to_string(place.location.column) + ": " + place.message});
  }
  std::erase_if(scenario.specs, [&](const Spec& spec) {
    return std::any_of(aside.begin(), aside.end(),
                       [&](const NotJudgedSpec& set) { return set.name == spec.name; });
  });
  return aside;
}

}  // namespace scenfuzz
