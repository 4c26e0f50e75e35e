// scenest's traffic-law signals on hand-built traces over the built-in maps (exact lane geometry
// from corpora/README.md) and on a simulated stop at a red light: LawBreaker's units and "none"
// values, road objects along the lanes the ego takes, vehicles ahead in its lane, and an error for
// each signal the oracle does not compute.
#include "oracle/law_signals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "oracle/judge.hpp"
#include "oracle/trace_signals.hpp"
#include "physics/map/lane_queries.hpp"
#include "tests/oracle/trace_fixtures.hpp"
#include "tests/support/shared_dir.hpp"

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

// Puts `actor` at arc length s of `lane` at sample i, `lateral` metres to the left of its centre
// line, facing along it.
void put_on_lane(const RoadMap& map, TraceActor& actor, std::size_t i, const std::string& lane,
                 double s, double lateral = 0) {
  const LaneIndex index = *map.find_lane(lane);
  const MapPose pose = *lane_pose_at(map, index, s, lateral);
  actor.x[i] = pose.position.x;
  actor.y[i] = pose.position.y;
  actor.heading[i] = pose.heading;
  actor.lane[i] = static_cast<std::int32_t>(index);
  actor.s[i] = s;
}

// A trace on `map` with an ego 4 m x 2 m and the scenario's other actors parked far away.
Trace law_trace(const RoadMap& map, std::size_t samples, double dt = 0.1) {
  Trace trace = empty_trace(samples, dt);
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

// The value of the first term of the first spec of a whole scenario file `text` on `trace`.
std::vector<double> first_term_values(const Trace& trace, const RoadMap& map,
                                      const std::string& text) {
  const test::ParsedScenario parsed = parse_scenario(text);
  const TraceSignals signals(trace, parsed.scenario, parsed.parameters, map);
  return signals.leaf(parsed.scenario.specs.at(0).formula.terms.at(0)).values;
}

TEST_F(LawSignalsTest, DirectionIsTheTurnOfTheNextJunctionLaneWithinAHundredMetres) {
  auto direction = [&](const Trace& trace) {
    const SignalValues values = law_values(trace, crossroads, "trace |= direction == left;\n");
    EXPECT_TRUE(values.discrete);
    return values.values;
  };
  // The junction lanes begin at s = 150 of the in lanes; the ego's front is 2 m ahead of it.
  Trace left = law_trace(crossroads, 4);
  put_on_lane(crossroads, left.actors[0], 0, "west_in_1", 47);  // 101 m before the junction
  put_on_lane(crossroads, left.actors[0], 1, "west_in_1", 49);  // 99 m
  put_on_lane(crossroads, left.actors[0], 2, "west_north_1", 5);
  put_on_lane(crossroads, left.actors[0], 3, "north_out_1", 20);
  EXPECT_EQ(direction(left), (std::vector<double>{0, 1, 1, 0}));

  Trace right = law_trace(crossroads, 3);
  put_on_lane(crossroads, right.actors[0], 0, "west_in_0", 100);
  put_on_lane(crossroads, right.actors[0], 1, "west_south_0", 3);
  put_on_lane(crossroads, right.actors[0], 2, "south_out_0", 3);
  EXPECT_EQ(direction(right), (std::vector<double>{2, 2, 0}));

  Trace straight_on = law_trace(crossroads, 3);
  put_on_lane(crossroads, straight_on.actors[0], 0, "west_in_0", 100);
  put_on_lane(crossroads, straight_on.actors[0], 1, "west_east_0", 3);
  put_on_lane(crossroads, straight_on.actors[0], 2, "east_out_0", 3);
  EXPECT_EQ(direction(straight_on), (std::vector<double>{0, 0, 0}));

  // The straight-on and left-turn connectors overlap where they begin: the lane column can
  // show the one and then the other. The junction lane the ego leaves the junction by counts.
  Trace overlapping = law_trace(crossroads, 3);
  put_on_lane(crossroads, overlapping.actors[0], 0, "west_east_1", 2);
  put_on_lane(crossroads, overlapping.actors[0], 1, "west_north_1", 5);
  put_on_lane(crossroads, overlapping.actors[0], 2, "north_out_1", 5);
  EXPECT_EQ(direction(overlapping), (std::vector<double>{1, 1, 0}));
}

TEST_F(LawSignalsTest, InARoundaboutTheDirectionIsTheTurnOfTheLaneItLeavesBy) {
  // Entering from the west and leaving to the north: the entry and the exit turn right, the
  // ring (a junction lane too) goes straight on.
  const RoadMap roundabout = load_map("roundabout", map_search_path({}));
  Trace trace = law_trace(roundabout, 5);
  put_on_lane(roundabout, trace.actors[0], 0, "west_in_0", 50);
  put_on_lane(roundabout, trace.actors[0], 1, "west_entry", 3);
  put_on_lane(roundabout, trace.actors[0], 2, "ring_0", 100);
  put_on_lane(roundabout, trace.actors[0], 3, "north_exit", 3);
  put_on_lane(roundabout, trace.actors[0], 4, "north_out_0", 20);
  EXPECT_EQ(law_values(trace, roundabout, "trace |= direction == right;\n").values,
            (std::vector<double>{2, 2, 2, 2, 0}));
  EXPECT_EQ(law_values(trace, roundabout, "trace |= currentLane.direction == right;\n").values,
            (std::vector<double>{2, 2, 0, 2, 0}));
}

// A map whose junction lanes have no turn types: from `in` (east along y = 0) a quarter circle
// of radius 10 to the left and one to the right, and a straight connector bent by 20 degrees.
RoadMap untyped_junction() {
  MapDescription map;
  map.name = "untyped";
  map.source = "test";
  auto arc = [](double side) {
    std::vector<MapPoint> points;
    for (int degrees = 0; degrees <= 90; degrees += 10) {
      const double angle = degrees * std::numbers::pi / 180;
      points.push_back({10 * std::sin(angle), side * (10 - 10 * std::cos(angle))});
    }
    return points;
  };
  auto lane = [](std::string id, std::vector<MapPoint> centre, std::string junction = "") {
    LaneDescription description;
    description.id = std::move(id);
    description.centre_line = std::move(centre);
    description.junction = std::move(junction);
    return description;
  };
  map.lanes.push_back(lane("in", {{-100, 0}, {0, 0}}));
  map.lanes.push_back(lane("left", arc(1), "box"));
  map.lanes.push_back(lane("right", arc(-1), "box"));
  map.lanes.push_back(
      lane("kinked", {{0, 0}, {5, 0}, {5 + 5 * std::cos(0.35), 5 * std::sin(0.35)}}, "box"));
  map.lanes.push_back(lane("north", {{10, 10}, {10, 100}}));
  map.lanes.push_back(lane("south", {{10, -10}, {10, -100}}));
  map.lanes[0].successors = {"left", "right", "kinked"};
  map.lanes[1].successors = {"north"};
  map.lanes[2].successors = {"south"};
  map.junctions.push_back({"box", {{0, -12}, {12, -12}, {12, 12}, {0, 12}}});
  return build_road_map(std::move(map));
}

TEST_F(LawSignalsTest, WithoutTurnTypesTheDirectionIsHowTheJunctionLaneBends) {
  const RoadMap map = untyped_junction();
  auto direction = [&](const std::string& connector, const std::string& out) {
    Trace trace = law_trace(map, 3);
    put_on_lane(map, trace.actors[0], 0, "in", 50);
    put_on_lane(map, trace.actors[0], 1, connector, 3);
    if (out.empty())
      trace.actors[0].lane[2] = -1;
    else
      put_on_lane(map, trace.actors[0], 2, out, 10);
    return law_values(trace, map, "trace |= direction == left;\n").values;
  };
  EXPECT_EQ(direction("left", "north"), (std::vector<double>{1, 1, 0}));
  EXPECT_EQ(direction("right", "south"), (std::vector<double>{2, 2, 0}));
  EXPECT_EQ(direction("kinked", ""), (std::vector<double>{0, 0, 0})) << "20 degrees is no turn";

  Trace on_in = law_trace(map, 1);
  put_on_lane(map, on_in.actors[0], 0, "in", 50);
  EXPECT_EQ(law_values(on_in, map, "trace |= currentLane.direction == left;\n").values,
            std::vector<double>{6})
      << "forward, left or right";
}

TEST_F(LawSignalsTest, PastTheRunTheDirectionFollowsTheRouteToTheEgosTarget) {
  // The run ends before the junction, where west_in_1 goes straight on or left.
  Trace trace = law_trace(crossroads, 1);
  put_on_lane(crossroads, trace.actors[0], 0, "west_in_1", 100);
  EXPECT_EQ(law_values(trace, crossroads, "trace |= direction == left;\n").values,
            std::vector<double>{0})
      << "without a target (the scenario's is on another map) either way: unknown";
  auto with_target = [&](const std::string& target) {
    return first_term_values(trace, crossroads,
                             "ego = AV((\"west_in_1\"->20, , 0), (\"" + target +
                                 "\"->50));\n"
                                 "scenario = CreateScenario{load(\"crossroads\"); ego; {}; {}; "
                                 "{};};\n"
                                 "Trace trace = EXE(scenario);\n"
                                 "trace |= direction == left;\n");
  };
  EXPECT_EQ(with_target("north_out_1"), std::vector<double>{1});
  EXPECT_EQ(with_target("east_out_1"), std::vector<double>{0});
}

TEST_F(LawSignalsTest, ALaneChangeLastsWhileTheEgoIsOffItsLanesCentreTowardsTheOther) {
  // On `straight` east_1 is the left neighbour of east_0; lateral offsets are to the left.
  Trace trace = law_trace(straight, 9);
  const std::vector<double> offsets = {0, 0.2, 0.8, 1.6, -1.4, -0.6, -0.2, 0, 0};
  for (std::size_t i = 0; i < 4; ++i)
    put_on_lane(straight, trace.actors[0], i, "east_0", 50 + static_cast<double>(i), offsets[i]);
  for (std::size_t i = 4; i < 9; ++i)
    put_on_lane(straight, trace.actors[0], i, "east_1", 50 + static_cast<double>(i), offsets[i]);
  const std::vector<double> changing = {0, 0, 1, 1, 1, 1, 0, 0, 0};
  EXPECT_EQ(law_values(trace, straight, "trace |= direction == left;\n").values, changing)
      << "left (1) while changing";
  const SignalValues flag = law_values(trace, straight, "trace |= isLaneChanging;\n");
  EXPECT_EQ(flag.values, changing);
  EXPECT_TRUE(flag.discrete);

  // The same the other way: east_1 to east_0 is to the right (2).
  Trace back = law_trace(straight, 9);
  for (std::size_t i = 0; i < 4; ++i)
    put_on_lane(straight, back.actors[0], i, "east_1", 50 + static_cast<double>(i), -offsets[i]);
  for (std::size_t i = 4; i < 9; ++i)
    put_on_lane(straight, back.actors[0], i, "east_0", 50 + static_cast<double>(i), -offsets[i]);
  EXPECT_EQ(law_values(back, straight, "trace |= direction == right;\n").values,
            (std::vector<double>{0, 0, 2, 2, 2, 2, 0, 0, 0}));
}

// The ego (4 m) on `straight` at arc length s[i] of lane[i], offset[i] to the left; npc1 (4.6 m)
// parked at east_0 -> 70.
Trace overtaking_trace(const RoadMap& map, const std::vector<std::string>& lanes,
                       const std::vector<double>& s, const std::vector<double>& offsets) {
  Trace trace = law_trace(map, s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    put_on_lane(map, trace.actors[0], i, lanes[i], s[i], offsets[i]);
    put_on_lane(map, trace.actors[1], i, "east_0", 70);
  }
  return trace;
}

TEST_F(LawSignalsTest, OverTakingIsPassingAVehicleByChangingLaneAndBack) {
  // Behind npc1 on east_0, out to east_1 (samples 3-6), past npc1 (beside at 8-12), back to
  // east_0 (15-18): overtaking from the lane change out to the end of the change back.
  const std::vector<std::string> lanes = {"east_0", "east_0", "east_0", "east_0", "east_0",
                                          "east_1", "east_1", "east_1", "east_1", "east_1",
                                          "east_1", "east_1", "east_1", "east_1", "east_1",
                                          "east_1", "east_1", "east_0", "east_0", "east_0"};
  const std::vector<double> s = {50, 52, 54, 56, 58, 60, 62, 64, 66, 68,
                                 70, 72, 74, 76, 78, 80, 82, 84, 86, 88};
  const std::vector<double> offsets = {0, 0, 0, 0.8, 1.6, -1.4, -0.6, 0,   0,   0,
                                       0, 0, 0, 0,   0,   -0.8, -1.6, 1.4, 0.6, 0};
  const Trace trace = overtaking_trace(straight, lanes, s, offsets);
  const SignalValues flag = law_values(trace, straight, "trace |= isOverTaking;\n");
  std::vector<double> expected(20, 0);
  std::fill(expected.begin() + 3, expected.begin() + 19, 1);
  EXPECT_EQ(flag.values, expected);
  EXPECT_TRUE(flag.discrete);
  // A flag is 0 when true: `G ~isOverTaking` is violated.
  EXPECT_LT(robustness_at_start(trace, straight, "trace |= G (~isOverTaking);\n"), 0);
}

TEST_F(LawSignalsTest, PassingAVehicleInTheNextLaneWithoutChangingLaneIsNotOverTaking) {
  // On east_1 all along, past npc1 on east_0: driving faster in its own lane than the traffic in
  // the next is not overtaking (law47 is not broken by it), though it goes from behind npc1,
  // beside it, to ahead.
  const std::vector<double> s = {60, 62, 64, 66, 68, 70, 72, 74, 76, 78};
  const Trace trace = overtaking_trace(straight, std::vector<std::string>(10, "east_1"), s,
                                       std::vector<double>(10, 0));
  EXPECT_EQ(law_values(trace, straight, "trace |= isOverTaking;\n").values,
            std::vector<double>(10, 0));
  EXPECT_GT(robustness_at_start(trace, straight, "trace |= G (~isOverTaking);\n"), 0);
}

TEST_F(LawSignalsTest, PassingASlowCarAfterChangingLaneOutOfItsLaneAndBackIsOverTaking) {
  // npc1 drives east_0 at 1 m a sample, the ego at 3 behind it: out to east_1 (samples 1-4)
  // while npc1 is still ahead, beside it at 4-8, back to east_0 (11-14) once it is behind.
  Trace trace = law_trace(straight, 17);
  const std::vector<double> offsets = {0, 0.8, 1.6,  -1.4, -0.6, 0,   0, 0, 0,
                                       0, 0,   -0.8, -1.6, 1.4,  0.6, 0, 0};
  for (std::size_t i = 0; i < 17; ++i) {
    const double step = static_cast<double>(i);
    const bool out = i >= 3 && i <= 12;
    put_on_lane(straight, trace.actors[0], i, out ? "east_1" : "east_0", 50 + 3 * step, offsets[i]);
    put_on_lane(straight, trace.actors[1], i, "east_0", 62 + step);
  }
  std::vector<double> expected(17, 0);
  std::fill(expected.begin() + 1, expected.begin() + 15, 1);
  EXPECT_EQ(law_values(trace, straight, "trace |= isOverTaking;\n").values, expected);
}

TEST_F(LawSignalsTest, FollowingBeingPassedOrMeetingAVehicleIsNotOverTaking) {
  const std::vector<double> zeros(10, 0);
  // Following npc1 in its lane, never beside it.
  const Trace following = overtaking_trace(straight, std::vector<std::string>(10, "east_0"),
                                           {40, 41, 42, 43, 44, 45, 46, 47, 48, 49}, zeros);
  EXPECT_EQ(law_values(following, straight, "trace |= isOverTaking;\n").values, zeros);
  // Being passed: npc1 goes by on east_1 while the ego stands on east_0.
  Trace passed = law_trace(straight, 10);
  for (std::size_t i = 0; i < 10; ++i) {
    put_on_lane(straight, passed.actors[0], i, "east_0", 70);
    put_on_lane(straight, passed.actors[1], i, "east_1", 60 + 2.0 * static_cast<double>(i));
  }
  EXPECT_EQ(law_values(passed, straight, "trace |= isOverTaking;\n").values, zeros);
  // Meeting a vehicle that comes the other way in the next lane.
  Trace meeting = overtaking_trace(straight, std::vector<std::string>(10, "east_1"),
                                   {60, 62, 64, 66, 68, 70, 72, 74, 76, 78}, zeros);
  for (std::size_t i = 0; i < 10; ++i) meeting.actors[1].heading[i] = std::numbers::pi;
  EXPECT_EQ(law_values(meeting, straight, "trace |= isOverTaking;\n").values, zeros);
  // The run ending before npc1 is behind: still overtaking while beside it, from the lane
  // change out of npc1's lane (samples 1-2).
  const Trace cut = overtaking_trace(straight, {"east_0", "east_0", "east_1", "east_1", "east_1"},
                                     {60, 62, 64, 66, 68}, {0, 1.6, -1.4, 0, 0});
  EXPECT_EQ(law_values(cut, straight, "trace |= isOverTaking;\n").values,
            (std::vector<double>{0, 1, 1, 1, 1}));
}

TEST_F(LawSignalsTest, NoMapMarksNoHonkingZonesOrSpecialLocations) {
  // The built-in maps, like Apollo's HD maps, have neither: honking is allowed, no special
  // location is ever ahead.
  for (const RoadMap* map : {&straight, &crossroads}) {
    Trace trace = law_trace(*map, 3);
    for (std::size_t i = 0; i < 3; ++i) {
      trace.actors[0].x[i] = map->lane(0).centre_line.points().front().x;
      trace.actors[0].y[i] = map->lane(0).centre_line.points().front().y;
    }
    const SignalValues honking = law_values(trace, *map, "trace |= honkingAllowed;\n");
    EXPECT_EQ(honking.values, std::vector<double>(3, 1));
    EXPECT_TRUE(honking.discrete);
    const SignalValues special = law_values(trace, *map, "trace |= specialLocationAhead(5);\n");
    EXPECT_EQ(special.values, std::vector<double>(3, kNoRoadObjectAhead));
    EXPECT_FALSE(special.discrete);
    EXPECT_EQ(law_values(trace, *map, "trace |= specialLocationAhead.type == 0;\n").values,
              std::vector<double>(3, 0));
    // law62 holds; a special location 5 m ahead is 195 m short of being true.
    EXPECT_DOUBLE_EQ(robustness_at_start(trace, *map, "trace |= specialLocationAhead(5);\n"), -195);
  }
}

TEST_F(LawSignalsTest, StreetLightsAreOnBetweenDuskAndDawnOnTownStreets) {
  // crossroads' lanes are limited to 50 km/h (a town street), straight's to 80 (a rural road).
  auto lights = [&](const RoadMap& map, const std::string& lane, const std::string& environment,
                    double dt = 0.1) {
    Trace trace = law_trace(map, 3, dt);
    for (std::size_t i = 0; i < 3; ++i) put_on_lane(map, trace.actors[0], i, lane, 10);
    const SignalValues values = law_values(trace, map, "trace |= streetLightOn;\n", environment);
    EXPECT_TRUE(values.discrete);
    return values.values;
  };
  EXPECT_EQ(lights(crossroads, "west_in_0", "Environment(23:00)"), std::vector<double>(3, 1));
  EXPECT_EQ(lights(crossroads, "west_in_0", "Environment(6:30)"), std::vector<double>(3, 1))
      << "before dawn";
  EXPECT_EQ(lights(crossroads, "west_in_0", ""), std::vector<double>(3, 0)) << "noon";
  EXPECT_EQ(lights(straight, "east_0", "Environment(23:00)"), std::vector<double>(3, 0));
  // Samples a minute apart from 17:59: the lamps come on after 18:00, at dusk.
  EXPECT_EQ(lights(crossroads, "west_in_0", "Environment(17:59)", 60),
            (std::vector<double>{0, 0, 1}));
  // Off the lanes there is no street to light.
  Trace off = law_trace(crossroads, 2);
  EXPECT_EQ(law_values(off, crossroads, "trace |= streetLightOn;\n", "Environment(23:00)").values,
            std::vector<double>(2, 0));
  // law58's first clause asks for high beams at night only where the street is not lit.
  const std::string law58 =
      "trace |= G ((~streetLightOn & (Time >= 20:00 | Time <= 7:00) & ~NPCAhead(10)) -> "
      "highBeamOn);\n";
  Trace dark = law_trace(straight, 2);
  Trace town = law_trace(crossroads, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    put_on_lane(straight, dark.actors[0], i, "east_0", 10);
    put_on_lane(crossroads, town.actors[0], i, "west_in_0", 10);
  }
  EXPECT_LT(robustness_at_start(dark, straight, law58, "Environment(23:00)"), 0);
  EXPECT_GT(robustness_at_start(town, crossroads, law58, "Environment(23:00)"), 0);
}

TEST_F(LawSignalsTest, TurningAroundIsAHeadingReversalWithinEightSecondsOfATurn) {
  // Samples 2 s apart on the left-turn connector; the heading is set by hand.
  Trace trace = law_trace(crossroads, 6, 2);
  for (std::size_t i = 0; i < 6; ++i)
    put_on_lane(crossroads, trace.actors[0], i, "west_north_1", 1 + static_cast<double>(i));
  trace.actors[0].heading = {0, 0.9, 1.6, 2.4, 3.2, 3.2};
  // 3.2 - 0 wraps to -3.08, more than 135 degrees (2.36 rad); 3.2 - 0.9 = 2.3 is less.
  EXPECT_EQ(law_values(trace, crossroads, "trace |= isTurningAround;\n").values,
            (std::vector<double>{1, 0, 0, 0, 0, 0}));
  trace.actors[0].heading = {0, 1.0, 1.2, 1.4, 1.6, 3.2};
  EXPECT_EQ(law_values(trace, crossroads, "trace |= isTurningAround;\n").values,
            (std::vector<double>(6, 0)))
      << "reversed only after 10 s";
  // Without a turn signalled, no turning around (LawBreaker's rule).
  Trace on_road = law_trace(straight, 3, 2);
  for (std::size_t i = 0; i < 3; ++i) put_on_lane(straight, on_road.actors[0], i, "east_0", 100);
  on_road.actors[0].heading = {0, 1.6, 3.2};
  EXPECT_EQ(law_values(on_road, straight, "trace |= isTurningAround;\n").values,
            (std::vector<double>(3, 0)));
}

TEST_F(LawSignalsTest, CurrentLaneDirectionCodesTheTurnsTheLaneAllows) {
  const std::vector<std::string> lanes = {"west_in_0",    "west_in_1",   "west_north_1",
                                          "west_south_0", "west_east_0", "east_out_0"};
  Trace trace = law_trace(crossroads, lanes.size() + 1);
  for (std::size_t i = 0; i < lanes.size(); ++i)
    put_on_lane(crossroads, trace.actors[0], i, lanes[i], 3);
  const SignalValues codes =
      law_values(trace, crossroads, "trace |= currentLane.direction == left;\n");
  // forward-or-right, forward-or-left, left, right, forward, forward; 0 off the lanes.
  EXPECT_EQ(codes.values, (std::vector<double>{5, 4, 1, 2, 0, 0, 0}));
  EXPECT_TRUE(codes.discrete);

  const RoadMap single = load_map("crossroads?lanes=1", map_search_path({}));
  const RoadMap junction = load_map("t_junction", map_search_path({}));
  const RoadMap single_junction = load_map("t_junction?lanes=1", map_search_path({}));
  auto code = [&](const RoadMap& map, const std::string& lane) {
    Trace one = law_trace(map, 1);
    put_on_lane(map, one.actors[0], 0, lane, 3);
    return law_values(one, map, "trace |= currentLane.direction == left;\n").values.at(0);
  };
  EXPECT_EQ(code(single, "west_in_0"), 6) << "any way";
  EXPECT_EQ(code(junction, "south_in_0"), 2) << "right only";
  EXPECT_EQ(code(junction, "south_in_1"), 1) << "left only";
  EXPECT_EQ(code(single_junction, "south_in_0"), 7) << "left or right";
}

TEST_F(LawSignalsTest, PriorityNPCAheadIsAVehicleTooCloseAheadOrCrossingWhileTurning) {
  auto priority = [&](const Trace& trace, const RoadMap& map) {
    const SignalValues values = law_values(trace, map, "trace |= PriorityNPCAhead;\n");
    EXPECT_TRUE(values.discrete);
    return values.values;
  };
  // (a) The vehicle ahead in the lane within 3 m.
  Trace close = law_trace(straight, 2);
  for (std::size_t i = 0; i < 2; ++i) put_on_lane(straight, close.actors[0], i, "east_0", 50);
  put_on_lane(straight, close.actors[1], 0, "east_0", 56);  // 1.7 m ahead
  put_on_lane(straight, close.actors[1], 1, "east_0", 60);  // 5.7 m ahead
  EXPECT_EQ(priority(close, straight), (std::vector<double>{1, 0}));

  // (b) Crossing traffic ahead within 30 m while turning left, from either side: headings
  // +90 and 270 degrees (the latter is -90 once wrapped; LawBreaker's unwrapped difference
  // misses it).
  auto turning = [&](const std::string& connector) {
    Trace trace = law_trace(crossroads, 2);
    put_on_lane(crossroads, trace.actors[0], 0, "west_in_1", 140);
    put_on_lane(crossroads, trace.actors[0], 1, connector, 1);
    trace.actors[0].x[1] = trace.actors[0].x[0];  // still at the stop line: the poses stay
    trace.actors[0].y[1] = trace.actors[0].y[0];
    trace.actors[0].heading[1] = 0;
    return trace;
  };
  Trace left = turning("west_north_1");
  left.actors[1].x = {1.75, 5000};
  left.actors[1].y = {-10, 5000};
  left.actors[1].heading = {std::numbers::pi / 2, 0};
  left.actors[2].x = {5000, -1.75};
  left.actors[2].y = {5000, 14};
  left.actors[2].heading = {0, 3 * std::numbers::pi / 2};
  EXPECT_EQ(priority(left, crossroads), (std::vector<double>{1, 1}));
  Trace straight_on = turning("west_east_1");
  straight_on.actors[1] = left.actors[1];
  straight_on.actors[2] = left.actors[2];
  EXPECT_EQ(priority(straight_on, crossroads), (std::vector<double>{0, 0}))
      << "no turn, no crossing conflict";
  Trace behind = turning("west_north_1");
  behind.actors[1].x = {-30, -30};  // behind the ego's rear bumper
  behind.actors[1].y = {-10, -10};
  behind.actors[1].heading = {std::numbers::pi / 2, std::numbers::pi / 2};
  EXPECT_EQ(priority(behind, crossroads), (std::vector<double>{0, 0}));
}

TEST_F(LawSignalsTest, PriorityNPCAheadIsAFasterCarBehindOnTheSideTheEgoChangesTo) {
  // The ego moves from east_0 to east_1 (to the left) over samples 0 and 1.
  auto changing_left = [&](double npc_y, double npc_speed) {
    Trace trace = law_trace(straight, 3);
    put_on_lane(straight, trace.actors[0], 0, "east_0", 50, 0.8);
    put_on_lane(straight, trace.actors[0], 1, "east_1", 51, -1.4);
    put_on_lane(straight, trace.actors[0], 2, "east_1", 52);
    trace.actors[0].speed = {10, 10, 10};
    for (std::size_t i = 0; i < 3; ++i) {
      trace.actors[1].x[i] = 42 + static_cast<double>(i);
      trace.actors[1].y[i] = npc_y;
      trace.actors[1].heading[i] = 0;
      trace.actors[1].speed[i] = npc_speed;
    }
    return law_values(trace, straight, "trace |= PriorityNPCAhead;\n").values;
  };
  EXPECT_EQ(changing_left(-1.75, 15), (std::vector<double>{1, 1, 0})) << "behind on the left";
  EXPECT_EQ(changing_left(-1.75, 5), (std::vector<double>{0, 0, 0})) << "slower";
  EXPECT_EQ(changing_left(-8.75, 15), (std::vector<double>{0, 0, 0}))
      << "on the right, where LawBreaker's strip named left lies";
}

TEST_F(LawSignalsTest, PriorityPedsAheadIsAPedestrianAheadOrOnTheSideTurnedTo) {
  auto pedestrian = [&](Trace trace, const RoadMap& map, double x, double y) {
    TraceActor& walker = trace.actors[5];
    walker.x.assign(trace.sample_count(), x);
    walker.y.assign(trace.sample_count(), y);
    const SignalValues values = law_values(trace, map, "trace |= PriorityPedsAhead;\n");
    EXPECT_TRUE(values.discrete);
    return values.values.at(0);
  };
  // Going straight on: within 3 m ahead (the ego's front is at x = 52).
  Trace ahead = law_trace(straight, 1);
  put_on_lane(straight, ahead.actors[0], 0, "east_0", 50);
  EXPECT_EQ(pedestrian(ahead, straight, 54, -5.25), 1);
  EXPECT_EQ(pedestrian(ahead, straight, 60, -5.25), 0) << "7.7 m ahead";
  EXPECT_EQ(pedestrian(ahead, straight, 44, -5.25), 0) << "behind";

  // Turning: within 10 m, in the 30 m square ahead on the side of the turn.
  auto turning = [&](const std::string& from, const std::string& connector) {
    Trace trace = law_trace(crossroads, 2);
    put_on_lane(crossroads, trace.actors[0], 0, from, 140);
    put_on_lane(crossroads, trace.actors[0], 1, connector, 1);
    return trace;
  };
  const Trace left = turning("west_in_1", "west_north_1");  // the ego at (-20, -1.75)
  EXPECT_EQ(pedestrian(left, crossroads, -15, 3), 1);
  EXPECT_EQ(pedestrian(left, crossroads, -15, -7), 0) << "on the right";
  const Trace right = turning("west_in_0", "west_south_0");  // the ego at (-20, -5.25)
  EXPECT_EQ(pedestrian(right, crossroads, -15, -10), 1);
  EXPECT_EQ(pedestrian(right, crossroads, -15, 0), 0) << "on the left";
}

TEST_F(LawSignalsTest, NPCOppositeIsTheNearestOncomingVehicleAhead) {
  // The ego on east_1; west_1 and west_0 run the other way beside it.
  Trace trace = law_trace(straight, 3);
  for (std::size_t i = 0; i < 3; ++i) put_on_lane(straight, trace.actors[0], i, "east_1", 50);
  for (std::size_t i = 0; i < 2; ++i) {
    put_on_lane(straight, trace.actors[1], i, "west_1", 420);  // x = 80
    put_on_lane(straight, trace.actors[3], i, "west_1", 470);  // x = 30, behind
    put_on_lane(straight, trace.actors[4], i, "east_0", 70);   // ahead, the same way
  }
  put_on_lane(straight, trace.actors[2], 0, "west_0", 430);  // x = 70, on the far lane
  trace.actors[1].speed = {8, 8, 0};
  trace.actors[2].speed = {6, 0, 0};
  const std::vector<double> distance =
      law_values(trace, straight, "trace |= NPCOpposite(20);\n").values;
  EXPECT_NEAR(distance[0], std::hypot(70 - 2.3 - 52, 4.35 + 0.75), 1e-9);
  EXPECT_NEAR(distance[1], std::hypot(80 - 2.3 - 52, 0.85 + 0.75), 1e-9);
  EXPECT_DOUBLE_EQ(distance[2], 1000) << "none";
  EXPECT_EQ(law_values(trace, straight, "trace |= NPCOpposite.speed < 1;\n").values,
            (std::vector<double>{6, 8, 0}));

  // In a junction the lanes cross: a car coming the other way across the junction, while the
  // ego waits to turn left.
  Trace junction = law_trace(crossroads, 2);
  put_on_lane(crossroads, junction.actors[0], 0, "west_in_1", 140);
  put_on_lane(crossroads, junction.actors[0], 1, "west_north_1", 1);
  put_on_lane(crossroads, junction.actors[1], 0, "east_west_1", 5);  // at (5, 1.75)
  const std::vector<double> across =
      law_values(junction, crossroads, "trace |= NPCOpposite(20);\n").values;
  EXPECT_NEAR(across[0], std::hypot(5 - 2.3 + 18, 0.85 + 0.75), 1e-9);
}

TEST_F(LawSignalsTest, ATrafficJamIsThreeStoppedVehiclesInTheJunctionAhead) {
  Trace trace = law_trace(crossroads, 3);
  for (std::size_t i = 0; i < 3; ++i) {
    put_on_lane(crossroads, trace.actors[0], i, "west_in_0", 100);
    put_on_lane(crossroads, trace.actors[1], i, "south_north_0", 3);
    put_on_lane(crossroads, trace.actors[2], i, "south_north_1", 8);
    put_on_lane(crossroads, trace.actors[3], i, "east_west_0", 12);
  }
  trace.actors[3].speed = {0.5, 2, 0};
  trace.actors[3].lane[2] = -1;  // off the lanes, its centre still in the junction box
  const SignalValues jam = law_values(trace, crossroads, "trace |= isTrafficJam;\n");
  EXPECT_EQ(jam.values, (std::vector<double>{1, 0, 1}));
  EXPECT_TRUE(jam.discrete);
}

TEST_F(LawSignalsTest, SpeedLimitsAreTheScenariosOrTheMapsInKilometresPerHour) {
  Trace trace = law_trace(straight, 3);
  put_on_lane(straight, trace.actors[0], 0, "east_0", 50);
  put_on_lane(straight, trace.actors[0], 1, "east_1", 50);
  trace.actors[0].lane[2] = -1;
  const std::string traffic = "{}; {SpeedLimit(\"east_0\", (5, 20))};";
  // The spec's left side is `speed`: the limit is the right side's term.
  auto limit = [&](const std::string& name, const std::string& environment) {
    const test::ParsedScenario parsed =
        parse_scenario(scenario_with(environment, "trace |= speed <= " + name + ";\n"));
    const TraceSignals signals(trace, parsed.scenario, parsed.parameters, straight);
    return signals.leaf(parsed.scenario.specs.at(0).formula.terms.at(1)).values;
  };
  // The scenario's limit on east_0, the map's on east_1, LawBreaker's placeholders off the lanes.
  const std::vector<double> upper = limit("speedLimit.upperLimit", traffic);
  const std::vector<double> lower = limit("speedLimit.lowerLimit", traffic);
  const std::vector<double> expected_upper = {72, 22.2 * 3.6, 1000}, expected_lower = {18, 0, 0};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(upper[i], expected_upper[i], 1e-9) << i;
    EXPECT_NEAR(lower[i], expected_lower[i], 1e-9) << i;
  }
  EXPECT_NEAR(limit("speedLimit.upperLimit", "")[0], 22.2 * 3.6, 1e-9) << "no SpeedLimit";
}

TEST_F(LawSignalsTest, VisibilityIsThePerceptionRangeForVehiclesInTheWeather) {
  const Trace trace = law_trace(straight, 2);
  auto visibility = [&](const std::string& environment) {
    const SignalValues values =
        law_values(trace, straight, "trace |= visibility <= 50;\n", environment);
    EXPECT_EQ(values.values[0], values.values[1]);
    return values.values[0];
  };
  EXPECT_DOUBLE_EQ(visibility(""), 150) << "clear daylight";
  EXPECT_NEAR(visibility("Environment(12:00, {fog: 0.5})"), 150 * std::pow(0.15, 0.5), 1e-9);
  EXPECT_NEAR(visibility("Environment(12:00, {rain: 0.5, snow: 0.2})"), 150 * 0.85 * 0.9, 1e-9);
  EXPECT_NEAR(visibility("Environment(23:00)"), 150 * 0.8, 1e-9) << "night";
}

TEST_F(LawSignalsTest, GearIsDriveAndBrakeIsTheShareOfFullBraking) {
  Trace trace = law_trace(straight, 4);
  trace.actors[0].acceleration = {-4, 2, -20, 0};  // a car brakes at most at 8 m/s^2
  const SignalValues gear = law_values(trace, straight, "trace |= gear == 2;\n");
  EXPECT_EQ(gear.values, std::vector<double>(4, 1));
  EXPECT_TRUE(gear.discrete);
  const SignalValues brake = law_values(trace, straight, "trace |= brake > 10;\n");
  EXPECT_EQ(brake.values, (std::vector<double>{50, 0, 100, 0}));
  EXPECT_FALSE(brake.discrete);
  // On a road with a fifth of the grip (CH-Scenario's ice), 1.6 m/s^2 is full braking.
  test::ParsedScenario icy = parse_scenario(scenario_with("", "trace |= brake > 10;\n"));
  if (!icy.scenario.environment) icy.scenario.environment.emplace();
  icy.scenario.environment->road_friction = constant_value(0.2);
  trace.actors[0].acceleration = {-0.8, 2, -1.6, -4};
  const TraceSignals signals(trace, icy.scenario, icy.parameters, straight);
  const SignalValues on_ice = signals.leaf(icy.scenario.specs.at(0).formula.terms.at(0));
  EXPECT_EQ(on_ice.values, (std::vector<double>{50, 0, 100, 100}));
}

TEST_F(LawSignalsTest, SignalsTheOracleDoesNotComputeAreErrorsAtTheTerm) {
  const Trace trace = law_trace(straight, 2);
  // They need blinking and arrow lights, which no map or run has.
  for (const std::string name :
       {"trafficLightAhead.isBlinking", "trafficLightAhead.direction.color == green",
        "trafficLightAhead.direction.isBlinking"}) {
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

// law_signal_computed, which check and the search read before any run, says exactly what
// law_signal computes, for every signal of LawBreaker's list.
TEST_F(LawSignalsTest, TheComputedNamesAreTheOnesLawSignalAnswers) {
  const Trace trace = law_trace(straight, 2);
  const test::ParsedScenario parsed = parse_scenario(scenario_with("", ""));
  std::size_t computed = 0;
  for (const char* name : {"speed",
                           "acc",
                           "brake",
                           "gear",
                           "direction",
                           "turnSignal",
                           "currentLane.number",
                           "currentLane.direction",
                           "speedLimit.upperLimit",
                           "speedLimit.lowerLimit",
                           "highBeamOn",
                           "lowBeamOn",
                           "hornOn",
                           "fogLightOn",
                           "warningFlashOn",
                           "engineOn",
                           "manualIntervention",
                           "isLaneChanging",
                           "isOverTaking",
                           "isTurningAround",
                           "honkingAllowed",
                           "streetLightOn",
                           "crosswalkAhead",
                           "junctionAhead",
                           "stopSignAhead",
                           "stoplineAhead",
                           "specialLocationAhead",
                           "trafficLightAhead.isBlinking",
                           "trafficLightAhead.direction.isBlinking",
                           "trafficLightAhead.color",
                           "trafficLightAhead.direction.color",
                           "signalAhead",
                           "specialLocationAhead.type",
                           "PriorityNPCAhead",
                           "PriorityPedsAhead",
                           "isTrafficJam",
                           "NPCAhead",
                           "NPCAhead.speed",
                           "NearestNPC",
                           "NearestNPC.speed",
                           "NPCOpposite",
                           "NPCOpposite.speed",
                           "Time",
                           "rain",
                           "fog",
                           "snow",
                           "wetness",
                           "visibility"}) {
    SpecTerm term;
    term.kind = TermKind::signal;
    term.name = name;
    bool answered = true;
    try {
      law_signal(term, trace, parsed.scenario, parsed.parameters, straight);
    } catch (const OracleError&) {
      answered = false;
    }
    EXPECT_EQ(law_signal_computed(name), answered) << name;
    if (answered) ++computed;
  }
  EXPECT_EQ(computed, 45u);
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

TEST_F(LawSignalsTest, AnEgoTurningLeftSignalsLeftFromAHundredMetresBeforeTheJunction) {
  // It waits at the red light (east-west is red for the first 30 s), then turns left.
  SimulationOptions options;
  options.duration = 45;
  const std::string text =
      "ego = AV((\"west_in_1\"->20, , 10), (\"north_out_1\"->60));\n"
      "scenario = CreateScenario{load(\"crossroads\"); ego; {}; {}; {};};\n"
      "Trace trace = EXE(scenario);\n"
      "trace |= direction == left;\n"
      "trace |= isLaneChanging;\n"
      "trace |= isTurningAround;\n"
      "trace |= currentLane.direction == left;\n";
  test::SimulatedScenario run = test::simulate_scenario(text, options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  const TraceSignals signals(trace, run.parsed.scenario, run.parsed.parameters, *run.map);
  auto values = [&](std::size_t spec) {
    return signals.leaf(run.parsed.scenario.specs.at(spec).formula.terms.at(0)).values;
  };
  const std::vector<double> direction = values(0), changing = values(1), around = values(2);
  const std::vector<double> lane_direction = values(3);
  const TraceActor& ego = trace.actors[0];
  bool turned = false;
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    ASSERT_GE(ego.lane[i], 0);
    const std::string& lane = run.map->lane(static_cast<LaneIndex>(ego.lane[i])).id;
    if (lane == "west_in_1") {
      const double to_junction = 150 - ego.s[i] - ego.length / 2;
      ASSERT_EQ(direction[i], to_junction <= 100 ? 1 : 0) << "at s = " << ego.s[i];
      ASSERT_EQ(lane_direction[i], 4) << "forward or left";
    } else if (lane == "west_north_1") {
      turned = true;
      ASSERT_EQ(direction[i], 1);
      ASSERT_EQ(lane_direction[i], 1);
    } else {
      ASSERT_EQ(lane, "north_out_1");
      ASSERT_EQ(direction[i], 0);
    }
    ASSERT_EQ(changing[i], 0);
    ASSERT_EQ(around[i], 0) << "a quarter turn";
  }
  EXPECT_TRUE(turned);
}

// The shared scenest example law38 (TrashFuzz's green, yellow and red light rules at a junction
// of san_francisco) is judged: every signal it reads is computed.
TEST_F(LawSignalsTest, TheSharedLaw38ExampleIsJudged) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::filesystem::path file =
      test::shared_dir() / "examples" / "scenest" / "trashfuzz__codes_testing__law38.scenest";
  const std::optional<SourceFile> source = read_source_file(file.string());
  ASSERT_TRUE(source) << file;
  avunit::ParseResult parsed = avunit::parse(*source);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(*source, parsed.diagnostics);
  const ParameterSpace space = parameter_space(parsed.scenario);
  const std::vector<double> parameters =
      decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  const RoadMap map = load_scenario_map(
      parsed.scenario.map, MapSearchPath{{test::shared_dir() / "maps" / "apollo"}}, parameters);
  Diagnostics diagnostics;
  const std::optional<SimulationSetup> setup =
      prepare_simulation(parsed.scenario, parameters, map, 0, diagnostics);
  ASSERT_TRUE(setup) << format_diagnostics(*source, diagnostics);
  const Trace trace = simulate(map, *setup, {});
  std::vector<SpecVerdict> verdicts;
  try {
    verdicts = judge_trace(parsed.scenario, parameters, trace, map, *source);
  } catch (const OracleError& error) {
    FAIL() << error.what();
  }
  ASSERT_EQ(verdicts.size(), 1u);
  EXPECT_EQ(verdicts[0].name, "law38");
  EXPECT_TRUE(std::isfinite(verdicts[0].robustness)) << verdicts[0].robustness;
}

}  // namespace
}  // namespace scenfuzz
