// The simulation's own parts on the built-in maps: lane tracking against the map's projection,
// the ego's route tracker (features, limits, where objects lie), and traffic-signal timing.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/actors/trajectory.hpp"
#include "physics/ego/route_tracker.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/traffic_signals.hpp"

namespace scenfuzz {
namespace {

const MapSearchPath kNoSearchPath{};

LaneIndex lane(const RoadMap& map, const char* id) {
  auto found = map.find_lane(id);
  EXPECT_TRUE(found) << id;
  return found.value_or(0);
}

TEST(LaneTracker, AgreesWithTheMapAlongADriveAcrossLanesAndOffTheRoad) {
  const RoadMap map = load_map("straight", kNoSearchPath);
  LaneTracker tracker(map.widest_half_lane());
  EXPECT_DOUBLE_EQ(map.widest_half_lane(), 1.75);
  // Along east_0, across into east_1, then out onto the northern pavement and back.
  for (int i = 0; i <= 400; ++i) {
    double x = 10 + i;
    double y = i < 100   ? -5.25
               : i < 140 ? -5.25 + (i - 100) * 0.0875
               : i < 300 ? -1.75
                         : -1.75 + (i - 300) * 0.1;
    LaneFix fix = tracker.update(map, {x, y}, 0);
    auto truth = project_to_lane(map, {x, y}, 0);
    ASSERT_TRUE(truth);
    if (!truth->inside) {
      EXPECT_EQ(fix.lane, -1) << "x " << x << " y " << y;
      continue;
    }
    EXPECT_EQ(fix.lane, static_cast<std::int32_t>(truth->lane)) << "x " << x << " y " << y;
    EXPECT_NEAR(fix.s, truth->s, 1e-9);
  }
}

TEST(LaneTracker, FollowsALeftTurnThroughTheJunctionLaneByLane) {
  const RoadMap map = load_map("crossroads", kNoSearchPath);
  auto route = find_route(map, LanePosition{lane(map, "west_in_1"), 100, 0},
                          LanePosition{lane(map, "north_out_1"), 50, 0});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 3u);
  const Polyline path = route_path(map, *route);
  LaneTracker tracker(map.widest_half_lane());
  std::size_t on_segment = 0;
  for (double s = 0; s <= path.length(); s += 0.5) {
    LaneFix fix = tracker.update(map, path.point_at(s), path.heading_at(s));
    ASSERT_GE(fix.lane, 0) << "s " << s;
    // The lanes come in the route's order: never back, never one that is not on the route.
    while (on_segment < route->segments.size() &&
           static_cast<std::int32_t>(route->segments[on_segment].lane) != fix.lane)
      ++on_segment;
    ASSERT_LT(on_segment, route->segments.size()) << map.lane(static_cast<LaneIndex>(fix.lane)).id;
  }
  EXPECT_EQ(on_segment, 2u) << "it ended on north_out_1";
}

TEST(RouteTracker, FindsTheLightsAndCrosswalksOnTheWayAndTheSpeedLimit) {
  const RoadMap map = load_map("crossroads", kNoSearchPath);
  auto route = find_route(map, LanePosition{lane(map, "west_in_0"), 20, 0},
                          LanePosition{lane(map, "east_out_0"), 100, 0});
  ASSERT_TRUE(route);
  std::pair<LaneIndex, double> slower{lane(map, "east_out_0"), 8.0};
  RouteTracker tracker(map, *route, std::span(&slower, 1), 13.9);
  ASSERT_FALSE(tracker.empty());
  EXPECT_NEAR(tracker.length(), route->length, 0.5);
  // The light's stop line is at s = 144 on west_in_0: 124 m along the route.
  bool light = false;
  int crosswalks = 0;
  for (const RouteFeature& feature : tracker.features()) {
    if (feature.kind == FeatureKind::traffic_light) {
      light = true;
      EXPECT_NEAR(feature.s, 124, 0.5);
    }
    if (feature.kind == FeatureKind::crosswalk) ++crosswalks;
  }
  EXPECT_TRUE(light);
  EXPECT_EQ(crosswalks, 2) << "one before the junction, one after it";
  EXPECT_NEAR(tracker.speed_limit_at(10), 13.9, 1e-9);
  EXPECT_NEAR(tracker.speed_limit_at(tracker.length() - 1), 8.0, 1e-9) << "the scenario's limit";
  EXPECT_NEAR(tracker.curvature_at(50), 0, 1e-9) << "a straight arm";
}

TEST(RouteTracker, LocatesPointsNearTheEgoAndFollowsItsProgress) {
  const RoadMap map = load_map("straight", kNoSearchPath);
  auto route = find_route(map, LanePosition{lane(map, "east_0"), 0, 0},
                          LanePosition{lane(map, "east_0"), 400, 0});
  ASSERT_TRUE(route);
  RouteTracker tracker(map, *route, {}, 13.9);
  tracker.update({50, -5.25});
  EXPECT_LE(tracker.progress(), 22) << "progress moves at most about 20 m per update";
  for (double x = 0; x <= 50; x += 1) tracker.update({x, -5.0});
  EXPECT_NEAR(tracker.progress(), 50, 1e-9);
  auto ahead = tracker.locate({80, -3.25}, 0, 60, 10);
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(ahead->s, 80, 1e-9);
  EXPECT_NEAR(ahead->lateral, 2, 1e-9);
  EXPECT_FALSE(ahead->beyond_end);
  EXPECT_FALSE(tracker.locate({80, 20}, 0, 60, 10)) << "too far to the side";
  auto far = tracker.locate({200, -5.25}, 0, 60, 1000);
  ASSERT_TRUE(far);
  EXPECT_TRUE(far->beyond_end) << "past the stretch searched";
}

TEST(TrafficSignals, RunThePlanAndStartAtTheScenariosColour) {
  const RoadMap map = load_map("crossroads", kNoSearchPath);
  ASSERT_FALSE(map.traffic_lights().empty());
  TrafficSignals plans(map, {});
  // Cycle 60 s: each light shows green 25 s, yellow 3 s, then red, or the same half a cycle later.
  std::vector<SignalColour> at_start = plans.colours_at(0);
  std::vector<SignalColour> half_cycle = plans.colours_at(30);
  std::vector<SignalColour> full_cycle = plans.colours_at(60);
  EXPECT_EQ(at_start, full_cycle);
  for (std::size_t i = 0; i < at_start.size(); ++i) {
    EXPECT_NE(at_start[i], SignalColour::yellow);
    EXPECT_NE(at_start[i], half_cycle[i]) << "opposite half of the cycle";
  }
  // A red light set to green by the scenario starts its green phase at t = 0.
  std::uint32_t red = 0;
  while (red < at_start.size() && at_start[red] != SignalColour::red) ++red;
  ASSERT_LT(red, at_start.size());
  LightSetting green{red, SignalColour::green};
  TrafficSignals set(map, std::span(&green, 1));
  EXPECT_EQ(set.colours_at(0)[red], SignalColour::green);
  EXPECT_EQ(set.colours_at(24.9)[red], SignalColour::green);
  EXPECT_EQ(set.colours_at(26)[red], SignalColour::yellow);
  EXPECT_EQ(set.colours_at(29)[red], SignalColour::red);
}

}  // namespace
}  // namespace scenfuzz
