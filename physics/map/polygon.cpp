// Point-in-polygon by the crossing number, plus the outline's margin.
#include "physics/map/polygon.hpp"

#include <algorithm>

namespace scenfuzz {
namespace {

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

double distance_to_segment(MapPoint p, MapPoint a, MapPoint b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double length2 = dx * dx + dy * dy;
  double t =
      length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0;
  return distance(p, {a.x + t * dx, a.y + t * dy});
}

bool near_polygon(MapPoint p, const std::vector<MapPoint>& polygon, double margin) {
  if (polygon.size() < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const MapPoint& a = polygon[j];
    const MapPoint& b = polygon[i];
    if ((a.y > p.y) != (b.y > p.y) && (cross(a, b, p) > 0) == (b.y > a.y)) inside = !inside;
    if (distance_to_segment(p, a, b) <= margin) return true;
  }
  return inside;
}

}  // namespace scenfuzz
