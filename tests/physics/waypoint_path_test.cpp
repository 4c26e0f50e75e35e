// Waypoint paths of NPC vehicles: lane legs over the lane graph (junction connectors, lane changes
// sized to the speed, lateral offsets kept), and the planner for the legs the rules send to it.
#include "physics/simulation/waypoint_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/polyline.hpp"
#include "physics/planning/path_planner.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

RoadMap builtin(std::string_view name) { return build_road_map(generate_builtin_map(name, {})); }

LaneIndex lane(const RoadMap& map, std::string_view id) { return map.find_lane(id).value(); }

MapPose on_lane(const RoadMap& map, std::string_view id, double s, double lateral = 0) {
  return lane_pose_at(map, lane(map, id), s, lateral).value();
}

WaypointPathRequest request_through(std::vector<MapPose> poses, double speed) {
  WaypointPathRequest request;
  request.speeds.assign(poses.size(), speed);
  request.poses = std::move(poses);
  request.turning_radius = 5.5;
  request.comfortable_lateral_acceleration = 3.0;
  return request;
}

// speed^2 x curvature at each inner point of a path (curvature from the turn between segments).
double largest_lateral_acceleration(const std::vector<MapPoint>& points, double speed) {
  double largest = 0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    double before = std::atan2(points[i].y - points[i - 1].y, points[i].x - points[i - 1].x);
    double after = std::atan2(points[i + 1].y - points[i].y, points[i + 1].x - points[i].x);
    double span = (distance(points[i - 1], points[i]) + distance(points[i], points[i + 1])) / 2;
    largest = std::max(largest, speed * speed * std::abs(angle_difference(after, before)) / span);
  }
  return largest;
}

// Each pose lies on the path at its waypoint_s, and the path keeps every point (so the arc lengths
// a Polyline computes are the ones waypoint_s was measured on).
void expect_waypoints_at_their_arc_lengths(const WaypointPath& path,
                                           const std::vector<MapPose>& poses) {
  ASSERT_EQ(path.waypoint_s.size(), poses.size());
  const Polyline line(path.points);
  ASSERT_EQ(line.points().size(), path.points.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    MapPoint at = line.point_at(path.waypoint_s[i]);
    EXPECT_NEAR(at.x, poses[i].position.x, 1e-6) << "waypoint " << i;
    EXPECT_NEAR(at.y, poses[i].position.y, 1e-6) << "waypoint " << i;
  }
  EXPECT_NEAR(path.waypoint_s.back(), line.length(), 1e-9);
}

TEST(WaypointPathTest, ALaneChangeTakesThreeSecondsOrWhatTheComfortableLateralAccelerationNeeds) {
  EXPECT_DOUBLE_EQ(waypoint_lane_change_length(17, 3.5, 3.0), 51);  // sqrt(6 x 3.5 / 3) < 3 s
  EXPECT_NEAR(waypoint_lane_change_length(10, 3.5, 1.5), 10 * std::sqrt(14.0), 1e-12);  // a bus
  EXPECT_DOUBLE_EQ(waypoint_lane_change_length(0, 3.5, 3.0), 10);  // from standstill: 10 m
}

TEST(WaypointPathTest, ALegAcrossTheJunctionFollowsItsConnectorLane) {
  // crossroads: the junction box is |x|, |y| < 10; west_in_1 turns left into north_out_1 over
  // the connector west_north_1. The start is 0.5 m left of its centre line, the end on it.
  const RoadMap map = builtin("crossroads");
  const std::vector<MapPose> poses{on_lane(map, "west_in_1", 100, 0.5),
                                   on_lane(map, "north_out_1", 50)};
  const WaypointPath path = waypoint_path(map, request_through(poses, 8));
  ASSERT_EQ(path.legs, std::vector<LegKind>{LegKind::lane});
  const Polyline& connector = map.lane(lane(map, "west_north_1")).centre_line;
  int inside_junction = 0;
  for (const MapPoint& point : path.points) {
    if (std::abs(point.x) >= 9.9 || std::abs(point.y) >= 9.9) continue;
    ++inside_junction;
    PolylineProjection on_connector = connector.project(point);
    EXPECT_GE(on_connector.lateral, -0.01) << point.x << ", " << point.y;
    EXPECT_LE(on_connector.lateral, 0.51) << point.x << ", " << point.y;
  }
  EXPECT_GT(inside_junction, 15);
  expect_waypoints_at_their_arc_lengths(path, poses);
}

TEST(WaypointPathTest, AScenarioLegAcrossTheJunctionDrivesTheConnector) {
  // The same turn as a scenario: the NPC's trace inside the junction stays on the connector (its
  // class's full-lock circle, 5.5 m, is far tighter than the connector's arc, so a free-space
  // curve would cut the corner).
  SimulationOptions options;
  options.duration = 15;
  auto run = test::simulate_text(
      "ego = AV((\"south_in_0\"->20, , 0), (\"south_in_0\"->130));\n"
      "npc = Vehicle((\"west_in_1\"->100, , 8), Waypoint((\"north_out_1\"->50, , 8)), "
      "(\"north_out_1\"->80), (\"Sedan\", red));\n"
      "scenario = CreateScenario{load(\"crossroads\"); ego; {npc}; {}; {};};\n",
      options);
  ASSERT_TRUE(run.trace) << run.errors;
  const RoadMap map = builtin("crossroads");
  const Polyline& connector = map.lane(lane(map, "west_north_1")).centre_line;
  const TraceActor& npc = run.trace->actors[1];
  int inside_junction = 0;
  for (std::size_t i = 0; i < npc.x.size(); ++i) {
    if (std::abs(npc.x[i]) >= 9.9 || std::abs(npc.y[i]) >= 9.9) continue;
    ++inside_junction;
    EXPECT_LT(connector.project({npc.x[i], npc.y[i]}).distance, 0.05)
        << "at " << run.trace->time[i] << " s";
  }
  EXPECT_GT(inside_junction, 10);
}

TEST(WaypointPathTest, ALaneChangeEndsAtTheWaypointAndStaysWithinTheComfortableLimit) {
  // straight: east_1 (y = -1.75) and east_0 (y = -5.25). 65 m at 17 m/s fit a 51 m lane change.
  const RoadMap map = builtin("straight");
  const std::vector<MapPose> poses{on_lane(map, "east_1", 60), on_lane(map, "east_0", 125),
                                   on_lane(map, "east_0", 250)};
  const WaypointPath path = waypoint_path(map, request_through(poses, 17));
  ASSERT_EQ(path.legs, (std::vector<LegKind>{LegKind::lane, LegKind::lane}));
  EXPECT_LE(largest_lateral_acceleration(path.points, 17), 3.0 * 1.02);
  const Polyline line(path.points);
  const double start_x = poses[0].position.x;
  EXPECT_NEAR(line.point_at(12).y, poses[0].position.y, 1e-6) << "still in east_1";
  EXPECT_LT(line.point_at(40).y, poses[0].position.y - 1) << "moving over";
  EXPECT_NEAR(line.point_at(63).y, poses[1].position.y, 0.01) << "arrived in east_0";
  for (const MapPoint& point : path.points) EXPECT_GE(point.x, start_x - 1e-9) << "forwards";
  expect_waypoints_at_their_arc_lengths(path, poses);
}

TEST(WaypointPathTest, ALegTooShortForAComfortableLaneChangeStillMovesOverSmoothly) {
  const RoadMap map = builtin("straight");
  const std::vector<MapPose> poses{on_lane(map, "east_1", 60), on_lane(map, "east_0", 85)};
  const WaypointPath path = waypoint_path(map, request_through(poses, 15));
  ASSERT_EQ(path.legs, std::vector<LegKind>{LegKind::lane});
  // A smoothstep over the whole 25 m: 6 x 3.5 / 25^2 per m^2 of speed^2, no kink.
  EXPECT_LE(largest_lateral_acceleration(path.points, 1), 6 * 3.5 / (25.0 * 25) * 1.05);
  expect_waypoints_at_their_arc_lengths(path, poses);
}

TEST(WaypointPathTest, TheLateralOffsetBlendsFromTheStartsToTheEnds) {
  const RoadMap map = builtin("straight");
  const std::vector<MapPose> poses{on_lane(map, "east_0", 50, 1.0),
                                   on_lane(map, "east_0", 150, -0.5)};
  const WaypointPath path = waypoint_path(map, request_through(poses, 10));
  ASSERT_EQ(path.legs, std::vector<LegKind>{LegKind::lane});
  const Polyline& centre = map.lane(lane(map, "east_0")).centre_line;
  double previous = 1.0;
  for (const MapPoint& point : path.points) {
    double lateral = centre.project(point).lateral;
    EXPECT_LE(lateral, previous + 1e-9);
    EXPECT_GE(lateral, -0.5 - 1e-9);
    previous = lateral;
  }
  // Halfway (the path is a little longer than the lane's 100 m where it moves sideways).
  EXPECT_NEAR(centre.project(Polyline(path.points).point_at(50)).lateral, 0.25, 1e-3);
}

TEST(WaypointPathTest, ALegWithAnEndOffTheLanesUsesThePlanner) {
  // The middle waypoint lies 30 m south of the road, in no lane: both its legs are planned, as
  // plan_path plans them; the last leg, between two lane poses, follows the lane.
  const RoadMap map = builtin("straight");
  const MapPose off_road{{100, -40}, 0};
  const std::vector<MapPose> poses{on_lane(map, "east_0", 20), off_road,
                                   on_lane(map, "east_0", 250), on_lane(map, "east_0", 300)};
  ASSERT_FALSE(project_to_lane(map, off_road.position, 0)->inside);
  WaypointPathRequest request = request_through(poses, 10);
  request.seed = 7;
  const WaypointPath path = waypoint_path(map, request);
  ASSERT_EQ(path.legs, (std::vector<LegKind>{LegKind::planned, LegKind::planned, LegKind::lane}));
  PathRequest plan;
  plan.waypoints = {poses[0], poses[1], poses[2]};
  plan.turning_radius = 5.5;
  plan.seed = 7;
  const PlannedPath planned = plan_path(plan);
  const std::size_t planned_points = planned.waypoint_at.back() + 1;
  ASSERT_GT(path.points.size(), planned_points);
  for (std::size_t i = 0; i < planned_points; ++i) {
    EXPECT_EQ(path.points[i].x, planned.poses[i].position.x) << i;
    EXPECT_EQ(path.points[i].y, planned.poses[i].position.y) << i;
  }
  // waypoint_s is measured along the points (plan_path's s along its curves is a few mm longer).
  EXPECT_NEAR(path.waypoint_s[2], planned.s[planned.waypoint_at.back()], 0.01);
  expect_waypoints_at_their_arc_lengths(path, poses);
}

TEST(WaypointPathTest, ADetourRoundTheRingIsPlannedInstead) {
  // ring_0 -> 100 to ring_0 -> 92 is 8 m back; the lanes would go once round (about 118 m).
  const RoadMap map = builtin("roundabout");
  const MapPose behind = on_lane(map, "ring_0", 92);
  const MapPose from = on_lane(map, "ring_0", 100);
  const WaypointPath path = waypoint_path(map, request_through({from, behind}, 5));
  EXPECT_EQ(path.legs, std::vector<LegKind>{LegKind::planned});
}

TEST(WaypointPathTest, ALanePathThatHitsAStaticObstacleIsPlannedAroundIt) {
  const RoadMap map = builtin("straight");
  const std::vector<MapPose> poses{on_lane(map, "east_0", 20), on_lane(map, "east_0", 120)};
  const MapPoint block{70, poses[0].position.y};
  WaypointPathRequest request = request_through(poses, 10);
  request.is_free = [&](const MapPose& pose) { return distance(pose.position, block) > 2; };
  const WaypointPath path = waypoint_path(map, request);
  ASSERT_EQ(path.legs, std::vector<LegKind>{LegKind::planned});
  for (const MapPoint& point : path.points) EXPECT_GT(distance(point, block), 2);
  expect_waypoints_at_their_arc_lengths(path, poses);
}

TEST(WaypointPathTest, APlannedLegAfterALaneLegIsNamedByItsPlaceInThePath) {
  // The third pose lies inside an obstacle: plan_path's error counts legs and waypoints of the
  // whole path, not of the planned part.
  const RoadMap map = builtin("straight");
  const MapPose off_road{{200, -40}, 0};
  const std::vector<MapPose> poses{on_lane(map, "east_0", 20), on_lane(map, "east_0", 100),
                                   off_road};
  WaypointPathRequest request = request_through(poses, 10);
  request.is_free = [&](const MapPose& pose) {
    return distance(pose.position, off_road.position) > 1;
  };
  try {
    waypoint_path(map, request);
    ADD_FAILURE() << "the waypoint inside the obstacle was accepted";
  } catch (const PlanningError& error) {
    EXPECT_NE(std::string(error.what()).find("waypoint 3 "), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace scenfuzz
