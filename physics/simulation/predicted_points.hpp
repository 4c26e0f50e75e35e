// Where an actor will be a few seconds on if it keeps its heading and speed: what a lane
// follower watches besides where the actor is (LaneFollower::in_path). Every follower looks at
// the same actors in a step, so the simulation shares one PointPredictor among them
// (WorldSnapshot::predictions) instead of a sine and cosine per follower and actor.
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

// Where each actor of a step will be (predicted_point), and the cosine and sine of its heading,
// worked out when first asked for: a lane follower asks for its own and its leader's at its looks
// only, the lane occupancy for everyone's at the steps somebody scans, so most actors at most
// steps need no sincos. Most actors keep their heading from one step to the next (a lane follower
// on a straight segment, a walking pedestrian), so the cosine and sine of each actor's last
// heading are kept: the same numbers without a sincos. Answers are cached in a const object
// (a step's view of the world is const); one simulation uses it from one thread.
class PointPredictor {
 public:
  // A new step: the actors' states, valid until the next call, and the prediction's horizon.
  void set_step(std::span<const KinematicState> states, double horizon) {
    states_ = states;
    horizon_ = horizon;
    if (headings_.size() != states.size()) {
      headings_.assign(states.size(), std::nan(""));  // equal to no heading: computed first time
      facings_.assign(states.size(), MapPoint{});
    }
  }

  std::size_t size() const { return states_.size(); }

  // The cosine and sine of actor k's heading.
  MapPoint facing(std::size_t k) const {
    const double heading = states_[k].heading;
    if (!(heading == headings_[k])) {
      headings_[k] = heading;
      facings_[k] = {std::cos(heading), std::sin(heading)};
    }
    return facings_[k];
  }

  // predicted_point(states[k], horizon) for an actor that moves (kPredictedMinSpeed), its
  // position for one that stands.
  MapPoint point(std::size_t k) const {
    const KinematicState& state = states_[k];
    if (!(state.speed > kPredictedMinSpeed)) return {state.x, state.y};
    // predicted_point's arithmetic, in its order.
    const MapPoint unit = facing(k);
    const double velocity = longitudinal_velocity(state);
    return {state.x + unit.x * velocity * horizon_, state.y + unit.y * velocity * horizon_};
  }

  // set_step, then every actor's point into `points`.
  void predict(std::span<const KinematicState> states, double horizon,
               std::vector<MapPoint>& points) {
    set_step(states, horizon);
    points.resize(states.size());
    for (std::size_t k = 0; k < states.size(); ++k) points[k] = point(k);
  }

 private:
  std::span<const KinematicState> states_;
  double horizon_ = 0;
  mutable std::vector<double> headings_;   // of each actor when its cosine and sine were taken
  mutable std::vector<MapPoint> facings_;  // their cosine and sine
};

// predicted_point(states[k], horizon) for every actor k that moves (kPredictedMinSpeed), and its
// position for one that stands, into `points` (reused from step to step).
inline void predict_points(std::span<const KinematicState> states, double horizon,
                           std::vector<MapPoint>& points) {
  PointPredictor().predict(states, horizon, points);
}

}  // namespace scenfuzz
