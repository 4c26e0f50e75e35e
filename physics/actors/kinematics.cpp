// Exact one-step integration of the kinematic bicycle model and the pedestrian point mass. The
// inputs are held constant over a step, so the speed is piecewise linear in time (it may reach
// 0, the speed limit or the requested speed part-way) and a vehicle's centre moves along a
// circular arc: both have closed forms, which keeps the result independent of the step size.
#include "physics/actors/kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "lang/demand.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

// The speed at the end of a step that starts at `speed` and accelerates at `acceleration`
// until it reaches `bound` (a speed limit, 0, or a requested speed), and the distance covered.
struct SpeedProfile {
  double end_speed = 0;
  double distance = 0;
  double acceleration = 0;  // the mean over the step: less than asked when a bound is reached
};

SpeedProfile accelerate_towards(double speed, double acceleration, double bound, double dt) {
  const double unbounded = speed + acceleration * dt;
  const bool passes_bound = acceleration > 0 ? unbounded > bound : unbounded < bound;
  if (acceleration == 0 || !passes_bound) {
    return {unbounded, (speed + unbounded) / 2 * dt, acceleration};
  }
  const double time_to_bound = (bound - speed) / acceleration;
  return {bound, (speed + bound) / 2 * time_to_bound + bound * (dt - time_to_bound),
          (bound - speed) / dt};
}

// The chord of an arc of length `distance` turning by `turn`, over the distance: 1 for a
// straight line. The series avoids 0/0 when the arc is nearly straight.
double chord_ratio(double turn) {
  const double half = turn / 2;
  if (std::abs(half) < 1e-4) return 1 - half * half / 6;
  return std::sin(half) / half;
}

// Moves (x, y) along an arc of length `distance` that starts in direction `direction` and turns
// by `turn` on the way; a negative distance runs the arc backwards.
void move_along_arc(KinematicState& state, double direction, double distance, double turn) {
  const double chord = distance * chord_ratio(turn);
  const double chord_direction = direction + turn / 2;
  state.x += chord * std::cos(chord_direction);
  state.y += chord * std::sin(chord_direction);
}

}  // namespace

double step_yaw_rate(double heading_before, double heading_after, double dt) {
  SCENFUZZ_DEMAND(dt > 0);
  return angle_difference(heading_after, heading_before) / dt;
}

KinematicState step_bicycle(const KinematicState& state, const VehicleControl& control,
                            const ActorClass& vehicle, double dt) {
  SCENFUZZ_DEMAND(dt > 0);
  SCENFUZZ_DEMAND(vehicle.wheelbase > 0);
  KinematicState next = state;

  const double max_angle = vehicle.max_steering_angle;
  const double requested_angle = std::clamp(control.steering_angle, -max_angle, max_angle);
  const double max_change = vehicle.max_steering_rate * dt;
  next.steering_angle =
      std::clamp(state.steering_angle +
                     std::clamp(requested_angle - state.steering_angle, -max_change, max_change),
                 -max_angle, max_angle);

  // A state from elsewhere (a scenario's initial speed) may lie outside the class's limits.
  const double speed = std::clamp(state.speed, 0.0, vehicle.max_speed);
  const double acceleration =
      std::clamp(control.acceleration, -vehicle.max_deceleration, vehicle.max_acceleration);
  const SpeedProfile profile =
      accelerate_towards(speed, acceleration, acceleration > 0 ? vehicle.max_speed : 0.0, dt);

  const bool backwards = speed > 0 ? state.reversing : control.reverse;
  // Reversing runs the same arc the other way: the heading turns the other way for the same
  // steering, as a car's does.
  const double travelled = backwards ? -profile.distance : profile.distance;

  const double rear_to_centre = vehicle.wheelbase / 2;
  const double slip = std::atan(rear_to_centre / vehicle.wheelbase * std::tan(next.steering_angle));
  const double turn = travelled * std::sin(slip) / rear_to_centre;
  move_along_arc(next, state.heading + slip, travelled, turn);

  next.heading = angle_difference(state.heading + turn, 0);
  next.speed = profile.end_speed;
  next.reversing = backwards && profile.end_speed > 0;
  next.acceleration = profile.acceleration;
  // step_yaw_rate's value (a step turns far less than half a turn), without the rounding of
  // wrapping the heading and taking the difference back.
  next.yaw_rate = turn / dt;
  return next;
}

KinematicState step_pedestrian(const KinematicState& state, const PedestrianControl& control,
                               const ActorClass& pedestrian, double dt) {
  SCENFUZZ_DEMAND(dt > 0);
  KinematicState next = state;
  const double speed = std::clamp(state.speed, 0.0, pedestrian.max_speed);
  const double requested = std::clamp(control.speed, 0.0, pedestrian.max_speed);
  const double acceleration =
      requested > speed ? pedestrian.max_acceleration : -pedestrian.max_deceleration;
  const SpeedProfile profile = requested == speed
                                   ? SpeedProfile{speed, speed * dt, 0}
                                   : accelerate_towards(speed, acceleration, requested, dt);

  next.heading = angle_difference(control.heading, 0);
  next.x += profile.distance * std::cos(next.heading);
  next.y += profile.distance * std::sin(next.heading);
  next.speed = profile.end_speed;
  next.acceleration = profile.acceleration;
  next.yaw_rate = step_yaw_rate(state.heading, next.heading, dt);
  next.steering_angle = 0;
  next.reversing = false;  // a pedestrian turns to face where it walks
  return next;
}

}  // namespace scenfuzz
