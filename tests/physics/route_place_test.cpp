// place_on_route: where a tracked actor is along a lane route (how a lane follower measures the
// gap to its leader between scans): along successors, across a lane change, and off the route.
#include "physics/simulation/route_place.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace scenfuzz {
namespace {

// Lane 4 from s = 10 to its end at 50, then its successor 7 to s = 20, then a lane change onto
// lane 8 beside it, from s = 20 on 8 to 60.
struct Fixture {
  LaneRoute route{{{4, 10, 50}, {7, 0, 20}, {8, 20, 60}}, 110, 1};
  std::vector<double> starts{0, 40, 60};
};

TEST(RoutePlace, AlongTheSegmentsLaneFromWhereTheRouteEntersIt) {
  Fixture f;
  auto on_first = place_on_route(f.route, f.starts, {4, 25}, 0, 1e9, 0.5);
  ASSERT_TRUE(on_first);
  EXPECT_EQ(on_first->segment, 0u);
  EXPECT_DOUBLE_EQ(on_first->distance, 15);
  auto on_successor = place_on_route(f.route, f.starts, {7, 5}, 0, 1e9, 0.5);
  ASSERT_TRUE(on_successor);
  EXPECT_EQ(on_successor->segment, 1u);
  EXPECT_DOUBLE_EQ(on_successor->distance, 45);
  auto after_change = place_on_route(f.route, f.starts, {8, 30}, 1, 1e9, 0.5);
  ASSERT_TRUE(after_change);
  EXPECT_EQ(after_change->segment, 2u);
  EXPECT_DOUBLE_EQ(after_change->distance, 70);
}

TEST(RoutePlace, WithinToleranceOfASegmentsEnds) {
  Fixture f;
  auto just_past = place_on_route(f.route, f.starts, {7, 20.4}, 0, 1e9, 0.5);
  ASSERT_TRUE(just_past);
  EXPECT_DOUBLE_EQ(just_past->distance, 60.4);
  EXPECT_FALSE(place_on_route(f.route, f.starts, {7, 20.6}, 0, 1e9, 0.5))
      << "beyond where the route leaves lane 7 sideways, lane 7 is beside the route";
  EXPECT_FALSE(place_on_route(f.route, f.starts, {4, 9}, 0, 1e9, 0.5))
      << "behind where the route enters lane 4";
}

TEST(RoutePlace, NothingOffTheRouteOrOnNoLane) {
  Fixture f;
  EXPECT_FALSE(place_on_route(f.route, f.starts, {5, 25}, 0, 1e9, 0.5));
  EXPECT_FALSE(place_on_route(f.route, f.starts, {-1, 25}, 0, 1e9, 0.5));
}

TEST(RoutePlace, OnlyFromTheGivenSegmentAndBeforeTheLimit) {
  Fixture f;
  EXPECT_FALSE(place_on_route(f.route, f.starts, {4, 25}, 1, 1e9, 0.5)) << "behind `from`";
  EXPECT_FALSE(place_on_route(f.route, f.starts, {8, 30}, 0, 60, 0.5))
      << "its segment begins at the limit";
  EXPECT_TRUE(place_on_route(f.route, f.starts, {8, 30}, 0, 60.5, 0.5));
}

}  // namespace
}  // namespace scenfuzz
