// Speed profiles: the plain constant-acceleration one, and the feasible one (bend caps inserted as
// extra points, backward and forward passes for braking and acceleration, then a symmetric
// jerk-limited change between consecutive points).
#include "physics/actors/speed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace scenfuzz {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Points closer than this are one point.
constexpr double kSameS = 1e-9;
// Curving stretches whose caps bind and lie closer than this form one bend, taken at one speed:
// a bend sampled as many short arcs is not driven as a staircase of speeds.
constexpr double kBendJoinGap = 1.0;
// A speed this far below the script's is a shortfall worth reporting (rounding is not).
constexpr double kShortfallTolerance = 1e-3;

struct CheckedPoint {
  double s = 0;
  double speed = 0;
  std::size_t given = 0;  // index in the speed points as given
};

// Speed points checked, sorted, clamped to the path and with repeated arc lengths merged (the
// later speed wins), so that every interval between them has a positive length.
std::vector<CheckedPoint> checked_speed_points(const std::vector<SpeedPoint>& speeds,
                                               double length) {
  if (speeds.empty()) throw std::invalid_argument("trajectory needs at least one speed point");
  std::vector<CheckedPoint> checked;
  double previous_s = 0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const SpeedPoint& point = speeds[i];
    if (!std::isfinite(point.s) || !std::isfinite(point.speed) || point.speed < 0)
      throw std::invalid_argument("trajectory speed points need finite s and speed >= 0");
    if (point.s < previous_s)
      throw std::invalid_argument("trajectory speed points must be sorted by s from s = 0");
    previous_s = point.s;
    double s = std::min(point.s, length);
    if (!checked.empty() && s - checked.back().s <= kSameS)
      checked.back() = {checked.back().s, point.speed, i};
    else
      checked.push_back({s, point.speed, i});
  }
  if (checked.front().s > kSameS)
    throw std::invalid_argument("trajectory speed points must start at s = 0");
  checked.front().s = 0;
  return checked;
}

bool positive(double value) { return value > 0 && std::isfinite(value); }

}  // namespace

MotionLimits class_motion_limits(const ActorClass& actor_class, double lateral_acceleration) {
  return {.max_acceleration = actor_class.max_acceleration,
          .max_deceleration = actor_class.max_deceleration,
          .stop_deceleration = actor_class.comfortable_deceleration,
          .max_jerk = actor_class.max_jerk,
          .max_lateral_acceleration = lateral_acceleration};
}

SpeedProfile::SpeedProfile(Knots knots) : knots_(std::move(knots)) {}

double SpeedProfile::duration() const { return knots_.time.empty() ? 0 : knots_.time.back(); }

ProfileState SpeedProfile::at(double t) const {
  const Knots& k = knots_;
  if (k.time.empty()) return {};
  t = std::max(t, 0.0);
  if (t >= k.time.back()) return {k.s.back(), 0, 0};
  // The piece [knot i, knot i + 1) containing t; a knot at infinite time is never reached.
  auto after = std::upper_bound(k.time.begin(), k.time.end(), t);
  std::size_t i = static_cast<std::size_t>(after - k.time.begin()) - 1;
  double e = t - k.time[i];
  double v0 = k.speed[i], a0 = k.acceleration[i], j = k.jerk[i];
  ProfileState state;
  state.acceleration = a0 + j * e;
  state.speed = std::max(0.0, v0 + a0 * e + j * e * e / 2);
  state.s = std::clamp(k.s[i] + v0 * e + a0 * e * e / 2 + j * e * e * e / 6, k.s[i], k.s[i + 1]);
  return state;
}

SpeedProfile constant_acceleration_profile(std::vector<SpeedPoint> speeds, double length,
                                           double stop_deceleration) {
  if (!positive(stop_deceleration))
    throw std::invalid_argument("trajectory stop deceleration must be positive");
  std::vector<CheckedPoint> points = checked_speed_points(speeds, length);
  // The last given speed holds to where braking at stop_deceleration stops the actor at the end;
  // if the last point is too close to the end for that, braking starts at the last point.
  const CheckedPoint last = points.back();
  if (last.s < length) {
    double braking_distance = last.speed * last.speed / (2 * stop_deceleration);
    double braking_start = length - braking_distance;
    if (last.speed > 0 && braking_start > last.s) points.push_back({braking_start, last.speed, 0});
    points.push_back({length, 0, 0});
  }
  SpeedProfile::Knots knots;
  double time = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) {
      double speed_sum = points[i - 1].speed + points[i].speed;
      // Standing still between two points: the actor never gets past the first.
      time = speed_sum > 0 ? time + 2 * (points[i].s - points[i - 1].s) / speed_sum : kInfinity;
    }
    knots.time.push_back(time);
    knots.s.push_back(points[i].s);
    knots.speed.push_back(points[i].speed);
    knots.jerk.push_back(0);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    double acceleration = 0;
    if (i + 1 < points.size() && std::isfinite(knots.time[i + 1])) {
      double v0 = points[i].speed, v1 = points[i + 1].speed;
      acceleration = (v1 * v1 - v0 * v0) / (2 * (points[i + 1].s - points[i].s));
    }
    knots.acceleration.push_back(acceleration);
  }
  return SpeedProfile(std::move(knots));
}

namespace {

// Time of a symmetric jerk-limited speed change by dv (zero acceleration at both ends, the
// acceleration ramping at `jerk` up to at most `acceleration`).
double change_time(double dv, double acceleration, double jerk) {
  dv = std::abs(dv);
  if (dv * jerk >= acceleration * acceleration) return dv / acceleration + acceleration / jerk;
  return 2 * std::sqrt(dv / jerk);
}

// Distance of that change from v0 to v1: the mean speed is their mean (the change is symmetric).
double change_distance(double v0, double v1, double acceleration, double jerk) {
  return 0.5 * (v0 + v1) * change_time(v1 - v0, acceleration, jerk);
}

// The highest speed reachable from `from` within `distance` (or, backwards, the highest speed
// from which `from` is reachable by braking): change_distance grows with the speed.
double fastest_change(double from, double distance, double acceleration, double jerk) {
  if (distance <= 0) return from;
  double low = from;
  double high = from + std::sqrt(2 * acceleration * distance);  // without the jerk bound
  for (int i = 0; i < 100 && high - low > 1e-12 * std::max(1.0, high); ++i) {
    double middle = 0.5 * (low + high);
    (change_distance(from, middle, acceleration, jerk) <= distance ? low : high) = middle;
  }
  return low;
}

// The script: the given speeds with constant acceleration between them (v^2 linear in s), the
// last one held to the end.
class Script {
 public:
  explicit Script(const std::vector<CheckedPoint>& points) : points_(points) {}
  double speed_at(double s) const {
    auto after = std::upper_bound(points_.begin(), points_.end(), s,
                                  [](double value, const CheckedPoint& p) { return value < p.s; });
    if (after == points_.begin()) return points_.front().speed;
    const CheckedPoint& before = *(after - 1);
    if (after == points_.end()) return before.speed;
    double fraction = (s - before.s) / (after->s - before.s);
    double v0 = before.speed, v1 = after->speed;
    return std::sqrt(std::max(0.0, v0 * v0 + (v1 * v1 - v0 * v0) * fraction));
  }
  double highest(double from, double to) const {
    double highest = std::max(speed_at(from), speed_at(to));
    for (const CheckedPoint& p : points_)
      if (p.s > from && p.s < to) highest = std::max(highest, p.speed);
    return highest;
  }

 private:
  const std::vector<CheckedPoint>& points_;
};

// A point of the plan: a given speed point, a bend's edge, or where braking for a bend (or the
// path's end) starts or speeding up after a bend ends.
struct PlanPoint {
  double s = 0;
  double wanted = 0;  // m/s: the script's speed, capped by bends
  std::optional<std::size_t> given;
  double speed = 0;  // after the passes
  ShortfallCause cause = ShortfallCause::bend;
  std::size_t other = 0;  // the plan point that limits it (acceleration, braking)
};

// A stretch whose speed is capped.
struct Cap {
  double s_begin = 0;
  double s_end = 0;
  double speed = 0;
};

class Plan {
 public:
  Plan(const std::vector<CheckedPoint>& given, const Script& script, const MotionLimits& limits)
      : script_(script), limits_(limits) {
    for (const CheckedPoint& p : given) points_.push_back({p.s, p.speed, p.given});
  }

  // Whether the profile could be faster than `cap` anywhere on its stretch: the speed between
  // two plan points stays between theirs, so every interval touching the stretch counts.
  bool binds(const Cap& cap) const {
    auto [first, last] = touching(cap.s_begin, cap.s_end);
    for (std::size_t i = first; i <= last; ++i)
      if (points_[i].wanted > cap.speed + 1e-9) return true;
    return false;
  }

  // Caps the stretch, with room to brake before it and to speed up after it.
  void apply(const Cap& cap) {
    for (PlanPoint& p : points_)
      if (p.s >= cap.s_begin - kSameS && p.s <= cap.s_end + kSameS)
        p.wanted = std::min(p.wanted, cap.speed);
    double entry = ceiling(cap.s_begin), exit = ceiling(cap.s_end);
    std::size_t begin = insert(cap.s_begin, cap.speed);
    std::size_t end = insert(cap.s_end, cap.speed);
    const double calm_acceleration = std::min(limits_.max_acceleration, limits_.stop_deceleration);
    if (entry > cap.speed && begin > 0) {
      double at = cap.s_begin -
                  change_distance(cap.speed, entry, limits_.stop_deceleration, limits_.max_jerk);
      if (at > points_[begin - 1].s + kSameS) insert(at, ceiling(at));
    }
    end = index_at(cap.s_end);
    if (exit > cap.speed && end + 1 < points_.size()) {
      double at = cap.s_end + change_distance(cap.speed, exit, calm_acceleration, limits_.max_jerk);
      if (at < points_[end + 1].s - kSameS) insert(at, ceiling(at));
    }
  }

  // Backward (braking) then forward (speeding up) passes: each only lowers speeds.
  void pass() {
    for (PlanPoint& p : points_) p.speed = p.wanted;
    const double jerk = limits_.max_jerk;
    for (std::size_t i = points_.size() - 1; i-- > 0;) {
      double room = points_[i + 1].s - points_[i].s;
      double most = fastest_change(points_[i + 1].speed, room, limits_.max_deceleration, jerk);
      if (points_[i].speed > most) {
        points_[i].speed = most;
        points_[i].cause = ShortfallCause::braking;
        points_[i].other = i + 1;
      }
    }
    for (std::size_t i = 1; i < points_.size(); ++i) {
      double room = points_[i].s - points_[i - 1].s;
      double most = fastest_change(points_[i - 1].speed, room, limits_.max_acceleration, jerk);
      if (points_[i].speed > most) {
        points_[i].speed = most;
        points_[i].cause = ShortfallCause::acceleration;
        points_[i].other = i - 1;
      }
    }
  }

  const std::vector<PlanPoint>& points() const { return points_; }

 private:
  // Indices of the plan points from the last before `from` to the first after `to`.
  std::pair<std::size_t, std::size_t> touching(double from, double to) const {
    std::size_t first = 0, last = points_.size() - 1;
    for (std::size_t i = 0; i < points_.size(); ++i) {
      if (points_[i].s < from - kSameS) first = i;
      if (points_[i].s > to + kSameS) {
        last = i;
        break;
      }
    }
    return {first, last};
  }

  // The most a new point at s may ask for: the script's speed there, and no more than the points
  // around it (so a new point never raises what the profile may do where a cap was checked).
  double ceiling(double s) const {
    auto [first, last] = touching(s, s);
    double around = 0;
    for (std::size_t i = first; i <= last; ++i) around = std::max(around, points_[i].wanted);
    return std::min(script_.speed_at(s), around);
  }

  std::size_t index_at(double s) const {
    std::size_t i = 0;
    while (i + 1 < points_.size() && points_[i].s < s - kSameS) ++i;
    return i;
  }

  std::size_t insert(double s, double wanted) {
    auto at = std::lower_bound(points_.begin(), points_.end(), s - kSameS,
                               [](const PlanPoint& p, double value) { return p.s < value; });
    if (at != points_.end() && at->s <= s + kSameS) {
      at->wanted = std::min(at->wanted, wanted);
      return static_cast<std::size_t>(at - points_.begin());
    }
    PlanPoint point;
    point.s = s;
    point.wanted = wanted;
    // The insertion may reallocate: the index is taken from the iterator it returns.
    auto inserted = points_.insert(at, point);
    return static_cast<std::size_t>(inserted - points_.begin());
  }

  const Script& script_;
  const MotionLimits& limits_;
  std::vector<PlanPoint> points_;
};

// Bend stretches as caps: binding stretches near each other joined into one bend at the lowest
// cap among them, the others kept as they are (they may bind once points are added).
std::vector<Cap> bend_caps(std::span<const PathBend> bends, const Script& script,
                           double lateral_acceleration) {
  std::vector<Cap> caps;
  if (lateral_acceleration <= 0) return caps;
  bool joining = false;
  for (const PathBend& bend : bends) {
    if (!(bend.curvature > 1e-9) || !(bend.s_end >= bend.s_begin)) continue;
    Cap cap{bend.s_begin, bend.s_end, std::sqrt(lateral_acceleration / bend.curvature)};
    bool binding = cap.speed < script.highest(cap.s_begin, cap.s_end);
    if (binding && joining && cap.s_begin - caps.back().s_end <= kBendJoinGap) {
      caps.back().s_end = std::max(caps.back().s_end, cap.s_end);
      caps.back().speed = std::min(caps.back().speed, cap.speed);
      continue;
    }
    caps.push_back(cap);
    joining = binding;
  }
  std::sort(caps.begin(), caps.end(),
            [](const Cap& a, const Cap& b) { return a.s_begin < b.s_begin; });
  return caps;
}

// Appends the symmetric jerk-limited change from (s0, v0) to (s1, v1) starting at `time`, and
// returns when it ends: it takes the time constant acceleration would, 2 (s1 - s0) / (v0 + v1).
double append_change(SpeedProfile::Knots& knots, double time, double s0, double v0, double s1,
                     double v1, double jerk) {
  auto add = [&](double t, double s, double v, double a, double j) {
    knots.time.push_back(t);
    knots.s.push_back(s);
    knots.speed.push_back(v);
    knots.acceleration.push_back(a);
    knots.jerk.push_back(j);
  };
  double total = 2 * (s1 - s0) / (v0 + v1);
  double dv = std::abs(v1 - v0);
  if (dv <= 1e-12) {
    add(time, s0, v0, 0, 0);
    return time + total;
  }
  double sign = v1 > v0 ? 1 : -1;
  // The peak acceleration p solves dv / p + p / jerk = total (the smaller root, stably).
  double root = std::sqrt(std::max(0.0, jerk * jerk * total * total - 4 * jerk * dv));
  double peak = 2 * jerk * dv / (jerk * total + root);
  double ramp = peak / jerk;
  double hold = std::max(0.0, total - 2 * ramp);
  add(time, s0, v0, 0, sign * jerk);
  double v = v0 + sign * peak * ramp / 2;
  double s = s0 + v0 * ramp + sign * jerk * ramp * ramp * ramp / 6;
  add(time + ramp, s, v, sign * peak, 0);
  s += v * hold + sign * peak * hold * hold / 2;
  v += sign * peak * hold;
  add(time + ramp + hold, std::min(s, s1), v, sign * peak, -sign * jerk);
  return time + total;
}

SpeedProfile profile_of(const std::vector<PlanPoint>& points, double jerk) {
  SpeedProfile::Knots knots;
  double time = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const PlanPoint &from = points[i], &to = points[i + 1];
    if (from.speed + to.speed <= 0) {
      // Standing still between two points: the actor never gets past the first.
      knots.time.insert(knots.time.end(), {time, kInfinity});
      knots.s.insert(knots.s.end(), {from.s, to.s});
      knots.speed.insert(knots.speed.end(), {0, 0});
      knots.acceleration.insert(knots.acceleration.end(), {0, 0});
      knots.jerk.insert(knots.jerk.end(), {0, 0});
      return SpeedProfile(std::move(knots));
    }
    time = append_change(knots, time, from.s, from.speed, to.s, to.speed, jerk);
  }
  knots.time.push_back(time);
  knots.s.push_back(points.back().s);
  knots.speed.push_back(points.back().speed);
  knots.acceleration.push_back(0);
  knots.jerk.push_back(0);
  return SpeedProfile(std::move(knots));
}

std::vector<SpeedShortfall> shortfalls_of(const std::vector<PlanPoint>& points,
                                          const std::vector<SpeedPoint>& given, double length) {
  std::vector<SpeedShortfall> shortfalls;
  for (const PlanPoint& p : points) {
    // Every actor stops at its path's end: a speed given there is not a shortfall.
    if (!p.given || p.s >= length - kSameS) continue;
    double wanted = given[*p.given].speed;
    if (p.speed >= wanted - kShortfallTolerance) continue;
    SpeedShortfall shortfall;
    shortfall.point = *p.given;
    shortfall.s = p.s;
    shortfall.wanted = wanted;
    shortfall.reached = p.speed;
    shortfall.cause = p.cause;
    if (p.cause != ShortfallCause::bend) {
      const PlanPoint& other = points[p.other];
      shortfall.other_s = other.s;
      shortfall.other_speed = other.speed;
      shortfall.other_point = other.given;
    }
    shortfalls.push_back(shortfall);
  }
  return shortfalls;
}

}  // namespace

FeasibleProfile feasible_profile(std::vector<SpeedPoint> speeds, double length,
                                 std::span<const PathBend> bends, const MotionLimits& limits) {
  if (!positive(limits.max_acceleration) || !positive(limits.max_deceleration) ||
      !positive(limits.stop_deceleration) || !positive(limits.max_jerk) ||
      !(limits.max_lateral_acceleration >= 0))
    throw std::invalid_argument("trajectory limits must be positive");
  std::vector<CheckedPoint> given = checked_speed_points(speeds, length);
  Script script(given);
  Plan plan(given, script, limits);
  for (const Cap& cap : bend_caps(bends, script, limits.max_lateral_acceleration))
    if (plan.binds(cap)) plan.apply(cap);
  plan.apply({length, length, 0});  // the actor stops at its path's end
  plan.pass();
  FeasibleProfile result;
  result.profile = profile_of(plan.points(), limits.max_jerk);
  result.shortfalls = shortfalls_of(plan.points(), speeds, length);
  return result;
}

}  // namespace scenfuzz
