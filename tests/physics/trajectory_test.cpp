// Scripted motion along a path, route paths over the built-in maps and the lane follower's route.
#include "physics/actors/trajectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "physics/map/builtin_maps.hpp"

namespace scenfuzz {
namespace {

Polyline straight_path(double length) {
  std::vector<MapPoint> points{{0, 0}, {length, 0}};
  return Polyline(points);
}

Polyline circle_path(double radius, int segments_per_turn) {
  std::vector<MapPoint> points;
  for (int i = 0; i <= segments_per_turn; ++i) {
    double angle = 2 * std::numbers::pi * i / segments_per_turn;
    points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return Polyline(points);
}

TEST(TrajectoryMotion, ConstantSpeedOnAStraightPath) {
  Trajectory trajectory(straight_path(100), {{0, 10}}, 5);
  for (double t : {0.0, 1.0, 3.5, 8.0}) {
    KinematicState state = trajectory.state_at(t);
    EXPECT_NEAR(state.x, 10 * t, 1e-9) << t;
    EXPECT_NEAR(state.y, 0, 1e-12);
    EXPECT_NEAR(state.speed, 10, 1e-12);
    EXPECT_EQ(state.acceleration, 0);
    EXPECT_NEAR(state.heading, 0, 1e-12);
    EXPECT_NEAR(state.yaw_rate, 0, 1e-12);
  }
}

TEST(TrajectoryMotion, ReachesTheNextSpeedExactlyAtItsPoint) {
  Trajectory trajectory(straight_path(200), {{0, 5}, {50, 15}}, 3);
  // dt = 2 ds / (v0 + v1) = 100 / 20, at a = (15^2 - 5^2) / (2 * 50) = 2.
  KinematicState at_point = trajectory.state_at(5);
  EXPECT_NEAR(at_point.x, 50, 1e-9);
  EXPECT_NEAR(at_point.speed, 15, 1e-9);
  KinematicState between = trajectory.state_at(2.5);
  EXPECT_NEAR(between.x, 5 * 2.5 + 0.5 * 2 * 2.5 * 2.5, 1e-9);
  EXPECT_NEAR(between.speed, 10, 1e-9);
  EXPECT_NEAR(between.acceleration, 2, 1e-9);
  KinematicState after = trajectory.state_at(6);
  EXPECT_NEAR(after.x, 65, 1e-9);
  EXPECT_NEAR(after.speed, 15, 1e-9);
}

TEST(TrajectoryMotion, StopsExactlyAtThePathEndAndStaysThere) {
  // 10 m/s braking at 2 m/s^2 needs 25 m: cruise to s = 75 (7.5 s), then 5 s of braking.
  Trajectory trajectory(straight_path(100), {{0, 10}}, 2);
  EXPECT_NEAR(trajectory.duration(), 12.5, 1e-9);
  KinematicState braking = trajectory.state_at(10);
  EXPECT_NEAR(braking.speed, 5, 1e-9);
  EXPECT_NEAR(braking.acceleration, -2, 1e-9);
  EXPECT_NEAR(braking.x, 75 + 10 * 2.5 - 0.5 * 2 * 2.5 * 2.5, 1e-9);
  for (double t : {12.5, 13.0, 100.0}) {
    KinematicState state = trajectory.state_at(t);
    EXPECT_NEAR(state.x, 100, 1e-9) << t;
    EXPECT_EQ(state.speed, 0);
    EXPECT_EQ(state.acceleration, 0);
  }
}

TEST(TrajectoryMotion, BrakesHarderWhenTheLastPointIsTooCloseToTheEnd) {
  // From 10 m/s, 10 m before the end: 5 m/s^2 instead of 2.
  Trajectory trajectory(straight_path(10), {{0, 10}}, 2);
  EXPECT_NEAR(trajectory.duration(), 2, 1e-9);
  EXPECT_NEAR(trajectory.state_at(1).acceleration, -5, 1e-9);
  EXPECT_NEAR(trajectory.state_at(2).x, 10, 1e-9);
}

TEST(TrajectoryMotion, ZeroSpeedsStandStill) {
  Trajectory standing(straight_path(100), {{0, 0}}, 2);
  EXPECT_TRUE(std::isinf(standing.duration()));
  KinematicState state = standing.state_at(1000);
  EXPECT_EQ(state.x, 0);
  EXPECT_EQ(state.speed, 0);

  // Drives to s = 50, stops there and never moves on.
  Trajectory stopping(straight_path(100), {{0, 10}, {50, 0}, {60, 0}}, 2);
  EXPECT_TRUE(std::isinf(stopping.duration()));
  EXPECT_NEAR(stopping.state_at(10).x, 50, 1e-9);
  EXPECT_NEAR(stopping.state_at(1e6).x, 50, 1e-9);
  EXPECT_EQ(stopping.state_at(1e6).speed, 0);
}

TEST(TrajectoryMotion, RestartsAfterAStop) {
  Trajectory trajectory(straight_path(100), {{0, 10}, {50, 0}, {75, 5}}, 1);
  // 10 s to s = 50, then 10 s to s = 75 at 5 m/s, then 12.5 m braking at 1 m/s^2 in 5 s, the rest
  // cruising: 12.5 m at 5 m/s.
  EXPECT_NEAR(trajectory.duration(), 10 + 10 + 2.5 + 5, 1e-9);
  EXPECT_NEAR(trajectory.state_at(10).speed, 0, 1e-9);
  EXPECT_NEAR(trajectory.state_at(20).x, 75, 1e-9);
}

TEST(TrajectoryMotion, PositionIsContinuousAcrossKnots) {
  Trajectory trajectory(circle_path(30, 90), {{0, 2}, {40, 12}, {90, 6}, {120, 6}, {150, 0.5}}, 3);
  ASSERT_TRUE(std::isfinite(trajectory.duration()));
  const double step = 1e-3;
  KinematicState previous = trajectory.state_at(0);
  for (double t = step; t <= trajectory.duration() + 1; t += step) {
    KinematicState state = trajectory.state_at(t);
    double moved = std::hypot(state.x - previous.x, state.y - previous.y);
    ASSERT_LE(moved, 12 * step + 1e-9) << t;
    ASSERT_LE(std::abs(state.speed - previous.speed), 3.1 * step + 1e-9) << t;
    ASSERT_LE(std::abs(angle_difference(state.heading, previous.heading)), 0.01) << t;
    previous = state;
  }
  EXPECT_NEAR(previous.x, 30, 1e-9);
  EXPECT_NEAR(previous.y, 0, 1e-6);
}

TEST(TrajectoryMotion, YawRateOnACircleIsSpeedOverRadius) {
  Trajectory trajectory(circle_path(20, 360), {{0, 8}}, 4);
  for (double t : {1.0, 3.3, 7.77, 10.0}) {
    KinematicState state = trajectory.state_at(t);
    EXPECT_NEAR(state.yaw_rate, 8.0 / 20, 0.004) << t;
    EXPECT_NEAR(std::hypot(state.x, state.y), 20, 0.01);
    // Counter-clockwise round the origin: heading 90 degrees ahead of the position's angle.
    double tangent = std::atan2(state.y, state.x) + std::numbers::pi / 2;
    EXPECT_NEAR(angle_difference(state.heading, tangent), 0, 0.01) << t;
  }
}

TEST(TrajectoryMotion, StandingActorKeepsItsPose) {
  Trajectory trajectory = Trajectory::standing({{3, 4}, 1.25});
  EXPECT_EQ(trajectory.duration(), 0);
  EXPECT_TRUE(trajectory.path().points().empty());
  for (double t : {0.0, 50.0}) {
    KinematicState state = trajectory.state_at(t);
    EXPECT_EQ(state.x, 3);
    EXPECT_EQ(state.y, 4);
    EXPECT_EQ(state.heading, 1.25);
    EXPECT_EQ(state.speed, 0);
  }
}

TEST(TrajectoryMotion, RejectsBadProfiles) {
  EXPECT_THROW(Trajectory(straight_path(10), {}, 2), std::invalid_argument);
  EXPECT_THROW(Trajectory(straight_path(10), {{1, 5}}, 2), std::invalid_argument);
  EXPECT_THROW(Trajectory(straight_path(10), {{0, 5}, {6, 2}, {3, 1}}, 2), std::invalid_argument);
  EXPECT_THROW(Trajectory(straight_path(10), {{0, -1}}, 2), std::invalid_argument);
  EXPECT_THROW(Trajectory(straight_path(10), {{0, 5}}, 0), std::invalid_argument);
  EXPECT_THROW(Trajectory(Polyline(), {{0, 5}}, 2), std::invalid_argument);
}

class TrajectoryRoutes : public ::testing::Test {
 protected:
  static RoadMap builtin(std::string_view name) {
    return build_road_map(generate_builtin_map(name, {}));
  }
  static LaneIndex lane(const RoadMap& map, std::string_view id) {
    return map.find_lane(id).value();
  }
  // The path's y where it crosses x (for paths heading east).
  static double y_at_x(const Polyline& path, double x) {
    const std::vector<MapPoint>& points = path.points();
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      if (points[i].x <= x && x <= points[i + 1].x) {
        double fraction = (x - points[i].x) / (points[i + 1].x - points[i].x);
        return points[i].y + fraction * (points[i + 1].y - points[i].y);
      }
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
  // The largest heading change between consecutive path segments.
  static double largest_turn(const Polyline& path) {
    double largest = 0;
    for (std::size_t i = 1; i < path.segment_count(); ++i) {
      double s = path.arc_lengths()[i];
      largest = std::max(largest,
                         std::abs(angle_difference(path.heading_at(s), path.heading_at(s - 1e-9))));
    }
    return largest;
  }
};

TEST_F(TrajectoryRoutes, LaneChangeOnStraightBlendsSmoothly) {
  RoadMap map = builtin("straight");
  auto route = find_route(map, LanePosition{lane(map, "east_0"), 10},
                          LanePosition{lane(map, "east_1"), 200});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->lane_changes, 1);
  Polyline path = route_path(map, *route);
  EXPECT_NEAR(path.points().front().x, 10, 1e-9);
  EXPECT_NEAR(path.points().front().y, -5.25, 1e-9);
  EXPECT_NEAR(path.points().back().x, 200, 1e-9);
  EXPECT_NEAR(path.points().back().y, -1.75, 1e-9);
  EXPECT_NEAR(path.length(), route->length, 0.5);
  EXPECT_GT(path.length(), route->length);
  // The change enters east_1 where the route starts, so the blend runs on into east_1: 30 m.
  EXPECT_NEAR(y_at_x(path, 25), -3.5, 0.01);
  EXPECT_NEAR(y_at_x(path, 41), -1.75, 1e-9);
  for (std::size_t i = 1; i < path.segment_count(); ++i) {
    double turn = std::abs(angle_difference(path.heading_at(path.arc_lengths()[i]),
                                            path.heading_at(path.arc_lengths()[i - 1])));
    double metres = path.arc_lengths()[i] - path.arc_lengths()[i - 1];
    ASSERT_LE(turn, 0.03 * std::max(metres, 1.0)) << i;
  }
}

TEST_F(TrajectoryRoutes, LaneChangeEndsWhereTheRouteEntersTheNewLane) {
  RoadMap map = builtin("straight");
  LaneRoute route{{{lane(map, "east_0"), 0, 100}, {lane(map, "east_1"), 100, 200}}, 200, 1};
  Polyline path = route_path(map, route, 0, 40, 2);
  auto y_at = [&](double x) { return y_at_x(path, x); };
  EXPECT_NEAR(y_at(59), -5.25, 1e-9);
  EXPECT_NEAR(y_at(80), -3.5, 1e-6);  // smoothstep(1/2) = 1/2
  EXPECT_NEAR(y_at(100), -1.75, 1e-9);
  EXPECT_NEAR(y_at(150), -1.75, 1e-9);
}

TEST_F(TrajectoryRoutes, LaneChangesInARowTakeTurns) {
  RoadMap map = build_road_map(generate_builtin_map("straight", {{"lanes", 3}}));
  auto route = find_route(map, LanePosition{lane(map, "east_0"), 10},
                          LanePosition{lane(map, "east_2"), 200});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->lane_changes, 2);
  Polyline path = route_path(map, *route);
  // east_0 at y = -8.75, east_1 at -5.25, east_2 at -1.75: 30 m into each, one after the other.
  EXPECT_NEAR(y_at_x(path, 10), -8.75, 1e-9);
  EXPECT_NEAR(y_at_x(path, 25), -7, 1e-6);
  EXPECT_NEAR(y_at_x(path, 40), -5.25, 1e-9);
  EXPECT_NEAR(y_at_x(path, 55), -3.5, 1e-6);
  EXPECT_NEAR(y_at_x(path, 70), -1.75, 1e-9);
  EXPECT_NEAR(y_at_x(path, 200), -1.75, 1e-9);
  EXPECT_LT(largest_turn(path), 0.03);
}

TEST_F(TrajectoryRoutes, LateralOffsetIsHonoured) {
  RoadMap map = builtin("straight");
  LaneRoute route{{{lane(map, "east_0"), 20, 120}}, 100, 0};
  Polyline path = route_path(map, route, 1.0, 30, 5);
  EXPECT_EQ(path.points().size(), 21u);
  for (const MapPoint& point : path.points()) EXPECT_NEAR(point.y, -4.25, 1e-9);
  EXPECT_NEAR(path.length(), 100, 1e-9);
  EXPECT_THROW(route_path(map, route, 0, 30, 0), std::invalid_argument);
  EXPECT_THROW(route_path(map, LaneRoute{}, 0), std::invalid_argument);
  EXPECT_THROW(route_path(map, LaneRoute{{{lane(map, "east_0"), 5, 5}}, 0, 0}),
               std::invalid_argument);
}

// route_path says where each of its points lies on the route: on the lane of its route segment
// at that lane's s (the point drawn there), except in a lane change's sideways move; rounding the
// corners places a moved point where it projects onto its lane.
TEST_F(TrajectoryRoutes, PlacesSayWhereEachPointLiesOnTheRoute) {
  RoadMap map = builtin("straight");
  LaneRoute change{{{lane(map, "east_0"), 0, 100}, {lane(map, "east_1"), 100, 200}}, 200, 1};
  std::vector<PathPlace> places;
  Polyline path = route_path(map, change, 0, 40, 2, &places);
  ASSERT_EQ(places.size(), path.points().size());
  int aside = 0;
  for (std::size_t i = 0; i < places.size(); ++i) {
    const RouteSegment& on = change.segments[places[i].segment];
    if (!places[i].on_lane) {
      ++aside;
      EXPECT_GT(path.points()[i].x, 60 - 1e-9) << i;  // the move runs from x = 60 to 100
      EXPECT_LT(path.points()[i].x, 100 + 1e-9) << i;
      continue;
    }
    const MapPoint drawn = map.lane(on.lane).centre_line.point_at(places[i].s);
    EXPECT_NEAR(distance(drawn, path.points()[i]), 0, 1e-9) << i;
  }
  EXPECT_EQ(aside, 20);  // 40 m at 2 m: the points inside the move and its end
  // Beside the centre line by more than kOnLaneLateral, no point is surely on its lane.
  route_path(map, LaneRoute{{{lane(map, "east_0"), 20, 120}}, 100, 0}, 1.0, 30, 5, &places);
  EXPECT_TRUE(std::none_of(places.begin(), places.end(),
                           [](const PathPlace& place) { return place.on_lane; }));

  RoadMap crossroads = builtin("crossroads");
  auto turn = find_route(crossroads, LanePosition{lane(crossroads, "west_in_1"), 100},
                         LanePosition{lane(crossroads, "north_out_1"), 50});
  ASSERT_TRUE(turn);
  const Polyline drawn = route_path(crossroads, *turn);
  const Polyline rounded = rounded_route_path(crossroads, *turn, 0, 15, places);
  ASSERT_EQ(places.size(), rounded.points().size());
  int moved = 0;
  for (std::size_t i = 0; i < places.size(); ++i) {
    ASSERT_TRUE(places[i].on_lane) << i << " of " << places.size() << " at "
                                   << rounded.points()[i].x << "," << rounded.points()[i].y;
    if (!(rounded.points()[i] == drawn.points()[i])) ++moved;
    const Polyline& centre = crossroads.lane(turn->segments[places[i].segment].lane).centre_line;
    EXPECT_NEAR(centre.project(rounded.points()[i]).s, places[i].s, 1e-6) << i;
  }
  EXPECT_GT(moved, 5) << "a 15 m radius should round the left turn's corners";
}

TEST_F(TrajectoryRoutes, LeftTurnThroughTheCrossroadsFollowsTheConnector) {
  RoadMap map = builtin("crossroads");
  auto route = find_route(map, LanePosition{lane(map, "west_in_1"), 100},
                          LanePosition{lane(map, "north_out_1"), 50});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 3u);
  LaneIndex connector = lane(map, "west_north_1");
  ASSERT_EQ(route->segments[1].lane, connector);
  for (double lateral : {0.0, 1.0}) {
    Polyline path = route_path(map, *route, lateral);
    int inside_junction = 0;
    for (const MapPoint& point : path.points()) {
      if (std::abs(point.x) >= 9.9 || std::abs(point.y) >= 9.9) continue;
      ++inside_junction;
      PolylineProjection on_connector = map.lane(connector).centre_line.project(point);
      EXPECT_NEAR(on_connector.lateral, lateral, 0.01) << point.x << ", " << point.y;
    }
    EXPECT_GT(inside_junction, 15);
    EXPECT_LT(largest_turn(path), 0.1);
    EXPECT_NEAR(path.points().back().x, 1.75 - lateral, 1e-9);
    EXPECT_NEAR(path.points().back().y, 60, 1e-9);
  }
}

TEST_F(TrajectoryRoutes, PathsOnEveryBuiltinMapTurnGently) {
  for (std::string_view name :
       {"straight", "curve", "t_junction", "crossroads", "roundabout", "merge"}) {
    RoadMap map = builtin(name);
    for (LaneIndex start = 0; start < map.lanes().size(); ++start) {
      LaneRoute route = route_ahead(map, LanePosition{start, 0}, 400);
      Polyline path = route_path(map, route);
      // Sharpest built-in curve: a 4.62 m roundabout entry arc sampled every metre.
      EXPECT_LT(largest_turn(path), 0.25) << name << " " << map.lane(start).id;
    }
  }
  RoadMap merge = builtin("merge");
  auto route = find_route(merge, LanePosition{lane(merge, "ramp_0"), 0},
                          LanePosition{lane(merge, "main_0"), 400});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->lane_changes, 1);
  Polyline path = route_path(merge, *route);
  EXPECT_LT(largest_turn(path), 0.05);
  EXPECT_NEAR(path.points().back().y, 1.75, 1e-9);
}

TEST_F(TrajectoryRoutes, RouteAheadOnStraightRunsToTheLaneEnd) {
  RoadMap map = builtin("straight");
  LaneIndex east_0 = lane(map, "east_0");
  LaneRoute to_end = route_ahead(map, LanePosition{east_0, 100}, 1000);
  ASSERT_EQ(to_end.segments.size(), 1u);
  EXPECT_EQ(to_end.segments[0].lane, east_0);
  EXPECT_DOUBLE_EQ(to_end.segments[0].s_begin, 100);
  EXPECT_DOUBLE_EQ(to_end.segments[0].s_end, 500);
  EXPECT_DOUBLE_EQ(to_end.length, 400);
  LaneRoute short_route = route_ahead(map, LanePosition{east_0, 100}, 50);
  ASSERT_EQ(short_route.segments.size(), 1u);
  EXPECT_DOUBLE_EQ(short_route.segments[0].s_end, 150);
  EXPECT_DOUBLE_EQ(short_route.length, 50);
}

TEST_F(TrajectoryRoutes, RouteAheadGoesStraightOverTheCrossroads) {
  RoadMap map = builtin("crossroads");
  LaneRoute route = route_ahead(map, LanePosition{lane(map, "west_in_1"), 0}, 250);
  ASSERT_EQ(route.segments.size(), 3u);
  EXPECT_EQ(route.segments[1].lane, lane(map, "west_east_1"));
  EXPECT_EQ(route.segments[2].lane, lane(map, "east_out_1"));
  EXPECT_NEAR(route.length, 250, 1e-9);
}

TEST_F(TrajectoryRoutes, RouteAheadKeepsGoingRoundTheRoundabout) {
  RoadMap map = builtin("roundabout");
  LaneIndex ring = lane(map, "ring_0");
  LaneRoute route = route_ahead(map, LanePosition{lane(map, "south_in_0"), 50}, 400);
  EXPECT_NEAR(route.length, 400, 1e-9);
  ASSERT_GE(route.segments.size(), 4u);
  EXPECT_EQ(route.segments[1].lane, lane(map, "south_entry"));
  for (std::size_t i = 2; i < route.segments.size(); ++i)
    EXPECT_EQ(route.segments[i].lane, ring) << i;
  Polyline path = route_path(map, route);
  EXPECT_NEAR(path.length(), 400, 1.0);
  EXPECT_NEAR(std::hypot(path.points().back().x, path.points().back().y), 20, 0.01);
}

}  // namespace
}  // namespace scenfuzz
