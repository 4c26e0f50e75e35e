// What an AVUnit expression evaluates to while a file is elaborated. AVUnit is dynamically typed:
// `(a, b)` is a coordinate, a state, a vehicle type or a colour depending on where it is used, so
// tuples stay tuples until a use site coerces them.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "lang/boxed.hpp"
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
  flow,           // Flow(...): background traffic (docs/avunit.md, "Extensions")
  npc_behaviour,  // NPCBehaviour(...): `word` is "reactive" or "scripted"
  traffic_light,  // TrafficLight(...): a light's colour at the start
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
  std::optional<NpcBehaviour> npc_behaviour;
  SourceLocation location;
};

struct Projection {
  std::string trace;
  ObjectSource source = ObjectSource::ego;
  std::string agent;
  bool complete = false;
};

// Each alternative is boxed: an actor takes 2 KB and a position 500 bytes, while a file of many
// small assignments holds hundreds of thousands of items, most with no payload at all (numbers,
// strings, tuples). A box allocates only the size of what it holds.
using ItemPayload =
    std::variant<std::monostate, Boxed<Position>, Boxed<Heading>, Boxed<State>, Boxed<Motion>,
                 Boxed<ActorType>, Boxed<Shape>, Boxed<Actor>, Boxed<Obstacle>, Boxed<Environment>,
                 Boxed<MapReference>, Boxed<std::shared_ptr<const ScenarioParts>>,
                 Boxed<Projection>, Boxed<SpecTerm>, Boxed<Formula>, Boxed<IntersectionControl>,
                 Boxed<SpeedLimit>, Boxed<TrafficFlow>, Boxed<TrafficLightSetting>>;

struct Item {
  ItemKind kind = ItemKind::error;
  SourceLocation location;
  std::string word;
  Value value;  // number, time
  std::vector<Item> elements;
  ItemPayload payload;
};

// The payload of an item of the kind that carries a T (throws std::bad_variant_access otherwise,
// a programmer bug).
template <class T>
T& payload_of(Item& item) {
  return *std::get<Boxed<T>>(item.payload);
}
template <class T>
const T& payload_of(const Item& item) {
  return *std::get<Boxed<T>>(item.payload);
}

// How an item is named in messages: "a number", "a tuple of 3 elements", "vehicle 'npc1'".
std::string describe(const Item& item);

}  // namespace scenfuzz::avunit
