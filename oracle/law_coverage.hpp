// Behaviour coverage of law specs: the LawBreaker sub-violations (sub_violations.hpp) a run
// reaches, as features "law.<spec>.<k>" (k from 1 in LawBreaker's order, zero-padded to the width
// of the spec's count, so that names sort in that order). A sub-violation is reached when its
// robustness at the start of the trace is >= 0, LawBreaker's "found".
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

// "law.<spec>.<k>" for sub-violation k (from 1) of a spec with `count` of them.
std::string law_feature_name(const std::string& spec, std::size_t k, std::size_t count);

// The reached sub-violations of every law spec of `scenario` on `trace` (the run at `parameters`
// on `map`), sorted. A spec with more than kMaxSubViolations, or reading a signal the oracle does
// not compute (OracleError), adds none: its verdict reports the problem (docs/coverage.md).
std::vector<std::string> law_coverage(const ScenarioTemplate& scenario,
                                      std::span<const double> parameters, const Trace& trace,
                                      const RoadMap& map);

}  // namespace scenfuzz
