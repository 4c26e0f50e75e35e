// Whether the other vehicle in a collision moved as no road user can shortly before it (the
// trace audit's motion checks: off the road, beyond its class's speed, acceleration, tyre grip or
// steering lock, turning without its heading turning). Such a collision says nothing about the
// driver under test, which cannot be expected to anticipate physically impossible motion: the
// responsibility oracle gives it to the other (docs/oracle.md, "Responsibility"). Pedestrians are
// left out: the simulation starts and stops them at once, which the audit's limits flag although
// a person can nearly do it.
#pragma once

#include <optional>
#include <string>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// How long before an impact implausible motion of the other still bears on it (s): about the time
// a car at urban speed takes to reach the ego from where the ego could first react to it.
inline constexpr double kImplausibleMotionWindow = 5;

// "turning tighter than its full steering lock allows 1.2 s before impact", for the first audit
// issue of `other` that falls in [time - kImplausibleMotionWindow, time]; nullopt when none does.
std::optional<std::string> implausible_motion_before(const Trace& trace, const RoadMap& map,
                                                     ActorId other, double time);

}  // namespace scenfuzz
