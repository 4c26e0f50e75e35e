// Failure-mode signatures: what the ego was doing, where, and who with, read from hand-built
// traces on the built-in maps.
#include "oracle/failure_mode.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(FailureModeTest, TheKeyTellsModesApartByEveryKeyField) {
  FailureMode mode;
  mode.atom = "collision";
  mode.event = FailureEvent::collision;
  mode.other_class = "car";
  mode.other_role = "npc1";
  mode.direction = ContactDirection::ahead;
  mode.responsibility = "ego";
  mode.phase = EgoPhase::in_lane;
  mode.ego_activity = EgoActivity::following;
  mode.ego_side = BodySide::front;
  mode.other_side = BodySide::rear;
  EXPECT_EQ(failure_mode_key(mode), "collision | collision | npc1 | ego | in lane");
  EXPECT_EQ(failure_mode_details(mode),
            "car npc1 ahead; ego following on a straight; touching ego front, npc1 rear");
  auto differs = [&](auto change) {
    FailureMode other = mode;
    change(other);
    return failure_mode_key(other) != failure_mode_key(mode);
  };
  EXPECT_TRUE(differs([](FailureMode& m) { m.atom = "spec1: d > 2"; }));
  EXPECT_TRUE(differs([](FailureMode& m) { m.event = FailureEvent::near_miss; }));
  EXPECT_TRUE(differs([](FailureMode& m) { m.other_role = "npc2"; }));
  EXPECT_TRUE(differs([](FailureMode& m) { m.responsibility = "other"; }));
  EXPECT_TRUE(differs([](FailureMode& m) { m.phase = EgoPhase::leaving_lane; }));
  // What flickers between runs of one failure describes it but does not split it.
  EXPECT_FALSE(differs([](FailureMode& m) { m.ego_side = BodySide::left; }));
  EXPECT_FALSE(differs([](FailureMode& m) { m.direction = ContactDirection::beside; }));
  EXPECT_FALSE(differs([](FailureMode& m) { m.ego_activity = EgoActivity::cruising; }));
  EXPECT_FALSE(differs([](FailureMode& m) { m.road_feature = RoadFeature::merge; }));
  EXPECT_FALSE(differs([](FailureMode& m) { m.other_class = "van"; }));
  FailureMode spec;
  spec.atom = "dist(ego, npc1) > 2";
  EXPECT_EQ(failure_mode_key(spec), "dist(ego, npc1) > 2 | rule | - | - | in lane");
}

// A rule of the ego's own driving broken near npc1 in one run and near npc3 in the next (the law
// corpus's `direction == left -> speed <= 30` gave one mode per nearby car) is one failure; a
// near miss or a collision is with someone, and stays apart by whom.
TEST(FailureModeTest, ARuleBrokenNearAnotherRoadUserIsOneMode) {
  FailureMode near_one;
  near_one.atom = "spec1: (direction == left) -> (speed <= 30)";
  near_one.event = FailureEvent::rule;
  near_one.other_class = "car";
  near_one.other_role = "npc1";
  near_one.phase = EgoPhase::leaving_lane;
  FailureMode near_three = near_one;
  near_three.other_role = "npc3";
  EXPECT_EQ(failure_mode_key(near_one), failure_mode_key(near_three));
  EXPECT_NE(failure_mode_details(near_one), failure_mode_details(near_three));
  for (FailureEvent event : {FailureEvent::near_miss, FailureEvent::collision}) {
    near_one.event = near_three.event = event;
    EXPECT_NE(failure_mode_key(near_one), failure_mode_key(near_three));
  }
}

// The ego waits behind `lead` in east_0, creeping at 0.5 m/s from `creeps_from` (none when it
// is 30 or more), then from 3 s pulls out to its left (heading `heading` rad) and clips the lead's
// rear at 4 s; from `changes_lane_at` on, the trace has it on east_1 already. The collision's
// sides are what the physics reported at contact.
Trace pull_out_and_clip(const RoadMap& map, double heading, std::size_t creeps_from,
                        std::size_t changes_lane_at, BodySide ego_side, BodySide lead_side) {
  Trace trace = empty_trace(41);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 50, -5.25));
  TraceActor& ego = trace.actors[kEgo];
  drive_east(trace, ego, 50, 0, lane_named(map, "east_0"), -5.25);
  double x = 50;
  for (std::size_t i = creeps_from; i < 30; ++i) {
    ego.speed[i] = 0.5;
    ego.x[i] = ego.s[i] = x += 0.05;
  }
  for (std::size_t i = 30; i <= 40; ++i) {
    const double t = 0.1 * static_cast<double>(i - 30);
    ego.speed[i] = 1 + 2 * t;
    ego.heading[i] = heading;
    ego.x[i] = ego.s[i] = x + 2 * t;
    ego.y[i] = -5.25 + 2 * t * std::sin(heading);
    if (i >= changes_lane_at) ego.lane[i] = lane_named(map, "east_1");
  }
  trace.actors.push_back(still_actor(trace, "lead", TraceActorKind::vehicle, BodyShape::box, 4.5,
                                     1.9, x + 6.6, -5.25));
  trace.collisions.push_back({4.0, kEgo, 1, {x + 4.4, -4.6}, ego_side, lead_side});
  return trace;
}

SpecVerdict collision_verdict(double time) {
  SpecVerdict verdict;
  verdict.name = kNoCollisionSpec;
  verdict.robustness = -0.5;
  verdict.time = time;
  return verdict;
}

// One failure (the ego pulls out round the stopped car ahead and clips it), seen twice: once the
// ego moves off just before and its front touches first ("pulling out"), once it crept up for a
// while, its centre crossed into the next lane and its left side touches ("changing lane"). Before
// the key was made of stable fields these were two modes.
TEST(FailureModeTest, OneFailureTouchingAtAnotherCornerIsOneMode) {
  const RoadMap map = two_lane_straight();
  const Trace front = pull_out_and_clip(map, 0.2, 30, 100, BodySide::front, BodySide::rear);
  const Trace side = pull_out_and_clip(map, 0.25, 5, 38, BodySide::left, BodySide::left);
  const FailureMode a = describe_failure(front, map, collision_verdict(4.0));
  const FailureMode b = describe_failure(side, map, collision_verdict(4.0));
  ASSERT_NE(a.ego_side, b.ego_side);  // the physics told them apart
  ASSERT_NE(a.ego_activity, b.ego_activity);
  EXPECT_EQ(failure_mode_key(a), failure_mode_key(b));
  EXPECT_EQ(failure_mode_key(a), "collision | collision | lead | - | leaving lane");
}

// Two different failures with the same actor: the ego clipping the car ahead as it pulls out,
// and a car running into the ego's rear while it stands; and the same pull-out that misses by a
// few centimetres.
TEST(FailureModeTest, DifferentFailuresWithTheSameActorAreDifferentModes) {
  const RoadMap map = two_lane_straight();
  const Trace clip = pull_out_and_clip(map, 0.2, 30, 100, BodySide::front, BodySide::rear);
  Trace rammed = empty_trace(41);
  rammed.actors.push_back(
      still_actor(rammed, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 50, -5.25));
  drive_east(rammed, rammed.actors[kEgo], 50, 0, lane_named(map, "east_0"), -5.25);
  rammed.actors.push_back(
      still_actor(rammed, "lead", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 45.6, -5.25));
  rammed.collisions.push_back({4.0, kEgo, 1, {47.8, -5.25}, BodySide::rear, BodySide::front});
  const FailureMode clip_mode = describe_failure(clip, map, collision_verdict(4));
  const FailureMode rammed_mode = describe_failure(rammed, map, collision_verdict(4));
  const std::string clip_key = failure_mode_key(clip_mode);
  const std::string rammed_key = failure_mode_key(rammed_mode);
  EXPECT_EQ(rammed_key, "collision | collision | lead | - | standing");
  EXPECT_NE(clip_key, rammed_key);
  EXPECT_EQ(clip_mode.direction, ContactDirection::ahead);  // described, not keyed
  EXPECT_EQ(rammed_mode.direction, ContactDirection::behind);

  Trace missed = clip;
  missed.collisions.clear();
  for (double& x : missed.actors[1].x) x += 0.4;  // 0.2 m clear of the ego at 4 s
  SpecVerdict near;
  near.name = "gap";
  near.atom_text = "dis(ego, lead) > 0.5";
  near.actor_distance = true;
  near.robustness = -0.3;
  near.time = 4.0;
  const std::string missed_key = failure_mode_key(describe_failure(missed, map, near));
  EXPECT_EQ(missed_key, "gap: dis(ego, lead) > 0.5 | near miss | lead | - | leaving lane");
  SpecVerdict jerk = near;  // a rule broken while pulling out, no distance in it
  jerk.name = "comfort";
  jerk.atom_text = "acc(ego, (0, 0)) <= 4";
  jerk.actor_distance = false;
  EXPECT_EQ(describe_failure(missed, map, jerk).other_role, "lead");
  EXPECT_EQ(failure_mode_key(describe_failure(missed, map, jerk)),
            "comfort: acc(ego, (0, 0)) <= 4 | rule | - | - | leaving lane");
  SpecVerdict stuck = near;
  stuck.ending = VerdictEnding::stuck;
  EXPECT_EQ(failure_mode_key(describe_failure(missed, map, stuck)),
            "gap: dis(ego, lead) > 0.5 | stuck | lead | - | leaving lane");
}

TEST(FailureModeTest, PhasesMergeTheLabelsOfOneManoeuvre) {
  const RoadMap map = two_lane_straight();
  const Trace clip = pull_out_and_clip(map, 0.2, 30, 100, BodySide::front, BodySide::rear);
  EXPECT_EQ(ego_phase_at(clip, map, 20), EgoPhase::standing);
  EXPECT_EQ(ego_activity_at(clip, map, 35), EgoActivity::pulling_out);
  EXPECT_EQ(ego_phase_at(clip, map, 35), EgoPhase::leaving_lane);
  // Following and cruising are one phase; so is moving off in the lane.
  Trace trace = empty_trace(100);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 50, -5.25));
  drive_east(trace, trace.actors[kEgo], 50, 0, lane_named(map, "east_0"), -5.25);
  for (std::size_t i = 40; i < 100; ++i)
    trace.actors[kEgo].speed[i] = 0.1 * static_cast<double>(i - 39);
  EXPECT_EQ(ego_activity_at(trace, map, 50), EgoActivity::pulling_out);
  EXPECT_EQ(ego_phase_at(trace, map, 50), EgoPhase::in_lane);
  EXPECT_EQ(ego_phase_at(trace, map, 90), EgoPhase::in_lane);
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
  EXPECT_EQ(failure_mode_key(mode), "collision | collision | flow2 | - | in lane");
  EXPECT_EQ(mode.ego_activity, EgoActivity::following);
  EXPECT_EQ(failure_mode_details(mode),
            "car flow2 ahead; ego following on a straight; touching ego front, flow2 rear");
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
  EXPECT_EQ(describe_failure(trace, map, verdict).other_role, "ped");
  verdict.actor_distance = true;  // a near miss is keyed by whom
  EXPECT_EQ(failure_mode_key(describe_failure(trace, map, verdict)),
            "keep_clear: dist(ego, ped) > 5 | near miss | ped | - | in lane");
}

// Two runs of one hard-braking violation named npc1 or npc2 by which was nearer at that moment;
// the car the ego follows is the one it brakes for.
TEST(FailureModeTest, AViolationWithoutCollisionNamesTheRoadUserTheEgoFollowsFirst) {
  const RoadMap map = two_lane_straight();
  Trace trace = empty_trace(50);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.9, 0, -5.25));
  drive_east(trace, trace.actors[kEgo], 0, 10, lane_named(map, "east_0"), -5.25);
  trace.actors.push_back(
      still_actor(trace, "beside", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 21, -1.75));
  trace.actors.push_back(
      still_actor(trace, "lead", TraceActorKind::vehicle, BodyShape::box, 4.5, 1.9, 35, -5.25));
  SpecVerdict verdict;
  verdict.name = "comfort";
  verdict.atom_text = "acc(ego, (0, 0)) <= 4";
  verdict.robustness = -1;
  verdict.time = 2.0;  // the ego at x = 20: `beside` 3.6 m away, `lead` 15 m ahead
  EXPECT_EQ(describe_failure(trace, map, verdict).other_role, "lead");
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
