// Lane maps from road outlines (physics/map/outline_map.hpp) against the rules of its header:
// lane counts and widths from the halves' widths, ids and driving directions, lane positions,
// neighbours and boundary types, a bend, connections of roads laid end to end (crossings and
// sharper turns are junctions: outline_junctions_test.cpp), every error with its message, and the
// result built into a RoadMap, directly and through load_scenario_map.
#include "physics/map/outline_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "lang/scenario.hpp"
#include "lang/value.hpp"
#include "outline_fixtures.hpp"
#include "physics/map/map_source.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

using test::lane_of;
using test::outline_error;

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::StartsWith;
using ::testing::UnorderedElementsAre;

constexpr double kTolerance = 1e-9;

// A straight road along +x from x0 to x1, its centre line on y = 0, its left boundary at
// y = left and its right boundary at y = -right.
RoadOutlineGeometry straight_road(std::string name, double x0, double x1, double left,
                                  double right) {
  return {
      std::move(name), {{x0, left}, {x1, left}}, {{x0, 0}, {x1, 0}}, {{x0, -right}, {x1, -right}}};
}

// The CH-Scenario grammar's worked example: a 400 m by 50 m road, its centre line in the middle.
RoadOutlineGeometry worked_example_road() {
  return {"narrow_road", {{0, 50}, {400, 50}}, {{0, 25}, {400, 25}}, {{0, 0}, {400, 0}}};
}

std::set<std::string> lane_ids(const MapDescription& map) {
  std::set<std::string> ids;
  for (const LaneDescription& lane : map.lanes) ids.insert(lane.id);
  return ids;
}

// Every width sample on both sides of the lane is `half_width`, within `tolerance`.
void expect_half_widths(const LaneDescription& lane, double half_width, double tolerance) {
  ASSERT_FALSE(lane.left_width.empty()) << lane.id;
  ASSERT_FALSE(lane.right_width.empty()) << lane.id;
  for (const auto* side : {&lane.left_width, &lane.right_width})
    for (const WidthSample& sample : *side)
      EXPECT_NEAR(sample.width, half_width, tolerance) << lane.id << " at s " << sample.s;
}

double heading_of(const LaneDescription& lane) {
  const MapPoint a = lane.centre_line.front(), b = lane.centre_line.back();
  return std::atan2(b.y - a.y, b.x - a.x);
}

TEST(OutlineMap, WorkedExampleRoadHasSevenLanesEachWayOf25Over7Metres) {
  const MapDescription map = describe_outline_map("blank", {worked_example_road()});
  EXPECT_EQ(map.name, "blank");
  EXPECT_EQ(map.source, "CH-Scenario road network");
  EXPECT_EQ(map.default_lane_width, 3.5);
  EXPECT_EQ(map.projection, "");
  ASSERT_EQ(map.lanes.size(), 14u);
  const double width = 25.0 / 7;
  for (int k = 0; k < 7; ++k) {
    const LaneDescription& forward = lane_of(map, "narrow_road_f" + std::to_string(k));
    const LaneDescription& backward = lane_of(map, "narrow_road_b" + std::to_string(k));
    expect_half_widths(forward, width / 2, kTolerance);
    expect_half_widths(backward, width / 2, kTolerance);
    // Forward lanes drive east below the centre line, backward lanes west above it.
    EXPECT_NEAR(heading_of(forward), 0, kTolerance) << forward.id;
    EXPECT_NEAR(std::abs(heading_of(backward)), std::numbers::pi, kTolerance) << backward.id;
    EXPECT_NEAR(forward.centre_line.front().x, 0, kTolerance);
    EXPECT_NEAR(forward.centre_line.back().x, 400, kTolerance);
    EXPECT_NEAR(backward.centre_line.front().x, 400, kTolerance);
    EXPECT_NEAR(backward.centre_line.back().x, 0, kTolerance);
    for (MapPoint point : forward.centre_line) EXPECT_NEAR(point.y, 25 - (k + 0.5) * width, 1e-9);
    for (MapPoint point : backward.centre_line) EXPECT_NEAR(point.y, 25 + (k + 0.5) * width, 1e-9);
    // The inner edge is the lane's left in both directions.
    EXPECT_NEAR(forward.left_boundary.front().y, 25 - k * width, 1e-9);
    EXPECT_NEAR(forward.right_boundary.front().y, 25 - (k + 1) * width, 1e-9);
    EXPECT_NEAR(backward.left_boundary.front().y, 25 + k * width, 1e-9);
    EXPECT_NEAR(backward.right_boundary.front().y, 25 + (k + 1) * width, 1e-9);
  }
  // Sampled every 5 m: 81 points over 400 m, width samples at the lane's own arc length.
  const LaneDescription& f3 = lane_of(map, "narrow_road_f3");
  ASSERT_EQ(f3.centre_line.size(), 81u);
  EXPECT_NEAR(f3.left_width[1].s, 5, kTolerance);
  EXPECT_NEAR(f3.left_width.back().s, 400, kTolerance);
  EXPECT_NEAR(lane_of(map, "narrow_road_b3").left_width.back().s, 400, kTolerance);
  EXPECT_EQ(lane_of(map, "narrow_road_f6").right_boundary_type, BoundaryType::curb);
  EXPECT_EQ(lane_of(map, "narrow_road_b6").right_boundary_type, BoundaryType::curb);
}

TEST(OutlineMap, SevenMetreTwoWayRoadHasOneLaneEachWayWithTheCentreLineBetween) {
  const MapDescription map =
      describe_outline_map("blank", {straight_road("narrow_road", 0, 100, 3.5, 3.5)});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"narrow_road_f0", "narrow_road_b0"}));
  const LaneDescription& f0 = lane_of(map, "narrow_road_f0");
  const LaneDescription& b0 = lane_of(map, "narrow_road_b0");
  expect_half_widths(f0, 1.75, kTolerance);
  expect_half_widths(b0, 1.75, kTolerance);
  EXPECT_NEAR(f0.centre_line.front().y, -1.75, kTolerance);
  EXPECT_NEAR(b0.centre_line.front().y, 1.75, kTolerance);
  EXPECT_THAT(f0.left_reverse_neighbours, ElementsAre("narrow_road_b0"));
  EXPECT_THAT(b0.left_reverse_neighbours, ElementsAre("narrow_road_f0"));
  for (const LaneDescription* lane : {&f0, &b0}) {
    EXPECT_THAT(lane->left_forward_neighbours, IsEmpty());
    EXPECT_THAT(lane->right_forward_neighbours, IsEmpty());
    EXPECT_THAT(lane->right_reverse_neighbours, IsEmpty());
    EXPECT_EQ(lane->left_boundary_type, BoundaryType::dotted_yellow);
    EXPECT_EQ(lane->right_boundary_type, BoundaryType::curb);
    EXPECT_THAT(lane->successors, IsEmpty());
    EXPECT_THAT(lane->predecessors, IsEmpty());
  }
}

TEST(OutlineMap, RoadWhoseLeftBoundaryIsItsCentreLineIsOneWay) {
  // 7 m to the right: two forward lanes, none backward.
  const MapDescription map =
      describe_outline_map("blank", {straight_road("one_way", 0, 100, 0, 7)});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"one_way_f0", "one_way_f1"}));
  const LaneDescription& f0 = lane_of(map, "one_way_f0");
  const LaneDescription& f1 = lane_of(map, "one_way_f1");
  EXPECT_THAT(f0.right_forward_neighbours, ElementsAre("one_way_f1"));
  EXPECT_THAT(f1.left_forward_neighbours, ElementsAre("one_way_f0"));
  EXPECT_THAT(f0.left_reverse_neighbours, IsEmpty());
  // With no lanes across it, the centre line is the road's edge.
  EXPECT_EQ(f0.left_boundary_type, BoundaryType::curb);
  EXPECT_EQ(f0.right_boundary_type, BoundaryType::dotted_white);
  EXPECT_EQ(f1.left_boundary_type, BoundaryType::dotted_white);
  EXPECT_EQ(f1.right_boundary_type, BoundaryType::curb);
  // A left half narrower than 1 m everywhere carries no lane either.
  EXPECT_EQ(lane_ids(describe_outline_map("blank", {straight_road("one_way", 0, 100, 0.9, 7)})),
            (std::set<std::string>{"one_way_f0", "one_way_f1"}));
  // One at least 1 m wide somewhere does: a lane, however narrow the half's mean.
  RoadOutlineGeometry widening = straight_road("one_way", 0, 100, 0.2, 7);
  widening.left_boundary.back().y = 1.2;
  EXPECT_EQ(lane_ids(describe_outline_map("blank", {widening})),
            (std::set<std::string>{"one_way_f0", "one_way_f1", "one_way_b0"}));
}

TEST(OutlineMap, RoadOfThreeLanesEachWayHasNeighboursAndBoundaryTypesAcross) {
  const MapDescription map =
      describe_outline_map("blank", {straight_road("wide", 0, 60, 10.5, 10.5)});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"wide_f0", "wide_f1", "wide_f2", "wide_b0",
                                                  "wide_b1", "wide_b2"}));
  for (const char* direction : {"f", "b"}) {
    const std::string prefix = std::string("wide_") + direction;
    const LaneDescription& lane0 = lane_of(map, prefix + "0");
    const LaneDescription& lane1 = lane_of(map, prefix + "1");
    const LaneDescription& lane2 = lane_of(map, prefix + "2");
    const double side = direction[0] == 'f' ? -1 : 1;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(lane_of(map, prefix + std::to_string(k)).centre_line.front().y,
                  side * (k + 0.5) * 3.5, kTolerance);
    EXPECT_THAT(lane0.left_forward_neighbours, IsEmpty());
    EXPECT_THAT(lane0.right_forward_neighbours, ElementsAre(prefix + "1"));
    EXPECT_THAT(lane1.left_forward_neighbours, ElementsAre(prefix + "0"));
    EXPECT_THAT(lane1.right_forward_neighbours, ElementsAre(prefix + "2"));
    EXPECT_THAT(lane2.left_forward_neighbours, ElementsAre(prefix + "1"));
    EXPECT_THAT(lane2.right_forward_neighbours, IsEmpty());
    EXPECT_THAT(lane0.left_reverse_neighbours,
                ElementsAre(direction[0] == 'f' ? "wide_b0" : "wide_f0"));
    EXPECT_THAT(lane1.left_reverse_neighbours, IsEmpty());
    EXPECT_THAT(lane2.left_reverse_neighbours, IsEmpty());
    EXPECT_EQ(lane0.left_boundary_type, BoundaryType::dotted_yellow);
    EXPECT_EQ(lane0.right_boundary_type, BoundaryType::dotted_white);
    EXPECT_EQ(lane1.left_boundary_type, BoundaryType::dotted_white);
    EXPECT_EQ(lane1.right_boundary_type, BoundaryType::dotted_white);
    EXPECT_EQ(lane2.left_boundary_type, BoundaryType::dotted_white);
    EXPECT_EQ(lane2.right_boundary_type, BoundaryType::curb);
  }
}

TEST(OutlineMap, HalfLaneCountIsItsMeanWidthOver3Point5Rounded) {
  // 5 m: round(1.43) = 1 lane of 5 m; 9 m: round(2.57) = 3 lanes of 3 m.
  const MapDescription map = describe_outline_map("blank", {straight_road("r", 0, 50, 5, 9)});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"r_b0", "r_f0", "r_f1", "r_f2"}));
  expect_half_widths(lane_of(map, "r_b0"), 2.5, kTolerance);
  expect_half_widths(lane_of(map, "r_f2"), 1.5, kTolerance);
}

// A point at `radius` from the origin at `degrees` counter-clockwise from +x.
MapPoint on_circle(double radius, double degrees) {
  const double angle = degrees * std::numbers::pi / 180;
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

// Points of a quarter circle every `step` degrees, counter-clockwise from +x.
std::vector<MapPoint> quarter_circle(double radius, double step) {
  std::vector<MapPoint> points;
  for (double degrees = 0; degrees <= 90 + 1e-9; degrees += step)
    points.push_back(on_circle(radius, degrees));
  return points;
}

TEST(OutlineMap, BendKeepsItsLaneWidthsAndLanesDoNotCross) {
  // Counter-clockwise about the origin, radius 50: the left half is inside the bend. The
  // boundaries have three times as many points as the centre line.
  const RoadOutlineGeometry bend{"bend", quarter_circle(43, 1), quarter_circle(50, 3),
                                 quarter_circle(57, 1)};
  const MapDescription map = describe_outline_map("blank", {bend});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"bend_f0", "bend_f1", "bend_b0", "bend_b1"}));
  // Each lane keeps to its own ring, so no two cross.
  const std::vector<std::pair<std::string, double>> rings = {
      {"bend_b1", 44.75}, {"bend_b0", 48.25}, {"bend_f0", 51.75}, {"bend_f1", 55.25}};
  for (const auto& [id, radius] : rings) {
    const LaneDescription& lane = lane_of(map, id);
    expect_half_widths(lane, 1.75, 0.01);
    for (MapPoint point : lane.centre_line)
      EXPECT_NEAR(std::hypot(point.x, point.y), radius, 0.01) << id;
    for (MapPoint point : lane.left_boundary)
      EXPECT_NEAR(std::hypot(point.x, point.y), radius + (id[5] == 'f' ? -1.75 : 1.75), 0.01);
    for (MapPoint point : lane.right_boundary)
      EXPECT_NEAR(std::hypot(point.x, point.y), radius + (id[5] == 'f' ? 1.75 : -1.75), 0.01);
  }
  // Forward lanes start heading north at (51.75, 0) and turn left; backward lanes start at
  // (0, 48.25) heading east. An end is offset square to the end chord (1.5 degrees off the
  // radius), hence the tolerance.
  EXPECT_NEAR(lane_of(map, "bend_f0").centre_line.front().x, 51.75, 0.01);
  EXPECT_NEAR(lane_of(map, "bend_f0").centre_line.front().y, 0, 0.05);
  EXPECT_NEAR(lane_of(map, "bend_b0").centre_line.front().x, 0, 0.05);
  EXPECT_NEAR(lane_of(map, "bend_b0").centre_line.front().y, 48.25, 0.01);
  const RoadMap road_map = build_road_map(map);
  const Lane& f1 = road_map.lane(*road_map.find_lane("bend_f1"));
  EXPECT_NEAR(f1.narrowest_left_width + f1.narrowest_right_width, 3.5, 0.02);
  // A quarter circle of radius 55.25, less what the square-cut ends take off.
  EXPECT_NEAR(f1.length(), 55.25 * std::numbers::pi / 2, 0.5);
}

TEST(OutlineMap, RoadsLaidEndToEndAreConnectedBothWays) {
  const MapDescription map = describe_outline_map(
      "blank", {straight_road("a", 0, 100, 7, 7), straight_road("b", 100, 250, 7, 7)});
  for (const std::string k : {"0", "1"}) {
    EXPECT_THAT(lane_of(map, "a_f" + k).successors, ElementsAre("b_f" + k));
    EXPECT_THAT(lane_of(map, "b_f" + k).predecessors, ElementsAre("a_f" + k));
    EXPECT_THAT(lane_of(map, "a_f" + k).predecessors, IsEmpty());
    EXPECT_THAT(lane_of(map, "b_f" + k).successors, IsEmpty());
    // Road b's backward lanes end where road a's begin.
    EXPECT_THAT(lane_of(map, "b_b" + k).successors, ElementsAre("a_b" + k));
    EXPECT_THAT(lane_of(map, "a_b" + k).predecessors, ElementsAre("b_b" + k));
    EXPECT_THAT(lane_of(map, "a_b" + k).successors, IsEmpty());
    EXPECT_THAT(lane_of(map, "b_b" + k).predecessors, IsEmpty());
  }
  const RoadMap road_map = build_road_map(map);
  const LaneIndex a_f0 = *road_map.find_lane("a_f0");
  const LaneIndex b_f0 = *road_map.find_lane("b_f0");
  EXPECT_THAT(road_map.lane(a_f0).successors, ElementsAre(b_f0));
  EXPECT_THAT(road_map.lane(b_f0).predecessors, ElementsAre(a_f0));
}

// A one-way road of one 3.5 m lane whose lane starts at `start` heading `degrees`.
RoadOutlineGeometry one_lane_road(std::string name, MapPoint start, double degrees) {
  const double angle = degrees * std::numbers::pi / 180;
  const MapPoint along{std::cos(angle), std::sin(angle)};
  const MapPoint left{-along.y, along.x};
  // The centre line is the lane's left edge, 1.75 m to the left of the lane's centre.
  const MapPoint c0{start.x + 1.75 * left.x, start.y + 1.75 * left.y};
  const MapPoint c1{c0.x + 50 * along.x, c0.y + 50 * along.y};
  const MapPoint r0{c0.x - 3.5 * left.x, c0.y - 3.5 * left.y};
  const MapPoint r1{c1.x - 3.5 * left.x, c1.y - 3.5 * left.y};
  return {std::move(name), {c0, c1}, {c0, c1}, {r0, r1}};
}

// Each pair alone: roads that start together would meet one another in junctions too.
TEST(OutlineMap, LanesConnectWithinOnePointFiveMetresAndSixtyDegrees) {
  // Lane "in_f0" ends at (50, -1.75) heading east.
  const RoadOutlineGeometry in = one_lane_road("in", {0, -1.75}, 0);
  const auto successors = [&](const RoadOutlineGeometry& next) {
    return lane_of(describe_outline_map("blank", {in, next}), "in_f0").successors;
  };
  EXPECT_THAT(successors(one_lane_road("bend_50", {50, -1.75}, 50)), ElementsAre("bend_50_f0"));
  EXPECT_THAT(successors(one_lane_road("near", {51.4, -1.75}, 0)), ElementsAre("near_f0"));
  EXPECT_THAT(successors(one_lane_road("far", {51.6, -1.75}, 0)), IsEmpty());
}

TEST(OutlineMap, PolylinesNeedTwoFinitePointsAndTheCentreLineALength) {
  RoadOutlineGeometry road = straight_road("r", 0, 100, 3.5, 3.5);
  road.centre_line.pop_back();
  EXPECT_EQ(outline_error({road}), "road 'r': the centre line needs at least two points, it has 1");
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.left_boundary.clear();
  EXPECT_EQ(outline_error({road}),
            "road 'r': the left boundary needs at least two points, it has 0");
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.right_boundary.pop_back();
  EXPECT_THAT(outline_error({road}), StartsWith("road 'r': the right boundary needs"));
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.centre_line = {{10, 0}, {10, 0}, {10, 0}};
  EXPECT_EQ(outline_error({road}),
            "road 'r': the centre line has zero length (all its points are at (10, 0))");
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.right_boundary[1].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(outline_error({road}),
              StartsWith("road 'r': point 2 of the right boundary is not finite"));
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.centre_line[0].x = std::numeric_limits<double>::infinity();
  EXPECT_THAT(outline_error({road}),
              StartsWith("road 'r': point 1 of the centre line is not finite"));
}

TEST(OutlineMap, BoundaryCrossingTheCentreLineIsAnErrorNamingThePoint) {
  RoadOutlineGeometry road = straight_road("r", 0, 100, 3.5, 3.5);
  road.right_boundary = {{0, -3.5}, {50, 1}, {100, -3.5}};
  EXPECT_EQ(outline_error({road}),
            "road 'r': point 2 (50, 1) of the right boundary lies 1 m left of the centre line: "
            "the boundary crosses to the other side");
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.left_boundary = {{0, 3.5}, {40, 3.5}, {100, -0.25}};
  EXPECT_EQ(outline_error({road}),
            "road 'r': point 3 (100, -0.25) of the left boundary lies 0.25 m right of the centre "
            "line: the boundary crosses to the other side");
  // Within a centimetre of the centre line is on it: a one-way road draws its left boundary there.
  road = straight_road("r", 0, 100, 3.5, 3.5);
  road.left_boundary = {{0, 0}, {30, -0.005}, {100, 0}};
  EXPECT_EQ(outline_error({road}), "no error");
}

TEST(OutlineMap, RoadWithoutLanesAndBadRoadListsAreErrors) {
  EXPECT_THAT(outline_error({straight_road("thin", 0, 100, 0.5, 0.9)}),
              StartsWith("road 'thin': the road has no lanes: both halves are narrower than 1 m"));
  EXPECT_EQ(
      outline_error({straight_road("r", 0, 100, 3.5, 3.5), straight_road("r", 100, 200, 3.5, 3.5)}),
      "road 'r': two roads have this name");
  EXPECT_EQ(outline_error({}), "map 'blank': the road network has no roads");
  EXPECT_EQ(
      outline_error({straight_road("r", 0, 100, 3.5, 3.5), straight_road("", 100, 200, 3.5, 3.5)}),
      "map 'blank': road 2 of the road network has no name");
}

TEST(OutlineMap, WorkedExampleBuildsIntoARoadMap) {
  const RoadMap map = build_road_map(describe_outline_map("blank", {worked_example_road()}));
  EXPECT_EQ(map.name(), "blank");
  EXPECT_EQ(map.source(), "CH-Scenario road network");
  EXPECT_THAT(map.warnings(), IsEmpty());
  ASSERT_EQ(map.lanes().size(), 14u);
  const LaneIndex f0 = *map.find_lane("narrow_road_f0");
  const LaneIndex f1 = *map.find_lane("narrow_road_f1");
  const LaneIndex b0 = *map.find_lane("narrow_road_b0");
  EXPECT_THAT(map.lane(f0).right_forward_neighbours, ElementsAre(f1));
  EXPECT_THAT(map.lane(f0).left_reverse_neighbours, ElementsAre(b0));
  EXPECT_THAT(map.lane(b0).left_reverse_neighbours, ElementsAre(f0));
  for (const Lane& lane : map.lanes()) {
    EXPECT_NEAR(lane.length(), 400, kTolerance) << lane.id;
    EXPECT_NEAR(lane.narrowest_left_width + lane.narrowest_right_width, 25.0 / 7, kTolerance);
  }
  EXPECT_NEAR(map.bounds().min.y, 0, kTolerance);
  EXPECT_NEAR(map.bounds().max.y, 50, kTolerance);
}

Point constant_point(double x, double y) { return {constant_value(x), constant_value(y)}; }

TEST(OutlineMap, LoadScenarioMapBuildsTheRoadsOfAMapReference) {
  // The left boundary's y is search parameter 0: 7 m gives two backward lanes. 45 km/h.
  MapReference reference;
  reference.name = "blank";
  reference.roads.push_back(
      {"narrow_road",
       {{constant_value(0), parameter_value(0)}, {constant_value(100), parameter_value(0)}},
       {constant_point(0, 0), constant_point(100, 0)},
       {constant_point(0, -3.5), constant_point(100, -3.5)},
       constant_value(12.5),
       {}});
  const std::vector<double> values = {7.0};
  const RoadMap map = load_scenario_map(reference, map_search_path({}), values);
  EXPECT_EQ(map.name(), "blank");
  EXPECT_EQ(map.source(), "CH-Scenario road network");
  std::set<std::string> ids;
  for (const Lane& lane : map.lanes()) ids.insert(lane.id);
  EXPECT_EQ(ids, (std::set<std::string>{"narrow_road_f0", "narrow_road_b0", "narrow_road_b1"}));
  const Lane& b1 = map.lane(*map.find_lane("narrow_road_b1"));
  EXPECT_NEAR(b1.centre_line.points().front().y, 5.25, kTolerance);
  // The road's speed limit is every lane's.
  for (const Lane& lane : map.lanes()) EXPECT_EQ(lane.speed_limit, 12.5) << lane.id;
  // Bad geometry is reported as for any map.
  reference.roads[0].right_boundary[1] = constant_point(100, 2);
  try {
    load_scenario_map(reference, map_search_path({}), values);
    ADD_FAILURE() << "no MapError";
  } catch (const MapError& error) {
    EXPECT_THAT(error.what(),
                HasSubstr("road 'narrow_road': point 2 (100, 2) of the right boundary"));
  }
}

}  // namespace
}  // namespace scenfuzz
