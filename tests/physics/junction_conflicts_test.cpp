// JunctionConflicts shares conflicting_lanes' answers among a simulation's followers: each lane's
// answer must be conflicting_lanes' own, in any order of asking, and found once (the same vector
// when asked again).
#include "physics/map/junction_conflicts.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "physics/map/lane_conflicts.hpp"
#include "physics/map/map_source.hpp"

namespace scenfuzz {
namespace {

TEST(JunctionConflicts, AreConflictingLanesFoundOncePerLane) {
  for (const char* name : {"crossroads", "roundabout", "t_junction"}) {
    const RoadMap map = load_map(name, MapSearchPath{});
    const JunctionConflicts conflicts(map);
    int junction_lanes = 0, conflicting = 0;
    // Backwards, so that the cache fills in another order than the lanes'.
    for (LaneIndex lane = static_cast<LaneIndex>(map.lanes().size()); lane-- > 0;) {
      const std::vector<LaneIndex>& found = conflicts.of(lane);
      ASSERT_EQ(found, conflicting_lanes(map, lane)) << name << " lane " << lane;
      EXPECT_EQ(&conflicts.of(lane), &found) << "found again";
      junction_lanes += map.lane(lane).junction ? 1 : 0;
      conflicting += found.empty() ? 0 : 1;
    }
    EXPECT_GT(junction_lanes, 0) << name;
    EXPECT_GT(conflicting, 0) << name;
  }
}

}  // namespace
}  // namespace scenfuzz
