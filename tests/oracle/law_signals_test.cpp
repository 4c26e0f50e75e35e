// scenest's traffic-law signals on hand-built traces over the built-in maps (exact lane geometry
// from corpora/README.md) and on a simulated stop at a red light: LawBreaker's units and "none"
// values, road objects along the lanes the ego takes, vehicles ahead in its lane, and an error for
// each signal the oracle does not compute.
#include "oracle/law_signals.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "oracle/trace_signals.hpp"
#include "physics/map/lane_queries.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::empty_trace;
using test::parse_scenario;
using test::still_actor;

std::string scenario_with(const std::string& environment, const std::string& specs) {
  return "ego = AV((\"east_0\"->50, , 0), (\"east_0\"->300));\n"
         "npc1 = Vehicle((\"east_0\"->70, , 0));\n"
         "npc2 = Vehicle((\"east_0\"->90, , 0));\n"
         "npc3 = Vehicle((\"east_1\"->55, , 0));\n"
         "npc4 = Vehicle((\"east_0\"->30, , 0));\n"
         "walker = Pedestrian((\"east_0\"->60, , 0));\n"
         "scenario = CreateScenario{load(\"straight\"); ego; {npc1, npc2, npc3, npc4}; {walker}; "
         "{}; " +
         environment +
         "};\n"
         "Trace trace = EXE(scenario);\n" +
         specs;
}

// Puts `actor` at arc length s of `lane` at sample i, facing along it.
void put_on_lane(const RoadMap& map, TraceActor& actor, std::size_t i, const std::string& lane,
                 double s) {
  const LaneIndex index = *map.find_lane(lane);
  const MapPose pose = *lane_pose_at(map, index, s);
  actor.x[i] = pose.position.x;
  actor.y[i] = pose.position.y;
  actor.heading[i] = pose.heading;
  actor.lane[i] = static_cast<std::int32_t>(index);
  actor.s[i] = s;
}

// A trace on `map` with an ego 4 m x 2 m and the scenario's other actors parked far away.
Trace law_trace(const RoadMap& map, std::size_t samples) {
  Trace trace = empty_trace(samples);
  trace.actors.push_back(
      still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4, 2, 0, 0));
  for (const char* name : {"npc1", "npc2", "npc3", "npc4"})
    trace.actors.push_back(
        still_actor(trace, name, TraceActorKind::vehicle, BodyShape::box, 4.6, 1.8, 5000, 5000));
  trace.actors.push_back(still_actor(trace, "walker", TraceActorKind::pedestrian,
                                     BodyShape::cylinder, 0.6, 0.6, 5000, 6000));
  test::perceive_perfectly(trace);
  for (const TrafficLight& light : map.traffic_lights())
    trace.lights.push_back({light.id, std::vector<SignalColour>(samples, SignalColour::red)});
  return trace;
}

// The value of the law signal in the first spec of `specs` (a predicate or the left side of a
// comparison) at every sample.
SignalValues law_values(const Trace& trace, const RoadMap& map, const std::string& specs,
                        const std::string& environment = "") {
  const test::ParsedScenario parsed = parse_scenario(scenario_with(environment, specs));
  const TraceSignals signals(trace, parsed.scenario, parsed.parameters, map);
  SignalValues values = signals.leaf(parsed.scenario.specs.at(0).formula.terms.at(0));
  EXPECT_EQ(values.values.size(), trace.sample_count());
  for (double value : values.values) EXPECT_TRUE(std::isfinite(value)) << specs;
  return values;
}

double robustness_at_start(const Trace& trace, const RoadMap& map, const std::string& specs,
                           const std::string& environment = "") {
  const test::ParsedScenario parsed = parse_scenario(scenario_with(environment, specs));
  return test::spec_robustness(trace, parsed, map).at(0);
}

class LawSignalsTest : public ::testing::Test {
 protected:
  RoadMap straight = load_map("straight", map_search_path({}));
  RoadMap crossroads = load_map("crossroads", map_search_path({}));
};

TEST_F(LawSignalsTest, SpeedIsInKilometresPerHourAccInMetresPerSecondSquared) {
  Trace trace = law_trace(straight, 2);
  TraceActor& ego = trace.actors[0];
  ego.speed = {10, 0};
  ego.acceleration = {-3, 0};
  ego.yaw_rate = {0.4, 0};
  const SignalValues speed = law_values(trace, straight, "trace |= speed > 30;\n");
  EXPECT_EQ(speed.values, (std::vector<double>{36, 0}));
  EXPECT_FALSE(speed.discrete);
  EXPECT_DOUBLE_EQ(robustness_at_start(trace, straight, "trace |= speed > 30;\n"), 6);
  // Braking at 3 m/s^2 while turning at 0.4 rad/s at 10 m/s (4 m/s^2 sideways). The AVUnit
  // front end reads a bare `acc` as the function acc(a, b), so the term is built here.
  SpecTerm acc;
  acc.kind = TermKind::signal;
  acc.name = "acc";
  const test::ParsedScenario parsed = parse_scenario(scenario_with("", ""));
  const TraceSignals signals(trace, parsed.scenario, parsed.parameters, straight);
  EXPECT_EQ(signals.leaf(acc).values, (std::vector<double>{5, 0}));
}

TEST_F(LawSignalsTest, TimeRunsOnFromTheScenarioTimeOfDay) {
  const Trace trace = law_trace(straight, 3);
  const std::vector<double> time =
      law_values(trace, straight, "trace |= Time <= 7:30;\n", "Environment(7:00);").values;
  EXPECT_DOUBLE_EQ(time[0], 7 * 3600);
  EXPECT_DOUBLE_EQ(time[2], 7 * 3600 + 0.2);
  EXPECT_DOUBLE_EQ(
      robustness_at_start(trace, straight, "trace |= G (Time <= 7:30);\n", "Environment(7:00);"),
      1800 - 0.2);
  EXPECT_DOUBLE_EQ(law_values(trace, straight, "trace |= Time <= 7:30;\n").values[0], 12 * 3600)
      << "noon without a time of day";
}

TEST_F(LawSignalsTest, WeatherIsTheScenarioIntensityOrZero) {
  const Trace trace = law_trace(straight, 2);
  const std::string environment =
      "Environment(9:00, {rain: range(0.2, 0.6), fog: heavy, wetness: light})";
  auto value = [&](const std::string& name) {
    return law_values(trace, straight, "trace |= " + name + " < 1;\n", environment).values;
  };
  EXPECT_EQ(value("rain"), (std::vector<double>{0.4, 0.4})) << "the middle of its range";
  EXPECT_DOUBLE_EQ(value("fog")[0], 0.8);
  EXPECT_DOUBLE_EQ(value("wetness")[1], 0.1);
  EXPECT_DOUBLE_EQ(value("snow")[0], 0);
  EXPECT_DOUBLE_EQ(law_values(trace, straight, "trace |= rain < 1;\n").values[0], 0);
}

TEST_F(LawSignalsTest, NPCAheadIsTheNearestVehicleAheadInTheEgosLane) {
  Trace trace = law_trace(straight, 3);
  TraceActor& ego = trace.actors[0];
  for (std::size_t i = 0; i < 3; ++i) put_on_lane(straight, ego, i, "east_0", 50);
  put_on_lane(straight, trace.actors[1], 0, "east_0", 70);  // npc1: 15.7 m ahead
  put_on_lane(straight, trace.actors[1], 1, "east_1", 70);  // then beside
  put_on_lane(straight, trace.actors[2], 0, "east_0", 90);  // npc2: 35.7 m ahead
  put_on_lane(straight, trace.actors[2], 1, "east_0", 90);
  put_on_lane(straight, trace.actors[3], 0, "east_1", 55);  // npc3: in the next lane
  put_on_lane(straight, trace.actors[4], 0, "east_0", 30);  // npc4: behind
  put_on_lane(straight, trace.actors[5], 0, "east_0", 60);  // a walker is no vehicle
  trace.actors[1].speed = {4, 6, 0};
  trace.actors[2].speed = {3, 5, 0};
  trace.actors[3].speed = {7, 0, 0};

  const SignalValues ahead = law_values(trace, straight, "trace |= NPCAhead(20);\n");
  EXPECT_NEAR(ahead.values[0], 70 - 2.3 - 50 - 2, 1e-9);
  EXPECT_NEAR(ahead.values[1], 90 - 2.3 - 50 - 2, 1e-9);
  EXPECT_DOUBLE_EQ(ahead.values[2], 1000) << "none";
  EXPECT_EQ(law_values(trace, straight, "trace |= NPCAhead.speed < 1;\n").values,
            (std::vector<double>{4, 5, 0}));
  EXPECT_NEAR(robustness_at_start(trace, straight, "trace |= NPCAhead(20);\n"), 20 - 15.7, 1e-9);

  // npc3's rear corner is 0.7 m ahead of the ego's front and 1.6 m to its left.
  const SignalValues nearest = law_values(trace, straight, "trace |= NearestNPC(5);\n");
  EXPECT_NEAR(nearest.values[0], std::hypot(0.7, 1.6), 1e-9);
  EXPECT_NEAR(nearest.values[1], std::hypot(70 - 2.3 - 52, 1.6), 1e-9) << "npc1 in the next lane";
  EXPECT_DOUBLE_EQ(nearest.values[2], 1000) << "every vehicle far away";
  EXPECT_EQ(law_values(trace, straight, "trace |= NearestNPC.speed < 1;\n").values,
            (std::vector<double>{7, 6, 0}));
}

TEST_F(LawSignalsTest, RoadObjectsAheadAlongTheEgosLanes) {
  // crossroads: on west_in_0 the stop line is at s = 144, the crosswalk covers 145..149, the
  // junction starts at 150; east_out_0's crosswalk covers 1..5.
  Trace trace = law_trace(crossroads, 6);
  TraceActor& ego = trace.actors[0];
  for (std::size_t i = 0; i < 3; ++i) put_on_lane(crossroads, ego, i, "west_in_0", 100);
  put_on_lane(crossroads, ego, 3, "west_in_0", 145);   // over the stop line
  put_on_lane(crossroads, ego, 4, "west_in_0", 148);   // rear past the stop line
  put_on_lane(crossroads, ego, 5, "west_east_0", 10);  // in the junction
  for (TraceLight& light : trace.lights)
    if (light.id == "light_west")
      light.colour = {SignalColour::red,   SignalColour::yellow, SignalColour::green,
                      SignalColour::green, SignalColour::red,    SignalColour::red};

  auto values = [&](const std::string& spec) {
    return law_values(trace, crossroads, "trace |= " + spec + ";\n").values;
  };
  EXPECT_EQ(values("stoplineAhead(2)"), (std::vector<double>{42, 42, 42, 0, 200, 200}));
  EXPECT_EQ(values("crosswalkAhead(2)"), (std::vector<double>{43, 43, 43, 0, 0, 9}));
  EXPECT_EQ(values("junctionAhead(2)"), (std::vector<double>{48, 48, 48, 3, 0, 0}));
  EXPECT_EQ(values("stopSignAhead(2)"), std::vector<double>(6, 200)) << "no stop signs";

  const SignalValues colour =
      law_values(trace, crossroads, "trace |= trafficLightAhead.color == red;\n");
  EXPECT_EQ(colour.values, (std::vector<double>{1, 2, 3, 3, 3, 3}))
      << "red, yellow, green; green (LawBreaker's value) once no light is ahead";
  EXPECT_TRUE(colour.discrete);
  EXPECT_EQ(values("signalAhead == 1"), (std::vector<double>{1, 1, 1, 1, 0, 0}));
  EXPECT_EQ(values("currentLane.number == 2"), (std::vector<double>{2, 2, 2, 2, 2, 0}))
      << "0 in a junction";
  EXPECT_DOUBLE_EQ(
      robustness_at_start(trace, crossroads, "trace |= trafficLightAhead.color == red;\n"), 1);
  EXPECT_DOUBLE_EQ(
      robustness_at_start(trace, crossroads, "trace |= X (trafficLightAhead.color == red);\n"), -1);
  EXPECT_DOUBLE_EQ(robustness_at_start(trace, crossroads, "trace |= stoplineAhead(50);\n"), 8);
}

TEST_F(LawSignalsTest, AStopSignIsAStopLineWithoutALight) {
  const RoadMap junction = load_map("t_junction", map_search_path({}));
  Trace trace = law_trace(junction, 2);
  put_on_lane(junction, trace.actors[0], 0, "south_in_0", 100);
  put_on_lane(junction, trace.actors[0], 1, "west_in_0", 100);
  auto values = [&](const std::string& spec) {
    return law_values(trace, junction, "trace |= " + spec + ";\n").values;
  };
  EXPECT_EQ(values("stopSignAhead(2)"), (std::vector<double>{42, 200}));
  EXPECT_EQ(values("stoplineAhead(2)"), (std::vector<double>{42, 200}))
      << "the main road has neither signs nor lights";
  EXPECT_EQ(values("trafficLightAhead.color == green"), (std::vector<double>{3, 3}));
  EXPECT_EQ(values("signalAhead == 0"), (std::vector<double>{0, 0}));
}

TEST_F(LawSignalsTest, CurrentLaneNumberCountsTheLanesOfTheEgosDirection) {
  const RoadMap wide = load_map("straight?lanes=3", map_search_path({}));
  Trace trace = law_trace(wide, 3);
  put_on_lane(wide, trace.actors[0], 0, "east_0", 10);
  put_on_lane(wide, trace.actors[0], 1, "east_2", 10);
  trace.actors[0].lane[2] = -1;  // off the road
  EXPECT_EQ(law_values(trace, wide, "trace |= currentLane.number == 2;\n").values,
            (std::vector<double>{3, 3, -1}));
  Trace narrow = law_trace(straight, 1);
  put_on_lane(straight, narrow.actors[0], 0, "east_1", 10);
  EXPECT_EQ(law_values(narrow, straight, "trace |= currentLane.number == 2;\n").values,
            (std::vector<double>{2}));
}

TEST_F(LawSignalsTest, TheWayAheadFollowsTheLaneTheEgoTakesNext) {
  // npc1 waits on the right-turn connector west_south_0; the ego goes straight on.
  Trace trace = law_trace(crossroads, 3);
  put_on_lane(crossroads, trace.actors[0], 0, "west_in_0", 140);
  put_on_lane(crossroads, trace.actors[0], 1, "west_in_0", 146);
  put_on_lane(crossroads, trace.actors[0], 2, "west_east_0", 2);
  for (std::size_t i = 0; i < 3; ++i)
    put_on_lane(crossroads, trace.actors[1], i, "west_south_0", 5);
  const std::vector<double> straight_on =
      law_values(trace, crossroads, "trace |= NPCAhead(5);\n").values;
  EXPECT_DOUBLE_EQ(straight_on[0], 1000) << "the car on the branch the ego does not take";
  // Where the run does not tell which way the ego goes, every branch is ahead.
  trace.actors[0].lane[2] = trace.actors[0].lane[1];
  trace.actors[0].s[2] = 147;
  const std::vector<double> undecided =
      law_values(trace, crossroads, "trace |= NPCAhead(5);\n").values;
  EXPECT_LT(undecided[0], 20);
  EXPECT_GT(undecided[0], 0);
}

TEST_F(LawSignalsTest, SignalsTheOracleDoesNotComputeAreErrorsAtTheTerm) {
  const Trace trace = law_trace(straight, 2);
  for (const std::string name :
       {"hornOn", "isLaneChanging", "PriorityNPCAhead", "NPCOpposite(5)", "gear == 2",
        "visibility > 50", "speedLimit.upperLimit > 1", "trafficLightAhead.isBlinking"}) {
    const test::ParsedScenario parsed =
        parse_scenario(scenario_with("", "trace |= " + name + ";\n"));
    const TraceSignals signals(trace, parsed.scenario, parsed.parameters, straight);
    const SpecTerm& term = parsed.scenario.specs.at(0).formula.terms.at(0);
    try {
      signals.leaf(term);
      ADD_FAILURE() << name << " gave a value";
    } catch (const OracleError& error) {
      EXPECT_EQ(std::string(error.what()),
                "the oracle does not compute '" + term.name + "' on simulated traces yet");
      EXPECT_EQ(error.location().line, 9u);
    }
  }
}

TEST_F(LawSignalsTest, AnEgoWaitingAtARedLightSeesItsStopLineAhead) {
  // On `crossroads` east-west traffic has red for the first 30 s; the ego stops before the line.
  SimulationOptions options;
  options.duration = 25;
  const std::string text =
      "ego = AV((\"west_in_0\"->60, , 10), (\"east_out_0\"->60));\n"
      "scenario = CreateScenario{load(\"crossroads\"); ego; {}; {}; {};};\n"
      "Trace trace = EXE(scenario);\n"
      "trace |= stoplineAhead(2);\n"
      "trace |= crosswalkAhead(2);\n"
      "trace |= junctionAhead(2);\n"
      "trace |= trafficLightAhead.color == red;\n"
      "trace |= currentLane.number == 2;\n"
      "trace |= G (trafficLightAhead.color == red & stoplineAhead(1) -> speed < 1);\n";
  test::SimulatedScenario run = test::simulate_scenario(text, options);
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceSignals signals(*run.trace, run.parsed.scenario, run.parsed.parameters, *run.map);
  auto values = [&](std::size_t spec) {
    return signals.leaf(run.parsed.scenario.specs.at(spec).formula.terms.at(0)).values;
  };
  const std::vector<double> stop_line = values(0), crosswalk = values(1), junction = values(2);
  const std::vector<double> colour = values(3), lanes = values(4);
  const std::size_t last = run.trace->sample_count() - 1;
  EXPECT_LT(run.trace->actors[0].speed[last], 0.1);
  EXPECT_GE(stop_line[last], 0);
  EXPECT_LT(stop_line[last], 9) << "close up to the line";
  for (std::size_t i = 0; i <= last; ++i) {
    ASSERT_NEAR(crosswalk[i] - stop_line[i], 1, 1e-9) << "the crosswalk is 1 m past the line";
    ASSERT_NEAR(junction[i] - stop_line[i], 6, 1e-9) << "the junction 6 m past it";
    ASSERT_EQ(colour[i], 1) << "red throughout";
    ASSERT_EQ(lanes[i], 2);
  }
  EXPECT_GT(test::spec_robustness(*run.trace, run.parsed, *run.map).at(5), 0)
      << "it does not run the red light";
}

}  // namespace
}  // namespace scenfuzz
