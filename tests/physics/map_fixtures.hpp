// Small hand-made maps for the lane model tests, independent of the built-in generators.
#pragma once

#include <string>
#include <vector>

#include "physics/map/map_description.hpp"

namespace scenfuzz::test {

inline LaneDescription straight_lane(std::string id, MapPoint from, MapPoint to) {
  LaneDescription lane;
  lane.id = std::move(id);
  lane.centre_line = {from, to};
  return lane;
}

// Two parallel eastbound lanes (a: y = 0, b: y = 3.5, 100 m), a dotted line between them, each
// followed by a 50 m lane; lane `a_next` continues through a junction and turns north as `turn`.
//
//   b (0,3.5)->(100,3.5) -> b_next (100,3.5)->(150,3.5)
//   a (0,0)  ->(100,0)   -> a_next (100,0)  ->(150,0) -> turn (150,0)->(150,50) [junction j]
inline MapDescription two_lane_road() {
  MapDescription map;
  map.name = "two_lane_road";
  map.source = "test";
  LaneDescription a = straight_lane("a", {0, 0}, {100, 0});
  a.successors = {"a_next"};
  a.left_forward_neighbours = {"b"};
  a.left_boundary_type = BoundaryType::dotted_white;
  LaneDescription b = straight_lane("b", {0, 3.5}, {100, 3.5});
  b.successors = {"b_next"};
  b.right_forward_neighbours = {"a"};
  b.right_boundary_type = BoundaryType::dotted_white;
  LaneDescription a_next = straight_lane("a_next", {100, 0}, {150, 0});
  a_next.successors = {"turn"};
  a_next.left_forward_neighbours = {"b_next"};
  a_next.left_boundary_type = BoundaryType::solid_white;
  LaneDescription b_next = straight_lane("b_next", {100, 3.5}, {150, 3.5});
  b_next.right_forward_neighbours = {"a_next"};
  b_next.right_boundary_type = BoundaryType::solid_white;
  LaneDescription turn = straight_lane("turn", {150, 0}, {150, 50});
  turn.junction = "j";
  turn.turn = LaneTurn::left;
  map.lanes = {a, b, a_next, b_next, turn};
  map.junctions = {{"j", {{145, -5}, {155, -5}, {155, 5}, {145, 5}}}};
  TrafficLightDescription signal;
  signal.id = "signal_a";
  signal.stop_lines = {{{90, -1.75}, {90, 5.25}}};
  signal.lanes = {{"a", 90, 90}, {"b", 90, 90}};
  map.traffic_lights = {signal};
  SignDescription stop;
  stop.id = "stop_next";
  stop.lanes = {{"a_next", 45, 45}};
  map.signs = {stop};
  CrosswalkDescription crosswalk;
  crosswalk.id = "crosswalk_turn";
  crosswalk.outline = {{145, 10}, {155, 10}, {155, 14}, {145, 14}};
  crosswalk.lanes = {{"turn", 10, 14}};
  map.crosswalks = {crosswalk};
  return map;
}

}  // namespace scenfuzz::test
