// Scripted NPC motion through the whole simulation is what its class can drive: bends taken at a
// speed its tyres hold, acceleration and jerk within the class's bounds in the recorded trace, and
// a warning naming the actor and the waypoint where the script asks for the impossible.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/actors/actor_class.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::simulate_text;

std::string scenario_on(const std::string& map, const std::string& body) {
  return body + "scenario = CreateScenario{load(\"" + map + "\");\nego;\n{npc1};\n{};\n{};\n};\n";
}

// The largest speed x |yaw rate| of an actor over the trace.
double largest_lateral_acceleration(const TraceActor& actor) {
  double largest = 0;
  for (std::size_t i = 0; i < actor.speed.size(); ++i)
    largest = std::max(largest, actor.speed[i] * std::abs(actor.yaw_rate[i]));
  return largest;
}

// The largest change of the recorded acceleration per second between samples.
double largest_jerk(const Trace& trace, const TraceActor& actor) {
  double largest = 0;
  for (std::size_t i = 1; i < actor.acceleration.size(); ++i)
    largest =
        std::max(largest, std::abs(actor.acceleration[i] - actor.acceleration[i - 1]) / trace.dt);
  return largest;
}

// The speed where the actor first gets to x (driving east).
double speed_at_x(const TraceActor& actor, double x) {
  for (std::size_t i = 0; i < actor.x.size(); ++i)
    if (actor.x[i] >= x) return actor.speed[i];
  return NAN;
}

TEST(ScriptedFeasibility, AJunctionTurnAlongALaneRouteIsTakenAtTheBendSpeed) {
  // A left turn over the crossroads' connector (about 20 m radius) at 11 m/s would be 6 m/s^2.
  // Scripted, so that it drives through the red light the reactive NPC would wait at.
  SimulationOptions scripted;
  scripted.npc_behaviour = NpcBehaviour::scripted;
  auto run = simulate_text(
      scenario_on("crossroads",
                  "ego = AV((\"south_in_0\"->5, , 0), (\"south_in_0\"->140));\n"
                  "npc1 = Vehicle((\"west_in_1\"->100, , 11), , (\"north_out_1\"->80));\n"),
      scripted);
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& npc = run.trace->actors[1];
  const ActorClass& car = actor_class(ActorCategory::car);
  EXPECT_LE(largest_lateral_acceleration(npc), car.comfortable_lateral_acceleration * 1.02);
  EXPECT_GT(npc.y.back(), 40) << "it still gets round the corner and on";
  EXPECT_LE(largest_jerk(*run.trace, npc), car.max_jerk * (1 + 1e-6));
  EXPECT_EQ(run.errors.find("npc1"), std::string::npos) << run.errors;
}

TEST(ScriptedFeasibility, AccelerationAndJerkStayBoundedOnALargeSpeedStep) {
  // 2 -> 12 m/s over 40 m asks for 1.75 m/s^2 at once, then 12 -> 0 over 12 m for 6 m/s^2.
  auto run = simulate_text(
      scenario_on("straight",
                  "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->490));\n"
                  "npc1 = Vehicle((\"east_0\"->100, , 2), Waypoint(((\"east_0\"->140, "
                  ", 12), (\"east_0\"->152, , 0))), (\"east_0\"->300));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& npc = run.trace->actors[1];
  const ActorClass& car = actor_class(ActorCategory::car);
  for (std::size_t i = 0; i < npc.acceleration.size(); ++i) {
    ASSERT_LE(npc.acceleration[i], car.max_acceleration + 1e-9) << i;
    ASSERT_GE(npc.acceleration[i], -car.max_deceleration - 1e-9) << i;
  }
  EXPECT_LE(largest_jerk(*run.trace, npc), car.max_jerk * (1 + 1e-6));
}

TEST(ScriptedFeasibility, AnImpossibleWaypointSpeedIsAWarningWithTheNearestFeasibleSpeed) {
  auto run = simulate_text(
      scenario_on("straight",
                  "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->490));\n"
                  "npc1 = Vehicle((\"east_0\"->100, , 2), Waypoint(((\"east_0\"->120, "
                  ", 2), (\"east_0\"->135, , 20))), (\"east_0\"->300));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  // The waypoint's speed is on line 2, column 78 of the inline file.
  const std::string expected =
      "npc1 cannot reach 20 m/s at its waypoint 2 (15 m after waypoint 1 at 2 m/s): reaches ";
  std::size_t at = run.errors.find(expected);
  ASSERT_NE(at, std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("inline.avu:2:"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("warning"), std::string::npos) << run.errors;
  double reached = std::stod(run.errors.substr(at + expected.size()));
  EXPECT_GT(reached, 5);
  EXPECT_LT(reached, 12);
  const TraceActor& npc = run.trace->actors[1];
  EXPECT_NEAR(speed_at_x(npc, 135), reached, 0.2) << "the warning says what the actor does";
  const ActorClass& car = actor_class(ActorCategory::car);
  EXPECT_LE(*std::max_element(npc.acceleration.begin(), npc.acceleration.end()),
            car.max_acceleration + 1e-9);
}

TEST(ScriptedFeasibility, AFeasibleScriptIsFollowedAsWritten) {
  auto run = simulate_text(
      scenario_on("straight",
                  "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->490));\n"
                  "npc1 = Vehicle((\"east_0\"->100, , 5), Waypoint(((\"east_0\"->150, "
                  ", 10), (\"east_0\"->250, , 6))), (\"east_0\"->400));\n"));
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_EQ(run.errors.find("npc1"), std::string::npos) << run.errors;
  const TraceActor& npc = run.trace->actors[1];
  EXPECT_NEAR(npc.speed.front(), 5, 1e-9);
  EXPECT_NEAR(speed_at_x(npc, 150), 10, 0.05);
  EXPECT_NEAR(speed_at_x(npc, 250), 6, 0.05);
  // And when it was to be there: 50 m at a mean 7.5 m/s, then 100 m at a mean 8 m/s.
  for (std::size_t i = 0; i < npc.x.size(); ++i) {
    if (npc.x[i] < 150) continue;
    EXPECT_NEAR(run.trace->time[i], 50 / 7.5, 0.06);
    break;
  }
}

}  // namespace
}  // namespace scenfuzz
