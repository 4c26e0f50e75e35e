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
  if (q.empty()) return false;
  // Segments that cannot reach the other line's bounding box cannot cross it (the same answer,
  // without the cross products for most pairs).
  MapPoint low = q.front(), high = q.front();
  for (MapPoint point : q) {
    low = {std::min(low.x, point.x), std::min(low.y, point.y)};
    high = {std::max(high.x, point.x), std::max(high.y, point.y)};
  }
  auto apart = [](MapPoint a, MapPoint b, MapPoint lo, MapPoint hi) {
    return std::max(a.x, b.x) < lo.x || std::min(a.x, b.x) > hi.x || std::max(a.y, b.y) < lo.y ||
           std::min(a.y, b.y) > hi.y;
  };
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (apart(p[i], p[i + 1], low, high)) continue;
    const MapPoint lo{std::min(p[i].x, p[i + 1].x), std::min(p[i].y, p[i + 1].y)};
    const MapPoint hi{std::max(p[i].x, p[i + 1].x), std::max(p[i].y, p[i + 1].y)};
    for (std::size_t j = 0; j + 1 < q.size(); ++j)
      if (!apart(q[j], q[j + 1], lo, hi) && segments_cross(p[i], p[i + 1], q[j], q[j + 1]))
        return true;
  }
  return false;
}

bool shares_successor(const Lane& first, const Lane& second) {
  return std::any_of(first.successors.begin(), first.successors.end(), [&](LaneIndex next) {
    return std::find(second.successors.begin(), second.successors.end(), next) !=
           second.successors.end();
  });
}

std::vector<LaneIndex> conflicting_lanes(const RoadMap& map, LaneIndex lane) {
  const Lane& mine = map.lane(lane);
  std::vector<LaneIndex> conflicts;
  for (LaneIndex other = 0; other < map.lanes().size(); ++other) {
    const Lane& candidate = map.lane(other);
    if (other == lane || !mine.junction || candidate.junction != mine.junction) continue;
    if (shares_successor(mine, candidate) || lines_cross(mine.centre_line, candidate.centre_line))
      conflicts.push_back(other);
  }
  return conflicts;
}

}  // namespace scenfuzz
