// Lane poses, point-to-lane projection (with and without a heading) and lane-change rules.
#include "physics/map/lane_queries.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "physics/map/builtin_maps.hpp"
#include "tests/physics/map_fixtures.hpp"

namespace scenfuzz {
namespace {

class LaneQueries : public ::testing::Test {
 protected:
  LaneIndex lane(std::string_view id) const { return map.find_lane(id).value(); }
  RoadMap map = build_road_map(test::two_lane_road());
};

TEST_F(LaneQueries, PoseAtArcLengthWithLateralOffset) {
  auto pose = lane_pose_at(map, lane("turn"), 20, 1.0);
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->position.x, 149, 1e-12);  // left of a northbound lane is west
  EXPECT_NEAR(pose->position.y, 20, 1e-12);
  EXPECT_NEAR(pose->heading, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(lane_heading_at(map, lane("a"), 50), 0, 1e-12);
}

TEST_F(LaneQueries, PoseOutsideTheLaneIsRefused) {
  EXPECT_FALSE(lane_pose_at(map, lane("a"), 100.5));
  EXPECT_FALSE(lane_pose_at(map, lane("a"), -0.5));
  EXPECT_FALSE(lane_pose_at(map, lane("a"), NAN));
  EXPECT_TRUE(lane_pose_at(map, lane("a"), 100.0005));  // within the millimetre tolerance
  EXPECT_TRUE(lane_pose_at(map, lane("a"), 0));
}

TEST_F(LaneQueries, ProjectionFindsNearestLane) {
  auto on_b = project_to_lane(map, {30, 4.0});
  ASSERT_TRUE(on_b);
  EXPECT_EQ(on_b->lane, lane("b"));
  EXPECT_NEAR(on_b->s, 30, 1e-12);
  EXPECT_NEAR(on_b->lateral, 0.5, 1e-12);
  EXPECT_TRUE(on_b->inside);
  auto right_of_a = project_to_lane(map, {60, -1.0});
  ASSERT_TRUE(right_of_a);
  EXPECT_EQ(right_of_a->lane, lane("a"));
  EXPECT_NEAR(right_of_a->lateral, -1.0, 1e-12);
  auto far = project_to_lane(map, {60, -30});
  ASSERT_TRUE(far);
  EXPECT_FALSE(far->inside);
  EXPECT_NEAR(far->distance, 30, 1e-12);
  EXPECT_FALSE(project_to_lane(map, {NAN, 0}));
}

TEST_F(LaneQueries, ProjectionAgreesWithBruteForce) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> x(-20, 170), y(-20, 70);
  for (int i = 0; i < 2000; ++i) {
    MapPoint point{x(random), y(random)};
    double best = INFINITY;
    for (const Lane& each : map.lanes())
      best = std::min(best, each.centre_line.project(point).distance);
    auto projection = project_to_lane(map, point);
    ASSERT_TRUE(projection);
    EXPECT_NEAR(projection->distance, best, 1e-9) << point.x << ", " << point.y;
  }
}

TEST_F(LaneQueries, HeadingPicksAmongOverlappingLanes) {
  // (150, 0.5): inside both a_next (ends at (150, 0)) and turn (starts there, northbound).
  MapPoint junction_entry{149.5, 0.5};
  auto east = project_to_lane(map, junction_entry, 0.0);
  auto north = project_to_lane(map, junction_entry, std::numbers::pi / 2);
  ASSERT_TRUE(east && north);
  EXPECT_EQ(east->lane, lane("a_next"));
  EXPECT_EQ(north->lane, lane("turn"));
  // Outside every lane, the heading cannot help: the nearest lane.
  auto outside = project_to_lane(map, {60, -30}, std::numbers::pi);
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->lane, lane("a"));
}

TEST_F(LaneQueries, LaneChangeNeedsADottedLineAndNoJunction) {
  EXPECT_TRUE(lane_change_allowed(map, lane("a"), lane("b")));
  EXPECT_TRUE(lane_change_allowed(map, lane("b"), lane("a")));
  EXPECT_FALSE(lane_change_allowed(map, lane("a_next"), lane("b_next")));  // solid line
  EXPECT_FALSE(lane_change_allowed(map, lane("a"), lane("a_next")));       // not a neighbour
  EXPECT_FALSE(lane_change_allowed(map, lane("a_next"), lane("turn")));
}

// A roundabout's ring is its own successor; its entries, exits and a straight road's lanes are not.
TEST(LaneQueriesRing, OnlyTheRingRunsIntoItself) {
  const RoadMap roundabout = build_road_map(generate_builtin_map("roundabout", {}));
  for (LaneIndex k = 0; k < roundabout.lanes().size(); ++k)
    EXPECT_EQ(runs_into_itself(roundabout, k), roundabout.lane(k).id == "ring_0")
        << roundabout.lane(k).id;
  const RoadMap straight = build_road_map(test::two_lane_road());
  for (LaneIndex k = 0; k < straight.lanes().size(); ++k)
    EXPECT_FALSE(runs_into_itself(straight, k));
}

}  // namespace
}  // namespace scenfuzz
