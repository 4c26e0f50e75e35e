// A search's sub-violation coverage of its law specs (docs/coverage.md, "Law coverage"): per law
// spec, k of its N LawBreaker sub-violations reached, which ones with their formula, and the
// first evaluation that reached each, for summary.json's "law_coverage" and the end-of-search
// text. Read from the evaluations' coverage features (no law signal is computed again).
#pragma once

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lang/scenario.hpp"
#include "oracle/law_coverage.hpp"

namespace scenfuzz {

// The first evaluation (index) that reached each law feature, filled in index order.
using FirstReached = std::map<std::string, std::size_t>;

// Notes the law features of evaluation `index` that no earlier evaluation reached.
void note_first_reached(const std::vector<std::string>& coverage, std::size_t index,
                        FirstReached& first);

// [{"spec", "covered": k, "of": N, "reached": [{"name", "formula", "first_evaluation"}],
//   "unreached": [names]}], one per law spec in the scenario's order; empty without law specs.
nlohmann::json law_coverage_json(const ScenarioTemplate& scenario,
                                 const std::vector<LawSubViolation>& subs,
                                 const FirstReached& first);

// "law coverage of laws: 12 of 81 sub-violations" and an indented line per reached one
// ("law.laws.07 (evaluation 3): F[0:10] ..."); empty without law specs.
std::string law_coverage_text(const ScenarioTemplate& scenario,
                              const std::vector<LawSubViolation>& subs, const FirstReached& first);

}  // namespace scenfuzz
