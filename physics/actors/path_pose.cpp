// Poses along a path with its heading blended through the vertices (see path_pose.hpp).
#include "physics/actors/path_pose.hpp"

#include <algorithm>
#include <cmath>

#include "physics/map/segment_walk.hpp"

namespace scenfuzz {
namespace {

// Within this distance of a vertex (and at most half of each adjoining segment) the heading turns
// linearly from one segment's heading to the next.
constexpr double kHeadingBlendDistance = 2;

double wrap_angle(double angle) { return angle_difference(angle, 0); }

double segment_length(const Polyline& path, std::size_t segment) {
  return path.arc_lengths()[segment + 1] - path.arc_lengths()[segment];
}

double segment_heading(const Polyline& path, std::size_t segment) {
  const MapPoint& a = path.points()[segment];
  const MapPoint& b = path.points()[segment + 1];
  return std::atan2(b.y - a.y, b.x - a.x);
}

// The heading at s on `segment`, continuous along the path, and its derivative; `heading(k)` is
// segment k's direction (only the segment's and its neighbours' are asked for).
template <typename SegmentHeading>
PathDirection direction_on(const Polyline& path, const SegmentHeading& heading_of,
                           std::size_t segment, double s) {
  double heading = heading_of(segment);
  double from_start = s - path.arc_lengths()[segment];
  double to_end = path.arc_lengths()[segment + 1] - s;
  if (segment > 0) {
    double blend = blend_half_width(path, segment);
    if (from_start < blend) {
      double turn = angle_difference(heading, heading_of(segment - 1));
      return {wrap_angle(heading - 0.5 * turn * (1 - from_start / blend)), turn / (2 * blend)};
    }
  }
  if (segment + 1 < path.segment_count()) {
    double blend = blend_half_width(path, segment + 1);
    if (to_end < blend) {
      double turn = angle_difference(heading_of(segment + 1), heading);
      return {wrap_angle(heading + 0.5 * turn * (1 - to_end / blend)), turn / (2 * blend)};
    }
  }
  return {heading, 0};
}

PathDirection direction_on(const Polyline& path, std::span<const double> headings,
                           std::size_t segment, double s) {
  return direction_on(
      path, [&](std::size_t k) { return headings[k]; }, segment, s);
}

}  // namespace

double blend_half_width(const Polyline& path, std::size_t vertex) {
  return std::min({kHeadingBlendDistance, 0.5 * segment_length(path, vertex - 1),
                   0.5 * segment_length(path, vertex)});
}

std::vector<double> segment_headings(const Polyline& path) {
  std::vector<double> headings;
  headings.reserve(path.segment_count());
  for (std::size_t segment = 0; segment < path.segment_count(); ++segment)
    headings.push_back(segment_heading(path, segment));
  return headings;
}

PathDirection direction_at(const Polyline& path, double s) {
  s = std::clamp(s, 0.0, path.length());
  return direction_on(
      path, [&](std::size_t k) { return segment_heading(path, k); }, path.segment_at(s), s);
}

PathDirection direction_at(const Polyline& path, std::span<const double> headings, double s) {
  s = std::clamp(s, 0.0, path.length());
  return direction_on(path, headings, path.segment_at(s), s);
}

double vertex_curvature(const Polyline& path, std::span<const double> headings,
                        std::size_t vertex) {
  if (vertex == 0 || vertex + 1 >= path.points().size()) return 0;
  double turn = angle_difference(headings[vertex], headings[vertex - 1]);
  return std::abs(turn) / (2 * blend_half_width(path, vertex));
}

Polyline round_corners(const Polyline& path, double min_radius) {
  constexpr int kPasses = 200;
  constexpr double kMargin = 0.95;  // of the curvature allowed, for the blend's rounding
  if (!(min_radius > 0) || path.points().size() < 3) return path;
  const double allowed = kMargin / min_radius;
  Polyline rounded = path;
  for (int pass = 0; pass < kPasses; ++pass) {
    const std::vector<double> headings = segment_headings(rounded);
    std::vector<MapPoint> points = rounded.points();
    bool moved = false;
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
      if (vertex_curvature(rounded, headings, i) <= allowed) continue;
      const MapPoint& before = rounded.points()[i - 1];
      const MapPoint& after = rounded.points()[i + 1];
      points[i] = {0.5 * points[i].x + 0.25 * (before.x + after.x),
                   0.5 * points[i].y + 0.25 * (before.y + after.y)};
      moved = true;
    }
    if (!moved) break;
    rounded = Polyline(points);
  }
  return rounded;
}

double planning_radius(const ActorClass& body) {
  constexpr double kLockMargin = 1.05;
  return kLockMargin * body.min_turning_radius();
}

namespace {

// The state at clamped arc length s, which lies on `segment`.
KinematicState state_on_segment(const Polyline& path, std::span<const double> headings,
                                std::size_t segment, double s, double speed, double acceleration) {
  const MapPoint& a = path.points()[segment];
  const MapPoint& b = path.points()[segment + 1];
  double t = (s - path.arc_lengths()[segment]) / segment_length(path, segment);
  PathDirection direction = direction_on(path, headings, segment, s);
  KinematicState state;
  state.x = a.x + t * (b.x - a.x);
  state.y = a.y + t * (b.y - a.y);
  state.heading = direction.heading;
  state.speed = speed;
  state.acceleration = acceleration;
  state.yaw_rate = speed * direction.curvature;
  return state;
}

}  // namespace

VertexBlend vertex_blend(const Polyline& path, std::span<const double> headings,
                         std::size_t vertex) {
  return {blend_half_width(path, vertex), angle_difference(headings[vertex], headings[vertex - 1])};
}

// direction_on's heading and state_on_segment's position, in their arithmetic.
MapPose pose_on_segment(const Polyline& path, std::span<const double> headings,
                        std::span<const VertexBlend> blends, std::size_t segment, double s) {
  const auto& arc = path.arc_lengths();
  const MapPoint& a = path.points()[segment];
  const MapPoint& b = path.points()[segment + 1];
  const double from_start = s - arc[segment];
  const double to_end = arc[segment + 1] - s;
  const double t = from_start / (arc[segment + 1] - arc[segment]);
  const MapPoint position{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  const double heading = headings[segment];
  if (segment > 0 && from_start < blends[segment].half_width) {
    const VertexBlend& blend = blends[segment];
    return {position, wrap_angle(heading - 0.5 * blend.turn * (1 - from_start / blend.half_width))};
  }
  if (segment + 1 < path.segment_count() && to_end < blends[segment + 1].half_width) {
    const VertexBlend& blend = blends[segment + 1];
    return {position, wrap_angle(heading + 0.5 * blend.turn * (1 - to_end / blend.half_width))};
  }
  return {position, heading};
}

KinematicState state_on_path(const Polyline& path, std::span<const double> headings, double s,
                             double speed, double acceleration) {
  s = std::clamp(s, 0.0, path.length());
  return state_on_segment(path, headings, path.segment_at(s), s, speed, acceleration);
}

KinematicState state_on_path(const Polyline& path, std::span<const double> headings, double s,
                             double speed, double acceleration, std::size_t hint) {
  s = std::clamp(s, 0.0, path.length());
  return state_on_segment(path, headings, segment_at_from(path, s, hint), s, speed, acceleration);
}

}  // namespace scenfuzz
