// Vehicles after an impact (physics/simulation/impact_slide.hpp): an impulse along the struck
// face's normal, then a slide on locked wheels to a standstill where a uniform deceleration stops
// it, the body keeping its heading.
#include "physics/simulation/impact_slide.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace scenfuzz {
namespace {

TEST(ImpactSlide, ASideImpactPushesAlongTheNormalAndKeepsWhatRunsAlongTheFace) {
  // A 10 t truck at 10 m/s east hits the left side of a 1.5 t car driving north at 17 m/s.
  const double truck = impact_mass(ActorCategory::truck), car = impact_mass(ActorCategory::car);
  const MapPoint into_car = face_normal(std::numbers::pi / 2, BodySide::left);
  const auto [truck_after, car_after] =
      impact_velocities({{10, 0}, truck}, {{0, 17}, car}, {-into_car.x, -into_car.y});
  const double impulse = 1.2 * 10 * truck * car / (truck + car);
  EXPECT_NEAR(car_after.x, impulse / car, 1e-9);
  EXPECT_NEAR(car_after.y, 17, 1e-9);  // along the struck face: kept
  EXPECT_NEAR(truck_after.x, 10 - impulse / truck, 1e-9);
  EXPECT_NEAR(truck_after.y, 0, 1e-9);
  // Momentum is kept; the closing speed along the normal is reversed by the restitution.
  EXPECT_NEAR(truck * truck_after.x + car * car_after.x, truck * 10, 1e-6);
  EXPECT_NEAR(car_after.x - truck_after.x, kRestitution * 10, 1e-9);
}

TEST(ImpactSlide, BodiesAlreadyPartingAreLeftAsTheyWere) {
  const auto [a, b] = impact_velocities({{-1, 0}, 1500}, {{3, 0}, 1500}, {1, 0});
  EXPECT_DOUBLE_EQ(a.x, -1);
  EXPECT_DOUBLE_EQ(b.x, 3);
}

TEST(ImpactSlide, FaceNormalsPointOutOfTheBody) {
  const MapPoint left = face_normal(0, BodySide::left), rear = face_normal(0, BodySide::rear);
  EXPECT_NEAR(left.y, 1, 1e-12);
  EXPECT_NEAR(rear.x, -1, 1e-12);
}

TEST(ImpactSlide, AVelocityIsTheSpeedAlongTheHeadingOrAgainstItInReverse) {
  KinematicState state;
  state.heading = std::numbers::pi / 2;
  state.speed = 4;
  EXPECT_NEAR(velocity_of(state).y, 4, 1e-12);
  state.reversing = true;
  EXPECT_NEAR(velocity_of(state).y, -4, 1e-12);
}

TEST(ImpactSlide, ASlideStopsWhereAUniformDecelerationStopsAndKeepsTheHeading) {
  KinematicState state;
  state.heading = std::numbers::pi / 2;  // facing north
  MapPoint velocity{6, 8};               // sliding north-east at 10 m/s
  const double deceleration = 8, dt = 0.05;
  for (int i = 0; i < 100; ++i) state = slide_step(state, velocity, deceleration, dt);
  // v^2 / 2a = 6.25 m along (0.6, 0.8).
  EXPECT_NEAR(state.x, 6.25 * 0.6, 1e-9);
  EXPECT_NEAR(state.y, 6.25 * 0.8, 1e-9);
  EXPECT_DOUBLE_EQ(state.speed, 0);
  EXPECT_DOUBLE_EQ(state.heading, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(velocity.x, 0);
}

}  // namespace
}  // namespace scenfuzz
