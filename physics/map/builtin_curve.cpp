// The built-in `curve` map: a two-way road that runs east from (0, 0), bends through a circular
// arc and runs straight on. The `fwd_k` lanes drive along the reference line, right of it; the
// `bwd_k` lanes drive back, left of it.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "physics/map/builtin_geometry.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz::builtin {

MapDescription generate_curve(const MapParameters& parameters) {
  const double radius = parameters.value("radius");
  const double angle = parameters.value("angle");
  const double straight_before = parameters.value("straight_before");
  const double straight_after = parameters.value("straight_after");
  const int lanes = parameters.count("lanes");
  const double lane_width = parameters.value("lane_width");
  const double speed_limit = parameters.value("speed_limit");

  // On the inside of the bend the road and its pavement must not reach the arc's centre.
  const double half_road_with_pavement = lanes * lane_width + 3;
  if (!(radius > half_road_with_pavement)) {
    std::ostringstream message;
    message << "built-in map 'curve': radius " << radius << " m is too tight for " << lanes
            << " lanes of " << lane_width << " m each way; it must exceed lanes * lane_width + 3 m "
            << "of pavement = " << half_road_with_pavement << " m";
    throw MapError(message.str());
  }
  if (angle == 0 && straight_before + straight_after <= 0)
    throw MapError(
        "built-in map 'curve': with angle 0, straight_before + straight_after must be positive "
        "(the road would have no length)");

  const std::vector<PathPiece> reference = {straight_piece(straight_before),
                                            arc_piece(radius, radians(angle)),
                                            straight_piece(straight_after)};
  const MapPose start{{0, 0}, 0};

  MapDescription map;
  map.name = "curve";
  map.source = "built-in";
  map.default_lane_width = lane_width;
  for (int k = 0; k < lanes; ++k) {
    double offset = (lanes - k - 0.5) * lane_width;
    LaneDescription forward;
    forward.id = lane_id("fwd_", k);
    forward.centre_line = offset_path(start, reference, -offset);
    forward.right_boundary_type = right_boundary_of(k);
    forward.left_boundary_type = left_boundary_of(k, lanes, BoundaryType::double_yellow);
    forward.speed_limit = speed_limit;
    if (k > 0) forward.right_forward_neighbours = {lane_id("fwd_", k - 1)};
    if (k < lanes - 1) forward.left_forward_neighbours = {lane_id("fwd_", k + 1)};
    if (k == lanes - 1) forward.left_reverse_neighbours = {lane_id("bwd_", k)};
    map.lanes.push_back(std::move(forward));
  }
  for (int k = lanes - 1; k >= 0; --k) {
    double offset = (lanes - k - 0.5) * lane_width;
    LaneDescription backward;
    backward.id = lane_id("bwd_", k);
    backward.centre_line = offset_path(start, reference, offset);
    std::reverse(backward.centre_line.begin(), backward.centre_line.end());
    backward.right_boundary_type = right_boundary_of(k);
    backward.left_boundary_type = left_boundary_of(k, lanes, BoundaryType::double_yellow);
    backward.speed_limit = speed_limit;
    if (k > 0) backward.right_forward_neighbours = {lane_id("bwd_", k - 1)};
    if (k < lanes - 1) backward.left_forward_neighbours = {lane_id("bwd_", k + 1)};
    if (k == lanes - 1) backward.left_reverse_neighbours = {lane_id("fwd_", k)};
    map.lanes.push_back(std::move(backward));
  }
  return map;
}

}  // namespace scenfuzz::builtin
