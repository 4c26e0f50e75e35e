// implausible_motion_before: the trace audit, narrowed to one actor's motion issues near a time.
#include "oracle/implausible_motion.hpp"

#include <algorithm>
#include <cmath>

#include "lang/number_format.hpp"
#include "oracle/trace_audit.hpp"

namespace scenfuzz {

namespace {

// What the other did, in words; empty for issues that are not its own motion (an overlap of two
// NPCs says nothing about how either drove into the ego).
std::string motion_words(AuditKind kind) {
  switch (kind) {
    case AuditKind::off_road: return "driving off the road";
    case AuditKind::speed_limit: return "driving faster than its class can";
    case AuditKind::lateral_acceleration: return "turning harder than its tyres hold";
    case AuditKind::acceleration: return "accelerating or braking harder than its class can";
    case AuditKind::turning_radius: return "turning tighter than its full steering lock allows";
    case AuditKind::yaw_rate_inconsistent: return "turning without its heading turning";
    case AuditKind::npc_overlap: return "";
  }
  return "";
}

}  // namespace

std::optional<std::string> implausible_motion_before(const Trace& trace, const RoadMap& map,
                                                     ActorId other, double time) {
  const TraceAudit audit = audit_trace(trace, map);
  for (const AuditIssue& issue : audit.issues) {
    const std::string words = motion_words(issue.kind);
    if (issue.actor != other || words.empty() || issue.time > time) continue;
    // The latest moment the audit names; an issue that began earlier may still have been going on.
    const double latest = std::max(issue.time, issue.worst_time);
    if (latest < time - kImplausibleMotionWindow) continue;
    const double before = std::round((time - latest) * 10) / 10;
    return words + " " + format_number(before) + " s before impact";
  }
  return std::nullopt;
}

}  // namespace scenfuzz
