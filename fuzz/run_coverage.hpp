// The behaviour-coverage features (docs/coverage.md) of one run a ScenarioEvaluator simulated:
// oracle/behaviour_coverage's families and the law sub-violations of the scenario's law specs.
// The search keeps them per evaluation (Evaluation::coverage, summary.json's "coverage") and the
// corpus tools per seed (seed_coverage.hpp), so both name exactly the same features.
#pragma once

#include <string>
#include <vector>

#include "fuzz/scenario_evaluator.hpp"
#include "lang/scenario.hpp"
#include "oracle/law_coverage.hpp"

namespace scenfuzz {

// Whether `run` left a trace whose features can be read: simulated, with samples, and not cut
// short by an ego plugin that could not even start (that drove nothing: the plugin's problem).
bool has_coverage(const ScenarioRun& run);

// The features `run` of `scenario` covers, sorted and unique; empty unless has_coverage(run).
std::vector<std::string> run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario);

// What one run covers, with the robustness its law features were read from.
struct RunCoverage {
  std::vector<std::string> features;   // as run_coverage gives them
  std::vector<double> law_robustness;  // one per `subs`; empty unless has_coverage(run)
};

// run_coverage with `subs` = law_sub_violations(scenario) worked out once by the caller, keeping
// each sub-violation's robustness (the search targets the unreached ones with it).
RunCoverage run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario,
                         const std::vector<LawSubViolation>& subs);

}  // namespace scenfuzz
