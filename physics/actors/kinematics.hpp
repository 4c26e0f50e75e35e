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
  double speed = 0;           // m/s, a magnitude: never negative, whichever way the actor moves
  double acceleration = 0;    // m/s^2 over the last step: how fast `speed` grew (negative: braking)
  double yaw_rate = 0;        // rad/s over the last step (step_yaw_rate)
  double steering_angle = 0;  // rad, front wheel, positive left; vehicles only
  // Moving backwards, against its heading (a vehicle in reverse): the body keeps facing the way
  // it did, so footprints and the sides a collision hits stay right. Never set at a standstill.
  bool reversing = false;
};

// The trace's yaw rate convention: the yaw rate recorded with a state is its heading's change
// since the state one step of `dt` before (wrapped to (-pi, pi]) over `dt`, so that a trace's
// yaw rate is its heading's derivative sample by sample. Every actor's motion records it so.
double step_yaw_rate(double heading_before, double heading_after, double dt);

// The velocity along the heading: the speed, negative while reversing.
inline double longitudinal_velocity(const KinematicState& state) {
  return state.reversing ? -state.speed : state.speed;
}

// What a driver asks for; the model clamps it to the actor class's limits.
struct VehicleControl {
  double acceleration = 0;    // m/s^2 on the speed, either way it moves; negative brakes
  double steering_angle = 0;  // rad, front wheel, positive left
  bool reverse = false;       // reverse gear: from a standstill, set off backwards
};

// One step of the kinematic bicycle model with the reference point at the body centre
// (rear axle wheelbase/2 behind it): acceleration clamped to [-max_deceleration,
// max_acceleration], the steering angle moves towards the request at most max_steering_rate*dt
// and stays within max_steering_angle, speed stays in [0, max_speed] (a braking vehicle stops
// rather than reverses). The direction of travel changes only at a standstill, as a gearbox
// allows: a vehicle at rest sets off backwards when `control.reverse` asks for it, and a moving
// one keeps its direction whatever the gear until it has braked to a stop.
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
