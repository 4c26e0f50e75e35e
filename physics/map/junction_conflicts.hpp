// The crossing and merging lanes of each junction lane (conflicting_lanes, lane_conflicts.hpp),
// found once per lane when first asked for and then shared: they are a property of the map, and
// every lane follower giving way at the same junction asks for the same lanes. Owned by one
// simulation (its LaneOccupancy) and used from its thread only, so the lazy filling needs no lock.
#pragma once

#include <optional>
#include <vector>

#include "physics/map/road_map.hpp"

namespace scenfuzz {

class JunctionConflicts {
 public:
  explicit JunctionConflicts(const RoadMap& map) : map_(&map) {}

  // conflicting_lanes(map, lane), computed at the first call for `lane`.
  const std::vector<LaneIndex>& of(LaneIndex lane) const;

 private:
  const RoadMap* map_;
  // By lane index, filled as asked for (a cache of a const query).
  mutable std::vector<std::optional<std::vector<LaneIndex>>> known_;
};

}  // namespace scenfuzz
