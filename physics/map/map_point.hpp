// Points and poses in a map's plane (ENU: x east, y north, metres; headings in radians,
// counter-clockwise from +x). Maps are flat: z is dropped when a map is read.
#pragma once

#include <cmath>

namespace scenfuzz {

struct MapPoint {
  double x = 0;
  double y = 0;

  bool operator==(const MapPoint&) const = default;
};

struct MapPose {
  MapPoint position;
  double heading = 0;  // radians, counter-clockwise from +x (east)
};

inline double distance(MapPoint a, MapPoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The angle a - b wrapped to (-pi, pi].
double angle_difference(double a, double b);

}  // namespace scenfuzz
