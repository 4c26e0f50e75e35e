// Places along a CH-Scenario road as written: the point and heading of its centre line at an arc
// length, and how far its boundaries lie on either side there. The translation places entities
// with them; the lanes themselves are built by the map layer (physics/map/outline_map.hpp), whose
// rules these follow: the right half drives in the point order, the left half against it.
#pragma once

#include <vector>

#include "lang/chs/syntax.hpp"

namespace scenfuzz::chs {

struct Station {
  double x = 0, y = 0;
  double heading = 0;  // radians counter-clockwise from east, along the point order
};

double polyline_length(const std::vector<Point>& line);

// The point at arc length `s` (clamped to the line) and the heading of the segment it lies on.
// The line has at least two points (the parser checks).
Station station_at(const std::vector<Point>& line, double s);

// The distance from (x, y) to the nearest point of `line`.
double distance_to(const std::vector<Point>& line, double x, double y);

// The point `offset` metres to the left of a station (negative: to the right).
Station offset_station(const Station& station, double offset);

}  // namespace scenfuzz::chs
