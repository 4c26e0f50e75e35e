// AVUnit's signal functions and projection columns on traces with exact geometry, and specs over
// simulated runs: dis is the gap between footprints, vel/acc norms of vector differences, spd a
// signed speed difference, diff LawBreaker's weighted perception error, 1000 where the agent is
// unseen; errors name the term.
#include "oracle/trace_signals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::empty_trace;
using test::miss;
using test::parse_scenario;
using test::perceive_perfectly;
using test::still_actor;

constexpr double kPi = std::numbers::pi;

// The scenario the hand-built traces belong to: its actors in trace order.
std::string scenario_with(const std::string& specs) {
  return "ego = AV((\"east_0\"->10, , 0), (\"east_0\"->300));\n"
         "npc = Vehicle((\"east_0\"->50, , 0));\n"
         "ped = Pedestrian(((80, -9), 90 deg, 1.4), uniform(((80, -9), 90 deg, 1.4)));\n"
         "box1 = Obstacle(((30, -5.25), 0 deg), (box, 2, 1, 1));\n"
         "ball = Obstacle((40, -5.25), (sphere, 0.5));\n"
         "cone1 = Obstacle((50, -5.25), (cone, 0.4, 1, 1));\n"
         "can = Obstacle((60, -5.25), (cylinder, 0.3, 1, 1));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {npc}; {ped}; "
         "{box1, ball, cone1, can};};\n"
         "Trace trace = EXE(scenario);\n" +
         specs;
}

class TraceSignalsTest : public ::testing::Test {
 protected:
  TraceSignalsTest() {
    // ego 4 x 2 at x = 0 facing east; npc 4.6 x 1.8 ten metres ahead, nose to tail.
    trace.actors.push_back(
        still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, -5.25));
    trace.actors.push_back(
        still_actor(trace, "npc", TraceActorKind::vehicle, BodyShape::box, 4.6, 1.8, 10, -5.25));
    trace.actors.push_back(still_actor(trace, "ped", TraceActorKind::pedestrian,
                                       BodyShape::cylinder, 0.6, 0.6, 0, -15.25));
    trace.actors.push_back(
        still_actor(trace, "box1", TraceActorKind::obstacle, BodyShape::box, 2, 1, 30, -5.25));
    trace.actors.push_back(
        still_actor(trace, "ball", TraceActorKind::obstacle, BodyShape::sphere, 1, 1, 40, -5.25));
    trace.actors.push_back(still_actor(trace, "cone1", TraceActorKind::obstacle, BodyShape::cone,
                                       0.8, 0.8, 50, -5.25));
    trace.actors.push_back(still_actor(trace, "can", TraceActorKind::obstacle, BodyShape::cylinder,
                                       0.6, 0.6, 60, -5.25));
    perceive_perfectly(trace);
  }

  TraceActor& actor(const std::string& name) { return trace.actors[*trace.find_actor(name)]; }
  PerceivedActor& seen(const std::string& name) {
    return trace.perceived[*trace.find_actor(name) - 1];
  }

  // The values of `expression` (a term of the spec language) at every sample.
  std::vector<double> values_of(const std::string& expression) {
    const test::ParsedScenario parsed =
        parse_scenario(scenario_with("trace |= " + expression + " >= 0;\n"));
    const TraceSignals signals(trace, parsed.scenario, parsed.parameters, map);
    std::vector<double> values =
        term_signal(parsed.scenario.specs.at(0).formula.terms.at(0), signals.source()).values;
    EXPECT_EQ(values.size(), trace.sample_count());
    for (double value : values) EXPECT_TRUE(std::isfinite(value)) << expression;
    return values;
  }

  // The error evaluating `expression` raises.
  OracleError error_of(const std::string& expression) {
    try {
      values_of(expression);
    } catch (const OracleError& error) {
      return error;
    }
    ADD_FAILURE() << expression << " gave no error";
    return OracleError({}, "");
  }

  RoadMap map = load_map("straight", map_search_path({}));
  Trace trace = empty_trace(5);
};

TEST_F(TraceSignalsTest, DisBetweenTwoCarsNoseToTailIsTheGapBetweenBumpers) {
  actor("npc").x[1] = 3;    // overlapping by 1.3 m
  actor("npc").x[2] = 4.3;  // touching
  perceive_perfectly(trace);
  const std::vector<double> gap = values_of("dis(trace[ego], trace[truth][npc])");
  EXPECT_DOUBLE_EQ(gap[0], 10 - 2 - 2.3);
  EXPECT_DOUBLE_EQ(gap[1], 0) << "clamped to 0 when overlapping";
  EXPECT_NEAR(gap[2], 0, 1e-12) << "0 when touching";
  EXPECT_EQ(values_of("dis(trace[truth][npc], trace[ego])"), gap) << "symmetric";
  EXPECT_EQ(values_of("dis(trace[ego], trace[ego])"), std::vector<double>(5, 0.0));
}

TEST_F(TraceSignalsTest, DisToAPositionIsFromTheFootprintToThePoint) {
  for (double gap : values_of("dis(trace[ego], (20, -5.25))")) EXPECT_DOUBLE_EQ(gap, 18);
  for (double gap : values_of("dis(trace[ego], \"east_0\"->30)")) EXPECT_DOUBLE_EQ(gap, 28);
  // IMU: x to the right, y forward of the ego's initial pose (facing east at (0, -5.25)).
  for (double gap : values_of("dis(trace[ego], IMU (0, 10))")) EXPECT_NEAR(gap, 8, 1e-9);
  for (double gap : values_of("dis(trace[ego], (1, -5.25))")) EXPECT_DOUBLE_EQ(gap, 0);
  for (double gap : values_of("dis((0, 0), (3, 4))")) EXPECT_DOUBLE_EQ(gap, 5);
}

TEST_F(TraceSignalsTest, DisToObstaclesOfEveryShape) {
  EXPECT_DOUBLE_EQ(values_of("dis(trace[ego], trace[truth][box1])")[0], 30 - 1 - 2);
  EXPECT_DOUBLE_EQ(values_of("dis(trace[ego], trace[truth][ball])")[0], 40 - 0.5 - 2);
  EXPECT_DOUBLE_EQ(values_of("dis(trace[ego], trace[truth][cone1])")[0], 50 - 0.4 - 2);
  EXPECT_DOUBLE_EQ(values_of("dis(trace[ego], trace[truth][can])")[0], 60 - 0.3 - 2);
  // A pedestrian 10 m to the right of the ego's centre line: a disc of radius 0.3.
  EXPECT_DOUBLE_EQ(values_of("dis(trace[ego], trace[truth][ped])")[0], 10 - 1 - 0.3);
  // The box turned across the road is narrower along it.
  actor("box1").heading[0] = kPi / 2;
  EXPECT_NEAR(values_of("dis(trace[ego], trace[truth][box1])")[0], 30 - 0.5 - 2, 1e-12);
  // Obstacle to obstacle: disc to disc.
  EXPECT_DOUBLE_EQ(values_of("dis(trace[truth][ball], trace[truth][cone1])")[0], 10 - 0.5 - 0.4);
}

TEST_F(TraceSignalsTest, DisToAPerceivedAgentUsesItsPerceivedPoseAndTrueSize) {
  seen("npc").x[0] = 11;
  seen("npc").heading[1] = kPi / 2;  // seen turned across: its 1.8 m width now lies along x
  miss(seen("npc"), 3);
  const std::vector<double> gap = values_of("dis(trace[ego], trace[perception][npc])");
  EXPECT_DOUBLE_EQ(gap[0], 11 - 2 - 2.3);
  EXPECT_NEAR(gap[1], 10 - 2 - 0.9, 1e-12);
  EXPECT_DOUBLE_EQ(gap[2], 10 - 2 - 2.3);
  EXPECT_DOUBLE_EQ(gap[3], 1000) << "LawBreaker's value for an agent that is not seen";
  EXPECT_DOUBLE_EQ(values_of("dis(trace[perception][npc], (10, -5.25))")[3], 1000);
}

TEST_F(TraceSignalsTest, VelIsTheNormOfTheVelocityDifference) {
  for (std::size_t i = 0; i < 5; ++i) {
    actor("ego").speed[i] = 10;
    actor("npc").speed[i] = 10;
    actor("npc").heading[i] = kPi / 2;
  }
  perceive_perfectly(trace);
  miss(seen("npc"), 4);
  const std::vector<double> crossing = values_of("vel(trace[ego], trace[truth][npc])");
  EXPECT_NEAR(crossing[0], std::sqrt(200.0), 1e-12);
  EXPECT_NEAR(values_of("vel(trace[ego], (10, 0))")[0], 0, 1e-12);
  EXPECT_NEAR(values_of("vel(trace[truth][npc], (0, 10))")[0], 0, 1e-12);
  EXPECT_NEAR(values_of("vel((3, 0), (0, 4))")[0], 5, 1e-12);
  const std::vector<double> perceived = values_of("vel(trace[ego], trace[perception][npc])");
  EXPECT_NEAR(perceived[0], std::sqrt(200.0), 1e-12);
  EXPECT_DOUBLE_EQ(perceived[4], 1000);
}

// `vel(a, (x, y, z))`: z is the up component (the grammar's <coordinate>), and simulated agents
// move in the plane, so it adds to the difference as a vertical one.
TEST_F(TraceSignalsTest, ThreeComponentVectorsHaveAVerticalComponent) {
  for (std::size_t i = 0; i < 5; ++i) actor("ego").speed[i] = 3;
  EXPECT_NEAR(values_of("vel(trace[ego], (3, 0, 4))")[0], 4, 1e-12);
  EXPECT_NEAR(values_of("vel(trace[ego], (0, 0, +4))")[0], 5, 1e-12);
  EXPECT_NEAR(values_of("vel((3, 0, 12), (0, 4))")[0], 13, 1e-12);
  EXPECT_NEAR(values_of("vel((1, 2, -3) + (2, 2, 3), (0, 0, 12))")[0], 13, 1e-12);
  EXPECT_NEAR(values_of("acc(trace[ego], (0, 0, -2))")[0], 2, 1e-12);
}

TEST_F(TraceSignalsTest, AReversingAgentsVelocityAndAccelerationPointBackwards) {
  // The npc backs up towards the ego at 4 m/s, facing east, and speeds up at 1 m/s^2; the ego
  // drives east at 10 m/s.
  TraceActor& npc = actor("npc");
  for (std::size_t i = 0; i < 5; ++i) {
    actor("ego").speed[i] = 10;
    npc.speed[i] = 4;
    npc.acceleration[i] = 1;
  }
  npc.reversing.assign(trace.sample_count(), 1);
  perceive_perfectly(trace);
  EXPECT_NEAR(values_of("vel(trace[ego], trace[truth][npc])")[0], 14, 1e-12);
  EXPECT_NEAR(values_of("vel(trace[truth][npc], (-4, 0))")[0], 0, 1e-12);
  EXPECT_NEAR(values_of("vel(trace[ego], trace[perception][npc])")[0], 14, 1e-12);
  EXPECT_NEAR(values_of("acc(trace[truth][npc], (-1, 0))")[0], 0, 1e-12);
  EXPECT_DOUBLE_EQ(values_of("spd(trace[ego], trace[truth][npc])")[0], 6)
      << "speeds stay magnitudes";
  EXPECT_NEAR(values_of("diff(trace[perception][npc], trace[truth][npc])")[0], 0, 1e-12);
}

TEST_F(TraceSignalsTest, SpdIsTheSignedDifferenceOfSpeeds) {
  for (std::size_t i = 0; i < 5; ++i) {
    actor("ego").speed[i] = 10;
    actor("npc").speed[i] = 4;
  }
  perceive_perfectly(trace);
  miss(seen("npc"), 2);
  EXPECT_DOUBLE_EQ(values_of("spd(trace[ego], trace[truth][npc])")[0], 6);
  EXPECT_DOUBLE_EQ(values_of("spd(trace[truth][npc], trace[ego])")[0], -6);
  EXPECT_DOUBLE_EQ(values_of("spd(trace[ego], 3)")[0], 7) << "a number is a speed";
  EXPECT_DOUBLE_EQ(values_of("spd(12, trace[ego])")[0], 2);
  const std::vector<double> perceived = values_of("spd(trace[ego], trace[perception][npc])");
  EXPECT_DOUBLE_EQ(perceived[0], 6);
  EXPECT_DOUBLE_EQ(perceived[2], 1000);
}

TEST_F(TraceSignalsTest, AccAddsTheLateralAccelerationOfTurning) {
  // 2 m/s^2 along the heading; 10 m/s at 0.1 rad/s: 1 m/s^2 towards the left.
  TraceActor& ego = actor("ego");
  for (std::size_t i = 0; i < 5; ++i) {
    ego.acceleration[i] = 2;
    ego.speed[i] = 10;
    ego.yaw_rate[i] = 0.1;
  }
  ego.heading[1] = kPi / 2;
  const std::vector<double> still = values_of("acc(trace[ego], (0, 0))");
  EXPECT_NEAR(still[0], std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(values_of("acc(trace[ego], (2, 1))")[0], 0, 1e-12);
  EXPECT_NEAR(values_of("acc(trace[ego], (-1, 2))")[1], 0, 1e-12) << "facing north";
  EXPECT_NEAR(values_of("acc(trace[ego], trace[truth][npc])")[0], std::sqrt(5.0), 1e-12);
}

TEST_F(TraceSignalsTest, AccOfAPerceivedAgentDifferencesItsPerceivedVelocity) {
  Trace longer = empty_trace(7);
  longer.actors = {
      still_actor(longer, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, -5.25),
      still_actor(longer, "npc", TraceActorKind::vehicle, BodyShape::box, 4.6, 1.8, 10, -5.25),
      still_actor(longer, "ped", TraceActorKind::pedestrian, BodyShape::cylinder, 0.6, 0.6, 0, -15),
      still_actor(longer, "box1", TraceActorKind::obstacle, BodyShape::box, 2, 1, 30, -5.25),
      still_actor(longer, "ball", TraceActorKind::obstacle, BodyShape::sphere, 1, 1, 40, -5.25),
      still_actor(longer, "cone1", TraceActorKind::obstacle, BodyShape::cone, 1, 1, 50, -5.25),
      still_actor(longer, "can", TraceActorKind::obstacle, BodyShape::cylinder, 1, 1, 60, -5.25)};
  // Speeding up by 0.3 m/s every 0.1 s: 3 m/s^2.
  for (std::size_t i = 0; i < 7; ++i) longer.actors[1].speed[i] = 0.3 * static_cast<double>(i);
  perceive_perfectly(longer);
  miss(longer.perceived[0], 2);
  miss(longer.perceived[0], 4);
  trace = longer;
  const std::vector<double> error = values_of("acc(trace[perception][npc], (3, 0))");
  EXPECT_NEAR(error[0], 0, 1e-9) << "one-sided at the start";
  EXPECT_NEAR(error[1], 0, 1e-9) << "one-sided before a miss";
  EXPECT_DOUBLE_EQ(error[2], 1000) << "not detected";
  EXPECT_DOUBLE_EQ(error[3], 1000) << "an isolated detection tells no acceleration";
  EXPECT_NEAR(error[5], 0, 1e-9);
  EXPECT_NEAR(error[6], 0, 1e-9);
}

TEST_F(TraceSignalsTest, DiffWeighsPositionVelocityAndHeadingErrors) {
  PerceivedActor& npc = seen("npc");
  npc.x[0] += 0.7;        // position error 0.7: 2 * 0.7 / 7
  npc.speed[1] += 0.35;   // velocity error 0.35: 2 * 0.35 / 7
  npc.heading[2] += 0.7;  // heading error 0.7 (npc stands still: no velocity error): 0.7 / 7
  miss(npc, 3);           // 10 m from the ego: 1000 for each error
  miss(npc, 4);
  actor("npc").x[4] = 200;  // more than 100 m away: not a perception error
  const std::vector<double> diff = values_of("diff(trace[perception][npc], trace[truth][npc])");
  EXPECT_NEAR(diff[0], 0.2, 1e-12);
  EXPECT_NEAR(diff[1], 0.1, 1e-12);
  EXPECT_NEAR(diff[2], 0.1, 1e-12);
  EXPECT_NEAR(diff[3], 5000.0 / 7, 1e-9);
  EXPECT_DOUBLE_EQ(diff[4], 0);
  // The heading error is wrapped: 2 pi - 0.1 off is 0.1 off.
  npc.heading[0] = 2 * kPi - 0.1;
  npc.x[0] = actor("npc").x[0];
  EXPECT_NEAR(values_of("diff(trace[perception][npc], trace[truth][npc])")[0], 0.1 / 7, 1e-12);
}

TEST_F(TraceSignalsTest, ColumnsReadTheProjectedActor) {
  TraceActor& npc = actor("npc");
  for (std::size_t i = 0; i < 5; ++i) {
    npc.speed[i] = 3 + static_cast<double>(i);
    npc.acceleration[i] = 1;
    npc.yaw_rate[i] = 0.25;
    npc.lane[i] = 0;
    npc.s[i] = 10;
  }
  perceive_perfectly(trace);
  seen("npc").x[2] = 10.5;
  EXPECT_EQ(values_of("trace[ego].x"), std::vector<double>(5, 0.0));
  EXPECT_EQ(values_of("trace[truth][npc].speed"), npc.speed);
  EXPECT_EQ(values_of("trace[truth][npc].acceleration"), npc.acceleration);
  EXPECT_EQ(values_of("trace[truth][npc].yaw_rate"), npc.yaw_rate);
  EXPECT_EQ(values_of("trace[truth][npc].s"), npc.s);
  EXPECT_EQ(values_of("trace[truth][npc].heading"), npc.heading);
  EXPECT_EQ(values_of("trace[truth][box1].y"), std::vector<double>(5, -5.25));
  EXPECT_DOUBLE_EQ(values_of("trace[perception][npc].x")[2], 10.5)
      << "the perceived value, defined because npc is seen throughout";
}

TEST_F(TraceSignalsTest, APerceivedColumnIsUndefinedWhereTheAgentIsNotDetected) {
  miss(seen("npc"), 3);
  const OracleError error = error_of("trace[perception][npc].x");
  const std::string message = error.what();
  EXPECT_NE(message.find("'trace[perception][npc].x' is undefined where npc is not detected"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("t = 0.3"), std::string::npos) << message;
  EXPECT_NE(message.find("dis(...)"), std::string::npos) << message;
  EXPECT_EQ(error.location().line, 10u);
  const std::string yaw = error_of("trace[perception][ped].yaw_rate").what();
  EXPECT_NE(yaw.find("x, y, heading and speed"), std::string::npos) << yaw;
}

TEST_F(TraceSignalsTest, WhatTheTraceCannotGiveIsAnErrorAtTheTerm) {
  trace.actors.pop_back();  // the trace lacks `can`
  trace.perceived.pop_back();
  const OracleError missing = error_of("dis(trace[ego], trace[truth][can])");
  EXPECT_NE(std::string(missing.what()).find("no actor 'can'"), std::string::npos);
  EXPECT_EQ(missing.location().line, 10u);
  EXPECT_GT(missing.location().column, 1u);

  const std::string lane = error_of("dis(trace[ego], \"nowhere\"->10)").what();
  EXPECT_NE(lane.find("nowhere"), std::string::npos) << lane;

  const std::string blinking = error_of("trafficLightAhead.isBlinking").what();
  EXPECT_EQ(blinking,
            "the oracle does not compute 'trafficLightAhead.isBlinking' on simulated traces yet");
}

TEST_F(TraceSignalsTest, RobustnessOfASpecReadsTheSignals) {
  // npc drives off at 5 m/s: the gap grows from 5.7 m by 0.5 m per sample.
  for (std::size_t i = 0; i < 5; ++i) actor("npc").x[i] = 10 + 0.5 * static_cast<double>(i);
  perceive_perfectly(trace);
  const test::ParsedScenario parsed =
      parse_scenario(scenario_with("trace |= G (dis(trace[ego], trace[truth][npc]) >= 1.0);\n"
                                   "trace |= F (dis(trace[ego], trace[truth][npc]) >= 7.0);\n"));
  const std::vector<double> robustness = test::spec_robustness(trace, parsed, map);
  EXPECT_NEAR(robustness[0], 5.7 - 1.0, 1e-12);
  EXPECT_NEAR(robustness[1], 7.7 - 7.0, 1e-12);
}

// A car 25 m behind the ego (which starts from rest) that drives on at `rammer_speed`: at 25 m/s
// a rear-end collision the ego cannot escape.
std::string rear_end(const std::string& rammer_speed) {
  return "ego = AV((\"east_0\"->100, , 0), (\"east_0\"->480));\n"
         "rammer = Vehicle((\"east_0\"->75, , " +
         rammer_speed + "), Waypoint((\"east_0\"->150, , " + rammer_speed +
         ")), (\"east_0\"->400));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {rammer}; {}; {};};\n"
         "Trace trace = EXE(scenario);\n"
         "ego_state = trace[ego];\n"
         "npc_truth = trace[truth][rammer];\n"
         "trace |= G (dis(ego_state, npc_truth) >= 1.0);\n";
}

TEST(TraceSignalsSimulationTest, ARearEndCollisionViolatesAKeepYourDistanceSpec) {
  test::SimulatedScenario run = test::simulate_scenario(rear_end("25"));
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_FALSE(run.trace->collisions.empty()) << "the scenario should end in a collision";
  const std::vector<double> robustness = test::spec_robustness(*run.trace, run.parsed, *run.map);
  EXPECT_DOUBLE_EQ(robustness[0], -1.0) << "dis is 0 at contact, 1 m short of the spec";
}

TEST(TraceSignalsSimulationTest, AFollowingCarThatKeepsItsDistanceSatisfiesIt) {
  SimulationOptions options;
  options.duration = 10;
  test::SimulatedScenario run = test::simulate_scenario(rear_end("0.5"), options);
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_TRUE(run.trace->collisions.empty());
  const std::vector<double> robustness = test::spec_robustness(*run.trace, run.parsed, *run.map);
  EXPECT_GT(robustness[0], 0);
}

TEST(TraceSignalsSimulationTest, EverySignalIsFiniteOnASimulatedRunWithMisses) {
  // Fog and distance make the ego miss the walker now and then.
  test::SimulatedScenario run = test::simulate_scenario(
      "ego = AV((\"east_0\"->10, , 10), (\"east_0\"->300));\n"
      "lead = Vehicle((\"east_0\"->60, , 8));\n"
      "walker = Pedestrian(((150, -9), 90 deg, 0.5), uniform(((150, -9), 90 deg, 0.5)));\n"
      "scenario = CreateScenario{load(\"straight\"); ego; {lead}; {walker}; {}; "
      "Environment(22:00, {fog: 0.9, rain: 0.8});};\n"
      "Trace trace = EXE(scenario);\n"
      "walker_seen = trace[perception][walker];\n"
      "walker_truth = trace[truth][walker];\n"
      "trace |= G (dis(trace[ego], walker_seen) > 0 & vel(trace[ego], walker_seen) > 0 & "
      "spd(trace[ego], walker_seen) > -100 & acc(trace[ego], walker_seen) > 0 & "
      "diff(walker_seen, walker_truth) >= 0);\n");
  ASSERT_TRUE(run.trace) << run.errors;
  const PerceivedActor& walker = run.trace->perceived[1];
  EXPECT_NE(std::count(walker.detected.begin(), walker.detected.end(), 0), 0)
      << "the test needs samples where the walker is not detected";
  const TraceSignals signals(*run.trace, run.parsed.scenario, run.parsed.parameters, *run.map);
  std::vector<const SpecTerm*> leaves;
  std::vector<const Formula*> pending = {&run.parsed.scenario.specs[0].formula};
  while (!pending.empty()) {
    const Formula* formula = pending.back();
    pending.pop_back();
    for (const Formula& operand : formula->operands) pending.push_back(&operand);
    for (const SpecTerm& term : formula->terms) leaves.push_back(&term);
  }
  ASSERT_EQ(leaves.size(), 10u);
  for (const SpecTerm* term : leaves) {
    const std::vector<double> values = term_signal(*term, signals.source()).values;
    ASSERT_EQ(values.size(), run.trace->sample_count()) << term->name;
    for (double value : values) ASSERT_TRUE(std::isfinite(value)) << term->name;
  }
}

}  // namespace
}  // namespace scenfuzz
