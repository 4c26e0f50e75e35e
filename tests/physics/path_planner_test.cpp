// Car-like paths through waypoints: analytic Dubins / Reeds-Shepp legs, legs planned around
// static obstacles, determinism across threads, and the errors of unplannable requests.
#include "physics/planning/path_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <thread>

namespace scenfuzz {
namespace {

constexpr double kPi = std::numbers::pi;

MapPose pose(double x, double y, double heading) { return MapPose{{x, y}, heading}; }

PathRequest request_through(std::vector<MapPose> waypoints, double turning_radius = 5) {
  PathRequest request;
  request.waypoints = std::move(waypoints);
  request.turning_radius = turning_radius;
  return request;
}

// Free everywhere except a disc.
std::function<bool(const MapPose&)> outside_disc(MapPoint centre, double radius) {
  return [=](const MapPose& at) { return distance(at.position, centre) > radius; };
}

// Heading change per metre between consecutive poses never exceeds the curvature of the turning
// circle (the chord is slightly shorter than the arc, hence the tolerance).
void expect_turning_radius_respected(const PlannedPath& path, double turning_radius) {
  for (std::size_t i = 0; i + 1 < path.poses.size(); ++i) {
    const double step = distance(path.poses[i].position, path.poses[i + 1].position);
    if (step < 1e-6) continue;
    const double turn =
        std::abs(angle_difference(path.poses[i + 1].heading, path.poses[i].heading));
    EXPECT_LE(turn / step, 1.01 / turning_radius) << "between poses " << i << " and " << i + 1;
  }
}

// Each pose's direction says whether the vehicle moves along or against its heading to the next.
void expect_directions_match_motion(const PlannedPath& path) {
  for (std::size_t i = 0; i + 1 < path.poses.size(); ++i) {
    const double dx = path.poses[i + 1].position.x - path.poses[i].position.x;
    const double dy = path.poses[i + 1].position.y - path.poses[i].position.y;
    if (std::hypot(dx, dy) < 1e-6) continue;
    const double along =
        dx * std::cos(path.poses[i].heading) + dy * std::sin(path.poses[i].heading);
    EXPECT_EQ(along > 0 ? 1 : -1, path.direction[i]) << "at pose " << i;
  }
}

void expect_consistent(const PlannedPath& path, const PathRequest& request) {
  ASSERT_EQ(path.s.size(), path.poses.size());
  ASSERT_EQ(path.direction.size(), path.poses.size());
  ASSERT_EQ(path.waypoint_at.size(), request.waypoints.size());
  EXPECT_EQ(path.s.front(), 0);
  EXPECT_DOUBLE_EQ(path.s.back(), path.length);
  for (std::size_t i = 0; i + 1 < path.poses.size(); ++i) {
    const double step = path.s[i + 1] - path.s[i];
    EXPECT_GT(step, 0) << "at pose " << i;
    EXPECT_LE(step, request.spacing + 1e-9) << "at pose " << i;
    // Evenly spaced: no sliver before a waypoint, whose vertex would turn the heading in one step.
    if (path.direction[i] == path.direction[i + 1] && path.length > request.spacing) {
      EXPECT_GE(step, 0.5 * request.spacing - 1e-9) << "at pose " << i;
    }
    // Consecutive poses lie on a curve between them, never further apart than its length.
    EXPECT_LE(distance(path.poses[i].position, path.poses[i + 1].position), step + 1e-9);
  }
  for (std::size_t k = 0; k < request.waypoints.size(); ++k) {
    const MapPose& at = path.poses[path.waypoint_at[k]];
    EXPECT_EQ(at.position, request.waypoints[k].position) << "waypoint " << k;
    EXPECT_EQ(at.heading, request.waypoints[k].heading) << "waypoint " << k;
  }
}

void expect_identical(const PlannedPath& a, const PlannedPath& b) {
  ASSERT_EQ(a.poses.size(), b.poses.size());
  EXPECT_EQ(0, std::memcmp(a.poses.data(), b.poses.data(), a.poses.size() * sizeof(MapPose)));
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.waypoint_at, b.waypoint_at);
  EXPECT_EQ(a.length, b.length);
  EXPECT_EQ(a.sampled_legs, b.sampled_legs);
}

std::string planning_error(const PathRequest& request) {
  try {
    plan_path(request);
  } catch (const PlanningError& error) {
    return error.what();
  }
  return "no error";
}

TEST(PathPlanner, StraightLegIsAStraightLineOfItsLength) {
  const auto request = request_through({pose(0, 0, 0), pose(20, 0, 0)});
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_NEAR(path.length, 20, 1e-9);
  ASSERT_EQ(path.poses.size(), 41u);
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    EXPECT_NEAR(path.poses[i].position.x, 0.5 * double(i), 1e-9);
    EXPECT_NEAR(path.poses[i].position.y, 0, 1e-9);
    EXPECT_NEAR(path.poses[i].heading, 0, 1e-9);
    EXPECT_EQ(path.direction[i], 1);
  }
  EXPECT_EQ(path.waypoint_at, (std::vector<std::size_t>{0, 40}));
  EXPECT_EQ(path.sampled_legs, 0);
}

TEST(PathPlanner, ANearlyStraightLongLegDoesNotTripOmplsDubinsAssertion) {
  // Found by the search (cyclist_ahead.avu): OMPL's Dubins solver aborted the process on this
  // leg, 208 m long, 4.7e-5 m off straight, both headings along the road.
  const auto request = request_through(
      {pose(281.97427980240798, -5.249953171457368, 0), pose(490, -5.25, 0)}, 1.3570114146796926);
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_NEAR(path.length, 490 - 281.97427980240798, 1e-6);
  for (const MapPose& sample : path.poses) EXPECT_NEAR(sample.position.y, -5.25, 1e-4);
}

TEST(PathPlanner, UTurnHasTheDubinsLengthAndRespectsTheTurningRadius) {
  // Straight 20 m along y = 0, then a left half circle of radius 5 about (20, 5): the Dubins
  // distance is 20 + 5 pi.
  const auto request = request_through({pose(0, 0, 0), pose(20, 10, kPi)});
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_NEAR(path.length, 20 + 5 * kPi, 1e-9);
  expect_turning_radius_respected(path, 5);
  for (const MapPose& at : path.poses) {
    const bool on_line = std::abs(at.position.y) < 1e-9 && at.position.x <= 20 + 1e-9;
    const bool on_circle =
        std::abs(distance(at.position, {20, 5}) - 5) < 1e-9 && at.position.x >= 20 - 1e-9;
    EXPECT_TRUE(on_line || on_circle) << "(" << at.position.x << ", " << at.position.y << ")";
  }
}

TEST(PathPlanner, UTurnNarrowerThanTheTurningCircleStillRespectsIt) {
  const auto request = request_through({pose(0, 0, 0), pose(0, 3, kPi)});
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_GT(path.length, 5 * kPi);
  expect_turning_radius_respected(path, 5);
}

TEST(PathPlanner, PassesEachWaypointExactlyWithItsHeading) {
  const auto request = request_through({pose(0, 0, 0), pose(30, 10, kPi / 2), pose(0, 40, kPi)}, 6);
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_GT(path.waypoint_at[1], 0u);
  EXPECT_LT(path.waypoint_at[1], path.poses.size() - 1);
  EXPECT_EQ(path.waypoint_at[2], path.poses.size() - 1);
  expect_turning_radius_respected(path, 6);
  for (std::int8_t direction : path.direction) EXPECT_EQ(direction, 1);
}

TEST(PathPlanner, ReversesOnlyWhenAllowed) {
  auto request = request_through({pose(0, 0, 0), pose(-3, 0, 0)});
  const PlannedPath forwards = plan_path(request);
  expect_consistent(forwards, request);
  for (std::int8_t direction : forwards.direction) EXPECT_EQ(direction, 1);
  EXPECT_GT(forwards.length, 2 * kPi * 5);
  expect_directions_match_motion(forwards);

  request.reversing_allowed = true;
  const PlannedPath backwards = plan_path(request);
  expect_consistent(backwards, request);
  EXPECT_NEAR(backwards.length, 3, 1e-9);
  for (std::int8_t direction : backwards.direction) EXPECT_EQ(direction, -1);
  expect_directions_match_motion(backwards);
}

TEST(PathPlanner, ReedsSheppManoeuvreHasACuspPoseAndMatchingDirections) {
  // Sideways by 2 m with the same heading: forwards and backwards manoeuvres with cusps.
  auto request = request_through({pose(0, 0, 0), pose(0, 2, 0)});
  request.reversing_allowed = true;
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  int flips = 0;
  for (std::size_t i = 0; i + 1 < path.direction.size(); ++i) {
    flips += path.direction[i] != path.direction[i + 1];
  }
  EXPECT_GE(flips, 1);
  expect_directions_match_motion(path);
  expect_turning_radius_respected(path, 5);
}

TEST(PathPlanner, AvoidsAnObstacleOnTheStraightLeg) {
  for (bool reversing : {false, true}) {
    SCOPED_TRACE(reversing ? "Reeds-Shepp" : "Dubins");
    auto request = request_through({pose(0, 0, 0), pose(40, 0, 0)});
    request.reversing_allowed = reversing;
    request.is_free = outside_disc({20, 0}, 4);
    request.seed = 7;
    const PlannedPath path = plan_path(request);
    expect_consistent(path, request);
    EXPECT_EQ(path.sampled_legs, 1);
    EXPECT_GT(path.length, 40);
    for (const MapPose& at : path.poses) {
      EXPECT_TRUE(request.is_free(at)) << "(" << at.position.x << ", " << at.position.y << ")";
    }
    expect_turning_radius_respected(path, 5);
    expect_directions_match_motion(path);
  }
}

TEST(PathPlanner, OnlyTheBlockedLegIsSampled) {
  auto request = request_through({pose(0, 0, 0), pose(40, 0, 0), pose(80, 0, 0)});
  request.is_free = outside_disc({60, 0}, 4);
  const PlannedPath path = plan_path(request);
  expect_consistent(path, request);
  EXPECT_EQ(path.sampled_legs, 1);
  EXPECT_NEAR(path.s[path.waypoint_at[1]], 40, 1e-9);
  for (const MapPose& at : path.poses) EXPECT_TRUE(request.is_free(at));
}

TEST(PathPlanner, SameSeedGivesBitIdenticalPlansOnAnyThread) {
  for (bool reversing : {false, true}) {
    SCOPED_TRACE(reversing ? "Reeds-Shepp" : "Dubins");
    auto request = request_through({pose(0, 0, 0), pose(40, 0, 0), pose(40, 30, kPi / 2)});
    request.reversing_allowed = reversing;
    request.is_free = [](const MapPose& at) {
      return distance(at.position, {20, 0}) > 4 && distance(at.position, {40, 15}) > 3;
    };
    request.seed = 12345;
    const PlannedPath serial = plan_path(request);
    EXPECT_EQ(serial.sampled_legs, 2);
    expect_identical(serial, plan_path(request));

    std::vector<PlannedPath> concurrent(4);
    std::vector<std::thread> threads;
    for (PlannedPath& result : concurrent) {
      threads.emplace_back([&request, &result] { result = plan_path(request); });
    }
    for (std::thread& thread : threads) thread.join();
    for (const PlannedPath& result : concurrent) expect_identical(serial, result);
  }
}

TEST(PathPlanner, RejectsAWaypointInsideAnObstacle) {
  auto request = request_through({pose(0, 0, 0), pose(20, 0, 0), pose(40, 0, 0)});
  request.is_free = outside_disc({20, 1}, 4);
  EXPECT_EQ(planning_error(request), "waypoint 2 at (20, 0) lies inside a static obstacle");
}

TEST(PathPlanner, ReportsAnEnclosedGoalAsUnplannable) {
  auto request = request_through({pose(0, 0, 0), pose(30, 0, 0), pose(60, 0, 0)});
  // A ring around the last waypoint: free inside and outside, never reachable.
  request.is_free = [](const MapPose& at) {
    const double from_goal = distance(at.position, {60, 0});
    return from_goal < 8 || from_goal > 10;
  };
  const std::string error = planning_error(request);
  EXPECT_NE(error.find("leg 2 (waypoint 2 -> 3): no path around the static obstacles found"),
            std::string::npos)
      << error;
}

TEST(PathPlanner, TightTimeLimitStillReturnsOrThrows) {
  auto request = request_through({pose(0, 0, 0), pose(40, 0, 0)});
  request.is_free = [](const MapPose& at) {
    const double from_goal = distance(at.position, {40, 0});
    return from_goal < 8 || from_goal > 10;
  };
  request.time_limit = 1e-3;
  EXPECT_NE(planning_error(request).find("leg 1 (waypoint 1 -> 2): no path"), std::string::npos);

  request.is_free = outside_disc({20, 0}, 4);
  try {
    const PlannedPath path = plan_path(request);
    for (const MapPose& at : path.poses) EXPECT_TRUE(request.is_free(at));
  } catch (const PlanningError& error) {
    EXPECT_NE(std::string(error.what()).find("leg 1"), std::string::npos);
  }
}

TEST(PathPlanner, RejectsDegenerateRequests) {
  EXPECT_EQ(planning_error(request_through({pose(0, 0, 0)})),
            "a path needs at least two waypoints, got 1");
  EXPECT_EQ(planning_error(request_through(
                {pose(0, 0, 0), pose(std::numeric_limits<double>::quiet_NaN(), 0, 0)})),
            "waypoint 2 has a non-finite position or heading");
  EXPECT_EQ(planning_error(request_through({pose(0, 0, 0), pose(10, 0, 0)}, 0)),
            "the turning radius must be positive and finite, got 0 m");
  auto request = request_through({pose(0, 0, 0), pose(10, 0, 0)});
  request.spacing = -1;
  EXPECT_EQ(planning_error(request), "the pose spacing must be positive and finite, got -1 m");
  request.spacing = 1e-9;
  EXPECT_NE(planning_error(request).find("leg 1 (waypoint 1 -> 2): the path is 10 m long"),
            std::string::npos);
}

TEST(PathPlanner, RepeatedWaypointAddsNoPose) {
  for (bool reversing : {false, true}) {
    auto request = request_through({pose(0, 0, 0), pose(10, 0, 0), pose(10, 0, 0)});
    request.reversing_allowed = reversing;
    const PlannedPath path = plan_path(request);
    expect_consistent(path, request);
    EXPECT_EQ(path.waypoint_at, (std::vector<std::size_t>{0, 20, 20}));
    EXPECT_NEAR(path.length, 10, 1e-9);
  }
}

TEST(PathPlanner, WrapsHeadingsOutsideMinusPiToPi) {
  const auto request = request_through({pose(0, 0, 2 * kPi), pose(20, 0, -2 * kPi)});
  const PlannedPath path = plan_path(request);
  EXPECT_NEAR(path.length, 20, 1e-9);
  EXPECT_NEAR(path.poses.front().heading, 0, 1e-12);
  EXPECT_NEAR(path.poses.back().heading, 0, 1e-12);
}

}  // namespace
}  // namespace scenfuzz
