// Treiber's constant-acceleration heuristic on top of IDM (physics/ego/
// constant_acceleration_heuristic.hpp): what it changes and what it keeps.
#include "physics/ego/constant_acceleration_heuristic.hpp"

#include <gtest/gtest.h>

namespace scenfuzz {
namespace {

TEST(ConstantAccelerationHeuristicTest, AGapTooSmallButNotClosingIsOpenedGently) {
  // The stop_and_go_traffic finding: 6.9 m behind a leader at 9.6 m/s, the ego at 9.8 m/s; IDM
  // (a 1.5, b 2.5, T 1.5 s, s0 2.5 m, v0 13.9 m/s) asks for about -8.5 m/s^2.
  const double acc = with_constant_acceleration_heuristic(-8.5, 9.8, 9.6, 6.9, 2.5);
  EXPECT_LT(acc, -2.0);  // it still brakes, firmly
  EXPECT_GT(acc, -2.7);  // but about one comfortable deceleration, not 8.5
}

TEST(ConstantAccelerationHeuristicTest, WhereIdmIsMildOrTheLeaderNeedsHardBrakingItStaysNearIdm) {
  EXPECT_EQ(with_constant_acceleration_heuristic(0.5, 10, 10, 20, 2.5), 0.5);  // not braking
  EXPECT_NEAR(with_constant_acceleration_heuristic(-1.0, 10, 9, 20, 2.5), -1.0, 0.1);
  // Closing at 10 m/s with 10 m left: the CAH needs 5 m/s^2 itself, and the result brakes at
  // least that hard.
  EXPECT_LE(with_constant_acceleration_heuristic(-9.0, 20, 10, 10, 2.5), -5.0);
}

TEST(ConstantAccelerationHeuristicTest, TheResultNeverAsksForMoreThanIdm) {
  for (double idm : {-9.0, -6.0, -3.0, -1.0})
    for (double gap : {2.0, 5.0, 15.0})
      for (double lead : {0.5, 5.0, 9.0, 12.0})
        EXPECT_GE(with_constant_acceleration_heuristic(idm, 10, lead, gap, 2.5), idm - 1e-12)
            << idm << " " << gap << " " << lead;
}

}  // namespace
}  // namespace scenfuzz
