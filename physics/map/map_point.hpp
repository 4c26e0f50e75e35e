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

// sqrt rather than std::hypot: map coordinates never come near overflow, and glibc's hypot costs
// several times as much in the simulation's inner loops.
inline double distance(MapPoint a, MapPoint b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

// The angle a - b wrapped to (-pi, pi].
double angle_difference(double a, double b);

}  // namespace scenfuzz
