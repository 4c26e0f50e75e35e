// The indicators of a path drawn before the run (waypoint NPCs): a lane route drawn as a path
// indicates as the route itself does (lane changes and junction turns), and a path planned in
// free space indicates for the lanes it crosses into, out and back across the centre line too.
#include "physics/simulation/path_indications.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "physics/actors/trajectory.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/simulation/lane_tracker.hpp"

namespace scenfuzz {
namespace {

namespace sig = vehicle_signal;

RoadMap builtin(const std::string& name, const std::vector<MapParameterValue>& parameters) {
  return build_road_map(generate_builtin_map(name, parameters));
}

Polyline line(const std::vector<MapPoint>& points) { return Polyline(points); }

std::vector<IndicationStretch> indications(const RoadMap& map, const Polyline& path) {
  return path_indications(map, path, map.widest_half_lane());
}

LanePosition at(const RoadMap& map, const std::string& lane, double s) {
  return {*map.find_lane(lane), s, 0};
}

// The route from `from` to `to`, its lane changes as late as they can be (as waypoint_path
// draws a lane leg), drawn as a path and read back: the same stretches as the route's own,
// to within the 1 m the path is looked at in (and the little a sideways move adds to its length).
void expect_as_the_route(const RoadMap& map, LanePosition from, LanePosition to) {
  const auto found = find_route(map, from, to);
  ASSERT_TRUE(found);
  const LaneRoute route = defer_lane_changes(map, *found, found->length);
  constexpr double kChange = 30;
  const Polyline path = route_path(map, route, 0, kChange, 1);
  const std::vector<IndicationStretch> expected =
      route_indications(map, route.segments, lane_change_stretches(map, route, kChange));
  const std::vector<IndicationStretch> read = indications(map, path);
  ASSERT_EQ(read.size(), expected.size());
  for (std::size_t k = 0; k < read.size(); ++k) {
    EXPECT_EQ(read[k].indicator, expected[k].indicator) << k;
    EXPECT_NEAR(read[k].begin, expected[k].begin, 1.5) << k;
    EXPECT_NEAR(read[k].end, expected[k].end, 1.5) << k;
    EXPECT_EQ(read[k].least_notice, expected[k].least_notice) << k;
  }
}

// Round a roundabout only the exit is indicated, from where the exit lane leaves the ring: npc1
// of corpora/avunit/roundabout_entry.avu showed no indicator at all.
TEST(PathIndicationsTest, ARoundaboutDrawnAsAPathIndicatesOnlyItsExit) {
  const RoadMap map = builtin("roundabout", {});
  for (const char* out : {"north_out_0", "west_out_0", "east_out_0"}) {
    SCOPED_TRACE(out);
    expect_as_the_route(map, at(map, "south_in_0", 10), at(map, out, 20));
  }
}

TEST(PathIndicationsTest, ALaneChangeDrawnAsAPathIndicatesAsTheRouteDoes) {
  const RoadMap map = builtin("straight", {{"two_way", 0}});
  expect_as_the_route(map, at(map, "east_0", 40), at(map, "east_1", 200));
  expect_as_the_route(map, at(map, "east_1", 40), at(map, "east_0", 200));
  expect_as_the_route(map, at(map, "east_0", 40), at(map, "east_0", 200));  // none
}

TEST(PathIndicationsTest, AJunctionTurnDrawnAsAPathIndicatesAsTheRouteDoes) {
  const RoadMap map = builtin("crossroads", {{"lanes", 1}});
  for (const std::string arm : {"west_out_0", "east_out_0", "north_out_0"})
    expect_as_the_route(map, at(map, "south_in_0", 20), at(map, arm, 40));
}

TEST(PathIndicationsTest, AFreePathIntoTheNextLaneIndicatesWhileItMovesOver) {
  // straight?two_way=0: east_0 at y = -5.25, east_1 at y = -1.75; straight across in 30 m.
  const RoadMap map = builtin("straight", {{"two_way", 0}});
  const Polyline path = line({{10, -5.25}, {50, -5.25}, {80, -1.75}, {120, -1.75}});
  const std::vector<IndicationStretch> read = indications(map, path);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].indicator, sig::left_indicator);
  EXPECT_NEAR(read[0].begin, 40, 1.5);
  EXPECT_NEAR(read[0].end, 40 + std::hypot(30, 3.5), 1.5);
}

TEST(PathIndicationsTest, OutAcrossTheCentreLineAndBackIndicatesLeftThenRight) {
  // straight (two-way, one lane each way): east_0 at y = -1.75, west_0 at y = 1.75.
  const RoadMap map = builtin("straight", {{"lanes", 1}, {"two_way", 1}});
  const Polyline path =
      line({{10, -1.75}, {50, -1.75}, {70, 1.75}, {110, 1.75}, {130, -1.75}, {170, -1.75}});
  const std::vector<IndicationStretch> read = indications(map, path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].indicator, sig::left_indicator);
  EXPECT_EQ(read[1].indicator, sig::right_indicator);
  // Each while it moves over: 40 m along, then 20.3 m across; 40 m on, then 20.3 m back.
  const double across = std::hypot(20, 3.5);
  EXPECT_NEAR(read[0].begin, 40, 1.5);
  EXPECT_NEAR(read[0].end, 40 + across, 1.5);
  EXPECT_NEAR(read[1].begin, 80 + across, 1.5);
  EXPECT_NEAR(read[1].end, 80 + 2 * across, 1.5);
}

TEST(PathIndicationsTest, ADriftWithinTheLaneOrAnEmptyPathIndicatesNothing) {
  const RoadMap map = builtin("straight", {{"two_way", 0}});
  EXPECT_TRUE(indications(map, line({{10, -5.25}, {50, -6.5}, {90, -4.0}})).empty());
  EXPECT_TRUE(indications(map, Polyline()).empty());
}

}  // namespace
}  // namespace scenfuzz
