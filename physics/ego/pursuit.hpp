// Pure-pursuit steering onto the route's path shifted sideways by an overtaking plan: the
// reference driver's lateral control, a free function so that the overtaking manoeuvre can roll
// the same control forward to check a pull-out's swept path (pull_out_sweep.hpp).
#pragma once

#include "physics/actors/actor_class.hpp"
#include "physics/actors/kinematics.hpp"
#include "physics/ego/overtaking.hpp"
#include "physics/ego/route_tracker.hpp"

namespace scenfuzz {

// The front-wheel angle (unclamped) that steers the rear axle onto the arc through the point
// `lookahead` metres of path ahead of `progress`, shifted as `plan` has it there.
double pursuit_steering(const RouteTracker& route, const OvertakePlan& plan, double progress,
                        const KinematicState& ego, const ActorClass& vehicle, double lookahead);

}  // namespace scenfuzz
