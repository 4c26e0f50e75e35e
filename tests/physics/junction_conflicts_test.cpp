// The map shares conflicting_lanes' answers among every simulation on it (RoadMap::
// junction_conflicts): each lane's answer must be conflicting_lanes' own, in any order of asking,
// found once (the same vector when asked again), and so from several threads at once, as a
// search's workers ask.
#include "physics/map/junction_conflicts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "physics/map/lane_conflicts.hpp"
#include "physics/map/map_source.hpp"

namespace scenfuzz {
namespace {

TEST(JunctionConflicts, AreConflictingLanesFoundOncePerLane) {
  for (const char* name : {"crossroads", "roundabout", "t_junction"}) {
    const RoadMap map = load_map(name, MapSearchPath{});
    int junction_lanes = 0, conflicting = 0;
    // Backwards, so that the cache fills in another order than the lanes'.
    for (LaneIndex lane = static_cast<LaneIndex>(map.lanes().size()); lane-- > 0;) {
      const std::vector<LaneIndex>& found = map.junction_conflicts(lane);
      ASSERT_EQ(found, conflicting_lanes(map, lane)) << name << " lane " << lane;
      EXPECT_EQ(&map.junction_conflicts(lane), &found) << "found again";
      junction_lanes += map.lane(lane).junction ? 1 : 0;
      conflicting += found.empty() ? 0 : 1;
    }
    EXPECT_GT(junction_lanes, 0) << name;
    EXPECT_GT(conflicting, 0) << name;
  }
}

// Where each junction lane meets its conflicting lanes, kept by the map too: conflict_points'
// own answer, the same vector when asked again; on the roundabout an entry meets the ring once
// (where it joins it) and no other entry.
TEST(JunctionConflicts, KeepWhereEachLaneMeetsThem) {
  for (const char* name : {"crossroads", "roundabout", "t_junction"}) {
    const RoadMap map = load_map(name, MapSearchPath{});
    for (LaneIndex lane = 0; lane < map.lanes().size(); ++lane) {
      const std::vector<ConflictPoint>& found = map.junction_conflict_points(lane);
      const LaneIndex own[] = {lane};
      const std::vector<ConflictPoint> direct =
          conflict_points(map, own, conflicting_lanes(map, lane));
      ASSERT_EQ(found.size(), direct.size()) << name << " lane " << lane;
      for (std::size_t k = 0; k < found.size(); ++k) {
        EXPECT_EQ(found[k].lane, direct[k].lane);
        EXPECT_EQ(found[k].s, direct[k].s);
      }
      EXPECT_EQ(&map.junction_conflict_points(lane), &found) << "found again";
    }
  }
  const RoadMap roundabout = load_map("roundabout", MapSearchPath{});
  const std::vector<ConflictPoint>& entry =
      roundabout.junction_conflict_points(*roundabout.find_lane("west_entry"));
  ASSERT_EQ(entry.size(), 1u);
  EXPECT_EQ(roundabout.lane(entry[0].lane).id, "ring_0");
}

TEST(JunctionConflicts, AreFoundOnceWhenThreadsAskAtOnce) {
  const RoadMap map = load_map("crossroads", MapSearchPath{});
  const auto lanes = static_cast<LaneIndex>(map.lanes().size());
  constexpr int kThreads = 4;
  std::vector<std::vector<const std::vector<LaneIndex>*>> seen(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      // Each thread in its own order, so that they race for different lanes first.
      for (LaneIndex i = 0; i < lanes; ++i)
        seen[t].push_back(&map.junction_conflicts((i * (2 * t + 1) + t) % lanes));
    });
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t)
    for (LaneIndex i = 0; i < lanes; ++i) {
      const LaneIndex lane = (i * (2 * t + 1) + t) % lanes;
      EXPECT_EQ(seen[t][i], &map.junction_conflicts(lane)) << "thread " << t << " lane " << lane;
      EXPECT_EQ(*seen[t][i], conflicting_lanes(map, lane)) << "lane " << lane;
    }
}

TEST(RoadMap, DerivesTheNarrowestAndWidestLaneWidthsAndJunctionLanes) {
  const RoadMap map = load_map("crossroads", MapSearchPath{});
  double widest = 0;
  std::size_t in_junctions = 0;
  for (LaneIndex lane = 0; lane < map.lanes().size(); ++lane) {
    const Lane& l = map.lane(lane);
    double left = l.left_width.front().width, right = l.right_width.front().width;
    for (const WidthSample& sample : l.left_width) left = std::min(left, sample.width);
    for (const WidthSample& sample : l.right_width) right = std::min(right, sample.width);
    EXPECT_EQ(l.narrowest_left_width, left) << "lane " << lane;
    EXPECT_EQ(l.narrowest_right_width, right) << "lane " << lane;
    for (const auto* side : {&l.left_width, &l.right_width})
      for (const WidthSample& sample : *side) widest = std::max(widest, sample.width);
    if (l.junction) {
      const std::vector<LaneIndex>& of = map.junctions()[*l.junction].lanes;
      EXPECT_TRUE(std::binary_search(of.begin(), of.end(), lane)) << "lane " << lane;
      ++in_junctions;
    }
  }
  EXPECT_EQ(map.widest_half_lane(), widest);
  std::size_t listed = 0;
  for (const Junction& junction : map.junctions()) {
    EXPECT_TRUE(std::is_sorted(junction.lanes.begin(), junction.lanes.end()));
    listed += junction.lanes.size();
  }
  EXPECT_EQ(listed, in_junctions);
  EXPECT_GT(in_junctions, 0u);
}

}  // namespace
}  // namespace scenfuzz
