// Feasible speed profiles: a feasible script kept (speeds at their points, at the same times),
// acceleration and jerk within the limits, bends slowed for, and what cannot be kept reported.
#include "physics/actors/speed_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/actors/trajectory.hpp"

namespace scenfuzz {
namespace {

constexpr MotionLimits kCar{.max_acceleration = 3.5,
                            .max_deceleration = 8,
                            .stop_deceleration = 3,
                            .max_jerk = 10,
                            .max_lateral_acceleration = 3};

Polyline straight_path(double length) {
  std::vector<MapPoint> points{{0, 0}, {length, 0}};
  return Polyline(points);
}

// Samples the trajectory every 0.05 s to its end and checks acceleration and jerk as a trace
// would record them.
void expect_within_limits(const Trajectory& trajectory, const MotionLimits& limits) {
  const double dt = 0.05;
  KinematicState previous = trajectory.state_at(0);
  double end = std::isfinite(trajectory.duration()) ? trajectory.duration() + 1 : 60;
  for (double t = dt; t <= end; t += dt) {
    KinematicState state = trajectory.state_at(t);
    ASSERT_LE(state.acceleration, limits.max_acceleration + 1e-9) << t;
    ASSERT_GE(state.acceleration, -limits.max_deceleration - 1e-9) << t;
    ASSERT_LE(std::abs(state.acceleration - previous.acceleration) / dt,
              limits.max_jerk * (1 + 1e-9))
        << t;
    ASSERT_LE(std::abs(state.speed - previous.speed) / dt, limits.max_deceleration + 1e-9) << t;
    previous = state;
  }
}

TEST(FeasibleProfile, AFeasibleScriptReachesItsSpeedsWhereAndWhenItSays) {
  Trajectory trajectory(straight_path(300), {{0, 5}, {50, 15}, {200, 10}}, kCar);
  EXPECT_TRUE(trajectory.shortfalls().empty());
  // 50 m at a mean 10 m/s: 5 s, as constant acceleration; then 150 m at a mean 12.5 m/s: 12 s.
  KinematicState at_first = trajectory.state_at(5);
  EXPECT_NEAR(at_first.x, 50, 1e-6);
  EXPECT_NEAR(at_first.speed, 15, 1e-6);
  EXPECT_NEAR(at_first.acceleration, 0, 1e-6) << "each point is reached without acceleration";
  KinematicState at_second = trajectory.state_at(17);
  EXPECT_NEAR(at_second.x, 200, 1e-6);
  EXPECT_NEAR(at_second.speed, 10, 1e-6);
  expect_within_limits(trajectory, kCar);
  // Stops at the end, braking at the comfortable deceleration at most.
  KinematicState end = trajectory.state_at(trajectory.duration());
  EXPECT_NEAR(end.x, 300, 1e-9);
  EXPECT_EQ(end.speed, 0);
  double hardest = 0;
  for (double t = 17; t < trajectory.duration(); t += 0.01)
    hardest = std::min(hardest, trajectory.state_at(t).acceleration);
  EXPECT_NEAR(hardest, -kCar.stop_deceleration, 1e-6);
}

TEST(FeasibleProfile, ALargeSpeedStepKeepsAccelerationAndJerkBounded) {
  Trajectory trajectory(straight_path(200), {{0, 2}, {20, 14}, {30, 0}, {60, 5}}, kCar);
  expect_within_limits(trajectory, kCar);
  EXPECT_FALSE(trajectory.shortfalls().empty());
}

TEST(FeasibleProfile, AnUnreachableSpeedIsReachedAsNearlyAsPossibleAndReported) {
  Trajectory trajectory(straight_path(200), {{0, 2}, {15, 20}}, kCar);
  ASSERT_EQ(trajectory.shortfalls().size(), 1u);
  const SpeedShortfall& shortfall = trajectory.shortfalls()[0];
  EXPECT_EQ(shortfall.point, 1u);
  EXPECT_EQ(shortfall.cause, ShortfallCause::acceleration);
  EXPECT_EQ(shortfall.wanted, 20);
  EXPECT_EQ(shortfall.other_point, 0u);
  EXPECT_NEAR(shortfall.other_speed, 2, 1e-12);
  // Without the jerk bound, 3.5 m/s^2 over 15 m would give sqrt(4 + 105) = 10.4 m/s.
  EXPECT_GT(shortfall.reached, 8);
  EXPECT_LT(shortfall.reached, 10.45);
  for (double t = 0; t < 10; t += 0.001) {
    KinematicState state = trajectory.state_at(t);
    if (state.x < 15) continue;
    EXPECT_NEAR(state.speed, shortfall.reached, 0.01);
    break;
  }
  expect_within_limits(trajectory, kCar);
}

TEST(FeasibleProfile, ASpeedThatCannotBeBrakedFromIsLoweredBeforeAndReported) {
  Trajectory trajectory(straight_path(200), {{0, 10}, {100, 20}, {105, 0}, {120, 0}}, kCar);
  ASSERT_EQ(trajectory.shortfalls().size(), 1u);
  const SpeedShortfall& shortfall = trajectory.shortfalls()[0];
  EXPECT_EQ(shortfall.point, 1u);
  EXPECT_EQ(shortfall.cause, ShortfallCause::braking);
  EXPECT_EQ(shortfall.other_point, 2u);
  EXPECT_LT(shortfall.reached, std::sqrt(2 * 8 * 5.0));
  EXPECT_TRUE(std::isinf(trajectory.duration()));
  EXPECT_NEAR(trajectory.state_at(1000).x, 105, 1e-9) << "it stops at the point that says so";
  expect_within_limits(trajectory, kCar);
}

TEST(FeasibleProfile, BendsAreTakenAtTheirSpeedAndBrakedFor) {
  // 100 m straight, a quarter circle of radius 20 m, 100 m straight; 15 m/s all along.
  std::vector<MapPoint> points;
  for (int i = 0; i <= 100; ++i) points.push_back({static_cast<double>(i), 0});
  for (int i = 1; i <= 60; ++i) {
    double angle = std::numbers::pi / 2 * i / 60;
    points.push_back({100 + 20 * std::sin(angle), 20 - 20 * std::cos(angle)});
  }
  for (int i = 1; i <= 100; ++i) points.push_back({120, 20.0 + i});
  Trajectory trajectory(Polyline(points), {{0, 15}}, kCar);
  EXPECT_TRUE(trajectory.shortfalls().empty());
  double largest_lateral = 0, slowest = 15;
  for (double t = 0; t < trajectory.duration(); t += 0.01) {
    KinematicState state = trajectory.state_at(t);
    largest_lateral = std::max(largest_lateral, state.speed * std::abs(state.yaw_rate));
    if (state.x > 105 && state.y < 15) slowest = std::min(slowest, state.speed);
  }
  EXPECT_LE(largest_lateral, kCar.max_lateral_acceleration * (1 + 1e-6));
  EXPECT_GT(slowest, 0.9 * std::sqrt(3.0 * 20)) << "not slower than the bend needs";
  EXPECT_NEAR(trajectory.state_at(2).speed, 15, 1e-9) << "full speed on the straight before";
  expect_within_limits(trajectory, kCar);
}

TEST(FeasibleProfile, RejectsLimitsThatAreNotPositive) {
  MotionLimits no_jerk = kCar;
  no_jerk.max_jerk = 0;
  EXPECT_THROW(Trajectory(straight_path(10), {{0, 5}}, no_jerk), std::invalid_argument);
  EXPECT_THROW(Trajectory(straight_path(10), {}, kCar), std::invalid_argument);
}

}  // namespace
}  // namespace scenfuzz
