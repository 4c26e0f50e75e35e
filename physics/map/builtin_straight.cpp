// The built-in `straight` map: one straight road along +x, east-bound lanes `east_k` south of the
// centre line y = 0 and (on a two-way road) west-bound lanes `west_k` north of it.
#include <utility>

#include "physics/map/builtin_geometry.hpp"

namespace scenfuzz::builtin {

MapDescription generate_straight(const MapParameters& parameters) {
  const int lanes = parameters.count("lanes");
  const double lane_width = parameters.value("lane_width");
  const double length = parameters.value("length");
  const bool two_way = parameters.flag("two_way");
  const double speed_limit = parameters.value("speed_limit");

  MapDescription map;
  map.name = "straight";
  map.source = "built-in";
  map.default_lane_width = lane_width;
  // A one-way road keeps its lanes where a two-way road has them, so scenarios written for one
  // stay valid on the other; its left edge is then a kerb instead of the centre line.
  const BoundaryType centre_line = two_way ? BoundaryType::double_yellow : BoundaryType::curb;

  for (int k = 0; k < lanes; ++k) {
    double offset = (lanes - k - 0.5) * lane_width;
    LaneDescription east;
    east.id = lane_id("east_", k);
    east.centre_line = {{0, -offset}, {length, -offset}};
    east.right_boundary_type = right_boundary_of(k);
    east.left_boundary_type = left_boundary_of(k, lanes, centre_line);
    east.speed_limit = speed_limit;
    if (k > 0) east.right_forward_neighbours = {lane_id("east_", k - 1)};
    if (k < lanes - 1) east.left_forward_neighbours = {lane_id("east_", k + 1)};
    if (k == lanes - 1 && two_way) east.left_reverse_neighbours = {lane_id("west_", k)};
    map.lanes.push_back(std::move(east));
  }
  if (!two_way) return map;
  for (int k = lanes - 1; k >= 0; --k) {
    double offset = (lanes - k - 0.5) * lane_width;
    LaneDescription west;
    west.id = lane_id("west_", k);
    west.centre_line = {{length, offset}, {0, offset}};
    west.right_boundary_type = right_boundary_of(k);
    west.left_boundary_type = left_boundary_of(k, lanes, centre_line);
    west.speed_limit = speed_limit;
    if (k > 0) west.right_forward_neighbours = {lane_id("west_", k - 1)};
    if (k < lanes - 1) west.left_forward_neighbours = {lane_id("west_", k + 1)};
    if (k == lanes - 1) west.left_reverse_neighbours = {lane_id("east_", k)};
    map.lanes.push_back(std::move(west));
  }
  return map;
}

}  // namespace scenfuzz::builtin
