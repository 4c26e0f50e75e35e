// Vehicles after an impact (impact_slide.hpp).
#include "physics/simulation/impact_slide.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scenfuzz {

double impact_mass(ActorCategory category) {
  switch (category) {
    case ActorCategory::car: return 1500;
    case ActorCategory::van: return 2500;
    case ActorCategory::bus: return 12000;
    case ActorCategory::truck: return 10000;  // a loaded medium box truck
    case ActorCategory::bicycle: return 90;   // with its rider, as the others with theirs
    case ActorCategory::motorbicycle: return 250;
    case ActorCategory::tricycle: return 300;
    case ActorCategory::pedestrian: return 75;
  }
  return 1500;
}

MapPoint velocity_of(const KinematicState& state) {
  const double speed = state.reversing ? -state.speed : state.speed;
  return {speed * std::cos(state.heading), speed * std::sin(state.heading)};
}

MapPoint face_normal(double heading, BodySide side) {
  const double angle = side == BodySide::front  ? heading
                       : side == BodySide::left ? heading + std::numbers::pi / 2
                       : side == BodySide::rear ? heading + std::numbers::pi
                                                : heading - std::numbers::pi / 2;
  return {std::cos(angle), std::sin(angle)};
}

std::pair<MapPoint, MapPoint> impact_velocities(const ImpactBody& a, const ImpactBody& b,
                                                MapPoint normal) {
  const double closing =
      (a.velocity.x - b.velocity.x) * normal.x + (a.velocity.y - b.velocity.y) * normal.y;
  if (closing <= 0) return {a.velocity, b.velocity};
  const double impulse = (1 + kRestitution) * closing * a.mass * b.mass / (a.mass + b.mass);
  return {{a.velocity.x - impulse / a.mass * normal.x, a.velocity.y - impulse / a.mass * normal.y},
          {b.velocity.x + impulse / b.mass * normal.x, b.velocity.y + impulse / b.mass * normal.y}};
}

KinematicState slide_step(const KinematicState& state, MapPoint& velocity, double deceleration,
                          double dt) {
  const double speed = std::hypot(velocity.x, velocity.y);
  const double slower = std::max(0.0, speed - deceleration * dt);
  // The distance at the step's mean speed, so that a slide stops where a uniform deceleration does.
  const double mean = speed > 0 ? (speed + slower) / 2 / speed : 0;
  KinematicState next = state;
  next.x += velocity.x * mean * dt;
  next.y += velocity.y * mean * dt;
  next.speed = slower;
  next.acceleration = (slower - speed) / dt;
  next.yaw_rate = 0;
  next.steering_angle = 0;
  next.reversing = false;
  const double scale = speed > 0 ? slower / speed : 0;
  velocity = {velocity.x * scale, velocity.y * scale};
  return next;
}

}  // namespace scenfuzz
