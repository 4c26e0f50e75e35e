// Questions asked of one lane or of the map's lanes near a point: where is s on a lane, which
// lane is a point on, may a car change from one lane to another.
#pragma once

#include <optional>
#include <span>

#include "physics/map/road_map.hpp"

namespace scenfuzz {

// A place on a lane: arc length s along its centre line, and a lateral offset (positive left).
struct LanePosition {
  LaneIndex lane = 0;
  double s = 0;
  double lateral = 0;
};

// Where a point lies relative to its lane.
struct LaneProjection {
  LaneIndex lane = 0;
  double s = 0;
  double lateral = 0;   // signed, positive to the left of the lane's direction
  double distance = 0;  // to the centre line
  bool inside = false;  // within the lane's boundaries at s
};

// The pose at (lane, s, lateral): the point offset sideways from the centre line, heading along
// the lane. Returns nullopt when s is outside [0, length] (beyond a tolerance of 1 mm).
std::optional<MapPose> lane_pose_at(const RoadMap& map, LaneIndex lane, double s,
                                    double lateral = 0);
// A scenario's `"lane" -> s`: Apollo clamps s to [0, length] (LaneInfo::GetSmoothPoint), and the
// AVUnit and scenest files written for it rely on that (shared examples put targets a few metres
// past a lane's end), so this clamps too. `overshoot` is how far s lay outside the lane (0 when
// inside), for a warning. nullopt only for a non-finite s or lateral.
struct ClampedLanePose {
  MapPose pose;
  double overshoot = 0;
};
std::optional<ClampedLanePose> clamped_lane_pose(const RoadMap& map, LaneIndex lane, double s,
                                                 double lateral = 0);

double lane_heading_at(const RoadMap& map, LaneIndex lane, double s);
// Distance from the centre line to the left and right boundary at s (linear between samples).
double lane_left_width_at(const RoadMap& map, LaneIndex lane, double s);
double lane_right_width_at(const RoadMap& map, LaneIndex lane, double s);

// The lane whose centre line is nearest to `point`; nullopt only for a map without lanes.
std::optional<LaneProjection> project_to_lane(const RoadMap& map, MapPoint point);
// As above, but where lanes overlap (junctions, merges) prefers, among the lanes that contain the
// point, the one whose direction is closest to `heading`. A point in no lane gets the nearest.
std::optional<LaneProjection> project_to_lane(const RoadMap& map, MapPoint point, double heading);

// The nearest of `lanes` to `point`; nullopt when `lanes` is empty or the point not finite.
std::optional<LaneProjection> project_onto_lanes(const RoadMap& map, MapPoint point,
                                                 std::span<const LaneIndex> lanes);

// A lane change from `from` to `to` is allowed when `to` is a forward neighbour of `from`, the
// boundary between them is not solid (dotted, or unknown as built-in maps and some Apollo maps
// leave it), and neither lane lies in a junction.
bool lane_change_allowed(const RoadMap& map, LaneIndex from, LaneIndex to);

// Whether `lane` is its own successor: a roundabout's ring, driven round and round.
bool runs_into_itself(const RoadMap& map, LaneIndex lane);

}  // namespace scenfuzz
