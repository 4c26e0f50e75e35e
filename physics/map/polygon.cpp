// Point-in-polygon by the crossing number, plus the outline's margin.
#include "physics/map/polygon.hpp"

#include <algorithm>

namespace scenfuzz {
namespace {

// m beyond the margin within which the box test below leaves the answer to the exact test: far
// above the rounding of a foot point on an outline (about 1e-10 m at UTM coordinates).
constexpr double kRoundingSlack = 1e-6;

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether p lies farther than `reach` from the polygon's bounding box along x or y: then it is
// outside the polygon and farther than `reach` from every edge. Callers ask mostly about points
// nowhere near (every pedestrian against every crosswalk ahead), and this skips the edges' roots.
bool clear_of_box(MapPoint p, const std::vector<MapPoint>& polygon, double reach) {
  double low_x = polygon[0].x, high_x = low_x, low_y = polygon[0].y, high_y = low_y;
  for (const MapPoint& vertex : polygon) {
    low_x = std::min(low_x, vertex.x);
    high_x = std::max(high_x, vertex.x);
    low_y = std::min(low_y, vertex.y);
    high_y = std::max(high_y, vertex.y);
  }
  return p.x < low_x - reach || p.x > high_x + reach || p.y < low_y - reach || p.y > high_y + reach;
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
  if (clear_of_box(p, polygon, std::max(margin, 0.0) + kRoundingSlack)) return false;
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
