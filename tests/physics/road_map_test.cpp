// build_road_map: id resolution, repairs with warnings, and what it refuses.
#include "physics/map/road_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/physics/map_fixtures.hpp"

namespace scenfuzz {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

LaneIndex lane_index(const RoadMap& map, std::string_view id) {
  auto lane = map.find_lane(id);
  EXPECT_TRUE(lane) << id;
  return lane.value_or(0);
}

TEST(RoadMap, ResolvesConnectionsToIndices) {
  RoadMap map = build_road_map(test::two_lane_road());
  ASSERT_EQ(map.lanes().size(), 5u);
  LaneIndex a = lane_index(map, "a"), b = lane_index(map, "b"), a_next = lane_index(map, "a_next"),
            turn = lane_index(map, "turn");
  EXPECT_THAT(map.lane(a).successors, ElementsAre(a_next));
  EXPECT_THAT(map.lane(a).left_forward_neighbours, ElementsAre(b));
  EXPECT_THAT(map.lane(b).right_forward_neighbours, ElementsAre(a));
  // Predecessors were not given: they are derived from the successors.
  EXPECT_THAT(map.lane(a_next).predecessors, ElementsAre(a));
  EXPECT_THAT(map.lane(turn).predecessors, ElementsAre(a_next));
  EXPECT_EQ(map.lane(turn).junction, 0u);
  EXPECT_FALSE(map.lane(a).junction);
  EXPECT_TRUE(map.warnings().empty());
  EXPECT_FALSE(map.find_lane("nope"));
}

TEST(RoadMap, AttachesFeaturesToLanesSortedByS) {
  MapDescription description = test::two_lane_road();
  description.signs.push_back({"yield_a", SignKind::yield, {}, {{"a", 20, 20}}});
  RoadMap map = build_road_map(std::move(description));
  const Lane& a = map.lane(lane_index(map, "a"));
  ASSERT_EQ(a.features.size(), 2u);
  EXPECT_EQ(a.features[0].kind, FeatureKind::yield_sign);
  EXPECT_DOUBLE_EQ(a.features[0].s_begin, 20);
  EXPECT_EQ(a.features[1].kind, FeatureKind::traffic_light);
  EXPECT_EQ(map.stop_sign_count(), 1u);
  EXPECT_EQ(map.yield_sign_count(), 1u);
  EXPECT_EQ(map.traffic_lights()[0].lanes.size(), 2u);
  EXPECT_EQ(map.crosswalks()[0].lanes[0].lane, lane_index(map, "turn"));
}

TEST(RoadMap, DefaultWidthsAndDerivedBoundaries) {
  RoadMap map = build_road_map(test::two_lane_road());
  const Lane& a = map.lane(lane_index(map, "a"));
  ASSERT_EQ(a.left_width.size(), 1u);
  EXPECT_DOUBLE_EQ(a.left_width[0].width, 1.75);
  ASSERT_EQ(a.left_boundary.size(), 2u);
  EXPECT_NEAR(a.left_boundary[0].y, 1.75, 1e-12);
  EXPECT_NEAR(a.right_boundary[1].y, -1.75, 1e-12);
  EXPECT_DOUBLE_EQ(map.bounds().min.x, 0);
  EXPECT_DOUBLE_EQ(map.bounds().max.y, 50);
  EXPECT_DOUBLE_EQ(map.bounds().min.y, -5);  // the junction outline
}

TEST(RoadMap, WidthsFromDrawnBoundaries) {
  MapDescription description;
  description.source = "test";
  LaneDescription lane = test::straight_lane("wide", {0, 0}, {10, 0});
  lane.left_boundary = {{0, 2.5}, {10, 2.5}};
  lane.right_boundary = {{0, -1.5}, {10, -1.0}};
  description.lanes = {lane};
  RoadMap map = build_road_map(std::move(description));
  EXPECT_DOUBLE_EQ(width_at(map.lane(0).left_width, 5), 2.5);
  // Perpendicular distances to the slanted boundary: close to, not exactly, the y offset.
  EXPECT_NEAR(width_at(map.lane(0).right_width, 5), 1.25, 2e-3);
}

TEST(RoadMap, UnknownReferencesAreDroppedWithWarnings) {
  MapDescription description = test::two_lane_road();
  description.lanes[0].successors.push_back("ghost");
  description.lanes[0].junction = "nowhere";
  description.traffic_lights[0].lanes.push_back({"phantom", 1, 1});
  RoadMap map = build_road_map(std::move(description));
  EXPECT_EQ(map.lane(0).successors.size(), 1u);
  EXPECT_FALSE(map.lane(0).junction);
  ASSERT_EQ(map.warnings().size(), 3u);
  EXPECT_THAT(map.warnings()[0], HasSubstr("lane 'a': successor 'ghost'"));
  EXPECT_THAT(map.warnings()[2], HasSubstr("traffic light 'signal_a': crosses 'phantom'"));
}

TEST(RoadMap, CrossingsAreClampedToTheLane) {
  MapDescription description = test::two_lane_road();
  description.crosswalks[0].lanes = {{"turn", 60, 45}};  // reversed and past the end (50 m)
  RoadMap map = build_road_map(std::move(description));
  EXPECT_DOUBLE_EQ(map.crosswalks()[0].lanes[0].s_begin, 45);
  EXPECT_DOUBLE_EQ(map.crosswalks()[0].lanes[0].s_end, 50);
}

TEST(RoadMap, RefusesWhatCannotBeRepaired) {
  MapDescription empty;
  empty.source = "empty.txt";
  EXPECT_THROW(
      {
        try {
          build_road_map(empty);
        } catch (const MapError& error) {
          EXPECT_THAT(error.what(), HasSubstr("empty.txt: error: the map has no lanes"));
          throw;
        }
      },
      MapError);

  MapDescription duplicate = test::two_lane_road();
  duplicate.lanes[1].id = "a";
  EXPECT_THROW(build_road_map(duplicate), MapError);

  MapDescription degenerate = test::two_lane_road();
  degenerate.lanes[2].centre_line = {{100, 0}, {100, 0}};
  try {
    build_road_map(degenerate);
    FAIL() << "a lane with one distinct point was accepted";
  } catch (const MapError& error) {
    EXPECT_THAT(error.what(), HasSubstr("lane 'a_next'"));
  }
}

}  // namespace
}  // namespace scenfuzz
