// Behaviour coverage of law specs: the LawBreaker sub-violations (sub_violations.hpp) a run
// reaches, as features "law.<spec>.<k>" (k from 1 in LawBreaker's order, zero-padded to the width
// of the spec's count, so that names sort in that order). A sub-violation is reached when its
// robustness at the start of the trace is >= 0, LawBreaker's "found". The search reads the same
// robustness values to target the sub-violations not reached yet (fuzz/law_targets.hpp).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "lang/scenario.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Whether `spec` is a law spec: it reads a scenest traffic-law signal (`speed`,
// `trafficLightAhead.color`, `stoplineAhead(2)`, ...), not only AVUnit's functions and columns.
bool is_law_spec(const Spec& spec);

// One sub-violation of a law spec of a scenario, in the order law_sub_violations lists them.
struct LawSubViolation {
  std::size_t spec = 0;  // index into the scenario's specs
  std::string name;      // its feature, law_feature_name
  Formula formula;
};

// The sub-violations of every law spec of `scenario`, spec by spec in LawBreaker's order; a spec
// with more than kMaxSubViolations adds none.
std::vector<LawSubViolation> law_sub_violations(const ScenarioTemplate& scenario);

// The robustness at the start of the trace of each of `subs` (law_sub_violations(scenario)) on
// the run at `parameters`: >= 0 where reached. Every sub-violation of a spec that reads a signal
// the oracle does not compute (OracleError) is -infinity: never reached. Each law signal is
// computed once for all of them.
std::vector<double> law_robustness(const std::vector<LawSubViolation>& subs,
                                   const ScenarioTemplate& scenario,
                                   std::span<const double> parameters, const Trace& trace,
                                   const RoadMap& map);

// The names of the sub-violations whose robustness (law_robustness) is >= 0, sorted.
std::vector<std::string> reached_law_features(const std::vector<LawSubViolation>& subs,
                                              std::span<const double> robustness);

// "law.<spec>.<k>" for sub-violation k (from 1) of a spec with `count` of them.
std::string law_feature_name(const std::string& spec, std::size_t k, std::size_t count);

// The reached sub-violations of every law spec of `scenario` on `trace` (the run at `parameters`
// on `map`), sorted. A spec with more than kMaxSubViolations, or reading a signal the oracle does
// not compute (OracleError), adds none: its verdict reports the problem (docs/coverage.md).
std::vector<std::string> law_coverage(const ScenarioTemplate& scenario,
                                      std::span<const double> parameters, const Trace& trace,
                                      const RoadMap& map);

}  // namespace scenfuzz
