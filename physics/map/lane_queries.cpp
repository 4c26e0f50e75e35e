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

// Lanes further than this from a point cannot contain it (no real lane is 40 m wide).
constexpr double kMaximumLaneHalfWidth = 20;

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

std::optional<LaneProjection> project_to_lane(const RoadMap& map, MapPoint point, double heading) {
  if (!std::isfinite(heading)) return project_to_lane(map, point);
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) return std::nullopt;
  std::optional<LaneProjection> nearest;
  std::optional<LaneProjection> best_inside;
  double best_heading_difference = std::numeric_limits<double>::infinity();
  map.segment_index().visit_nearest(point, [&](const LaneSegmentReference& segment) {
    const Polyline& centre_line = map.lane(segment.lane).centre_line;
    PolylineProjection on_line = centre_line.project_to_segment(point, segment.segment);
    if (nearest && on_line.distance > std::max(nearest->distance, kMaximumLaneHalfWidth))
      return false;
    LaneProjection candidate = make_projection(map, segment.lane, on_line);
    if (!nearest) nearest = candidate;
    if (candidate.inside) {
      double difference = std::abs(angle_difference(heading, centre_line.heading_at(candidate.s)));
      // Ties (the same lane met again at a vertex) keep the nearer projection.
      if (difference < best_heading_difference - 1e-9 ||
          (difference <= best_heading_difference + 1e-9 && best_inside &&
           candidate.distance < best_inside->distance)) {
        best_heading_difference = difference;
        best_inside = candidate;
      }
    }
    return true;
  });
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

}  // namespace scenfuzz
