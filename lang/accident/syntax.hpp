// The accident formalism of CarSim (Dupuy, Egges, Legendre, Nugues 2001) as written in a `.acc`
// file: the static objects of the scene (the road layout, trees, traffic lights, level crossings,
// stop signs), the vehicles with their chains of events, and the collisions. Every value keeps
// where it was written, so that a translation can point its diagnostics at it and a finding can
// replace a number in the user's text; trees compare equal wherever their values were written
// (SourceLocation's == holds always). docs/accident.md gives the layout accepted and why; nothing
// here is interpreted yet.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/source_location.hpp"

namespace scenfuzz::accident {

// An object's `ID = name;`, or a reference to one (an actor, a victim, a start sign).
struct Name {
  std::string text;
  SourceLocation location;

  bool operator==(const Name&) const = default;
};

// `( x , y )` in metres: x east, y north (docs/accident.md).
struct Point {
  double x = 0, y = 0;
  SourceLocation location;    // the whole `( x , y )`
  SourceLocation x_at, y_at;  // each number's text: what a finding rewrites

  bool operator==(const Point&) const = default;
};

// One of a closed list of lower-case words (`crossroad`, `red`, `truck`, ...), where written.
template <typename Value>
struct Word {
  Value value{};
  SourceLocation location;

  bool operator==(const Word&) const = default;
};

enum class RoadKind { crossroad, straightroad, turn_left, turn_right };
enum class Colour { red, orange, green, inactive };
enum class VehicleKind { car, truck };
enum class Direction { north, south, east, west };
enum class EventKind {
  driving_forward,
  turn_left,
  turn_right,
  stop,
  overtake,
  change_lane_left,
  change_lane_right
};
enum class Part { front, rear, leftside, rightside, unknown };

// The road layout of the whole scene: a description has exactly one.
struct Road {
  Word<RoadKind> kind;
  SourceLocation location;

  bool operator==(const Road&) const = default;
};

struct Tree {
  Name id;
  Point coords;
  SourceLocation location;

  bool operator==(const Tree&) const = default;
};

struct Light {
  Name id;
  Word<Colour> colour;
  Point coords;
  SourceLocation location;

  bool operator==(const Light&) const = default;
};

struct LevelCrossing {
  Point coords;
  SourceLocation location;

  bool operator==(const LevelCrossing&) const = default;
};

struct StopSign {
  Point coords;
  SourceLocation location;

  bool operator==(const StopSign&) const = default;
};

// `STARTSIGN = light1;` names a static object with an ID (a LIGHT or a TREE); `STARTSIGN =
// (0, -20);` gives a place, such as that of a STOPSIGN, which has no ID.
struct SignReference {
  enum class Kind { name, point };
  Kind kind = Kind::name;
  Name name;    // name
  Point point;  // point
  SourceLocation location;

  bool operator==(const SignReference&) const = default;
};

// An EVENT or a CRITICAL_EVENT of a vehicle's CHAIN, in the order written.
struct Event {
  Word<EventKind> kind;
  bool critical = false;
  SourceLocation location;

  bool operator==(const Event&) const = default;
};

struct Vehicle {
  Name id;
  Word<VehicleKind> kind;
  std::optional<Word<Direction>> init_direction;
  std::optional<SignReference> start_sign, end_sign;
  std::vector<Event> chain;  // empty when the vehicle has no CHAIN (a written CHAIN is not)
  SourceLocation location;

  bool operator==(const Vehicle&) const = default;
};

// `ACTOR = car1, front;`: who, and which part of it was hit.
struct Involvement {
  Name id;
  Word<Part> part;
  SourceLocation location;

  bool operator==(const Involvement&) const = default;
};

// The actor is a vehicle; the victim a vehicle or a static object with an ID (a TREE, a LIGHT).
struct Collision {
  Involvement actor, victim;
  std::optional<Point> coords;
  SourceLocation location;

  bool operator==(const Collision&) const = default;
};

struct File {
  // STATIC
  Road road;
  std::vector<Tree> trees;
  std::vector<Light> lights;
  std::vector<LevelCrossing> crossings;
  std::vector<StopSign> stop_signs;
  // DYNAMIC
  std::vector<Vehicle> vehicles;
  // ACCIDENT
  std::vector<Collision> collisions;
  // Where each part's keyword was written.
  SourceLocation static_at, dynamic_at, accident_at;

  bool operator==(const File&) const = default;
};

}  // namespace scenfuzz::accident
