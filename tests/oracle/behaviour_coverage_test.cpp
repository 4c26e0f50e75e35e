// Behaviour coverage on hand-made traces over the built-in maps: each family (manoeuvres, road
// features, interactions, weather and light, law sub-violations) with cases that tell its
// features apart.
#include "oracle/behaviour_coverage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "oracle/law_coverage.hpp"
#include "oracle/sub_violations.hpp"
#include "oracle/trace_signals.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"
#include "tests/oracle/hand_traces.hpp"

namespace scenfuzz {
namespace {

using test::along_lanes;
using test::builtin;
using test::kDt;
using test::move;
using test::State;
using test::steady;
using test::stopping_at;

// `straight` with two east-bound lanes: east_0 along y = -5.25, east_1 along y = -1.75.
RoadMap two_lanes() { return build_road_map(generate_builtin_map("straight", {{"lanes", 2}})); }

bool has(const std::vector<std::string>& features, const std::string& name) {
  return std::find(features.begin(), features.end(), name) != features.end();
}

// The features of `family` ("interaction.pedestrian.F."), for messages and exact checks.
std::vector<std::string> starting(const std::vector<std::string>& features,
                                  const std::string& family) {
  std::vector<std::string> out;
  for (const std::string& f : features)
    if (f.rfind(family, 0) == 0) out.push_back(f);
  return out;
}

std::string listed(const std::vector<std::string>& features) {
  std::ostringstream out;
  for (const std::string& f : features) out << f << "\n";
  return out.str();
}

// Coverage in clear daylight, checked to be sorted, unique and within the fixed set.
std::vector<std::string> cover(const Trace& trace, const RoadMap& map) {
  const std::vector<std::string> features = behaviour_coverage(trace, map, Conditions{});
  EXPECT_TRUE(std::is_sorted(features.begin(), features.end()));
  EXPECT_EQ(std::adjacent_find(features.begin(), features.end()), features.end());
  const std::vector<std::string> fixed = behaviour_feature_names();
  for (const std::string& f : features)
    EXPECT_TRUE(std::binary_search(fixed.begin(), fixed.end(), f)) << f;
  return features;
}

// An ego alone for `seconds`, moved by `motion`.
Trace ego_alone(const RoadMap& map, double seconds, const test::Motion& motion) {
  Trace trace = test::two_actor_trace(seconds);
  trace.actors.pop_back();
  move(trace, map, trace.actors[kEgo], motion);
  return trace;
}

// East along `straight` (two lanes: east_0 at y = -5.25, east_1 at -1.75 on its left) at
// `speed`, moving from y0 to y1 between 1 s and 3 s.
test::Motion east_changing_lane(double speed, double y0, double y1) {
  return [=](double t) {
    const double u = std::clamp((t - 1) / 2, 0.0, 1.0);
    const double vy = (t > 1 && t < 3) ? (y1 - y0) / 2 : 0.0;
    return State{10 + speed * t, y0 + (y1 - y0) * u, speed, vy};
  };
}

TEST(BehaviourCoverageTest, ALaneChangeLeftIsLeftAndNotRight) {
  const RoadMap map = two_lanes();
  const auto left = cover(ego_alone(map, 5, east_changing_lane(10, -5.25, -1.75)), map);
  EXPECT_TRUE(has(left, "ego.lane_change_left")) << listed(left);
  EXPECT_FALSE(has(left, "ego.lane_change_right")) << listed(left);
  const auto right = cover(ego_alone(map, 5, east_changing_lane(10, -1.75, -5.25)), map);
  EXPECT_TRUE(has(right, "ego.lane_change_right")) << listed(right);
  EXPECT_FALSE(has(right, "ego.lane_change_left")) << listed(right);
  const auto keep = cover(ego_alone(map, 5, east_changing_lane(10, -5.25, -5.25)), map);
  EXPECT_TRUE(starting(keep, "ego.").empty()) << listed(keep);
}

// Through the crossroads from the west arm onto `lanes`, lights showing `colour` throughout.
Trace through_crossroads(const RoadMap& map, const std::vector<std::string>& lanes,
                         const test::Distance& distance, SignalColour colour, double seconds) {
  Trace trace = ego_alone(map, seconds, along_lanes(map, lanes, 0, distance));
  for (const TrafficLight& light : map.traffic_lights())
    trace.lights.push_back({light.id, std::vector<SignalColour>(trace.sample_count(), colour)});
  return trace;
}

TEST(BehaviourCoverageTest, TurnsThroughASignalisedJunctionAreTheirTurn) {
  const RoadMap map = builtin("crossroads");
  const auto left = cover(through_crossroads(map, {"west_in_1", "west_north_1", "north_out_1"},
                                             steady(8), SignalColour::green, 25),
                          map);
  EXPECT_TRUE(has(left, "ego.turn_left")) << listed(left);
  EXPECT_FALSE(has(left, "ego.turn_right")) << listed(left);
  EXPECT_TRUE(has(left, "road.junction.signalised")) << listed(left);
  EXPECT_TRUE(has(left, "road.light.green")) << listed(left);
  EXPECT_FALSE(has(left, "road.light.red")) << listed(left);
  EXPECT_FALSE(has(left, "road.junction.uncontrolled")) << listed(left);

  const auto right = cover(through_crossroads(map, {"west_in_0", "west_south_0", "south_out_0"},
                                              steady(8), SignalColour::green, 25),
                           map);
  EXPECT_TRUE(has(right, "ego.turn_right")) << listed(right);
  EXPECT_FALSE(has(right, "ego.turn_left")) << listed(right);
}

TEST(BehaviourCoverageTest, StoppingAtTheStopLineOfARedLightIsAStopAtRedAndNotOnGreen) {
  const RoadMap map = builtin("crossroads");
  const Lane& approach = map.lane(*map.find_lane("west_in_0"));
  // The stop line lies 6 m before the junction, at the lane's end less 6 m; the front stops 1 m
  // before it.
  const double stop_centre = approach.length() - 6 - 1 - test::kCarLength / 2;
  const test::Distance stopping = stopping_at(8, 3, stop_centre);
  const auto red =
      cover(through_crossroads(map, {"west_in_0"}, stopping, SignalColour::red, 30), map);
  EXPECT_TRUE(has(red, "ego.stop_at_red_light")) << listed(red);
  EXPECT_TRUE(has(red, "road.light.red")) << listed(red);
  EXPECT_FALSE(has(red, "road.light.green")) << listed(red);
  const auto green =
      cover(through_crossroads(map, {"west_in_0"}, stopping, SignalColour::green, 30), map);
  EXPECT_FALSE(has(green, "ego.stop_at_red_light")) << listed(green);
  EXPECT_TRUE(has(green, "road.light.green")) << listed(green);
}

TEST(BehaviourCoverageTest, StoppingAtAStopSignThenPullingOutIntoTheJunction) {
  const RoadMap map = builtin("t_junction");
  const Lane& approach = map.lane(*map.find_lane("south_in_0"));
  const double stop_centre = approach.length() - 6 - 1 - test::kCarLength / 2;
  const test::Distance stop = stopping_at(8, 3, stop_centre);
  // Stands 3 s after stopping (braking at 3 m/s^2 from 8 m/s takes 8/3 s), then moves off at
  // 1 m/s^2 into a right turn (south to east).
  const double stopped_at = (stop_centre - 8.0 * 8.0 / 6) / 8 + 8.0 / 3;
  const test::Distance stop_and_go = [=](double t) {
    if (t <= stopped_at) return stop(t);
    const double go = std::max(0.0, t - stopped_at - 3);
    return stop(stopped_at) + go * go / 2;
  };
  const std::vector<std::string> lanes = {"south_in_0", "south_east_0", "east_out_0"};
  Trace trace = ego_alone(map, 40, along_lanes(map, lanes, 0, stop_and_go));
  const auto features = cover(trace, map);
  EXPECT_TRUE(has(features, "ego.stop_at_stop_sign")) << listed(features);
  EXPECT_TRUE(has(features, "ego.pulling_out")) << listed(features);
  EXPECT_TRUE(has(features, "road.junction.stop_sign")) << listed(features);
  EXPECT_FALSE(has(features, "road.junction.signalised")) << listed(features);
  EXPECT_FALSE(has(features, "ego.stop_at_red_light")) << listed(features);
}

TEST(BehaviourCoverageTest, RoundaboutAndMergeAreRoadFeatures) {
  const RoadMap merge = builtin("merge");
  const Lane& accel = merge.lane(*merge.find_lane("accel_0"));
  const MapPoint start = accel.centre_line.point_at(0);
  const double h = accel.centre_line.heading_at(0);
  const auto features =
      cover(ego_alone(merge, 3,
                      [&](double t) {
                        return State{start.x + 10 * t * std::cos(h), start.y + 10 * t * std::sin(h),
                                     10 * std::cos(h), 10 * std::sin(h)};
                      }),
            merge);
  EXPECT_TRUE(has(features, "road.merge")) << listed(features);
  EXPECT_FALSE(has(features, "road.roundabout")) << listed(features);

  const RoadMap roundabout = builtin("roundabout");
  const auto ring =
      cover(ego_alone(roundabout, 3, along_lanes(roundabout, {"ring_0"}, 0, test::steady(8))),
            roundabout);
  EXPECT_TRUE(has(ring, "road.roundabout")) << listed(ring);
  EXPECT_FALSE(has(ring, "road.merge")) << listed(ring);
}

// A pedestrian crosses the ego's lane 36 m ahead of where it starts, walking north at 1.5 m/s
// while the ego drives east at 4 m/s: in front (F) its least gap is 13.3 - 2.6 = 10.7 m
// (mid) and the centres close at up to 4.1 m/s (closing_2_5), entering F from the right.
TEST(BehaviourCoverageTest, APedestrianCrossingInFrontIsSeenInItsSectorsAndBands) {
  const RoadMap map = two_lanes();
  Trace trace = test::two_actor_trace(8, TraceActorKind::pedestrian);
  move(trace, map, trace.actors[kEgo], [](double t) { return State{4 * t, -5.25, 4, 0}; });
  move(trace, map, trace.actors[1], [](double t) { return State{36, -12 + 1.5 * t, 0, 1.5}; });
  const auto features = cover(trace, map);
  EXPECT_EQ(starting(features, "interaction.pedestrian.F."),
            std::vector<std::string>{"interaction.pedestrian.F.closing_2_5.mid"})
      << listed(features);
  EXPECT_FALSE(starting(features, "interaction.pedestrian.FSR.").empty()) << listed(features);
  EXPECT_TRUE(starting(features, "interaction.pedestrian.R").empty()) << listed(features);
  EXPECT_TRUE(starting(features, "interaction.car.").empty()) << listed(features);
}

TEST(BehaviourCoverageTest, DrivingIntoAStandingCarIsContactInFront) {
  const RoadMap map = two_lanes();
  Trace trace = test::two_actor_trace(10);
  move(trace, map, trace.actors[kEgo], [](double t) { return State{8 * t, -5.25, 8, 0}; });
  move(trace, map, trace.actors[1], [](double) { return State{40, -5.25, 0, 0}; });
  test::end_at_contact(trace);
  const auto features = cover(trace, map);
  EXPECT_TRUE(has(features, "interaction.car.F.closing_5_10.contact")) << listed(features);
  EXPECT_TRUE(has(features, "ego.following")) << listed(features);
  EXPECT_FALSE(has(features, "ego.overtaking")) << listed(features);
}

// The ego comes up behind a slower car in east_0, moves into east_1 and passes it.
TEST(BehaviourCoverageTest, PassingASlowerCarAheadInTheLaneIsOvertaking) {
  const RoadMap map = two_lanes();
  Trace trace = test::two_actor_trace(6);
  move(trace, map, trace.actors[kEgo], east_changing_lane(15, -5.25, -1.75));
  move(trace, map, trace.actors[1], [](double t) { return State{40 + 8 * t, -5.25, 8, 0}; });
  const auto passing = cover(trace, map);
  EXPECT_TRUE(has(passing, "ego.overtaking")) << listed(passing);
  EXPECT_TRUE(has(passing, "ego.lane_change_left")) << listed(passing);
  EXPECT_FALSE(starting(passing, "interaction.car.RSR.").empty()) << listed(passing);

  // Staying behind it in its lane never passes it.
  move(trace, map, trace.actors[kEgo], [](double t) { return State{10 + 8 * t, -5.25, 8, 0}; });
  const auto behind = cover(trace, map);
  EXPECT_FALSE(has(behind, "ego.overtaking")) << listed(behind);
  EXPECT_TRUE(has(behind, "interaction.car.F.not_closing.far")) << listed(behind);
}

TEST(BehaviourCoverageTest, WeatherAndLightBandsComeFromTheConditions) {
  const RoadMap map = builtin("straight");
  const Trace trace = ego_alone(map, 1, [](double t) { return State{10 + 5 * t, -1.75, 5, 0}; });
  const auto clear = behaviour_coverage(trace, map, Conditions{});
  EXPECT_TRUE(has(clear, "weather.clear"));
  EXPECT_TRUE(has(clear, "light.day"));
  Conditions foggy_night;
  foggy_night.fog = 0.5;
  foggy_night.rain = 0.8;
  foggy_night.darkness = 1;
  const auto night = behaviour_coverage(trace, map, foggy_night);
  EXPECT_TRUE(has(night, "weather.fog.moderate")) << listed(night);
  EXPECT_TRUE(has(night, "weather.rain.heavy")) << listed(night);
  EXPECT_FALSE(has(night, "weather.clear")) << listed(night);
  EXPECT_TRUE(has(night, "light.night")) << listed(night);
  Conditions dusk;
  dusk.darkness = darkness_at(19 * 3600);
  dusk.snow = 0.1;
  const auto evening = behaviour_coverage(trace, map, dusk);
  EXPECT_TRUE(has(evening, "light.twilight")) << listed(evening);
  EXPECT_TRUE(has(evening, "weather.snow.light")) << listed(evening);
}

TEST(BehaviourCoverageTest, BandEdges) {
  EXPECT_EQ(closing_speed_band(-3), "not_closing");
  EXPECT_EQ(closing_speed_band(0.49), "not_closing");
  EXPECT_EQ(closing_speed_band(0.5), "closing_0_2");
  EXPECT_EQ(closing_speed_band(4.99), "closing_2_5");
  EXPECT_EQ(closing_speed_band(25), "closing_20_up");
  EXPECT_EQ(distance_band(0.2, true), "contact");
  EXPECT_EQ(distance_band(0.2, false), "close");
  EXPECT_EQ(distance_band(1, false), "near");
  EXPECT_EQ(distance_band(14.9, false), "mid");
  EXPECT_EQ(distance_band(15, false), "far");
  EXPECT_EQ(weather_band(0), "none");
  EXPECT_EQ(weather_band(0.5), "moderate");
  EXPECT_EQ(light_band(0), "day");
}

TEST(BehaviourCoverageTest, TheFixedSetIsSortedUniqueAndHasEveryFamily) {
  const std::vector<std::string> names = behaviour_feature_names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  // 20 fixed flags, 9 classes x 8 sectors x 6 closing x 5 distance bands, 10 weather, 3 light.
  EXPECT_EQ(names.size(), 20u + 9u * 8u * 6u * 5u + 10u + 3u);
}

// A comparison `speed <op> value` (LawBreaker's km/h) as a formula.
Formula speed_compared(CompareOp op, double kmh) {
  Formula atom;
  atom.kind = FormulaKind::comparison;
  atom.compare = op;
  SpecTerm speed;
  speed.kind = TermKind::signal;
  speed.name = "speed";
  SpecTerm value;
  value.kind = TermKind::number;
  value.value = constant_value(kmh);
  atom.terms = {speed, value};
  return atom;
}

Formula always(Formula inner) {
  Formula formula;
  formula.kind = FormulaKind::always;
  formula.operands.push_back(std::move(inner));
  return formula;
}

TEST(BehaviourCoverageTest, ALawSpecReachesTheSubViolationsItsTraceSatisfies) {
  const RoadMap map = builtin("straight");
  ScenarioTemplate scenario;
  Spec law;
  law.name = "limit";
  // G(speed < 30 | speed > 60): two sub-violations, ~(speed < 30) & ~(speed > 60) eventually.
  Formula either;
  either.kind = FormulaKind::disjunction;
  either.operands = {speed_compared(CompareOp::less, 30), speed_compared(CompareOp::greater, 60)};
  law.formula = always(either);
  scenario.specs.push_back(law);
  const std::optional<std::vector<Formula>> subs = sub_violations(law.formula);
  ASSERT_TRUE(subs);
  EXPECT_EQ(subs->size(), 1u);
  EXPECT_TRUE(is_law_spec(law));
  // 10 m/s is 36 km/h: neither below 30 nor above 60, so the one sub-violation is reached.
  const Trace fast = ego_alone(map, 2, [](double t) { return State{10 + 10 * t, -1.75, 10, 0}; });
  EXPECT_EQ(law_coverage(scenario, {}, fast, map), std::vector<std::string>{"law.limit.1"});
  const Trace slow = ego_alone(map, 2, [](double t) { return State{10 + 5 * t, -1.75, 5, 0}; });
  EXPECT_TRUE(law_coverage(scenario, {}, slow, map).empty());
}

// ((s < 1 | s > 2) & ... k times) -> s < 3: the antecedent has 2^k positive forms, each one
// sub-violation; beyond kMaxSubViolations the spec is not expanded.
TEST(BehaviourCoverageTest, SubViolationsMultiplyUpToTheirLimit) {
  auto law = [](int k) {
    Formula antecedent;
    for (int j = 0; j < k; ++j) {
      Formula either;
      either.kind = FormulaKind::disjunction;
      either.operands = {speed_compared(CompareOp::less, 1), speed_compared(CompareOp::greater, 2)};
      if (j == 0) {
        antecedent = either;
        continue;
      }
      Formula both;
      both.kind = FormulaKind::conjunction;
      both.operands = {antecedent, either};
      antecedent = both;
    }
    Formula implication;
    implication.kind = FormulaKind::implication;
    implication.operands = {antecedent, speed_compared(CompareOp::less, 3)};
    return always(implication);
  };
  ASSERT_TRUE(sub_violations(law(9)));
  EXPECT_EQ(sub_violations(law(9))->size(), 512u);
  EXPECT_FALSE(sub_violations(law(10)));
}

TEST(BehaviourCoverageTest, LawFeatureNumbersArePaddedToSortInOrder) {
  EXPECT_EQ(law_feature_name("laws", 7, 81), "law.laws.07");
  EXPECT_EQ(law_feature_name("laws", 81, 81), "law.laws.81");
  EXPECT_EQ(law_feature_name("s", 1, 1), "law.s.1");
}

// TrashFuzz's 13-law specification has 81 sub-violations (reference section 3.2). LawBreaker's
// input-test.scenest writes it with one law changed: its law50 is
// G((PriorityNPCAhead | crosswalkAhead(2)) -> ~(gear == 2)), whose antecedent has two positive
// forms, where laws.txt has G(~(gear == 2)) with one: 82. The other twelve laws are laws.txt's.
TEST(BehaviourCoverageTest, TheThirteenLawsHaveEightyOneSubViolations) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::filesystem::path file =
      test::shared_dir() / "examples" / "scenest" / "lawbreaker__input-test.scenest";
  const std::optional<SourceFile> source = read_source_file(file.string());
  ASSERT_TRUE(source) << file;
  const avunit::ParseResult parsed = avunit::parse(*source);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(*source, parsed.diagnostics);
  ASSERT_EQ(parsed.scenario.specs.size(), 1u);
  const Spec& spec = parsed.scenario.specs.front();
  EXPECT_TRUE(is_law_spec(spec));
  const std::optional<std::vector<Formula>> subs = sub_violations(spec.formula);
  ASSERT_TRUE(subs);
  EXPECT_EQ(subs->size(), 81u + 1u);
}

// The shared law38 example (TrashFuzz's light rules, san_francisco) simulated at its values: its
// 9 sub-violations are evaluated, and the reached ones are exactly those whose robustness,
// computed without law_coverage's cache of leaves, is >= 0.
TEST(BehaviourCoverageTest, TheSharedLaw38ExampleReachesWhatItsRobustnessSays) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::filesystem::path file =
      test::shared_dir() / "examples" / "scenest" / "trashfuzz__codes_testing__law38.scenest";
  const std::optional<SourceFile> source = read_source_file(file.string());
  ASSERT_TRUE(source) << file;
  const avunit::ParseResult parsed = avunit::parse(*source);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(*source, parsed.diagnostics);
  const std::vector<double> parameters;
  const RoadMap map = load_scenario_map(
      parsed.scenario.map, MapSearchPath{{test::shared_dir() / "maps" / "apollo"}}, parameters);
  Diagnostics diagnostics;
  const std::optional<SimulationSetup> setup =
      prepare_simulation(parsed.scenario, parameters, map, 0, diagnostics);
  ASSERT_TRUE(setup) << format_diagnostics(*source, diagnostics);
  const Trace trace = simulate(map, *setup, {});
  const Spec& law = parsed.scenario.specs.at(0);
  ASSERT_TRUE(is_law_spec(law));
  const std::optional<std::vector<Formula>> subs = sub_violations(law.formula);
  ASSERT_TRUE(subs);
  ASSERT_EQ(subs->size(), 9u);
  const TraceSignals signals(trace, parsed.scenario, parameters, map);
  std::vector<std::string> expected;
  std::string values;
  for (std::size_t k = 0; k < subs->size(); ++k) {
    const double robustness = robustness_signal((*subs)[k], signals.source()).front();
    values += std::to_string(robustness) + " ";
    if (robustness >= 0) expected.push_back(law_feature_name(law.name, k + 1, subs->size()));
  }
  EXPECT_EQ(law_coverage(parsed.scenario, parameters, trace, map), expected) << values;
}

}  // namespace
}  // namespace scenfuzz
