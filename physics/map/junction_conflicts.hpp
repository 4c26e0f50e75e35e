// The crossing and merging lanes of each junction lane (conflicting_lanes, lane_conflicts.hpp),
// found once per lane when first asked for and then kept by the map (RoadMap::junction_conflicts):
// with where the lane meets them (conflict_points): they are a property of the map, every lane
// follower giving way at the same junction asks for the same lanes, and so do the runs of a search
// after the first. A search simulates on one map from several threads, so each lane's answer is
// made under its own std::call_once.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "physics/map/lane_conflicts.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

class JunctionConflicts {
 public:
  // For a map of `lanes` lanes.
  explicit JunctionConflicts(std::size_t lanes);

  // conflicting_lanes(map, lane), computed at the first call for `lane`.
  const std::vector<LaneIndex>& of(const RoadMap& map, LaneIndex lane) const;
  // conflict_points(map, {lane}, of(map, lane)), computed at the first call for `lane`.
  const std::vector<ConflictPoint>& points_of(const RoadMap& map, LaneIndex lane) const;

 private:
  struct Known {
    std::once_flag once, points_once;
    std::vector<LaneIndex> lanes;
    std::vector<ConflictPoint> points;
  };
  std::unique_ptr<Known[]> known_;  // by lane (a once_flag does not move: no vector)
  std::size_t lanes_ = 0;
};

}  // namespace scenfuzz
