// Lane poses, point-to-lane projection and lane-change rules.
#include "physics/map/lane_queries.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/map/lane_segment_index.hpp"

namespace scenfuzz {

namespace {

// s a little outside a lane still names its end: scenario files write "lane" -> 0 and lengths
// rounded to the millimetre.
constexpr double kLaneEndTolerance = 1e-3;

// Lanes further than this from a point cannot contain it (no lane is wider than 20 m).
constexpr double kMaximumLaneHalfWidth = 10;

LaneProjection make_projection(const RoadMap& map, LaneIndex lane,
                               const PolylineProjection& on_centre_line) {
  LaneProjection projection;
  projection.lane = lane;
  projection.s = on_centre_line.s;
  projection.lateral = on_centre_line.lateral;
  projection.distance = on_centre_line.distance;
  // Inside: the foot of the perpendicular is on the centre line (not beyond an end) and the point
  // is between the boundaries there.
  bool beside = on_centre_line.distance <= std::abs(on_centre_line.lateral) + 1e-9;
  projection.inside = beside &&
                      on_centre_line.lateral <= lane_left_width_at(map, lane, projection.s) &&
                      -on_centre_line.lateral <= lane_right_width_at(map, lane, projection.s);
  return projection;
}

}  // namespace

std::optional<MapPose> lane_pose_at(const RoadMap& map, LaneIndex lane, double s, double lateral) {
  const Polyline& centre_line = map.lane(lane).centre_line;
  if (!std::isfinite(s) || !std::isfinite(lateral) || s < -kLaneEndTolerance ||
      s > centre_line.length() + kLaneEndTolerance)
    return std::nullopt;
  MapPoint centre = centre_line.point_at(s);
  double heading = centre_line.heading_at(s);
  return MapPose{{centre.x - std::sin(heading) * lateral, centre.y + std::cos(heading) * lateral},
                 heading};
}

std::optional<ClampedLanePose> clamped_lane_pose(const RoadMap& map, LaneIndex lane, double s,
                                                 double lateral) {
  if (!std::isfinite(s)) return std::nullopt;
  double length = map.lane(lane).length();
  double clamped = std::clamp(s, 0.0, length);
  auto pose = lane_pose_at(map, lane, clamped, lateral);
  if (!pose) return std::nullopt;
  return ClampedLanePose{*pose, std::abs(s - clamped)};
}

double lane_heading_at(const RoadMap& map, LaneIndex lane, double s) {
  return map.lane(lane).centre_line.heading_at(s);
}

double lane_left_width_at(const RoadMap& map, LaneIndex lane, double s) {
  return width_at(map.lane(lane).left_width, s);
}

double lane_right_width_at(const RoadMap& map, LaneIndex lane, double s) {
  return width_at(map.lane(lane).right_width, s);
}

std::optional<LaneProjection> project_to_lane(const RoadMap& map, MapPoint point) {
  LaneSegmentReference nearest;
  if (!std::isfinite(point.x) || !std::isfinite(point.y) ||
      !map.segment_index().nearest(point, nearest))
    return std::nullopt;
  const Polyline& centre_line = map.lane(nearest.lane).centre_line;
  return make_projection(map, nearest.lane, centre_line.project_to_segment(point, nearest.segment));
}

std::optional<LaneProjection> project_onto_lanes(const RoadMap& map, MapPoint point,
                                                 std::span<const LaneIndex> lanes) {
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) return std::nullopt;
  std::optional<LaneProjection> nearest;
  for (LaneIndex lane : lanes) {
    LaneProjection candidate =
        make_projection(map, lane, map.lane(lane).centre_line.project(point));
    if (!nearest || candidate.distance < nearest->distance) nearest = candidate;
  }
  return nearest;
}

std::optional<LaneProjection> project_to_lane(const RoadMap& map, MapPoint point, double heading) {
  if (!std::isfinite(heading)) return project_to_lane(map, point);
  std::optional<LaneProjection> nearest = project_to_lane(map, point);
  if (!nearest) return std::nullopt;
  // Every lane that could contain the point has a centre-line segment within this radius.
  double radius = std::min(nearest->distance + kMaximumLaneHalfWidth, 2 * kMaximumLaneHalfWidth);
  std::optional<LaneProjection> best_inside;
  double best_heading_difference = std::numeric_limits<double>::infinity();
  for (const LaneSegmentReference& segment : map.segment_index().segments_in_box(
           {point.x - radius, point.y - radius}, {point.x + radius, point.y + radius})) {
    const Polyline& centre_line = map.lane(segment.lane).centre_line;
    LaneProjection candidate =
        make_projection(map, segment.lane, centre_line.project_to_segment(point, segment.segment));
    if (!candidate.inside) continue;
    double difference = std::abs(angle_difference(heading, centre_line.heading_at(candidate.s)));
    // Equal headings (the same lane met at a vertex, parallel lanes) keep the nearer projection;
    // exact ties go to the lower lane index, so the answer never depends on the index's order.
    bool better =
        !best_inside || difference < best_heading_difference - 1e-9 ||
        (difference <= best_heading_difference + 1e-9 &&
         (candidate.distance < best_inside->distance ||
          (candidate.distance == best_inside->distance && candidate.lane < best_inside->lane)));
    if (better) {
      best_heading_difference = std::min(best_heading_difference, difference);
      best_inside = candidate;
    }
  }
  return best_inside ? best_inside : nearest;
}

bool lane_change_allowed(const RoadMap& map, LaneIndex from, LaneIndex to) {
  const Lane& lane = map.lane(from);
  if (lane.junction || map.lane(to).junction) return false;
  auto solid = [](BoundaryType type) {
    return type != BoundaryType::unknown && type != BoundaryType::dotted_white &&
           type != BoundaryType::dotted_yellow;
  };
  const auto& left = lane.left_forward_neighbours;
  const auto& right = lane.right_forward_neighbours;
  if (std::find(left.begin(), left.end(), to) != left.end()) return !solid(lane.left_boundary_type);
  if (std::find(right.begin(), right.end(), to) != right.end())
    return !solid(lane.right_boundary_type);
  return false;
}

bool runs_into_itself(const RoadMap& map, LaneIndex lane) {
  const std::vector<LaneIndex>& after = map.lane(lane).successors;
  return std::find(after.begin(), after.end(), lane) != after.end();
}

}  // namespace scenfuzz
