#include "lang/avunit/elaborator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "lang/avunit/builtins.hpp"
#include "lang/avunit/item.hpp"
#include "lang/avunit/scenario_choice.hpp"
#include "lang/avunit/template_checks.hpp"
#include "lang/avunit/traffic_extensions.hpp"
#include "lang/edit_distance.hpp"
#include "lang/number_format.hpp"

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
  }
  return "a value";
}

namespace {

constexpr double kPi = std::numbers::pi;

ValueOp value_op(TokenKind kind) {
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

TermKind term_op(ValueOp op) {
  switch (op) {
    case ValueOp::add: return TermKind::add;
    case ValueOp::subtract: return TermKind::subtract;
    case ValueOp::multiply: return TermKind::multiply;
    case ValueOp::divide: return TermKind::divide;
    default: return TermKind::power;
  }
}

CompareOp compare_op(TokenKind kind) {
  switch (kind) {
    case TokenKind::less: return CompareOp::less;
    case TokenKind::less_equal: return CompareOp::less_equal;
    case TokenKind::greater: return CompareOp::greater;
    case TokenKind::greater_equal: return CompareOp::greater_equal;
    case TokenKind::equal: return CompareOp::equal;
    default: return CompareOp::not_equal;
  }
}

bool is_comparison(TokenKind kind) {
  return kind == TokenKind::less || kind == TokenKind::less_equal || kind == TokenKind::greater ||
         kind == TokenKind::greater_equal || kind == TokenKind::equal ||
         kind == TokenKind::not_equal;
}

bool is_numeric(const Item& item) {
  return item.kind == ItemKind::number || item.kind == ItemKind::time;
}

bool all_numbers(const Item& item) {
  return item.kind == ItemKind::tuple && !item.elements.empty() &&
         std::all_of(item.elements.begin(), item.elements.end(),
                     [](const Item& e) { return e.kind == ItemKind::number; });
}

Item make_item(ItemKind kind, SourceLocation location) {
  Item item;
  item.kind = kind;
  item.location = location;
  return item;
}

template <class T>
Item make_item(ItemKind kind, SourceLocation location, T payload) {
  Item item = make_item(kind, location);
  item.payload = Boxed<T>(std::move(payload));
  return item;
}

Item number_item(Value value, SourceLocation location, ItemKind kind = ItemKind::number) {
  Item item = make_item(kind, location);
  item.value = std::move(value);
  return item;
}

}  // namespace

class Elaborator {
 public:
  Elaborator(Diagnostics& diagnostics, SourceLanguage language, ScenarioRequest request = {})
      : diagnostics_(diagnostics), language_(language), request_(std::move(request)) {}

  // A lone formula whose unknown names are signals (`scenfuzz stl`: columns of a CSV file).
  std::optional<Formula> lone_formula(const Syntax& syntax) {
    free_signals_ = true;
    Item item = evaluate(syntax);
    if (item.kind == ItemKind::error) return std::nullopt;
    std::optional<Formula> formula = need_formula(item);
    if (diagnostics_.has_errors()) return std::nullopt;
    return formula;
  }

  void add(const Statement& statement) {
    if (diagnostics_.too_many_errors()) return;
    switch (statement.kind) {
      case StatementKind::assignment: assign(statement); break;
      case StatementKind::trace_declaration: declare_trace(statement); break;
      case StatementKind::assertion: assert_spec(statement); break;
    }
  }

  ScenarioTemplate finish() { return build_template(); }

  const std::vector<std::string>& scenario_names() const { return scenario_names_; }

 private:
  // ---- reporting -------------------------------------------------------------------------

  Item fail(SourceLocation where, const std::string& message) {
    diagnostics_.error(where, message);
    return make_item(ItemKind::error, where);
  }

  // Reports "expected X, found Y" unless the item is already an error.
  void mismatch(const Item& item, const std::string& expected) {
    if (item.kind != ItemKind::error)
      diagnostics_.error(item.location, "expected " + expected + ", found " + describe(item));
  }

  std::string suggestion(const std::string& name) const {
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

  // ---- statements ------------------------------------------------------------------------

  void bind(const std::string& name, Item item) {
    auto [found, added] = variables_.insert_or_assign(name, std::move(item));
    if (added) names_.push_back(name);
  }

  static bool reserved(const std::string& name) {
    return name == "G" || name == "F" || name == "X" || name == "U";
  }

  void assign(const Statement& statement) {
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

  void declare_trace(const Statement& statement) {
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

  void assert_spec(const Statement& statement) {
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

  // ---- expressions -----------------------------------------------------------------------

  Item evaluate(const Syntax& syntax) {
    switch (syntax.kind) {
      case SyntaxKind::error: return make_item(ItemKind::error, syntax.location);
      case SyntaxKind::number:
        return number_item(constant_value(syntax.number, syntax.location), syntax.location);
      case SyntaxKind::time:
        return number_item(constant_value(syntax.number, syntax.location), syntax.location,
                           ItemKind::time);
      case SyntaxKind::string: {
        Item item = make_item(ItemKind::string, syntax.location);
        item.word = syntax.text;
        return item;
      }
      case SyntaxKind::identifier: return identifier(syntax);
      case SyntaxKind::empty: return make_item(ItemKind::empty, syntax.location);
      case SyntaxKind::star: return make_item(ItemKind::star, syntax.location);
      case SyntaxKind::tuple: {
        Item item = make_item(ItemKind::tuple, syntax.location);
        for (const Syntax& child : syntax.children) item.elements.push_back(evaluate(child));
        if (syntax.parenthesised) {  // (x) only groups
          Item inner = std::move(item.elements[0]);
          return inner;
        }
        return item;
      }
      case SyntaxKind::set: {
        Item item = make_item(ItemKind::set, syntax.location);
        for (const Syntax& child : syntax.children) item.elements.push_back(evaluate(child));
        return item;
      }
      case SyntaxKind::keyed: {
        Item item = make_item(ItemKind::keyed, syntax.location);
        item.word = syntax.text;
        item.elements.push_back(evaluate(syntax.children[0]));
        return item;
      }
      case SyntaxKind::call: return call(syntax);
      case SyntaxKind::scenario: return scenario(syntax);
      case SyntaxKind::binary: return binary(syntax);
      case SyntaxKind::unary: return unary(syntax);
      case SyntaxKind::temporal: return temporal(syntax);
      case SyntaxKind::until: return until(syntax);
      case SyntaxKind::index: return index(syntax);
      case SyntaxKind::member: return member(syntax);
      case SyntaxKind::angle: return angle(syntax);
      case SyntaxKind::pi: {
        Item factor = evaluate(syntax.children[0]);
        std::optional<Value> value = need_value(factor, "a number before 'pi'");
        if (!value) return make_item(ItemKind::error, syntax.location);
        return number_item(binary_value(ValueOp::multiply, *value, constant_value(kPi)),
                           syntax.location);
      }
      case SyntaxKind::coordinate_range: return coordinate_range(syntax);
    }
    return fail(syntax.location, "unsupported expression");
  }

  Item identifier(const Syntax& syntax) {
    const std::string& name = syntax.text;
    if (auto found = variables_.find(name); found != variables_.end()) {
      Item item = found->second;
      item.location = syntax.location;
      return item;
    }
    if (name == "pi") return number_item(constant_value(kPi, syntax.location), syntax.location);
    if (name == "EGO" || name == "ego" || name == "truth" || name == "perception" ||
        is_color_word(name) || is_vehicle_kind_word(name) || is_shape_word(name) ||
        is_weather_level(name) || is_enumeration_word(name)) {
      Item item = make_item(ItemKind::word, syntax.location);
      item.word = name;
      return item;
    }
    // A lone formula's bare names are its data's columns, built-in names included.
    if (free_signals_) return signal_item(name, {}, syntax.location);
    switch (signal_class(name)) {
      case SignalClass::flag:
      case SignalClass::value: return signal_item(name, {}, syntax.location);
      case SignalClass::distance_predicate:
        return fail(syntax.location, "'" + name + "' needs a distance: write '" + name + "(2)'");
      case SignalClass::function:
        // scenest's `acc` is also the ego's acceleration, the function's name without a call.
        if (name == "acc") return signal_item(name, {}, syntax.location);
        return fail(syntax.location,
                    "'" + name + "' is a function of two arguments: write '" + name + "(a, b)'");
      case SignalClass::none: break;
    }
    return fail(syntax.location, "'" + name + "' is not defined" + suggestion(name));
  }

  Item signal_item(const std::string& name, std::vector<SpecTerm> arguments,
                   SourceLocation location) {
    SpecTerm term;
    term.kind = TermKind::signal;
    term.name = name;
    term.operands = std::move(arguments);
    term.location = location;
    return make_item(ItemKind::term, location, std::move(term));
  }

  Item member(const Syntax& syntax) {
    const Syntax& object = syntax.children[0];
    if (object.kind == SyntaxKind::index ||
        (object.kind == SyntaxKind::identifier && variables_.count(object.text))) {
      Item base = evaluate(object);
      if (base.kind == ItemKind::error) return base;
      if (base.kind == ItemKind::projection) return projection_column(syntax, base);
      return fail(syntax.location, "'." + syntax.text +
                                       "' can only follow a trace projection (trace[ego]." +
                                       syntax.text +
                                       ") or a signal name such as "
                                       "'trafficLightAhead'");
    }
    // Dotted signal names: trafficLightAhead.direction.color.
    std::string dotted = syntax.text;
    const Syntax* base = &object;
    while (base->kind == SyntaxKind::member) {
      dotted = base->text + "." + dotted;
      base = &base->children[0];
    }
    if (base->kind != SyntaxKind::identifier || variables_.count(base->text))
      return fail(syntax.location, "'." + syntax.text +
                                       "' can only follow a signal name such as "
                                       "'trafficLightAhead'");
    dotted = base->text + "." + dotted;
    SignalClass kind = signal_class(dotted);
    if (free_signals_ && kind == SignalClass::none) return signal_item(dotted, {}, syntax.location);
    if (kind != SignalClass::flag && kind != SignalClass::value)
      return fail(syntax.location, "unknown signal '" + dotted + "'" + suggestion(dotted));
    return signal_item(dotted, {}, syntax.location);
  }

  // trace[ego].speed, npc_truth.x: a numeric column of a projection.
  Item projection_column(const Syntax& syntax, const Item& projection) {
    if (!is_trace_column(syntax.text))
      return fail(syntax.location, "a trace projection has no column '" + syntax.text +
                                       "'; its columns are " + trace_column_list());
    std::optional<SpecTerm> object = need_term(projection);
    if (!object) return make_item(ItemKind::error, syntax.location);
    SpecTerm term;
    term.kind = TermKind::column;
    term.name = syntax.text;
    term.operands.push_back(std::move(*object));
    term.location = syntax.location;
    return make_item(ItemKind::term, syntax.location, std::move(term));
  }

  Item binary(const Syntax& syntax) {
    TokenKind op = syntax.op;
    if (op == TokenKind::arrow) return arrow(syntax);
    Item left = evaluate(syntax.children[0]);
    Item right = evaluate(syntax.children[1]);
    if (left.kind == ItemKind::error || right.kind == ItemKind::error)
      return make_item(ItemKind::error, syntax.location);
    if (op == TokenKind::ampersand || op == TokenKind::bar) {
      return logical(
          op == TokenKind::ampersand ? FormulaKind::conjunction : FormulaKind::disjunction, left,
          right, syntax.location);
    }
    if (is_comparison(op)) {
      std::optional<SpecTerm> a = need_term(left), b = need_term(right);
      if (!a || !b) return make_item(ItemKind::error, syntax.location);
      Formula formula;
      formula.kind = FormulaKind::comparison;
      formula.compare = compare_op(op);
      formula.terms = {std::move(*a), std::move(*b)};
      formula.location = syntax.location;
      return make_item(ItemKind::formula, syntax.location, std::move(formula));
    }
    return arithmetic(value_op(op), left, right, syntax.location);
  }

  Item logical(FormulaKind kind, const Item& left, const Item& right, SourceLocation location) {
    std::optional<Formula> a = need_formula(left), b = need_formula(right);
    if (!a || !b) return make_item(ItemKind::error, location);
    Formula formula;
    formula.kind = kind;
    formula.operands = {std::move(*a), std::move(*b)};
    formula.location = location;
    return make_item(ItemKind::formula, location, std::move(formula));
  }

  // `"lane_1"->20` is a lane position; between formulas `->` is implication.
  Item arrow(const Syntax& syntax) {
    const Syntax& lhs = syntax.children[0];
    Item left = evaluate(lhs);
    if (left.kind == ItemKind::string ||
        (left.kind == ItemKind::number && lhs.kind == SyntaxKind::number)) {
      Item offset = evaluate(syntax.children[1]);
      std::optional<Value> s = need_value(offset, "an arc length along the lane");
      if (!s) return make_item(ItemKind::error, syntax.location);
      Position position;
      position.kind = PositionKind::lane;
      position.lane = left.kind == ItemKind::string ? left.word : lhs.text;
      position.s = std::move(*s);
      position.location = syntax.location;
      if (position.lane.empty()) return fail(lhs.location, "a lane id cannot be empty");
      if (!check_not_negative(position.s, offset.location, "an arc length along a lane"))
        return make_item(ItemKind::error, syntax.location);
      return make_item(ItemKind::position, syntax.location, std::move(position));
    }
    Item right = evaluate(syntax.children[1]);
    if (left.kind == ItemKind::error || right.kind == ItemKind::error)
      return make_item(ItemKind::error, syntax.location);
    return logical(FormulaKind::implication, left, right, syntax.location);
  }

  static std::string reaches(const Value& value, double extreme) {
    return (is_constant(value) ? "found " : "but it can reach ") + format_number(extreme);
  }

  bool check_not_negative(const Value& value, SourceLocation where, const std::string& what) {
    double lowest = value_range(value, parameters_).lower;
    if (lowest < 0.0) {
      diagnostics_.error(where, what + " cannot be negative, " + reaches(value, lowest));
      return false;
    }
    return true;
  }

  Item arithmetic(ValueOp op, const Item& left, const Item& right, SourceLocation location) {
    if (is_numeric(left) && is_numeric(right)) {
      Value result = binary_value(op, left.value, right.value, location);
      if (is_constant(result) && !std::isfinite(result.constant))
        return fail(location, op == ValueOp::divide && right.value.constant == 0.0
                                  ? "division by zero"
                                  : "the result is too large to represent");
      bool time = (left.kind == ItemKind::time || right.kind == ItemKind::time) &&
                  (op == ValueOp::add || op == ValueOp::subtract);
      return number_item(std::move(result), location, time ? ItemKind::time : ItemKind::number);
    }
    if (op == ValueOp::add && left.kind == ItemKind::string && right.kind == ItemKind::string) {
      Item item = make_item(ItemKind::string, location);
      item.word = left.word + right.word;
      return item;
    }
    if ((op == ValueOp::add || op == ValueOp::subtract) &&
        (left.kind == ItemKind::position || all_numbers(left)) &&
        (right.kind == ItemKind::position || all_numbers(right)))
      return coordinate_arithmetic(op, left, right, location);
    if ((op == ValueOp::multiply || op == ValueOp::divide) && all_numbers(left) &&
        right.kind == ItemKind::number) {
      Item item = make_item(ItemKind::tuple, location);
      for (const Item& element : left.elements)
        item.elements.push_back(arithmetic(op, element, right, location));
      return item;
    }
    if (op == ValueOp::multiply && left.kind == ItemKind::number && all_numbers(right))
      return arithmetic(op, right, left, location);
    if (is_term_like(left) || is_term_like(right)) {
      std::optional<SpecTerm> a = need_term(left), b = need_term(right);
      if (!a || !b) return make_item(ItemKind::error, location);
      SpecTerm term;
      term.kind = term_op(op);
      term.operands = {std::move(*a), std::move(*b)};
      term.location = location;
      return make_item(ItemKind::term, location, std::move(term));
    }
    return fail(location, "cannot combine " + describe(left) + " and " + describe(right) +
                              " with this arithmetic operator");
  }

  static bool is_term_like(const Item& item) {
    return item.kind == ItemKind::term || item.kind == ItemKind::projection;
  }

  // (x1, y1) + (x2, y2): coordinates add element by element; a frame on either side is kept.
  Item coordinate_arithmetic(ValueOp op, const Item& left, const Item& right,
                             SourceLocation location) {
    std::optional<Position> a = need_position(left), b = need_position(right);
    if (!a || !b) return make_item(ItemKind::error, location);
    if (a->kind != PositionKind::coordinate || b->kind != PositionKind::coordinate)
      return fail(location, "only coordinates can be added or subtracted, not lane positions");
    if (a->frame != Frame::enu && b->frame != Frame::enu && a->frame != b->frame)
      return fail(location, "cannot combine coordinates in two different frames");
    Position result = *a;
    if (result.frame == Frame::enu) result.frame = b->frame;
    result.x = binary_value(op, a->x, b->x, location);
    result.y = binary_value(op, a->y, b->y, location);
    if (a->z || b->z)
      result.z = binary_value(op, a->z.value_or(constant_value(0)),
                              b->z.value_or(constant_value(0)), location);
    result.location = location;
    return make_item(ItemKind::position, location, std::move(result));
  }

  Item unary(const Syntax& syntax) {
    Item operand = evaluate(syntax.children[0]);
    if (operand.kind == ItemKind::error) return operand;
    if (syntax.op == TokenKind::tilde) {
      std::optional<Formula> inner = need_formula(operand);
      if (!inner) return make_item(ItemKind::error, syntax.location);
      Formula formula;
      formula.kind = FormulaKind::negation;
      formula.operands.push_back(std::move(*inner));
      formula.location = syntax.location;
      return make_item(ItemKind::formula, syntax.location, std::move(formula));
    }
    if (syntax.op == TokenKind::plus) {
      operand.location = syntax.location;
      return operand;
    }
    if (operand.kind == ItemKind::number) {
      return number_item(negated_value(operand.value, syntax.location), syntax.location);
    }
    if (operand.kind == ItemKind::heading) {  // `-5 deg`: the sign belongs to the angle
      Heading& heading = payload_of<Heading>(operand);
      heading.angle = negated_value(heading.angle, syntax.location);
      heading.location = syntax.location;
      operand.location = syntax.location;
      return operand;
    }
    if (all_numbers(operand)) {
      for (Item& element : operand.elements) element.value = negated_value(element.value);
      operand.location = syntax.location;
      return operand;
    }
    if (is_term_like(operand)) {
      std::optional<SpecTerm> inner = need_term(operand);
      if (!inner) return make_item(ItemKind::error, syntax.location);
      SpecTerm term;
      term.kind = TermKind::negate;
      term.operands.push_back(std::move(*inner));
      term.location = syntax.location;
      return make_item(ItemKind::term, syntax.location, std::move(term));
    }
    return fail(syntax.location, "cannot negate " + describe(operand));
  }

  std::optional<TimeInterval> interval(const std::optional<IntervalSyntax>& written) {
    if (!written) return std::nullopt;
    if (written->lower > written->upper) {
      diagnostics_.error(written->location,
                         "inverted interval: the lower bound " + format_number(written->lower) +
                             " is above the upper bound " + format_number(written->upper));
    }
    return TimeInterval{written->lower, written->upper};
  }

  Item temporal(const Syntax& syntax) {
    Item operand = evaluate(syntax.children[0]);
    std::optional<Formula> inner = need_formula(operand);
    std::optional<TimeInterval> window = interval(syntax.interval);
    if (!inner) return make_item(ItemKind::error, syntax.location);
    Formula formula;
    // `X[a, b] p` is read as `F[a, b] p` (docs/avunit.md): "p at some time between a and b
    // seconds from now". The literal MTL reading (the next sample, if it is a to b seconds away)
    // is false at every sample of a fixed-step trace, which is not what a file means by it.
    formula.kind = syntax.text == "G"                      ? FormulaKind::always
                   : syntax.text == "F" || syntax.interval ? FormulaKind::eventually
                                                           : FormulaKind::next;
    formula.interval = window;
    formula.operands.push_back(std::move(*inner));
    formula.location = syntax.location;
    return make_item(ItemKind::formula, syntax.location, std::move(formula));
  }

  Item until(const Syntax& syntax) {
    Item left = evaluate(syntax.children[0]);
    Item right = evaluate(syntax.children[1]);
    std::optional<TimeInterval> window = interval(syntax.interval);
    Item result = logical(FormulaKind::until, left, right, syntax.location);
    if (result.kind == ItemKind::formula) payload_of<Formula>(result).interval = window;
    return result;
  }

  // trace[ego], trace[truth][npc1], trace['perception']["npc1"]
  Item index(const Syntax& syntax) {
    Item base = evaluate(syntax.children[0]);
    if (base.kind == ItemKind::error) return base;
    const Syntax& key = syntax.children[1];
    if (key.kind != SyntaxKind::identifier && key.kind != SyntaxKind::string)
      return fail(key.location, "expected a name inside [...], such as ego, truth or npc1");
    const std::string& name = key.text;
    if (base.kind == ItemKind::trace) {
      Projection projection;
      projection.trace = base.word;
      if (name == "ego" || is_ego_variable(name)) {
        projection.complete = true;
      } else if (name == "truth" || name == "perception") {
        projection.source = name == "truth" ? ObjectSource::truth : ObjectSource::perception;
      } else {
        return fail(key.location, "expected ego, truth or perception inside " + base.word +
                                      "[...], found '" + name + "'");
      }
      return make_item(ItemKind::projection, syntax.location, projection);
    }
    if (base.kind == ItemKind::projection && !payload_of<Projection>(base).complete) {
      Projection projection = payload_of<Projection>(base);
      auto found = variables_.find(name);
      if (found == variables_.end())
        return fail(key.location, "'" + name + "' is not defined" + suggestion(name));
      const Item& agent = found->second;
      if (agent.kind == ItemKind::actor) {
        projection.agent = payload_of<Actor>(agent).name;
      } else if (agent.kind == ItemKind::obstacle) {
        projection.agent = payload_of<Obstacle>(agent).name;
      } else {
        if (agent.kind != ItemKind::error)
          fail(key.location,
               "expected a vehicle, pedestrian or obstacle inside [...], found " + describe(agent));
        return make_item(ItemKind::error, syntax.location);
      }
      projection.complete = true;
      return make_item(ItemKind::projection, syntax.location, projection);
    }
    return fail(syntax.location, "only a trace can be indexed, not " + describe(base));
  }

  bool is_ego_variable(const std::string& name) const {
    auto found = variables_.find(name);
    return found != variables_.end() && found->second.kind == ItemKind::actor &&
           payload_of<Actor>(found->second).kind == ActorKind::ego;
  }

  // 90 deg, range(-5, 5) deg related to "lane_1"->20, 1.2 rad related to npc1
  Item angle(const Syntax& syntax) {
    Item magnitude = evaluate(syntax.children[0]);
    std::optional<Value> value = need_value(magnitude, "an angle before '" + syntax.text + "'");
    if (!value) return make_item(ItemKind::error, syntax.location);
    Heading heading;
    heading.angle = std::move(*value);
    heading.unit = syntax.text == "deg" ? AngleUnit::degree : AngleUnit::radian;
    heading.location = syntax.location;
    if (syntax.children.size() == 2) {
      std::optional<Direction> direction = this->direction(syntax.children[1]);
      if (!direction) return make_item(ItemKind::error, syntax.location);
      heading.relative_to = std::move(direction);
    }
    return make_item(ItemKind::heading, syntax.location, std::move(heading));
  }

  std::optional<Direction> direction(const Syntax& syntax) {
    Direction direction;
    direction.location = syntax.location;
    if (syntax.kind == SyntaxKind::identifier && syntax.text == "EGO" && !variables_.count("EGO")) {
      direction.kind = Direction::Kind::ego;
      return direction;
    }
    Item target = evaluate(syntax);
    if (target.kind == ItemKind::position &&
        payload_of<Position>(target).kind == PositionKind::lane) {
      const Position& lane = payload_of<Position>(target);
      direction.kind = Direction::Kind::lane;
      direction.lane = lane.lane;
      direction.s = lane.s;
      return direction;
    }
    if (target.kind == ItemKind::actor && !payload_of<Actor>(target).name.empty()) {
      direction.kind = Direction::Kind::actor;
      direction.actor = payload_of<Actor>(target).name;
      return direction;
    }
    mismatch(target, "a lane position, a named actor or EGO after 'related to'");
    return std::nullopt;
  }

  // (x, y) range(a, b) & (c, d): x + an offset in [a, b], y + an offset in [c, d].
  Item coordinate_range(const Syntax& syntax) {
    Item base = evaluate(syntax.children[0]);
    std::optional<Position> position = need_position(base);
    if (!position) return make_item(ItemKind::error, syntax.location);
    if (position->kind != PositionKind::coordinate)
      return fail(base.location,
                  "'range(...) & (...)' offsets a coordinate, not a lane position: "
                  "write \"lane\"->range(a, b)");
    SourceLocation range_location = span(syntax.children[1].location, syntax.children[2].location);
    std::optional<Value> dx = offset_parameter(syntax.children[1], range_location, "x");
    std::optional<Value> dy = offset_parameter(syntax.children[2], range_location, "y");
    if (!dx || !dy) return make_item(ItemKind::error, syntax.location);
    position->x = binary_value(ValueOp::add, position->x, *dx, syntax.location);
    position->y = binary_value(ValueOp::add, position->y, *dy, syntax.location);
    position->location = syntax.location;
    return make_item(ItemKind::position, syntax.location, std::move(*position));
  }

  std::optional<Value> offset_parameter(const Syntax& bounds, SourceLocation range_location,
                                        const std::string& axis) {
    Item item = evaluate(bounds);
    if (item.kind == ItemKind::error) return std::nullopt;
    if (item.kind != ItemKind::tuple || item.elements.size() != 2) {
      mismatch(item, "the " + axis + " offset range '(lower, upper)'");
      return std::nullopt;
    }
    return new_parameter(item.elements[0], item.elements[1], bounds.location, range_location);
  }

  // ---- parameters ------------------------------------------------------------------------

  std::optional<double> constant_bound(const Item& item) {
    if (item.kind == ItemKind::error) return std::nullopt;
    if (!is_numeric(item)) {
      mismatch(item, "a number as range bound");
      return std::nullopt;
    }
    if (!is_constant(item.value)) {
      diagnostics_.error(item.location, "a range bound must be a constant, not another range");
      return std::nullopt;
    }
    return item.value.constant;
  }

  std::optional<Value> new_parameter(const Item& lower_item, const Item& upper_item,
                                     SourceLocation where, SourceLocation range_location) {
    std::optional<double> lower = constant_bound(lower_item), upper = constant_bound(upper_item);
    if (!lower || !upper) return std::nullopt;
    if (lower_item.kind != upper_item.kind) {
      diagnostics_.error(where, "a range cannot mix a time of day and a number");
      return std::nullopt;
    }
    bool time = lower_item.kind == ItemKind::time;
    auto bound = [&](double value) {
      return time ? format_time_of_day(value) : format_number(value);
    };
    if (*lower > *upper) {
      diagnostics_.error(where, "inverted range: the lower bound " + bound(*lower) +
                                    " is above the upper bound " + bound(*upper));
      return std::nullopt;
    }
    if (*lower == *upper) {
      diagnostics_.error(where, "empty range: both bounds are " + bound(*lower) +
                                    "; write the constant "
                                    "instead");
      return std::nullopt;
    }
    Parameter parameter;
    parameter.lower = *lower;
    parameter.upper = *upper;
    parameter.location = range_location;
    if (lower_item.kind == ItemKind::time) parameter.unit = "time of day";
    parameters_.push_back(parameter);
    return parameter_value(static_cast<int>(parameters_.size() - 1), where);
  }

  Item range(const Syntax& syntax, const std::vector<Item>& arguments) {
    if (arguments.size() != 2 || arguments[0].kind == ItemKind::empty ||
        arguments[1].kind == ItemKind::empty)
      return fail(syntax.location, "range(...) takes two bounds: range(lower, upper)");
    std::optional<Value> value =
        new_parameter(arguments[0], arguments[1], syntax.location, syntax.location);
    if (!value) return make_item(ItemKind::error, syntax.location);
    return number_item(std::move(*value), syntax.location, arguments[0].kind);
  }

  // ---- calls -----------------------------------------------------------------------------

  Item call(const Syntax& syntax) {
    const std::string& name = syntax.text;
    if (name == "NPCBehaviour") return npc_behaviour(syntax);  // its argument is a bare word
    std::vector<Item> arguments;
    for (const Syntax& child : syntax.children) arguments.push_back(evaluate(child));
    for (const Item& argument : arguments)
      if (argument.kind == ItemKind::error) return make_item(ItemKind::error, syntax.location);
    if (name == "range") return range(syntax, arguments);
    if (name == "load") return map(syntax, arguments);
    if (name == "AV") return ego(syntax, arguments);
    if (name == "Vehicle") return actor(syntax, arguments, ActorKind::vehicle);
    if (name == "Pedestrian") return actor(syntax, arguments, ActorKind::pedestrian);
    if (name == "Obstacle") return obstacle(syntax, arguments);
    if (name == "Environment") return environment(syntax, arguments);
    if (is_motion_function(name)) return motion(syntax, arguments);
    if (name == "IMU" || name == "ENU" || name == "WGS84") return framed(syntax, arguments);
    if (name == "Intersection") return intersection(syntax, arguments);
    if (name == "SpeedLimit") return speed_limit(syntax, arguments);
    if (name == "Flow") return flow(syntax, arguments);
    if (name == "EXE")
      return fail(syntax.location, "EXE(...) can only be used as 'Trace name = EXE(scenario);'");
    switch (signal_class(name)) {
      case SignalClass::function: return signal_function(syntax, arguments);
      case SignalClass::distance_predicate: return distance_predicate(syntax, arguments);
      case SignalClass::flag:
      case SignalClass::value:
        return fail(syntax.location, "'" + name + "' is a signal and takes no arguments");
      case SignalClass::none: break;
    }
    return fail(syntax.location, "unknown function '" + name + "'" + suggestion(name));
  }

  bool check_arity(const Syntax& syntax, const std::vector<Item>& arguments, std::size_t least,
                   std::size_t most, const std::string& form) {
    for (const Item& argument : arguments)
      if (argument.kind == ItemKind::star) {
        diagnostics_.error(argument.location,
                           "'*' (an actor generated at random) is not supported: write " + form);
        return false;
      }
    if (arguments.size() < least || arguments.size() > most ||
        (least > 0 && arguments[0].kind == ItemKind::empty)) {
      diagnostics_.error(syntax.location, syntax.text + "(...) expects " + form + ", found " +
                                              std::to_string(arguments.size()) +
                                              (arguments.size() == 1 ? " argument" : " arguments"));
      return false;
    }
    return true;
  }

  static bool given(const std::vector<Item>& arguments, std::size_t i) {
    return i < arguments.size() && arguments[i].kind != ItemKind::empty;
  }

  Item map(const Syntax& syntax, const std::vector<Item>& arguments) {
    if (!check_arity(syntax, arguments, 1, 1, "a map name: load(\"san_francisco\")"))
      return make_item(ItemKind::error, syntax.location);
    if (arguments[0].kind != ItemKind::string) {
      mismatch(arguments[0], "a map name in quotes");
      return make_item(ItemKind::error, syntax.location);
    }
    if (arguments[0].word.empty()) return fail(arguments[0].location, "the map name is empty");
    MapReference map;
    map.name = arguments[0].word;
    map.location = syntax.location;
    return make_item(ItemKind::map, syntax.location, std::move(map));
  }

  Item ego(const Syntax& syntax, const std::vector<Item>& arguments) {
    const char* form =
        "an initial state, a target state and an optional vehicle type: "
        "AV(init, target, type)";
    if (!check_arity(syntax, arguments, 2, 3, form) || !given(arguments, 1)) {
      if (arguments.size() >= 2 && !given(arguments, 1))
        diagnostics_.error(arguments[1].location, "the ego vehicle needs a target state");
      return make_item(ItemKind::error, syntax.location);
    }
    Actor actor;
    actor.kind = ActorKind::ego;
    actor.location = syntax.location;
    std::optional<State> initial = need_state(arguments[0]);
    std::optional<State> target = need_state(arguments[1]);
    std::optional<ActorType> type;
    if (given(arguments, 2)) {
      type = need_actor_type(arguments[2], false);
      if (!type) return make_item(ItemKind::error, syntax.location);
    }
    if (!initial || !target) return make_item(ItemKind::error, syntax.location);
    actor.initial = std::move(*initial);
    actor.target = std::move(*target);
    actor.type = std::move(type);
    return make_item(ItemKind::actor, syntax.location, std::move(actor));
  }

  // Vehicle(init[, motion[, target[, type]]]) and Pedestrian(...) with any slot left empty.
  Item actor(const Syntax& syntax, const std::vector<Item>& arguments, ActorKind kind) {
    bool pedestrian = kind == ActorKind::pedestrian;
    std::string form = syntax.text + "(init, motion, target, type) with the initial state first";
    if (!check_arity(syntax, arguments, 1, 4, form))
      return make_item(ItemKind::error, syntax.location);
    Actor actor;
    actor.kind = kind;
    actor.location = syntax.location;
    std::optional<State> initial = need_state(arguments[0]);
    if (!initial) return make_item(ItemKind::error, syntax.location);
    actor.initial = std::move(*initial);
    if (given(arguments, 1)) {
      if (arguments[1].kind != ItemKind::motion) {
        mismatch(arguments[1], "a motion such as Waypoint(...) or uniform(...)");
        return make_item(ItemKind::error, syntax.location);
      }
      actor.motion = payload_of<Motion>(arguments[1]);
      if (actor.motion.kind == MotionKind::random_walk && !pedestrian)
        return fail(arguments[1].location, "Random(...) motion is for pedestrians only");
    }
    if (given(arguments, 2)) {
      std::optional<State> target = need_state(arguments[2]);
      if (!target) return make_item(ItemKind::error, syntax.location);
      actor.target = std::move(*target);
    }
    if (given(arguments, 3)) {
      actor.type = need_actor_type(arguments[3], pedestrian);
      if (!actor.type) return make_item(ItemKind::error, syntax.location);
    }
    return make_item(ItemKind::actor, syntax.location, std::move(actor));
  }

  Item obstacle(const Syntax& syntax, const std::vector<Item>& arguments) {
    if (!check_arity(syntax, arguments, 1, 2,
                     "a position and an optional shape: "
                     "Obstacle(position, (box, 4.5, 1.9, 1.5))"))
      return make_item(ItemKind::error, syntax.location);
    Obstacle obstacle;
    obstacle.location = syntax.location;
    const Item& where = arguments[0];
    std::optional<Position> position;
    if (where.kind == ItemKind::state || (where.kind == ItemKind::tuple && !all_numbers(where))) {
      std::optional<State> state = need_state(where);
      if (!state) return make_item(ItemKind::error, syntax.location);
      position = state->position;
      obstacle.heading = state->heading;
    } else {
      position = need_position(where);
    }
    if (!position) return make_item(ItemKind::error, syntax.location);
    obstacle.position = std::move(*position);
    if (given(arguments, 1)) {
      obstacle.shape = need_shape(arguments[1]);
      if (!obstacle.shape) return make_item(ItemKind::error, syntax.location);
    }
    return make_item(ItemKind::obstacle, syntax.location, std::move(obstacle));
  }

  Item motion(const Syntax& syntax, const std::vector<Item>& arguments) {
    Motion motion;
    motion.location = syntax.location;
    const std::string& name = syntax.text;
    if (is_waypoint_function(name)) {
      if (!check_arity(syntax, arguments, 1, 1000, "a list of states: " + name + "((s1), (s2))"))
        return make_item(ItemKind::error, syntax.location);
      motion.kind = MotionKind::waypoints;
      for (const Item& argument : arguments) {
        std::optional<std::vector<State>> states = need_states(argument);
        if (!states) return make_item(ItemKind::error, syntax.location);
        motion.states.insert(motion.states.end(), states->begin(), states->end());
      }
    } else {
      if (!check_arity(syntax, arguments, 1, 1, "one state: " + name + "(state)"))
        return make_item(ItemKind::error, syntax.location);
      motion.kind = name == "Random" ? MotionKind::random_walk : MotionKind::uniform;
      // `t |= U (p)`: until needs a left side, so U here is uniform motion. Say both readings.
      if (name == "U" &&
          (arguments[0].kind == ItemKind::formula || arguments[0].kind == ItemKind::term))
        return fail(arguments[0].location,
                    "'U(...)' with nothing before it is uniform motion and takes a state; until "
                    "is written 'a U b'");
      std::optional<State> state = need_state(arguments[0]);
      if (!state) return make_item(ItemKind::error, syntax.location);
      motion.states.push_back(std::move(*state));
    }
    return make_item(ItemKind::motion, syntax.location, std::move(motion));
  }

  // IMU (x, y), ENU((1, 2) + offset), WGS84 (lon, lat)
  Item framed(const Syntax& syntax, const std::vector<Item>& arguments) {
    Frame frame = syntax.text == "IMU"   ? Frame::imu
                  : syntax.text == "ENU" ? Frame::enu
                                         : Frame::wgs84;
    Item coordinates = make_item(ItemKind::tuple, syntax.location);
    coordinates.elements = arguments;
    const Item& source = arguments.size() == 1 ? arguments[0] : coordinates;
    std::optional<Position> position = need_position(source);
    if (!position) return make_item(ItemKind::error, syntax.location);
    if (position->kind == PositionKind::lane) {
      // scenest's grammar allows `IMU "lane"->s`; a lane position is a point of the map whatever
      // the frame, so the frame changes nothing. Said once, so the user knows it is ignored.
      diagnostics_.warning(syntax.location, "the frame " + syntax.text +
                                                " has no effect on a lane position: it is the "
                                                "point s metres along the lane in any frame");
      return make_item(ItemKind::position, syntax.location, std::move(*position));
    }
    if (position->kind != PositionKind::coordinate)
      return fail(syntax.location, syntax.text + " applies to coordinates, not to a lane position");
    if (position->frame != Frame::enu && position->frame != frame)
      return fail(syntax.location, "these coordinates already have another frame");
    position->frame = frame;
    position->location = syntax.location;
    return make_item(ItemKind::position, syntax.location, std::move(*position));
  }

  Item environment(const Syntax& syntax, const std::vector<Item>& arguments) {
    Environment environment;
    environment.location = syntax.location;
    if (arguments.size() > 2)
      return fail(syntax.location,
                  "Environment(...) expects a time and a weather set: "
                  "Environment(12:00, {rain: 0.5})");
    if (given(arguments, 0)) {
      if (arguments[0].kind != ItemKind::time) {
        mismatch(arguments[0], "a time of day such as 12:00");
        return make_item(ItemKind::error, syntax.location);
      }
      environment.time_of_day = arguments[0].value;
    }
    if (given(arguments, 1) && !weather(arguments[1], environment.weather))
      return make_item(ItemKind::error, syntax.location);
    return make_item(ItemKind::environment, syntax.location, std::move(environment));
  }

  bool weather(const Item& item, std::vector<WeatherComponent>& components) {
    if (item.kind != ItemKind::set) {
      mismatch(item, "a weather set such as {rain: 0.5, fog: light}");
      return false;
    }
    for (const Item& entry : item.elements) {
      if (entry.kind == ItemKind::set) {  // {w1, w2} of variables holding sets
        if (!weather(entry, components)) return false;
        continue;
      }
      if (entry.kind != ItemKind::keyed) {
        mismatch(entry, "a weather entry 'kind: value'");
        return false;
      }
      if (!is_weather_kind(entry.word)) {
        diagnostics_.error(entry.location, "unknown weather kind '" + entry.word +
                                               "': expected sunny, rain, snow, fog, wetness or "
                                               "cloudiness");
        return false;
      }
      for (const WeatherComponent& existing : components)
        if (existing.kind == entry.word) {
          diagnostics_.error(entry.location, "'" + entry.word + "' is given twice");
          return false;
        }
      WeatherComponent component;
      component.kind = entry.word;
      component.location = entry.location;
      const Item& level = entry.elements[0];
      if (level.kind == ItemKind::word && is_weather_level(level.word)) {
        component.level = level.word == "light"    ? WeatherLevel::light
                          : level.word == "middle" ? WeatherLevel::middle
                                                   : WeatherLevel::heavy;
        component.intensity = constant_value(weather_level_intensity(level.word), level.location);
      } else {
        std::optional<Value> value =
            need_value(level, "a weather intensity in [0, 1] or light, middle, heavy");
        if (!value) return false;
        if (!check_fraction(*value, level.location, entry.word)) return false;
        component.intensity = std::move(*value);
      }
      components.push_back(std::move(component));
    }
    return true;
  }

  bool check_fraction(const Value& value, SourceLocation where, const std::string& what) {
    ValueRange range = value_range(value, parameters_);
    if (range.lower < 0.0 || range.upper > 1.0) {
      diagnostics_.error(where, what + " must be between 0 and 1, " +
                                    reaches(value, range.lower < 0.0 ? range.lower : range.upper));
      return false;
    }
    return true;
  }

  Item intersection(const Syntax& syntax, const std::vector<Item>& arguments) {
    const char* form = "Intersection(id, traffic light 0|1, stop sign 0|1, crosswalk 0|1)";
    if (!check_arity(syntax, arguments, 4, 4, form))
      return make_item(ItemKind::error, syntax.location);
    IntersectionControl control;
    control.location = syntax.location;
    control.id =
        arguments[0].kind == ItemKind::string ? arguments[0].word : syntax.children[0].text;
    bool* flags[] = {&control.traffic_light, &control.stop_sign, &control.crosswalk};
    for (std::size_t i = 1; i < 4; ++i) {
      const Item& flag = arguments[i];
      if (flag.kind != ItemKind::number || !is_constant(flag.value) ||
          (flag.value.constant != 0.0 && flag.value.constant != 1.0)) {
        mismatch(flag, "0 or 1");
        return make_item(ItemKind::error, syntax.location);
      }
      *flags[i - 1] = flag.value.constant == 1.0;
    }
    return make_item(ItemKind::intersection, syntax.location, std::move(control));
  }

  Item speed_limit(const Syntax& syntax, const std::vector<Item>& arguments) {
    if (!check_arity(syntax, arguments, 2, 2, "SpeedLimit(\"lane\", (lower, upper))"))
      return make_item(ItemKind::error, syntax.location);
    SpeedLimit limit;
    limit.location = syntax.location;
    if (arguments[0].kind != ItemKind::string) {
      mismatch(arguments[0], "a lane id in quotes");
      return make_item(ItemKind::error, syntax.location);
    }
    limit.lane = arguments[0].word;
    const Item& bounds = arguments[1];
    if (!all_numbers(bounds) || bounds.elements.size() != 2) {
      mismatch(bounds, "a speed range (lower, upper)");
      return make_item(ItemKind::error, syntax.location);
    }
    limit.lower = bounds.elements[0].value;
    limit.upper = bounds.elements[1].value;
    return make_item(ItemKind::speed_limit, syntax.location, std::move(limit));
  }

  Item npc_behaviour(const Syntax& syntax) {
    std::optional<NpcBehaviour> behaviour = elaborate_npc_behaviour(syntax, diagnostics_);
    if (!behaviour) return make_item(ItemKind::error, syntax.location);
    Item item = make_item(ItemKind::npc_behaviour, syntax.location);
    item.word = npc_behaviour_word(*behaviour);
    return item;
  }

  Item flow(const Syntax& syntax, const std::vector<Item>& arguments) {
    std::optional<TrafficFlow> flow = elaborate_flow(syntax, arguments, parameters_, diagnostics_);
    if (!flow) return make_item(ItemKind::error, syntax.location);
    return make_item(ItemKind::flow, syntax.location, std::move(*flow));
  }

  // dis(a, b), vel(a, b), spd(a, b), acc(a, b), diff(perceived, truth)
  Item signal_function(const Syntax& syntax, const std::vector<Item>& arguments) {
    const std::string& name = syntax.text;
    if (arguments.size() != 2 || !given(arguments, 0) || !given(arguments, 1))
      return fail(syntax.location, name + "(...) takes two arguments: " + name + "(a, b)");
    std::vector<SpecTerm> terms;
    for (std::size_t i = 0; i < 2; ++i) {
      std::optional<SpecTerm> term = function_argument(name, arguments[i]);
      if (!term) return make_item(ItemKind::error, syntax.location);
      terms.push_back(std::move(*term));
    }
    if (name == "diff") {
      if (terms[0].kind != TermKind::object || terms[0].source != ObjectSource::perception ||
          terms[1].kind != TermKind::object || terms[1].source != ObjectSource::truth ||
          terms[0].name != terms[1].name)
        return fail(syntax.location,
                    "diff(...) compares an agent's perceived and true states: "
                    "diff(trace[perception][a], trace[truth][a])");
    }
    return signal_item(name, std::move(terms), syntax.location);
  }

  std::optional<SpecTerm> function_argument(const std::string& function, const Item& argument) {
    if (argument.kind == ItemKind::projection) return need_term(argument);
    if (function == "dis" && (argument.kind == ItemKind::position || all_numbers(argument))) {
      std::optional<Position> position = need_position(argument);
      if (!position) return std::nullopt;
      SpecTerm term;
      term.kind = TermKind::position;
      term.position = std::move(*position);
      term.location = argument.location;
      return term;
    }
    if (function == "vel" || function == "acc") {
      if (std::optional<SpecTerm> vector = vector_argument(argument)) return vector;
    }
    if (function == "spd" && argument.kind == ItemKind::number) return need_term(argument);
    std::string expected = function == "dis"   ? "a trace projection or a position"
                           : function == "spd" ? "a trace projection or a speed"
                           : function == "diff"
                               ? "a trace projection"
                               : "a trace projection or a vector (x, y) or (x, y, z)";
    mismatch(argument, expected + " as argument of " + function + "(...)");
    return std::nullopt;
  }

  // A vel/acc vector: `(x, y)`, `(x, y, z)` or coordinates summed to one, such as `(1, 2, -3) + v`.
  // The grammar's <velocity> is a <coordinate>, whose third component is the frame's up axis
  // (ENU/IMU are east-north-up / right-forward-up), so z is the vertical component. Only ENU:
  // a vector in another frame would have to be rotated, which the oracle does not do.
  std::optional<SpecTerm> vector_argument(const Item& argument) {
    bool numbers =
        all_numbers(argument) && (argument.elements.size() == 2 || argument.elements.size() == 3);
    bool summed = argument.kind == ItemKind::position &&
                  payload_of<Position>(argument).kind == PositionKind::coordinate &&
                  payload_of<Position>(argument).frame == Frame::enu;
    if (!numbers && !summed) return std::nullopt;
    SpecTerm term;
    term.kind = TermKind::vector;
    term.location = argument.location;
    if (numbers) {
      for (const Item& element : argument.elements) term.operands.push_back(*need_term(element));
      return term;
    }
    const Position& position = payload_of<Position>(argument);
    for (const Value* component : {&position.x, &position.y}) {
      SpecTerm number;
      number.kind = TermKind::number;
      number.value = *component;
      number.location = argument.location;
      term.operands.push_back(std::move(number));
    }
    if (position.z) {
      SpecTerm number;
      number.kind = TermKind::number;
      number.value = *position.z;
      number.location = argument.location;
      term.operands.push_back(std::move(number));
    }
    return term;
  }

  // stoplineAhead(2): true while the stop line is within 2 m. The distance is a constant.
  Item distance_predicate(const Syntax& syntax, const std::vector<Item>& arguments) {
    if (arguments.size() != 1 || arguments[0].kind != ItemKind::number ||
        !is_constant(arguments[0].value))
      return fail(syntax.location, syntax.text + "(...) takes one constant distance in metres: " +
                                       syntax.text + "(2)");
    return signal_item(syntax.text, {*need_term(arguments[0])}, syntax.location);
  }

  // ---- scenario --------------------------------------------------------------------------

  Item scenario(const Syntax& syntax) {
    std::size_t slots = syntax.children.size();
    if (slots < 5 || slots > 7)
      return fail(syntax.location,
                  "CreateScenario{...} has " + std::to_string(slots) +
                      " slots; expected 'load(map); ego; vehicles; pedestrians; obstacles;' "
                      "and optionally 'environment;' and 'traffic;'");
    std::vector<Item> items;
    for (const Syntax& child : syntax.children) items.push_back(evaluate(child));
    for (const Item& item : items)
      if (item.kind == ItemKind::error) return make_item(ItemKind::error, syntax.location);
    auto parts = std::make_shared<ScenarioParts>();
    parts->location = syntax.location;
    if (items[0].kind != ItemKind::map) {
      mismatch(items[0], "the map 'load(\"name\")' in the first slot of CreateScenario");
      return make_item(ItemKind::error, syntax.location);
    }
    parts->map = payload_of<MapReference>(items[0]);
    if (items[1].kind != ItemKind::actor || payload_of<Actor>(items[1]).kind != ActorKind::ego) {
      mismatch(items[1], "the ego vehicle AV(...) in the second slot of CreateScenario");
      return make_item(ItemKind::error, syntax.location);
    }
    parts->ego = payload_of<Actor>(items[1]);
    if (parts->ego.name.empty()) parts->ego.name = "ego";
    std::set<std::string> names = {parts->ego.name};
    bool ok =
        collect_actors(items[2], ActorKind::vehicle, "vehicle", parts->vehicles, names) &&
        collect_actors(items[3], ActorKind::pedestrian, "pedestrian", parts->pedestrians, names) &&
        collect_obstacles(items[4], parts->obstacles, names);
    if (!ok) return make_item(ItemKind::error, syntax.location);
    if (slots >= 6 && !(items[5].kind == ItemKind::set && items[5].elements.empty())) {
      if (items[5].kind != ItemKind::environment) {
        mismatch(items[5], "an Environment(...) or {} in the sixth slot of CreateScenario");
        return make_item(ItemKind::error, syntax.location);
      }
      parts->environment = payload_of<Environment>(items[5]);
    }
    if (slots == 7 && !traffic(items[6], *parts, names))
      return make_item(ItemKind::error, syntax.location);
    Item item =
        make_item(ItemKind::scenario, syntax.location, std::shared_ptr<const ScenarioParts>(parts));
    scenarios_.push_back(payload_of<std::shared_ptr<const ScenarioParts>>(item));
    return item;
  }

  // Sets flatten: `{npc1, npc2}`, a variable holding such a set, or `{npcs}`.
  static void flatten(const Item& item, std::vector<const Item*>& out) {
    if (item.kind == ItemKind::set || item.kind == ItemKind::tuple) {
      for (const Item& element : item.elements) flatten(element, out);
    } else if (item.kind != ItemKind::empty) {
      out.push_back(&item);
    }
  }

  static std::string fresh_name(const std::string& stem, std::set<std::string>& names) {
    for (int i = 1;; ++i) {
      std::string name = stem + std::to_string(i);
      if (names.insert(name).second) return name;
    }
  }

  bool claim_name(const std::string& name, SourceLocation where, std::set<std::string>& names) {
    if (names.insert(name).second) return true;
    diagnostics_.error(where, "'" + name + "' appears twice in the scenario");
    return false;
  }

  bool collect_actors(const Item& slot, ActorKind kind, const std::string& stem,
                      std::vector<Actor>& actors, std::set<std::string>& names) {
    std::vector<const Item*> elements;
    flatten(slot, elements);
    for (const Item* element : elements) {
      if (element->kind != ItemKind::actor || payload_of<Actor>(*element).kind != kind) {
        mismatch(*element,
                 std::string(kind == ActorKind::vehicle ? "a Vehicle(...)" : "a Pedestrian(...)") +
                     " in the " + stem + " slot of CreateScenario");
        return false;
      }
      Actor actor = payload_of<Actor>(*element);
      if (actor.name.empty())
        actor.name = fresh_name(stem, names);
      else if (!claim_name(actor.name, element->location, names))
        return false;
      actors.push_back(std::move(actor));
    }
    return true;
  }

  bool collect_obstacles(const Item& slot, std::vector<Obstacle>& obstacles,
                         std::set<std::string>& names) {
    std::vector<const Item*> elements;
    flatten(slot, elements);
    for (const Item* element : elements) {
      if (element->kind != ItemKind::obstacle) {
        mismatch(*element, "an Obstacle(...) in the obstacle slot of CreateScenario");
        return false;
      }
      Obstacle obstacle = payload_of<Obstacle>(*element);
      if (obstacle.name.empty())
        obstacle.name = fresh_name("obstacle", names);
      else if (!claim_name(obstacle.name, element->location, names))
        return false;
      obstacles.push_back(std::move(obstacle));
    }
    return true;
  }

  // Flows are named like actors (`flow1`, or their variable), in one namespace with them.
  bool traffic(const Item& slot, ScenarioParts& parts, std::set<std::string>& names) {
    std::vector<const Item*> elements;
    flatten(slot, elements);
    for (const Item* element : elements) {
      if (element->kind == ItemKind::intersection) {
        parts.traffic.intersections.push_back(payload_of<IntersectionControl>(*element));
      } else if (element->kind == ItemKind::speed_limit) {
        parts.traffic.speed_limits.push_back(payload_of<SpeedLimit>(*element));
      } else if (element->kind == ItemKind::flow) {
        TrafficFlow flow = payload_of<TrafficFlow>(*element);
        if (flow.name.empty())
          flow.name = fresh_name("flow", names);
        else if (!claim_name(flow.name, element->location, names))
          return false;
        parts.traffic.flows.push_back(std::move(flow));
      } else if (element->kind == ItemKind::npc_behaviour) {
        if (parts.npc_behaviour) {
          diagnostics_.error(element->location,
                             "NPCBehaviour(...) is given twice in the traffic slot; keep one");
          return false;
        }
        parts.npc_behaviour =
            element->word == "scripted" ? NpcBehaviour::scripted : NpcBehaviour::reactive;
      } else {
        mismatch(*element,
                 "an Intersection(...), SpeedLimit(...), Flow(...) or NPCBehaviour(...) in the "
                 "traffic slot");
        return false;
      }
    }
    return true;
  }

  // ---- coercions at use sites ------------------------------------------------------------

  std::optional<Value> need_value(const Item& item, const std::string& expected) {
    if (is_numeric(item)) return item.value;
    if (item.kind == ItemKind::set && item.elements.size() == 1)  // `{dis1}` as in AVUnit's docs
      return need_value(item.elements[0], expected);
    mismatch(item, expected);
    return std::nullopt;
  }

  std::optional<Position> need_position(const Item& item, bool report = true) {
    if (item.kind == ItemKind::position) return payload_of<Position>(item);
    if (all_numbers(item) && (item.elements.size() == 2 || item.elements.size() == 3)) {
      Position position;
      position.kind = PositionKind::coordinate;
      position.x = item.elements[0].value;
      position.y = item.elements[1].value;
      if (item.elements.size() == 3) position.z = item.elements[2].value;
      position.location = item.location;
      return position;
    }
    if (report) mismatch(item, "a position: (x, y) or \"lane\"->s");
    return std::nullopt;
  }

  // (position), (position, heading), (position, heading, speed), (position, , speed)
  std::optional<State> need_state(const Item& item, bool report = true) {
    State state;
    state.location = item.location;
    if (item.kind == ItemKind::state) return payload_of<State>(item);
    if (std::optional<Position> position = need_position(item, false)) {
      state.position = std::move(*position);
      return state;
    }
    if (item.kind != ItemKind::tuple || item.elements.empty() || item.elements.size() > 3) {
      if (report) mismatch(item, "a state: (position, heading, speed)");
      return std::nullopt;
    }
    std::optional<Position> position = need_position(item.elements[0], report);
    if (!position) return std::nullopt;
    state.position = std::move(*position);
    if (item.elements.size() >= 2 && item.elements[1].kind != ItemKind::empty) {
      const Item& heading = item.elements[1];
      if (heading.kind != ItemKind::heading) {
        if (report) {
          if (heading.kind == ItemKind::number)
            diagnostics_.error(heading.location,
                               "a heading needs a unit: write '90 deg' or '1.57 rad'");
          else
            mismatch(heading, "a heading such as '90 deg' as the second element of a state");
        }
        return std::nullopt;
      }
      state.heading = payload_of<Heading>(heading);
    }
    if (item.elements.size() == 3 && item.elements[2].kind != ItemKind::empty) {
      const Item& speed = item.elements[2];
      if (speed.kind != ItemKind::number) {
        if (report) mismatch(speed, "a speed in m/s as the third element of a state");
        return std::nullopt;
      }
      if (report && !check_not_negative(speed.value, speed.location, "a speed"))
        return std::nullopt;
      state.speed = speed.value;
    }
    return state;
  }

  // A list of states `((s1), (s2))`, or a single state.
  std::optional<std::vector<State>> need_states(const Item& item) {
    if (item.kind == ItemKind::tuple || item.kind == ItemKind::set) {
      std::vector<State> states;
      for (const Item& element : item.elements) {
        std::optional<State> state = need_state(element, false);
        if (!state) break;
        states.push_back(std::move(*state));
      }
      if (states.size() == item.elements.size() && !states.empty()) {
        // Report what a quiet check skipped (e.g. negative speeds) on the real states.
        for (const Item& element : item.elements)
          if (!need_state(element)) return std::nullopt;
        return states;
      }
    }
    std::optional<State> state = need_state(item);
    if (!state) return std::nullopt;
    return std::vector<State>{std::move(*state)};
  }

  std::optional<Color> need_color(const Item& item) {
    if (item.kind == ItemKind::word && is_color_word(item.word)) return Color{item.word, {}};
    if (all_numbers(item) && item.elements.size() == 3) {
      std::array<int, 3> rgb{};
      for (std::size_t i = 0; i < 3; ++i) {
        const Value& channel = item.elements[i].value;
        if (!is_constant(channel) || channel.constant < 0 || channel.constant > 255 ||
            channel.constant != std::floor(channel.constant)) {
          diagnostics_.error(item.elements[i].location,
                             "an RGB colour channel is a whole number from 0 to 255");
          return std::nullopt;
        }
        rgb[i] = static_cast<int>(channel.constant);
      }
      return Color{"", rgb};
    }
    mismatch(item, "a colour: red, green, blue, black, white or (r, g, b)");
    return std::nullopt;
  }

  // Vehicles: "model", car, ("model", colour). Pedestrians: "model", (height, colour).
  std::optional<ActorType> need_actor_type(const Item& item, bool pedestrian) {
    ActorType type;
    type.location = item.location;
    std::vector<Item> parts =
        item.kind == ItemKind::tuple ? item.elements : std::vector<Item>{item};
    if (parts.empty() || parts.size() > 2 || parts[0].kind == ItemKind::empty) {
      mismatch(item, pedestrian ? "a pedestrian type: \"model\" or (height, colour)"
                                : "a vehicle type: (\"model\", colour)");
      return std::nullopt;
    }
    const Item& first = parts[0];
    if (first.kind == ItemKind::string) {
      type.model = first.word;
    } else if (first.kind == ItemKind::word && is_vehicle_kind_word(first.word) && !pedestrian) {
      type.model = first.word;
      type.general = true;
    } else if (pedestrian && first.kind == ItemKind::number) {
      if (!check_not_negative(first.value, first.location, "a height")) return std::nullopt;
      type.height = first.value;
    } else {
      mismatch(first, pedestrian ? "a model name or a height in metres"
                                 : "a model name in quotes or car, bus, Van, truck, bicycle, "
                                   "motorbicycle, tricycle");
      return std::nullopt;
    }
    if (parts.size() == 2 && parts[1].kind != ItemKind::empty) {
      std::optional<Color> color = need_color(parts[1]);
      if (!color) return std::nullopt;
      type.color = std::move(color);
    }
    return type;
  }

  std::optional<Shape> need_shape(const Item& item) {
    if (item.kind != ItemKind::tuple || item.elements.empty() ||
        item.elements[0].kind != ItemKind::word || !is_shape_word(item.elements[0].word)) {
      mismatch(item, "a shape: (sphere, r), (box, l, w, h), (cone, ...) or (cylinder, ...)");
      return std::nullopt;
    }
    const std::string& word = item.elements[0].word;
    Shape shape;
    shape.location = item.location;
    shape.kind = word == "sphere" ? ShapeKind::sphere
                 : word == "box"  ? ShapeKind::box
                 : word == "cone" ? ShapeKind::cone
                                  : ShapeKind::cylinder;
    std::size_t expected = shape.kind == ShapeKind::sphere ? 1 : 3;
    if (item.elements.size() != expected + 1) {
      diagnostics_.error(item.location, "a " + word + " has " + std::to_string(expected) +
                                            (expected == 1 ? " dimension" : " dimensions") +
                                            ", found " + std::to_string(item.elements.size() - 1));
      return std::nullopt;
    }
    for (std::size_t i = 1; i < item.elements.size(); ++i) {
      std::optional<Value> dimension = need_value(item.elements[i], "a dimension in metres");
      if (!dimension) return std::nullopt;
      if (is_constant(*dimension) && dimension->constant <= 0.0) {
        diagnostics_.error(item.elements[i].location, "a shape's dimensions must be positive");
        return std::nullopt;
      }
      shape.dimensions.push_back(std::move(*dimension));
    }
    return shape;
  }

  std::optional<SpecTerm> need_term(const Item& item) {
    SpecTerm term;
    term.location = item.location;
    switch (item.kind) {
      case ItemKind::term: return payload_of<SpecTerm>(item);
      case ItemKind::number:
        term.kind = TermKind::number;
        term.value = item.value;
        return term;
      case ItemKind::time:
        term.kind = TermKind::time_of_day;
        term.value = item.value;
        return term;
      case ItemKind::word:
        if (is_enumeration_word(item.word)) {
          term.kind = TermKind::word;
          term.name = item.word;
          return term;
        }
        break;
      case ItemKind::projection: {
        const Projection& projection = payload_of<Projection>(item);
        if (!projection.complete) {
          diagnostics_.error(item.location, "name the agent: " + projection.trace +
                                                "[truth][npc1] or " + projection.trace +
                                                "[perception][npc1]");
          return std::nullopt;
        }
        if (!current_trace_.empty() && projection.trace != current_trace_) {
          diagnostics_.error(item.location, "this projection reads trace '" + projection.trace +
                                                "', but the specification is asserted on '" +
                                                current_trace_ + "'");
          return std::nullopt;
        }
        term.kind = TermKind::object;
        term.source = projection.source;
        term.name = projection.agent;
        return term;
      }
      case ItemKind::position:
        term.kind = TermKind::position;
        term.position = payload_of<Position>(item);
        return term;
      case ItemKind::set:
        if (item.elements.size() == 1) return need_term(item.elements[0]);
        break;
      default: break;
    }
    mismatch(item, "a signal or a number");
    return std::nullopt;
  }

  std::optional<Formula> need_formula(const Item& item) {
    if (item.kind == ItemKind::formula) return payload_of<Formula>(item);
    if (item.kind == ItemKind::term) {
      const SpecTerm& term = payload_of<SpecTerm>(item);
      SignalClass kind =
          term.kind == TermKind::signal ? signal_class(term.name) : SignalClass::none;
      bool free_flag = free_signals_ && term.kind == TermKind::signal && term.operands.empty() &&
                       kind == SignalClass::none;
      if (kind == SignalClass::flag || kind == SignalClass::distance_predicate || free_flag) {
        Formula formula;
        formula.kind = FormulaKind::predicate;
        formula.terms.push_back(term);
        formula.location = item.location;
        return formula;
      }
    }
    if (item.kind == ItemKind::set && item.elements.size() == 1)
      return need_formula(item.elements[0]);
    mismatch(item, "a formula such as 'dis(a, b) > 1.0'");
    return std::nullopt;
  }

  // ---- the template ----------------------------------------------------------------------

  // A scenario the file executes (or, executing none, creates), with how a user names it.
  struct Candidate {
    std::shared_ptr<const ScenarioParts> parts;
    ScenarioCandidate described;
  };

  // The first variable, by name, bound to the scenario `parts` ("" when none is).
  std::string variable_of(const std::shared_ptr<const ScenarioParts>& parts) const {
    for (const auto& [name, item] : variables_)
      if (item.kind == ItemKind::scenario &&
          *std::get<Boxed<std::shared_ptr<const ScenarioParts>>>(item.payload) == parts)
        return name;
    return "";
  }

  // Each executed scenario once, in the order of its first trace; with no trace, every scenario
  // the file creates.
  std::vector<Candidate> candidates() const {
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

  // One candidate as a template: its parts, the specs asserted on its traces, every parameter.
  ScenarioTemplate template_of(const Candidate& candidate) const {
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

  ScenarioTemplate build_template() {
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
