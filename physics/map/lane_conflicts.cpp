// Crossing and merging lanes (lane_conflicts.hpp).
#include "physics/map/lane_conflicts.hpp"

#include <algorithm>

namespace scenfuzz {

namespace {

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool segments_cross(MapPoint a, MapPoint b, MapPoint c, MapPoint d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

bool lines_cross(const Polyline& first, const Polyline& second) {
  const auto& p = first.points();
  const auto& q = second.points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    for (std::size_t j = 0; j + 1 < q.size(); ++j)
      if (segments_cross(p[i], p[i + 1], q[j], q[j + 1])) return true;
  return false;
}

bool shares_successor(const Lane& first, const Lane& second) {
  return std::any_of(first.successors.begin(), first.successors.end(), [&](LaneIndex next) {
    return std::find(second.successors.begin(), second.successors.end(), next) !=
           second.successors.end();
  });
}

}  // namespace scenfuzz
