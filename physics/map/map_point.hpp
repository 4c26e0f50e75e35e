// Points and poses in a map's plane (ENU: x east, y north, metres; headings in radians,
// counter-clockwise from +x). Maps are flat: z is dropped when a map is read.
#pragma once

#include <cmath>
#include <numbers>

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

// a - b wrapped to (-pi, pi] when it lies outside (angle_difference's rare case).
double wrapped_difference(double raw);

// The angle a - b wrapped to (-pi, pi]. Inline: the simulation asks for it tens of times per
// actor and step, and nearly always a - b is already in range (then it is returned as it is:
// remainder would return it unchanged).
inline double angle_difference(double a, double b) {
  const double raw = a - b;
  if (raw > -std::numbers::pi && raw <= std::numbers::pi) return raw;
  return wrapped_difference(raw);
}

}  // namespace scenfuzz
