// Whether the ego could still have avoided a collision another road user caused: the standard a
// driver is held to when an accident report becomes a regression test (AC3R, SoVAR), in the
// spirit of Waymo's NIEON reference driver. The conflict begins when, from then until the impact,
// both bodies carrying on as they move (speed, acceleration and turn rate held) would meet within
// kConflictHorizon; an attentive driver answers one RSS response time later by braking at its
// full braking along the path it drove. The collision was avoidable when that braking ego never
// touches the other. Braking is the only answer tried (no swerving, no speeding up), so an
// "unavoidable" verdict may be generous to the driver, never harsh. docs/oracle.md,
// "Avoidability", says why these choices.
#pragma once

#include <cstddef>
#include <string>

#include "oracle/rss_parameters.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// How far ahead carrying on is looked at: a conflict seen this long before the impact is one an
// attentive driver notices (the 3 s of traffic-conflict studies' time-to-collision threshold).
inline constexpr double kConflictHorizon = 3.0;  // s

struct Avoidability {
  bool avoidable = false;
  double conflict_time = 0;  // s, when the conflict began
  double brake_time = 0;     // s, conflict_time + the ego's response time: when braking starts
  // m, the closest the braking ego comes to the other from brake_time to the trace's end:
  // positive exactly when avoidable. The impact's own distance (0) when braking came too late.
  double clearance = 0;
  double stop_short = 0;  // m the braking ego stops short of where it was at the impact; 0: none
  std::string reason;     // one sentence, no final full stop
};

// Whether collision `collision` of `trace`, which must involve the ego, was avoidable by braking.
// The other's samples after the impact are read as where it would have gone: the trace should
// come from a run that went on after the collision with an other that ignores it (a replay).
Avoidability collision_avoidability(const Trace& trace, std::size_t collision,
                                    const RssParameters& rss);

}  // namespace scenfuzz
