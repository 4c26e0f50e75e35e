// WMG SDL scenarios built directly as IR (the shapes docs/wmg-semantics.md fixes), on the
// built-in one-way three-lane `straight` road: east_0 (kerb, y = -8.75), east_1 (y = -5.25),
// east_2 (y = -1.75), 500 m along +x.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "lang/scenario.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"

namespace scenfuzz::test {

inline SourceLocation at_line(std::uint32_t line) { return {line, 1, 0, 1}; }

inline SpecTerm number_term(double value) {
  SpecTerm term;
  term.kind = TermKind::number;
  term.value = constant_value(value);
  return term;
}

inline SpecTerm word_term(const std::string& name) {
  SpecTerm term;
  term.kind = TermKind::word;
  term.name = name;
  return term;
}

// speed(Ego), timer(T), lateral_offset(A, B), collision() ...
inline SpecTerm signal_term(const std::string& name,
                            const std::vector<std::string>& operands = {}) {
  SpecTerm term;
  term.kind = TermKind::signal;
  term.name = name;
  for (const std::string& operand : operands) term.operands.push_back(word_term(operand));
  return term;
}

inline Formula compare(SpecTerm left, CompareOp op, SpecTerm right) {
  Formula formula;
  formula.kind = FormulaKind::comparison;
  formula.compare = op;
  formula.terms = {std::move(left), std::move(right)};
  return formula;
}

inline Formula both(Formula a, Formula b) {
  Formula formula;
  formula.kind = FormulaKind::conjunction;
  formula.operands = {std::move(a), std::move(b)};
  return formula;
}

inline Formula holds(SpecTerm term) {
  Formula formula;
  formula.kind = FormulaKind::predicate;
  formula.terms = {std::move(term)};
  return formula;
}

inline State lane_state(const std::string& lane, double s, double speed) {
  State state;
  state.position.kind = PositionKind::lane;
  state.position.lane = lane;
  state.position.s = constant_value(s);
  state.speed = constant_value(speed);
  return state;
}

inline State relative_state(const std::string& reference, const std::string& sector, double s,
                            double speed, const std::string& lane = "") {
  State state;
  state.position.kind = PositionKind::relative;
  state.position.reference = reference;
  state.position.relative_location = sector;
  state.position.s = constant_value(s);
  state.position.lane = lane;
  state.position.location = at_line(7);
  state.speed = constant_value(speed);
  return state;
}

inline ManoeuvrePhase phase(const std::string& manoeuvre, std::optional<double> speed,
                            std::optional<double> duration, std::optional<double> gap = {},
                            const std::string& reference = "") {
  ManoeuvrePhase phase;
  phase.manoeuvre = manoeuvre;
  if (speed) phase.parameters.push_back({"speed", constant_value(*speed), {}});
  if (duration) phase.parameters.push_back({"duration", constant_value(*duration), {}});
  if (gap) phase.parameters.push_back({"gap", constant_value(*gap), {}});
  phase.reference = reference;
  phase.location = at_line(20);
  return phase;
}

inline Actor manoeuvring(ActorKind kind, const std::string& name, State initial,
                         std::vector<ManoeuvrePhase> phases) {
  Actor actor;
  actor.kind = kind;
  actor.name = name;
  actor.initial = std::move(initial);
  actor.motion.kind = MotionKind::manoeuvres;
  actor.motion.phases = std::move(phases);
  actor.location = at_line(5);
  return actor;
}

// The ego ("Ego", the reference driver, no target) on east_0 at s with the speed given.
inline ScenarioTemplate three_lane_road(double ego_s, double ego_speed, double duration = 12) {
  ScenarioTemplate scenario;
  scenario.language = SourceLanguage::wmg_sdl;
  scenario.has_scenario = true;
  scenario.map.name = "straight";
  scenario.map.parameters = {{"two_way", constant_value(0), {}}, {"lanes", constant_value(3), {}}};
  scenario.ego.kind = ActorKind::ego;
  scenario.ego.name = "Ego";
  scenario.ego.initial = lane_state("east_0", ego_s, ego_speed);
  scenario.duration = constant_value(duration);
  return scenario;
}

struct ManoeuvreRun {
  std::optional<SimulationSetup> setup;
  std::optional<Trace> trace;
  Diagnostics diagnostics;
  std::string messages;  // every diagnostic, one a line
};

inline RoadMap scenario_map(const ScenarioTemplate& scenario) {
  return load_scenario_map(scenario.map, map_search_path({}), {});
}

inline ManoeuvreRun run_manoeuvres(const ScenarioTemplate& scenario,
                                   SimulationOptions options = {}) {
  ManoeuvreRun run;
  RoadMap map = scenario_map(scenario);
  run.setup = prepare_simulation(scenario, {}, map, options.seed, run.diagnostics);
  for (const Diagnostic& diagnostic : run.diagnostics.all())
    run.messages += std::to_string(diagnostic.location.line) + ": " + diagnostic.message + "\n";
  if (run.setup) run.trace = simulate(map, *run.setup, options);
  return run;
}

// The first sample at or after time t.
inline std::size_t sample_at(const Trace& trace, double t) {
  std::size_t i = 0;
  while (i + 1 < trace.sample_count() && trace.time[i] < t - 1e-9) ++i;
  return i;
}

}  // namespace scenfuzz::test
