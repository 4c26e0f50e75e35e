// Placing a scenario's positions on its map: lanes (clamped like Apollo), ENU, WGS84 through the
// map header's projection, IMU relative to the ego, and the errors a user sees.
#include "physics/map/scenario_position.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tests/physics/map_fixtures.hpp"

namespace scenfuzz {
namespace {

using ::testing::HasSubstr;

Position coordinate(Frame frame, double x, double y) {
  Position position;
  position.kind = PositionKind::coordinate;
  position.frame = frame;
  position.x = constant_value(x);
  position.y = constant_value(y);
  position.location = {3, 7, 20, 5};
  return position;
}

Position on_lane(std::string lane, Value s) {
  Position position;
  position.kind = PositionKind::lane;
  position.lane = std::move(lane);
  position.s = std::move(s);
  position.location = {4, 1, 30, 9};
  return position;
}

RoadMap geo_referenced_map() {
  MapDescription description = test::two_lane_road();
  description.projection = "+proj=utm +zone=10 +ellps=WGS84 +datum=WGS84 +units=m +no_defs";
  return build_road_map(std::move(description));
}

TEST(PlacePosition, LanePositionWithParameterAndClamping) {
  RoadMap map = build_road_map(test::two_lane_road());
  Diagnostics diagnostics;
  std::vector<double> values{42};
  auto placed = place_position(map, on_lane("turn", parameter_value(0)), values, {}, diagnostics);
  ASSERT_TRUE(placed);
  EXPECT_NEAR(placed->pose.position.x, 150, 1e-12);
  EXPECT_NEAR(placed->pose.position.y, 42, 1e-12);
  EXPECT_NEAR(placed->pose.heading, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(placed->lane, map.find_lane("turn"));
  EXPECT_EQ(placed->overshoot, 0);
  values[0] = 57;  // 7 m past the end of the 50 m lane: its end, as Apollo does
  placed = place_position(map, on_lane("turn", parameter_value(0)), values, {}, diagnostics);
  ASSERT_TRUE(placed);
  EXPECT_NEAR(placed->pose.position.y, 50, 1e-12);
  EXPECT_NEAR(placed->overshoot, 7, 1e-12);
  EXPECT_FALSE(diagnostics.has_errors());
}

TEST(PlacePosition, UnknownLaneIsAnErrorAtThePosition) {
  RoadMap map = build_road_map(test::two_lane_road());
  Diagnostics diagnostics;
  EXPECT_FALSE(place_position(map, on_lane("lane_9", constant_value(1)), {}, {}, diagnostics));
  ASSERT_EQ(diagnostics.error_count(), 1u);
  EXPECT_EQ(diagnostics.all()[0].location.line, 4u);
  EXPECT_THAT(diagnostics.all()[0].message, HasSubstr("lane 'lane_9' is not in map"));
}

// A lane id from a newer release of a map (CausAVFuzzer's lane_1560 on a san_francisco whose
// lanes end at lane_1523): the message shows the map's range, in numeric order.
TEST(PlacePosition, UnknownLaneNamesTheMapsLaneRange) {
  MapDescription description = test::two_lane_road();
  description.lanes.clear();
  double y = 0;
  for (const char* id : {"lane_10", "lane_2", "lane_1523", "lane_0", "lane_99"}) {
    description.lanes.push_back(test::straight_lane(id, {0, y}, {100, y}));
    y += 10;
  }
  RoadMap map = build_road_map(description);
  Diagnostics diagnostics;
  EXPECT_FALSE(place_position(map, on_lane("lane_1560", constant_value(1)), {}, {}, diagnostics));
  ASSERT_EQ(diagnostics.error_count(), 1u);
  EXPECT_EQ(diagnostics.all()[0].message,
            "lane 'lane_1560' is not in map 'two_lane_road' (its lanes are lane_0 .. lane_1523, "
            "5 lanes)");
}

TEST(PlacePosition, Wgs84IsProjectedWithTheMapHeader) {
  RoadMap map = geo_referenced_map();
  Diagnostics diagnostics;
  // The san_francisco header's corner; GeographicLib puts it at (552873.985519, 4182486.019823).
  auto placed = place_position(map, coordinate(Frame::wgs84, -122.39949797829956, 37.7882039998496),
                               {}, {}, diagnostics);
  ASSERT_TRUE(placed);
  EXPECT_NEAR(placed->pose.position.x, 552873.985519, 1e-3);
  EXPECT_NEAR(placed->pose.position.y, 4182486.019823, 1e-3);
  EXPECT_FALSE(placed->lane);
}

TEST(PlacePosition, Wgs84NeedsAProjectionAndALatitude) {
  Diagnostics diagnostics;
  RoadMap plain = build_road_map(test::two_lane_road());
  EXPECT_FALSE(place_position(plain, coordinate(Frame::wgs84, -122.4, 37.8), {}, {}, diagnostics));
  RoadMap geo = geo_referenced_map();
  EXPECT_FALSE(place_position(geo, coordinate(Frame::wgs84, 37.8, -122.4), {}, {}, diagnostics));
  ASSERT_EQ(diagnostics.error_count(), 2u);
  EXPECT_THAT(diagnostics.all()[0].message, HasSubstr("has no projection"));
  EXPECT_THAT(diagnostics.all()[1].message, HasSubstr("(longitude, latitude)"));
}

TEST(PlacePosition, ImuIsRightForwardFromTheEgo) {
  RoadMap map = build_road_map(test::two_lane_road());
  Diagnostics diagnostics;
  MapPose ego{{10, 20}, std::numbers::pi / 2};  // facing north: right is east
  auto placed = place_position(map, coordinate(Frame::imu, 2, 5), {}, ego, diagnostics);
  ASSERT_TRUE(placed);
  EXPECT_NEAR(placed->pose.position.x, 12, 1e-12);
  EXPECT_NEAR(placed->pose.position.y, 25, 1e-12);
  EXPECT_FALSE(place_position(map, coordinate(Frame::imu, 2, 5), {}, {}, diagnostics));
  EXPECT_EQ(diagnostics.error_count(), 1u);
}

TEST(PlacePosition, EnuAndNonFiniteValues) {
  RoadMap map = build_road_map(test::two_lane_road());
  Diagnostics diagnostics;
  auto placed = place_position(map, coordinate(Frame::enu, 3, 4), {}, {}, diagnostics);
  ASSERT_TRUE(placed);
  EXPECT_EQ(placed->pose.position, (MapPoint{3, 4}));
  EXPECT_FALSE(place_position(map, coordinate(Frame::enu, NAN, 4), {}, {}, diagnostics));
  EXPECT_FALSE(place_position(map, on_lane("a", constant_value(INFINITY)), {}, {}, diagnostics));
  EXPECT_EQ(diagnostics.error_count(), 2u);
}

}  // namespace
}  // namespace scenfuzz
