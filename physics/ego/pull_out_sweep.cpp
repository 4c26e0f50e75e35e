// The swept path of a pull-out (pull_out_sweep.hpp).
#include "physics/ego/pull_out_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/collision/footprint.hpp"
#include "physics/ego/pursuit.hpp"

namespace scenfuzz {
namespace {

constexpr double kRollStep = 0.05;     // s, the simulation's default step
constexpr double kLongestRoll = 20;    // s: a pull-out not past the blocker by then is not made
constexpr double kMinimumSpeed = 0.1;  // m/s, keeps the free-road term finite

Footprint footprint_of(const KinematicState& state, const ActorClass& vehicle) {
  return {{state.x, state.y}, state.heading, vehicle.length / 2, vehicle.width / 2, false};
}

Footprint footprint_of(const WorldObject& object) {
  return {{object.x, object.y}, object.heading, object.length / 2, object.width / 2, false};
}

// The driver's free-road acceleration (IDM without a lead): what it pulls out with, the blocker
// being off its shifted path.
double free_acceleration(const OvertakeContext& context, double speed) {
  double ratio = speed / std::max(context.desired_speed, kMinimumSpeed);
  return context.comfortable_acceleration * (1 - ratio * ratio * ratio * ratio);
}

}  // namespace

double pull_out_clearance(const OvertakeContext& context, const OvertakePlan& plan,
                          const Blocker& blocker, double margin) {
  const ActorClass& vehicle = context.vehicle;
  const RouteTracker& route = context.route;
  const Footprint standing = footprint_of(*blocker.object);
  KinematicState state = context.ego;
  double s = route.progress();
  double least = std::numeric_limits<double>::infinity();
  for (double t = 0; t < kLongestRoll; t += kRollStep) {
    if (s - vehicle.length / 2 > blocker.front_s + margin) return least;
    double lookahead = std::max(context.min_lookahead, context.lookahead_time * state.speed);
    if (plan.pull_out_lookahead > 0 && s < plan.out_end) lookahead = plan.pull_out_lookahead;
    double steer = std::clamp(pursuit_steering(route, plan, s, state, vehicle, lookahead),
                              -vehicle.max_steering_angle, vehicle.max_steering_angle);
    double path_heading = route.heading_at(s);
    state =
        step_bicycle(state, {free_acceleration(context, state.speed), steer}, vehicle, kRollStep);
    // Progress along the path: the travel's component along it (the path is near straight over
    // a pull-out's few metres).
    s += state.speed * kRollStep * std::cos(angle_difference(state.heading, path_heading));
    least = std::min(least, signed_distance(footprint_of(state, vehicle), standing));
  }
  return -std::numeric_limits<double>::infinity();
}

}  // namespace scenfuzz
