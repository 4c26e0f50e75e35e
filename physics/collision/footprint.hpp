// Bodies seen from above: an oriented rectangle (vehicles, box obstacles) or a disc
// (pedestrians, round obstacles). Exact 2-D distances between them, negative when they overlap,
// because FCL's signed distance is unusable for boxes on a plane
// (../shared/reference/dependencies.md); and which side of a body a point lies on.
#pragma once

#include "physics/collision/body_side.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

struct Footprint {
  MapPoint centre;
  double heading = 0;      // rad; the direction of the body's front
  double half_length = 0;  // along the heading; a disc's radius
  double half_width = 0;   // across; a disc's radius
  bool round = false;      // a disc of radius half_length
};

// The distance between the two shapes when apart, 0 when touching, and minus the penetration
// depth (the shortest translation that separates them) when they overlap.
double signed_distance(const Footprint& a, const Footprint& b);

// The side of `body` nearest to `point` (a contact point): front or rear when the point lies
// further out along the body's length than across it, relative to the half extents.
BodySide side_of(const Footprint& body, MapPoint point);

}  // namespace scenfuzz
