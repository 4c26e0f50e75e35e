// The built-in `merge` map: an on-ramp joining a one-way main road. The main road runs along +x
// from x = 0 with lanes `main_k` north of y = 0 (main_0 at the kerb); the ramp `ramp_0` climbs in
// from the south-west at the merge angle and bends into the acceleration lane `accel_0`, which
// runs beside main_0 and ends: a car on it must change left into main_0 before its end.
#include <algorithm>
#include <numbers>
#include <utility>
#include <vector>

#include "physics/map/builtin_geometry.hpp"

namespace scenfuzz::builtin {

MapDescription generate_merge(const MapParameters& parameters) {
  const int lanes = parameters.count("lanes");
  const double lane_width = parameters.value("lane_width");
  const double approach_length = parameters.value("approach_length");
  const double accel_length = parameters.value("accel_length");
  const double after_length = parameters.value("after_length");
  const double ramp_length = parameters.value("ramp_length");
  const double ramp_radius = parameters.value("ramp_radius");
  const double merge_angle = radians(parameters.value("merge_angle"));
  const double speed_limit = parameters.value("speed_limit");
  const double ramp_speed_limit = parameters.value("ramp_speed_limit");

  const double main_length = approach_length + accel_length + after_length;
  const double accel_y = -lane_width / 2;

  MapDescription map;
  map.name = "merge";
  map.source = "built-in";
  map.default_lane_width = lane_width;
  for (int k = 0; k < lanes; ++k) {
    double y = (k + 0.5) * lane_width;
    LaneDescription main;
    main.id = lane_id("main_", k);
    main.centre_line = {{0, y}, {main_length, y}};
    // main_0's right edge is a kerb along most of its length; the change onto the ending
    // acceleration lane is not offered, the change off it is (accel_0's left edge is dotted).
    main.right_boundary_type = right_boundary_of(k);
    main.left_boundary_type = left_boundary_of(k, lanes, BoundaryType::curb);
    main.speed_limit = speed_limit;
    if (k > 0) main.right_forward_neighbours = {lane_id("main_", k - 1)};
    if (k < lanes - 1) main.left_forward_neighbours = {lane_id("main_", k + 1)};
    if (k == 0) main.right_forward_neighbours = {"accel_0"};
    map.lanes.push_back(std::move(main));
  }

  LaneDescription accel;
  accel.id = "accel_0";
  accel.centre_line = {{approach_length, accel_y}, {approach_length + accel_length, accel_y}};
  accel.left_boundary_type = BoundaryType::dotted_white;
  accel.right_boundary_type = BoundaryType::curb;
  accel.speed_limit = speed_limit;
  accel.left_forward_neighbours = {"main_0"};
  accel.predecessors = {"ramp_0"};

  // Built backwards from where the acceleration lane begins: the bend (turning right when
  // driven, left when traced backwards), then the straight part of the ramp.
  LaneDescription ramp;
  ramp.id = "ramp_0";
  const std::vector<PathPiece> backwards = {arc_piece(ramp_radius, merge_angle),
                                            straight_piece(ramp_length)};
  ramp.centre_line = offset_path({{approach_length, accel_y}, std::numbers::pi}, backwards, 0);
  std::reverse(ramp.centre_line.begin(), ramp.centre_line.end());
  ramp.left_boundary_type = BoundaryType::curb;
  ramp.right_boundary_type = BoundaryType::curb;
  ramp.speed_limit = ramp_speed_limit;
  ramp.successors = {"accel_0"};

  map.lanes.push_back(std::move(ramp));
  map.lanes.push_back(std::move(accel));
  return map;
}

}  // namespace scenfuzz::builtin
