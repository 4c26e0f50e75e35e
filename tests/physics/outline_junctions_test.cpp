// Junctions of road outlines (physics/map/outline_map.hpp, rule 9): two roads crossing, a road
// ending at another's edge, a corner, the lanes cut into pieces with their chains, the turn
// connectors, the junction's stretch along each road, the errors for what scenfuzz cannot make a
// junction of, and a junction's traffic lights (rule 10).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "outline_fixtures.hpp"
#include "physics/map/outline_map.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/traffic_signals.hpp"

namespace scenfuzz {
namespace {

using test::lane_of;
using test::outline_error;

using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::UnorderedElementsAre;

// A straight two-way road from `from` to `to` with halves `half` metres wide.
RoadOutlineGeometry road(std::string name, MapPoint from, MapPoint to, double half) {
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  const MapPoint left{-(to.y - from.y) / length * half, (to.x - from.x) / length * half};
  return {std::move(name),
          {{from.x + left.x, from.y + left.y}, {to.x + left.x, to.y + left.y}},
          {from, to},
          {{from.x - left.x, from.y - left.y}, {to.x - left.x, to.y - left.y}}};
}

std::set<std::string> connectors_of(const MapDescription& map, const std::string& junction) {
  std::set<std::string> ids;
  for (const LaneDescription& lane : map.lanes)
    if (lane.junction == junction && lane.turn != LaneTurn::none) ids.insert(lane.id);
  return ids;
}

// East: 200 m of two lanes each way (7 m halves); north: 200 m of one lane each way crossing it
// at x = 100. Along east the junction reaches north's 3.5 m half and 6 m to turn in, 9.5 m either
// side; along north, 13 m.
MapDescription crossroads() {
  return describe_outline_map(
      "blank", {road("east", {0, 0}, {200, 0}, 7), road("north", {100, -100}, {100, 100}, 3.5)});
}

TEST(OutlineJunctions, CrossingRoadsAreCutIntoPiecesWithTheJunctionsStretchBetween) {
  const MapDescription map = crossroads();
  ASSERT_EQ(map.junctions.size(), 1u);
  EXPECT_EQ(map.junctions[0].id, "junction_east_north");
  const LaneDescription& before = lane_of(map, "east_f0_1");
  const LaneDescription& inside = lane_of(map, "east_f0_2");
  const LaneDescription& after = lane_of(map, "east_f0_3");
  EXPECT_NEAR(before.centre_line.back().x, 90.5, 1e-9);
  EXPECT_NEAR(inside.centre_line.front().x, 90.5, 1e-9);
  EXPECT_NEAR(inside.centre_line.back().x, 109.5, 1e-9);
  EXPECT_NEAR(after.centre_line.front().x, 109.5, 1e-9);
  EXPECT_NEAR(after.centre_line.back().x, 200, 1e-9);
  EXPECT_EQ(before.junction, "");
  EXPECT_EQ(inside.junction, "junction_east_north");
  EXPECT_EQ(inside.turn, LaneTurn::none);
  EXPECT_TRUE(before.junction.empty() && after.junction.empty());
  // Backward lanes are numbered in their own driving direction: east_b0_1 starts at x = 200.
  EXPECT_NEAR(lane_of(map, "east_b0_1").centre_line.front().x, 200, 1e-9);
  EXPECT_NEAR(lane_of(map, "east_b0_3").centre_line.back().x, 0, 1e-9);
  EXPECT_NEAR(lane_of(map, "north_f0_1").centre_line.back().y, -13, 1e-9);
  // Outside junctions lanes keep their neighbours; inside there are none.
  EXPECT_THAT(before.right_forward_neighbours, ElementsAre("east_f1_1"));
  EXPECT_THAT(before.left_reverse_neighbours, ElementsAre("east_b0_3"));
  EXPECT_THAT(inside.right_forward_neighbours, IsEmpty());
  EXPECT_THAT(inside.left_reverse_neighbours, IsEmpty());
  // The junction's outline is the hull of the cuts across both roads.
  EXPECT_EQ(map.junctions[0].outline.size(), 8u);
}

// Eastbound, right is south (north's backward lanes, north_b0_3 its first piece south of the
// junction) and left is north (north_f0_3); the right turn leaves from the kerb lane east_f1.
TEST(OutlineJunctions, EveryArmTurnsLeftFromBesideTheCentreLineAndRightFromTheKerb) {
  const MapDescription map = crossroads();
  EXPECT_THAT(connectors_of(map, "junction_east_north"),
              UnorderedElementsAre("east_f1_1_to_north_b0_3", "east_f0_1_to_north_f0_3",
                                   "east_b1_1_to_north_f0_3", "east_b0_1_to_north_b0_3",
                                   "north_f0_1_to_east_f1_3", "north_f0_1_to_east_b0_3",
                                   "north_b0_1_to_east_b1_3", "north_b0_1_to_east_f0_3"));
  const LaneDescription& right = lane_of(map, "east_f1_1_to_north_b0_3");
  EXPECT_EQ(right.turn, LaneTurn::right);
  EXPECT_EQ(lane_of(map, "east_f0_1_to_north_f0_3").turn, LaneTurn::left);
  // Tangent to both lanes, ends on them.
  EXPECT_NEAR(right.centre_line.front().x, 90.5, 1e-9);
  EXPECT_NEAR(right.centre_line.front().y, -5.25, 1e-9);
  EXPECT_NEAR(right.centre_line.back().x, 98.25, 1e-9);
  EXPECT_NEAR(right.centre_line.back().y, -13, 1e-9);
  const std::vector<MapPoint>& line = right.centre_line;
  const std::size_t n = line.size();
  EXPECT_NEAR(std::atan2(line[1].y - line[0].y, line[1].x - line[0].x), 0, 0.05);
  EXPECT_NEAR(std::atan2(line[n - 1].y - line[n - 2].y, line[n - 1].x - line[n - 2].x),
              -std::numbers::pi / 2, 0.05);
  EXPECT_THAT(lane_of(map, "east_f1_1").successors,
              UnorderedElementsAre("east_f1_2", "east_f1_1_to_north_b0_3"));
  EXPECT_THAT(right.successors, ElementsAre("north_b0_3"));
  EXPECT_THAT(
      lane_of(map, "north_b0_3").predecessors,
      UnorderedElementsAre("north_b0_2", "east_f1_1_to_north_b0_3", "east_b0_1_to_north_b0_3"));
}

TEST(OutlineJunctions, AChainFindsThePieceOfAWrittenPlaceAlongTheWholeLane) {
  const RoadMap map = build_road_map(crossroads());
  const std::optional<LaneStation> ahead = map.find_lane_station("east_f0", 150);
  ASSERT_TRUE(ahead);
  EXPECT_EQ(map.lane(ahead->lane).id, "east_f0_3");
  EXPECT_NEAR(ahead->s, 40.5, 1e-9);
  const std::optional<LaneStation> inside = map.find_lane_station("east_f0", 100);
  ASSERT_TRUE(inside);
  EXPECT_EQ(map.lane(inside->lane).id, "east_f0_2");
  EXPECT_NEAR(inside->s, 9.5, 1e-9);
  // Backward: s counts from x = 200.
  const std::optional<LaneStation> back = map.find_lane_station("east_b1", 10);
  ASSERT_TRUE(back);
  EXPECT_EQ(map.lane(back->lane).id, "east_b1_1");
  EXPECT_NEAR(back->s, 10, 1e-9);
  EXPECT_EQ(map.lane(map.find_lane_station("east_f0_1", 5)->lane).id, "east_f0_1");
  EXPECT_FALSE(map.find_lane_station("east_f7", 5));
  ASSERT_EQ(map.junctions().size(), 1u);
  EXPECT_EQ(map.junctions()[0].lanes.size(), 4u + 2u + 8u);  // through lanes, then turns
}

// A side road from the south ending at the main road's right edge: the main road crosses the
// junction, the side road ends in it (its stretch there is dropped), and its lanes turn both ways.
TEST(OutlineJunctions, ARoadEndingAtAnothersEdgeMakesAJunctionOfThreeArms) {
  const MapDescription map = describe_outline_map(
      "blank", {road("main", {0, 0}, {200, 0}, 3.5), road("side", {100, -100}, {100, -3.5}, 3.5)});
  ASSERT_EQ(map.junctions.size(), 1u);
  EXPECT_THAT(connectors_of(map, "junction_main_side"),
              UnorderedElementsAre("side_f0_1_to_main_f0_3", "side_f0_1_to_main_b0_3",
                                   "main_f0_1_to_side_b0_1", "main_b0_1_to_side_b0_1"));
  // The side road's stretch inside the junction is dropped: it ends 9.5 m before the main
  // road's centre line, which the junction reaches 3.5 + 6 m along it.
  EXPECT_NEAR(lane_of(map, "side_f0_1").centre_line.back().y, -9.5, 1e-9);
  EXPECT_THAT(lane_of(map, "side_f0_1").successors,
              UnorderedElementsAre("side_f0_1_to_main_f0_3", "side_f0_1_to_main_b0_3"));
  // A chain's s still counts from the side road's written end for its backward lane.
  const RoadMap built = build_road_map(map);
  const std::optional<LaneStation> side = built.find_lane_station("side_b0", 13);
  ASSERT_TRUE(side);
  EXPECT_EQ(built.lane(side->lane).id, "side_b0_1");
  EXPECT_NEAR(side->s, 7, 1e-9);
}

TEST(OutlineJunctions, RoadsMeetingEndToStartTurnThroughAJunctionBeyondSixtyDegrees) {
  const MapDescription straight_on = describe_outline_map(
      "blank", {road("a", {0, 0}, {100, 0}, 3.5), road("b", {100, 0}, {150, 40}, 3.5)});
  EXPECT_THAT(straight_on.junctions, IsEmpty());
  EXPECT_THAT(lane_of(straight_on, "a_f0").successors, ElementsAre("b_f0"));

  const MapDescription corner = describe_outline_map(
      "blank", {road("a", {0, 0}, {100, 0}, 3.5), road("b", {100, 0}, {100, 100}, 3.5)});
  ASSERT_EQ(corner.junctions.size(), 1u);
  EXPECT_THAT(connectors_of(corner, "junction_a_b"),
              UnorderedElementsAre("a_f0_1_to_b_f0_1", "b_b0_1_to_a_b0_1"));
  EXPECT_EQ(lane_of(corner, "a_f0_1_to_b_f0_1").turn, LaneTurn::left);
}

TEST(OutlineJunctions, WhatCannotBeAJunctionIsAnErrorNamingTheRoads) {
  EXPECT_THAT(
      outline_error({road("a", {0, 0}, {200, 0}, 3.5), road("b", {0, -30}, {200, 40}, 3.5)}),
      HasSubstr("road 'a': it meets road 'b' at (85.71, 0) at 19.29 degrees; scenfuzz "
                "makes a junction only of roads meeting at 30 degrees or more"));
  EXPECT_THAT(
      outline_error({road("a", {0, 0}, {200, 0}, 3.5), road("b", {100, -5}, {100, 5}, 3.5)}),
      HasSubstr("road 'b': it is too short to leave its junction with road 'a'"));
  EXPECT_THAT(
      outline_error({road("a", {0, 0}, {200, 0}, 3.5), road("b", {100, -50}, {100, 50}, 3.5),
                     road("c", {110, -50}, {110, 50}, 3.5)}),
      HasSubstr("road 'a': its junctions at (100, 0) and (110, 0) overlap along it"));
}

// The signal's road (east) shows red at the start of its red phase; north has its red's last
// 2 s (the all-red gap), then its green; east goes green 2 s after north's yellow ends.
TEST(OutlineJunctions, ATrafficLightGivesEachRoadALightTakingTurnsFromTheSignalsColour) {
  const MapDescription description = describe_outline_map(
      "blank", {road("east", {0, 0}, {200, 0}, 7), road("north", {100, -100}, {100, 100}, 3.5)},
      {{"light", {90, 5}, "east", SignalColour::red}});
  ASSERT_EQ(description.traffic_lights.size(), 2u);
  const TrafficLightDescription& east = description.traffic_lights[0];
  EXPECT_EQ(east.id, "light_east");
  EXPECT_EQ(description.traffic_lights[1].id, "light_north");
  ASSERT_EQ(east.lanes.size(), 4u);
  EXPECT_EQ(east.lanes[0].lane, "east_f0_1");
  EXPECT_NEAR(east.lanes[0].s_begin, 90.5, 1e-9);
  EXPECT_EQ(east.stop_lines.size(), 2u);
  const RoadMap map = build_road_map(description);
  TrafficSignals signals(map, {});
  const auto colours = [&](double t) {
    const std::vector<SignalColour>& at = signals.colours_at(t);
    return std::vector<SignalColour>(at.begin(), at.end());
  };
  using enum SignalColour;
  EXPECT_THAT(colours(0), ElementsAre(red, red));
  EXPECT_THAT(colours(3), ElementsAre(red, green));
  EXPECT_THAT(colours(28), ElementsAre(red, yellow));
  EXPECT_THAT(colours(31), ElementsAre(red, red));
  EXPECT_THAT(colours(33), ElementsAre(green, red));
  // The east lanes coming in stop at the light; the turns and the lanes leaving do not.
  const Lane& in = map.lane(*map.find_lane("east_f0_1"));
  ASSERT_EQ(in.features.size(), 1u);
  EXPECT_EQ(in.features[0].kind, FeatureKind::traffic_light);
  EXPECT_THAT(map.lane(*map.find_lane("east_f0_3")).features, IsEmpty());
}

TEST(OutlineJunctions, ALightNeedsAJunctionOfItsOwn) {
  EXPECT_THAT(
      outline_error({road("east", {0, 0}, {200, 0}, 7)},
                    {{"light", {50, 0}, "east", SignalColour::red}}),
      HasSubstr("traffic light 'light': the road network has no junction for it to control"));
  EXPECT_THAT(outline_error(
                  {road("east", {0, 0}, {200, 0}, 7), road("north", {100, -100}, {100, 100}, 3.5)},
                  {{"one", {90, 0}, "east", SignalColour::red},
                   {"two", {0, 0}, "north", SignalColour::green}}),
              HasSubstr("traffic lights 'one' and 'two' are both nearest junction_east_north"));
}

}  // namespace
}  // namespace scenfuzz
