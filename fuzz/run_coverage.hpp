// The behaviour-coverage features (docs/coverage.md) of one run a ScenarioEvaluator simulated:
// oracle/behaviour_coverage's families and the law sub-violations of the scenario's law specs.
// The search keeps them per evaluation (Evaluation::coverage, summary.json's "coverage") and the
// corpus tools per seed (seed_coverage.hpp), so both name exactly the same features.
#pragma once

#include <string>
#include <vector>

#include "fuzz/scenario_evaluator.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz {

// Whether `run` left a trace whose features can be read: simulated, with samples, and not cut
// short by an ego plugin that could not even start (that drove nothing: the plugin's problem).
bool has_coverage(const ScenarioRun& run);

// The features `run` of `scenario` covers, sorted and unique; empty unless has_coverage(run).
std::vector<std::string> run_coverage(const ScenarioRun& run, const ScenarioTemplate& scenario);

}  // namespace scenfuzz
