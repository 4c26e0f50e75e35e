// When another road user last came into a vehicle's path before a collision (its body ahead of
// the vehicle's centre and overlapping the band the vehicle's width sweeps along its frame), and
// how much room was left then: the numbers a user triages a collision with. Private to the
// responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct PathEntry {
  std::size_t sample = 0;
  double time = 0;                   // s, when it came into the path
  double gap = 0;                    // m, between the bodies along the path then
  double closing_speed = 0;          // m/s, the vehicle's speed along its path minus the other's
  double time_to_collision = 0;      // s, gap / closing speed; +inf when not closing
  double required_deceleration = 0;  // m/s^2, closing^2 / (2 gap): to avoid it by braking alone
  bool from_start = false;           // it was in the path from its first sample
};

// The entry of `other` into `vehicle`'s path that lasted until the collision at
// `collision_sample` (the path may be left up to half a second before it: a side impact);
// nullopt when `other` was not in the path then.
std::optional<PathEntry> path_entry(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                    ActorId other, std::size_t collision_sample);

}  // namespace scenfuzz
