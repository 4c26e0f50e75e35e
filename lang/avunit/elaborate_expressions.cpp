// The AVUnit elaborator's expressions: names, members, operators, temporal operators, angles,
// coordinate ranges, and the bounds of parameter ranges (elaborator_class.hpp).
#include "lang/avunit/elaborator_class.hpp"

namespace scenfuzz::avunit {

Item Elaborator::evaluate(const Syntax& syntax) {
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

Item Elaborator::identifier(const Syntax& syntax) {
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

Item Elaborator::signal_item(const std::string& name, std::vector<SpecTerm> arguments,
                             SourceLocation location) {
  SpecTerm term;
  term.kind = TermKind::signal;
  term.name = name;
  term.operands = std::move(arguments);
  term.location = location;
  return make_item(ItemKind::term, location, std::move(term));
}

Item Elaborator::member(const Syntax& syntax) {
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

Item Elaborator::projection_column(const Syntax& syntax, const Item& projection) {
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

Item Elaborator::binary(const Syntax& syntax) {
  TokenKind op = syntax.op;
  if (op == TokenKind::arrow) return arrow(syntax);
  Item left = evaluate(syntax.children[0]);
  Item right = evaluate(syntax.children[1]);
  if (left.kind == ItemKind::error || right.kind == ItemKind::error)
    return make_item(ItemKind::error, syntax.location);
  if (op == TokenKind::ampersand || op == TokenKind::bar) {
    return logical(op == TokenKind::ampersand ? FormulaKind::conjunction : FormulaKind::disjunction,
                   left, right, syntax.location);
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

Item Elaborator::logical(FormulaKind kind, const Item& left, const Item& right,
                         SourceLocation location) {
  std::optional<Formula> a = need_formula(left), b = need_formula(right);
  if (!a || !b) return make_item(ItemKind::error, location);
  Formula formula;
  formula.kind = kind;
  formula.operands = {std::move(*a), std::move(*b)};
  formula.location = location;
  return make_item(ItemKind::formula, location, std::move(formula));
}

Item Elaborator::arrow(const Syntax& syntax) {
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

std::string Elaborator::reaches(const Value& value, double extreme) {
  return (is_constant(value) ? "found " : "but it can reach ") + format_number(extreme);
}

bool Elaborator::check_not_negative(const Value& value, SourceLocation where,
                                    const std::string& what) {
  double lowest = value_range(value, parameters_).lower;
  if (lowest < 0.0) {
    diagnostics_.error(where, what + " cannot be negative, " + reaches(value, lowest));
    return false;
  }
  return true;
}

Item Elaborator::arithmetic(ValueOp op, const Item& left, const Item& right,
                            SourceLocation location) {
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

bool Elaborator::is_term_like(const Item& item) {
  return item.kind == ItemKind::term || item.kind == ItemKind::projection;
}

Item Elaborator::coordinate_arithmetic(ValueOp op, const Item& left, const Item& right,
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
    result.z = binary_value(op, a->z.value_or(constant_value(0)), b->z.value_or(constant_value(0)),
                            location);
  result.location = location;
  return make_item(ItemKind::position, location, std::move(result));
}

Item Elaborator::unary(const Syntax& syntax) {
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

std::optional<TimeInterval> Elaborator::interval(const std::optional<IntervalSyntax>& written) {
  if (!written) return std::nullopt;
  if (written->lower > written->upper) {
    diagnostics_.error(written->location,
                       "inverted interval: the lower bound " + format_number(written->lower) +
                           " is above the upper bound " + format_number(written->upper));
  }
  return TimeInterval{written->lower, written->upper};
}

Item Elaborator::temporal(const Syntax& syntax) {
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

Item Elaborator::until(const Syntax& syntax) {
  Item left = evaluate(syntax.children[0]);
  Item right = evaluate(syntax.children[1]);
  std::optional<TimeInterval> window = interval(syntax.interval);
  Item result = logical(FormulaKind::until, left, right, syntax.location);
  if (result.kind == ItemKind::formula) payload_of<Formula>(result).interval = window;
  return result;
}

Item Elaborator::index(const Syntax& syntax) {
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

bool Elaborator::is_ego_variable(const std::string& name) const {
  auto found = variables_.find(name);
  return found != variables_.end() && found->second.kind == ItemKind::actor &&
         payload_of<Actor>(found->second).kind == ActorKind::ego;
}

Item Elaborator::angle(const Syntax& syntax) {
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

std::optional<Direction> Elaborator::direction(const Syntax& syntax) {
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

Item Elaborator::coordinate_range(const Syntax& syntax) {
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

std::optional<Value> Elaborator::offset_parameter(const Syntax& bounds,
                                                  SourceLocation range_location,
                                                  const std::string& axis) {
  Item item = evaluate(bounds);
  if (item.kind == ItemKind::error) return std::nullopt;
  if (item.kind != ItemKind::tuple || item.elements.size() != 2) {
    mismatch(item, "the " + axis + " offset range '(lower, upper)'");
    return std::nullopt;
  }
  return new_parameter(item.elements[0], item.elements[1], bounds.location, range_location);
}

std::optional<double> Elaborator::constant_bound(const Item& item) {
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

std::optional<Value> Elaborator::new_parameter(const Item& lower_item, const Item& upper_item,
                                               SourceLocation where,
                                               SourceLocation range_location) {
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

Item Elaborator::range(const Syntax& syntax, const std::vector<Item>& arguments) {
  if (arguments.size() != 2 || arguments[0].kind == ItemKind::empty ||
      arguments[1].kind == ItemKind::empty)
    return fail(syntax.location, "range(...) takes two bounds: range(lower, upper)");
  std::optional<Value> value =
      new_parameter(arguments[0], arguments[1], syntax.location, syntax.location);
  if (!value) return make_item(ItemKind::error, syntax.location);
  return number_item(std::move(*value), syntax.location, arguments[0].kind);
}

}  // namespace scenfuzz::avunit
