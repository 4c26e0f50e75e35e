// run_coverage: one pass of behaviour_coverage over the trace, plus law_coverage for law specs.
#include "fuzz/run_coverage.hpp"

#include <algorithm>

#include "oracle/behaviour_coverage.hpp"
#include "oracle/law_coverage.hpp"

namespace scenfuzz {

bool has_coverage(const ScenarioRun& run) {
  if (!run.trace || !run.map || run.trace->sample_count() == 0) return false;
  return !run.trace->ego_failure || is_finding(*run.trace->ego_failure);
}

std::vector<std::string> run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario) {
  if (!has_coverage(run)) return {};
  std::vector<std::string> features = behaviour_coverage(*run.trace, *run.map, run.conditions);
  const std::vector<std::string> laws = law_coverage(scenario, run.values, *run.trace, *run.map);
  if (laws.empty()) return features;
  features.insert(features.end(), laws.begin(), laws.end());
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  return features;
}

}  // namespace scenfuzz
