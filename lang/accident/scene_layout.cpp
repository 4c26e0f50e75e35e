// The built-in maps an accident description's roads are simulated on (scene_layout.hpp).
#include "lang/accident/scene_layout.hpp"

#include <cmath>
#include <numbers>

#include "lang/demand.hpp"

namespace scenfuzz::accident {

namespace {

constexpr double kLaneWidth = 3.5;       // the corpus's and the built-in maps' default
constexpr double kPavement = 3;          // physics/map/builtin_junctions.cpp: kPavementWidth
constexpr double kArmLength = 150;       // every crossroad arm
constexpr double kStraightLength = 400;  // the straight road; the scene's centre in its middle
// A turn: a town corner, with room on each side of it for the run-up.
constexpr double kTurnRadius = 30;
constexpr double kTurnStraights = 150;

SceneLayout crossroad(int lanes) {
  SceneLayout layout;
  layout.map = "crossroads";
  layout.lanes = lanes;
  layout.parameters = {{"lanes", lanes}, {"lane_width", kLaneWidth}, {"arm_length", kArmLength}};
  // Each arm's lanes begin where the junction box ends: the half-size of a road with pavements.
  const double h = lanes * kLaneWidth + kPavement;
  layout.approaches = {{Direction::north, {{0, -h}, {0, 1}}},
                       {Direction::east, {{-h, 0}, {1, 0}}},
                       {Direction::south, {{0, h}, {0, -1}}},
                       {Direction::west, {{h, 0}, {-1, 0}}}};
  return layout;
}

SceneLayout straight(int lanes) {
  SceneLayout layout;
  layout.map = "straight";
  layout.lanes = lanes;
  layout.parameters = {
      {"lanes", lanes}, {"lane_width", kLaneWidth}, {"length", kStraightLength}, {"two_way", 1}};
  layout.origin = {kStraightLength / 2, 0};
  layout.approaches = {{Direction::east, {{0, 0}, {1, 0}}}, {Direction::west, {{0, 0}, {-1, 0}}}};
  return layout;
}

// The `curve` map runs east from its (0, 0) and bends at straight_before: the description's
// (0, 0) is where the bend begins. Eastbound traffic enters the bend there; the other way's
// traffic arrives along the straight after it and enters it at its far end.
SceneLayout turn(bool left, int lanes) {
  SceneLayout layout;
  layout.map = "curve";
  layout.lanes = lanes;
  const double degrees = left ? 90 : -90;
  layout.parameters = {{"radius", kTurnRadius},
                       {"angle", degrees},
                       {"straight_before", kTurnStraights},
                       {"straight_after", kTurnStraights},
                       {"lanes", lanes},
                       {"lane_width", kLaneWidth}};
  layout.origin = {kTurnStraights, 0};
  const double side = left ? 1 : -1;  // the bend's centre is at (0, side * radius)
  const PlanePoint end{kTurnRadius, side * kTurnRadius};
  const PlanePoint after{0, side};  // the direction after a quarter turn
  layout.approaches = {{Direction::east, {{0, 0}, {1, 0}}},
                       {left ? Direction::south : Direction::north, {end, {-after.x, -after.y}}}};
  return layout;
}

}  // namespace

const Approach* SceneLayout::approach(Direction heading) const {
  for (const auto& [direction, way] : approaches)
    if (direction == heading) return &way;
  return nullptr;
}

SceneLayout scene_layout(RoadKind kind, int lanes) {
  switch (kind) {
    case RoadKind::crossroad: return crossroad(lanes);
    case RoadKind::straightroad: return straight(lanes);
    case RoadKind::turn_left: return turn(true, lanes);
    case RoadKind::turn_right: return turn(false, lanes);
  }
  SCENFUZZ_DEMAND(false);
  return {};
}

std::string direction_name(Direction direction) {
  switch (direction) {
    case Direction::north: return "north";
    case Direction::south: return "south";
    case Direction::east: return "east";
    case Direction::west: return "west";
  }
  return "north";
}

}  // namespace scenfuzz::accident
