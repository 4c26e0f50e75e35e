// Prints a template as AVUnit: canonically (every actor and spec written out, ranges inline), or
// concretely in the user's own layout (only the ranges of the original file replaced).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "lang/avunit/avunit.hpp"
#include "lang/avunit/traffic_extensions.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/parameter_provenance.hpp"
#include "lang/walk_values.hpp"

namespace scenfuzz::avunit {

namespace {

// A string reads back only with quotes of a family it does not contain: a string opened with
// `"` ends at any of " “ ”, one opened with ' at any of ' ‘ ’.
std::string quoted(const std::string& text) {
  bool has_double = text.find('"') != std::string::npos ||
                    text.find("\u201C") != std::string::npos ||
                    text.find("\u201D") != std::string::npos;
  return has_double ? "'" + text + "'" : "\"" + text + "\"";
}

// Whole seconds within a day print as H:MM[:SS]; anything else as an offset from midnight.
std::string time_constant_text(double seconds) {
  if (seconds >= 0 && seconds <= 86400 && seconds == std::floor(seconds))
    return format_time_of_day(seconds);
  return "0:00 + " + format_number(seconds);
}

class Printer {
 public:
  explicit Printer(const ScenarioTemplate& scenario) : scenario_(scenario) {}

  // One formula alone, its trace projections named after `trace`.
  std::string formula_text(const Formula& formula, const std::string& trace) {
    trace_ = trace;
    return formula_text(formula);
  }

  std::string run() {
    if (!scenario_.has_scenario) return "// AVUnit printed by scenfuzz\n// (no scenario)\n";
    name_shared_parameters();
    const std::string scenario_name =
        scenario_.scenario_name.empty() ? "scenario" : scenario_.scenario_name;
    out_ += actor_statements();
    for (const Obstacle& obstacle : scenario_.obstacles)
      out_ += obstacle.name + " = " + obstacle_text(obstacle) + ";\n";
    // Assigned, so that a flow keeps its name (and its parameters theirs) when read back.
    for (const TrafficFlow& flow : scenario_.traffic.flows)
      out_ += flow.name + " = " + flow_text(flow) + ";\n";
    out_ += scenario_name + " = CreateScenario{load(" + quoted(scenario_.map.name) + ");\n";
    out_ += "    " + scenario_.ego.name + ";\n";
    out_ += "    " + name_set(scenario_.vehicles) + ";\n";
    out_ += "    " + name_set(scenario_.pedestrians) + ";\n";
    std::vector<std::string> obstacle_names;
    for (const Obstacle& obstacle : scenario_.obstacles) obstacle_names.push_back(obstacle.name);
    out_ += "    " + set_text(obstacle_names) + ";\n";
    bool has_traffic = !scenario_.traffic.intersections.empty() ||
                       !scenario_.traffic.speed_limits.empty() ||
                       !scenario_.traffic.flows.empty() || !scenario_.traffic.lights.empty() ||
                       scenario_.npc_behaviour;
    if (scenario_.environment || has_traffic)
      out_ += "    " + (scenario_.environment ? environment_text(*scenario_.environment) : "{}") +
              ";\n";
    if (has_traffic) out_ += "    " + traffic_text(scenario_.traffic) + ";\n";
    out_ += "};\n";
    // The first trace is the template's; specs may be asserted on other traces of it too.
    std::vector<std::string> traces;
    if (!scenario_.trace_name.empty()) traces.push_back(scenario_.trace_name);
    for (const Spec& spec : scenario_.specs)
      if (std::find(traces.begin(), traces.end(), spec.trace) == traces.end())
        traces.push_back(spec.trace);
    for (const std::string& trace : traces)
      out_ += "Trace " + trace + " = EXE(" + scenario_name + ");\n";
    for (std::size_t i = 0; i < scenario_.specs.size(); ++i) {
      const Spec& spec = scenario_.specs[i];
      trace_ = spec.trace;
      std::string formula = formula_text(spec.formula);
      if (spec.name == "spec" + std::to_string(i + 1)) {
        out_ += spec.trace + " |= " + formula + ";\n";
      } else {
        out_ += spec.name + " = " + formula + ";\n";
        out_ += spec.trace + " |= " + spec.name + ";\n";
      }
    }
    return header_ + out_;
  }

 private:
  // A parameter read in several places is one variable in the file, so that it stays one
  // parameter when read back.
  void name_shared_parameters() {
    std::map<int, int> uses;
    for_each_value(scenario_, [&](const Value& value, const std::string&, const std::string&) {
      std::vector<int> read;
      collect_parameters(value, read);
      for (int p : read) ++uses[p];
    });
    std::set<std::string> taken;
    taken.insert(scenario_.ego.name);
    for (const Actor& actor : scenario_.vehicles) taken.insert(actor.name);
    for (const Actor& actor : scenario_.pedestrians) taken.insert(actor.name);
    for (const Obstacle& obstacle : scenario_.obstacles) taken.insert(obstacle.name);
    for (const TrafficFlow& flow : scenario_.traffic.flows) taken.insert(flow.name);
    for (const Spec& spec : scenario_.specs) taken.insert({spec.name, spec.trace});
    taken.insert(scenario_.scenario_name.empty() ? "scenario" : scenario_.scenario_name);
    taken.insert(scenario_.trace_name);
    header_ = "// AVUnit printed by scenfuzz\n";
    for (const auto& [parameter, count] : uses) {
      if (count < 2) continue;
      std::string name = "parameter_" + std::to_string(parameter + 1);
      while (!taken.insert(name).second) name += "_";
      shared_[parameter] = name;
      header_ += name + " = " + range_text(parameter) + ";\n";
    }
  }

  std::string range_text(int index) const {
    const Parameter& parameter = scenario_.parameters[static_cast<std::size_t>(index)];
    bool time = parameter.unit == "time of day";
    auto bound = [&](double value) {
      return time ? time_constant_text(value) : format_number(value);
    };
    return "range(" + bound(parameter.lower) + ", " + bound(parameter.upper) + ")";
  }

  static int value_precedence(const Value& value) {
    if (value.op == ValueOp::constant && value.constant < 0) return precedence(ValueOp::negate);
    return precedence(value.op);
  }

  std::string value_text(const Value& value) const {
    switch (value.op) {
      case ValueOp::constant: return format_number(value.constant);
      case ValueOp::parameter: {
        auto shared = shared_.find(value.parameter);
        return shared != shared_.end() ? shared->second : range_text(value.parameter);
      }
      case ValueOp::negate:
        return "-" + operand_text(value.operands[0], precedence(ValueOp::negate));
      default: break;
    }
    static const std::map<ValueOp, std::string> symbols = {{ValueOp::add, " + "},
                                                           {ValueOp::subtract, " - "},
                                                           {ValueOp::multiply, " * "},
                                                           {ValueOp::divide, " / "},
                                                           {ValueOp::power, " ^ "}};
    int level = precedence(value.op);
    // Left-associative: only the right operand needs parentheses at equal precedence.
    return operand_text(value.operands[0], level) + symbols.at(value.op) +
           operand_text(value.operands[1], level + 1);
  }

  std::string operand_text(const Value& value, int level) const {
    std::string text = value_text(value);
    return value_precedence(value) < level ? "(" + text + ")" : text;
  }

  std::string time_text(const Value& value) const {
    return is_constant(value) ? time_constant_text(value.constant) : value_text(value);
  }

  std::string position_text(const Position& position) const {
    if (position.kind == PositionKind::lane)
      return quoted(position.lane) + "->" + value_text(position.s);
    std::string text = "(" + value_text(position.x) + ", " + value_text(position.y);
    if (position.z) text += ", " + value_text(*position.z);
    text += ")";
    if (position.frame == Frame::imu) return "IMU " + text;
    if (position.frame == Frame::wgs84) return "WGS84 " + text;
    return text;
  }

  std::string heading_text(const Heading& heading) const {
    std::string angle = value_text(heading.angle);
    bool atomic = heading.angle.op == ValueOp::constant || heading.angle.op == ValueOp::parameter;
    std::string text = (atomic ? angle : "(" + angle + ")") +
                       (heading.unit == AngleUnit::degree ? " deg" : " rad");
    if (!heading.relative_to) return text;
    const Direction& direction = *heading.relative_to;
    switch (direction.kind) {
      case Direction::Kind::ego: return text + " related to EGO";
      case Direction::Kind::actor: return text + " related to " + direction.actor;
      case Direction::Kind::lane:
        return text + " related to " + quoted(direction.lane) + "->" + value_text(direction.s);
    }
    return text;
  }

  std::string state_text(const State& state) const {
    std::string text = "(" + position_text(state.position);
    if (state.heading || state.speed) text += ", ";
    if (state.heading) text += heading_text(*state.heading);
    if (state.speed) text += ", " + value_text(*state.speed);
    return text + ")";
  }

  static std::string color_text(const Color& color) {
    if (!color.rgb) return color.name;
    const auto& rgb = *color.rgb;
    return "(" + std::to_string(rgb[0]) + ", " + std::to_string(rgb[1]) + ", " +
           std::to_string(rgb[2]) + ")";
  }

  std::string type_text(const ActorType& type) const {
    std::string first = type.height    ? value_text(*type.height)
                        : type.general ? type.model
                                       : quoted(type.model);
    if (type.color) return "(" + first + ", " + color_text(*type.color) + ")";
    return "(" + first + ")";
  }

  std::string motion_text(const Motion& motion) const {
    switch (motion.kind) {
      case MotionKind::follow_route:
      case MotionKind::manoeuvres: return "";
      case MotionKind::uniform: return "uniform(" + state_text(motion.states.at(0)) + ")";
      case MotionKind::random_walk: return "Random(" + state_text(motion.states.at(0)) + ")";
      case MotionKind::waypoints: {
        std::string text = "Waypoint(";
        for (std::size_t i = 0; i < motion.states.size(); ++i)
          text += (i ? ", " : "") + state_text(motion.states[i]);
        return text + ")";
      }
    }
    return "";
  }

  // An actor whose heading is related to another must come after it, as in the source.
  std::string actor_statements() const {
    std::vector<std::pair<const Actor*, const char*>> pending = {{&scenario_.ego, "AV"}};
    for (const Actor& actor : scenario_.vehicles) pending.push_back({&actor, "Vehicle"});
    for (const Actor& actor : scenario_.pedestrians) pending.push_back({&actor, "Pedestrian"});
    std::set<std::string> printed;
    std::string text;
    while (!pending.empty()) {
      auto ready = std::find_if(pending.begin(), pending.end(), [&](const auto& entry) {
        for (const std::string& name : related_actors(*entry.first))
          if (name != entry.first->name && !printed.count(name)) return false;
        return true;
      });
      if (ready == pending.end()) ready = pending.begin();  // a cycle cannot be written anyway
      text += actor_statement(*ready->first, ready->second);
      printed.insert(ready->first->name);
      pending.erase(ready);
    }
    return text;
  }

  static std::vector<std::string> related_actors(const Actor& actor) {
    std::vector<std::string> names;
    auto add = [&](const State& state) {
      if (state.heading && state.heading->relative_to &&
          state.heading->relative_to->kind == Direction::Kind::actor)
        names.push_back(state.heading->relative_to->actor);
    };
    add(actor.initial);
    for (const State& state : actor.motion.states) add(state);
    if (actor.target) add(*actor.target);
    return names;
  }

  std::string actor_statement(const Actor& actor, const std::string& constructor) const {
    std::vector<std::string> arguments = {state_text(actor.initial)};
    if (actor.kind == ActorKind::ego) {
      arguments.push_back(actor.target ? state_text(*actor.target) : "");
    } else {
      arguments.push_back(motion_text(actor.motion));
      arguments.push_back(actor.target ? state_text(*actor.target) : "");
    }
    arguments.push_back(actor.type ? type_text(*actor.type) : "");
    while (arguments.size() > 1 && arguments.back().empty()) arguments.pop_back();
    std::string text = actor.name + " = " + constructor + "(";
    for (std::size_t i = 0; i < arguments.size(); ++i) text += (i ? ", " : "") + arguments[i];
    return text + ");\n";
  }

  std::string obstacle_text(const Obstacle& obstacle) const {
    std::string where = position_text(obstacle.position);
    if (obstacle.heading) where = "(" + where + ", " + heading_text(*obstacle.heading) + ")";
    if (!obstacle.shape) return "Obstacle(" + where + ")";
    static const char* kinds[] = {"sphere", "box", "cone", "cylinder"};
    std::string shape = std::string("(") + kinds[static_cast<int>(obstacle.shape->kind)];
    for (const Value& dimension : obstacle.shape->dimensions) shape += ", " + value_text(dimension);
    return "Obstacle(" + where + ", " + shape + "))";
  }

  static std::string set_text(const std::vector<std::string>& names) {
    std::string text = "{";
    for (std::size_t i = 0; i < names.size(); ++i) text += (i ? ", " : "") + names[i];
    return text + "}";
  }

  static std::string name_set(const std::vector<Actor>& actors) {
    std::vector<std::string> names;
    for (const Actor& actor : actors) names.push_back(actor.name);
    return set_text(names);
  }

  // The road's friction is left out: AVUnit has no syntax for it (only CH-Scenario sets it).
  std::string environment_text(const Environment& environment) const {
    std::string text = "Environment(";
    if (environment.time_of_day) text += time_text(*environment.time_of_day);
    if (!environment.weather.empty()) {
      text += ", {";  // with no time, the first argument is left out
      for (std::size_t i = 0; i < environment.weather.size(); ++i) {
        const WeatherComponent& component = environment.weather[i];
        static const char* levels[] = {"light", "middle", "heavy"};
        text += (i ? ", " : "") + component.kind + ": " +
                (component.level ? levels[static_cast<int>(*component.level)]
                                 : value_text(component.intensity));
      }
      text += "}";
    }
    return text + ")";
  }

  std::string traffic_text(const Traffic& traffic) const {
    std::vector<std::string> items;
    for (const IntersectionControl& control : traffic.intersections) {
      bool numeric =
          !control.id.empty() && control.id.find_first_not_of("0123456789.") == std::string::npos;
      items.push_back("Intersection(" + (numeric ? control.id : quoted(control.id)) + ", " +
                      (control.traffic_light ? "1" : "0") + ", " + (control.stop_sign ? "1" : "0") +
                      ", " + (control.crosswalk ? "1" : "0") + ")");
    }
    for (const SpeedLimit& limit : traffic.speed_limits)
      items.push_back("SpeedLimit(" + quoted(limit.lane) + ", (" + value_text(limit.lower) + ", " +
                      value_text(limit.upper) + "))");
    for (const TrafficFlow& flow : traffic.flows) items.push_back(flow.name);
    for (const TrafficLightSetting& light : traffic.lights)
      items.push_back("TrafficLight(" + quoted(light.id) + ", " + light.color + ")");
    if (scenario_.npc_behaviour)
      items.push_back("NPCBehaviour(" + npc_behaviour_word(*scenario_.npc_behaviour) + ")");
    return set_text(items);
  }

  std::string flow_text(const TrafficFlow& flow) const {
    // Every AVUnit flow has a speed; other languages' flows are printed by their own printers.
    SCENFUZZ_DEMAND(flow.speed.has_value());
    std::string text = "Flow(" + quoted(flow.source_lane) + ", " + value_text(flow.rate) + ", " +
                       value_text(*flow.speed);
    if (!flow.destination_lane.empty()) text += ", " + quoted(flow.destination_lane);
    return text + ")";
  }

  // ---- specifications --------------------------------------------------------------------

  static int term_precedence(const SpecTerm& term) {
    switch (term.kind) {
      case TermKind::add:
      case TermKind::subtract: return 1;
      case TermKind::multiply:
      case TermKind::divide: return 2;
      case TermKind::power: return 3;
      case TermKind::negate: return 4;
      case TermKind::number:
        return term.value.op == ValueOp::constant && term.value.constant >= 0 ? 5
               : term.value.op == ValueOp::parameter                          ? 5
                                                                              : 0;
      default: return 5;
    }
  }

  std::string term_operand(const SpecTerm& term, int level) const {
    std::string text = term_text(term);
    return term_precedence(term) < level ? "(" + text + ")" : text;
  }

  std::string term_text(const SpecTerm& term) const {
    switch (term.kind) {
      case TermKind::number: return value_text(term.value);
      case TermKind::time_of_day: return time_text(term.value);
      case TermKind::word: return term.name;
      case TermKind::signal: {
        if (term.operands.empty()) return term.name;
        std::string text = term.name + "(";
        for (std::size_t i = 0; i < term.operands.size(); ++i)
          text += (i ? ", " : "") + term_text(term.operands[i]);
        return text + ")";
      }
      case TermKind::object:
        if (term.source == ObjectSource::ego) return trace_ + "[ego]";
        return trace_ + (term.source == ObjectSource::truth ? "[truth][" : "[perception][") +
               term.name + "]";
      case TermKind::column: return term_text(term.operands[0]) + "." + term.name;
      case TermKind::position: return position_text(*term.position);
      case TermKind::vector: {
        std::string text = "(";
        for (std::size_t i = 0; i < term.operands.size(); ++i)
          text += (i ? ", " : "") + term_text(term.operands[i]);
        return text + ")";
      }
      case TermKind::negate: return "-" + term_operand(term.operands[0], 5);
      default: break;
    }
    static const std::map<TermKind, std::pair<std::string, int>> symbols = {
        {TermKind::add, {" + ", 1}},
        {TermKind::subtract, {" - ", 1}},
        {TermKind::multiply, {" * ", 2}},
        {TermKind::divide, {" / ", 2}},
        {TermKind::power, {" ^ ", 3}}};
    const auto& [symbol, level] = symbols.at(term.kind);
    return term_operand(term.operands[0], level) + symbol +
           term_operand(term.operands[1], level + 1);
  }

  static int formula_level(const Formula& formula) {
    switch (formula.kind) {
      case FormulaKind::implication: return 1;
      case FormulaKind::disjunction: return 2;
      case FormulaKind::conjunction: return 3;
      case FormulaKind::until: return 4;
      case FormulaKind::comparison: return 5;
      default: return 6;
    }
  }

  static std::string interval_text(const std::optional<TimeInterval>& interval) {
    if (!interval) return "";
    return "[" + format_number(interval->lower) + ":" + format_number(interval->upper) + "]";
  }

  std::string formula_operand(const Formula& formula, int level) const {
    std::string text = formula_text(formula);
    return formula_level(formula) < level ? "(" + text + ")" : text;
  }

  std::string formula_text(const Formula& formula) const {
    static const std::map<CompareOp, std::string> compare = {
        {CompareOp::less, " < "},    {CompareOp::less_equal, " <= "},
        {CompareOp::greater, " > "}, {CompareOp::greater_equal, " >= "},
        {CompareOp::equal, " == "},  {CompareOp::not_equal, " != "}};
    switch (formula.kind) {
      case FormulaKind::comparison:
        return term_text(formula.terms[0]) + compare.at(formula.compare) +
               term_text(formula.terms[1]);
      case FormulaKind::predicate: return term_text(formula.terms[0]);
      case FormulaKind::negation: return "~" + formula_operand(formula.operands[0], 6);
      case FormulaKind::always:
      case FormulaKind::eventually:
      case FormulaKind::next: {
        const char* op = formula.kind == FormulaKind::always       ? "G"
                         : formula.kind == FormulaKind::eventually ? "F"
                                                                   : "X";
        return op + interval_text(formula.interval) + " " + formula_operand(formula.operands[0], 6);
      }
      default: break;
    }
    int level = formula_level(formula);
    std::string op = formula.kind == FormulaKind::implication   ? " -> "
                     : formula.kind == FormulaKind::disjunction ? " | "
                     : formula.kind == FormulaKind::conjunction
                         ? " & "
                         : " U" + interval_text(formula.interval) + " ";
    return formula_operand(formula.operands[0], level) + op +
           formula_operand(formula.operands[1], level + 1);
  }

  const ScenarioTemplate& scenario_;
  std::map<int, std::string> shared_;
  std::string header_;
  std::string trace_;
  std::string out_;
};

}  // namespace

std::string print(const ScenarioTemplate& scenario) { return Printer(scenario).run(); }

std::string print_formula(const ScenarioTemplate& scenario, const Spec& spec,
                          const Formula& formula) {
  return Printer(scenario).formula_text(formula, spec.trace);
}

std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values) {
  // Parameters sharing one span are a coordinate offset `range(a, b) & (c, d)`: x then y.
  SCENFUZZ_DEMAND(parameter_values.size() == scenario.parameters.size());
  std::map<std::uint32_t, std::vector<std::size_t>> by_offset;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    by_offset[scenario.parameters[i].location.offset].push_back(i);
  std::string text = file.text();
  std::string header = "// concrete scenario of " + file.path() + " chosen by scenfuzz:\n";
  for (auto it = by_offset.rbegin(); it != by_offset.rend(); ++it) {
    const std::vector<std::size_t>& group = it->second;
    const Parameter& first = scenario.parameters[group[0]];
    auto value_text = [&](std::size_t index) {
      const Parameter& parameter = scenario.parameters[index];
      double value = parameter_values[index];
      if (parameter.unit == "time of day") return format_time_of_day(value);
      if (parameter.kind == ParameterKind::discrete)
        return "\"" + parameter.choices.at(static_cast<std::size_t>(value)) + "\"";
      return format_number(value);
    };
    std::string replacement = group.size() == 2
                                  ? "+ (" + value_text(group[0]) + ", " + value_text(group[1]) + ")"
                                  : value_text(group[0]);
    if (first.location.end_offset() <= text.size())
      text.replace(first.location.offset, first.location.length, replacement);
  }
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    header += "//   " + parameter_value_text(file, scenario, parameter_values, i) + "\n";
  return header + text;
}

}  // namespace scenfuzz::avunit
