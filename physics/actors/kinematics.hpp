// How actors move from one step to the next: the kinematic bicycle model for vehicles and a
// point mass for pedestrians. Both integrate exactly for inputs held constant over the step.
#pragma once

#include "physics/actors/actor_class.hpp"

namespace scenfuzz {

// The state of one actor at one instant. (x, y) is the body centre in the map frame.
struct KinematicState {
  double x = 0;
  double y = 0;
  double heading = 0;         // rad, counter-clockwise from east
  double speed = 0;           // m/s along the heading, never negative
  double acceleration = 0;    // m/s^2, the longitudinal acceleration applied over the last step
  double yaw_rate = 0;        // rad/s over the last step
  double steering_angle = 0;  // rad, front wheel, positive left; vehicles only
};

// What a driver asks for; the model clamps it to the actor class's limits.
struct VehicleControl {
  double acceleration = 0;    // m/s^2, negative brakes
  double steering_angle = 0;  // rad, front wheel, positive left
};

// One step of the kinematic bicycle model with the reference point at the body centre
// (rear axle wheelbase/2 behind it): acceleration clamped to [-max_deceleration,
// max_acceleration], the steering angle moves towards the request at most max_steering_rate*dt
// and stays within max_steering_angle, speed stays in [0, max_speed] (a braking vehicle stops
// rather than reverses).
KinematicState step_bicycle(const KinematicState& state, const VehicleControl& control,
                            const ActorClass& vehicle, double dt);

// What a pedestrian wants: walk at `speed` towards `heading`.
struct PedestrianControl {
  double heading = 0;
  double speed = 0;
};

// One step of a point mass that turns on the spot and changes speed within the class's limits.
KinematicState step_pedestrian(const KinematicState& state, const PedestrianControl& control,
                               const ActorClass& pedestrian, double dt);

}  // namespace scenfuzz
