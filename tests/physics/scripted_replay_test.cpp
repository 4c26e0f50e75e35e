// Replaying scripts as an accident reconstruction needs them: an ego that drives its manoeuvre
// phases instead of being driven (SimulationSetup::ego_script), scripts that run without looking
// under scripted NPC behaviour (ManoeuvreScript::heedless), and Overtake, out onto the oncoming
// lane of a road with one lane each way and back, where reactive, it follows what is in that lane
// (oncoming traffic) and not what it passes in its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "manoeuvre_fixtures.hpp"
#include "physics/actors/vehicle_signals.hpp"

namespace scenfuzz {
namespace {

using namespace test;

constexpr std::size_t kEgoId = 0;

Formula clock_reaches(double seconds) {
  return compare(signal_term("timer", {"Clock"}), CompareOp::greater_equal, number_term(seconds));
}

// An accident reconstruction on the `straight` map, the ego on `ego_lane` at s, standing: its
// phases (none yet) are a script.
ScenarioTemplate reconstruction(int lanes, bool two_way, const std::string& ego_lane, double ego_s,
                                double ego_speed, double duration) {
  ScenarioTemplate scenario;
  scenario.language = SourceLanguage::accident;
  scenario.has_scenario = true;
  scenario.map.name = "straight";
  scenario.map.parameters = {{"two_way", constant_value(two_way ? 1 : 0), {}},
                             {"lanes", constant_value(lanes), {}}};
  scenario.ego = manoeuvring(ActorKind::ego, "Ego", lane_state(ego_lane, ego_s, ego_speed), {});
  scenario.timers.push_back({"Clock", constant_value(0), {}});
  scenario.duration = constant_value(duration);
  return scenario;
}

// The ego on east_0 of a one-way three-lane road at 6 m/s: up to 10 m/s over 2 s, then on at
// that until t = 9, then a stop over 2 s.
ScenarioTemplate ego_drives_then_stops() {
  ScenarioTemplate scenario = reconstruction(3, false, "east_0", 20, 6, 14);
  ManoeuvrePhase stop = phase("Stop", {}, 2);
  stop.start_when = clock_reaches(9);
  scenario.ego.motion.phases = {phase("Drive", 10, 2), std::move(stop)};
  scenario.npc_behaviour = NpcBehaviour::scripted;
  return scenario;
}

Actor parked(const std::string& lane, double s) {
  return manoeuvring(ActorKind::vehicle, "Parked", lane_state(lane, s, 0),
                     {phase("Stopped", {}, {})});
}

bool shows(const TraceActor& actor, std::size_t sample, VehicleSignals signal) {
  return sample < actor.signals.size() && (actor.signals[sample] & signal) != 0;
}

TEST(ScriptedReplay, OvertakeIsAManoeuvreWord) {
  for (const char* word : {"Overtake", "overtake", "OVER_TAKE", "Overtake_Away"}) {
    const auto choice = motion_primitive_named(word);
    ASSERT_TRUE(choice) << word;
    EXPECT_EQ(choice->primitive, MotionPrimitive::overtake) << word;
    EXPECT_EQ(choice->side, LaneSide::left) << word;
  }
}

TEST(ScriptedReplay, AnEgoWithPhasesFollowsItsScript) {
  ManoeuvreRun run = run_manoeuvres(ego_drives_then_stops());
  ASSERT_TRUE(run.trace) << run.messages;
  ASSERT_TRUE(run.setup->ego_script);
  EXPECT_TRUE(run.setup->ego_script->heedless);
  const Trace& trace = *run.trace;
  const TraceActor& ego = trace.actors[kEgoId];
  EXPECT_NEAR(ego.speed[sample_at(trace, 2.1)], 10, 0.2);
  // Between its phases it keeps its speed: the reference driver would speed up to the limit.
  for (double t = 2.5; t < 9; t += 0.5) EXPECT_NEAR(ego.speed[sample_at(trace, t)], 10, 0.15) << t;
  EXPECT_LE(*std::max_element(ego.speed.begin(), ego.speed.end()), 10.2);
  EXPECT_LT(ego.speed[sample_at(trace, 11.5)], 0.05);
  EXPECT_NEAR(trace.time.back(), 14, 1e-9) << "it ran its time, not to a target";
  for (double y : ego.y) ASSERT_NEAR(y, -8.75, 0.01) << "it keeps its lane";
}

TEST(ScriptedReplay, AScriptedEgoDoesNotBrakeForWhatIsAhead) {
  ScenarioTemplate scenario = ego_drives_then_stops();
  scenario.vehicles.push_back(parked("east_0", 80));
  ManoeuvreRun scripted = run_manoeuvres(scenario);
  ASSERT_TRUE(scripted.trace) << scripted.messages;
  ASSERT_FALSE(scripted.trace->collisions.empty());
  const Collision& hit = scripted.trace->collisions.front();
  EXPECT_EQ(hit.first, kEgoId);
  EXPECT_EQ(hit.second, *scripted.trace->find_actor("Parked"));
  EXPECT_EQ(hit.first_side, BodySide::front);
  EXPECT_LT(hit.time, 9) << "it hit before its stop was due";
  EXPECT_GT(scripted.trace->actors[kEgoId].speed.back(), 9) << "at full speed";

  // WMG SDL's ego keeps its driver whatever phases a sequence gives it: the reference driver
  // stops short of the parked car.
  scenario.language = SourceLanguage::wmg_sdl;
  ManoeuvreRun driven = run_manoeuvres(scenario);
  ASSERT_TRUE(driven.trace) << driven.messages;
  EXPECT_FALSE(driven.setup->ego_script);
  EXPECT_TRUE(driven.trace->collisions.empty());
}

// A truck on east_0 at 15 m/s, 60 m behind a car standing in its lane; the ego out of the way on
// east_2. Its phase keeps 15 m/s for `phase_time` seconds; after that it drives on.
ScenarioTemplate truck_behind_parked_car(NpcBehaviour behaviour, double phase_time) {
  ScenarioTemplate scenario = reconstruction(3, false, "east_2", 10, 0, 12);
  scenario.ego.motion = {};
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Truck",
                                          lane_state("east_0", 100, 15),
                                          {phase("Drive", 15, phase_time)}));
  scenario.vehicles.push_back(parked("east_0", 160));
  scenario.npc_behaviour = behaviour;
  return scenario;
}

class HeedlessScript : public testing::TestWithParam<double> {};

TEST_P(HeedlessScript, ScriptedBehaviourRearEndsWhatReactiveBrakesFor) {
  ManoeuvreRun scripted =
      run_manoeuvres(truck_behind_parked_car(NpcBehaviour::scripted, GetParam()));
  ASSERT_TRUE(scripted.trace) << scripted.messages;
  EXPECT_FALSE(scripted.setup->ego_script);
  EXPECT_TRUE(scripted.setup->actors[0].manoeuvres->heedless);
  const Trace& trace = *scripted.trace;
  ASSERT_EQ(trace.collisions.size(), 1u);
  const Collision& hit = trace.collisions.front();
  EXPECT_EQ(hit.first, *trace.find_actor("Truck"));
  EXPECT_EQ(hit.second, *trace.find_actor("Parked"));
  EXPECT_EQ(hit.first_side, BodySide::front);
  EXPECT_EQ(hit.second_side, BodySide::rear);
  const std::size_t at = sample_at(trace, hit.time);
  EXPECT_GT(trace.actors[*trace.find_actor("Truck")].speed[at], 14) << "without braking";

  ManoeuvreRun reactive =
      run_manoeuvres(truck_behind_parked_car(NpcBehaviour::reactive, GetParam()));
  ASSERT_TRUE(reactive.trace) << reactive.messages;
  EXPECT_FALSE(reactive.setup->actors[0].manoeuvres->heedless);
  EXPECT_TRUE(reactive.trace->collisions.empty());
  EXPECT_LT(reactive.trace->actors[*reactive.trace->find_actor("Truck")].speed.back(), 0.1);
}

// In its phase (held back there when reactive), and after it (cruising reactively).
INSTANTIATE_TEST_SUITE_P(InAndAfterThePhase, HeedlessScript, testing::Values(10.0, 0.5));

// On `straight` with `lanes` each way, the ego standing at the start of east_0 and "Overtaker"
// 40 m ahead of it on `lane` at 15 m/s: Overtake to 18 m/s over 3 s, and from t = 8 a
// LaneChangeRight over 3 s.
ManoeuvreRun overtake_on(int lanes, const std::string& lane = "east_0") {
  ScenarioTemplate scenario = reconstruction(lanes, true, "east_0", 5, 0, 13);
  scenario.ego.motion.phases = {phase("Stopped", {}, {})};
  ManoeuvrePhase back = phase("LaneChangeRight", {}, 3);
  back.start_when = clock_reaches(8);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Overtaker", lane_state(lane, 45, 15),
                                          {phase("Overtake", 18, 3), std::move(back)}));
  return run_manoeuvres(scenario);
}

TEST(ScriptedReplay, OvertakeOnATwoLaneRoadUsesTheOncomingLaneAndComesBack) {
  ManoeuvreRun run = overtake_on(1);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& car = trace.actors[*trace.find_actor("Overtaker")];
  EXPECT_NEAR(car.y[0], -1.75, 0.01);
  EXPECT_TRUE(shows(car, sample_at(trace, 1.5), vehicle_signal::left_indicator));
  for (double t = 4; t < 8; t += 0.25) {
    const std::size_t i = sample_at(trace, t);
    EXPECT_NEAR(car.y[i], 1.75, 0.05) << "on the oncoming lane at t = " << t;
    EXPECT_NEAR(car.heading[i], 0, 0.01) << "facing its own way at t = " << t;
    EXPECT_NEAR(car.speed[i], 18, 0.2) << t;
  }
  EXPECT_TRUE(shows(car, sample_at(trace, 9.5), vehicle_signal::right_indicator));
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    ASSERT_LT(std::abs(car.heading[i]), 0.2) << "at t = " << trace.time[i];
    if (i > 0) {
      ASSERT_GT(car.x[i], car.x[i - 1]) << "driving east at t = " << trace.time[i];
    }
  }
  const std::size_t back = sample_at(trace, 12);
  EXPECT_NEAR(car.y[back], -1.75, 0.05) << "back in its own lane";
  EXPECT_NEAR(car.y.back(), -1.75, 0.01);
  EXPECT_NEAR(car.heading.back(), 0, 0.01);
  EXPECT_TRUE(trace.collisions.empty());
}

TEST(ScriptedReplay, OvertakeWithALaneToTheLeftTakesIt) {
  ManoeuvreRun run = overtake_on(2);
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const RoadMap map = scenario_map(reconstruction(2, true, "east_0", 5, 0, 13));
  const TraceActor& car = trace.actors[*trace.find_actor("Overtaker")];
  EXPECT_NEAR(car.y[0], -5.25, 0.01);
  EXPECT_EQ(car.lane[0], static_cast<std::int32_t>(*map.find_lane("east_0")));
  const std::size_t out = sample_at(trace, 6);
  EXPECT_NEAR(car.y[out], -1.75, 0.05);
  EXPECT_EQ(car.lane[out], static_cast<std::int32_t>(*map.find_lane("east_1")));
  EXPECT_NEAR(car.heading[out], 0, 0.01);
  EXPECT_TRUE(shows(car, sample_at(trace, 1.5), vehicle_signal::left_indicator));
  // And LaneChangeRight back to east_0, a neighbour like any other.
  EXPECT_NEAR(car.y.back(), -5.25, 0.01);
  EXPECT_EQ(car.lane.back(), static_cast<std::int32_t>(*map.find_lane("east_0")));
}

TEST(ScriptedReplay, BackFromTheOncomingLaneIsIntoItsOwnLane) {
  // From the inner lane of two each way: out onto west_1, and LaneChangeRight ends in east_1
  // again, not in east_0, the right neighbour of the lane whose frame it kept.
  ManoeuvreRun run = overtake_on(2, "east_1");
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& car = trace.actors[*trace.find_actor("Overtaker")];
  EXPECT_NEAR(car.y[0], -1.75, 0.01);
  EXPECT_NEAR(car.y[sample_at(trace, 6)], 1.75, 0.05);
  EXPECT_NEAR(car.y.back(), -1.75, 0.01);
  EXPECT_NEAR(car.heading.back(), 0, 0.01);
}

// On `straight` with a lane each way, reactive: "Overtaker" at 15 m/s pulls out (to 18 m/s over
// 3 s) past "Slow", 50 m ahead of it at 5 m/s in its lane (beside it from t = 4), and from
// t = 8 comes back.
ScenarioTemplate overtake_past_slow_car() {
  ScenarioTemplate scenario = reconstruction(1, true, "east_0", 5, 0, 13);
  scenario.ego.motion.phases = {phase("Stopped", {}, {})};
  ManoeuvrePhase back = phase("LaneChangeRight", {}, 3);
  back.start_when = clock_reaches(8);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Overtaker",
                                          lane_state("east_0", 45, 15),
                                          {phase("Overtake", 18, 3), std::move(back)}));
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Slow", lane_state("east_0", 95, 5),
                                          {phase("Drive", 5, 13)}));
  scenario.npc_behaviour = NpcBehaviour::reactive;
  return scenario;
}

TEST(ScriptedReplay, OutOnTheOncomingLaneWhatItPassesDoesNotHoldItBack) {
  ManoeuvreRun run = run_manoeuvres(overtake_past_slow_car());
  ASSERT_TRUE(run.trace) << run.messages;
  const Trace& trace = *run.trace;
  const TraceActor& car = trace.actors[*trace.find_actor("Overtaker")];
  const TraceActor& slow = trace.actors[*trace.find_actor("Slow")];
  EXPECT_FALSE(run.setup->actors[0].manoeuvres->heedless);
  for (double t = 4; t < 8; t += 0.25) {
    const std::size_t i = sample_at(trace, t);
    EXPECT_NEAR(car.y[i], 1.75, 0.05) << "on the oncoming lane at t = " << t;
    EXPECT_GT(car.speed[i], 17.5) << "not held back by Slow at t = " << t;
  }
  EXPECT_NEAR(car.y.back(), -1.75, 0.01) << "back in its own lane";
  EXPECT_GT(car.x.back() - slow.x.back(), 20) << "ahead of Slow";
  EXPECT_TRUE(trace.collisions.empty());
}

// As overtake_on(1), `behaviour` NPCs, but nothing brings it back: out on the oncoming lane,
// "Oncoming" stands in it at x = 150 (west_0 runs from x = 500 to 0). With `then_drive`, a Drive
// phase at 18 m/s follows the Overtake for 10 s; without, it drives on outside its phases.
ScenarioTemplate oncoming_car_in_the_way(NpcBehaviour behaviour, bool then_drive) {
  ScenarioTemplate scenario = reconstruction(1, true, "east_0", 5, 0, 13);
  scenario.ego.motion.phases = {phase("Stopped", {}, {})};
  std::vector<ManoeuvrePhase> phases = {phase("Overtake", 18, 3)};
  if (then_drive) phases.push_back(phase("Drive", 18, 10));
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Overtaker",
                                          lane_state("east_0", 45, 15), std::move(phases)));
  scenario.vehicles.push_back(manoeuvring(
      ActorKind::vehicle, "Oncoming", lane_state("west_0", 350, 0), {phase("Stopped", {}, {})}));
  scenario.npc_behaviour = behaviour;
  return scenario;
}

class OncomingOnThePassingLane : public testing::TestWithParam<bool> {};

TEST_P(OncomingOnThePassingLane, ReactiveStopsForItScriptedRunsIntoIt) {
  ManoeuvreRun reactive =
      run_manoeuvres(oncoming_car_in_the_way(NpcBehaviour::reactive, GetParam()));
  ASSERT_TRUE(reactive.trace) << reactive.messages;
  const TraceActor& car = reactive.trace->actors[*reactive.trace->find_actor("Overtaker")];
  EXPECT_NEAR(car.y.back(), 1.75, 0.05) << "still out on the oncoming lane";
  EXPECT_LT(car.speed.back(), 0.1) << "stopped in front of Oncoming";
  EXPECT_TRUE(reactive.trace->collisions.empty());

  ManoeuvreRun scripted =
      run_manoeuvres(oncoming_car_in_the_way(NpcBehaviour::scripted, GetParam()));
  ASSERT_TRUE(scripted.trace) << scripted.messages;
  const Trace& trace = *scripted.trace;
  ASSERT_FALSE(trace.collisions.empty()) << "heedless, it sees nothing";
  EXPECT_EQ(trace.collisions.front().first, *trace.find_actor("Overtaker"));
  EXPECT_EQ(trace.collisions.front().second, *trace.find_actor("Oncoming"));
}

// In a phase (phase_leader_limit) and after it (cruising).
INSTANTIATE_TEST_SUITE_P(InAndAfterThePhase, OncomingOnThePassingLane, testing::Bool());

}  // namespace
}  // namespace scenfuzz
