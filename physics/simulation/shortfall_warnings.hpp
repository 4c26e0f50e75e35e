// Warnings for the speeds a scripted actor's script asks for but its class cannot drive (a
// waypoint speed too far from the one before for the distance between them, or too fast for the
// bend it lies in): which actor, which waypoint (at the source of its speed), and what it does
// instead.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/actors/trajectory.hpp"

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

}  // namespace scenfuzz
