// run_coverage: one pass of behaviour_coverage over the trace, plus the law sub-violations'
// robustness for law specs, from which their features are read.
#include "fuzz/run_coverage.hpp"

#include <algorithm>

#include "oracle/behaviour_coverage.hpp"

namespace scenfuzz {

bool has_coverage(const ScenarioRun& run) {
  if (!run.trace || !run.map || run.trace->sample_count() == 0) return false;
  return !run.trace->ego_failure || is_finding(*run.trace->ego_failure);
}

std::vector<std::string> run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario) {
  return run_coverage(run, scenario, law_sub_violations(scenario)).features;
}

RunCoverage run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario,
                         const std::vector<LawSubViolation>& subs) {
  RunCoverage coverage;
  if (!has_coverage(run)) return coverage;
  coverage.features = behaviour_coverage(*run.trace, *run.map, run.conditions);
  if (subs.empty()) return coverage;
  coverage.law_robustness = law_robustness(subs, scenario, run.values, *run.trace, *run.map);
  const std::vector<std::string> laws = reached_law_features(subs, coverage.law_robustness);
  coverage.features.insert(coverage.features.end(), laws.begin(), laws.end());
  std::sort(coverage.features.begin(), coverage.features.end());
  coverage.features.erase(std::unique(coverage.features.begin(), coverage.features.end()),
                          coverage.features.end());
  return coverage;
}

}  // namespace scenfuzz
