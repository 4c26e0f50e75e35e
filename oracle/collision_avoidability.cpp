// Avoidability of a collision by braking (collision_avoidability.hpp): when the conflict began,
// and whether the ego braking at full from one response time later stays clear of the other.
#include "oracle/collision_avoidability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "oracle/pair_geometry.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

// Seconds between the poses of a prediction: a car at 30 m/s moves 3 m, less than its length.
constexpr double kPredictionStep = 0.1;

std::string shown(double value) { return format_number(std::round(value * 100) / 100); }

// A body carrying on from one sample: its speed changing at its acceleration down to a stop (never
// turning round), its heading at its turn rate.
struct CarryingOn {
  Footprint body;
  double velocity = 0;  // along the heading; negative reversing
  double acceleration = 0;
  double yaw_rate = 0;
};

CarryingOn carrying_on(const Trace& trace, ActorId actor, std::size_t i) {
  const TraceActor& a = trace.actors[actor];
  const double velocity = longitudinal_velocity_at(a.speed, a.reversing, i);
  const double towards_speed = velocity >= 0 ? a.acceleration[i] : -a.acceleration[i];
  return {footprint_at(trace, actor, i), velocity, towards_speed, a.yaw_rate[i]};
}

void advance(CarryingOn& b, double dt) {
  double next = b.velocity + b.acceleration * dt;
  if (b.velocity * next < 0 || (b.velocity == 0 && b.acceleration < 0)) next = 0;
  const double heading = b.body.heading + b.yaw_rate * dt / 2;
  const double moved = (b.velocity + next) / 2 * dt;
  b.body.centre.x += moved * std::cos(heading);
  b.body.centre.y += moved * std::sin(heading);
  b.body.heading += b.yaw_rate * dt;
  b.velocity = next;
}

// Whether the two, carrying on from sample i, touch within kConflictHorizon.
bool meet_carrying_on(const Trace& trace, ActorId a, ActorId b, std::size_t i) {
  CarryingOn first = carrying_on(trace, a, i), second = carrying_on(trace, b, i);
  for (double t = 0; t <= kConflictHorizon + 1e-9; t += kPredictionStep) {
    if (signed_distance(first.body, second.body) <= 0) return true;
    advance(first, kPredictionStep);
    advance(second, kPredictionStep);
  }
  return false;
}

// The first sample of the unbroken run of samples before `impact` from which the ego and `other`
// carrying on meet; `impact` itself when the sample before it already does not.
std::size_t conflict_onset(const Trace& trace, ActorId other, std::size_t impact) {
  std::size_t onset = impact;
  while (onset > 0 && present_at(trace.actors[other], onset - 1) &&
         meet_carrying_on(trace, kEgo, other, onset - 1))
    --onset;
  return onset;
}

// The path the ego drove, by arc length: where a braking ego would have been on it.
class DrivenPath {
 public:
  explicit DrivenPath(const TraceActor& ego) : ego_(ego), length_(ego.x.size(), 0.0) {
    for (std::size_t i = 1; i < length_.size(); ++i)
      length_[i] = length_[i - 1] + std::hypot(ego.x[i] - ego.x[i - 1], ego.y[i] - ego.y[i - 1]);
  }

  // Metres driven by `time` (samples dt apart), between samples linearly.
  double driven(double time, double dt) const {
    const double at = std::clamp(time / dt, 0.0, static_cast<double>(length_.size() - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(at), length_.size() - 1);
    if (i + 1 >= length_.size()) return length_[i];
    return length_[i] + (length_[i + 1] - length_[i]) * (at - static_cast<double>(i));
  }
  double driven_at(std::size_t sample) const { return length_[sample]; }

  // The body `driven` metres along the path, on from its last pose when beyond it.
  Footprint body_at(double driven, const Footprint& shape) const {
    const auto after = std::upper_bound(length_.begin(), length_.end(), driven);
    const std::size_t k =
        after == length_.begin() ? 0 : static_cast<std::size_t>(after - length_.begin()) - 1;
    Footprint body = shape;
    const double rest = driven - length_[k];
    if (k + 1 < length_.size() && length_[k + 1] > length_[k]) {
      const double f = rest / (length_[k + 1] - length_[k]);
      body.centre = {ego_.x[k] + (ego_.x[k + 1] - ego_.x[k]) * f,
                     ego_.y[k] + (ego_.y[k + 1] - ego_.y[k]) * f};
      body.heading = ego_.heading[k] + wrap_angle(ego_.heading[k + 1] - ego_.heading[k]) * f;
    } else {
      body.centre = {ego_.x[k] + rest * std::cos(ego_.heading[k]),
                     ego_.y[k] + rest * std::sin(ego_.heading[k])};
      body.heading = ego_.heading[k];
    }
    return body;
  }

 private:
  const TraceActor& ego_;
  std::vector<double> length_;  // metres driven by each sample
};

// Metres covered braking at `deceleration` from `speed` for `time` seconds, a stop included.
double braking_distance(double speed, double deceleration, double time) {
  const double stopping = speed / deceleration;
  const double t = std::min(time, stopping);
  return speed * t - deceleration * t * t / 2;
}

struct BrakingRun {
  double clearance = std::numeric_limits<double>::infinity();
  double stopped_at = 0;  // metres along the path where the braking ego ends
};

// The ego braking at `deceleration` from `brake_time` along its path, against `other` as it went.
BrakingRun brake_from(const Trace& trace, const DrivenPath& path, ActorId other, double brake_time,
                      double deceleration) {
  const TraceActor& ego = trace.actors[kEgo];
  const double start = path.driven(brake_time, trace.dt);
  const std::size_t before =
      std::min(static_cast<std::size_t>(brake_time / trace.dt), trace.sample_count() - 1);
  const double speed = ego.speed[before];
  BrakingRun run;
  const Footprint shape = footprint_at(trace, kEgo, 0);
  for (std::size_t j = before + 1; j < trace.sample_count(); ++j) {
    // Never further than it went: it may have braked as hard itself.
    const double driven =
        std::min(path.driven_at(j),
                 start + braking_distance(speed, deceleration, trace.time[j] - brake_time));
    run.stopped_at = driven;
    if (!present_at(trace.actors[other], j)) continue;
    run.clearance = std::min(
        run.clearance, signed_distance(path.body_at(driven, shape), footprint_at(trace, other, j)));
  }
  return run;
}

std::size_t impact_sample(const Trace& trace, const Collision& collision) {
  const auto sample = static_cast<std::size_t>(std::lround(collision.time / trace.dt));
  return std::min(sample, trace.sample_count() - 1);
}

}  // namespace

Avoidability collision_avoidability(const Trace& trace, std::size_t collision,
                                    const RssParameters& rss) {
  SCENFUZZ_DEMAND(collision < trace.collisions.size());
  const Collision& c = trace.collisions[collision];
  SCENFUZZ_DEMAND(c.first == kEgo || c.second == kEgo);
  const ActorId other = c.first == kEgo ? c.second : c.first;
  const std::string& name = trace.actors[other].name;
  const std::size_t impact = impact_sample(trace, c);

  Avoidability result;
  result.conflict_time = trace.time[conflict_onset(trace, other, impact)];
  result.brake_time = result.conflict_time + rss.response_time_ego;
  const std::string conflict = "the conflict with " + name + " began at " +
                               shown(result.conflict_time) + " s, " +
                               shown(c.time - result.conflict_time) + " s before the impact";
  if (result.brake_time >= c.time) {
    result.reason =
        conflict + ": less than the ego's " + shown(rss.response_time_ego) + " s response time";
    return result;
  }
  const double deceleration = actor_class(trace.actors[kEgo].category).max_deceleration;
  const DrivenPath path(trace.actors[kEgo]);
  const BrakingRun braking = brake_from(trace, path, other, result.brake_time, deceleration);
  result.avoidable = braking.clearance > 0;
  result.clearance = std::max(braking.clearance, 0.0);
  result.stop_short = std::max(0.0, path.driven_at(impact) - braking.stopped_at);
  result.reason = conflict + "; braking at full (" + shown(deceleration) + " m/s^2) from " +
                  shown(result.brake_time) + " s, after the ego's " + shown(rss.response_time_ego) +
                  " s response time, the ego " +
                  (result.avoidable
                       ? "stops " + shown(result.stop_short) + " m short of the impact and stays " +
                             shown(result.clearance) + " m clear of " + name
                       : "still meets " + name);
  return result;
}

}  // namespace scenfuzz
