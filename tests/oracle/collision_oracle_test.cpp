// The collision oracle: the ego's clearance to the nearest other body (vehicles, pedestrians,
// obstacles of every shape), negative by the penetration depth, and the verdict's minimum, first
// sample and body; on simulated runs it is negative exactly when the ego collided.
#include "oracle/collision_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::empty_trace;
using test::still_actor;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(CollisionOracleTest, AnEgoAloneHasInfiniteClearance) {
  Trace trace = empty_trace(3);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, 0));
  EXPECT_EQ(ego_clearance(trace), std::vector<double>(3, kInfinity));
  const CollisionVerdict verdict = collision_verdict(trace);
  EXPECT_EQ(verdict.robustness, kInfinity);
  EXPECT_EQ(verdict.sample, 0u);
  EXPECT_EQ(verdict.other, kEgo);
}

TEST(CollisionOracleTest, ClearanceIsTheGapToTheNearestBodyAndMinusThePenetration) {
  Trace trace = empty_trace(4);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, 0));
  trace.actors.push_back(
      still_actor(trace, "npc", TraceActorKind::vehicle, BodyShape::box, 4.6, 1.8, 10, 0));
  TraceActor& npc = trace.actors[1];
  npc.x[1] = 4.3;  // touching
  npc.x[2] = 3;    // 1.3 m into the ego
  npc.x[3] = 3;
  const std::vector<double> clearance = ego_clearance(trace);
  EXPECT_DOUBLE_EQ(clearance[0], 10 - 2 - 2.3);
  EXPECT_NEAR(clearance[1], 0, 1e-12);
  EXPECT_NEAR(clearance[2], -1.3, 1e-12) << "not clamped: minus the penetration depth";
  const CollisionVerdict verdict = collision_verdict(trace);
  EXPECT_NEAR(verdict.robustness, -1.3, 1e-12);
  EXPECT_EQ(verdict.sample, 2u) << "the first sample of the minimum";
  EXPECT_EQ(verdict.other, 1u);
}

TEST(CollisionOracleTest, EveryKindOfBodyCounts) {
  // Each body is nearest at one sample: the others are parked far away then.
  Trace trace = empty_trace(5);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, 0));
  trace.actors.push_back(
      still_actor(trace, "npc", TraceActorKind::vehicle, BodyShape::box, 4, 2, 100, 0));
  trace.actors.push_back(still_actor(trace, "ped", TraceActorKind::pedestrian, BodyShape::cylinder,
                                     0.6, 0.6, 100, 50));
  trace.actors.push_back(
      still_actor(trace, "crate", TraceActorKind::obstacle, BodyShape::box, 2, 1, 100, 100));
  trace.actors.push_back(
      still_actor(trace, "ball", TraceActorKind::obstacle, BodyShape::sphere, 1, 1, 100, 150));
  trace.actors.push_back(
      still_actor(trace, "cone", TraceActorKind::obstacle, BodyShape::cone, 0.8, 0.8, 100, 200));
  // npc 3 m ahead; the walker beside the right flank; the crate, turned across, behind; the
  // ball 0.3 m into the front; the cone 0.6 m into the left flank.
  trace.actors[1].x[0] = 7;
  trace.actors[2].x[1] = 0;
  trace.actors[2].y[1] = -2.5;
  trace.actors[3].x[2] = -3.5;
  trace.actors[3].y[2] = 0;
  trace.actors[3].heading[2] = std::numbers::pi / 2;
  trace.actors[4].x[3] = 2.2;
  trace.actors[4].y[3] = 0;
  trace.actors[5].x[4] = 0;
  trace.actors[5].y[4] = 0.8;
  const std::vector<double> clearance = ego_clearance(trace);
  EXPECT_DOUBLE_EQ(clearance[0], 7 - 2 - 2);
  EXPECT_DOUBLE_EQ(clearance[1], 2.5 - 1 - 0.3);
  EXPECT_NEAR(clearance[2], 3.5 - 2 - 0.5, 1e-12);
  EXPECT_NEAR(clearance[3], -0.3, 1e-12);
  EXPECT_NEAR(clearance[4], -0.6, 1e-12);
  const CollisionVerdict verdict = collision_verdict(trace);
  EXPECT_NEAR(verdict.robustness, -0.6, 1e-12);
  EXPECT_EQ(verdict.sample, 4u);
  EXPECT_EQ(verdict.other, 5u);
}

// The rammer starts 25 m behind the ego (at rest) and drives on at `speed`; the cutter starts in
// the left lane just ahead of the ego and moves over into its lane at `speed`.
std::string rear_end(const std::string& speed) {
  return "ego = AV((\"east_0\"->100, , 0), (\"east_0\"->480));\n"
         "rammer = Vehicle((\"east_0\"->75, , " +
         speed + "), Waypoint((\"east_0\"->150, , " + speed +
         ")), (\"east_0\"->400));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {rammer}; {}; {};};\n"
         "Trace trace = EXE(scenario);\n";
}

std::string cut_in(const std::string& speed) {
  return "ego = AV((\"east_0\"->50, , 25), (\"east_0\"->480));\n"
         "cutter = Vehicle((\"east_1\"->57.7, , " +
         speed + "), Waypoint((\"east_0\"->85, , " + speed +
         ")), (\"east_0\"->400));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {cutter}; {}; {};};\n"
         "Trace trace = EXE(scenario);\n";
}

bool ego_collided(const Trace& trace) {
  for (const Collision& collision : trace.collisions)
    if (collision.first == kEgo) return true;
  return false;
}

TEST(CollisionOracleTest, NegativeExactlyWhenTheSimulatedEgoCollides) {
  int collisions = 0, clear_runs = 0;
  for (const std::string& text :
       {rear_end("25"), rear_end("15"), rear_end("0.5"), cut_in("15"), cut_in("22")}) {
    SimulationOptions options;
    options.duration = 15;
    test::SimulatedScenario run = test::simulate_scenario(text, options);
    ASSERT_TRUE(run.trace) << run.errors;
    const CollisionVerdict verdict = collision_verdict(*run.trace);
    const bool collided = ego_collided(*run.trace);
    (collided ? collisions : clear_runs) += 1;
    EXPECT_EQ(verdict.robustness < 0, collided) << text << "robustness " << verdict.robustness;
    EXPECT_EQ(verdict.other, 1u);
    const std::vector<double> clearance = ego_clearance(*run.trace);
    ASSERT_EQ(clearance.size(), run.trace->sample_count());
    EXPECT_EQ(clearance[verdict.sample], verdict.robustness);
    if (collided) {
      EXPECT_NEAR(run.trace->time[verdict.sample], run.trace->collisions[0].time, 1e-9)
          << "the deepest contact is where the run stopped";
    }
  }
  EXPECT_GT(collisions, 0);
  EXPECT_GT(clear_runs, 0);
}

}  // namespace
}  // namespace scenfuzz
