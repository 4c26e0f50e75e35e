// The whole simulation on small scenarios whose outcome a competent driver fixes: the reference
// driver stops behind a stopped car, at a red light and for a crossing pedestrian; a cut-in too
// close to avoid collides; the same seed gives the same trace bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::closest_approach;
using test::simulate_text;

std::string scenario_text(const std::string& map, const std::string& ego, const std::string& npcs,
                          const std::string& pedestrians, const std::string& body,
                          const std::string& environment = "") {
  return body + "\nscenario = CreateScenario{load(\"" + map + "\");\n" + ego + ";\n{" + npcs +
         "};\n{" + pedestrians + "};\n{};\n" + environment + "};\n";
}

TEST(SimulationTest, StopsBehindAStoppedCarFrom20MetresPerSecond) {
  // One lane between kerbs: the ego cannot pass the car (reference_driver_test.cpp has it pass).
  auto run = simulate_text(scenario_text("straight?two_way=0&lanes=1", "ego", "parked", "",
                                         "ego = AV((\"east_0\"->20, , 20), (\"east_0\"->480));\n"
                                         "parked = Vehicle((\"east_0\"->250, , 0));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  double gap = closest_approach(trace, 0, 1);
  EXPECT_GT(gap, 0.5);
  EXPECT_LT(gap, 8.0) << "the ego should close up behind the car, not stop far away";
  EXPECT_LT(trace.actors[0].speed.back(), 0.1);
  EXPECT_EQ(trace.end, EndReason::duration);
}

TEST(SimulationTest, StopsAtARedLightAndGoesOnGreen) {
  // On `crossroads` east-west traffic has red for the first half cycle (30 s).
  std::string text = scenario_text("crossroads", "ego", "", "",
                                   "ego = AV((\"west_in_0\"->60, , 10), (\"east_out_0\"->60));\n");
  SimulationOptions options;
  options.duration = 25;
  auto stopped = simulate_text(text, options);
  ASSERT_TRUE(stopped.trace) << stopped.errors;
  const TraceActor& ego = stopped.trace->actors[0];
  // The stop line is at x = -16 (s = 144 on west_in_0): the front bumper stays behind it.
  double front = ego.x.back() + ego.length / 2;
  EXPECT_LT(front, -16.0);
  EXPECT_GT(front, -25.0);
  EXPECT_LT(ego.speed.back(), 0.1);
  for (std::size_t i = 0; i < ego.x.size(); ++i) ASSERT_LT(ego.x[i] + ego.length / 2, -16.0);

  options.duration = 60;
  auto through = simulate_text(text, options);
  ASSERT_TRUE(through.trace) << through.errors;
  EXPECT_EQ(through.trace->end, EndReason::target_reached);
  EXPECT_GT(through.trace->time.back(), 30.0);
}

TEST(SimulationTest, YieldsToACrossingPedestrian) {
  auto run = simulate_text(scenario_text(
      "straight", "ego", "", "walker",
      "ego = AV((\"east_0\"->10, , 12), (\"east_0\"->300));\n"
      "walker = Pedestrian(((80, -9), 90 deg, 1.4), uniform(((80, -9), 90 deg, 1.4)));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_GT(closest_approach(trace, 0, 1), 0.5);
  EXPECT_EQ(trace.end, EndReason::target_reached) << "the ego goes on once the road is clear";
}

// npc starts in the left lane with its rear 3 m ahead of the ego's front and moves over.
// The ego at 25 m/s in east_0; a car in east_1 starting `start` m along it at `cutter_speed`
// moves over into east_0, arriving at `arrival` m along it.
std::string cut_in(const std::string& cutter_speed, const std::string& start = "57.7",
                   const std::string& arrival = "85") {
  return scenario_text("straight", "ego", "cutter", "",
                       "ego = AV((\"east_0\"->50, , 25), (\"east_0\"->480));\n"
                       "cutter = Vehicle((\"east_1\"->" +
                           start + ", , " + cutter_speed + "), Waypoint((\"east_0\"->" + arrival +
                           ", , " + cutter_speed + ")), (\"east_0\"->400));\n");
}

TEST(SimulationTest, StopsAtAStopSignThenGoesOn) {
  // t_junction: the side road's stop line is at s = 144 on south_in_0 (y = -16).
  SimulationOptions options;
  options.duration = 40;
  auto run =
      simulate_text(scenario_text("t_junction", "ego", "", "",
                                  "ego = AV((\"south_in_0\"->100, , 10), (\"east_out_0\"->60));\n"),
                    options);
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& ego = run.trace->actors[0];
  bool stopped_at_line = false;
  for (std::size_t i = 0; i < ego.y.size(); ++i) {
    double front = ego.y[i] + ego.length / 2;  // driving north
    if (ego.speed[i] < 0.2 && front > -19 && front <= -16) stopped_at_line = true;
    if (front > -16 + 0.1) {
      EXPECT_TRUE(stopped_at_line) << "crossed the line without stopping";
    }
  }
  EXPECT_TRUE(stopped_at_line);
  EXPECT_EQ(run.trace->end, EndReason::target_reached);
}

TEST(SimulationTest, YieldsToAPedestrianOnACrosswalk) {
  // crossroads: north-south has green first; the south crosswalk spans -15 < y < -11.
  SimulationOptions options;
  options.duration = 20;
  auto run = simulate_text(
      scenario_text(
          "crossroads", "ego", "", "walker",
          "ego = AV((\"south_in_0\"->100, , 10), (\"north_out_0\"->60));\n"
          "walker = Pedestrian(((11, -13), 180 deg, 1.5), uniform(((11, -13), 180 deg, 1.5)));\n"),
      options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  const TraceActor& ego = trace.actors[0];
  const TraceActor& walker = trace.actors[1];
  for (std::size_t i = 0; i < ego.y.size(); ++i) {
    if (std::abs(walker.x[i]) < 10) {
      EXPECT_LT(ego.y[i] + ego.length / 2, -15.0)
          << "entered the crosswalk at t = " << trace.time[i];
    }
  }
  EXPECT_GT(ego.y.back(), -15.0) << "and went on once it was clear";
}

TEST(SimulationTest, ACutInWithAThreeMetreGapAt25MetresPerSecondCollides) {
  // Closing at 10 m/s from 3 m: even full braking (8 m/s^2) needs 6.25 m.
  auto run = simulate_text(cut_in("15"));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  ASSERT_FALSE(trace.collisions.empty());
  EXPECT_EQ(trace.collisions[0].first, kEgo);
  // The ego's front-left corner meets the cutter's right flank or rear while it moves over.
  const Collision& hit = trace.collisions[0];
  EXPECT_TRUE(hit.first_side == BodySide::front || hit.first_side == BodySide::left);
  EXPECT_TRUE(hit.second_side == BodySide::right || hit.second_side == BodySide::rear);
  EXPECT_EQ(trace.end, EndReason::collision);
  // The cutter moves over along a smooth lane change; the ego brakes hard once it sees it come
  // (the reference driver lets go in the step before contact, when the cutter already overlaps
  // its front, so the last sample is not the one to check).
  const std::vector<double>& acceleration = trace.actors[0].acceleration;
  EXPECT_LT(*std::min_element(acceleration.begin(), acceleration.end()), -5)
      << "the ego was braking hard";
}

TEST(SimulationTest, TheSameCutInByAFasterCarIsAvoided) {
  // Closing at 3 m/s: braking in time is possible, and the driver does it. The cutter moves over
  // in 2 s (45 m at 22 m/s, 5 m/s^2 sideways): faster than its tyres allow, it would slow for it.
  auto run = simulate_text(cut_in("22", "62", "107"));
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_TRUE(run.trace->collisions.empty());
  EXPECT_GT(closest_approach(*run.trace, 0, 1), 0.0);
}

TEST(SimulationTest, ReachesItsTargetOnAnEmptyRoad) {
  auto run = simulate_text(scenario_text("straight", "ego", "", "",
                                         "ego = AV((\"east_0\"->10, , 0), (\"east_1\"->300));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& ego = run.trace->actors[0];
  EXPECT_EQ(run.trace->end, EndReason::target_reached);
  EXPECT_NEAR(ego.y.back(), -1.75, 0.3) << "it changed into east_1";
  for (double speed : ego.speed) EXPECT_LE(speed, 22.2 + 0.1) << "speed limit";
}

TEST(SimulationTest, WaitsForAGapBeforeChangingLane) {
  // The target is in the left lane, where a car drives beside the ego, a little faster.
  SimulationOptions options;
  options.duration = 60;
  auto run = simulate_text(scenario_text("straight", "ego", "beside", "",
                                         "ego = AV((\"east_0\"->10, , 10), (\"east_1\"->300));\n"
                                         "beside = Vehicle((\"east_1\"->12, , 11));\n"),
                           options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const TraceActor& ego = trace.actors[0];
  const TraceActor& beside = trace.actors[1];
  std::size_t crossing = 0;
  while (crossing < ego.y.size() && ego.y[crossing] < -3.5) ++crossing;
  ASSERT_LT(crossing, ego.y.size()) << "it did change lane";
  EXPECT_GT(beside.x[crossing] - ego.x[crossing], 6.0) << "only once the car had gone by";
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(SimulationTest, TheSameSeedGivesABitIdenticalTraceOnAnyThread) {
  std::string text = scenario_text(
      "straight", "ego", "lead", "walker",
      "ego = AV((\"east_0\"->10, , 15), (\"east_0\"->400));\n"
      "lead = Vehicle((\"east_0\"->60, , 8));\n"
      "walker = Pedestrian(((120, -9), 90 deg, 1.0), Random(((120, -9), 90 deg, 1.0)));\n",
      "Environment(22:00, {fog: 0.4, rain: 0.5});\n");
  SimulationOptions options;
  options.seed = 42;
  auto first = simulate_text(text, options);
  ASSERT_TRUE(first.trace) << first.errors;
  test::SimulatedRun second, third;
  std::thread one([&] { second = simulate_text(text, options); });
  std::thread two([&] { third = simulate_text(text, options); });
  one.join();
  two.join();
  for (const auto* other : {&second, &third}) {
    ASSERT_TRUE(other->trace);
    const Trace& a = *first.trace;
    const Trace& b = *other->trace;
    ASSERT_EQ(a.actors.size(), b.actors.size());
    for (std::size_t k = 0; k < a.actors.size(); ++k) {
      EXPECT_TRUE(same_bits(a.actors[k].x, b.actors[k].x));
      EXPECT_TRUE(same_bits(a.actors[k].y, b.actors[k].y));
      EXPECT_TRUE(same_bits(a.actors[k].heading, b.actors[k].heading));
      EXPECT_TRUE(same_bits(a.actors[k].speed, b.actors[k].speed));
    }
    for (std::size_t k = 0; k < a.perceived.size(); ++k) {
      EXPECT_EQ(a.perceived[k].detected, b.perceived[k].detected);
      EXPECT_TRUE(same_bits(a.perceived[k].x, b.perceived[k].x));
    }
  }
  options.seed = 43;
  auto other_seed = simulate_text(text, options);
  ASSERT_TRUE(other_seed.trace);
  EXPECT_FALSE(same_bits(first.trace->perceived[0].x, other_seed.trace->perceived[0].x))
      << "perception noise depends on the seed";
}

TEST(SimulationTest, AnUnknownLaneIsAnErrorAtItsPlace) {
  auto run = simulate_text(scenario_text("straight", "ego", "", "",
                                         "ego = AV((\"nowhere\"->10, , 0), (\"east_1\"->300));\n"));
  EXPECT_FALSE(run.trace);
  EXPECT_NE(run.errors.find("inline.avu:1:"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("nowhere"), std::string::npos) << run.errors;
}

TEST(SimulationTest, AnUnreachableTargetIsAnError) {
  auto run = simulate_text(scenario_text("straight", "ego", "", "",
                                         "ego = AV((\"east_0\"->10, , 0), (\"west_0\"->300));\n"));
  EXPECT_FALSE(run.trace);
  EXPECT_NE(run.errors.find("no route"), std::string::npos) << run.errors;
}

std::string straight_drive() {
  return scenario_text("straight", "ego", "lead", "",
                       "ego = AV((\"east_0\"->10, , 5), (\"east_0\"->300));\n"
                       "lead = Vehicle((\"east_0\"->60, , 6));\n");
}

TEST(SimulationTest, TheExamplePluginDrivesAScenario) {
  SimulationOptions options;
  options.ego_plugin = SCENFUZZ_EXAMPLE_EGO_PLUGIN;
  options.duration = 20;
  auto run = simulate_text(straight_drive(), options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_EQ(trace.end, EndReason::duration);
  EXPECT_TRUE(trace.collisions.empty());
  const TraceActor& ego = trace.actors[0];
  EXPECT_GT(ego.x.back(), 60.0) << "it drove";
  for (double y : ego.y) EXPECT_NEAR(y, -5.25, 0.5) << "in its lane";
  EXPECT_GT(closest_approach(trace, 0, 1), 1.0) << "behind the slower lead";
}

TEST(SimulationTest, TheExamplePluginReachesItsTarget) {
  SimulationOptions options;
  options.ego_plugin = SCENFUZZ_EXAMPLE_EGO_PLUGIN;
  auto run = simulate_text(scenario_text("straight", "ego", "", "",
                                         "ego = AV((\"east_0\"->10, , 10), (\"east_0\"->150));\n"),
                           options);
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_EQ(run.trace->end, EndReason::target_reached);
  EXPECT_NEAR(run.trace->actors[0].x.back(), 150, 2.0);
}

TEST(SimulationTest, ACrashingPluginEndsOnlyItsOwnRun) {
  SimulationOptions options;
  options.ego_plugin = std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/libcrashing.so";
  auto crashed = simulate_text(straight_drive(), options);
  ASSERT_TRUE(crashed.trace) << crashed.errors;
  EXPECT_EQ(crashed.trace->end, EndReason::ego_failure);
  ASSERT_FALSE(crashed.trace->events.empty());
  const TraceEvent& failure = crashed.trace->events.back();
  EXPECT_EQ(failure.kind, TraceEventKind::ego_failure);
  EXPECT_NE(failure.message.find("SIGSEGV"), std::string::npos) << failure.message;
  EXPECT_GE(crashed.trace->sample_count(), 3u) << "the samples before the crash are kept";

  options.ego_plugin = SCENFUZZ_EXAMPLE_EGO_PLUGIN;
  options.duration = 5;
  auto next = simulate_text(straight_drive(), options);
  ASSERT_TRUE(next.trace);
  EXPECT_EQ(next.trace->end, EndReason::duration) << "the next run is unaffected";
}

TEST(SimulationTest, FogShortensHowFarTheEgoSees) {
  // A car parked 120 m ahead: seen from the start in clear weather, only when close in fog.
  auto first_seen = [](const std::string& environment) {
    auto run = simulate_text(scenario_text("straight", "ego", "parked", "",
                                           "ego = AV((\"east_0\"->10, , 10), (\"east_0\"->400));\n"
                                           "parked = Vehicle((\"east_1\"->130, , 0));\n",
                                           environment));
    EXPECT_TRUE(run.trace) << run.errors;
    const PerceivedActor& seen = run.trace->perceived[0];
    for (std::size_t i = 0; i < seen.detected.size(); ++i)
      if (seen.detected[i])
        return std::hypot(run.trace->actors[1].x[i] - run.trace->actors[0].x[i],
                          run.trace->actors[1].y[i] - run.trace->actors[0].y[i]);
    return 0.0;
  };
  double clear = first_seen("");
  double foggy = first_seen("Environment(12:00, {fog: 0.9});\n");
  EXPECT_GT(clear, 110.0);
  EXPECT_GT(foggy, 5.0);
  EXPECT_LT(foggy, clear / 2);
}

}  // namespace
}  // namespace scenfuzz
