// The next stretch of a route that runs through a junction: where it enters the junction and
// where it leaves it, in route distance. The junction priority rule (docs/simulation.md,
// "Junctions") holds a vehicle at the entry and lets it go only when it can clear the exit.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct JunctionStretch {
  std::size_t first = 0, last = 0;  // the route segments in the junction
  double entry = 0, exit = 0;       // route distance where they begin and end
  std::uint32_t junction = 0;
};

// The first run of consecutive route segments in one junction that ends beyond route distance
// `from` (the one the vehicle is in, or the next ahead). `starts` are the route distances where
// each segment begins.
std::optional<JunctionStretch> junction_stretch_ahead(const RoadMap& map,
                                                      std::span<const RouteSegment> segments,
                                                      std::span<const double> starts, double from);

}  // namespace scenfuzz
