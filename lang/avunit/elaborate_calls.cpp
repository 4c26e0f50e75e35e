// The AVUnit elaborator's built-in calls: Map, ego and actors, obstacles, motions, frames,
// environments and weather, intersections, speed limits, flows, and the signal functions of
// specs (elaborator_class.hpp).
#include "lang/avunit/elaborator_class.hpp"

namespace scenfuzz::avunit {

Item Elaborator::call(const Syntax& syntax) {
  const std::string& name = syntax.text;
  if (name == "NPCBehaviour") return npc_behaviour(syntax);  // its argument is a bare word
  if (name == "TrafficLight") return traffic_light(syntax);  // so is its colour
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

bool Elaborator::check_arity(const Syntax& syntax, const std::vector<Item>& arguments,
                             std::size_t least, std::size_t most, const std::string& form) {
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

bool Elaborator::given(const std::vector<Item>& arguments, std::size_t i) {
  return i < arguments.size() && arguments[i].kind != ItemKind::empty;
}

Item Elaborator::map(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::ego(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::actor(const Syntax& syntax, const std::vector<Item>& arguments, ActorKind kind) {
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

Item Elaborator::obstacle(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::motion(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::framed(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::environment(const Syntax& syntax, const std::vector<Item>& arguments) {
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

bool Elaborator::weather(const Item& item, std::vector<WeatherComponent>& components) {
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

bool Elaborator::check_fraction(const Value& value, SourceLocation where, const std::string& what) {
  ValueRange range = value_range(value, parameters_);
  if (range.lower < 0.0 || range.upper > 1.0) {
    diagnostics_.error(where, what + " must be between 0 and 1, " +
                                  reaches(value, range.lower < 0.0 ? range.lower : range.upper));
    return false;
  }
  return true;
}

Item Elaborator::intersection(const Syntax& syntax, const std::vector<Item>& arguments) {
  const char* form = "Intersection(id, traffic light 0|1, stop sign 0|1, crosswalk 0|1)";
  if (!check_arity(syntax, arguments, 4, 4, form))
    return make_item(ItemKind::error, syntax.location);
  IntersectionControl control;
  control.location = syntax.location;
  control.id = arguments[0].kind == ItemKind::string ? arguments[0].word : syntax.children[0].text;
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

Item Elaborator::speed_limit(const Syntax& syntax, const std::vector<Item>& arguments) {
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

Item Elaborator::npc_behaviour(const Syntax& syntax) {
  std::optional<NpcBehaviour> behaviour = elaborate_npc_behaviour(syntax, diagnostics_);
  if (!behaviour) return make_item(ItemKind::error, syntax.location);
  Item item = make_item(ItemKind::npc_behaviour, syntax.location);
  item.word = npc_behaviour_word(*behaviour);
  return item;
}

Item Elaborator::traffic_light(const Syntax& syntax) {
  std::optional<TrafficLightSetting> light = elaborate_traffic_light(syntax, diagnostics_);
  if (!light) return make_item(ItemKind::error, syntax.location);
  return make_item(ItemKind::traffic_light, syntax.location, std::move(*light));
}

Item Elaborator::flow(const Syntax& syntax, const std::vector<Item>& arguments) {
  std::optional<TrafficFlow> flow = elaborate_flow(syntax, arguments, parameters_, diagnostics_);
  if (!flow) return make_item(ItemKind::error, syntax.location);
  return make_item(ItemKind::flow, syntax.location, std::move(*flow));
}

Item Elaborator::signal_function(const Syntax& syntax, const std::vector<Item>& arguments) {
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

std::optional<SpecTerm> Elaborator::function_argument(const std::string& function,
                                                      const Item& argument) {
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

std::optional<SpecTerm> Elaborator::vector_argument(const Item& argument) {
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

Item Elaborator::distance_predicate(const Syntax& syntax, const std::vector<Item>& arguments) {
  if (arguments.size() != 1 || arguments[0].kind != ItemKind::number ||
      !is_constant(arguments[0].value))
    return fail(syntax.location, syntax.text + "(...) takes one constant distance in metres: " +
                                     syntax.text + "(2)");
  return signal_item(syntax.text, {*need_term(arguments[0])}, syntax.location);
}

}  // namespace scenfuzz::avunit
