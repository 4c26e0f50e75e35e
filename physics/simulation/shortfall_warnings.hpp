// Warnings for the speeds a scripted actor's script asks for but its class cannot drive (a
// waypoint speed too far from the one before for the distance between them, or too fast for the
// bend it lies in): which actor, which waypoint (at the source of its speed), and what it does
// instead. Also for a reactive lane follower whose initial speed the bends ahead do not allow.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

// One given speed point of a script, as messages name it.
struct ScriptPoint {
  std::string own;    // "its waypoint 2", "its start", "its target"
  std::string other;  // as another point's message refers to it: "waypoint 2", "its start"
  SourceLocation location;
};

// The actor's start, where its initial speed is written.
ScriptPoint start_point(const Actor& actor);

// The speed points of a waypoint script: `states` are the waypoints then the target,
// `pose_count` the poses kept of them (the start first; a waypoint where the actor already is
// gives no pose, and then poses are numbered instead), `point_poses` the pose of each speed point.
std::vector<ScriptPoint> waypoint_points(const Actor& actor, std::span<const State> states,
                                         std::size_t pose_count,
                                         std::span<const std::size_t> point_poses);

// One warning per shortfall of the trajectory; `points[i]` names its i-th given speed point.
void warn_shortfalls(const Trajectory& trajectory, const std::string& actor,
                     std::span<const ScriptPoint> points, Diagnostics& diagnostics);

// The most speed a reactive lane follower (LaneFollower) of class `body` starts `path` at: from
// it, every bend ahead can be taken within the class's comfortable lateral acceleration, braking
// at its comfortable deceleration; no more than its top speed.
double reactive_start_limit(const Polyline& path, const ActorClass& body);

// A warning at `start` when `initial_speed` is above reactive_start_limit: the actor starts at
// that limit instead, which the warning names.
void warn_reactive_start(const Polyline& path, const ActorClass& body, double initial_speed,
                         const std::string& actor, const ScriptPoint& start,
                         Diagnostics& diagnostics);

}  // namespace scenfuzz
