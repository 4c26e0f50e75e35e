// Traces for the oracle's tests: built by hand with exact geometry, or simulated from an AVUnit
// scenario on a built-in map (parse, evaluate at the middle of the search space, prepare,
// simulate), keeping the scenario, its parameters and its map for the oracle to read.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "oracle/robustness.hpp"
#include "oracle/trace_signals.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz::test {

// `samples` samples every `dt` seconds, no actors yet.
inline Trace empty_trace(std::size_t samples, double dt = 0.1) {
  Trace trace;
  trace.map_name = "straight";
  trace.dt = dt;
  for (std::size_t i = 0; i < samples; ++i) trace.time.push_back(static_cast<double>(i) * dt);
  return trace;
}

// An actor standing (or moving, once its columns are edited) at one pose at every sample, on no
// lane.
inline TraceActor still_actor(const Trace& trace, std::string name, TraceActorKind kind,
                              BodyShape shape, double length, double width, double x, double y,
                              double heading = 0, double speed = 0) {
  const std::size_t n = trace.sample_count();
  TraceActor actor;
  actor.name = std::move(name);
  actor.kind = kind;
  actor.shape = shape;
  actor.length = length;
  actor.width = width;
  actor.height = 1.5;
  actor.x.assign(n, x);
  actor.y.assign(n, y);
  actor.heading.assign(n, heading);
  actor.speed.assign(n, speed);
  actor.acceleration.assign(n, 0);
  actor.yaw_rate.assign(n, 0);
  actor.lane.assign(n, -1);
  actor.s.assign(n, 0);
  return actor;
}

// Moves an actor along +x from `x0` at `speed`, on `lane` (whose s equals x, as on `straight`).
inline void drive_east(const Trace& trace, TraceActor& actor, double x0, double speed,
                       std::int32_t lane, double lane_y) {
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    actor.x[i] = x0 + speed * trace.time[i];
    actor.y[i] = lane_y;
    actor.heading[i] = 0;
    actor.speed[i] = speed;
    actor.lane[i] = lane;
    actor.s[i] = actor.x[i];
  }
}

// The ego's flawless perception of every other actor, as the trace's `perceived` requires.
inline void perceive_perfectly(Trace& trace) {
  trace.perceived.clear();
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    const TraceActor& actor = trace.actors[k];
    PerceivedActor seen;
    seen.actor = static_cast<ActorId>(k);
    seen.detected.assign(trace.sample_count(), 1);
    seen.x = actor.x;
    seen.y = actor.y;
    seen.heading = actor.heading;
    seen.speed = actor.speed;
    seen.reversing = actor.reversing;
    trace.perceived.push_back(std::move(seen));
  }
}

// Marks sample i of `seen` as missed, as the simulation writes it.
inline void miss(PerceivedActor& seen, std::size_t i) {
  seen.detected[i] = 0;
  seen.x[i] = seen.y[i] = seen.heading[i] = seen.speed[i] = NAN;
  if (!seen.reversing.empty()) seen.reversing[i] = 0;
}

struct ParsedScenario {
  ScenarioTemplate scenario;
  std::vector<double> parameters;  // at the middle of the search space
};

// Parses an AVUnit file that must have no errors.
inline ParsedScenario parse_scenario(const std::string& text) {
  const SourceFile file("inline.avu", text);
  avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  ParameterSpace space = parameter_space(parsed.scenario);
  std::vector<double> middle(space.dimensions.size(), 0.5);
  return {std::move(parsed.scenario), decode(space, middle)};
}

struct SimulatedScenario {
  ParsedScenario parsed;
  std::optional<RoadMap> map;
  std::optional<Trace> trace;  // nullopt when it could not be prepared
  std::string errors;
};

inline SimulatedScenario simulate_scenario(const std::string& text,
                                           SimulationOptions options = {}) {
  SimulatedScenario run{parse_scenario(text), std::nullopt, std::nullopt, ""};
  run.map = load_scenario_map(run.parsed.scenario.map, map_search_path({}), run.parsed.parameters);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(run.parsed.scenario, run.parsed.parameters, *run.map,
                                  options.seed, diagnostics);
  run.errors = format_diagnostics(SourceFile("inline.avu", text), diagnostics);
  if (setup) run.trace = simulate(*run.map, *setup, options);
  return run;
}

// The robustness at t = 0 of every spec of `scenario` on `trace`, in file order.
inline std::vector<double> spec_robustness(const Trace& trace, const ParsedScenario& parsed,
                                           const RoadMap& map) {
  const TraceSignals signals(trace, parsed.scenario, parsed.parameters, map);
  std::vector<double> robustness;
  for (const Spec& spec : parsed.scenario.specs)
    robustness.push_back(robustness_signal(spec.formula, signals.source()).at(0));
  return robustness;
}

}  // namespace scenfuzz::test
