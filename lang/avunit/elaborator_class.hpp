// The AVUnit elaborator (private to lang/avunit): the class that turns parsed statements into
// a scenario template, and the small item helpers its parts share. It evaluates each statement's
// expressions to items (item.hpp), binds variables, and at the end builds the template of the
// scenario the file executes. Its member functions are defined by concern: elaborator.cpp
// (reporting, statements, the template, the public entry points), elaborate_expressions.cpp
// (expressions and parameter ranges), elaborate_calls.cpp (built-in calls: Map, Vehicle,
// Environment, signal functions, ...), elaborate_scenario.cpp (Scenario and its names) and
// elaborate_coercions.cpp (an item needed as a value, position, state, term or formula).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "lang/avunit/builtins.hpp"
#include "lang/avunit/elaborator.hpp"
#include "lang/avunit/item.hpp"
#include "lang/avunit/scenario_choice.hpp"
#include "lang/avunit/template_checks.hpp"
#include "lang/avunit/traffic_extensions.hpp"
#include "lang/edit_distance.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::avunit {

inline constexpr double kPi = std::numbers::pi;

inline ValueOp value_op(TokenKind kind) {
  switch (kind) {
    case TokenKind::plus:
    case TokenKind::dot_plus: return ValueOp::add;
    case TokenKind::minus:
    case TokenKind::dot_minus: return ValueOp::subtract;
    case TokenKind::star:
    case TokenKind::dot_star: return ValueOp::multiply;
    case TokenKind::slash:
    case TokenKind::dot_slash: return ValueOp::divide;
    default: return ValueOp::power;
  }
}

inline TermKind term_op(ValueOp op) {
  switch (op) {
    case ValueOp::add: return TermKind::add;
    case ValueOp::subtract: return TermKind::subtract;
    case ValueOp::multiply: return TermKind::multiply;
    case ValueOp::divide: return TermKind::divide;
    default: return TermKind::power;
  }
}

inline CompareOp compare_op(TokenKind kind) {
  switch (kind) {
    case TokenKind::less: return CompareOp::less;
    case TokenKind::less_equal: return CompareOp::less_equal;
    case TokenKind::greater: return CompareOp::greater;
    case TokenKind::greater_equal: return CompareOp::greater_equal;
    case TokenKind::equal: return CompareOp::equal;
    default: return CompareOp::not_equal;
  }
}

inline bool is_comparison(TokenKind kind) {
  return kind == TokenKind::less || kind == TokenKind::less_equal || kind == TokenKind::greater ||
         kind == TokenKind::greater_equal || kind == TokenKind::equal ||
         kind == TokenKind::not_equal;
}

inline bool is_numeric(const Item& item) {
  return item.kind == ItemKind::number || item.kind == ItemKind::time;
}

inline bool all_numbers(const Item& item) {
  return item.kind == ItemKind::tuple && !item.elements.empty() &&
         std::all_of(item.elements.begin(), item.elements.end(),
                     [](const Item& e) { return e.kind == ItemKind::number; });
}

inline Item make_item(ItemKind kind, SourceLocation location) {
  Item item;
  item.kind = kind;
  item.location = location;
  return item;
}

template <class T>
inline Item make_item(ItemKind kind, SourceLocation location, T payload) {
  Item item = make_item(kind, location);
  item.payload = Boxed<T>(std::move(payload));
  return item;
}

inline Item number_item(Value value, SourceLocation location, ItemKind kind = ItemKind::number) {
  Item item = make_item(kind, location);
  item.value = std::move(value);
  return item;
}

class Elaborator {
 public:
  Elaborator(Diagnostics& diagnostics, SourceLanguage language, ScenarioRequest request = {})
      : diagnostics_(diagnostics), language_(language), request_(std::move(request)) {}
  // A lone formula whose unknown names are signals (`scenfuzz stl`: columns of a CSV file).
  std::optional<Formula> lone_formula(const Syntax& syntax);
  void add(const Statement& statement);
  ScenarioTemplate finish() { return build_template(); }
  const std::vector<std::string>& scenario_names() const { return scenario_names_; }

 private:
  // ---- reporting -------------------------------------------------------------------------

  Item fail(SourceLocation where, const std::string& message);
  // Reports "expected X, found Y" unless the item is already an error.
  void mismatch(const Item& item, const std::string& expected);
  std::string suggestion(const std::string& name) const;

  // ---- statements ------------------------------------------------------------------------

  void bind(const std::string& name, Item item);
  static bool reserved(const std::string& name);
  void assign(const Statement& statement);
  void declare_trace(const Statement& statement);
  void assert_spec(const Statement& statement);

  // ---- expressions -----------------------------------------------------------------------

  Item evaluate(const Syntax& syntax);
  Item identifier(const Syntax& syntax);
  Item signal_item(const std::string& name, std::vector<SpecTerm> arguments,
                   SourceLocation location);
  Item member(const Syntax& syntax);
  // trace[ego].speed, npc_truth.x: a numeric column of a projection.
  Item projection_column(const Syntax& syntax, const Item& projection);
  Item binary(const Syntax& syntax);
  Item logical(FormulaKind kind, const Item& left, const Item& right, SourceLocation location);
  // `"lane_1"->20` is a lane position; between formulas `->` is implication.
  Item arrow(const Syntax& syntax);
  static std::string reaches(const Value& value, double extreme);
  bool check_not_negative(const Value& value, SourceLocation where, const std::string& what);
  Item arithmetic(ValueOp op, const Item& left, const Item& right, SourceLocation location);
  static bool is_term_like(const Item& item);
  // (x1, y1) + (x2, y2): coordinates add element by element; a frame on either side is kept.
  Item coordinate_arithmetic(ValueOp op, const Item& left, const Item& right,
                             SourceLocation location);
  Item unary(const Syntax& syntax);
  std::optional<TimeInterval> interval(const std::optional<IntervalSyntax>& written);
  Item temporal(const Syntax& syntax);
  Item until(const Syntax& syntax);
  // trace[ego], trace[truth][npc1], trace['perception']["npc1"]
  Item index(const Syntax& syntax);
  bool is_ego_variable(const std::string& name) const;
  // 90 deg, range(-5, 5) deg related to "lane_1"->20, 1.2 rad related to npc1
  Item angle(const Syntax& syntax);
  std::optional<Direction> direction(const Syntax& syntax);
  // (x, y) range(a, b) & (c, d): x + an offset in [a, b], y + an offset in [c, d].
  Item coordinate_range(const Syntax& syntax);
  std::optional<Value> offset_parameter(const Syntax& bounds, SourceLocation range_location,
                                        const std::string& axis);

  // ---- parameters ------------------------------------------------------------------------

  std::optional<double> constant_bound(const Item& item);
  std::optional<Value> new_parameter(const Item& lower_item, const Item& upper_item,
                                     SourceLocation where, SourceLocation range_location);
  Item range(const Syntax& syntax, const std::vector<Item>& arguments);

  // ---- calls -----------------------------------------------------------------------------

  Item call(const Syntax& syntax);
  bool check_arity(const Syntax& syntax, const std::vector<Item>& arguments, std::size_t least,
                   std::size_t most, const std::string& form);
  static bool given(const std::vector<Item>& arguments, std::size_t i);
  Item map(const Syntax& syntax, const std::vector<Item>& arguments);
  Item ego(const Syntax& syntax, const std::vector<Item>& arguments);
  // Vehicle(init[, motion[, target[, type]]]) and Pedestrian(...) with any slot left empty.
  Item actor(const Syntax& syntax, const std::vector<Item>& arguments, ActorKind kind);
  Item obstacle(const Syntax& syntax, const std::vector<Item>& arguments);
  Item motion(const Syntax& syntax, const std::vector<Item>& arguments);
  // IMU (x, y), ENU((1, 2) + offset), WGS84 (lon, lat)
  Item framed(const Syntax& syntax, const std::vector<Item>& arguments);
  Item environment(const Syntax& syntax, const std::vector<Item>& arguments);
  bool weather(const Item& item, std::vector<WeatherComponent>& components);
  bool check_fraction(const Value& value, SourceLocation where, const std::string& what);
  Item intersection(const Syntax& syntax, const std::vector<Item>& arguments);
  Item speed_limit(const Syntax& syntax, const std::vector<Item>& arguments);
  Item npc_behaviour(const Syntax& syntax);
  Item flow(const Syntax& syntax, const std::vector<Item>& arguments);
  Item traffic_light(const Syntax& syntax);
  // dis(a, b), vel(a, b), spd(a, b), acc(a, b), diff(perceived, truth)
  Item signal_function(const Syntax& syntax, const std::vector<Item>& arguments);
  std::optional<SpecTerm> function_argument(const std::string& function, const Item& argument);
  // A vel/acc vector: `(x, y)`, `(x, y, z)` or coordinates summed to one, such as `(1, 2, -3) + v`.
  // The grammar's <velocity> is a <coordinate>, whose third component is the frame's up axis
  // (ENU/IMU are east-north-up / right-forward-up), so z is the vertical component. Only ENU:
  // a vector in another frame would have to be rotated, which the oracle does not do.
  std::optional<SpecTerm> vector_argument(const Item& argument);
  // stoplineAhead(2): true while the stop line is within 2 m. The distance is a constant.
  Item distance_predicate(const Syntax& syntax, const std::vector<Item>& arguments);

  // ---- scenario --------------------------------------------------------------------------

  Item scenario(const Syntax& syntax);
  // Sets flatten: `{npc1, npc2}`, a variable holding such a set, or `{npcs}`.
  static void flatten(const Item& item, std::vector<const Item*>& out);
  static std::string fresh_name(const std::string& stem, std::set<std::string>& names);
  bool claim_name(const std::string& name, SourceLocation where, std::set<std::string>& names);
  bool collect_actors(const Item& slot, ActorKind kind, const std::string& stem,
                      std::vector<Actor>& actors, std::set<std::string>& names);
  bool collect_obstacles(const Item& slot, std::vector<Obstacle>& obstacles,
                         std::set<std::string>& names);
  // Flows are named like actors (`flow1`, or their variable), in one namespace with them.
  bool traffic(const Item& slot, ScenarioParts& parts, std::set<std::string>& names);

  // ---- coercions at use sites ------------------------------------------------------------

  std::optional<Value> need_value(const Item& item, const std::string& expected);
  std::optional<Position> need_position(const Item& item, bool report = true);
  // (position), (position, heading), (position, heading, speed), (position, , speed)
  std::optional<State> need_state(const Item& item, bool report = true);
  // A list of states `((s1), (s2))`, or a single state.
  std::optional<std::vector<State>> need_states(const Item& item);
  std::optional<Color> need_color(const Item& item);
  // Vehicles: "model", car, ("model", colour). Pedestrians: "model", (height, colour).
  std::optional<ActorType> need_actor_type(const Item& item, bool pedestrian);
  std::optional<Shape> need_shape(const Item& item);
  std::optional<SpecTerm> need_term(const Item& item);
  std::optional<Formula> need_formula(const Item& item);

  // ---- the template ----------------------------------------------------------------------

  // A scenario the file executes (or, executing none, creates), with how a user names it.
  struct Candidate {
    std::shared_ptr<const ScenarioParts> parts;
    ScenarioCandidate described;
  };

  // The first variable, by name, bound to the scenario `parts` ("" when none is).
  std::string variable_of(const std::shared_ptr<const ScenarioParts>& parts) const;
  // Each executed scenario once, in the order of its first trace; with no trace, every scenario
  // the file creates.
  std::vector<Candidate> candidates() const;
  // One candidate as a template: its parts, the specs asserted on its traces, every parameter.
  ScenarioTemplate template_of(const Candidate& candidate) const;
  ScenarioTemplate build_template();
  Diagnostics& diagnostics_;
  SourceLanguage language_;
  bool free_signals_ = false;  // unknown names are signals (lone formulas)
  std::map<std::string, Item> variables_;
  // The same names side by side: a suggestion weighs every one, and walking the map's nodes for
  // that cost a cache miss each (seconds for 25 errors in a file of 400,000 names).
  std::vector<std::string> names_;
  std::vector<Parameter> parameters_;
  std::vector<std::shared_ptr<const ScenarioParts>> scenarios_;
  // A `Trace name = EXE(scenario);`: which scenario the trace's specs judge.
  struct TraceBinding {
    std::string name;
    std::shared_ptr<const ScenarioParts> parts;
    SourceLocation location;
  };
  ScenarioRequest request_;
  std::vector<TraceBinding> traces_;
  std::vector<std::string> scenario_names_;
  std::string current_trace_;
  std::vector<Spec> specs_;
  std::vector<std::shared_ptr<const ScenarioParts>> spec_parts_;  // the scenario each spec judges
};

}  // namespace scenfuzz::avunit
