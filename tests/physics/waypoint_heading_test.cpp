// The heading a waypoint without one gets (waypoint_path.hpp, waypoint_heading): its lane's
// direction, unless that lane runs against the way the actor comes to it.
#include <gtest/gtest.h>

#include <numbers>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/simulation/waypoint_path.hpp"

namespace scenfuzz {
namespace {

constexpr double kPi = std::numbers::pi;

// The built-in two-way "straight": east lanes below y = 0, west lanes above.
RoadMap two_way_road() { return build_road_map(generate_builtin_map("straight", {})); }

TEST(WaypointHeadingTest, AWaypointInItsWayLaneFacesAlongIt) {
  const RoadMap map = two_way_road();
  EXPECT_DOUBLE_EQ(waypoint_heading(map, {100, -5.25}, {150, -1.75}, 0.0), 0.0);
}

TEST(WaypointHeadingTest, AWaypointJustOverTheCentreLineFacesTheWayTheCarComes) {
  const RoadMap map = two_way_road();
  // Coming west along y = 1.75 to a point 0.1 m into the eastbound lane, whose direction is 0.
  const double heading = waypoint_heading(map, {347, 1.75}, {147, -0.1}, 0.0);
  EXPECT_NEAR(std::abs(angle_difference(heading, kPi)), 0, 0.05);
}

TEST(WaypointHeadingTest, AWaypointAgainstItsLaneFarFromAnyLaneTheWayItComesKeepsItsLanes) {
  const RoadMap map = two_way_road();
  // Coming east to the middle of the outer westbound lane (y = 5.25): the nearest eastbound lane
  // is over 3 m away, so the waypoint is not a drift; it faces its lane's way (west).
  const double heading = waypoint_heading(map, {100, 5.25}, {200, 5.25}, kPi);
  EXPECT_DOUBLE_EQ(heading, kPi);
}

}  // namespace
}  // namespace scenfuzz
