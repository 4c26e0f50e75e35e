// Pedestrians on a crosswalk have the way over a vehicle turning into the road they cross: the
// driver turning right (or left) at a junction gives way to them. Read from the junction lane the
// trace records the ego on and the map's crosswalk outlines. Private to the responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct CrosswalkPriority {
  std::uint32_t crosswalk = 0;  // into RoadMap::crosswalks()
  LaneTurn turn = LaneTurn::right;
  double ahead = 0;  // s the pedestrian was on the crosswalk before the ego reached it
};

// The way the ego owed `pedestrian` at the collision at `k`: the ego was turning at a junction in
// the `memory` seconds before, the pedestrian was on a crosswalk at impact and had been on it
// before the ego reached it. nullopt otherwise.
std::optional<CrosswalkPriority> crosswalk_priority(const Trace& trace, const RoadMap& map,
                                                    ActorId pedestrian, std::size_t k,
                                                    double memory);

}  // namespace scenfuzz
