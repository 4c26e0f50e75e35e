// Dangerous time and proper response on the samples of a trace. Measured responses get small
// allowances so that the simulation's discretisation and its limited jerk do not count as faults:
// 0.5 m/s^2 on accelerations, 10 % and 0.5 m/s on a braking's speed drop, 0.2 m/s sideways.
#include "oracle/rss_response.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "oracle/pair_geometry.hpp"
#include "oracle/right_of_way.hpp"
#include "oracle/rss_distances.hpp"

namespace scenfuzz {

namespace {

constexpr double kAccelerationAllowance = 0.5;  // m/s^2
constexpr double kBrakingShare = 0.9;           // of the owed speed drop
constexpr double kBrakingAllowance = 0.5;       // m/s of the owed speed drop
constexpr double kLateralAllowance = 0.2;       // m/s sideways
// A lane change has ended once both cars have kept to one lane, moving sideways towards each
// other slower than this, for this long.
constexpr double kSettledSideways = 0.1;  // m/s
constexpr double kSettleTime = 1;         // s

struct Safety {
  bool lon_safe = true;
  bool lat_safe = true;
  bool dangerous() const { return !lon_safe && !lat_safe; }
};

bool same_direction(const PairGeometry& g) { return std::cos(g.heading_difference) >= 0; }

double safe_longitudinal(const PairGeometry& g, const RssParameters& rss) {
  const double ego_rho = rss.response_time_ego;
  const double other_rho = rss.response_time_other;
  if (same_direction(g))
    return g.dx >= 0 ? rss_safe_longitudinal_same(g.reference_lon, g.other_lon, ego_rho, rss)
                     : rss_safe_longitudinal_same(g.other_lon, g.reference_lon, other_rho, rss);
  // Opposite directions: the ego is taken as the one on its lane's direction.
  return rss_safe_longitudinal_opposite(g.reference_lon * g.ahead(), ego_rho,
                                        -g.other_lon * g.ahead(), other_rho, rss);
}

Safety safety_at(const Trace& trace, const RoadMap& map, ActorId other, std::size_t i,
                 const RssParameters& rss) {
  const PairGeometry g = pair_geometry(trace, map, kEgo, other, i);
  const double lateral = rss_safe_lateral(g.reference_towards(), rss.response_time_ego,
                                          g.other_towards(), rss.response_time_other, rss);
  return {g.gap_lon > safe_longitudinal(g, rss), g.gap_lat > lateral};
}

std::size_t samples_in(const Trace& trace, double seconds) {
  return static_cast<std::size_t>(std::ceil(seconds / trace.dt - 1e-9));
}

// Braking owed by a rear (or oncoming) party: no more than accel_max within its response time,
// then at least `brake`.
void check_braking(const Trace& trace, ActorId actor, std::size_t from, std::size_t collision,
                   double brake, const RssParameters& rss, std::vector<ResponseViolation>& out) {
  const TraceActor& a = trace.actors[actor];
  const std::size_t respond = from + samples_in(trace, rss_response_time(actor, rss));
  for (std::size_t i = from + 1; i <= std::min(respond, collision); ++i)
    if (a.acceleration[i] > rss.accel_max + kAccelerationAllowance) {
      out.push_back({actor, ResponseFault::accelerated, i, a.acceleration[i], rss.accel_max});
      return;
    }
  if (braked_properly(trace, actor, from, collision, brake, rss)) return;
  const double span = trace.time[collision] - trace.time[respond];
  const double average = (a.speed[respond] - a.speed[collision]) / span;
  out.push_back({actor, ResponseFault::did_not_brake, respond, average, brake});
}

// A leader may brake up to brake_max and must not reverse into the one behind.
void check_leading(const Trace& trace, ActorId actor, std::size_t from, std::size_t collision,
                   const RssParameters& rss, std::vector<ResponseViolation>& out) {
  const TraceActor& a = trace.actors[actor];
  for (std::size_t i = from; i <= collision; ++i) {
    if (reversing_at(a.reversing, i) && a.speed[i] > kStandstillSpeed) {
      out.push_back({actor, ResponseFault::reversed, i, a.speed[i], 0});
      return;
    }
    if (-a.acceleration[i] > rss.brake_max + kAccelerationAllowance) {
      out.push_back({actor, ResponseFault::braked_hard, i, -a.acceleration[i], rss.brake_max});
      return;
    }
  }
}

double towards(const PairGeometry& g, ActorId actor) {
  return actor == kEgo ? g.reference_towards() : g.other_towards();
}

// Sideways: up to lateral_accel_max more towards the other within the response time, then
// braking at lateral_brake_min down to no sideways motion towards it.
void check_lateral(const Trace& trace, const RoadMap& map, ActorId other, ActorId actor,
                   std::size_t from, std::size_t collision, const RssParameters& rss,
                   std::vector<ResponseViolation>& out) {
  const double rho = rss_response_time(actor, rss);
  const double start = std::max(0.0, towards(pair_geometry(trace, map, kEgo, other, from), actor));
  bool previous_over = false;
  for (std::size_t i = from + 1; i <= collision; ++i) {
    const double t = trace.time[i] - trace.time[from];
    const double peak = start + rss.lateral_accel_max * std::min(t, rho);
    const double allowed =
        std::max(0.0, t <= rho ? peak : peak - rss.lateral_brake_min * (t - rho));
    const double u = towards(pair_geometry(trace, map, kEgo, other, i), actor);
    const bool over = u > allowed + kLateralAllowance;
    // Two samples in a row: one may be a lane's kink under the actor.
    if (over && previous_over) {
      out.push_back({actor, ResponseFault::moved_sideways, i - 1, u, allowed});
      return;
    }
    previous_over = over;
  }
}

// The first sample from which the pair has been in one lane, neither moving sideways towards
// the other, for kSettleTime: a lane change that ended with one car behind the other.
std::optional<std::size_t> lane_change_settled(const Trace& trace, const RoadMap& map,
                                               ActorId other, std::size_t from,
                                               std::size_t collision) {
  const std::size_t hold = samples_in(trace, kSettleTime);
  std::size_t calm = 0;
  for (std::size_t i = from; i < collision; ++i) {
    const PairGeometry g = pair_geometry(trace, map, kEgo, other, i);
    const std::int32_t lane = trace.actors[kEgo].lane[i];
    const bool settled = lane >= 0 && lane == trace.actors[other].lane[i] &&
                         std::abs(g.reference_towards()) < kSettledSideways &&
                         std::abs(g.other_towards()) < kSettledSideways;
    calm = settled ? calm + 1 : 0;
    if (calm >= hold) return i + 1 - hold;
  }
  return std::nullopt;
}

}  // namespace

double rss_response_time(ActorId actor, const RssParameters& rss) {
  return actor == kEgo ? rss.response_time_ego : rss.response_time_other;
}

BlameTime rss_blame_time(const Trace& trace, const RoadMap& map, ActorId other,
                         std::size_t collision_sample, const RssParameters& rss) {
  const std::size_t first = trace.actors[other].present_from;
  std::size_t b = collision_sample;
  while (b > first && safety_at(trace, map, other, b - 1, rss).dangerous()) --b;
  if (b == first && safety_at(trace, map, other, b, rss).dangerous())
    return {b, RssCase::from_start};
  if (b == first) return {b, RssCase::longitudinal};
  const Safety before = safety_at(trace, map, other, b - 1, rss);
  return {b, before.lon_safe ? RssCase::longitudinal : RssCase::lateral};
}

bool ego_is_behind(const Trace& trace, const RoadMap& map, ActorId other, std::size_t sample) {
  return pair_geometry(trace, map, kEgo, other, sample).dx >= 0;
}

bool opposite_directions(const Trace& trace, const RoadMap& map, ActorId other,
                         std::size_t sample) {
  return !same_direction(pair_geometry(trace, map, kEgo, other, sample));
}

bool braked_properly(const Trace& trace, ActorId actor, std::size_t from,
                     std::size_t collision_sample, double brake, const RssParameters& rss) {
  const TraceActor& a = trace.actors[actor];
  const std::size_t respond = from + samples_in(trace, rss_response_time(actor, rss));
  if (respond + 2 > collision_sample) return true;
  for (std::size_t i = respond; i <= collision_sample; ++i)
    if (a.speed[i] <= kStandstillSpeed) return true;
  const double span = trace.time[collision_sample] - trace.time[respond];
  const double drop = a.speed[respond] - a.speed[collision_sample];
  return drop >= kBrakingShare * brake * span - kBrakingAllowance;
}

std::vector<ResponseViolation> rss_improper_responses(const Trace& trace, const RoadMap& map,
                                                      ActorId other, const BlameTime& blame,
                                                      std::size_t collision_sample,
                                                      const RssParameters& rss) {
  std::vector<ResponseViolation> out;
  const std::size_t b = blame.sample;
  if (blame.which != RssCase::lateral) {
    if (opposite_directions(trace, map, other, b)) {
      check_braking(trace, kEgo, b, collision_sample, rss.brake_min_correct, rss, out);
      check_braking(trace, other, b, collision_sample, rss.brake_min_correct, rss, out);
    } else {
      const bool ego_behind = ego_is_behind(trace, map, other, b);
      const ActorId rear = ego_behind ? kEgo : other;
      const ActorId front = ego_behind ? other : kEgo;
      check_braking(trace, rear, b, collision_sample, rss.brake_min, rss, out);
      check_leading(trace, front, b, collision_sample, rss, out);
    }
  }
  if (blame.which != RssCase::longitudinal) {
    check_lateral(trace, map, other, kEgo, b, collision_sample, rss, out);
    check_lateral(trace, map, other, other, b, collision_sample, rss, out);
  }
  // A lane change that ended well before the impact with one car behind the other left a
  // longitudinal danger: from then on the rear car owes RSS's braking too (it had its response
  // time to see the car ahead), and the front one must not brake harder than RSS allows.
  if (blame.which == RssCase::lateral)
    if (const auto settled = lane_change_settled(trace, map, other, b, collision_sample)) {
      const bool ego_behind = ego_is_behind(trace, map, other, *settled);
      const ActorId rear = ego_behind ? kEgo : other;
      const ActorId front = ego_behind ? other : kEgo;
      check_braking(trace, rear, *settled, collision_sample, rss.brake_min, rss, out);
      check_leading(trace, front, *settled, collision_sample, rss, out);
    }
  return out;
}

}  // namespace scenfuzz
