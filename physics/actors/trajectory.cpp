// Scripted motion along a path (a piecewise constant-acceleration speed profile), and the paths
// themselves: lane routes turned into drivable polylines, and the route a lane follower takes.
#include "physics/actors/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>

#include "physics/actors/path_pose.hpp"

namespace scenfuzz {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Route path points closer than this to the previous point are dropped: a near-duplicate at a lane
// joint would make a tiny segment with an arbitrary heading.
constexpr double kMinimumPointGap = 0.01;

// How far into a successor route_ahead looks to judge how much it turns: a connector that joins
// tangentially turns only after its first metres (a roundabout's exit leaves the ring tangentially
// and then turns away).
constexpr double kTurnLookahead = 5;

// route_ahead stops after this many segments: a ring of tiny lanes must not loop for ever.
constexpr std::size_t kMaximumRouteSegments = 100000;

// The path without points closer than kMinimumPointGap to the one before (the last point kept):
// a planner's path can join two legs with a near-duplicate point, whose tiny segment has an
// arbitrary heading that no vehicle could follow and a bend cap would crawl through.
Polyline without_near_duplicates(Polyline path) {
  const std::vector<MapPoint>& points = path.points();
  std::vector<MapPoint> kept;
  for (const MapPoint& point : points) {
    if (!kept.empty() && distance(kept.back(), point) < kMinimumPointGap) continue;
    kept.push_back(point);
  }
  if (kept.size() == points.size()) return path;
  if (distance(kept.back(), points.back()) > 0) {
    if (kept.size() > 1)
      kept.back() = points.back();
    else
      kept.push_back(points.back());
  }
  if (kept.size() < 2) return path;
  return Polyline(kept);
}

}  // namespace

std::vector<PathBend> path_bends(const Polyline& path) {
  const std::vector<double> headings = segment_headings(path);
  std::vector<PathBend> bends;
  for (std::size_t vertex = 1; vertex < path.segment_count(); ++vertex) {
    double blend = blend_half_width(path, vertex);
    double curvature = vertex_curvature(path, headings, vertex);
    if (blend <= 0 || curvature == 0) continue;
    double at = path.arc_lengths()[vertex];
    bends.push_back({at - blend, at + blend, curvature});
  }
  return bends;
}

Trajectory::Trajectory(Polyline path, std::vector<SpeedPoint> speeds, double stop_deceleration)
    : path_(std::move(path)) {
  if (path_.points().empty())
    throw std::invalid_argument("trajectory needs a path; use Trajectory::standing for none");
  profile_ = constant_acceleration_profile(std::move(speeds), path_.length(), stop_deceleration);
  prepare_path();
}

Trajectory::Trajectory(Polyline path, std::vector<SpeedPoint> speeds, const MotionLimits& limits)
    : path_(without_near_duplicates(std::move(path))) {
  if (path_.points().empty())
    throw std::invalid_argument("trajectory needs a path; use Trajectory::standing for none");
  std::vector<PathBend> bends;
  if (limits.max_lateral_acceleration > 0) bends = path_bends(path_);
  FeasibleProfile feasible = feasible_profile(std::move(speeds), path_.length(), bends, limits);
  profile_ = std::move(feasible.profile);
  shortfalls_ = std::move(feasible.shortfalls);
  prepare_path();
}

void Trajectory::prepare_path() {
  standing_pose_ = {path_.points().front(), direction_at(path_, 0).heading};
  segment_headings_ = segment_headings(path_);
}

Trajectory Trajectory::standing(MapPose pose) {
  Trajectory trajectory;
  trajectory.standing_pose_ = pose;
  return trajectory;
}

double Trajectory::duration() const { return profile_.duration(); }

KinematicState Trajectory::state_at(double t) const {
  if (profile_.empty()) {
    KinematicState state;
    state.x = standing_pose_.position.x;
    state.y = standing_pose_.position.y;
    state.heading = standing_pose_.heading;
    return state;
  }
  ProfileState along = profile_.at(t);
  return state_on_path(path_, segment_headings_, along.s, along.speed, along.acceleration);
}

namespace {

// The segments of a route laid end to end: segment k covers route distances [start[k], end[k]].
struct RouteLayout {
  std::vector<double> start, end;
  // change[k]: segments k and k + 1 are joined by a lane change (else by a successor link).
  std::vector<bool> change;
};

RouteLayout lay_out(const RoadMap& map, const LaneRoute& route) {
  RouteLayout layout;
  double distance_so_far = 0;
  for (std::size_t k = 0; k < route.segments.size(); ++k) {
    const RouteSegment& segment = route.segments[k];
    if (segment.lane >= map.lanes().size())
      throw std::invalid_argument("route names a lane the map does not have");
    if (!(segment.s_begin <= segment.s_end))
      throw std::invalid_argument("route segment ends before it begins");
    layout.start.push_back(distance_so_far);
    distance_so_far += segment.s_end - segment.s_begin;
    layout.end.push_back(distance_so_far);
    if (k + 1 == route.segments.size()) break;
    const RouteSegment& next = route.segments[k + 1];
    const Lane& lane = map.lane(segment.lane);
    bool successor =
        std::find(lane.successors.begin(), lane.successors.end(), next.lane) !=
            lane.successors.end() &&
        distance(lane.centre_line.point_at(segment.s_end),
                 map.lane(next.lane).centre_line.point_at(next.s_begin)) <= kJointTolerance;
    layout.change.push_back(!successor);
  }
  return layout;
}

// A stretch of the path: on one segment's lane, or blending from one segment's lane to the next
// one's. A segment's lane extends beyond the segment (lanes beside each other run on together),
// at s = s_begin + (route distance - segment start).
struct PathPiece {
  double begin = 0;
  double end = 0;
  std::size_t from = 0;
  std::size_t to = 0;  // == from when not blending
};

// Follows the segments and places each lane change's blend: ending at the change point when the
// lane before has room, otherwise as early as it can and running on into the new lane. Lane
// changes in a row (a route enters a lane and leaves it sideways at once) share the room up to
// the next successor link or the route's end.
std::vector<PathPiece> plan_pieces(const RoadMap& map, const LaneRoute& route,
                                   const RouteLayout& layout, double lane_change_length) {
  std::vector<PathPiece> pieces;
  const std::size_t count = route.segments.size();
  double cursor = 0;
  auto follow = [&](std::size_t segment, double until) {
    if (until > cursor) pieces.push_back({cursor, until, segment, segment});
    cursor = std::max(cursor, until);
  };
  for (std::size_t k = 0; k + 1 < count; ++k) {
    if (!layout.change[k]) {
      follow(k, layout.end[k]);
      continue;
    }
    std::size_t changes_after = 0;
    while (k + 1 + changes_after < count - 1 && layout.change[k + 1 + changes_after])
      ++changes_after;
    const double room_end = layout.end[k + 1 + changes_after];
    const double change_point = layout.end[k];
    const RouteSegment& old_segment = route.segments[k];
    const RouteSegment& new_segment = route.segments[k + 1];
    double old_room = map.lane(old_segment.lane).length() - old_segment.s_end;
    double new_room = map.lane(new_segment.lane).length() - new_segment.s_begin;
    double begin = std::max(cursor, change_point - lane_change_length);
    double share = (room_end - begin) / static_cast<double>(changes_after + 1);
    double end = std::min({begin + lane_change_length, begin + share, change_point + old_room,
                           change_point + new_room});
    follow(k, begin);
    if (end > begin) {
      pieces.push_back({begin, end, k, k + 1});
      cursor = end;
    }
  }
  follow(count - 1, layout.end[count - 1]);
  return pieces;
}

MapPoint lane_point(const RoadMap& map, const LaneRoute& route, const RouteLayout& layout,
                    std::size_t segment, double route_distance, double lateral) {
  const RouteSegment& on = route.segments[segment];
  const Polyline& centre_line = map.lane(on.lane).centre_line;
  double s = on.s_begin + (route_distance - layout.start[segment]);
  MapPoint centre = centre_line.point_at(s);
  double heading = direction_at(centre_line, s).heading;
  return {centre.x - std::sin(heading) * lateral, centre.y + std::cos(heading) * lateral};
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

}  // namespace

Polyline route_path(const RoadMap& map, const LaneRoute& route, double lateral,
                    double lane_change_length, double spacing, std::vector<PathPlace>* places) {
  if (route.segments.empty()) throw std::invalid_argument("route_path needs a route");
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw std::invalid_argument("route_path spacing must be positive");
  if (!(lane_change_length >= 0) || !std::isfinite(lane_change_length) || !std::isfinite(lateral))
    throw std::invalid_argument("route_path needs a finite lateral offset and lane change length");
  RouteLayout layout = lay_out(map, route);
  std::vector<MapPoint> points;
  if (places != nullptr) places->clear();
  auto add = [&](MapPoint point, const PathPiece& piece, double at) {
    if (!points.empty() && distance(points.back(), point) < kMinimumPointGap) return;
    points.push_back(point);
    if (places == nullptr) return;
    const RouteSegment& on = route.segments[piece.from];
    places->push_back({static_cast<std::uint32_t>(piece.from),
                       on.s_begin + (at - layout.start[piece.from]),
                       piece.to == piece.from && std::abs(lateral) <= kOnLaneLateral});
  };
  for (const PathPiece& piece : plan_pieces(map, route, layout, lane_change_length)) {
    double span = piece.end - piece.begin;
    auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil(span / spacing - 1e-9)));
    for (std::size_t i = 0; i <= steps; ++i) {
      double fraction = static_cast<double>(i) / static_cast<double>(steps);
      double at = piece.begin + span * fraction;
      MapPoint from = lane_point(map, route, layout, piece.from, at, lateral);
      if (piece.to == piece.from) {
        add(from, piece, at);
        continue;
      }
      MapPoint to = lane_point(map, route, layout, piece.to, at, lateral);
      double weight = smoothstep(fraction);
      add({from.x + weight * (to.x - from.x), from.y + weight * (to.y - from.y)}, piece, at);
    }
  }
  if (points.size() < 2)
    throw std::invalid_argument("route_path: the route has no length (use a standing actor)");
  return Polyline(points);
}

namespace {

// Where `point` lies along `centre` near `s`: the nearest point of the few segments around the
// one at s (rounding moves a point by far less than a segment's length), when the point is
// beside those segments rather than beyond their ends.
std::optional<double> along_near(const Polyline& centre, MapPoint point, double s) {
  constexpr std::size_t kAround = 3;
  const std::size_t at = centre.segment_at(s);
  const std::size_t first = at > kAround ? at - kAround : 0;
  const std::size_t last = std::min(at + kAround, centre.segment_count() - 1);
  PolylineProjection best = centre.project_to_segment(point, first);
  for (std::size_t k = first + 1; k <= last; ++k) {
    PolylineProjection candidate = centre.project_to_segment(point, k);
    if (candidate.distance < best.distance) best = candidate;
  }
  if (!(best.distance <= std::abs(best.lateral) + 1e-9)) return std::nullopt;
  return best.s;
}

// `place` again for `point`, moved aside from where route_path drew it: on its lane, or, rounded
// beyond that lane's end or start, on the route's next or previous lane. Else not on a lane.
void replace(const RoadMap& map, const LaneRoute& route, MapPoint point, PathPlace& place) {
  if (!place.on_lane) return;
  const RouteSegment& on = route.segments[place.segment];
  if (auto s = along_near(map.lane(on.lane).centre_line, point, place.s)) {
    place.s = *s;
    return;
  }
  const std::size_t k = place.segment;
  for (std::size_t other : {k + 1, k - 1}) {
    if (other >= route.segments.size()) continue;  // k - 1 wraps round at the first segment
    const RouteSegment& there = route.segments[other];
    const double near = other > k ? there.s_begin : there.s_end;
    if (auto s = along_near(map.lane(there.lane).centre_line, point, near)) {
      place = {static_cast<std::uint32_t>(other), *s, true};
      return;
    }
  }
  place.on_lane = false;
}

}  // namespace

Polyline rounded_route_path(const RoadMap& map, const LaneRoute& route, double lateral,
                            double min_radius, std::vector<PathPlace>& places) {
  const Polyline drawn =
      route_path(map, route, lateral, kLaneChangeLength, kRoutePathSpacing, &places);
  Polyline rounded = round_corners(drawn, min_radius);
  if (rounded.points().size() != places.size()) {
    places.clear();  // two points merged: no place is known (the lane is looked for)
    return rounded;
  }
  for (std::size_t i = 0; i < places.size(); ++i)
    if (!(rounded.points()[i] == drawn.points()[i]))
      replace(map, route, rounded.points()[i], places[i]);
  return rounded;
}

std::vector<LaneChangeStretch> lane_change_stretches(const RoadMap& map, const LaneRoute& route,
                                                     double lane_change_length) {
  std::vector<LaneChangeStretch> stretches;
  if (route.segments.empty()) return stretches;
  RouteLayout layout = lay_out(map, route);
  for (const PathPiece& piece : plan_pieces(map, route, layout, lane_change_length))
    if (piece.to != piece.from)
      stretches.push_back(
          {piece.begin, piece.end, route.segments[piece.from].lane, route.segments[piece.to].lane});
  return stretches;
}

LaneRoute route_ahead(const RoadMap& map, LanePosition start, double length) {
  if (start.lane >= map.lanes().size())
    throw std::invalid_argument("route_ahead: the map has no such lane");
  if (!std::isfinite(start.s) || std::isnan(length))
    throw std::invalid_argument("route_ahead needs a finite s and a length");
  LaneRoute route;
  LaneIndex lane = start.lane;
  double s = std::clamp(start.s, 0.0, map.lane(lane).length());
  while (route.segments.size() < kMaximumRouteSegments) {
    const Lane& current = map.lane(lane);
    double remaining = length - route.length;
    // Among the successors that branch off ahead, the one that turns least over its first metres
    // (the nearer branch point on a tie).
    std::optional<LaneIndex> next;
    LinkPoints next_link;
    double least_turn = kInfinity;
    for (LaneIndex successor : current.successors) {
      LinkPoints link = link_points(map, lane, successor);
      if (link.exit_s < s) continue;
      const Polyline& successor_line = map.lane(successor).centre_line;
      double ahead = std::min(link.entry_s + kTurnLookahead, successor_line.length());
      double turn =
          std::abs(angle_difference(direction_at(successor_line, ahead).heading,
                                    direction_at(current.centre_line, link.exit_s).heading));
      if (turn < least_turn || (turn == least_turn && link.exit_s < next_link.exit_s)) {
        least_turn = turn;
        next = successor;
        next_link = link;
      }
    }
    double end = next ? next_link.exit_s : current.length();
    if (end - s >= remaining || !next) {
      end = std::min(end, s + std::max(remaining, 0.0));
      route.segments.push_back({lane, s, end});
      route.length += end - s;
      break;
    }
    route.segments.push_back({lane, s, end});
    route.length += end - s;
    lane = *next;
    s = next_link.entry_s;
  }
  return route;
}

}  // namespace scenfuzz
