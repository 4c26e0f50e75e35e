// The trace audit: one pass over each actor's columns per check, and the collisions between
// actors other than the ego.
#include "oracle/trace_audit.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "lang/demand.hpp"
#include "physics/actors/friction_circle.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {
namespace {

// The samples of one actor that failed one check: the first, the worst, how many.
struct Failures {
  std::size_t samples = 0;
  std::size_t first = 0;
  std::size_t worst = 0;
  double worst_excess = 0;  // how far beyond the limit, in the check's unit
  double worst_value = 0;
  double worst_limit = 0;

  void add(std::size_t i, double value, double limit, double excess) {
    if (samples == 0) first = i;
    if (samples == 0 || excess > worst_excess) {
      worst = i;
      worst_excess = excess;
      worst_value = value;
      worst_limit = limit;
    }
    ++samples;
  }
};

// The samples [begin, end) the actor is on the map: background traffic comes and goes, and is
// audited only while there.
struct Presence {
  std::size_t begin = 0, end = 0;
};

Presence presence(const Trace& trace, const TraceActor& actor) {
  const std::size_t end = std::min(actor.present_until, trace.sample_count());
  return {std::min(actor.present_from, end), end};
}

// `value` beyond `limit` by more than rounding.
bool exceeds(double value, double limit) {
  return value > limit + kAuditThresholds.relative_tolerance * std::max(1.0, std::abs(limit));
}

AuditIssue issue_of(const Trace& trace, ActorId actor, AuditKind kind, const Failures& failures) {
  AuditIssue issue;
  issue.actor = actor;
  issue.actor_name = trace.actors[actor].name;
  issue.kind = kind;
  issue.time = trace.time[failures.first];
  issue.worst_time = trace.time[failures.worst];
  issue.worst = failures.worst_value;
  issue.limit = failures.worst_limit;
  issue.samples = failures.samples;
  return issue;
}

void add_issue(TraceAudit& audit, const Trace& trace, ActorId actor, AuditKind kind,
               const Failures& failures) {
  if (failures.samples == 0) return;
  audit.issues.push_back(issue_of(trace, actor, kind, failures));
}

// Whether the recorded (lane, s) of sample i holds the actor's centre: beside the centre line at
// s and within the lane's width there.
bool on_recorded_lane(const RoadMap& map, const TraceActor& actor, std::size_t i) {
  if (actor.lane[i] < 0 || static_cast<std::size_t>(actor.lane[i]) >= map.lanes().size())
    return false;
  const auto lane = static_cast<LaneIndex>(actor.lane[i]);
  const std::optional<MapPose> pose = lane_pose_at(map, lane, actor.s[i]);
  if (!pose) return false;
  const double dx = actor.x[i] - pose->position.x, dy = actor.y[i] - pose->position.y;
  const double along = std::cos(pose->heading) * dx + std::sin(pose->heading) * dy;
  const double lateral = -std::sin(pose->heading) * dx + std::cos(pose->heading) * dy;
  if (std::abs(along) > kAuditThresholds.lane_along_tolerance) return false;
  return lateral >= 0 ? lateral <= lane_left_width_at(map, lane, actor.s[i])
                      : -lateral <= lane_right_width_at(map, lane, actor.s[i]);
}

// Whether the actor's centre lies within some lane at sample i. The recorded lane answers almost
// always; otherwise (lane -1, or a lane that does not hold the point) the map is asked.
bool on_some_lane(const RoadMap& map, const TraceActor& actor, std::size_t i) {
  if (on_recorded_lane(map, actor, i)) return true;
  const std::optional<LaneProjection> projection =
      project_to_lane(map, {actor.x[i], actor.y[i]}, actor.heading[i]);
  return projection && projection->inside;
}

// Stretches of samples off every lane longer than the grace time. The value of a stretch is its
// duration (samples * dt); the worst is the longest.
void audit_off_road(TraceAudit& audit, const Trace& trace, const RoadMap& map, ActorId id) {
  const TraceActor& actor = trace.actors[id];
  const double grace = kAuditThresholds.off_road_grace;
  Failures failures;
  std::size_t samples_off = 0;
  const Presence there = presence(trace, actor);
  std::size_t stretch_start = there.begin;
  auto close_stretch = [&](std::size_t end) {
    const std::size_t length = end - stretch_start;
    const double duration = static_cast<double>(length) * trace.dt;
    if (length > 0 && exceeds(duration, grace)) {
      failures.add(stretch_start, duration, grace, duration - grace);
      samples_off += length;
    }
  };
  for (std::size_t i = there.begin; i < there.end; ++i) {
    if (on_some_lane(map, actor, i)) {
      close_stretch(i);
      stretch_start = i + 1;
    }
  }
  close_stretch(there.end);
  failures.samples = samples_off;
  add_issue(audit, trace, id, AuditKind::off_road, failures);
}

void audit_speed(TraceAudit& audit, const Trace& trace, ActorId id,
                 const AuditClassLimits& limits) {
  const TraceActor& actor = trace.actors[id];
  Failures failures;
  const Presence there = presence(trace, actor);
  for (std::size_t i = there.begin; i < there.end; ++i)
    if (exceeds(actor.speed[i], limits.max_speed))
      failures.add(i, actor.speed[i], limits.max_speed, actor.speed[i] - limits.max_speed);
  add_issue(audit, trace, id, AuditKind::speed_limit, failures);
}

// The recorded acceleration (how fast the speed grows) against the class's acceleration and
// braking.
void audit_acceleration(TraceAudit& audit, const Trace& trace, ActorId id,
                        const AuditClassLimits& limits) {
  const TraceActor& actor = trace.actors[id];
  Failures failures;
  const Presence there = presence(trace, actor);
  for (std::size_t i = there.begin; i < there.end; ++i) {
    const double a = actor.acceleration[i];
    if (exceeds(a, limits.max_acceleration))
      failures.add(i, a, limits.max_acceleration, a - limits.max_acceleration);
    else if (exceeds(-a, limits.max_deceleration))
      failures.add(i, a, -limits.max_deceleration, -a - limits.max_deceleration);
  }
  add_issue(audit, trace, id, AuditKind::acceleration, failures);
}

// Centripetal acceleration speed * |yaw rate| against the class's grip, and the yaw rate against
// the tightest circle at full lock. Sample i's yaw rate is the turn over the step ending at i, so
// the most the speed allows is at the faster of the step's two ends.
void audit_turning(TraceAudit& audit, const Trace& trace, ActorId id,
                   const AuditClassLimits& limits) {
  if (limits.max_lateral_acceleration <= 0 || limits.min_turning_radius <= 0) return;
  const TraceActor& actor = trace.actors[id];
  Failures lateral, turning;
  const Presence there = presence(trace, actor);
  for (std::size_t i = there.begin; i < there.end; ++i) {
    const double yaw_rate = std::abs(actor.yaw_rate[i]);
    const double centripetal = actor.speed[i] * yaw_rate;
    if (exceeds(centripetal, limits.max_lateral_acceleration))
      lateral.add(i, centripetal, limits.max_lateral_acceleration,
                  centripetal - limits.max_lateral_acceleration);
    const double step_speed =
        i > there.begin ? std::max(actor.speed[i - 1], actor.speed[i]) : actor.speed[i];
    const double allowed = step_speed / limits.min_turning_radius;
    if (exceeds(yaw_rate, allowed)) turning.add(i, yaw_rate, allowed, yaw_rate - allowed);
  }
  add_issue(audit, trace, id, AuditKind::lateral_acceleration, lateral);
  add_issue(audit, trace, id, AuditKind::turning_radius, turning);
}

// The trace's convention (physics/actors/kinematics.cpp): sample i's yaw rate is the heading's
// change from sample i - 1 to i over the time between them, so sample 0 has nothing to check.
void audit_yaw_rate(TraceAudit& audit, const Trace& trace, ActorId id) {
  const TraceActor& actor = trace.actors[id];
  const double tolerance = kAuditThresholds.yaw_rate_tolerance;
  Failures failures;
  // The first sample on the map has no step on the map before it.
  const Presence there = presence(trace, actor);
  for (std::size_t i = there.begin + 1; i < there.end; ++i) {
    const double dt = trace.time[i] - trace.time[i - 1];
    if (dt <= 0) continue;
    const double derivative = angle_difference(actor.heading[i], actor.heading[i - 1]) / dt;
    const double gap = std::abs(actor.yaw_rate[i] - derivative);
    if (gap > tolerance) failures.add(i, gap, tolerance, gap - tolerance);
  }
  add_issue(audit, trace, id, AuditKind::yaw_rate_inconsistent, failures);
}

void audit_actor(TraceAudit& audit, const Trace& trace, const RoadMap& map, ActorId id) {
  const TraceActor& actor = trace.actors[id];
  if (actor.kind == TraceActorKind::obstacle) return;
  const AuditClassLimits limits = audit_class_limits(actor_class(actor.category));
  if (actor.kind != TraceActorKind::pedestrian) audit_off_road(audit, trace, map, id);
  audit_speed(audit, trace, id, limits);
  if (actor.kind != TraceActorKind::pedestrian) audit_turning(audit, trace, id, limits);
  audit_acceleration(audit, trace, id, limits);
  audit_yaw_rate(audit, trace, id);
}

void audit_overlaps(TraceAudit& audit, const Trace& trace) {
  for (const Collision& collision : trace.collisions) {
    if (collision.first == kEgo || collision.second == kEgo) continue;
    AuditIssue issue;
    issue.actor = collision.first;
    issue.actor_name = trace.actors[collision.first].name;
    issue.kind = AuditKind::npc_overlap;
    issue.time = issue.worst_time = collision.time;
    issue.other = collision.second;
    issue.other_name = trace.actors[collision.second].name;
    audit.issues.push_back(std::move(issue));
  }
}

}  // namespace

std::string_view audit_kind_name(AuditKind kind) {
  switch (kind) {
    case AuditKind::off_road: return "off_road";
    case AuditKind::speed_limit: return "speed_limit";
    case AuditKind::lateral_acceleration: return "lateral_acceleration";
    case AuditKind::acceleration: return "acceleration";
    case AuditKind::turning_radius: return "turning_radius";
    case AuditKind::yaw_rate_inconsistent: return "yaw_rate_inconsistent";
    case AuditKind::npc_overlap: return "npc_overlap";
  }
  SCENFUZZ_DEMAND(false);
  return "";
}

AuditClassLimits audit_class_limits(const ActorClass& actor_class) {
  AuditClassLimits limits;
  limits.max_speed = actor_class.max_speed;
  limits.max_acceleration = actor_class.max_acceleration;
  limits.max_deceleration = actor_class.max_deceleration;
  // The friction circle (physics/actors/friction_circle.hpp). Pedestrians have no steering:
  // neither is checked.
  if (actor_class.category != ActorCategory::pedestrian) {
    limits.max_lateral_acceleration = grip_lateral_acceleration(actor_class);
    limits.min_turning_radius = actor_class.min_turning_radius();
  }
  return limits;
}

TraceAudit audit_trace(const Trace& trace, const RoadMap& map) {
  TraceAudit audit;
  for (std::size_t k = 0; k < trace.actors.size(); ++k) {
    const TraceActor& actor = trace.actors[k];
    const std::size_t n = trace.sample_count();
    for (const auto* column : {&actor.x, &actor.y, &actor.heading, &actor.speed,
                               &actor.acceleration, &actor.yaw_rate, &actor.s})
      SCENFUZZ_DEMAND(column->size() == n);
    SCENFUZZ_DEMAND(actor.lane.size() == n);
    audit_actor(audit, trace, map, static_cast<ActorId>(k));
  }
  audit_overlaps(audit, trace);
  std::stable_sort(audit.issues.begin(), audit.issues.end(),
                   [](const AuditIssue& a, const AuditIssue& b) {
                     if (a.actor != b.actor) return a.actor < b.actor;
                     return a.kind < b.kind;
                   });
  for (const AuditIssue& issue : audit.issues) ++audit.counts[static_cast<std::size_t>(issue.kind)];
  return audit;
}

}  // namespace scenfuzz
