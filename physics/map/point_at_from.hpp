// Polyline::point_at from a known segment: a caller that has found the segment of s already (for
// a heading there, or a projection's) need not binary-search the polyline again. The arithmetic
// is point_at's, step for step, so the point is the same bit for bit.
#pragma once

#include <algorithm>
#include <cstddef>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/segment_walk.hpp"

namespace scenfuzz {

// path.point_at(s), walking from segment `hint` (any index; the nearer s, the cheaper).
inline MapPoint point_at_from(const Polyline& path, double s, std::size_t hint) {
  s = std::clamp(s, 0.0, path.length());
  const std::size_t segment = segment_at_from(path, s, hint);
  const MapPoint& a = path.points()[segment];
  const MapPoint& b = path.points()[segment + 1];
  const auto& arc = path.arc_lengths();
  const double t = (s - arc[segment]) / (arc[segment + 1] - arc[segment]);
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

}  // namespace scenfuzz
