// When a road user put itself in a vehicle's path, and whether that vehicle could still stop: the
// moment it came into the path, or, when it then came to rest there, the moment it stopped (a
// vehicle standing in another's way is only excused when it stopped early enough). The vehicle
// had room when its gap then was at least RSS's safe longitudinal distance towards a standing or
// slower body. The path of a vehicle that follows its lane is that lane ahead of it. Private to the
// responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>

#include "oracle/rss_parameters.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct PathIntrusion {
  std::size_t sample = 0;     // when it came into the path, or came to rest in it
  bool came_to_rest = false;  // `sample` is when it stopped in the path, after coming into it
  double gap = 0;             // m, between the bodies along the vehicle's path then
  double speed = 0;           // m/s, the vehicle's speed along its path then
  double safe_distance = 0;   // m, RSS's for the vehicle then
  bool unsafe() const { return gap < safe_distance; }
};

// How `intruder` came into `vehicle`'s path before the collision at `collision_sample`; nullopt
// when it was not in the path then, was in it from the start, or stood still already when the
// path came to it (the vehicle moved, not the intruder), or kept to its own lane along it while the
// vehicle came against that lane's direction.
std::optional<PathIntrusion> path_intrusion(const Trace& trace, const RoadMap& map, ActorId vehicle,
                                            ActorId intruder, std::size_t collision_sample,
                                            const RssParameters& rss);

}  // namespace scenfuzz
