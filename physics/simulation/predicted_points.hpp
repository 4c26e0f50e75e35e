// Where an actor will be a few seconds on if it keeps its heading and speed: what a lane
// follower watches besides where the actor is (LaneFollower::in_path). Every follower looks at
// the same actors in a step, so the simulation computes these once per step for all of them
// (WorldSnapshot::predicted) instead of a sine and cosine per follower and actor.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

// m/s: an actor slower than this is taken to stand where it is (nothing is predicted for it).
constexpr double kPredictedMinSpeed = 0.1;

// The point `horizon` seconds ahead of `state` along its heading, at its speed (backwards when
// reversing).
inline MapPoint predicted_point(const KinematicState& state, double horizon) {
  const double velocity = longitudinal_velocity(state);
  return {state.x + std::cos(state.heading) * velocity * horizon,
          state.y + std::sin(state.heading) * velocity * horizon};
}

// predicted_point(states[k], horizon) for every actor k that moves (kPredictedMinSpeed), and its
// position for one that stands, into `points` (reused from step to step).
inline void predict_points(std::span<const KinematicState> states, double horizon,
                           std::vector<MapPoint>& points) {
  points.resize(states.size());
  for (std::size_t k = 0; k < states.size(); ++k)
    points[k] = states[k].speed > kPredictedMinSpeed ? predicted_point(states[k], horizon)
                                                     : MapPoint{states[k].x, states[k].y};
}

}  // namespace scenfuzz
