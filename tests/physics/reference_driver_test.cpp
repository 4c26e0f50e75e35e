// The reference driver on small scenarios where a real driver would not get stuck: it passes a
// stopped car when the lane beside is free, a slow car only with room to stop at its target
// beyond it, passes a cyclist through a clear oncoming lane but follows it while an oncoming car
// makes that unsafe, does not wait for a pedestrian standing at the kerb, and still stops for one
// walking into its lane; in fog it drives no faster than it can stop within what it sees, and it
// slows for a pedestrian crossing the road towards its lane.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "physics/actors/actor_class.hpp"
#include "physics/ego/sight_distance.hpp"
#include "simulation_fixtures.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

using test::closest_approach;
using test::simulate_text;

std::string scenario(const std::string& map, const std::string& npcs,
                     const std::string& pedestrians, const std::string& obstacles,
                     const std::string& body) {
  return body + "\nscenario = CreateScenario{load(\"" + map + "\");\nego;\n{" + npcs + "};\n{" +
         pedestrians + "};\n{" + obstacles + "};\n};\n";
}

SimulationOptions lasting(double seconds) {
  SimulationOptions options;
  options.duration = seconds;
  return options;
}

double largest(const std::vector<double>& values) {
  return *std::max_element(values.begin(), values.end());
}

// No collision, the target reached, and never closer than 0.5 m to actor 1.
void expect_reached_target_safely(const Trace& trace) {
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 1), 0.5);
}

TEST(ReferenceDriverTest, PassesAStoppedCarOnATwoLaneOneWayRoad) {
  // east_0 (y = -5.25) and east_1 (y = -1.75), a broken line between them.
  auto run = simulate_text(scenario("straight?two_way=0", "parked", "", "",
                                    "ego = AV((\"east_0\"->20, , 15), (\"east_0\"->400));\n"
                                    "parked = Vehicle((\"east_0\"->150, , 0));\n"),
                           lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  expect_reached_target_safely(trace);
  EXPECT_GT(largest(trace.actors[0].y), -2.5) << "the ego should have moved into east_1";
  EXPECT_LT(trace.actors[0].y.back(), -4.5) << "and come back into east_0";
}

// A car at 9 m/s ahead on a two-lane one-way road: the ego passes it when its target is far, but
// not when it would have to stop at its target soon after moving back in front of it (it did, and
// was rear-ended there: cut_in_straight's findings).
TEST(ReferenceDriverTest, PassesASlowCarOnlyWithRoomToStopBeyondIt) {
  for (const std::string target : {"250", "450"}) {
    SCOPED_TRACE(target);
    auto run = simulate_text(
        scenario("straight?two_way=0&length=500", "car", "", "",
                 "ego = AV((\"east_0\"->20, , 15), (\"east_0\"->" + target +
                     "));\ncar = Vehicle((\"east_0\"->60, , 9), uniform((\"east_0\"->60, , 9)), "
                     "(\"east_0\"->499));\n"),
        lasting(60));
    ASSERT_TRUE(run.trace) << run.errors;
    const Trace& trace = *run.trace;
    expect_reached_target_safely(trace);
    if (target == "250") {
      EXPECT_LT(largest(trace.actors[0].y), -4.5) << "it should have followed the car";
    } else {
      EXPECT_GT(largest(trace.actors[0].y), -2.5) << "it should have passed in east_1";
    }
  }
}

// From a finding of lane_change_into_gap (its scenario and seed as written): the ego, at a
// crawl behind a slow van, found the next lane's gap free while the car at its rear was still
// 25 m back, but moved over only 4 s later, 0.2 m in front of that car, which was 4 m/s faster and
// does not brake. The gap behind must hold for as long as the move takes.
TEST(ReferenceDriverTest, ChangesLaneOnlyWhereTheCarBehindDoesNotCloseInDuringTheMove) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // san_francisco
  const std::string text =
      "ego_vehicle = AV((\"lane_318\"->44.32068853049931, , 9.998257886375526), "
      "((553367.80, 4183173.51)), (\"Lincoln2017MKZ\", white));\n"
      "npc1 = Vehicle((\"lane_317\"->54.03632424916502, , 10.320530356113762), "
      "uniform((\"lane_317\"->54.03632424916502, , 10.320530356113762)), "
      "(\"lane_321\"->100), (\"Sedan\", blue));\n"
      "npc2 = Vehicle((\"lane_317\"->15.448050456080043, , 10.320530356113762), "
      "uniform((\"lane_317\"->15.448050456080043, , 10.320530356113762)), "
      "(\"lane_321\"->80), (\"SUV\", black));\n"
      "npc3 = Vehicle((\"lane_318\"->127.4104184804591, , 4.563733569939876), "
      "Waypoint(((\"lane_318\"->200, , 3.50160397405183), ((553333.27, 4183203.37), , 4))), "
      "(\"lane_322\"->60), (\"Van\", white));\n"
      "scenario = CreateScenario{load(\"san_francisco\"); ego_vehicle; {npc1, npc2, npc3}; {}; "
      "{}; };\n";
  SimulationOptions options = lasting(60);
  options.seed = 7577010756027538418ull;
  const auto run = test::simulate_file(SourceFile("lane_change_into_gap.avu", text), options,
                                       MapSearchPath{{test::shared_dir() / "maps" / "apollo"}});
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 2), 2.0) << "within the spec's 2 m of the car behind";
}

// From a finding of stop_and_go_harsh_braking (its scenario and seed as written): at 1.3 m/s and
// 9 m behind a crawling car, the ego decided to wait to pass it, wanted 12 m of room and braked
// at 8 m/s^2 to win it back.
TEST(ReferenceDriverTest, WaitingToPassNeverBrakesHarshlyToMakeRoom) {
  const std::string text =
      "ego_vehicle = AV((\"east_0\"->15.346549152740469, , 6.849728892155392), "
      "(\"east_0\"->420), (\"Lincoln2017MKZ\", white));\n"
      "npc1 = Vehicle((\"east_0\"->47.17824642915126, , 7.352490784313085), "
      "Waypoint(((\"east_0\"->90.67795236701227, , 0.6608137228058366), "
      "(\"east_0\"->152.04196943805192, , 9.9662548895136), "
      "(\"east_0\"->219.51342473965423, , 1.1181736732233432), "
      "(\"east_0\"->271.63154994897343, , 10))), (\"east_0\"->495), (\"Sedan\", white));\n"
      "npc2 = Vehicle((\"east_1\"->21.374808345035753, , 5.081956299993578), "
      "W(((\"east_1\"->137.7115265822348, , 2.6237940154488486), "
      "(\"east_1\"->206.16326523301964, , 9))), (\"east_1\"->495), (\"Van\", blue));\n"
      "env = Environment(8:15, {cloudiness: 0.7});\n"
      "scenario = CreateScenario{load(\"straight\"); ego_vehicle; {npc1, npc2}; {}; {}; env;};\n";
  SimulationOptions options = lasting(30);
  options.seed = 13233401231234309212ull;
  auto run = simulate_text(text, options);
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& ego = run.trace->actors[0];
  EXPECT_TRUE(run.trace->collisions.empty());
  for (std::size_t i = 0; i < ego.acceleration.size(); ++i)
    EXPECT_GT(ego.acceleration[i], -5.5)
        << "at " << run.trace->time[i] << " s, speed " << ego.speed[i];
}

TEST(ReferenceDriverTest, PassesAStoppedCarWhenTheCarBesideHasGone) {
  // A car in east_1 beside the ego at first: the ego waits behind the parked car, then passes.
  auto run = simulate_text(scenario("straight?two_way=0", "parked, beside", "", "",
                                    "ego = AV((\"east_0\"->20, , 10), (\"east_0\"->300));\n"
                                    "parked = Vehicle((\"east_0\"->70, , 0));\n"
                                    "beside = Vehicle((\"east_1\"->15, , 3), "
                                    "uniform((\"east_1\"->15, , 3)), (\"east_1\"->499));\n"),
                           lasting(90));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  expect_reached_target_safely(trace);
  EXPECT_GT(closest_approach(trace, 0, 2), 0.5);
}

// One lane each way, 40 km/h, the centre line a double yellow: a cyclist at 3 m/s may be passed
// across it (as slow as a bicycle), when the oncoming lane is clear.
std::string cyclist_on_two_way_road(const std::string& oncoming) {
  std::string npcs = "bike";
  std::string body =
      "ego = AV((\"east_0\"->20, , 11), (\"east_0\"->420));\n"
      "bike = Vehicle((\"east_0\"->70, , 3), uniform((\"east_0\"->70, , 3)), (\"east_0\"->499), "
      "(\"Bicycle\", green));\n";
  if (!oncoming.empty()) {
    npcs += ", car";
    body += "car = Vehicle((\"west_0\"->" + oncoming + ", , 11), uniform((\"west_0\"->" + oncoming +
            ", , 11)), (\"west_0\"->499));\n";
  }
  return scenario("straight?lanes=1&speed_limit=11", npcs, "", "", body);
}

TEST(ReferenceDriverTest, PassesACyclistThroughAClearOncomingLane) {
  auto run = simulate_text(cyclist_on_two_way_road(""), lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 1), 1.0) << "a wide berth for the cyclist";
  EXPECT_GT(largest(trace.actors[0].y), 0.5) << "the ego should have used the oncoming lane";
}

TEST(ReferenceDriverTest, FollowsTheCyclistWhileAnOncomingCarMakesPassingUnsafe) {
  // The oncoming car starts at x = 250 (west_0 runs from x = 500 to 0), in sight when the ego
  // catches up with the cyclist; closing at 22 m/s it would meet the ego during the pass, so the
  // ego stays behind the cyclist until the car has gone by, and passes then.
  auto run = simulate_text(cyclist_on_two_way_road("250"), lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_GT(closest_approach(trace, 0, 1), 0.5);
  EXPECT_GT(closest_approach(trace, 0, 2), 1.0) << "never nearer than side by side in its lane";
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const TraceActor& ego = trace.actors[0];
  const TraceActor& car = trace.actors[2];
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    if (car.x[i] > ego.x[i]) {
      ASSERT_LT(ego.y[i], -0.5) << "the ego pulled out at t = " << trace.time[i]
                                << " with the oncoming car still ahead";
    }
  }
}

TEST(ReferenceDriverTest, DoesNotWaitForeverForAPedestrianStandingAtTheKerb) {
  // On t_junction the west arm's crosswalk runs from x = -15 to -11; the pedestrian stands on
  // the pavement beside it (the road's edge is y = -7) and never crosses.
  auto run = simulate_text(scenario("t_junction", "", "ped", "",
                                    "ego = AV((\"west_in_0\"->60, , 10), (\"east_out_0\"->60));\n"
                                    "ped = Pedestrian(((-13, -8), 90 deg, 0));\n"),
                           lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  expect_reached_target_safely(trace);
}

TEST(ReferenceDriverTest, StopsForAPedestrianWalkingIntoItsLane) {
  // The pedestrian walks from the pavement into east_0 and stops in its middle.
  auto run = simulate_text(
      scenario("straight?two_way=0&lanes=1", "", "ped", "",
               "ego = AV((\"east_0\"->20, , 12), (\"east_0\"->400));\n"
               "ped = Pedestrian(((90, -5), 90 deg, 1.4), Waypoint(((90, -2.5), , 1.4)), "
               "((90, -1.75), , 0));\n"),
      lasting(30));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_GT(closest_approach(trace, 0, 1), 1.0);
  const TraceActor& ego = trace.actors[0];
  EXPECT_LT(ego.speed.back(), 0.2) << "the ego waits for the pedestrian in its lane";
  EXPECT_LT(largest(ego.x), 90.0);
}

// Thick fog by day: perception sees pedestrians to 12 m and vehicles to 22.5 m. A car stands in
// the ego's only lane (a kerb each side: no passing), so it comes into sight at the edge of the
// ego's sight range; the ego starts at 25 m/s on a 30 m/s road. It slows to the speed from which
// it can stop within its sight and stops behind the car (without the limit it found the car about
// 20 m ahead at 25 m/s and hit it).
TEST(ReferenceDriverTest, InFogDrivesNoFasterThanItCanStopWithinItsSight) {
  const std::string text =
      "ego = AV((\"east_0\"->20, , 25), (\"east_0\"->400));\n"
      "parked = Vehicle((\"east_0\"->250, , 0));\n"
      "env = Environment(12:00, {fog: 1.0});\n"
      "scenario = CreateScenario{load(\"straight?two_way=0&lanes=1&speed_limit=30\");\n"
      "ego; {parked}; {}; {}; env;};\n";
  auto run = simulate_text(text, lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_GT(closest_approach(trace, 0, 1), 0.5);
  const TraceActor& ego = trace.actors[0];
  EXPECT_LT(ego.speed.back(), 0.2) << "the ego waits behind the car";
  const PerceptionSettings fog = degraded({}, {.fog = 1.0});
  const double limit =
      sight_speed(fog, ego.length / 2, actor_class(ActorCategory::car).max_deceleration);
  EXPECT_LT(limit, 8.0);
  // Slowing from 25 m/s at its firm 4 m/s^2 takes under 5 s, settling on the limit a little more.
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    if (trace.time[i] >= 8.0) {
      ASSERT_LE(ego.speed[i], limit * 1.02) << "at " << trace.time[i];
    }
  }
}

TEST(SightDistanceTest, TheSightSpeedStopsWithinTheSightDistance) {
  const PerceptionSettings night_fog = degraded({}, {.fog = 0.7, .darkness = 1});
  const SightSettings settings;
  const double speed = sight_speed(night_fog, 2.5, 8.0, settings);
  const double planned = planned_deceleration(night_fog, 8.0, settings);
  EXPECT_NEAR(stopping_distance(speed, settings.reaction_time, planned) + 2.5 +
                  settings.object_extent + settings.margin,
              sight_distance(night_fog), 1e-9);
  // The poorer the sight, the gentler the braking planned: from the comfortable 2.5 m/s^2 with
  // no sight to full braking in clear daylight, continuously.
  EXPECT_NEAR(planned_deceleration(degraded({}, {.fog = 1.0, .darkness = 1}), 8.0, settings), 2.5,
              0.1);
  EXPECT_DOUBLE_EQ(planned_deceleration(degraded({}, {}), 8.0, settings), 8.0);
  PerceptionSettings almost_clear = degraded({}, {});
  almost_clear.pedestrian_range -= 0.01;
  EXPECT_NEAR(sight_speed(almost_clear, 2.5, 8.0, settings),
              sight_speed(degraded({}, {}), 2.5, 8.0, settings), 0.01);
  EXPECT_EQ(speed_to_stop_within(0, 0.75, 8.0), 0);
  EXPECT_EQ(sight_speed(degraded({}, {}), 2.5, 8.0, settings) > 29, true)
      << "clear daylight: no limit below 29 m/s";
}

// Four lanes, clear daylight: a pedestrian on the carriageway (in west_1) walks slowly across
// towards the ego's lane east_1. It needs some 10 s to reach the ego's path, longer than the ego
// needs to get there, so the ego used to pass it at 13.9 m/s 3 m away; now it slows so that it
// could stop before the pedestrian's crossing point, should the pedestrian hurry.
TEST(ReferenceDriverTest, SlowsForAPedestrianOnTheRoadWalkingTowardsItsLane) {
  auto run = simulate_text(
      scenario("straight", "", "ped", "",
               "ego = AV((\"east_1\"->20, , 13.9), (\"east_1\"->400));\n"
               "ped = Pedestrian(((120, 6.0), -90 deg, 0.6), , ((120, -8.5), -90 deg, 0));\n"),
      lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const TraceActor& ego = trace.actors[0];
  const TraceActor& ped = trace.actors[1];
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    const double front = ego.x[i] + ego.length / 2;
    if (front > ped.x[i] - 10 && ego.x[i] < ped.x[i] && ped.y[i] > -0.75) {
      ASSERT_LT(ego.speed[i], 8.0)
          << "at " << trace.time[i] << " s, the pedestrian at y " << ped.y[i];
    }
  }
}

}  // namespace
}  // namespace scenfuzz
