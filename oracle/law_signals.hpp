// scenest's traffic-law signals (`speed`, `Time`, `stoplineAhead(d)`, `NPCAhead.speed`,
// `trafficLightAhead.color`, ...) computed from a simulated trace, its scenario and its map, with
// LawBreaker's units and "none" values (../shared/reference/scenest-law-signals.md) so that laws
// written for LawBreaker keep their meaning. docs/oracle.md lists what each one is.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "lang/scenario.hpp"
#include "oracle/robustness.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// What a law signal that looks ahead gives when there is nothing there: LawBreaker's values.
inline constexpr double kNoRoadObjectAhead = 200;  // m: stop lines, junctions, crosswalks, signs
inline constexpr double kNoVehicle = 1000;         // m: NPCAhead, NearestNPC

// The law signal `term` (TermKind::signal, named in lang/avunit/builtins.cpp as a flag, distance
// predicate or value) at every sample of `trace`. A distance predicate `P(d)` gives its distance:
// the caller compares it with d. Throws OracleError at the term's location for a signal it does
// not compute.
// Whether law_signal computes the law signal `name` (it throws for every other).
bool law_signal_computed(std::string_view name);

// What law_signal says of a law signal it does not compute.
std::string uncomputed_law_signal_message(std::string_view name);

SignalValues law_signal(const SpecTerm& term, const Trace& trace, const ScenarioTemplate& scenario,
                        std::span<const double> parameters, const RoadMap& map);

}  // namespace scenfuzz
