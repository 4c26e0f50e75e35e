// CH-Scenario (.chs) as written: the scenario entity module (map, road network, weather, natural
// disasters, special high-risk conditions, entities) and the specification module (safety
// protocols, constraints and their events), each value with where it was written.
// docs/ch-scenario.md gives the layout accepted and why; nothing here is interpreted yet.
#pragma once

#include <string>
#include <vector>

#include "lang/source_location.hpp"

namespace scenfuzz::chs {

struct Number {
  double value = 0;
  SourceLocation location;  // unknown when the file does not give it (the default holds)
};

struct Flag {
  bool value = false;
  SourceLocation location;
};

struct Text {
  std::string text;
  SourceLocation location;
};

struct Point {
  double x = 0, y = 0;
  SourceLocation location;
};

// `map: NAME` names a map (an Apollo map or a built-in one); `import from MAP` with a length and
// a width is a blank rectangle on which the road network is laid.
struct MapSource {
  enum class Kind { none, named, blank };
  Kind kind = Kind::none;
  Text name;             // named
  Number length, width;  // blank, m
  SourceLocation location;
};

// A road by its boundary and centre polylines, in the order written (the driving direction).
struct Road {
  Text name;
  std::vector<Point> left_boundary, centre_lines, right_boundary;
  SourceLocation location;
};

// Each in [0, 1] except the air pressure (in atmospheres, > 0): defaults are a clear, dry day.
struct Weather {
  Number cloudiness, wetness, air_pressure{1, {}}, precipitation, wind_intensity, visibility{1, {}};
  SourceLocation location;
};

struct NaturalDisaster {
  Flag rainstorm, sandstorm, typhoon, tornado;  // meteorological
  Flag debris_flow, landslide, collapse;        // geological
  SourceLocation location;
};

struct SpecialHighRisk {
  Flag rough, ice_road, steep_descent_ahead, muddy, wade;
  SourceLocation location;
};

struct StaticEntity {
  Text name, overview;
  SourceLocation location;
};

struct DynamicEntity {
  Text name, timestamp;
  Number speed, acceleration;  // km/h as the grammar's example (45.0 for a minibus), m/s^2
  Text track, aim;             // free text: a direction or manoeuvre, a destination
  SourceLocation location;
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
};

// An action's statement: `position++`, `speed--`, `parked = false`.
struct Statement {
  enum class Kind { increment, decrement, assign };
  Kind kind = Kind::assign;
  Text target;
  Expression value;  // assign
  SourceLocation location;
};

// `event: when GUARD do ACTION`, with the probability that it fires when its guard holds.
struct Event {
  Expression guard;
  std::vector<Statement> action;
  Number probability{1, {}};
  SourceLocation location;
};

struct Constraint {
  Text name;
  std::vector<Text> related;  // the entities it `relate with`s
  std::vector<Expression> safety_protocols;
  std::vector<Event> events;
  SourceLocation location;
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
};

}  // namespace scenfuzz::chs
