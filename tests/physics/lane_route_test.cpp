// Routing over the lane graph and the road furniture ahead on a route.
#include "physics/map/lane_route.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "physics/map/builtin_maps.hpp"
#include "tests/physics/map_fixtures.hpp"

namespace scenfuzz {
namespace {

class LaneRouting : public ::testing::Test {
 protected:
  LaneIndex lane(std::string_view id) const { return map.find_lane(id).value(); }
  RoadMap map = build_road_map(test::two_lane_road());
};

TEST_F(LaneRouting, SameLaneAhead) {
  auto route = find_route(map, LanePosition{lane("a"), 10}, LanePosition{lane("a"), 60});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 1u);
  EXPECT_DOUBLE_EQ(route->length, 50);
  EXPECT_EQ(route->lane_changes, 0);
}

TEST_F(LaneRouting, FollowsSuccessorsThroughTheJunction) {
  auto route = find_route(map, LanePosition{lane("a"), 10}, LanePosition{lane("turn"), 30});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 3u);
  EXPECT_EQ(route->segments[0].lane, lane("a"));
  EXPECT_DOUBLE_EQ(route->segments[0].s_end, 100);
  EXPECT_EQ(route->segments[1].lane, lane("a_next"));
  EXPECT_EQ(route->segments[2].lane, lane("turn"));
  EXPECT_DOUBLE_EQ(route->segments[2].s_begin, 0);
  EXPECT_DOUBLE_EQ(route->segments[2].s_end, 30);
  EXPECT_DOUBLE_EQ(route->length, 90 + 50 + 30);
}

TEST_F(LaneRouting, ChangesLaneOnlyWhereAllowed) {
  // From b to the turn: change to a on the dotted stretch, not on the solid one.
  auto route = find_route(map, LanePosition{lane("b"), 20}, LanePosition{lane("turn"), 10});
  ASSERT_TRUE(route);
  EXPECT_EQ(route->lane_changes, 1);
  ASSERT_EQ(route->segments.size(), 4u);
  EXPECT_EQ(route->segments[0].lane, lane("b"));
  EXPECT_EQ(route->segments[1].lane, lane("a"));
  EXPECT_DOUBLE_EQ(route->segments[1].s_begin, 20);
  // From b_next, only a solid line separates it from a_next: no route.
  EXPECT_FALSE(find_route(map, LanePosition{lane("b_next"), 0}, LanePosition{lane("turn"), 10}));
  RouteOptions no_changes;
  no_changes.allow_lane_changes = false;
  EXPECT_FALSE(
      find_route(map, LanePosition{lane("b"), 20}, LanePosition{lane("turn"), 10}, no_changes));
}

TEST_F(LaneRouting, NoRouteBackwards) {
  EXPECT_FALSE(find_route(map, LanePosition{lane("a"), 60}, LanePosition{lane("a"), 10}));
  EXPECT_FALSE(find_route(map, LanePosition{lane("turn"), 0}, LanePosition{lane("a"), 10}));
}

TEST_F(LaneRouting, RouteBetweenPoses) {
  auto route = find_route(map, MapPose{{5, 0.3}, 0}, MapPose{{150.4, 40}, std::numbers::pi / 2});
  ASSERT_TRUE(route);
  EXPECT_EQ(route->segments.front().lane, lane("a"));
  EXPECT_EQ(route->segments.back().lane, lane("turn"));
  EXPECT_NEAR(route->length, 95 + 50 + 40, 1e-9);
}

TEST_F(LaneRouting, FeaturesAheadInRouteOrder) {
  auto route = find_route(map, LanePosition{lane("a"), 10}, LanePosition{lane("turn"), 30});
  ASSERT_TRUE(route);
  auto first = next_feature_ahead(map, *route, 0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->kind, FeatureKind::traffic_light);
  EXPECT_DOUBLE_EQ(first->distance, 80);
  auto stop = next_feature_ahead(map, *route, 0, FeatureKind::stop_sign);
  ASSERT_TRUE(stop);
  EXPECT_EQ(stop->lane, lane("a_next"));
  EXPECT_DOUBLE_EQ(stop->distance, 90 + 45);
  auto crosswalk = next_feature_ahead(map, *route, 100);  // past the signal
  ASSERT_TRUE(crosswalk);
  EXPECT_EQ(crosswalk->kind, FeatureKind::stop_sign);
  EXPECT_DOUBLE_EQ(crosswalk->distance, 35);
  auto last = next_feature_ahead(map, *route, 140, FeatureKind::crosswalk);
  ASSERT_TRUE(last);
  EXPECT_DOUBLE_EQ(last->distance, 10);
  EXPECT_FALSE(next_feature_ahead(map, *route, 151));  // the crosswalk begins at 150
}

// The roundabout's ring is one closed lane that entries join and exits leave part-way along.
TEST(LaneRoutingRoundabout, EntersAndLeavesTheRingPartWayAndWrapsThroughZero) {
  RoadMap map = build_road_map(generate_builtin_map("roundabout", {}));
  auto lane = [&](std::string_view id) { return map.find_lane(id).value(); };
  auto route =
      find_route(map, LanePosition{lane("south_in_0"), 50}, LanePosition{lane("north_out_0"), 10});
  ASSERT_TRUE(route);
  std::vector<std::string> lanes;
  for (const RouteSegment& segment : route->segments) lanes.push_back(map.lane(segment.lane).id);
  EXPECT_EQ(lanes, (std::vector<std::string>{"south_in_0", "south_entry", "ring_0", "ring_0",
                                             "north_exit", "north_out_0"}));
  EXPECT_NEAR(route->segments[2].s_begin, 99.48, 0.01);
  EXPECT_NEAR(route->segments[2].s_end, 125.66, 0.01);
  EXPECT_NEAR(route->segments[3].s_begin, 0, 1e-9);
  EXPECT_NEAR(route->segments[3].s_end, 26.18, 0.01);
  // The east exit is the first after the south entry: no wrap.
  auto east =
      find_route(map, LanePosition{lane("south_in_0"), 50}, LanePosition{lane("east_out_0"), 10});
  ASSERT_TRUE(east);
  EXPECT_EQ(east->segments.size(), 5u);
  EXPECT_NEAR(east->segments[2].s_end, 120.43, 0.01);
  // Around the ring from s = 110 to s = 10.
  auto around =
      find_route(map, LanePosition{lane("ring_0"), 110}, LanePosition{lane("ring_0"), 10});
  ASSERT_TRUE(around);
  ASSERT_EQ(around->segments.size(), 2u);
  EXPECT_NEAR(around->length, 125.66 - 110 + 10, 0.01);
}

}  // namespace
}  // namespace scenfuzz
