// The kinematic models against their closed forms: straight motion, constant acceleration,
// braking to a stop, circles at constant steering, and the class limits.
#include "physics/actors/kinematics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

constexpr double kDt = 0.05;
constexpr double kPi = std::numbers::pi;

const ActorClass& car() { return actor_class(ActorCategory::car); }

KinematicState drive(KinematicState state, const VehicleControl& control, int steps,
                     const ActorClass& vehicle = car()) {
  for (int i = 0; i < steps; ++i) state = step_bicycle(state, control, vehicle, kDt);
  return state;
}

TEST(KinematicsBicycle, ConstantSpeedStraight) {
  KinematicState state{.speed = 10};
  state = drive(state, {}, 200);
  EXPECT_NEAR(state.x, 10 * 200 * kDt, 1e-9);
  EXPECT_NEAR(state.y, 0, 1e-12);
  EXPECT_NEAR(state.heading, 0, 1e-12);
  EXPECT_DOUBLE_EQ(state.speed, 10);
  EXPECT_DOUBLE_EQ(state.acceleration, 0);
  EXPECT_DOUBLE_EQ(state.yaw_rate, 0);
}

TEST(KinematicsBicycle, StraightAlongAnyHeading) {
  KinematicState state{.x = 3, .y = -2, .heading = 2.0, .speed = 7};
  state = drive(state, {}, 40);
  const double distance = 7 * 40 * kDt;
  EXPECT_NEAR(state.x, 3 + distance * std::cos(2.0), 1e-9);
  EXPECT_NEAR(state.y, -2 + distance * std::sin(2.0), 1e-9);
  EXPECT_NEAR(state.heading, 2.0, 1e-12);
}

TEST(KinematicsBicycle, ConstantAccelerationFromRest) {
  const double a = 2.0;
  const int steps = 60;
  const KinematicState state = drive({}, {.acceleration = a}, steps);
  const double t = steps * kDt;
  EXPECT_NEAR(state.x, a * t * t / 2, 1e-9);
  EXPECT_NEAR(state.speed, a * t, 1e-9);
  EXPECT_NEAR(state.acceleration, a, 1e-9);
}

TEST(KinematicsBicycle, BrakingStopsAtTheClosedFormDistanceAndNeverReverses) {
  const double v0 = 13, b = 5;  // stops after 2.6 s, within a step (not on a step boundary)
  KinematicState state{.speed = v0};
  double previous_x = 0;
  for (int i = 0; i < 100; ++i) {
    state = step_bicycle(state, {.acceleration = -b}, car(), 0.07);
    EXPECT_GE(state.speed, 0);
    EXPECT_GE(state.x, previous_x - 1e-12);
    previous_x = state.x;
  }
  EXPECT_EQ(state.speed, 0);
  EXPECT_NEAR(state.x, v0 * v0 / (2 * b), 1e-9);
  EXPECT_NEAR(state.y, 0, 1e-12);
  EXPECT_EQ(state.acceleration, 0);  // standing still: the brake no longer decelerates
}

TEST(KinematicsBicycle, TheStoppingStepReportsTheActualDeceleration) {
  const KinematicState state =
      step_bicycle({.speed = 1}, {.acceleration = -5}, car(), 0.5);  // stops after 0.2 s
  EXPECT_EQ(state.speed, 0);
  EXPECT_NEAR(state.x, 0.1, 1e-12);
  EXPECT_NEAR(state.acceleration, -1 / 0.5, 1e-12);
}

TEST(KinematicsBicycle, ReverseGearSetsOffBackwardsFacingTheSameWay) {
  const double a = 2, heading = 0.5;
  const int steps = 40;  // 2 s
  KinematicState state = drive({.heading = heading}, {.acceleration = a, .reverse = true}, steps);
  const double t = steps * kDt;
  EXPECT_TRUE(state.reversing);
  EXPECT_NEAR(state.speed, a * t, 1e-9) << "the speed stays a magnitude";
  EXPECT_NEAR(state.acceleration, a, 1e-9);
  EXPECT_NEAR(longitudinal_velocity(state), -a * t, 1e-9);
  EXPECT_NEAR(state.x, -a * t * t / 2 * std::cos(heading), 1e-9);
  EXPECT_NEAR(state.y, -a * t * t / 2 * std::sin(heading), 1e-9);
  EXPECT_NEAR(state.heading, heading, 1e-12);

  // Braking stops it where the closed form says, backwards, and it stays there.
  const double x_before = state.x;
  const double b = 5;
  state = drive(state, {.acceleration = -b, .reverse = true}, 40);
  EXPECT_EQ(state.speed, 0);
  EXPECT_FALSE(state.reversing) << "no direction at a standstill";
  EXPECT_NEAR(state.x - x_before, -(a * t) * (a * t) / (2 * b) * std::cos(heading), 1e-9);
}

TEST(KinematicsBicycle, TheDirectionChangesOnlyAtAStandstill) {
  // Moving forwards, reverse gear does not make it go backwards: it brakes to a stop first.
  KinematicState state =
      step_bicycle({.speed = 5}, {.acceleration = 2, .reverse = true}, car(), kDt);
  EXPECT_FALSE(state.reversing);
  EXPECT_GT(state.x, 0);
  // Reversing, a forward gear keeps it reversing until it stands.
  KinematicState backing{.speed = 3, .reversing = true};
  backing = step_bicycle(backing, {.acceleration = 1}, car(), kDt);
  EXPECT_TRUE(backing.reversing);
  EXPECT_LT(backing.x, 0);
  EXPECT_NEAR(backing.speed, 3 + kDt, 1e-12);
}

// The centre of curvature for a centre point moving in direction heading + beta on a circle of
// radius R = l_r / sin(beta), turning left for positive beta.
MapPoint curvature_centre(const KinematicState& state, double slip, double radius) {
  const double direction = state.heading + slip;
  return {state.x - radius * std::sin(direction), state.y + radius * std::cos(direction)};
}

TEST(KinematicsBicycle, ConstantSteeringDrivesACircle) {
  const ActorClass& vehicle = car();
  const double steering = 0.2;
  const double rear_to_centre = vehicle.wheelbase / 2;
  const double slip = std::atan(rear_to_centre / vehicle.wheelbase * std::tan(steering));
  const double radius = rear_to_centre / std::sin(slip);
  const double speed = 8;

  KinematicState state{.speed = speed, .steering_angle = steering};
  const MapPoint centre = curvature_centre(state, slip, radius);
  // A full turn in whole steps: pick dt so the circumference is covered in exactly 400 steps.
  const int steps = 400;
  const double dt = 2 * kPi * radius / speed / steps;
  for (int i = 0; i < steps; ++i) {
    state = step_bicycle(state, {.steering_angle = steering}, vehicle, dt);
    const MapPoint now = curvature_centre(state, slip, radius);
    ASSERT_NEAR(now.x, centre.x, 1e-9) << "step " << i;
    ASSERT_NEAR(now.y, centre.y, 1e-9) << "step " << i;
    ASSERT_NEAR(std::hypot(state.x - centre.x, state.y - centre.y), radius, 1e-9);
    ASSERT_NEAR(state.yaw_rate, speed * std::sin(slip) / rear_to_centre, 1e-9);
  }
  EXPECT_NEAR(angle_difference(state.heading, 0), 0, 1e-9);
  EXPECT_NEAR(state.x, 0, 1e-8);
  EXPECT_NEAR(state.y, 0, 1e-8);
}

TEST(KinematicsBicycle, ReversingWithTheWheelTurnedRunsTheSameCircleTheOtherWay) {
  const ActorClass& vehicle = car();
  const double steering = 0.2;
  const double rear_to_centre = vehicle.wheelbase / 2;
  const double slip = std::atan(rear_to_centre / vehicle.wheelbase * std::tan(steering));
  const double radius = rear_to_centre / std::sin(slip);
  KinematicState state{.speed = 4, .steering_angle = steering, .reversing = true};
  const MapPoint centre = curvature_centre(state, slip, radius);
  for (int i = 0; i < 100; ++i) {
    state = step_bicycle(state, {.steering_angle = steering, .reverse = true}, vehicle, kDt);
    const MapPoint now = curvature_centre(state, slip, radius);
    ASSERT_NEAR(now.x, centre.x, 1e-9) << "step " << i;
    ASSERT_NEAR(now.y, centre.y, 1e-9) << "step " << i;
  }
  // Wheel to the left, backing up: the nose swings right, the car goes round clockwise.
  EXPECT_NEAR(state.yaw_rate, -4 * std::sin(slip) / rear_to_centre, 1e-9);
  EXPECT_LT(state.heading, 0);
  EXPECT_LT(state.x, 0);
}

TEST(KinematicsBicycle, CircleDoesNotDependOnTheStepSize) {
  const VehicleControl control{.steering_angle = -0.3};
  KinematicState coarse{.speed = 12, .steering_angle = -0.3};
  KinematicState fine = coarse;
  for (int i = 0; i < 10; ++i) coarse = step_bicycle(coarse, control, car(), 0.1);
  for (int i = 0; i < 100; ++i) fine = step_bicycle(fine, control, car(), 0.01);
  EXPECT_NEAR(coarse.x, fine.x, 1e-9);
  EXPECT_NEAR(coarse.y, fine.y, 1e-9);
  EXPECT_NEAR(coarse.heading, fine.heading, 1e-9);
  EXPECT_LT(coarse.heading, 0);  // negative steering turns right
}

TEST(KinematicsBicycle, FullLockCircleHasTheMinimumTurningRadius) {
  for (const ActorClass& vehicle : actor_classes()) {
    if (vehicle.category == ActorCategory::pedestrian) continue;
    SCOPED_TRACE(std::string(vehicle.name));
    const double lock = vehicle.max_steering_angle;
    KinematicState state{.speed = 3, .steering_angle = lock};
    std::vector<MapPoint> points;
    for (int i = 0; i < 3; ++i) {
      state = drive(state, {.steering_angle = 10.0}, 7, vehicle);  // request beyond the lock
      EXPECT_DOUBLE_EQ(state.steering_angle, lock);
      points.push_back({state.x, state.y});
    }
    // The circumscribed circle of three points on the path.
    const auto [a, b, c] = std::tuple{points[0], points[1], points[2]};
    const double ab = distance(a, b), bc = distance(b, c), ca = distance(c, a);
    const double area2 = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    EXPECT_NEAR(ab * bc * ca / (2 * area2), vehicle.min_turning_radius(), 1e-6);
  }
}

TEST(KinematicsBicycle, SteeringRateIsLimited) {
  const ActorClass& vehicle = car();
  KinematicState state{.speed = 5};
  const double step_limit = vehicle.max_steering_rate * kDt;
  for (int i = 1; i <= 5; ++i) {
    state = step_bicycle(state, {.steering_angle = 0.5}, vehicle, kDt);
    EXPECT_NEAR(state.steering_angle, std::min(0.5, i * step_limit), 1e-12);
  }
  state = drive(state, {.steering_angle = 0.5}, 100);
  EXPECT_DOUBLE_EQ(state.steering_angle, 0.5);
  state = step_bicycle(state, {.steering_angle = -0.5}, vehicle, kDt);
  EXPECT_NEAR(state.steering_angle, 0.5 - step_limit, 1e-12);
}

TEST(KinematicsBicycle, LimitsClamp) {
  const ActorClass& vehicle = car();
  KinematicState state = step_bicycle({.speed = 10}, {.acceleration = 100}, vehicle, kDt);
  EXPECT_DOUBLE_EQ(state.acceleration, vehicle.max_acceleration);
  state = step_bicycle({.speed = 10}, {.acceleration = -100}, vehicle, kDt);
  EXPECT_DOUBLE_EQ(state.acceleration, -vehicle.max_deceleration);
  state = drive({.speed = vehicle.max_speed - 0.01}, {.acceleration = 3}, 20);
  EXPECT_DOUBLE_EQ(state.speed, vehicle.max_speed);
  EXPECT_DOUBLE_EQ(state.acceleration, 0);
  state = drive({}, {.steering_angle = -3}, 100);
  EXPECT_DOUBLE_EQ(state.steering_angle, -vehicle.max_steering_angle);
}

TEST(KinematicsBicycle, ReachingTheSpeedLimitMidStepIsExact) {
  const ActorClass& vehicle = car();
  const double v0 = vehicle.max_speed - 1;  // reaches the limit after 1/3.5 s
  const KinematicState state =
      step_bicycle({.speed = v0}, {.acceleration = vehicle.max_acceleration}, vehicle, 1.0);
  const double ramp = 1 / vehicle.max_acceleration;
  EXPECT_DOUBLE_EQ(state.speed, vehicle.max_speed);
  EXPECT_NEAR(state.x, (v0 + vehicle.max_speed) / 2 * ramp + vehicle.max_speed * (1 - ramp), 1e-9);
  EXPECT_NEAR(state.acceleration, 1.0, 1e-12);
}

TEST(KinematicsPedestrian, StraightWalk) {
  const ActorClass& walker = actor_class(ActorCategory::pedestrian);
  KinematicState state{.heading = 0.3, .speed = 1.4};
  for (int i = 0; i < 100; ++i) {
    state = step_pedestrian(state, {.heading = kPi / 2, .speed = 1.4}, walker, kDt);
  }
  EXPECT_NEAR(state.heading, kPi / 2, 1e-12);
  EXPECT_NEAR(state.x, 0, 1e-9);
  EXPECT_NEAR(state.y, 1.4 * 100 * kDt, 1e-9);
  EXPECT_DOUBLE_EQ(state.speed, 1.4);
}

TEST(KinematicsPedestrian, TurnsAtOnceAndChangesSpeedWithinLimits) {
  const ActorClass& walker = actor_class(ActorCategory::pedestrian);
  KinematicState state = step_pedestrian({}, {.heading = kPi, .speed = 10}, walker, kDt);
  EXPECT_NEAR(state.heading, kPi, 1e-12);
  EXPECT_NEAR(state.yaw_rate, kPi / kDt, 1e-9);
  EXPECT_NEAR(state.speed, walker.max_acceleration * kDt, 1e-12);
  EXPECT_NEAR(state.x, -walker.max_acceleration * kDt * kDt / 2, 1e-12);
  for (int i = 0; i < 200; ++i) {
    state = step_pedestrian(state, {.heading = kPi, .speed = 10}, walker, kDt);
  }
  EXPECT_DOUBLE_EQ(state.speed, walker.max_speed);
  // Slowing to 1 m/s takes (3 - 1) / max_deceleration and then holds.
  const double x_before = state.x;
  const double t_slow = (walker.max_speed - 1) / walker.max_deceleration;
  state = step_pedestrian(state, {.heading = kPi, .speed = 1}, walker, 1.0);
  EXPECT_DOUBLE_EQ(state.speed, 1);
  EXPECT_NEAR(x_before - state.x, (walker.max_speed + 1) / 2 * t_slow + (1 - t_slow), 1e-9);
  EXPECT_NEAR(state.acceleration, -(walker.max_speed - 1), 1e-12);
}

}  // namespace
}  // namespace scenfuzz
