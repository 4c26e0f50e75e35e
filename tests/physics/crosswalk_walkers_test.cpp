// LaneOccupancy::walkers_at answers once per step for every follower what each follower's own
// crosswalk test (a present pedestrian walking at least so fast within the clearance of the
// crosswalk's outline) answered before. Checked against that plain test on random worlds, asked
// repeatedly within a step, with the followers' settings and with others.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "map_fixtures.hpp"
#include "physics/map/polygon.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/lane_occupancy.hpp"
#include "physics/simulation/predicted_points.hpp"

namespace scenfuzz {
namespace {

bool plain_walkers_at(const Crosswalk& crosswalk, const std::vector<KinematicState>& states,
                      const std::vector<TraceActorKind>& kinds,
                      const std::vector<std::uint8_t>& present, double walking_speed,
                      double clearance) {
  for (std::size_t k = 0; k < states.size(); ++k)
    if (kinds[k] == TraceActorKind::pedestrian && present[k] != 0 &&
        states[k].speed >= walking_speed &&
        near_polygon({states[k].x, states[k].y}, crosswalk.outline, clearance))
      return true;
  return false;
}

TEST(LaneOccupancy, WalkersAtEqualsEachPedestrianTestedAgainstTheCrosswalk) {
  const RoadMap map = build_road_map(test::two_lane_road());
  ASSERT_EQ(map.crosswalks().size(), 1u);
  const Crosswalk& crosswalk = map.crosswalks()[0];
  LaneOccupancy occupancy(map);
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<KinematicState> states;
  std::vector<LaneFix> fixes;
  std::vector<TraceActorKind> kinds;
  std::vector<double> lengths, widths;
  std::vector<std::uint8_t> present;
  std::vector<MapPoint> predicted;
  PointPredictor predictor;
  int walkers_seen = 0, none_seen = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const std::size_t count = 1 + random() % 8;
    states.assign(count, {});
    fixes.assign(count, {-1, 0});
    kinds.assign(count, TraceActorKind::vehicle);
    lengths.assign(count, 0.5);
    widths.assign(count, 0.5);
    present.assign(count, 1);
    for (std::size_t k = 0; k < count; ++k) {
      // Around the crosswalk (x 145..155, y 10..14), inside, at its edge or well off it.
      states[k].x = 140 + 20 * unit(random);
      states[k].y = 6 + 12 * unit(random);
      states[k].speed = unit(random) < 0.3 ? 0.1 : 1.5 * unit(random);
      if (unit(random) < 0.7) kinds[k] = TraceActorKind::pedestrian;
      if (unit(random) < 0.1) present[k] = 0;
    }
    predictor.predict(states, 1.5, predicted);
    occupancy.set_step({states, &predictor, fixes, lengths, widths, kinds, present, 1.5});
    // Several followers ask in a step; now and then one with settings of its own.
    for (int ask = 0; ask < 3; ++ask) {
      const bool own = unit(random) < 0.2;
      const double speed = own ? unit(random) : 0.3, clearance = own ? 3 * unit(random) : 1.5;
      const bool expected = plain_walkers_at(crosswalk, states, kinds, present, speed, clearance);
      ASSERT_EQ(occupancy.walkers_at(0, speed, clearance), expected) << "trial " << trial;
      (expected ? walkers_seen : none_seen) += 1;
    }
  }
  // Both answers were met many times.
  EXPECT_GT(walkers_seen, 200);
  EXPECT_GT(none_seen, 200);
}

}  // namespace
}  // namespace scenfuzz
