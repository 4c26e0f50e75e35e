// LaneOccupancy::gather answers what a lane follower's scan looked at before it: the actors filed
// under each watched lane and the loose ones, sorted and without repeats. Checked against that
// on random worlds (vehicles on and across lanes, near lane ends, the ego, pedestrians, absent
// actors, more than 64 of them) and random lists of watched lanes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "map_fixtures.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/lane_occupancy.hpp"
#include "physics/simulation/predicted_points.hpp"

namespace scenfuzz {
namespace {

TEST(LaneOccupancy, GatherEqualsTheWatchedLanesActorsAndTheLooseOnesSorted) {
  const RoadMap map = build_road_map(test::two_lane_road());
  const auto lanes = static_cast<LaneIndex>(map.lanes().size());
  LaneOccupancy occupancy(map);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<KinematicState> states;
  std::vector<LaneFix> fixes;
  std::vector<TraceActorKind> kinds;
  std::vector<double> lengths, widths;
  std::vector<std::uint8_t> present;
  std::vector<MapPoint> predicted;
  PointPredictor predictor;
  std::vector<std::uint32_t> gathered, expected;
  std::size_t filed_seen = 0, loose_seen = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Up to 140 actors: masks of more than one word.
    const std::size_t count = 1 + random() % (trial % 4 == 0 ? 140 : 12);
    states.assign(count, {});
    fixes.assign(count, {});
    kinds.assign(count, TraceActorKind::vehicle);
    lengths.assign(count, 4.6);
    widths.assign(count, 1.9);
    present.assign(count, 1);
    for (std::size_t k = 0; k < count; ++k) {
      // Along lane a or b (x from 0 to 150, over a's and b's ends), near the centre line or
      // across the lane line, nearly straight or turned.
      const bool on_b = unit(random) < 0.5;
      const double x = 150 * unit(random);
      const double offset = unit(random) < 0.7 ? 0.4 * (unit(random) - 0.5) : 3 * unit(random);
      states[k].x = x;
      states[k].y = (on_b ? 3.5 : 0) + offset;
      states[k].heading = unit(random) < 0.7 ? 0.02 * (unit(random) - 0.5) : unit(random) - 0.5;
      states[k].speed = unit(random) < 0.2 ? 0 : 15 * unit(random);
      const char* id = x < 100 ? (on_b ? "b" : "a") : (on_b ? "b_next" : "a_next");
      fixes[k] = {static_cast<std::int32_t>(*map.find_lane(id)), x < 100 ? x : x - 100};
      const double kind = unit(random);
      if (kind < 0.1) kinds[k] = TraceActorKind::pedestrian;
      if (kind > 0.95) kinds[k] = TraceActorKind::ego;
      if (unit(random) < 0.1) fixes[k].lane = -1;
      if (unit(random) < 0.1) present[k] = 0;
    }
    predictor.predict(states, 1.5, predicted);
    occupancy.set_step({states, &predictor, fixes, lengths, widths, kinds, present, 1.5});
    std::vector<LaneIndex> watched;
    for (LaneIndex lane = 0; lane < lanes; ++lane)
      if (unit(random) < 0.4) watched.push_back(lane);
    if (!watched.empty() && unit(random) < 0.3) watched.push_back(watched.front());  // a repeat
    expected.clear();
    for (LaneIndex lane : watched) occupancy.append_on(lane, expected);
    filed_seen += expected.size();
    const std::vector<std::uint32_t>& loose = occupancy.loose();
    loose_seen += loose.size();
    expected.insert(expected.end(), loose.begin(), loose.end());
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    occupancy.gather(watched, gathered);
    ASSERT_EQ(gathered, expected) << "trial " << trial;
  }
  // Both kinds of actor were met many times.
  EXPECT_GT(filed_seen, 400u);
  EXPECT_GT(loose_seen, 400u);
}

}  // namespace
}  // namespace scenfuzz
