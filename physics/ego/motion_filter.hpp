// Smoothed velocities of perceived objects, by id: perception's speed and heading carry noise, so
// that a pedestrian standing still seems to drift a few centimetres a second in any direction.
// The reference driver tells standing from walking pedestrians by the smoothed speed, and asks
// it of nothing else: only pedestrians are tracked (a sine and cosine per vehicle a step spared).
#pragma once

#include <span>
#include <vector>

#include "physics/ego/perception.hpp"

namespace scenfuzz {

class MotionFilter {
 public:
  explicit MotionFilter(double time_constant = 0.5) : time_constant_(time_constant) {}

  // Folds in one step's pedestrians (objects sorted by id, as perception gives them; the others
  // are passed over) `dt` seconds after the previous call; pedestrians no longer seen are
  // forgotten.
  void update(std::span<const WorldObject> objects, double dt);

  // The smoothed speed of a pedestrian seen at the last update (0 for an unknown id, and for any
  // other object).
  double speed(ActorId id) const;

 private:
  struct Track {
    ActorId id = 0;
    double vx = 0, vy = 0;
  };
  double time_constant_;
  std::vector<Track> tracks_;  // sorted by id
  std::vector<Track> spare_;   // the previous tracks' storage, refilled by the next update
};

}  // namespace scenfuzz
