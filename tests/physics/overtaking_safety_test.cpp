// The reference driver's overtaking done as a law-abiding driver does it: it does not pull out
// while a car is alongside or close behind in the passing lane (the mirror check), it pulls out
// from a standstill close behind a parked car without touching it (the swept path is checked
// before it moves), and it indicates for 3 s before its centre leaves its lane (indicate, then
// move) and indicates back before it returns.
#include <gtest/gtest.h>

#include <string>

#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::closest_approach;
using test::simulate_text;

// east_0 (y = -5.25) and east_1 (y = -1.75) with a broken line between them at y = -3.5.
constexpr double kOwnLaneEdge = -3.5;

std::string two_lane_scenario(const std::string& npcs, const std::string& body) {
  return body + "scenario = CreateScenario{load(\"straight?two_way=0\");\nego;\n{" + npcs +
         "};\n{};\n{};\n};\n";
}

SimulationOptions lasting(double seconds) {
  SimulationOptions options;
  options.duration = seconds;
  return options;
}

// The first sample at which the ego's centre has left east_0, or the sample count.
std::size_t first_out_of_lane(const Trace& trace) {
  const TraceActor& ego = trace.actors[0];
  std::size_t i = 0;
  while (i < trace.sample_count() && ego.y[i] <= kOwnLaneEdge) ++i;
  return i;
}

bool shows(const TraceActor& actor, std::size_t i, VehicleSignals signal) {
  return i < actor.signals.size() && (actor.signals[i] & signal) != 0;
}

// A car in east_1 starts a little behind the ego at its speed and stays beside it while the ego
// closes in on a parked car: the ego must wait until that car has gone by before pulling out.
TEST(OvertakingSafetyTest, DoesNotPullOutWhileACarIsAlongsideInThePassingLane) {
  auto run =
      simulate_text(two_lane_scenario("parked, beside",
                                      "ego = AV((\"east_0\"->40, , 8), (\"east_0\"->300));\n"
                                      "parked = Vehicle((\"east_0\"->75, , 0));\n"
                                      "beside = Vehicle((\"east_1\"->36, , 6), "
                                      "uniform((\"east_1\"->36, , 6)), (\"east_1\"->499));\n"),
                    lasting(90));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 2), 1.0) << "never nearer than side by side in lanes";
  const TraceActor& ego = trace.actors[0];
  const TraceActor& beside = trace.actors[2];
  const std::size_t out = first_out_of_lane(trace);
  ASSERT_LT(out, trace.sample_count()) << "the ego should have passed the parked car";
  // Bumper to bumper (4.93 m and 4.7 m long): the car beside is well ahead when the ego moves.
  EXPECT_GT(beside.x[out] - ego.x[out], 4.9 + 5.0)
      << "pulled out at t = " << trace.time[out] << " with the car beside at " << beside.x[out]
      << " and the ego at " << ego.x[out];
}

// In thick fog (vehicles seen to about 22 m) the ego stands behind a parked car with room to pull
// out, while a car comes up east_1 from 35 m behind at 16 m/s, unseen at first. Pulling out at
// once, the ego would put itself in that car's way; indicating first, it sees the car come up
// (the mirror) and waits for it. The rear car never has to brake harder than the safe-braking
// limit (2 m/s^2, with a little slack for its own controller).
TEST(OvertakingSafetyTest, DoesNotPullOutInFrontOfACarComingUpBehindInFog) {
  auto run = simulate_text(
      "ego = AV((\"east_0\"->60, , 0), (\"east_0\"->300));\n"
      "parked = Vehicle((\"east_0\"->77.5, , 0));\n"
      "behind = Vehicle((\"east_1\"->25, , 16), uniform((\"east_1\"->25, , 16)), "
      "(\"east_1\"->499));\n"
      "scenario = CreateScenario{load(\"straight?two_way=0\");\nego;\n{parked, behind};\n{};\n{};\n"
      "Environment(12:00, {fog: 1.0});\n};\n",
      lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 2), 1.0);
  const TraceActor& behind = trace.actors[2];
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    ASSERT_GT(behind.acceleration[i], -2.5) << "the car behind braked at t = " << trace.time[i];
  const std::size_t out = first_out_of_lane(trace);
  ASSERT_LT(out, trace.sample_count()) << "the ego should have passed the parked car";
  EXPECT_GT(behind.x[out], trace.actors[0].x[out]) << "it pulled out before the car went by";
}

// From a standstill 5 m behind a parked car (bumper to bumper), east_1 free: the ego pulls out
// round it (tightly, at walking pace) and never touches it.
TEST(OvertakingSafetyTest, PullsOutFromFiveMetresBehindAParkedCarWithoutContact) {
  // The ego's front at 20 + 4.93 / 2 = 22.47; the parked car's rear at 29.82 - 4.7 / 2 = 27.47.
  auto run = simulate_text(two_lane_scenario("parked",
                                             "ego = AV((\"east_0\"->20, , 0), (\"east_0\"->200));\n"
                                             "parked = Vehicle((\"east_0\"->29.82, , 0));\n"),
                           lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 1), 0.2);
}

// A car crawling at 0.6 m/s (faster than standing, slower than walking pace) is swept as if it
// stood: the ego, crawling up behind it, pulled out round it unchecked and clipped its rear
// corner (a law-corpus finding on san_francisco, following_slow).
TEST(OvertakingSafetyTest, PullsOutRoundACarCrawlingAtWalkingPaceWithoutContact) {
  for (const char* start : {"28.0", "30.0", "32.0"}) {
    auto run =
        simulate_text(two_lane_scenario("crawler",
                                        "ego = AV((\"east_0\"->20, , 0), (\"east_0\"->200));\n"
                                        "crawler = Vehicle((\"east_0\"->" +
                                            std::string(start) + ", , 0.6));\n"),
                      lasting(90));
    ASSERT_TRUE(run.trace) << run.errors;
    const Trace& trace = *run.trace;
    EXPECT_TRUE(trace.collisions.empty()) << start;
    EXPECT_EQ(trace.end, EndReason::target_reached) << start;
    EXPECT_GT(closest_approach(trace, 0, 1), 0.2) << start;
  }
}

// Stopped behind a crate with traffic in the passing lane, the ego began a pull-out, gave it up
// for a car coming up behind before it had moved out, and then stood indicating right for ever,
// waiting to drive a move back it never needed (a corpus finding, stationary_obstacle_in_lane).
TEST(OvertakingSafetyTest, APullOutGivenUpBeforeMovingOutIsDroppedNotDrivenBack) {
  auto run = simulate_text(
      "ego = AV((\"east_0\"->47.3, , 15.97), (\"east_0\"->420));\n"
      "wreck = Obstacle(\"east_0\"->297.56, (box, 4.5, 1.9, 1.5));\n"
      "crate = Obstacle(\"east_0\"->289.56, (box, 1.2, 1.0, 0.8));\n"
      "npc1 = Vehicle((\"east_1\"->118.02, , 10.51), uniform((\"east_1\"->118.02, , 10.51)), "
      "(\"east_1\"->495));\n"
      "npc2 = Vehicle((\"east_1\"->17.27, , 10.51), uniform((\"east_1\"->17.27, , 10.51)), "
      "(\"east_1\"->470), (\"Truck\", red));\n"
      "scenario = CreateScenario{load(\"straight\");\nego;\n{npc1, npc2};\n{};\n"
      "{wreck, crate};\n};\n",
      lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_EQ(trace.end, EndReason::target_reached);
  for (const auto& collision : trace.collisions) EXPECT_NE(collision.first, 0u);
}

// Indicate, then move: the left indicator is on for at least 2.5 s (the rule is 3 s) before the
// ego's centre leaves its lane, and the right one comes on before it moves back.
TEST(OvertakingSafetyTest, IndicatesBeforeItsCentreLeavesItsLane) {
  auto run =
      simulate_text(two_lane_scenario("parked",
                                      "ego = AV((\"east_0\"->20, , 15), (\"east_0\"->400));\n"
                                      "parked = Vehicle((\"east_0\"->150, , 0));\n"),
                    lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const TraceActor& ego = trace.actors[0];
  const std::size_t out = first_out_of_lane(trace);
  ASSERT_LT(out, trace.sample_count()) << "the ego should have passed the parked car";
  std::size_t on = out;
  while (on > 0 && shows(ego, on - 1, vehicle_signal::left_indicator)) --on;
  EXPECT_GE(trace.time[out] - trace.time[on], 2.5)
      << "the indicator came on at t = " << trace.time[on]
      << ", the centre left at t = " << trace.time[out];
  // Moving back: the right indicator is on before the centre re-enters east_0.
  std::size_t back = out;
  while (back < trace.sample_count() && ego.y[back] > kOwnLaneEdge) ++back;
  ASSERT_LT(back, trace.sample_count()) << "the ego should have come back into east_0";
  std::size_t right = back;
  while (right > out && shows(ego, right - 1, vehicle_signal::right_indicator)) --right;
  EXPECT_GE(trace.time[back] - trace.time[right], 1.0)
      << "the right indicator came on at t = " << trace.time[right]
      << ", back in at t = " << trace.time[back];
}

}  // namespace
}  // namespace scenfuzz
