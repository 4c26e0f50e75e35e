// Car-like paths through waypoints, planned with OMPL (which stays inside path_planner.cpp):
// for each leg the analytic Dubins curve (Reeds-Shepp where reversing is allowed) with the
// vehicle's minimum turning radius; only when that curve touches a static obstacle, a sampling
// planner (RRTConnect) in the same state space, with its own seeded generator so plans repeat
// whatever thread runs them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

struct PathRequest {
  std::vector<MapPose> waypoints;  // at least two; the path passes each with its heading
  double turning_radius = 5;       // m, > 0
  bool reversing_allowed = false;
  // Whether the body may stand at a pose; empty when there are no static obstacles.
  std::function<bool(const MapPose&)> is_free;
  std::uint64_t seed = 0;
  double time_limit = 0.5;  // s of planning per leg for the sampling planner
  double spacing = 0.5;     // m at most between the returned poses, evenly along each leg
  // Index of waypoints.front() in a longer path of which this plans a part: errors name legs and
  // waypoints, and legs draw their seeds, by their place in the whole path.
  std::size_t first_leg = 0;
};

struct PlannedPath {
  std::vector<MapPose> poses;            // first = waypoints.front(), last = waypoints.back()
  std::vector<double> s;                 // arc length at each pose, from 0
  std::vector<std::int8_t> direction;    // +1 forwards, -1 reversing, per pose
  std::vector<std::size_t> waypoint_at;  // index into poses of each waypoint
  double length = 0;
  int sampled_legs = 0;  // legs the sampling planner had to plan
};

// A path that cannot be planned: which leg, and why (waypoint inside an obstacle, no path found
// within the time limit, a degenerate request).
class PlanningError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

PlannedPath plan_path(const PathRequest& request);

}  // namespace scenfuzz
