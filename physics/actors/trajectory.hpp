// Scripted motion: a path with a speed profile along it, for NPC vehicles and pedestrians that
// follow what the scenario says rather than react. The profile (physics/actors/speed_profile.hpp)
// is continuous and every time is finite; past the end the actor stands still. Built with an
// actor's motion limits, it is one its class can drive: slower in bends, acceleration and jerk
// bounded.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/actors/speed_profile.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

class Trajectory {
 public:
  Trajectory() = default;
  // `speeds` sorted by s, the first at s = 0; a missing last point keeps the last speed up to the
  // path's end, where the actor stops (braking at `stop_deceleration` so as to stop there).
  // Throws std::invalid_argument for an empty path or speed list, speeds out of order or
  // negative, or a deceleration that is not positive.
  Trajectory(Polyline path, std::vector<SpeedPoint> speeds, double stop_deceleration);
  // The feasible profile of `speeds` (feasible_profile) for `limits`, the path's curvature
  // bounding the speed in bends; shortfalls() says which given speeds it cannot keep to. Throws
  // std::invalid_argument as above and for limits that are not positive.
  Trajectory(Polyline path, std::vector<SpeedPoint> speeds, const MotionLimits& limits);
  // An actor that stays at `pose` (a Polyline needs two distinct points, so a standing actor has
  // no path: path() is empty and duration() is 0).
  static Trajectory standing(MapPose pose);

  // The state at time t >= 0 (since the start of the motion). Its yaw rate is the path's turn
  // rate at t (speed x curvature), not the heading's change over a step that a trace records
  // (step_yaw_rate): a simulation step that samples the trajectory replaces it.
  KinematicState state_at(double t) const;
  const Polyline& path() const { return path_; }
  // How far along the path the actor is at time t >= 0 (0 for a standing actor): its route
  // distance, where the path was drawn along a lane route (the NPCs' indicators).
  double distance_at(double t) const { return profile_.empty() ? 0 : profile_.at(t).s; }
  double duration() const;  // time to reach the end of the path (infinite if it never does)
  // The given speed points the actor cannot keep to (only with motion limits), by point.
  const std::vector<SpeedShortfall>& shortfalls() const { return shortfalls_; }

 private:
  void prepare_path();  // the standing pose and the segment headings, for state_at

  Polyline path_;
  std::vector<double> segment_headings_;  // of each path segment, for state_at
  MapPose standing_pose_;                 // where an actor without a path stays
  SpeedProfile profile_;
  std::vector<SpeedShortfall> shortfalls_;
};

// The curving stretches of a path as the trajectory's heading turns along it (near each vertex),
// with their |curvature|: what bounds the speed in bends.
std::vector<PathBend> path_bends(const Polyline& path);

// A drivable path along a lane route, `lateral` metres left of the centre lines, sampled every
// `spacing` metres. A lane change in the route becomes a smooth sideways move over
// `lane_change_length` metres ending where the route enters the new lane; when the route has
// less than that on the lane before (find_route changes lane where it entered a lane, so it has
// none), the move starts as early as it can and runs on into the new lane. Lane changes in a row
// take turns. Throws std::invalid_argument for an empty or zero-length route or a bad spacing.
// `places`, when given, receives where each point of the path lies on the route (PathPlace).
struct PathPlace;
inline constexpr double kLaneChangeLength = 30;  // m
inline constexpr double kRoutePathSpacing = 1;   // m
Polyline route_path(const RoadMap& map, const LaneRoute& route, double lateral = 0,
                    double lane_change_length = kLaneChangeLength,
                    double spacing = kRoutePathSpacing, std::vector<PathPlace>* places = nullptr);

// Where a point of route_path lies on the route: on route segment `segment`'s lane at lane
// arc length `s` (on its centre line, or beside it by a `lateral` of at most kOnLaneLateral,
// well inside any lane), or not surely on that lane (`on_lane` false: in a lane change's
// sideways move, or drawn farther aside).
inline constexpr double kOnLaneLateral = 0.5;  // m
struct PathPlace {
  std::uint32_t segment = 0;
  double s = 0;
  bool on_lane = true;
};

// route_path with its corners rounded for a body turning no tighter than `min_radius`
// (round_corners), and the places of its points: one the rounding moved is placed where it
// projects onto its lane's centre line.
Polyline rounded_route_path(const RoadMap& map, const LaneRoute& route, double lateral,
                            double min_radius, std::vector<PathPlace>& places);

// Where route_path moves sideways: from route distance `begin` to `end`, from lane `from` to `to`.
struct LaneChangeStretch {
  double begin = 0;
  double end = 0;
  LaneIndex from = 0;
  LaneIndex to = 0;
};
std::vector<LaneChangeStretch> lane_change_stretches(const RoadMap& map, const LaneRoute& route,
                                                     double lane_change_length = kLaneChangeLength);

// Where a lane-following actor goes without a target: from `start` along successors (the one
// that turns least over its first metres at each fork), for `length` metres (the last segment
// is cut there) or to a dead end.
LaneRoute route_ahead(const RoadMap& map, LanePosition start, double length);

}  // namespace scenfuzz
