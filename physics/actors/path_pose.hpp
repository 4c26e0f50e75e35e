// Poses along a polyline path whose heading turns smoothly through each vertex: what scripted
// and lane-following actors drive along. A polyline's heading jumps at its vertices; here it
// turns linearly within a short blend around each one, so the heading is continuous and the yaw
// rate (speed x curvature) finite.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

struct PathDirection {
  double heading = 0;
  double curvature = 0;  // rad/m, positive turning left
};

// The direction of each segment of `path`, computed once for paths sampled at every step.
std::vector<double> segment_headings(const Polyline& path);

// The heading at arc length s (clamped to the path) and its derivative along the path; it looks
// at the segment there and its neighbours only, so it suits long paths asked at one point.
PathDirection direction_at(const Polyline& path, double s);
// As direction_at, with the segment headings computed beforehand.
PathDirection direction_at(const Polyline& path, std::span<const double> headings, double s);

// Half the length of the stretch around interior vertex `vertex` over which the heading turns
// from one segment's direction to the next.
double blend_half_width(const Polyline& path, std::size_t vertex);

// The largest |curvature| the blended heading has around interior vertex `vertex` (0 at the ends).
double vertex_curvature(const Polyline& path, std::span<const double> headings, std::size_t vertex);

// The path with its sharp corners rounded so that the blended heading never turns tighter than
// `min_radius` (a vehicle's full lock): lane polylines meet at kinks (Apollo's junction lanes
// start at an angle to the lane before them) that no vehicle could follow. Each pass moves every
// offending vertex towards its neighbours' midpoint, spreading the turn over more of the path;
// straight stretches and gentle bends stay exactly where they were.
Polyline round_corners(const Polyline& path, double min_radius);

// The tightest turn the paths an NPC is given take: a little wider than full lock, which no
// driver holds and which a trace sampled while braking would read as tighter than it is.
double planning_radius(const ActorClass& body);

// The state at arc length s (clamped to the path), moving at `speed` with `acceleration`; its
// yaw rate is speed x curvature.
KinematicState state_on_path(const Polyline& path, std::span<const double> headings, double s,
                             double speed, double acceleration);
// The same, finding s's segment by walking from segment `hint` (an actor's last one) instead of
// a binary search over the whole path: the same state bit for bit, sooner on long paths.
KinematicState state_on_path(const Polyline& path, std::span<const double> headings, double s,
                             double speed, double acceleration, std::size_t hint);

// The blend at interior vertex `vertex`: its half width and the turn from segment vertex - 1's
// heading to segment vertex's, which state_on_path works out at every call. An actor asking for
// its pose at every step (a lane follower) keeps them.
struct VertexBlend {
  double half_width = 0;
  double turn = 0;
};
VertexBlend vertex_blend(const Polyline& path, std::span<const double> headings,
                         std::size_t vertex);

// state_on_path's position and heading at s (within the path) on `segment`, bit for bit, from
// the kept blends of the segment's two vertices (`blends` by vertex: those two must be known).
MapPose pose_on_segment(const Polyline& path, std::span<const double> headings,
                        std::span<const VertexBlend> blends, std::size_t segment, double s);

}  // namespace scenfuzz
