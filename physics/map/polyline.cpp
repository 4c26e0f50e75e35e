// Arc-length parameterised polylines: the geometry under every lane query.
#include "physics/map/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace scenfuzz {

namespace {

// Closer than this, consecutive points are the same point (Apollo curves repeat segment joints).
constexpr double kDuplicatePointDistance = 1e-6;

}  // namespace

Polyline::Polyline(std::span<const MapPoint> points) {
  points_.reserve(points.size());
  arc_lengths_.reserve(points.size());
  for (const MapPoint& point : points) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y))
      throw std::invalid_argument("polyline point is not finite");
    if (!points_.empty()) {
      double step = distance(points_.back(), point);
      if (step <= kDuplicatePointDistance) continue;
      arc_lengths_.push_back(arc_lengths_.back() + step);
    } else {
      arc_lengths_.push_back(0);
    }
    points_.push_back(point);
  }
  if (points_.size() < 2) throw std::invalid_argument("polyline needs two distinct points");
}

std::size_t Polyline::segment_at(double s) const {
  // The last segment whose start is <= s.
  auto after = std::upper_bound(arc_lengths_.begin(), arc_lengths_.end(), s);
  std::size_t index = after == arc_lengths_.begin()
                          ? 0
                          : static_cast<std::size_t>(after - arc_lengths_.begin()) - 1;
  return std::min(index, segment_count() - 1);
}

MapPoint Polyline::point_at(double s) const {
  s = std::clamp(s, 0.0, length());
  std::size_t segment = segment_at(s);
  const MapPoint& a = points_[segment];
  const MapPoint& b = points_[segment + 1];
  double t = (s - arc_lengths_[segment]) / (arc_lengths_[segment + 1] - arc_lengths_[segment]);
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

double Polyline::heading_at(double s) const {
  std::size_t segment = segment_at(std::clamp(s, 0.0, length()));
  const MapPoint& a = points_[segment];
  const MapPoint& b = points_[segment + 1];
  return std::atan2(b.y - a.y, b.x - a.x);
}

PolylineProjection Polyline::project_to_segment(MapPoint point, std::size_t segment) const {
  const MapPoint& a = points_[segment];
  const MapPoint& b = points_[segment + 1];
  double segment_length = arc_lengths_[segment + 1] - arc_lengths_[segment];
  double ux = (b.x - a.x) / segment_length;
  double uy = (b.y - a.y) / segment_length;
  double px = point.x - a.x;
  double py = point.y - a.y;
  double along = std::clamp(px * ux + py * uy, 0.0, segment_length);
  double lateral = ux * py - uy * px;
  PolylineProjection projection;
  projection.s = arc_lengths_[segment] + along;
  projection.lateral = lateral;
  // sqrt, not hypot: this is the innermost loop of every projection, and glibc's hypot (which
  // guards against overflow no map coordinate comes near) costs several times as much.
  const double off_x = px - along * ux, off_y = py - along * uy;
  projection.distance = std::sqrt(off_x * off_x + off_y * off_y);
  projection.segment = segment;
  return projection;
}

PolylineProjection Polyline::project(MapPoint point) const {
  // A segment lies within half its length of its midpoint, so one whose midpoint is farther than
  // the nearest found plus that (and 1 µm for rounding) cannot be nearer: it is skipped before the
  // projection's divisions and square root. The answer is the same, bit for bit.
  constexpr double kRounding = 1e-6;
  PolylineProjection best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t segment = 0; segment < segment_count(); ++segment) {
    const MapPoint& a = points_[segment];
    const MapPoint& b = points_[segment + 1];
    const double mx = 0.5 * (a.x + b.x) - point.x, my = 0.5 * (a.y + b.y) - point.y;
    const double reach =
        best.distance + 0.5 * (arc_lengths_[segment + 1] - arc_lengths_[segment]) + kRounding;
    if (mx * mx + my * my > reach * reach) continue;
    PolylineProjection candidate = project_to_segment(point, segment);
    if (candidate.distance < best.distance) best = candidate;
  }
  return best;
}

}  // namespace scenfuzz
