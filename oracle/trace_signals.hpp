// What a spec's named signals mean on a simulated trace: AVUnit's signal functions `dis vel spd
// acc diff` over trace projections (the ego, an actor's ground truth, the ego's perception of
// it), positions and vectors; numeric columns of a projection (`ego_state.speed`); and the
// scenest traffic-law signals that a trace determines. docs/oracle.md defines each.
#pragma once

#include <span>

#include "lang/scenario.hpp"
#include "oracle/robustness.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Reads `trace`, the run of `scenario` at the point `parameters` on `map`. Holds references:
// every argument must outlive it.
class TraceSignals {
 public:
  TraceSignals(const Trace& trace, const ScenarioTemplate& scenario,
               std::span<const double> parameters, const RoadMap& map);

  // The value of a TermKind::signal or TermKind::column term at every sample. Throws
  // OracleError at the term's location for what the trace cannot give (an actor the trace does
  // not have, a law signal the oracle does not compute).
  SignalValues leaf(const SpecTerm& term) const;

  // A SignalSource over the trace's samples that resolves leaves with leaf(); valid while this
  // object lives.
  SignalSource source() const;

 private:
  const Trace& trace_;
  const ScenarioTemplate& scenario_;
  std::span<const double> parameters_;
  const RoadMap& map_;
};

}  // namespace scenfuzz
