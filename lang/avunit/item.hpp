// What an AVUnit expression evaluates to while a file is elaborated. AVUnit is dynamically typed:
// `(a, b)` is a coordinate, a state, a vehicle type or a colour depending on where it is used, so
// tuples stay tuples until a use site coerces them.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

enum class ItemKind {
  error,  // already reported: every use of it stays silent
  empty,  // a left-out argument
  star,   // `*`
  number,
  time,    // seconds since midnight
  string,  // `word` holds the text
  word,    // a keyword-like name: colours, vehicle kinds, shapes, levels, EGO, ego/truth/...
  tuple,
  set,
  keyed,  // `word: elements[0]`
  position,
  heading,
  state,
  motion,
  actor_type,
  shape,
  actor,
  obstacle,
  environment,
  map,
  scenario,
  trace,       // `word` is the trace's name
  projection,  // trace[ego], trace[truth][npc1]; trace[truth] alone is incomplete
  term,
  formula,
  intersection,
  speed_limit,
};

// The parts of one CreateScenario{...}, shared by every variable that holds it.
struct ScenarioParts {
  MapReference map;
  Actor ego;
  std::vector<Actor> vehicles;
  std::vector<Actor> pedestrians;
  std::vector<Obstacle> obstacles;
  std::optional<Environment> environment;
  Traffic traffic;
  SourceLocation location;
};

struct Projection {
  std::string trace;
  ObjectSource source = ObjectSource::ego;
  std::string agent;
  bool complete = false;
};

struct Item {
  ItemKind kind = ItemKind::error;
  SourceLocation location;
  std::string word;
  Value value;  // number, time
  std::vector<Item> elements;
  std::variant<std::monostate, Position, Heading, State, Motion, ActorType, Shape, Actor, Obstacle,
               Environment, MapReference, std::shared_ptr<const ScenarioParts>, Projection,
               SpecTerm, Formula, IntersectionControl, SpeedLimit>
      payload;
};

// How an item is named in messages: "a number", "a tuple of 3 elements", "vehicle 'npc1'".
std::string describe(const Item& item);

}  // namespace scenfuzz::avunit
