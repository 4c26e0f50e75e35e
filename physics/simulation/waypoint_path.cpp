// Paths through an NPC vehicle's waypoints: lane legs over the lane graph, the others planned in
// free space (the rules are in waypoint_path.hpp).
#include "physics/simulation/waypoint_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "lang/demand.hpp"
#include "physics/actors/path_pose.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/lane_segment_index.hpp"
#include "physics/map/polyline.hpp"
#include "physics/planning/path_planner.hpp"

namespace scenfuzz {
namespace {

constexpr double kMaxHeadingOffLane = std::numbers::pi / 3;
// m beyond a lane's edge where a waypoint still counts as drifted out of it (waypoint_heading).
constexpr double kBesideLaneMargin = 1;
// A lane route longer than this many times the straight distance, plus the allowance, is a
// detour the waypoints did not ask for.
constexpr double kDetourFactor = 3;
constexpr double kDetourAllowance = 50;      // m
constexpr double kMinLaneChangeTime = 3;     // s of travel: brisk but calm
constexpr double kMinLaneChangeLength = 10;  // m: a crawling car still moves over gradually
constexpr double kSmoothstepPeak = 6;        // max |d^2/du^2| of 3u^2 - 2u^3
constexpr double kMinLaneLegLength = 0.5;    // m: shorter lane routes are sideways nudges
constexpr double kPointSpacing = 1;          // m between the points of a lane leg
constexpr double kFreeCheckSpacing = 0.5;    // m between the poses checked against obstacles
constexpr double kJoinGap = 1e-3;            // m: consecutive points closer are one

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// Where a pose lies on a lane it drives along: inside the lane, heading its way.
std::optional<LaneProjection> lane_under(const RoadMap& map, const MapPose& pose) {
  auto projection = project_to_lane(map, pose.position, pose.heading);
  if (!projection || !projection->inside) return std::nullopt;
  double lane_heading = lane_heading_at(map, projection->lane, projection->s);
  if (std::abs(angle_difference(pose.heading, lane_heading)) > kMaxHeadingOffLane)
    return std::nullopt;
  return projection;
}

bool is_forward_neighbour(const Lane& lane, LaneIndex other) {
  auto holds = [&](const std::vector<LaneIndex>& lanes) {
    return std::find(lanes.begin(), lanes.end(), other) != lanes.end();
  };
  return holds(lane.left_forward_neighbours) || holds(lane.right_forward_neighbours);
}

// The largest sideways distance of the route's lane changes (0 without any).
double widest_lane_change(const RoadMap& map, const LaneRoute& route) {
  double widest = 0;
  for (std::size_t k = 0; k + 1 < route.segments.size(); ++k) {
    const RouteSegment& leaving = route.segments[k];
    const RouteSegment& entering = route.segments[k + 1];
    if (!is_forward_neighbour(map.lane(leaving.lane), entering.lane)) continue;
    MapPoint from = map.lane(leaving.lane).centre_line.point_at(leaving.s_end);
    MapPoint to = map.lane(entering.lane).centre_line.point_at(entering.s_begin);
    widest = std::max(widest, distance(from, to));
  }
  return widest;
}

// `points` moved sideways (left of their direction) by an offset blending smoothly from `begin`
// at the first point to `end` at the last.
std::vector<MapPoint> offset_sideways(const std::vector<MapPoint>& points, double begin,
                                      double end) {
  const Polyline line(points);
  const std::vector<MapPoint>& kept = line.points();
  std::vector<MapPoint> moved;
  moved.reserve(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    MapPoint behind = kept[i == 0 ? 0 : i - 1];
    MapPoint ahead = kept[std::min(i + 1, kept.size() - 1)];
    double heading = std::atan2(ahead.y - behind.y, ahead.x - behind.x);
    double offset = begin + (end - begin) * smoothstep(line.arc_lengths()[i] / line.length());
    moved.push_back(
        {kept[i].x - std::sin(heading) * offset, kept[i].y + std::cos(heading) * offset});
  }
  return moved;
}

bool touches_obstacle(const std::vector<MapPoint>& points,
                      const std::function<bool(const MapPose&)>& is_free) {
  if (!is_free) return false;
  const Polyline line(points);
  auto steps = static_cast<std::size_t>(std::ceil(line.length() / kFreeCheckSpacing));
  for (std::size_t i = 0; i <= steps; ++i) {
    double s = std::min(line.length(), static_cast<double>(i) * kFreeCheckSpacing);
    if (!is_free({line.point_at(s), line.heading_at(s)})) return true;
  }
  return false;
}

// The leg from poses[leg] to poses[leg + 1] over the lanes, or nullopt when the rules send it to
// the planner.
std::optional<std::vector<MapPoint>> lane_leg(const RoadMap& map,
                                              const WaypointPathRequest& request, std::size_t leg) {
  const MapPose& start = request.poses[leg];
  const MapPose& end = request.poses[leg + 1];
  auto from = lane_under(map, start);
  auto to = lane_under(map, end);
  if (!from || !to) return std::nullopt;
  auto route =
      find_route(map, LanePosition{from->lane, from->s, 0}, LanePosition{to->lane, to->s, 0});
  double straight = distance(start.position, end.position);
  if (!route || route->segments.empty() || route->length < kMinLaneLegLength ||
      route->length > kDetourFactor * straight + kDetourAllowance)
    return std::nullopt;
  // Lane changes as late as the lanes allow: they end where the leg ends.
  LaneRoute late = defer_lane_changes(map, *route, route->length);
  double change_length = 0;
  if (route->lane_changes > 0) {
    double speed = std::max(request.speeds[leg], request.speeds[leg + 1]);
    change_length = std::min(waypoint_lane_change_length(speed, widest_lane_change(map, late),
                                                         request.comfortable_lateral_acceleration),
                             route->length);
  }
  std::vector<MapPoint> points;
  try {
    points = route_path(map, late, 0, change_length, kPointSpacing).points();
    points = offset_sideways(points, from->lateral, to->lateral);
    points = round_corners(Polyline(points), request.turning_radius).points();
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a route too short to draw: the planner joins the two poses
  }
  // The leg joins the poses themselves (a projection is exact to rounding, a vertex aside).
  points.front() = start.position;
  points.back() = end.position;
  if (touches_obstacle(points, request.is_free)) return std::nullopt;
  return points;
}

// The planner's points for legs [first, last) in one request, so that consecutive planned legs
// keep plan_path's numbering and seeds.
std::vector<std::vector<MapPoint>> planned_legs(const WaypointPathRequest& request,
                                                std::size_t first, std::size_t last) {
  PathRequest plan;
  plan.waypoints.assign(request.poses.begin() + static_cast<std::ptrdiff_t>(first),
                        request.poses.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  plan.turning_radius = request.turning_radius;
  plan.is_free = request.is_free;
  plan.seed = request.seed;
  plan.first_leg = first;
  const PlannedPath planned = plan_path(plan);
  std::vector<std::vector<MapPoint>> legs;
  for (std::size_t k = 0; k + 1 < planned.waypoint_at.size(); ++k) {
    std::vector<MapPoint> points;
    for (std::size_t i = planned.waypoint_at[k]; i <= planned.waypoint_at[k + 1]; ++i)
      points.push_back(planned.poses[i].position);
    legs.push_back(std::move(points));
  }
  return legs;
}

// Appends a leg's points (the first joins the path's last) and the arc length at its end.
void append_leg(WaypointPath& path, double& s, const std::vector<MapPoint>& points) {
  for (const MapPoint& point : points) {
    if (!path.points.empty()) {
      double step = distance(path.points.back(), point);
      if (step < kJoinGap) continue;
      s += step;
    }
    path.points.push_back(point);
  }
  path.waypoint_s.push_back(s);
}

}  // namespace

double waypoint_heading(const RoadMap& map, MapPoint from, MapPoint at, double lane_heading) {
  if (distance(from, at) < 1e-9) return lane_heading;
  const double bearing = std::atan2(at.y - from.y, at.x - from.x);
  if (std::abs(angle_difference(lane_heading, bearing)) <= std::numbers::pi / 2)
    return lane_heading;
  // Only beside a lane running the actor's way: on a ring, a waypoint far round it may well lie
  // against the bearing from the one before, and its lane's direction is the right one.
  constexpr double kSearchRadius = 8;  // m: a wide lane's half width and the margin, with room
  std::optional<double> best_heading;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const LaneSegmentReference& segment :
       map.segment_index().segments_in_box({at.x - kSearchRadius, at.y - kSearchRadius},
                                           {at.x + kSearchRadius, at.y + kSearchRadius})) {
    const Polyline& centre_line = map.lane(segment.lane).centre_line;
    const PolylineProjection p = centre_line.project_to_segment(at, segment.segment);
    const double heading = centre_line.heading_at(p.s);
    if (std::abs(angle_difference(heading, bearing)) > kMaxHeadingOffLane) continue;
    const double half_width = p.lateral >= 0 ? lane_left_width_at(map, segment.lane, p.s)
                                             : lane_right_width_at(map, segment.lane, p.s);
    if (std::abs(p.lateral) > half_width + kBesideLaneMargin || p.distance >= best_distance)
      continue;
    best_distance = p.distance;
    best_heading = heading;
  }
  return best_heading.value_or(lane_heading);
}

double waypoint_lane_change_length(double speed, double width,
                                   double comfortable_lateral_acceleration) {
  double time = kMinLaneChangeTime;
  if (comfortable_lateral_acceleration > 0)
    time = std::max(time, std::sqrt(kSmoothstepPeak * width / comfortable_lateral_acceleration));
  return std::max(kMinLaneChangeLength, std::max(speed, 0.0) * time);
}

WaypointPath waypoint_path(const RoadMap& map, const WaypointPathRequest& request) {
  SCENFUZZ_DEMAND(request.poses.size() >= 2);
  SCENFUZZ_DEMAND(request.speeds.size() == request.poses.size());
  const std::size_t leg_count = request.poses.size() - 1;
  std::vector<std::optional<std::vector<MapPoint>>> lane_legs;
  for (std::size_t leg = 0; leg < leg_count; ++leg)
    lane_legs.push_back(lane_leg(map, request, leg));

  WaypointPath path;
  double s = 0;
  path.points.push_back(request.poses.front().position);
  path.waypoint_s.push_back(0);
  for (std::size_t leg = 0; leg < leg_count;) {
    if (lane_legs[leg]) {
      append_leg(path, s, *lane_legs[leg]);
      path.legs.push_back(LegKind::lane);
      ++leg;
      continue;
    }
    std::size_t last = leg;
    while (last < leg_count && !lane_legs[last]) ++last;
    for (const std::vector<MapPoint>& points : planned_legs(request, leg, last)) {
      append_leg(path, s, points);
      path.legs.push_back(LegKind::planned);
    }
    leg = last;
  }
  return path;
}

}  // namespace scenfuzz
