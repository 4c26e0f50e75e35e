// Routes over the lane graph (A* from a lane position to a target lane position, following
// successors through junctions and changing lanes where allowed), and what lies ahead on a route.
#pragma once

#include <optional>
#include <vector>

#include "physics/map/lane_queries.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// Driving along `lane` from s_begin to s_end (s_begin <= s_end).
struct RouteSegment {
  LaneIndex lane = 0;
  double s_begin = 0;
  double s_end = 0;
};

// Consecutive segments either follow a successor link (the next starts at s = 0 where the
// previous ends at its lane's length) or change lane sideways (the next starts beside where the
// previous ends).
struct LaneRoute {
  std::vector<RouteSegment> segments;
  double length = 0;  // metres driven along centre lines
  int lane_changes = 0;
};

// Where a successor link leaves `from` and enters `to`: usually from's end and to's start, but a
// closed ring (roundabout) is one lane whose entries and exits join it part-way along.
struct LinkPoints {
  double exit_s = 0;
  double entry_s = 0;
};
LinkPoints link_points(const RoadMap& map, LaneIndex from, LaneIndex to);

// Lane ends closer than this are joined end to start (Apollo's joints are within millimetres).
inline constexpr double kJointTolerance = 0.5;

struct RouteOptions {
  // Extra cost of a lane change in metres, so that a route keeps its lane when it can.
  double lane_change_cost = 20;
  bool allow_lane_changes = true;
};

std::optional<LaneRoute> find_route(const RoadMap& map, LanePosition from, LanePosition to,
                                    const RouteOptions& options = {});
// From a pose (projected onto the lane best matching its heading) to a target pose.
std::optional<LaneRoute> find_route(const RoadMap& map, MapPose from, MapPose to,
                                    const RouteOptions& options = {});

// The same route with each lane change moved to at least `distance` metres past where the route
// entered the lane it leaves, as far as both lanes run on: find_route changes lane at once, and a
// driver needs room to wait for a gap in the next lane. The route's length stays the same.
LaneRoute defer_lane_changes(const RoadMap& map, LaneRoute route, double distance);

struct FeatureAhead {
  FeatureKind kind = FeatureKind::traffic_light;
  std::uint32_t index = 0;  // into the map's traffic_lights(), signs() or crosswalks()
  LaneIndex lane = 0;
  double s = 0;         // on `lane`, where the feature begins (the stop line)
  double distance = 0;  // along the route from the query point
};

// The first traffic light, stop sign, yield sign or crosswalk (of `kind`, or any when nullopt)
// at or after `route_distance` metres along the route, within the route.
std::optional<FeatureAhead> next_feature_ahead(const RoadMap& map, const LaneRoute& route,
                                               double route_distance,
                                               std::optional<FeatureKind> kind = std::nullopt);

}  // namespace scenfuzz
