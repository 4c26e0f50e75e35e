// CH-Scenario (.chs) as written: the scenario entity module (map, road network, weather, natural
// disasters, special high-risk conditions, entities) and the specification module (safety
// protocols, constraints and their events), each value with where it was written (trees compare
// equal wherever their values were written). docs/ch-scenario.md gives the layout accepted and
// why; nothing here is interpreted yet.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/source_location.hpp"

namespace scenfuzz::chs {

struct Number {
  double value = 0;
  SourceLocation location;  // unknown when the file does not give it (the default holds)

  bool operator==(const Number&) const = default;
};

struct Flag {
  bool value = false;
  SourceLocation location;

  bool operator==(const Flag&) const = default;
};

struct Text {
  std::string text;
  SourceLocation location;

  bool operator==(const Text&) const = default;
};

struct Point {
  double x = 0, y = 0;
  SourceLocation location;    // the whole `(x, y)`
  SourceLocation x_at, y_at;  // each number's text: what a finding rewrites

  bool operator==(const Point&) const = default;
};

// `map: NAME` names a map (an Apollo map or a built-in one); `import from MAP` with a length and
// a width is a blank rectangle on which the road network is laid.
struct MapSource {
  enum class Kind { none, named, blank };
  Kind kind = Kind::none;
  Text name;             // named
  Number length, width;  // blank, m
  SourceLocation location;

  bool operator==(const MapSource&) const = default;
};

// A road by its boundary and centre polylines, in the order written (the driving direction).
struct Road {
  Text name;
  std::vector<Point> left_boundary, centre_lines, right_boundary;
  SourceLocation location;

  bool operator==(const Road&) const = default;
};

// Each in [0, 1] except the air pressure (in atmospheres, > 0): defaults are a clear, dry day.
struct Weather {
  Number cloudiness, wetness, air_pressure{1, {}}, precipitation, wind_intensity, visibility{1, {}};
  SourceLocation location;

  bool operator==(const Weather&) const = default;
};

struct NaturalDisaster {
  Flag rainstorm, sandstorm, typhoon, tornado;  // meteorological
  Flag debris_flow, landslide, collapse;        // geological
  SourceLocation location;

  bool operator==(const NaturalDisaster&) const = default;
};

struct SpecialHighRisk {
  Flag rough, ice_road, steep_descent_ahead, muddy, wade;
  SourceLocation location;

  bool operator==(const SpecialHighRisk&) const = default;
};

// `position: (x, y)` is scenfuzz's addition to both kinds of entity (docs/ch-scenario.md): where
// it starts, on the map. Without it the translation places the entity by its words.
struct StaticEntity {
  Text name, overview;
  std::optional<Point> position;
  SourceLocation location;

  bool operator==(const StaticEntity&) const = default;
};

struct DynamicEntity {
  Text name, timestamp;
  Number speed, acceleration;  // km/h as the grammar's example (45.0 for a minibus), m/s^2
  Text track, aim;             // free text: a direction or manoeuvre, a destination
  std::optional<Point> position;
  SourceLocation location;

  bool operator==(const DynamicEntity&) const = default;
};

// A guard or a safety protocol's predicate: `(wiper = true) && (dist > safedistance)`. In a
// predicate `=` compares, as `==` does.
struct Expression {
  enum class Kind { name, number, boolean, negation, binary };
  Kind kind = Kind::name;
  std::string text;  // name: the name; binary: the operator (&&, ||, ==, !=, <, >, <=, >=)
  double number = 0;
  bool boolean = false;
  std::vector<Expression> operands;  // negation: one; binary: two
  SourceLocation location;

  bool operator==(const Expression&) const = default;
};

// An action's statement: `position++`, `speed--`, `parked = false`.
struct Statement {
  enum class Kind { increment, decrement, assign };
  Kind kind = Kind::assign;
  Text target;
  Expression value;  // assign
  SourceLocation location;

  bool operator==(const Statement&) const = default;
};

// `event: when GUARD do ACTION`, with the probability that it fires when its guard holds.
struct Event {
  Expression guard;
  std::vector<Statement> action;
  Number probability{1, {}};
  SourceLocation location;

  bool operator==(const Event&) const = default;
};

struct Constraint {
  Text name;
  std::vector<Text> related;  // the entities it `relate with`s
  std::vector<Expression> safety_protocols;
  std::vector<Event> events;
  SourceLocation location;

  bool operator==(const Constraint&) const = default;
};

struct File {
  MapSource map;
  std::vector<Road> roads;
  Weather weather;
  NaturalDisaster disaster;
  SpecialHighRisk high_risk;
  std::vector<StaticEntity> static_entities;
  std::vector<DynamicEntity> dynamic_entities;
  std::vector<Expression> safety_protocols;  // of the whole constraint list
  std::vector<Constraint> constraints;

  bool operator==(const File&) const = default;
};

}  // namespace scenfuzz::chs
