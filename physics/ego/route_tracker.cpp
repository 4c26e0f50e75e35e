// Route tracking for the ego: the path, its features and limits, computed once per run; progress
// and object positions found by searching only the stretch of path near the ego.
#include "physics/ego/route_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/actors/path_pose.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/map/segment_walk.hpp"

namespace scenfuzz {
namespace {

// Curvature is measured over this many path vertices on either side, so that the polyline's
// small kinks (1 m spacing) do not look like sharp bends.
constexpr std::size_t kCurvatureReach = 3;
// locate() first looks at every this-many path vertices.
constexpr std::size_t kCoarseStride = 4;

}  // namespace

RouteTracker::RouteTracker(const RoadMap& map, const LaneRoute& route,
                           std::span<const std::pair<LaneIndex, double>> speed_limits,
                           double default_speed_limit) {
  if (route.segments.empty()) return;
  path_ = route_path(map, route);
  lane_changes_ = lane_change_stretches(map, route);
  segments_ = route.segments;

  double route_s = 0;
  for (const RouteSegment& segment : route.segments) {
    const Lane& lane = map.lane(segment.lane);
    double limit = lane.speed_limit > 0 ? lane.speed_limit : default_speed_limit;
    for (const auto& [limited_lane, speed] : speed_limits)
      if (limited_lane == segment.lane && speed > 0) limit = speed;
    limit_s_.push_back(route_s);
    limit_speed_.push_back(limit);
    for (const LaneFeature& feature : lane.features) {
      if (feature.s_end < segment.s_begin || feature.s_begin > segment.s_end) continue;
      double s = route_s + std::max(0.0, feature.s_begin - segment.s_begin);
      double s_end = route_s + std::min(segment.s_end, feature.s_end) - segment.s_begin;
      // A feature met again on the next lane (a crosswalk spanning two lanes) is one feature.
      bool repeated = std::any_of(features_.begin(), features_.end(), [&](const RouteFeature& f) {
        return f.kind == feature.kind && f.index == feature.index && s - f.s_end < 1;
      });
      if (!repeated) features_.push_back({feature.kind, feature.index, s, s_end});
    }
    route_s += segment.s_end - segment.s_begin;
  }
  std::sort(features_.begin(), features_.end(),
            [](const RouteFeature& a, const RouteFeature& b) { return a.s < b.s; });
  for (double from = 0;;) {
    auto stretch = junction_stretch_ahead(map, segments_, limit_s_, from);
    if (!stretch) break;
    junctions_.push_back(*stretch);
    from = stretch->exit;
  }

  headings_ = segment_headings(path_);
  frames_ = SegmentFrames(path_);
  boxes_ = PolylineBoxes(path_);
  const auto& points = path_.points();
  const auto& arc = path_.arc_lengths();
  curvature_.assign(points.size(), 0.0);
  std::size_t segments = path_.segment_count();
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t before = i > kCurvatureReach ? i - kCurvatureReach : 0;
    std::size_t after = std::min(i + kCurvatureReach, segments);
    if (after <= before + 1) continue;
    // Segment headings belong to segment midpoints: the turn between two of them happens over
    // the distance between those midpoints. (headings_[k] is path_.heading_at(arc[k]), the same
    // atan2 of segment k.)
    double turn = angle_difference(headings_[after - 1], headings_[before]);
    double from = (arc[before] + arc[before + 1]) / 2;
    double to = (arc[after - 1] + arc[after]) / 2;
    if (to > from) curvature_[i] = std::abs(turn) / (to - from);
  }
}

void RouteTracker::update(MapPoint point) {
  if (empty()) return;
  // Progress moves on by at most a few metres per step; search a little behind and ahead.
  auto found = locate(point, 5, 20, 1e9);
  if (found) {
    progress_ = std::max(progress_, found->s);
    segment_ = segment_at_from(path_, progress_, segment_);
  }
}

double RouteTracker::speed_limit_at(double s) const {
  if (limit_s_.empty()) return 0;
  auto next = std::upper_bound(limit_s_.begin(), limit_s_.end(), s);
  std::size_t index =
      next == limit_s_.begin() ? 0 : static_cast<std::size_t>(next - limit_s_.begin()) - 1;
  return limit_speed_[index];
}

std::optional<RouteLanePosition> RouteTracker::lane_at(double s) const {
  if (segments_.empty()) return std::nullopt;
  auto next = std::upper_bound(limit_s_.begin(), limit_s_.end(), s);
  std::size_t index =
      next == limit_s_.begin() ? 0 : static_cast<std::size_t>(next - limit_s_.begin()) - 1;
  const RouteSegment& segment = segments_[index];
  double begin = limit_s_[index];
  return RouteLanePosition{segment.lane, segment.s_begin + (s - begin),
                           begin + segment.s_end - segment.s_begin};
}

std::size_t RouteTracker::segment_at(double s) const {
  // segment_ is path_.segment_at(progress_), kept by update().
  return segment_near(std::clamp(s, 0.0, length()), segment_);
}

double RouteTracker::heading_at(double s) const {
  // Polyline::heading_at's segment, and the same atan2 of it (segment_headings).
  return headings_[path_.segment_at(std::clamp(s, 0.0, length()))];
}

double RouteTracker::heading_at(double s, std::size_t hint) const {
  return headings_[segment_at_from(path_, std::clamp(s, 0.0, length()), hint)];
}

double RouteTracker::curvature_at(double s) const {
  if (curvature_.empty()) return 0;
  return curvature_at(s, path_.segment_at(s));
}

double RouteTracker::curvature_at(double s, std::size_t hint) const {
  if (curvature_.empty()) return 0;
  std::size_t segment = segment_at_from(path_, s, hint);
  return std::max(curvature_[segment], curvature_[std::min(segment + 1, curvature_.size() - 1)]);
}

std::optional<PathCoordinate> RouteTracker::locate(MapPoint point, double behind, double ahead,
                                                   double max_lateral) const {
  if (empty()) return std::nullopt;
  return locate(point, window(behind, ahead), max_lateral);
}

// path_.segment_at(s): walking from `hint` when it lies a few metres from s, else searching (a
// caller with the same `behind` may ask for a window far longer than the last).
std::size_t RouteTracker::segment_near(double s, std::size_t hint) const {
  constexpr double kWalk = 8;  // m: a few segments (the path is sampled about every metre)
  return std::abs(path_.arc_lengths()[hint] - s) <= kWalk ? segment_at_from(path_, s, hint)
                                                          : path_.segment_at(s);
}

PathWindow RouteTracker::window(double behind, double ahead) const {
  if (empty()) return {};
  const double from = std::max(0.0, progress_ - behind), to = std::min(length(), progress_ + ahead);
  for (WindowHint& hint : window_hints_)
    if (hint.behind == behind) {
      hint.window = {segment_near(from, hint.window.first), segment_near(to, hint.window.last)};
      return hint.window;
    }
  WindowHint& fresh = window_hints_[next_hint_];
  next_hint_ = (next_hint_ + 1) % window_hints_.size();
  fresh = {behind, {path_.segment_at(from), path_.segment_at(to)}};
  return fresh.window;
}

bool RouteTracker::surely_farther(MapPoint point, PathWindow window, double distance) const {
  if (empty() || !(distance >= 0)) return false;
  const double squared = distance * distance;
  constexpr std::size_t run = PolylineBoxes::kRun;
  constexpr std::size_t group = PolylineBoxes::kGroup;
  const std::size_t last = std::min(window.last / run, boxes_.size() - 1);
  for (std::size_t box = window.first / run; box <= last; ++box) {
    // A group's box is no farther than any of its boxes (exactly): when it is farther, so is
    // each of them, and the group is passed over at once.
    if ((box % group == 0 || box == window.first / run) &&
        boxes_.group_distance_squared(box / group, point) > squared) {
      box = (box / group + 1) * group - 1;
      continue;
    }
    if (!(boxes_.distance_squared(box, point) > squared)) return false;
  }
  return true;
}

std::optional<PathCoordinate> RouteTracker::locate(MapPoint point, PathWindow window,
                                                   double max_lateral) const {
  if (empty()) return std::nullopt;
  const std::size_t first = window.first, last = window.last;
  // Coarse to fine: the nearest of every few vertices, then the segments around it. The path is
  // sampled every metre or so, far finer than it bends.
  const auto& points = path_.points();
  std::size_t nearest_vertex = first;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t vertex = first; vertex <= last + 1; vertex += kCoarseStride) {
    double dx = points[vertex].x - point.x, dy = points[vertex].y - point.y;
    double squared = dx * dx + dy * dy;
    if (squared < nearest) {
      nearest = squared;
      nearest_vertex = vertex;
    }
  }
  std::size_t from =
      std::max(first, nearest_vertex > kCoarseStride ? nearest_vertex - kCoarseStride : 0);
  std::size_t to = std::min(last, nearest_vertex + kCoarseStride);
  // The first nearest segment, as comparing every projection's distance would find it: squares
  // first (a larger square is no nearer), and a root only for a candidate.
  std::size_t best = to + 1;
  double best_squared = std::numeric_limits<double>::infinity();
  double best_distance = best_squared;
  for (std::size_t segment = from; segment <= to; ++segment) {
    const double squared = frames_.distance_squared(path_, point, segment);
    const bool any = best <= to;  // the first projection is taken whatever it is (NaN too)
    if (any && squared > best_squared) continue;
    const double distance = std::sqrt(squared);
    if (any && !(distance < best_distance)) continue;  // equally near: the first found stays
    best = segment;
    best_squared = squared;
    best_distance = distance;
  }
  if (best > to || best_distance > max_lateral) return std::nullopt;
  const PolylineProjection projection = frames_.project(path_, point, best);
  // The nearest point is an end point when it lies off the normal through it.
  bool beyond_end = projection.distance > std::abs(projection.lateral) + 1e-6;
  return PathCoordinate{projection.s, projection.lateral, beyond_end, best};
}

std::optional<JunctionStretch> RouteTracker::junction_ahead(double s) const {
  for (const JunctionStretch& stretch : junctions_)
    if (stretch.exit > s) return stretch;
  return std::nullopt;
}

}  // namespace scenfuzz
