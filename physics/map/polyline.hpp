// A polyline parameterised by arc length: the shape of every lane centre line. Points that
// repeat are dropped when it is built, so every segment has a positive length.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

// The point of a polyline nearest to a query point.
struct PolylineProjection {
  double s = 0;         // arc length of the nearest point
  double lateral = 0;   // signed distance, positive to the left of the direction of travel
  double distance = 0;  // |lateral| unless the nearest point is an end point
  std::size_t segment = 0;
};

class Polyline {
 public:
  Polyline() = default;
  // Needs at least two distinct points; throws std::invalid_argument otherwise.
  explicit Polyline(std::span<const MapPoint> points);

  const std::vector<MapPoint>& points() const { return points_; }
  // Arc length at each point; starts at 0.
  const std::vector<double>& arc_lengths() const { return arc_lengths_; }
  double length() const { return arc_lengths_.empty() ? 0 : arc_lengths_.back(); }
  std::size_t segment_count() const { return points_.empty() ? 0 : points_.size() - 1; }

  // s is clamped to [0, length()].
  MapPoint point_at(double s) const;
  // The direction of the segment containing s (at a vertex, of the segment starting there).
  double heading_at(double s) const;
  std::size_t segment_at(double s) const;

  PolylineProjection project(MapPoint point) const;
  PolylineProjection project_to_segment(MapPoint point, std::size_t segment) const;

 private:
  std::vector<MapPoint> points_;
  std::vector<double> arc_lengths_;
};

}  // namespace scenfuzz
