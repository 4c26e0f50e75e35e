// A scripted actor's speed along its path over time: the speeds a scenario gives at points of the
// path, made into a profile that is continuous, finite wherever the actor moves, and (for the
// feasible kind) within its class's acceleration, braking, jerk and bend limits. The profile is
// time-parametrised once, when built: evaluating it is a binary search over its pieces.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "physics/actors/actor_class.hpp"

namespace scenfuzz {

// The actor's speed when its path reaches arc length s.
struct SpeedPoint {
  double s = 0;
  double speed = 0;
};

// What a feasible profile keeps to. All positive except max_lateral_acceleration (0: bends do not
// limit the speed, as for pedestrians, who turn on the spot).
struct MotionLimits {
  double max_acceleration = 0;   // m/s^2, speeding up
  double max_deceleration = 0;   // m/s^2, braking
  double stop_deceleration = 0;  // m/s^2 it brakes with to stop at the path's end and for bends
  double max_jerk = 0;           // m/s^3, how fast the acceleration changes
  double max_lateral_acceleration = 0;  // m/s^2 in bends: speed^2 x |curvature|
};

// A class's limits for scripted motion, cornering at up to `lateral_acceleration` and braking at
// its comfortable deceleration for bends and its path's end.
MotionLimits class_motion_limits(const ActorClass& actor_class, double lateral_acceleration);

// A stretch of path with a constant |curvature| (1/m), for the bend limit.
struct PathBend {
  double s_begin = 0;
  double s_end = 0;
  double curvature = 0;
};

enum class ShortfallCause {
  bend,          // the bend at the point allows no more
  acceleration,  // the distance from the point before is too short to speed up that much
  braking,       // the actor must slow down for what lies ahead (a slower point, a bend, the end)
};

// A given speed point the actor cannot keep to, and the nearest it does.
struct SpeedShortfall {
  std::size_t point = 0;  // index in the speed points as given
  double s = 0;           // its arc length
  double wanted = 0;      // m/s the script asks for
  double reached = 0;     // m/s the actor has there
  ShortfallCause cause = ShortfallCause::bend;
  // acceleration: the point before (its arc length, the speed the actor has there); braking: the
  // point after that forces the slowing down.
  double other_s = 0;
  double other_speed = 0;
  std::optional<std::size_t> other_point;  // its index among the given points, if given
};

// The motion along the path at one time.
struct ProfileState {
  double s = 0;
  double speed = 0;
  double acceleration = 0;
};

class SpeedProfile {
 public:
  // Pieces of constant jerk: from time[i] on, at s[i] with speed[i], acceleration[i] and jerk[i].
  // A piece that starts at an infinite time is never reached (the actor stands for ever before it).
  struct Knots {
    std::vector<double> time, s, speed, acceleration, jerk;
  };
  SpeedProfile() = default;
  explicit SpeedProfile(Knots knots);

  // At time t >= 0: O(log pieces). Past the end: the last knot's s, standing.
  ProfileState at(double t) const;
  double duration() const;  // time the last knot is reached (infinite if never)
  bool empty() const { return knots_.time.empty(); }

 private:
  Knots knots_;
};

// The profile of the speed points as given: constant acceleration between consecutive points,
// the last speed held up to where braking at `stop_deceleration` stops the actor at `length`
// (braking harder, from the last point, when that is too close to the end). `speeds` sorted by
// s, the first at s = 0. Throws std::invalid_argument for an empty list, speeds out of order or
// negative, or a deceleration that is not positive.
SpeedProfile constant_acceleration_profile(std::vector<SpeedPoint> speeds, double length,
                                           double stop_deceleration);

struct FeasibleProfile {
  SpeedProfile profile;
  std::vector<SpeedShortfall> shortfalls;  // by point
};

// The nearest profile to the speed points that the limits allow: each point's speed reached there
// with zero acceleration, by a symmetric jerk-limited change that takes the whole stretch from the
// point before (so, where that is feasible, the point is reached when the constant-acceleration
// profile reaches it); slower in bends (speed <= sqrt(max_lateral_acceleration / curvature)),
// braking into them and speeding up after them at stop_deceleration (harder, up to the limits,
// where there is no room), and stopping at the path's end. Speeds the limits do not allow are
// lowered (never raised: the start too, if the actor could not brake in time from its initial
// speed) and reported. Throws std::invalid_argument as constant_acceleration_profile does, and
// for limits that are not positive.
FeasibleProfile feasible_profile(std::vector<SpeedPoint> speeds, double length,
                                 std::span<const PathBend> bends, const MotionLimits& limits);

}  // namespace scenfuzz
