// The AVUnit elaborator's entry points, its reporting, its statements (assignments, trace
// declarations, assertions) and the template it builds at the end (elaborator_class.hpp).
#include "lang/avunit/elaborator.hpp"

#include "lang/avunit/elaborator_class.hpp"

namespace scenfuzz::avunit {

std::string describe(const Item& item) {
  switch (item.kind) {
    case ItemKind::error: return "an erroneous value";
    case ItemKind::empty: return "nothing";
    case ItemKind::star: return "'*'";
    case ItemKind::number: return "a number";
    case ItemKind::time: return "a time of day";
    case ItemKind::string: return "string \"" + item.word + "\"";
    case ItemKind::word: return "'" + item.word + "'";
    case ItemKind::tuple:
      return "a tuple of " + std::to_string(item.elements.size()) +
             (item.elements.size() == 1 ? " element" : " elements");
    case ItemKind::set: return "a set";
    case ItemKind::keyed: return "'" + item.word + ": ...'";
    case ItemKind::position: return "a position";
    case ItemKind::heading: return "a heading";
    case ItemKind::state: return "a state";
    case ItemKind::motion: return "a motion";
    case ItemKind::actor_type: return "a vehicle type";
    case ItemKind::shape: return "a shape";
    case ItemKind::actor: {
      const Actor& actor = payload_of<Actor>(item);
      std::string kind = actor.kind == ActorKind::ego          ? "the ego vehicle"
                         : actor.kind == ActorKind::pedestrian ? "pedestrian"
                                                               : "vehicle";
      return actor.name.empty() ? kind : kind + " '" + actor.name + "'";
    }
    case ItemKind::obstacle: return "an obstacle";
    case ItemKind::environment: return "an environment";
    case ItemKind::map: return "a map";
    case ItemKind::scenario: return "a scenario";
    case ItemKind::trace: return "trace '" + item.word + "'";
    case ItemKind::projection: return "a trace projection";
    case ItemKind::term: return "a signal";
    case ItemKind::formula: return "a formula";
    case ItemKind::intersection: return "an intersection";
    case ItemKind::speed_limit: return "a speed limit";
    case ItemKind::flow: {
      const TrafficFlow& flow = payload_of<TrafficFlow>(item);
      return flow.name.empty() ? "a traffic flow" : "traffic flow '" + flow.name + "'";
    }
    case ItemKind::npc_behaviour: return "NPCBehaviour(" + item.word + ")";
    case ItemKind::traffic_light:
      return "TrafficLight(\"" + payload_of<TrafficLightSetting>(item).id + "\", ...)";
  }
  return "a value";
}

std::optional<Formula> Elaborator::lone_formula(const Syntax& syntax) {
  free_signals_ = true;
  Item item = evaluate(syntax);
  if (item.kind == ItemKind::error) return std::nullopt;
  std::optional<Formula> formula = need_formula(item);
  if (diagnostics_.has_errors()) return std::nullopt;
  return formula;
}

void Elaborator::add(const Statement& statement) {
  if (diagnostics_.too_many_errors()) return;
  switch (statement.kind) {
    case StatementKind::assignment: assign(statement); break;
    case StatementKind::trace_declaration: declare_trace(statement); break;
    case StatementKind::assertion: assert_spec(statement); break;
  }
}

Item Elaborator::fail(SourceLocation where, const std::string& message) {
  diagnostics_.error(where, message);
  return make_item(ItemKind::error, where);
}

void Elaborator::mismatch(const Item& item, const std::string& expected) {
  if (item.kind != ItemKind::error)
    diagnostics_.error(item.location, "expected " + expected + ", found " + describe(item));
}

std::string Elaborator::suggestion(const std::string& name) const {
  std::string best;
  std::size_t best_distance = name.size() / 3 + 1;
  auto consider = [&](std::string_view candidate) {
    std::size_t d = edit_distance_within(name, candidate, best_distance);
    if (d < best_distance || (d == best_distance && best.empty() && d <= 2)) {
      best_distance = d;
      best = std::string(candidate);
    }
  };
  for (const std::string& variable : names_) consider(variable);
  for (std::string_view builtin : builtin_names()) consider(builtin);
  return best.empty() || best == name ? "" : "; did you mean '" + best + "'?";
}

void Elaborator::bind(const std::string& name, Item item) {
  auto [found, added] = variables_.insert_or_assign(name, std::move(item));
  if (added) names_.push_back(name);
}

bool Elaborator::reserved(const std::string& name) {
  return name == "G" || name == "F" || name == "X" || name == "U";
}

void Elaborator::assign(const Statement& statement) {
  if (reserved(statement.name)) {
    fail(statement.name_location,
         "'" + statement.name + "' is a temporal operator and cannot name a variable");
    return;
  }
  Item item = evaluate(statement.value);
  // An actor takes the name of the first variable it is bound to: specs refer to it by it.
  if (item.kind == ItemKind::actor) {
    Actor& actor = payload_of<Actor>(item);
    if (actor.name.empty()) actor.name = statement.name;
  } else if (item.kind == ItemKind::obstacle) {
    Obstacle& obstacle = payload_of<Obstacle>(item);
    if (obstacle.name.empty()) obstacle.name = statement.name;
  } else if (item.kind == ItemKind::flow) {
    TrafficFlow& flow = payload_of<TrafficFlow>(item);
    if (flow.name.empty()) flow.name = statement.name;
  }
  item.location = statement.value.location;
  bind(statement.name, std::move(item));
}

void Elaborator::declare_trace(const Statement& statement) {
  Item trace = make_item(ItemKind::error, statement.name_location);
  const Syntax& value = statement.value;
  if (value.kind != SyntaxKind::call || value.text != "EXE" || value.children.size() != 1) {
    fail(value.location, "expected 'EXE(scenario)' after 'Trace " + statement.name + " ='");
  } else {
    Item scenario = evaluate(value.children[0]);
    if (scenario.kind != ItemKind::scenario) {
      mismatch(scenario, "a scenario made by CreateScenario{...}");
    } else {
      auto parts = payload_of<std::shared_ptr<const ScenarioParts>>(scenario);
      traces_.push_back(TraceBinding{statement.name, parts, statement.name_location});
      trace = make_item(ItemKind::trace, statement.name_location, parts);
      trace.word = statement.name;
    }
  }
  bind(statement.name, std::move(trace));
}

void Elaborator::assert_spec(const Statement& statement) {
  auto found = variables_.find(statement.name);
  if (found == variables_.end() || found->second.kind != ItemKind::trace) {
    if (found == variables_.end() || found->second.kind != ItemKind::error)
      fail(statement.name_location,
           "'" + statement.name + "' is not a trace: declare it with 'Trace " + statement.name +
               " = EXE(scenario);' before asserting on it");
    return;
  }
  current_trace_ = statement.name;
  Item value = evaluate(statement.value);
  current_trace_.clear();
  std::optional<Formula> formula = need_formula(value);
  if (!formula) return;
  Spec spec;
  spec.trace = statement.name;
  spec.formula = std::move(*formula);
  spec.location = statement.location;
  spec.name = value.kind == ItemKind::formula && statement.value.kind == SyntaxKind::identifier
                  ? statement.value.text
                  : "spec" + std::to_string(specs_.size() + 1);
  specs_.push_back(std::move(spec));
  spec_parts_.push_back(payload_of<std::shared_ptr<const ScenarioParts>>(found->second));
}

std::string Elaborator::variable_of(const std::shared_ptr<const ScenarioParts>& parts) const {
  for (const auto& [name, item] : variables_)
    if (item.kind == ItemKind::scenario &&
        *std::get<Boxed<std::shared_ptr<const ScenarioParts>>>(item.payload) == parts)
      return name;
  return "";
}

std::vector<Elaborator::Candidate> Elaborator::candidates() const {
  std::vector<Candidate> found;
  auto entry = [&](const std::shared_ptr<const ScenarioParts>& parts) -> Candidate& {
    for (Candidate& candidate : found)
      if (candidate.parts == parts) return candidate;
    found.push_back(Candidate{parts, {variable_of(parts), {}, parts->location}});
    return found.back();
  };
  for (const TraceBinding& trace : traces_) {
    ScenarioCandidate& described = entry(trace.parts).described;
    if (described.traces.empty()) described.location = trace.location;
    if (described.name.empty()) described.name = trace.name;
    described.traces.push_back(trace.name);
  }
  if (traces_.empty())
    for (const auto& parts : scenarios_) entry(parts);
  return found;
}

ScenarioTemplate Elaborator::template_of(const Candidate& candidate) const {
  const ScenarioParts& parts = *candidate.parts;
  ScenarioTemplate result;
  result.language = language_;
  result.has_scenario = true;
  result.map = parts.map;
  result.ego = parts.ego;
  result.vehicles = parts.vehicles;
  result.pedestrians = parts.pedestrians;
  result.obstacles = parts.obstacles;
  result.environment = parts.environment;
  result.traffic = parts.traffic;
  result.npc_behaviour = parts.npc_behaviour;
  if (!candidate.described.traces.empty()) result.trace_name = candidate.described.traces.front();
  result.scenario_name = variable_of(candidate.parts);
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (spec_parts_[i] == candidate.parts) result.specs.push_back(specs_[i]);
  result.parameters = parameters_;
  return result;
}

ScenarioTemplate Elaborator::build_template() {
  const std::vector<Candidate> found = candidates();
  std::vector<ScenarioCandidate> described;
  for (const Candidate& candidate : found) {
    described.push_back(candidate.described);
    scenario_names_.push_back(candidate.described.name);
  }
  ScenarioRequest request = request_;
  request.executed = !traces_.empty();
  const std::optional<std::size_t> chosen = choose_scenario(described, request, diagnostics_);
  // Every scenario is checked, chosen or not; a range only another scenario reads is no
  // "unused range".
  std::vector<ScenarioTemplate> templates;
  std::vector<bool> read_elsewhere(parameters_.size(), false);
  for (std::size_t i = 0; i < found.size(); ++i) {
    templates.push_back(template_of(found[i]));
    check_references(templates.back(), diagnostics_);
    if (chosen != i) mark_read_parameters(templates.back(), read_elsewhere);
  }
  ScenarioTemplate result;
  if (chosen) {
    result = std::move(templates[*chosen]);
  } else {
    result.language = language_;
    result.parameters = parameters_;
    if (found.empty()) result.specs = specs_;
  }
  name_parameters(result, read_elsewhere, diagnostics_);
  return result;
}

StatementElaborator::StatementElaborator(SourceLanguage language, Diagnostics& diagnostics,
                                         ScenarioRequest request)
    : elaborator_(std::make_unique<Elaborator>(diagnostics, language, std::move(request))) {}

StatementElaborator::~StatementElaborator() = default;

void StatementElaborator::add(const Statement& statement) { elaborator_->add(statement); }

ScenarioTemplate StatementElaborator::finish() { return elaborator_->finish(); }

const std::vector<std::string>& StatementElaborator::scenario_names() const {
  return elaborator_->scenario_names();
}

std::optional<Formula> elaborate_lone_formula(const Syntax& syntax, Diagnostics& diagnostics) {
  return Elaborator(diagnostics, SourceLanguage::avunit).lone_formula(syntax);
}

}  // namespace scenfuzz::avunit
