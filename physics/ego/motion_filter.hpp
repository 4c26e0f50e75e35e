// Smoothed velocities of perceived objects, by id: perception's speed and heading carry noise, so
// that a pedestrian standing still seems to drift a few centimetres a second in any direction.
// The reference driver tells standing from walking pedestrians by the smoothed speed, and whether
// a vehicle beside its path is moving into it by the smoothed velocity: a heading error of a few
// degrees on a fast oncoming car is a lateral speed enough to seem to swerve. A vehicle's heading
// is smoothed too (averaged as a unit vector, so across +-pi), for where a slow or oncoming
// vehicle's body lies. Obstacles are not tracked (they stand).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/ego/perception.hpp"

namespace scenfuzz {

class MotionFilter {
 public:
  struct Velocity {
    double x = 0, y = 0;  // m/s along the map's axes
  };

  explicit MotionFilter(double time_constant = 0.5) : time_constant_(time_constant) {}

  // Folds in one step's pedestrians and vehicles (objects sorted by id, as perception gives them;
  // obstacles are passed over) `dt` seconds after the previous call; those no longer seen are
  // forgotten.
  void update(std::span<const WorldObject> objects, double dt);

  // The smoothed speed of a pedestrian or vehicle seen at the last update (0 for an unknown id,
  // and for an obstacle).
  double speed(ActorId id) const;
  // Its smoothed velocity (none for an unknown id or an obstacle).
  std::optional<Velocity> velocity(ActorId id) const;
  // A vehicle's smoothed heading (none for an unknown id, a pedestrian or an obstacle): heading
  // noise of 3 degrees swings a 12 m bus's corner 0.3 m sideways.
  std::optional<double> heading(ActorId id) const;

  // The standard deviation of a smoothed velocity component over that of one step's, for
  // independent noise from step to step and steps of `dt` s (1 without smoothing).
  double noise_reduction(double dt) const;

 private:
  struct Track {
    ActorId id = 0;
    double vx = 0, vy = 0;
    double hx = 0, hy = 0;  // the smoothed heading's unit vector (0, 0: none)
  };
  const Track* find(ActorId id) const;

  double time_constant_;
  std::vector<Track> tracks_;  // sorted by id
  std::vector<Track> spare_;   // the previous tracks' storage, refilled by the next update
};

}  // namespace scenfuzz
