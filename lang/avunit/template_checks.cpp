#include "lang/avunit/template_checks.hpp"

#include <set>
#include <string>

#include "lang/walk_values.hpp"

namespace scenfuzz::avunit {

namespace {

// Specs may read only the actors of the scenario their trace executes.
void check_term(const SpecTerm& term, const std::set<std::string>& names, const std::string& trace,
                Diagnostics& diagnostics) {
  if (term.kind == TermKind::object && term.source != ObjectSource::ego && !names.count(term.name))
    diagnostics.error(term.location, "'" + term.name + "' is not part of the scenario that '" +
                                         trace + "' executes");
  for (const SpecTerm& operand : term.operands) check_term(operand, names, trace, diagnostics);
}

void check_formula(const Formula& formula, const std::set<std::string>& names,
                   const std::string& trace, Diagnostics& diagnostics) {
  for (const SpecTerm& term : formula.terms) check_term(term, names, trace, diagnostics);
  for (const Formula& operand : formula.operands) check_formula(operand, names, trace, diagnostics);
}

// Points a parameter reference at the parameter's new index.
void renumber(Value& value, const std::vector<int>& new_index) {
  if (value.op == ValueOp::parameter)
    value.parameter = new_index[static_cast<std::size_t>(value.parameter)];
  for (Value& operand : value.operands) renumber(operand, new_index);
}

}  // namespace

// Headings related to actors and specs reading actors need those actors in the scenario.
void check_references(const ScenarioTemplate& scenario, Diagnostics& diagnostics) {
  std::set<std::string> names;
  auto add = [&](const std::string& name) { names.insert(name); };
  add(scenario.ego.name);
  for (const Actor& actor : scenario.vehicles) add(actor.name);
  for (const Actor& actor : scenario.pedestrians) add(actor.name);
  for (const Obstacle& obstacle : scenario.obstacles) add(obstacle.name);
  auto check_state = [&](const State& state) {
    if (state.heading && state.heading->relative_to &&
        state.heading->relative_to->kind == Direction::Kind::actor &&
        !names.count(state.heading->relative_to->actor))
      diagnostics.error(state.heading->relative_to->location,
                        "the heading is related to '" + state.heading->relative_to->actor +
                            "', which is not part of the scenario");
  };
  auto check_actor = [&](const Actor& actor) {
    check_state(actor.initial);
    for (const State& state : actor.motion.states) check_state(state);
    if (actor.target) check_state(*actor.target);
  };
  check_actor(scenario.ego);
  for (const Actor& actor : scenario.vehicles) check_actor(actor);
  for (const Actor& actor : scenario.pedestrians) check_actor(actor);
  for (const Spec& spec : scenario.specs)
    check_formula(spec.formula, names, spec.trace, diagnostics);
}

// Marks the parameters the scenario reads.
void mark_read_parameters(ScenarioTemplate& scenario, std::vector<bool>& read) {
  for_each_value(scenario, [&](Value& value, const std::string&, const std::string&) {
    std::vector<int> parameters;
    collect_parameters(value, parameters);
    for (int p : parameters) read[static_cast<std::size_t>(p)] = true;
  });
}

// Names each parameter after the first slot that reads it, orders the parameters by that
// walk, and drops those nothing reads.
// A range that only another of the file's scenarios reads (`read_elsewhere`) is not warned of.
void name_parameters(ScenarioTemplate& scenario, const std::vector<bool>& read_elsewhere,
                     Diagnostics& diagnostics) {
  std::vector<int> new_index(scenario.parameters.size(), -1);
  std::vector<Parameter> ordered;
  std::set<std::string> taken;
  for_each_value(scenario, [&](Value& value, const std::string& path, const std::string& unit) {
    std::vector<int> read;
    collect_parameters(value, read);
    for (int p : read) {
      if (new_index[static_cast<std::size_t>(p)] >= 0) continue;
      Parameter parameter = scenario.parameters[static_cast<std::size_t>(p)];
      parameter.name = path;
      for (int k = 2; !taken.insert(parameter.name).second; ++k)
        parameter.name = path + "#" + std::to_string(k);
      if (parameter.unit.empty()) parameter.unit = unit;
      if (unit == "deg" || unit == "rad") parameter.kind = ParameterKind::angle;
      new_index[static_cast<std::size_t>(p)] = static_cast<int>(ordered.size());
      ordered.push_back(std::move(parameter));
    }
  });
  if (scenario.has_scenario)
    for (std::size_t p = 0; p < new_index.size(); ++p)
      if (new_index[p] < 0 && !read_elsewhere[p])
        diagnostics.warning(scenario.parameters[p].location,
                            "this range is used by neither the scenario nor a specification, "
                            "so it is not a search dimension");
  for_each_value(scenario, [&](Value& value, const std::string&, const std::string&) {
    renumber(value, new_index);
  });
  scenario.parameters = std::move(ordered);
}

}  // namespace scenfuzz::avunit
