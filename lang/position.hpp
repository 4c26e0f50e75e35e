// Where an actor is and how it faces: positions on the map, headings, and actor states.
#pragma once

#include <optional>
#include <string>

#include "lang/value.hpp"

namespace scenfuzz {

enum class Frame {
  enu,    // east-north-up map frame (the default)
  imu,    // relative to the ego's initial pose
  wgs84,  // longitude / latitude, needs the map's geo-reference
};

enum class PositionKind {
  coordinate,  // (x, y[, z]) in `frame`
  lane,        // arc length `s` along `lane`'s centre line, `lateral` metres to its left
  relative,    // relative to another actor (WMG SDL): `s` ahead, `lateral` to the left of it
};

struct Position {
  PositionKind kind = PositionKind::coordinate;
  Frame frame = Frame::enu;       // coordinate
  Value x, y;                     // coordinate: metres (ENU, IMU) or degrees (WGS84 x=lon, y=lat)
  std::optional<Value> z;         // coordinate
  std::string lane;               // lane; relative: the lane the actor is in, if given
  Value s;                        // lane: arc length (m); relative: longitudinal offset (m)
  std::optional<Value> lateral;   // lane, relative: lateral offset (m, left positive)
  std::string reference;          // relative: the actor this position is taken from
  std::string relative_location;  // relative: WMG sector F, FSR, SR, RSR, R, RSL, SL, FSL
  SourceLocation location;

  bool operator==(const Position&) const = default;
};

enum class AngleUnit { degree, radian };

// What a heading is measured from. Without one, a heading is absolute in the map frame.
struct Direction {
  enum class Kind { lane, ego, actor };
  Kind kind = Kind::ego;
  std::string lane;   // lane: the lane's direction at arc length `s`
  Value s;            // lane
  std::string actor;  // actor: the heading of the named actor
  SourceLocation location;

  bool operator==(const Direction&) const = default;
};

struct Heading {
  Value angle;  // in `unit`, as written
  AngleUnit unit = AngleUnit::degree;
  std::optional<Direction> relative_to;
  SourceLocation location;

  bool operator==(const Heading&) const = default;
};

// An actor's state at a point of its motion. A missing heading means the lane's direction there.
struct State {
  Position position;
  std::optional<Heading> heading;
  std::optional<Value> speed;         // m/s
  std::optional<Value> acceleration;  // m/s^2
  SourceLocation location;

  bool operator==(const State&) const = default;
};

}  // namespace scenfuzz
