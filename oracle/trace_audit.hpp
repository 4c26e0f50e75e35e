// The trace audit: after a simulation, what its actors did that no real road user does (drive
// off the road, beat their class's limits, turn without their heading turning, drive through
// each other). It judges the simulation, not the ego: a finding of the audit is a flaw of the
// simulated world that may make a spec violation (or its absence) meaningless.
// docs/oracle.md ("Trace audit") lists each check, its threshold and why.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

enum class AuditKind {
  off_road,               // a vehicle's centre on no lane for longer than the grace time
  speed_limit,            // faster than its class's top speed
  lateral_acceleration,   // speed * |yaw rate| above what its tyres hold
  acceleration,           // speeding up or braking harder than its class can
  turning_radius,         // turning tighter than its full steering lock allows
  yaw_rate_inconsistent,  // the recorded yaw rate is not the heading's derivative
  npc_overlap,            // two actors other than the ego touched (the ego's contacts are findings)
};
inline constexpr std::size_t kAuditKindCount = 7;

// "off_road", "speed_limit", ... as the JSON reports write them.
std::string_view audit_kind_name(AuditKind kind);

// Every threshold the audit uses that is not a row of the actor class table.
struct AuditThresholds {
  double off_road_grace = 1.0;         // s a vehicle may spend off every lane (corner cutting)
  double yaw_rate_tolerance = 1e-6;    // rad/s between the yaw rate and the heading's derivative
  double relative_tolerance = 1e-6;    // of a class limit: rounding, not a violation
  double lane_along_tolerance = 0.05;  // m: a recorded (lane, s) further away is looked up again
};
inline constexpr AuditThresholds kAuditThresholds{};

// What the audit holds one actor class to, derived from its row of the class table in one place.
struct AuditClassLimits {
  double max_speed = 0;                 // m/s
  double max_acceleration = 0;          // m/s^2
  double max_deceleration = 0;          // m/s^2, positive
  double max_lateral_acceleration = 0;  // m/s^2; 0: not checked (pedestrians turn on the spot)
  double min_turning_radius = 0;        // m; 0: not checked
};
AuditClassLimits audit_class_limits(const ActorClass& actor_class);

// One kind of implausibility of one actor (or, for npc_overlap, of one pair), over the run.
// Times are simulated seconds. `worst` and `limit` are in the kind's unit: off_road s (the
// longest stretch off every lane; limit the grace), speed_limit m/s, lateral_acceleration and
// acceleration m/s^2 (acceleration signed: a braking worst is negative, and so is its limit),
// turning_radius and yaw_rate_inconsistent rad/s (the yaw rate and the most its speed allows; the
// gap to the heading's derivative and the tolerance), npc_overlap 0 (a trace records only a
// pair's first contact).
struct AuditIssue {
  ActorId actor = 0;
  std::string actor_name;
  AuditKind kind = AuditKind::off_road;
  double time = 0;        // when it first happened
  double worst_time = 0;  // when the worst value happened (off_road: that stretch's start)
  double worst = 0;
  double limit = 0;
  std::size_t samples = 0;  // samples that failed the check (npc_overlap: 0)
  ActorId other = 0;        // npc_overlap: the other actor of the pair
  std::string other_name;   // npc_overlap: its name; empty otherwise
};

struct TraceAudit {
  std::vector<AuditIssue> issues;  // by actor, then by kind (AuditKind order), then by time
  std::array<std::size_t, kAuditKindCount> counts{};  // issues per kind, indexed by AuditKind

  std::size_t count(AuditKind kind) const { return counts[static_cast<std::size_t>(kind)]; }
  bool clean() const { return issues.empty(); }
};

// Audits a finished trace on the map it was simulated on. Linear in the trace's samples (a map
// lookup only for samples whose recorded lane does not hold the actor). Obstacles are not
// audited; pedestrians are not held to lanes, a lateral acceleration or a turning radius.
TraceAudit audit_trace(const Trace& trace, const RoadMap& map);

}  // namespace scenfuzz
