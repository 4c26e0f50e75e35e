// Failure-mode signatures: what the ego was doing, where, and who with, read from hand-built
// traces on the built-in maps.
#include "oracle/failure_mode.hpp"

#include <gtest/gtest.h>

#include "physics/map/builtin_maps.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::drive_east;
using test::empty_trace;
using test::still_actor;

RoadMap builtin(std::string_view name, std::vector<MapParameterValue> parameters = {}) {
  return build_road_map(generate_builtin_map(name, parameters));
}

LaneIndex lane_named(const RoadMap& map, std::string_view id) {
  const auto lane = map.find_lane(id);
  EXPECT_TRUE(lane.has_value()) << id;
  return lane.value_or(0);
}

// A trace of `samples` at 0.1 s whose ego stands at the middle of `lane`, on it.
Trace ego_on_lane(const RoadMap& map, LaneIndex lane, std::size_t samples = 50, double speed = 8) {
  Trace trace = empty_trace(samples);
  const Polyline& centre = map.lane(lane).centre_line;
  const double s = centre.length() / 2;
  const MapPoint p = centre.point_at(s);
  trace.actors.push_back(still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9,
                                     p.x, p.y, centre.heading_at(s), speed));
  trace.actors[kEgo].lane.assign(samples, static_cast<std::int32_t>(lane));
  trace.actors[kEgo].s.assign(samples, s);
  return trace;
}

// `straight` with two east-bound lanes: east_0 along y = -5.25, east_1 along y = -1.75.
RoadMap two_lane_straight() { return builtin("straight", {{"lanes", 2}}); }

TEST(FailureModeTest, AStandingEgoIsStoppedAndOneMovingOffIsPullingOut) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(100);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 50, -5.25));
  drive_east(trace, trace.actors[kEgo], 50, 0, lane_named(map, "east_0"), -5.25);
  for (std::size_t i = 40; i < 100; ++i)
    trace.actors[kEgo].speed[i] = 0.1 * static_cast<double>(i - 39);
  EXPECT_EQ(ego_activity_at(trace, map, 20), EgoActivity::stopped);
  EXPECT_EQ(ego_activity_at(trace, map, 50), EgoActivity::pulling_out);  // 1 s after moving off
  EXPECT_EQ(ego_activity_at(trace, map, 90), EgoActivity::cruising);     // 5 s after
}

TEST(FailureModeTest, AnEgoOnANeighbourLaneWithinTwoSecondsIsChangingLane) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(100);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 0, -5.25));
  drive_east(trace, trace.actors[kEgo], 0, 10, lane_named(map, "east_0"), -5.25);
  for (std::size_t i = 60; i < 100; ++i) trace.actors[kEgo].lane[i] = lane_named(map, "east_1");
  EXPECT_EQ(ego_activity_at(trace, map, 45), EgoActivity::changing_lane);
  EXPECT_EQ(ego_activity_at(trace, map, 70), EgoActivity::changing_lane);
  EXPECT_EQ(ego_activity_at(trace, map, 30), EgoActivity::cruising);  // 3 s before the change
  EXPECT_EQ(ego_activity_at(trace, map, 95), EgoActivity::cruising);
}

TEST(FailureModeTest, FollowingNeedsSomeoneAheadInTheLaneWithinThreeSeconds) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(10);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 100, -5.25, 0, 10));
  trace.actors.push_back(still_actor(trace, "npc1", TraceActorKind::vehicle, BodyShape::box, 4.5,
                                     1.9, 125, -5.25, 0, 10));
  EXPECT_EQ(ego_activity_at(trace, map, 0), EgoActivity::following);  // 25 m < 30 m
  trace.actors[1].x.assign(10, 135);
  EXPECT_EQ(ego_activity_at(trace, map, 0), EgoActivity::cruising);  // 35 m ahead
  trace.actors[1].x.assign(10, 120);
  trace.actors[1].y.assign(10, -1.75);  // alongside, in the next lane
  EXPECT_EQ(ego_activity_at(trace, map, 0), EgoActivity::cruising);
  trace.actors[1].y.assign(10, -5.25);
  trace.actors[1].x.assign(10, 90);  // behind
  EXPECT_EQ(ego_activity_at(trace, map, 0), EgoActivity::cruising);
}

TEST(FailureModeTest, JunctionLanesThatTurnAreTurnsAndTheirPlaceAJunction) {
  const RoadMap map = builtin("crossroads");
  std::optional<LaneIndex> left, right, ahead;
  for (LaneIndex i = 0; i < map.lanes().size(); ++i) {
    const Lane& lane = map.lane(i);
    if (!lane.junction) continue;
    if (lane.turn == LaneTurn::left) left = i;
    if (lane.turn == LaneTurn::right) right = i;
    if (lane.turn == LaneTurn::none) ahead = i;
  }
  ASSERT_TRUE(left && right && ahead);
  EXPECT_EQ(ego_activity_at(ego_on_lane(map, *left), map, 0), EgoActivity::turning_left);
  EXPECT_EQ(ego_activity_at(ego_on_lane(map, *right), map, 0), EgoActivity::turning_right);
  EXPECT_EQ(ego_activity_at(ego_on_lane(map, *ahead), map, 0), EgoActivity::cruising);
  EXPECT_EQ(road_feature_at(ego_on_lane(map, *left), map, 0), RoadFeature::junction);
}

TEST(FailureModeTest, RoadFeaturesOfTheBuiltInMaps) {
  const RoadMap roundabout = builtin("roundabout");
  EXPECT_EQ(
      road_feature_at(ego_on_lane(roundabout, lane_named(roundabout, "ring_0")), roundabout, 0),
      RoadFeature::roundabout);

  const RoadMap merge = builtin("merge");
  EXPECT_EQ(road_feature_at(ego_on_lane(merge, lane_named(merge, "accel_0")), merge, 0),
            RoadFeature::merge);
  EXPECT_EQ(road_feature_at(ego_on_lane(merge, lane_named(merge, "main_0")), merge, 0),
            RoadFeature::merge);  // the middle of main_0 lies beside accel_0

  const RoadMap straight = two_lane_straight();
  EXPECT_EQ(road_feature_at(ego_on_lane(straight, lane_named(straight, "east_0")), straight, 0),
            RoadFeature::straight);
}

TEST(FailureModeTest, ACrosswalkOutsideTheJunctionIsNamed) {
  const RoadMap map = builtin("crossroads", {{"crosswalks", 1}});
  ASSERT_FALSE(map.crosswalks().empty());
  const Crosswalk& crosswalk = map.crosswalks().front();
  MapPoint centre{0, 0};
  for (const MapPoint& p : crosswalk.outline) centre = {centre.x + p.x, centre.y + p.y};
  centre = {centre.x / static_cast<double>(crosswalk.outline.size()),
            centre.y / static_cast<double>(crosswalk.outline.size())};
  Trace trace = empty_trace(5);
  trace.actors.push_back(still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9,
                                     centre.x, centre.y, 0, 5));
  EXPECT_EQ(road_feature_at(trace, map, 0), RoadFeature::crosswalk);  // before the junction
  trace.actors[kEgo].x.assign(5, centre.x * 3);  // on the arm, well before the crosswalk
  trace.actors[kEgo].y.assign(5, centre.y * 3);
  EXPECT_EQ(road_feature_at(trace, map, 0), RoadFeature::straight);
}

TEST(FailureModeTest, BackgroundVehiclesAreKnownByTheirFlow) {
  Trace trace = empty_trace(2);
  TraceActor flow_car =
      still_actor(trace, "flow1.17", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 0, 0);
  EXPECT_EQ(actor_role(flow_car), "flow1");
  flow_car.name = "npc1";
  EXPECT_EQ(actor_role(flow_car), "npc1");
  flow_car.name = "odd.name";
  EXPECT_EQ(actor_role(flow_car), "odd.name");
  EXPECT_EQ(actor_class_name(flow_car), "car");
  flow_car.kind = TraceActorKind::obstacle;
  EXPECT_EQ(actor_class_name(flow_car), "obstacle");
}

TEST(FailureModeTest, TheKeyTellsModesApartByEveryField) {
  FailureMode mode;
  mode.atom = "collision";
  mode.other_class = "car";
  mode.other_role = "npc1";
  mode.responsibility = "ego";
  mode.ego_activity = EgoActivity::following;
  mode.road_feature = RoadFeature::straight;
  mode.ego_side = BodySide::front;
  mode.other_side = BodySide::rear;
  EXPECT_EQ(failure_mode_key(mode),
            "collision | car npc1 | ego | following | straight | front-rear");
  FailureMode other = mode;
  other.responsibility = "other";
  EXPECT_NE(failure_mode_key(other), failure_mode_key(mode));
  other = mode;
  other.ego_side = BodySide::left;
  EXPECT_NE(failure_mode_key(other), failure_mode_key(mode));
  FailureMode spec;
  spec.atom = "dist(ego, npc1) > 2";
  EXPECT_EQ(failure_mode_key(spec), "dist(ego, npc1) > 2 | - | - | cruising | straight");
}

TEST(FailureModeTest, ACollisionNamesItsOtherActorAndSidesAtItsMoment) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(50);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 0, -5.25));
  drive_east(trace, trace.actors[kEgo], 0, 10, lane_named(map, "east_0"), -5.25);
  trace.actors.push_back(
      still_actor(trace, "flow2.4", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 44, -5.25));
  trace.actors.push_back(
      still_actor(trace, "ped", TraceActorKind::pedestrian, BodyShape::cylinder, 0.5, 0.5, 20, -8));
  trace.collisions.push_back({4.0, kEgo, 1, {42, -5.25}, BodySide::front, BodySide::rear});
  SpecVerdict verdict;
  verdict.name = kNoCollisionSpec;
  verdict.robustness = -0.3;
  verdict.time = 1.0;  // nearest approach is not where the mode is read: the collision is
  const FailureMode mode = describe_failure(trace, map, verdict);
  EXPECT_EQ(failure_mode_key(mode),
            "collision | car flow2 | - | following | straight | front-rear");
}

TEST(FailureModeTest, AViolationWithoutCollisionNamesTheNearestRoadUser) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(50);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 0, -5.25));
  drive_east(trace, trace.actors[kEgo], 0, 10, lane_named(map, "east_0"), -5.25);
  trace.actors.push_back(
      still_actor(trace, "far", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 400, -1.75));
  trace.actors.push_back(
      still_actor(trace, "ped", TraceActorKind::pedestrian, BodyShape::cylinder, 0.5, 0.5, 22, -8));
  trace.actors[2].category = ActorCategory::pedestrian;
  SpecVerdict verdict;
  verdict.name = "keep_clear";
  verdict.atom_text = "dist(ego, ped) > 5";
  verdict.robustness = -1;
  verdict.time = 2.0;  // the ego at x = 20
  EXPECT_EQ(failure_mode_key(describe_failure(trace, map, verdict)),
            "keep_clear: dist(ego, ped) > 5 | pedestrian ped | - | cruising | straight");
}

TEST(FailureModeTest, SampleAtTimeRoundsAndClamps) {
  const Trace trace = empty_trace(11);  // 0 .. 1 s
  EXPECT_EQ(sample_at_time(trace, 0.44), 4u);
  EXPECT_EQ(sample_at_time(trace, 0.46), 5u);
  EXPECT_EQ(sample_at_time(trace, -3), 0u);
  EXPECT_EQ(sample_at_time(trace, 7), 10u);
}

}  // namespace
}  // namespace scenfuzz
