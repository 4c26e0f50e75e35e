// The AVUnit elaborator's coercions at use sites: an item needed as a value, position, state,
// colour, actor type, shape, term or formula, with a diagnostic when it is not one
// (elaborator_class.hpp).
#include "lang/avunit/elaborator_class.hpp"

namespace scenfuzz::avunit {

std::optional<Value> Elaborator::need_value(const Item& item, const std::string& expected) {
  if (is_numeric(item)) return item.value;
  if (item.kind == ItemKind::set && item.elements.size() == 1)  // `{dis1}` as in AVUnit's docs
    return need_value(item.elements[0], expected);
  mismatch(item, expected);
  return std::nullopt;
}

std::optional<Position> Elaborator::need_position(const Item& item, bool report) {
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

std::optional<State> Elaborator::need_state(const Item& item, bool report) {
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
    if (report && !check_not_negative(speed.value, speed.location, "a speed")) return std::nullopt;
    state.speed = speed.value;
  }
  return state;
}

std::optional<std::vector<State>> Elaborator::need_states(const Item& item) {
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

std::optional<Color> Elaborator::need_color(const Item& item) {
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

std::optional<ActorType> Elaborator::need_actor_type(const Item& item, bool pedestrian) {
  ActorType type;
  type.location = item.location;
  std::vector<Item> parts = item.kind == ItemKind::tuple ? item.elements : std::vector<Item>{item};
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

std::optional<Shape> Elaborator::need_shape(const Item& item) {
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

std::optional<SpecTerm> Elaborator::need_term(const Item& item) {
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

std::optional<Formula> Elaborator::need_formula(const Item& item) {
  if (item.kind == ItemKind::formula) return payload_of<Formula>(item);
  if (item.kind == ItemKind::term) {
    const SpecTerm& term = payload_of<SpecTerm>(item);
    SignalClass kind = term.kind == TermKind::signal ? signal_class(term.name) : SignalClass::none;
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

}  // namespace scenfuzz::avunit
