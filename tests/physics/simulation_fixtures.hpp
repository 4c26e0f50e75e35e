// Runs scenarios written inline as AVUnit through the whole simulation: parse, evaluate at the
// middle of the search space, load the map, prepare, simulate.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "physics/collision/footprint.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "physics/trace/trace_footprint.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz::test {

struct SimulatedRun {
  std::optional<Trace> trace;  // nullopt when the scenario did not get as far as simulating
  std::string errors;          // diagnostics, formatted
};

inline SimulatedRun simulate_file(const SourceFile& file, SimulationOptions options = {},
                                  const MapSearchPath& search_path = map_search_path({})) {
  SimulatedRun run;
  avunit::ParseResult parsed = avunit::parse(file);
  run.errors = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok()) return run;
  ParameterSpace space = parameter_space(parsed.scenario);
  std::vector<double> middle(space.dimensions.size(), 0.5);
  std::vector<double> values = decode(space, middle);
  RoadMap map = load_scenario_map(parsed.scenario.map, search_path, values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, options.seed, diagnostics);
  run.errors += format_diagnostics(file, diagnostics);
  if (!setup) return run;
  run.trace = simulate(map, *setup, options);
  return run;
}

inline SimulatedRun simulate_text(const std::string& text, SimulationOptions options = {}) {
  return simulate_file(SourceFile("inline.avu", text), options);
}

// The smallest footprint distance between two actors over the trace.
inline double closest_approach(const Trace& trace, ActorId a, ActorId b) {
  double closest = INFINITY;
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    closest =
        std::min(closest, signed_distance(footprint_at(trace, a, i), footprint_at(trace, b, i)));
  return closest;
}

}  // namespace scenfuzz::test
