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
// position for one that stands, into `points`, step after step; and the cosine and sine of every
// actor's heading (facings()). Most actors keep their heading
// from one step to the next (a lane follower on a straight segment, a walking pedestrian), so the
// cosine and sine of each actor's last heading are kept: the same numbers without a sincos.
class PointPredictor {
 public:
  void predict(std::span<const KinematicState> states, double horizon,
               std::vector<MapPoint>& points) {
    points.resize(states.size());
    if (headings_.size() != states.size()) {
      headings_.assign(states.size(), std::nan(""));  // equal to no heading: computed first time
      facings_.assign(states.size(), MapPoint{});
    }
    for (std::size_t k = 0; k < states.size(); ++k) {
      const KinematicState& state = states[k];
      if (!(state.heading == headings_[k])) {
        headings_[k] = state.heading;
        facings_[k] = {std::cos(state.heading), std::sin(state.heading)};
      }
      if (!(state.speed > kPredictedMinSpeed)) {
        points[k] = {state.x, state.y};
        continue;
      }
      // predicted_point's arithmetic, in its order.
      const double velocity = longitudinal_velocity(state);
      points[k] = {state.x + facings_[k].x * velocity * horizon,
                   state.y + facings_[k].y * velocity * horizon};
    }
  }

  // The cosine and sine of every actor's heading at the last predict (for LaneOccupancy).
  const std::vector<MapPoint>& facings() const { return facings_; }

 private:
  std::vector<double> headings_;   // of each actor when its cosine and sine were taken
  std::vector<MapPoint> facings_;  // their cosine and sine
};

// predicted_point(states[k], horizon) for every actor k that moves (kPredictedMinSpeed), and its
// position for one that stands, into `points` (reused from step to step).
inline void predict_points(std::span<const KinematicState> states, double horizon,
                           std::vector<MapPoint>& points) {
  PointPredictor().predict(states, horizon, points);
}

}  // namespace scenfuzz
