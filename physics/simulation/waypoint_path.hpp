// The path of an NPC vehicle driving through its waypoints (`Waypoint(...)` motion): lane-true
// where the waypoints lie on lanes, planned in free space where they do not.
//
// A leg joins two consecutive poses of the path (start, waypoints, target). A leg follows the lane
// graph (find_route, drawn by route_path: lane changes as smooth sideways moves, junction
// connector lanes, roundabout rings) when
//   - both its ends lie inside a lane and head within 60 degrees of that lane's direction,
//   - the lanes route it from one end to the other, at most 3 x the straight distance + 50 m long
//     (a longer route is a detour the waypoints did not ask for, e.g. once round a ring to reach
//     a point just behind), and
//   - the lane path touches no static obstacle (is_free every 0.5 m).
// Otherwise the leg is planned as before: the Dubins curve with the turning radius, RRTConnect
// around the static obstacles (plan_path, physics/planning/path_planner.hpp).
//
// On a lane leg the lateral offset from the centre line blends smoothly from the start's to the
// end's, and a lane change ends where the leg ends (a waypoint in the next lane is where the
// actor has arrived in it). It takes max(3 s, sqrt(6 w / a)) of travel at the leg's faster speed
// (w the distance between the lanes, a the class's comfortable lateral acceleration: a smoothstep
// move of length L peaks at 6 w v^2 / L^2), at least 10 m; a leg too short for that gets the
// smoothest change that fits (its speed profile may then ask too much, which is not judged here).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "physics/map/map_point.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct WaypointPathRequest {
  std::vector<MapPose> poses;  // start, waypoints, target: at least two, consecutive ones apart
  std::vector<double> speeds;  // m/s at each pose, for the length of a lane change
  double turning_radius = 5;   // m, for the planned legs
  double comfortable_lateral_acceleration = 2;  // m/s^2 a lane change keeps within when it can
  // Whether the body may stand at a pose; empty when there are no static obstacles.
  std::function<bool(const MapPose&)> is_free;
  std::uint64_t seed = 0;  // of the planner's sampling
};

enum class LegKind { lane, planned };

struct WaypointPath {
  std::vector<MapPoint> points;    // distinct consecutive points, from the start to the target
  std::vector<double> waypoint_s;  // arc length along `points` at each pose of the request
  std::vector<LegKind> legs;       // how each leg was made
};

// Throws PlanningError (physics/planning/path_planner.hpp) when a planned leg cannot be planned,
// naming the leg by its place in the whole path.
WaypointPath waypoint_path(const RoadMap& map, const WaypointPathRequest& request);

// The heading of a waypoint whose script gives none, at `at` with `lane_heading` the direction of
// the lane it lies in, reached from `from`: that direction, unless it runs against the way the
// actor comes (more than 90 degrees from the bearing from `from`) and the point lies in or within
// 1 m of a lane running the actor's way (within 60 degrees of the bearing), as when a car drifts
// across the centre line into the oncoming lane: facing that lane's way, it would have to loop
// round. Then that lane's direction.
double waypoint_heading(const RoadMap& map, MapPoint from, MapPoint at, double lane_heading);

// Metres a lane change of `width` metres takes at `speed` (the rule above, before fitting it into
// a leg).
double waypoint_lane_change_length(double speed, double width,
                                   double comfortable_lateral_acceleration);

}  // namespace scenfuzz
