// Each segment's unit direction, computed once for a polyline projected onto many times (a lane
// follower's path, every actor at every scan): Polyline::project_to_segment divides by the
// segment's length twice per call. The projection below is its arithmetic step for step, with
// the two quotients taken from the table, so its results are the same bit for bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "physics/map/polyline.hpp"

namespace scenfuzz {

class SegmentFrames {
 public:
  SegmentFrames() = default;
  explicit SegmentFrames(const Polyline& path) {
    directions_.reserve(path.segment_count());
    extend(path, path.segment_count());
  }

  // The frames of the segments before `segments` (made as far as a caller reads).
  void extend(const Polyline& path, std::size_t segments) {
    const auto& points = path.points();
    const auto& arc = path.arc_lengths();
    for (std::size_t segment = directions_.size(); segment < segments; ++segment) {
      const double length = arc[segment + 1] - arc[segment];
      directions_.push_back({(points[segment + 1].x - points[segment].x) / length,
                             (points[segment + 1].y - points[segment].y) / length});
    }
  }
  std::size_t segments() const { return directions_.size(); }
  MapPoint direction(std::size_t segment) const { return directions_[segment]; }
  void reserve(std::size_t segments) { directions_.reserve(segments); }

  // Polyline::project_to_segment(point, segment) of the polyline these frames were made from.
  PolylineProjection project(const Polyline& path, MapPoint point, std::size_t segment) const {
    const Offset offset = offset_from(path, point, segment);
    PolylineProjection projection;
    projection.s = path.arc_lengths()[segment] + offset.along;
    projection.lateral = offset.lateral;
    projection.distance = std::sqrt(offset.squared);
    projection.segment = segment;
    return projection;
  }

  // project(path, point, segment).distance squared, without the root (and without the arc length
  // and lateral offset): for finding the nearest segment, comparing squares first.
  double distance_squared(const Polyline& path, MapPoint point, std::size_t segment) const {
    return offset_from(path, point, segment).squared;
  }

 private:
  struct Offset {
    double along = 0;    // m from the segment's start to the foot, clamped to the segment
    double lateral = 0;  // m left of the segment's line
    double squared = 0;  // m^2 from the foot to the point
  };

  // One computation for project and distance_squared, so that their answers agree bit for bit.
  Offset offset_from(const Polyline& path, MapPoint point, std::size_t segment) const {
    const MapPoint& a = path.points()[segment];
    const double segment_length = path.arc_lengths()[segment + 1] - path.arc_lengths()[segment];
    const double ux = directions_[segment].x, uy = directions_[segment].y;
    const double px = point.x - a.x;
    const double py = point.y - a.y;
    Offset offset;
    offset.along = std::clamp(px * ux + py * uy, 0.0, segment_length);
    offset.lateral = ux * py - uy * px;
    const double off_x = px - offset.along * ux, off_y = py - offset.along * uy;
    offset.squared = off_x * off_x + off_y * off_y;
    return offset;
  }

  std::vector<MapPoint> directions_;  // unit vector along each segment
};

}  // namespace scenfuzz
