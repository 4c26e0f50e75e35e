// WMG SDL manoeuvre phases in the simulation: relative initial positions, cut-ins that end
// where the scenario says (or collide when too tight), stops, WHILE conditions, timers,
// pedestrians crossing, END conditions, and the same trace for the same seed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "manoeuvre_fixtures.hpp"

namespace scenfuzz {
namespace {

using namespace test;

constexpr double kCarLength = 4.7;

const TraceActor& actor_named(const Trace& trace, const std::string& name) {
  return trace.actors[*trace.find_actor(name)];
}

TEST(ManoeuvreTest, RelativeInitialPositionsLandBesideTheReference) {
  ScenarioTemplate scenario = three_lane_road(50, 20);
  // Front-side-left: the left neighbour lane, 10 m ahead.
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Left", relative_state("Ego", "FSL", 10, 15), {}));
  // A lane written wins over the sector; lateral offsets are to the left.
  State written = relative_state("Ego", "SL", -5, 15, "east_2");
  written.position.lateral = constant_value(0.5);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Written", written, {}));
  // The ego's lane has no right neighbour: a right sector stays in it.
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Right", relative_state("Ego", "FSR", 20, 15), {}));
  // Relative to an actor placed before it.
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Chained", relative_state("Left", "F", 12, 15), {}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.setup) << run.messages;
  const auto& actors = run.setup->actors;
  ASSERT_EQ(actors.size(), 4u);
  auto expect_at = [](const ScriptedActor& actor, double x, double y) {
    ASSERT_TRUE(actor.manoeuvres);
    EXPECT_NEAR(actor.manoeuvres->initial.x, x, 1e-6) << actor.name;
    EXPECT_NEAR(actor.manoeuvres->initial.y, y, 1e-6) << actor.name;
    EXPECT_NEAR(actor.manoeuvres->initial.heading, 0, 1e-9) << actor.name;
    EXPECT_DOUBLE_EQ(actor.manoeuvres->initial.speed, 15) << actor.name;
  };
  expect_at(actors[0], 60, -5.25);
  expect_at(actors[1], 45, -1.25);
  expect_at(actors[2], 70, -8.75);
  expect_at(actors[3], 72, -5.25);
}

TEST(ManoeuvreTest, RelativePositionErrorsNameTheActorAtItsPlace) {
  ScenarioTemplate unknown = three_lane_road(50, 20);
  unknown.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Cutter", relative_state("Ghost", "F", 10, 15), {}));
  ManoeuvreRun missing = run_manoeuvres(unknown);
  EXPECT_FALSE(missing.setup);
  EXPECT_NE(missing.messages.find("7: Cutter is placed relative to 'Ghost'"), std::string::npos)
      << missing.messages;

  ScenarioTemplate beyond = three_lane_road(50, 20);
  beyond.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Cutter", relative_state("Ego", "FSL", 460, 15), {}));
  ManoeuvreRun off = run_manoeuvres(beyond);
  EXPECT_FALSE(off.setup);
  EXPECT_NE(off.messages.find("7: Cutter's position"), std::string::npos) << off.messages;
  EXPECT_NE(off.messages.find("falls off lane 'east_1'"), std::string::npos) << off.messages;
}

// The ego starts at 20 m/s and speeds up to the limit (22.2 m/s); Cutter, 8 m ahead in the next
// lane, cuts in once the ego does 21 m/s or more.
ScenarioTemplate cut_in(double gap, double speed, double duration, double start_offset = 8,
                        double cutter_speed = 24) {
  ScenarioTemplate scenario = three_lane_road(50, 20);
  ManoeuvrePhase cut = phase("Drive_CutIn", speed, duration, gap, "Ego");
  cut.start_when =
      both(compare(signal_term("speed", {"Ego"}), CompareOp::greater_equal, number_term(21)),
           compare(signal_term("speed", {"Ego"}), CompareOp::less_equal, number_term(30)));
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Cutter",
                                          relative_state("Ego", "FSL", start_offset, cutter_speed),
                                          {cut}));
  return scenario;
}

TEST(ManoeuvreTest, CutInStartsOnItsTriggerAndEndsGapAheadInTheEgosLane) {
  const double gap = 25, duration = 4;
  ManoeuvreRun run = run_manoeuvres(cut_in(gap, 22, duration));
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& ego = trace.actors[0];
  const TraceActor& cutter = actor_named(trace, "Cutter");
  EXPECT_TRUE(trace.collisions.empty());

  // The phase starts at the first sample where the ego does 21 m/s; the cutter moves sideways
  // from the next one.
  std::size_t moved = 0;
  while (moved < cutter.y.size() && std::abs(cutter.y[moved] + 5.25) < 1e-6) ++moved;
  ASSERT_LT(moved, cutter.y.size()) << "the cutter never left its lane";
  ASSERT_GE(moved, 2u) << "the cut-in started before the ego reached 21 m/s";
  EXPECT_GE(ego.speed[moved - 1], 21.0);
  EXPECT_LT(ego.speed[moved - 2], 21.0);

  const double start = trace.time[moved - 1];
  std::size_t end = sample_at(trace, start + duration + 0.1);
  EXPECT_EQ(cutter.lane[end], ego.lane[end]) << "the cutter is in the ego's lane at the end";
  EXPECT_NEAR(cutter.y[end], -8.75, 0.05);
  double gap_at_end = cutter.x[end] - ego.x[end] - kCarLength;
  EXPECT_NEAR(gap_at_end, gap, 2.0);
  EXPECT_NEAR(cutter.speed[end], 22, 1.0);
  // Half-way through, it is between the lanes, heading to the right of the road.
  std::size_t middle = sample_at(trace, start + duration / 2);
  EXPECT_GT(cutter.y[middle], -8.0);
  EXPECT_LT(cutter.y[middle], -6.0);
  EXPECT_LT(cutter.heading[middle], -0.01);
  // The ego's perception saw it throughout.
  const PerceivedActor& seen = trace.perceived[*trace.find_actor("Cutter") - 1];
  EXPECT_EQ(seen.detected[end], 1);
}

TEST(ManoeuvreTest, TooTightACutInAtALowerSpeedCollidesWithTheEgo) {
  ManoeuvreRun run = run_manoeuvres(cut_in(0.5, 12, 1.5, 0, 21));
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  ASSERT_FALSE(trace.collisions.empty());
  EXPECT_EQ(trace.collisions[0].first, kEgo);
  EXPECT_EQ(trace.collisions[0].second, *trace.find_actor("Cutter"));
  EXPECT_EQ(trace.end, EndReason::collision);
}

// A lead car 30 m ahead of the ego in the next lane, at 15 m/s, with one phase.
ScenarioTemplate lead_with(ManoeuvrePhase lead_phase, double duration = 8) {
  ScenarioTemplate scenario = three_lane_road(50, 15, duration);
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Lead", relative_state("Ego", "FSL", 30, 15), {lead_phase}));
  return scenario;
}

TEST(ManoeuvreTest, AStopPhaseBringsTheCarToRestOverItsDuration) {
  ManoeuvreRun run = run_manoeuvres(lead_with(phase("Stop", {}, 3)));
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& lead = actor_named(*run.trace, "Lead");
  EXPECT_NEAR(lead.speed[sample_at(*run.trace, 1.5)], 7.5, 0.5) << "braking evenly";
  EXPECT_LT(lead.speed[sample_at(*run.trace, 3.1)], 0.01);
  EXPECT_EQ(lead.speed.back(), 0);
  EXPECT_NEAR(lead.x.back(), lead.x[sample_at(*run.trace, 3.1)], 0.01) << "and stays";
  EXPECT_NEAR(lead.y.back(), -5.25, 1e-6);
}

TEST(ManoeuvreTest, AWhileConditionEndsThePhaseEarly) {
  ManoeuvrePhase slow = phase("Drive_Away", 5, 10);  // 15 -> 5 m/s over 10 s
  ManoeuvreRun full = run_manoeuvres(lead_with(slow));
  ASSERT_TRUE(full.trace) << full.messages;
  EXPECT_NEAR(actor_named(*full.trace, "Lead").speed.back(), 7, 0.2);

  ScenarioTemplate scenario = lead_with(slow);
  scenario.timers.push_back({"T", constant_value(0), {}});
  scenario.vehicles[0].motion.phases[0].continue_while =
      compare(signal_term("timer", {"T"}), CompareOp::less, number_term(3));
  ManoeuvreRun early = run_manoeuvres(scenario);
  ASSERT_TRUE(early.trace) << early.messages;
  const TraceActor& lead = actor_named(*early.trace, "Lead");
  EXPECT_NEAR(lead.speed[sample_at(*early.trace, 3.0)], 12, 0.2);
  EXPECT_NEAR(lead.speed.back(), lead.speed[sample_at(*early.trace, 3.1)], 1e-9)
      << "after its last phase a car holds its speed";
}

TEST(ManoeuvreTest, ALocalTimerCountsFromItsActorsFirstPhase) {
  // Phase 1 starts at t = 2 (a global timer's condition); its WHILE on a local timer then holds
  // for 1.5 s more, where a global timer would already read past it.
  ManoeuvrePhase slow = phase("Drive_Away", 5, 10);
  slow.start_when = compare(signal_term("timer", {"G"}), CompareOp::greater_equal, number_term(2));
  ScenarioTemplate scenario = lead_with(slow);
  scenario.timers.push_back({"G", constant_value(0), {}});
  scenario.timers.push_back({"L", constant_value(0), {}});
  scenario.vehicles[0].motion.phases[0].continue_while =
      compare(signal_term("timer", {"L", "Lead"}), CompareOp::less, number_term(1.5));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& lead = actor_named(*run.trace, "Lead");
  EXPECT_DOUBLE_EQ(lead.speed[sample_at(*run.trace, 2.0)], 15);
  EXPECT_LT(lead.speed[sample_at(*run.trace, 3.0)], 15 - 0.5) << "slowing down after t = 2";
  EXPECT_NEAR(lead.speed.back(), lead.speed[sample_at(*run.trace, 3.6)], 1e-9)
      << "the phase ended at t = 3.5, when the local timer reached 1.5";
  EXPECT_LT(lead.speed.back(), lead.speed[sample_at(*run.trace, 3.4)] - 0.05) << "and not before";
}

TEST(ManoeuvreTest, ATimerConditionStartsThePhaseOnTime) {
  ManoeuvrePhase stop = phase("Stop", {}, 2);
  stop.start_when = compare(signal_term("timer", {"T"}), CompareOp::greater_equal, number_term(4));
  ScenarioTemplate scenario = lead_with(stop);
  scenario.timers.push_back({"T", constant_value(1.5), {}});  // reads 4 at t = 2.5 s
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& lead = actor_named(*run.trace, "Lead");
  EXPECT_DOUBLE_EQ(lead.speed[sample_at(*run.trace, 2.5)], 15);
  EXPECT_LT(lead.speed[sample_at(*run.trace, 2.55)], 15 - 0.2);
  EXPECT_LT(lead.speed[sample_at(*run.trace, 4.6)], 0.01);
}

TEST(ManoeuvreTest, APedestrianWalkCrossCrossesTheRoad) {
  ScenarioTemplate scenario = three_lane_road(300, 10);
  State kerb;
  kerb.position.kind = PositionKind::coordinate;
  kerb.position.x = constant_value(150);
  kerb.position.y = constant_value(-12);  // on the south pavement
  kerb.speed = constant_value(0);
  scenario.pedestrians.push_back(
      manoeuvring(ActorKind::pedestrian, "Walker", kerb, {phase("Walk_Cross", 1.5, {})}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& walker = actor_named(*run.trace, "Walker");
  EXPECT_EQ(walker.kind, TraceActorKind::pedestrian);
  EXPECT_GT(walker.y.back(), 0.5) << "beyond the road's far edge";
  bool on_a_lane = false;
  for (std::size_t i = 0; i < walker.x.size(); ++i) {
    ASSERT_NEAR(walker.x[i], 150, 0.05) << "straight across";
    on_a_lane = on_a_lane || walker.lane[i] >= 0;
  }
  EXPECT_TRUE(on_a_lane);
  EXPECT_NEAR(walker.speed.back(), 1.5, 1e-6);
  EXPECT_NEAR(walker.heading.back(), std::numbers::pi / 2, 1e-6);
}

TEST(ManoeuvreTest, APedestrianInTheKerbLaneCrossesTowardsTheRestOfTheRoad) {
  // WMG SDL places a pavement's pedestrian in the kerb-side lane.
  ScenarioTemplate scenario = three_lane_road(300, 10);
  State kerb_lane = lane_state("east_0", 150, 0);
  scenario.pedestrians.push_back(
      manoeuvring(ActorKind::pedestrian, "Walker", kerb_lane, {phase("Run_Cross", 3, {})}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& walker = actor_named(*run.trace, "Walker");
  EXPECT_GT(walker.y.back(), 0.5) << "over all three lanes to the far edge";
  EXPECT_NEAR(walker.x.back(), 150, 0.05);
  EXPECT_EQ(walker.lane.back(), -1);
}

TEST(ManoeuvreTest, AWhileConditionEndsThePhaseWhenItBecomesFalse) {
  // The walker starts on the pavement, outside the lane its WHILE names: the phase goes on until
  // it has been in east_0 and left it, then it stops in east_1.
  ScenarioTemplate scenario = three_lane_road(300, 10);
  State kerb;
  kerb.position.kind = PositionKind::coordinate;
  kerb.position.x = constant_value(150);
  kerb.position.y = constant_value(-12);
  kerb.speed = constant_value(0);
  ManoeuvrePhase cross = phase("Walk_Cross", 1.5, {});
  cross.continue_while =
      compare(signal_term("lane", {"Walker"}), CompareOp::equal, word_term("east_0"));
  scenario.pedestrians.push_back(
      manoeuvring(ActorKind::pedestrian, "Walker", kerb, {cross, phase("Stopped", {}, {})}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& walker = actor_named(*run.trace, "Walker");
  RoadMap map = scenario_map(scenario);
  EXPECT_EQ(walker.lane.back(), static_cast<std::int32_t>(*map.find_lane("east_1")));
  EXPECT_EQ(walker.speed.back(), 0);
  EXPECT_LT(walker.y.back(), -7.0 + 1.0) << "stopped just past east_0's edge";
}

TEST(ManoeuvreTest, AnEndConditionEndsTheRunWhereItHolds) {
  SimulationOptions options;
  options.stop_at_collision = false;
  ScenarioTemplate scenario = cut_in(0.5, 12, 1.5, 0, 21);
  ManoeuvreRun on = run_manoeuvres(scenario, options);
  ASSERT_TRUE(on.trace) << on.messages;
  ASSERT_FALSE(on.trace->collisions.empty());
  EXPECT_GT(on.trace->time.back(), on.trace->collisions[0].time + 1) << "the run went on";

  scenario.end_conditions.push_back(holds(signal_term("collision")));
  ManoeuvreRun ended = run_manoeuvres(scenario, options);
  ASSERT_TRUE(ended.trace) << ended.messages;
  ASSERT_FALSE(ended.trace->collisions.empty());
  EXPECT_EQ(ended.trace->end, EndReason::end_condition);
  EXPECT_DOUBLE_EQ(ended.trace->time.back(), ended.trace->collisions[0].time);
  EXPECT_EQ(ended.trace->events.back().kind, TraceEventKind::end_condition);
}

TEST(ManoeuvreTest, AManoeuvreConditionSeesAnotherActorChangeLane) {
  // Mover leaves the middle lane to the left; Watcher, ahead in the kerb lane, stops as soon as
  // it sees Mover changing lane to the left.
  ScenarioTemplate scenario = three_lane_road(20, 10);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Mover",
                                          relative_state("Ego", "FSL", 40, 10),
                                          {phase("LaneChangeLeft_CutOut", 10, 4)}));
  ManoeuvrePhase stop = phase("Stop", {}, 1);
  stop.start_when =
      compare(signal_term("manoeuvre", {"Mover"}), CompareOp::equal, word_term("LaneChangeLeft"));
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Watcher", relative_state("Ego", "F", 80, 10), {stop}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& mover = actor_named(*run.trace, "Mover");
  const TraceActor& watcher = actor_named(*run.trace, "Watcher");
  EXPECT_NEAR(mover.y.back(), -1.75, 1e-3) << "in the left lane";
  std::size_t braking = 0;
  while (braking < watcher.speed.size() && watcher.speed[braking] >= 10) ++braking;
  ASSERT_LT(braking, watcher.speed.size());
  // Mover's sideways speed passed 0.3 m/s in the sample before Watcher began braking.
  double lateral_speed = (mover.y[braking - 1] - mover.y[braking - 2]) / run.trace->dt;
  EXPECT_GT(lateral_speed, 0.25);
  EXPECT_GT(mover.y[braking - 1], -5.25 + 0.01);
  EXPECT_LT(mover.y[braking], -5.25 + 0.5) << "early in the lane change";
}

TEST(ManoeuvreTest, ALaneChangePhaseIndicatesTowardsTheNewLaneUntilItIsOver) {
  ScenarioTemplate scenario = three_lane_road(20, 10);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Mover",
                                          relative_state("Ego", "FSL", 40, 10),
                                          {phase("LaneChangeLeft_CutOut", 10, 4)}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& mover = actor_named(*run.trace, "Mover");
  ASSERT_EQ(mover.signals.size(), run.trace->sample_count());
  bool indicated = false;
  for (std::size_t i = 0; i < mover.y.size(); ++i) {
    EXPECT_FALSE(signal_on(mover.signals, i, vehicle_signal::right_indicator)) << i;
    if (mover.y[i] > -5.0 && mover.y[i] < -2.0) {
      ASSERT_TRUE(signal_on(mover.signals, i, vehicle_signal::left_indicator)) << i;
      indicated = true;
    }
  }
  EXPECT_TRUE(indicated);
  EXPECT_FALSE(signal_on(mover.signals, mover.y.size() - 1, vehicle_signal::left_indicator));
}

TEST(ManoeuvreTest, ConditionsThatCannotBeEvaluatedAreErrors) {
  ScenarioTemplate scenario = lead_with(phase("Stop", {}, 2));
  Formula eventually;
  eventually.kind = FormulaKind::eventually;
  eventually.location = at_line(30);
  eventually.operands.push_back(
      compare(signal_term("speed", {"Ego"}), CompareOp::greater, number_term(3)));
  scenario.vehicles[0].motion.phases[0].start_when = eventually;
  Formula unknown = compare(signal_term("speed", {"Nobody"}), CompareOp::greater, number_term(3));
  unknown.terms[0].operands[0].location = at_line(31);
  scenario.end_conditions.push_back(unknown);
  ManoeuvreRun run = run_manoeuvres(scenario);
  EXPECT_FALSE(run.setup);
  EXPECT_NE(run.messages.find("30: a trigger or end condition holds at one instant"),
            std::string::npos)
      << run.messages;
  EXPECT_NE(run.messages.find("31: the condition names an unknown actor 'Nobody'"),
            std::string::npos)
      << run.messages;

  ScenarioTemplate unknown_manoeuvre = lead_with(phase("Hover_Away", 2, 2));
  ManoeuvreRun unsupported = run_manoeuvres(unknown_manoeuvre);
  EXPECT_FALSE(unsupported.setup);
  EXPECT_NE(unsupported.messages.find("20: Lead's manoeuvre 'Hover_Away' is not simulated"),
            std::string::npos)
      << unsupported.messages;
}

TEST(ManoeuvreTest, AReverseAwayPhaseBacksTheCarAlongItsLaneAtItsSpeed) {
  // From a standstill in east_1 (eastbound), 3 m/s backwards reached evenly over 2 s.
  ScenarioTemplate scenario = three_lane_road(50, 10, 8);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Reverser",
                                          relative_state("Ego", "FSL", 200, 0),
                                          {phase("Reverse_Away", 3, 2)}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& reverser = actor_named(trace, "Reverser");
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_NEAR(reverser.speed[sample_at(trace, 1)], 1.5, 0.05) << "speeding up evenly";
  for (std::size_t i = sample_at(trace, 2.05); i < trace.sample_count(); ++i) {
    ASSERT_NEAR(reverser.speed[i], 3, 0.05) << "the speed is a magnitude, at t = " << trace.time[i];
    ASSERT_EQ(reverser.reversing[i], 1) << trace.time[i];
  }
  const std::size_t from = sample_at(trace, 3), to = sample_at(trace, 8);
  EXPECT_NEAR((reverser.x[to] - reverser.x[from]) / (trace.time[to] - trace.time[from]), -3, 0.01)
      << "westwards, against its heading";
  RoadMap map = scenario_map(scenario);
  for (std::size_t i = 1; i < trace.sample_count(); ++i) {
    ASSERT_LE(reverser.x[i], reverser.x[i - 1]) << "never forwards, at t = " << trace.time[i];
    ASSERT_NEAR(reverser.heading[i], 0, 1e-9) << "still facing east";
    ASSERT_NEAR(reverser.y[i], -5.25, 1e-9) << "in its lane";
    ASSERT_EQ(reverser.lane[i], static_cast<std::int32_t>(*map.find_lane("east_1")));
  }
  EXPECT_LT(reverser.x.back(), reverser.x.front() - 15);
}

TEST(ManoeuvreTest, AReversingCarStopsWhereNoLaneLeadsIntoItsOwn) {
  // 5 m from the start of the road, backing up at 3 m/s: it gets there after about 2.7 s.
  ScenarioTemplate scenario = three_lane_road(50, 10, 5);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Reverser",
                                          relative_state("Ego", "FSL", -45, 0),
                                          {phase("Reverse_Away", 3, 2)}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& reverser = actor_named(*run.trace, "Reverser");
  EXPECT_NEAR(reverser.x.front(), 5, 1e-9);
  const std::size_t after = sample_at(*run.trace, 2.8);
  EXPECT_NEAR(reverser.x[after], 0, 1e-9);
  EXPECT_EQ(reverser.speed[after], 0);
  EXPECT_EQ(reverser.reversing[after], 0);
  EXPECT_NEAR(reverser.x.back(), 0, 1e-9) << "and stays";
}

TEST(ManoeuvreTest, AManoeuvreConditionSeesAnotherActorReverse) {
  // Reverser backs up from t = 2 s; Watcher, ahead in the kerb lane, stops as soon as it sees
  // Reverser reversing.
  ScenarioTemplate scenario = three_lane_road(20, 10);
  scenario.timers.push_back({"T", constant_value(0), {}});
  ManoeuvrePhase back = phase("Reverse_Towards", 2, 1);
  back.start_when = compare(signal_term("timer", {"T"}), CompareOp::greater_equal, number_term(2));
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Reverser", relative_state("Ego", "FSL", 150, 0), {back}));
  ManoeuvrePhase stop = phase("Stop", {}, 1);
  stop.start_when =
      compare(signal_term("manoeuvre", {"Reverser"}), CompareOp::equal, word_term("Reverse"));
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Watcher", relative_state("Ego", "F", 80, 10), {stop}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& reverser = actor_named(trace, "Reverser");
  const TraceActor& watcher = actor_named(trace, "Watcher");
  std::size_t braking = 0;
  while (braking < watcher.speed.size() && watcher.speed[braking] >= 10) ++braking;
  ASSERT_LT(braking, watcher.speed.size()) << "Watcher never saw Reverser reverse";
  // The sample before Watcher began braking is the first where Reverser backed up at 0.1 m/s or
  // more (slower is Stopped).
  EXPECT_GE(trace.time[braking - 1], 2.0);
  EXPECT_LE(trace.time[braking - 1], 2.15);
  EXPECT_GE(reverser.speed[braking - 1], 0.1 - 1e-9);
  EXPECT_EQ(reverser.reversing[braking - 1], 1);
  EXPECT_LT(reverser.speed[braking - 2], 0.1);
}

// Parked stands in east_1; Reverser starts `offset` metres (centre to centre) ahead of it in the
// same lane, at rest.
ScenarioTemplate reversing_near_parked(double offset, std::vector<ManoeuvrePhase> phases) {
  ScenarioTemplate scenario = three_lane_road(20, 10);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Parked",
                                          relative_state("Ego", "FSL", 150, 0),
                                          {phase("Stopped", {}, {})}));
  scenario.vehicles.push_back(manoeuvring(
      ActorKind::vehicle, "Reverser", relative_state("Parked", "F", offset, 0), std::move(phases)));
  return scenario;
}

TEST(ManoeuvreTest, AReversingCarHitsTheStoppedCarBehindIt) {
  // 7.3 m between the bumpers: 2.25 m while reaching 3 m/s over 1.5 s, the rest at 3 m/s.
  ManoeuvreRun run = run_manoeuvres(reversing_near_parked(12, {phase("Reverse_Towards", 3, 1.5)}));
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  ASSERT_EQ(trace.collisions.size(), 1u);
  const Collision& hit = trace.collisions[0];
  EXPECT_EQ(hit.first, *trace.find_actor("Parked"));
  EXPECT_EQ(hit.second, *trace.find_actor("Reverser"));
  EXPECT_EQ(hit.first_side, BodySide::front);
  EXPECT_EQ(hit.second_side, BodySide::rear) << "it backed into it";
  EXPECT_NEAR(hit.time, 1.5 + (7.3 - 2.25) / 3, 0.1);
  EXPECT_EQ(trace.end, EndReason::duration) << "a collision between NPCs does not end the run";
}

TEST(ManoeuvreTest, ReverseTowardsAndAwayEndAtTheirGap) {
  const double length = kCarLength;
  // Towards: from 10.3 m between the bumpers, speeding up to 3 m/s over 6 s, reaches 3 m from
  // Parked's front after 5.4 s, at 2.7 m/s, and brakes over 0.5 s (0.675 m).
  ScenarioTemplate towards = reversing_near_parked(
      15, {phase("Reverse_Towards", 3, 6, 3, "Parked"), phase("Stop", {}, 0.5)});
  ManoeuvreRun closing = run_manoeuvres(towards);
  ASSERT_TRUE(closing.trace) << closing.messages;
  const TraceActor& parked = actor_named(*closing.trace, "Parked");
  const TraceActor& reverser = actor_named(*closing.trace, "Reverser");
  EXPECT_TRUE(closing.trace->collisions.empty());
  double clearance = reverser.x.back() - parked.x.back() - length;
  EXPECT_GT(clearance, 3 - 0.675 - 0.15);
  EXPECT_LT(clearance, 3 - 0.675 + 0.01);
  EXPECT_EQ(reverser.speed.back(), 0);

  // Away: from behind Parked (2.3 m between the bumpers), speeding up to 3 m/s over 4 s, is 6 m
  // away after 3.1 s, at 2.4 m/s, and stops at full braking (0.35 m).
  ScenarioTemplate away = reversing_near_parked(
      -7, {phase("Reverse_Away", 3, 4, 6, "Parked"), phase("Stopped", {}, {})});
  ManoeuvreRun opening = run_manoeuvres(away);
  ASSERT_TRUE(opening.trace) << opening.messages;
  const TraceActor& still = actor_named(*opening.trace, "Parked");
  const TraceActor& leaver = actor_named(*opening.trace, "Reverser");
  clearance = still.x.back() - leaver.x.back() - length;
  EXPECT_GT(clearance, 6 + 0.3);
  EXPECT_LT(clearance, 6 + 0.5);
  EXPECT_EQ(leaver.speed.back(), 0);

  // A gap it is already past ends the phase on its duration: Towards from 2.3 m with a 3 m gap.
  ScenarioTemplate past =
      reversing_near_parked(7, {phase("Reverse_Towards", 1, 1, 3, "Parked"), phase("Stop", {}, 1)});
  ManoeuvreRun backed = run_manoeuvres(past);
  ASSERT_TRUE(backed.trace) << backed.messages;
  const TraceActor& mover = actor_named(*backed.trace, "Reverser");
  EXPECT_NEAR(mover.x.front() - mover.x.back(), 0.5 + 0.5, 0.1)
      << "1 s speeding up to 1 m/s, 1 s braking";
}

TEST(ManoeuvreTest, AReverseCutOutChangesLaneBackwards) {
  // From the middle lane, out to the left lane while backing up at 2 m/s over 3 s. 3.5 m sideways
  // within 6 m of travel is tighter than full lock: the move is drawn over the distance the lock
  // allows (sqrt(5.77 x 3.5 m x 5.5 m), about 10.5 m, 5.3 s at 2 m/s) and finishes after the phase.
  ScenarioTemplate scenario = three_lane_road(20, 10);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Reverser",
                                          relative_state("Ego", "FSL", 150, 0),
                                          {phase("Reverse_CutOut", 2, 3)}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& reverser = actor_named(trace, "Reverser");
  RoadMap map = scenario_map(scenario);
  const std::size_t end = sample_at(trace, 6.0);
  EXPECT_EQ(reverser.lane[end], static_cast<std::int32_t>(*map.find_lane("east_2")));
  EXPECT_NEAR(reverser.y[end], -1.75, 0.01);
  EXPECT_NEAR(reverser.speed[end], 2, 0.05);
  EXPECT_EQ(reverser.reversing[end], 1);
  // Half-way, backing to the left: the rear leads, so the nose points right of the lane.
  const std::size_t middle = sample_at(trace, 2.6);
  EXPECT_GT(reverser.y[middle], -5.0);
  EXPECT_LT(reverser.heading[middle], -0.01);
  EXPECT_LT(reverser.x[end], reverser.x[0]);
}

TEST(ManoeuvreTest, TheSameSeedGivesTheSameTrace) {
  SimulationOptions options;
  options.seed = 7;
  ManoeuvreRun first = run_manoeuvres(cut_in(10, 20, 3), options);
  ManoeuvreRun second = run_manoeuvres(cut_in(10, 20, 3), options);
  ASSERT_TRUE(first.trace && second.trace) << first.messages;
  ASSERT_EQ(first.trace->actors.size(), second.trace->actors.size());
  for (std::size_t k = 0; k < first.trace->actors.size(); ++k) {
    EXPECT_EQ(first.trace->actors[k].x, second.trace->actors[k].x);
    EXPECT_EQ(first.trace->actors[k].y, second.trace->actors[k].y);
    EXPECT_EQ(first.trace->actors[k].speed, second.trace->actors[k].speed);
  }
  EXPECT_EQ(first.trace->perceived[0].x.size(), second.trace->perceived[0].x.size());
}

}  // namespace
}  // namespace scenfuzz

namespace scenfuzz {
namespace {

using namespace test;

// On `crossroads` the ego comes from the east and waits at its red light; the turner comes from
// the west.
ScenarioTemplate crossroads_turn(const std::string& lane, const std::string& manoeuvre) {
  ScenarioTemplate scenario;
  scenario.language = SourceLanguage::wmg_sdl;
  scenario.has_scenario = true;
  scenario.map.name = "crossroads";
  scenario.ego.kind = ActorKind::ego;
  scenario.ego.name = "Ego";
  scenario.ego.initial = lane_state("east_in_0", 0, 10);
  scenario.duration = constant_value(20);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Turner", lane_state(lane, 100, 8),
                                          {phase(manoeuvre, 8, {})}));
  return scenario;
}

TEST(ManoeuvreTest, TurnsTakeTheConnectorOfTheirSideAtTheNextJunction) {
  for (const auto& [lane, manoeuvre, exit, heading] :
       {std::tuple{"west_in_1", "TurnLeft_AtJunction", "north_out_1", 90.0},
        std::tuple{"west_in_0", "TurnRight_AtJunction", "south_out_0", -90.0}}) {
    ScenarioTemplate scenario = crossroads_turn(lane, manoeuvre);
    RoadMap map = scenario_map(scenario);
    ManoeuvreRun run = run_manoeuvres(scenario);
    ASSERT_TRUE(run.trace) << run.messages;
    const TraceActor& turner = actor_named(*run.trace, "Turner");
    EXPECT_EQ(turner.lane.back(), static_cast<std::int32_t>(*map.find_lane(exit))) << manoeuvre;
    EXPECT_NEAR(turner.heading.back() * 180 / std::numbers::pi, heading, 1.0) << manoeuvre;
    EXPECT_TRUE(run.trace->collisions.empty());
    // It indicates its side through the turn, and not once it is done.
    const VehicleSignals side =
        heading > 0 ? vehicle_signal::left_indicator : vehicle_signal::right_indicator;
    bool indicated = false;
    for (std::size_t i = 0; i < turner.signals.size(); ++i)
      indicated = indicated || signal_on(turner.signals, i, side);
    EXPECT_TRUE(indicated) << manoeuvre;
    EXPECT_FALSE(signal_on(turner.signals, turner.signals.size() - 1, side)) << manoeuvre;
  }
}

TEST(ManoeuvreTest, ATurnWithoutAJunctionAheadKeepsTheLaneWithAWarning) {
  ScenarioTemplate scenario = three_lane_road(50, 15);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Turner",
                                          relative_state("Ego", "FSL", 20, 15),
                                          {phase("TurnLeft_AtJunction", 15, {})}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  EXPECT_NE(run.messages.find("has no left-turn connector; Turner keeps its lane"),
            std::string::npos)
      << run.messages;
  for (double y : actor_named(*run.trace, "Turner").y) ASSERT_NEAR(y, -5.25, 1e-9);
}

TEST(ManoeuvreTest, RelativeLocationAndHeadingConditionsReadTheActorsPlaces) {
  // Overtaker passes the ego in the next lane; Watcher stops once Overtaker is front-side-left
  // of the ego and heading the same way.
  ScenarioTemplate scenario = three_lane_road(50, 10);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Overtaker",
                                          relative_state("Ego", "RSL", -20, 20),
                                          {phase("Drive_Away", 20, {})}));
  ManoeuvrePhase stop = phase("Stop", {}, 1);
  stop.start_when = both(compare(signal_term("relative_location", {"Overtaker", "Ego"}),
                                 CompareOp::equal, word_term("FSL")),
                         compare(signal_term("relative_heading", {"Overtaker", "Ego"}),
                                 CompareOp::less, number_term(5)));
  scenario.vehicles.push_back(
      manoeuvring(ActorKind::vehicle, "Watcher", relative_state("Ego", "F", 150, 10), {stop}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& ego = trace.actors[0];
  const TraceActor& overtaker = actor_named(trace, "Overtaker");
  const TraceActor& watcher = actor_named(trace, "Watcher");
  std::size_t braking = 0;
  while (braking < watcher.speed.size() && watcher.speed[braking] >= 10) ++braking;
  ASSERT_LT(braking, watcher.speed.size());
  // The sample that triggered it: Overtaker's rear just cleared the ego's front.
  double ahead = overtaker.x[braking - 1] - ego.x[braking - 1];
  EXPECT_GT(ahead, kCarLength);
  EXPECT_LT(overtaker.x[braking - 2] - ego.x[braking - 2], kCarLength + 1e-9);
}

}  // namespace
}  // namespace scenfuzz

namespace scenfuzz {
namespace {

// A phase that never starts (its timer never reaches 1000 s): the actor drives outside its phases
// throughout.
ManoeuvrePhase never_starting(const std::string& manoeuvre) {
  ManoeuvrePhase later = phase(manoeuvre, {}, 2);
  later.start_when =
      compare(signal_term("timer", {"T"}), CompareOp::greater_equal, number_term(1000));
  return later;
}

TEST(ManoeuvreTest, OutsideItsPhasesACarStopsBehindAStandingOne) {
  ScenarioTemplate scenario = three_lane_road(10, 0, 25);
  scenario.timers.push_back({"T", constant_value(0), {}});
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Standing",
                                          lane_state("east_1", 150, 0), {never_starting("Stop")}));
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Follower",
                                          lane_state("east_1", 40, 12), {never_starting("Stop")}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  EXPECT_TRUE(run.trace->collisions.empty());
  const TraceActor& standing = actor_named(*run.trace, "Standing");
  const TraceActor& follower = actor_named(*run.trace, "Follower");
  EXPECT_EQ(standing.x.back(), standing.x.front()) << "standing, it stays";
  double gap = standing.x.back() - follower.x.back() - (standing.length + follower.length) / 2;
  EXPECT_GT(gap, 0.5);
  EXPECT_LT(gap, 6.0);
  EXPECT_LT(follower.speed.back(), 0.01);
}

TEST(ManoeuvreTest, ACarComesToRestBeforeTheEndOfARoadThatLeadsNowhere) {
  ScenarioTemplate scenario = three_lane_road(10, 0, 20);
  scenario.timers.push_back({"T", constant_value(0), {}});
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Runner",
                                          lane_state("east_1", 380, 15), {never_starting("Stop")}));
  ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& runner = actor_named(*run.trace, "Runner");
  const ActorClass& car = actor_class(ActorCategory::car);
  EXPECT_LT(runner.speed.back(), 0.01);
  EXPECT_LE(runner.x.back(), 500 + 1e-9);
  EXPECT_GT(runner.x.back(), 490) << "it stops at the end, not far before it";
  for (double a : runner.acceleration) EXPECT_GE(a, -car.comfortable_deceleration - 0.5);
}

TEST(ManoeuvreTest, AnEgoWithoutATargetStopsBeforeTheRoadEnds) {
  // WMG egos have no target: the lanes ahead end with the map, 120 m on (the road is 500 m).
  ManoeuvreRun run = run_manoeuvres(three_lane_road(380, 15, 20));
  ASSERT_TRUE(run.trace) << run.messages;
  const TraceActor& ego = run.trace->actors[kEgo];
  EXPECT_LT(ego.speed.back(), 0.01);
  for (double x : ego.x) ASSERT_LE(x + ego.length / 2, 500.0) << "it drove off the road";
  EXPECT_GT(ego.x.back() + ego.length / 2, 490.0) << "and stops near the end, not far before";
}

}  // namespace
}  // namespace scenfuzz
