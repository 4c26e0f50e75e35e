// Scenario values no vehicle or map could have (speeds of 1e300 m/s, coordinates beyond the
// Earth, a day-long duration, an ego whose start and target are both off the map) are errors at
// the value's place in the file, never exceptions from deep in the simulation; an ego placed far
// from every lane is a warning at its position.
#include <gtest/gtest.h>

#include <stdexcept>

#include "physics/simulation/simulation_limits.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::simulate_text;

std::string on_straight(const std::string& definitions, const std::string& npcs = "",
                        const std::string& pedestrians = "") {
  return definitions + "scenario = CreateScenario{load(\"straight\");\nego;\n{" + npcs + "};\n{" +
         pedestrians + "};\n{};\n};\n";
}

const std::string kEgo = "ego = AV((\"east_0\"->10, , 5), (\"east_0\"->300));\n";

// Expects the run to stop at an error at `line` whose text holds `words`.
void expect_error(const test::SimulatedRun& run, int line, const std::string& words) {
  EXPECT_FALSE(run.trace) << "the scenario was simulated";
  EXPECT_NE(run.errors.find("inline.avu:" + std::to_string(line) + ":"), std::string::npos)
      << run.errors;
  EXPECT_NE(run.errors.find("error"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find(words), std::string::npos) << run.errors;
}

TEST(ScenarioValidation, AnNpcSpeedBeyondAnyVehicleIsAnErrorAtTheSpeed) {
  auto run = simulate_text(
      on_straight(kEgo + "npc = Vehicle((\"east_0\"->60, , range(1e300, 1e301)));\n", "npc"));
  expect_error(run, 2, "200 m/s");
}

TEST(ScenarioValidation, AnEgoSpeedBeyondAnyVehicleIsAnErrorAtTheSpeed) {
  auto run = simulate_text(
      on_straight("ego = AV((\"east_0\"->10, , range(1e300, 1e301)), (\"east_0\"->300));\n"));
  expect_error(run, 1, "200 m/s");
}

TEST(ScenarioValidation, AWaypointSpeedBeyondAnyVehicleIsAnError) {
  auto run =
      simulate_text(on_straight(kEgo + "fast = (\"east_0\"->120, , 450);\n"
                                       "npc = Vehicle((\"east_0\"->60, , 5), Waypoint(fast), "
                                       "(\"east_0\"->200));\n",
                                "npc"));
  expect_error(run, 2, "200 m/s");
}

TEST(ScenarioValidation, APedestrianFasterThanAnyRunnerIsAnError) {
  auto run = simulate_text(on_straight(
      kEgo + "ped = Pedestrian(((100, -9), 90 deg, 35), , ((100, 9), , 0), (1.7, red));\n", "",
      "ped"));
  expect_error(run, 2, "20 m/s");
}

TEST(ScenarioValidation, AnAbsurdCoordinateIsAnErrorAtThePosition) {
  auto run =
      simulate_text(on_straight(kEgo + "npc = Vehicle(((range(1e300, 1e301), 0), , 5));\n", "npc"));
  expect_error(run, 2, "beyond any map");
}

TEST(ScenarioValidation, AnEgoWhoseStartAndTargetAreBothOffTheMapIsAnError) {
  auto run = simulate_text(on_straight("ego = AV(((100000, 100000), , 5), ((100100, 100000)));\n"));
  expect_error(run, 1, "route to its target has no length");
  EXPECT_NE(run.errors.find("(100000, 100000)"), std::string::npos) << "where: " << run.errors;
  EXPECT_NE(run.errors.find("(100100, 100000)"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("both off the map"), std::string::npos) << run.errors;
}

TEST(ScenarioValidation, AHugeScenarioDurationIsAnErrorAtTheDuration) {
  const SourceFile file("inline.avu", on_straight(kEgo));
  avunit::ParseResult parsed = avunit::parse(file);
  ASSERT_TRUE(parsed.ok());
  SourceLocation where;
  where.line = 2;
  where.column = 1;
  parsed.scenario.duration = constant_value(1e9, where);
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), {});
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, {}, map, 0, diagnostics);
  const std::string errors = format_diagnostics(file, diagnostics);
  EXPECT_FALSE(setup);
  EXPECT_NE(errors.find("inline.avu:2:1"), std::string::npos) << errors;
  EXPECT_NE(errors.find("duration"), std::string::npos) << errors;
}

TEST(ScenarioValidation, SimulateRefusesMoreSamplesThanTheLimitInsteadOfAllocatingThem) {
  auto run = simulate_text(on_straight(kEgo), [] {
    SimulationOptions options;
    options.duration = 1;
    return options;
  }());
  ASSERT_TRUE(run.trace) << run.errors;
  const SourceFile file("inline.avu", on_straight(kEgo));
  avunit::ParseResult parsed = avunit::parse(file);
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), {});
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, {}, map, 0, diagnostics);
  ASSERT_TRUE(setup);
  SimulationOptions options;
  options.duration = 1e9;
  EXPECT_THROW(simulate(map, *setup, options), std::invalid_argument);
  EXPECT_TRUE(sample_count_problem(1e9, 0.05));
  EXPECT_FALSE(sample_count_problem(30, 0.05));
}

TEST(ScenarioValidation, AnEgoFarFromEveryLaneIsAWarningWithTheDistance) {
  auto run =
      simulate_text(on_straight("ego = AV(((-4210000, -5), , 5), (\"east_0\"->300));\n"), [] {
        SimulationOptions options;
        options.duration = 1;
        return options;
      }());
  EXPECT_TRUE(run.trace) << "a warning, not an error: " << run.errors;
  EXPECT_NE(run.errors.find("inline.avu:1:11: warning"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("4210 km from the nearest lane ('east_0')"), std::string::npos)
      << run.errors;
}

TEST(ScenarioValidation, AnEgoWhoseTargetIsWhereItStartsIsAnError) {
  auto run = simulate_text(on_straight("ego = AV((\"east_0\"->100, , 5), (\"east_0\"->100));\n"));
  expect_error(run, 1, "is where it starts");
}

TEST(ScenarioValidation, AnEgoWithoutTargetAtTheEndOfTheRoadDrivesWithoutARoute) {
  // The lane ahead has no length there: the ego has no route rather than one route_path cannot
  // lay out. AVUnit always gives a target (WMG SDL need not), so the test takes it away.
  const SourceFile file("inline.avu", on_straight("ego = AV((\"east_0\"->500, , 5), "
                                                  "(\"east_0\"->500));\n"));
  avunit::ParseResult parsed = avunit::parse(file);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  parsed.scenario.ego.target.reset();
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), {});
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, {}, map, 0, diagnostics);
  ASSERT_TRUE(setup) << format_diagnostics(file, diagnostics);
  SimulationOptions options;
  options.duration = 1;
  EXPECT_EQ(simulate(map, *setup, options).end, EndReason::duration);
}

TEST(ScenarioValidation, AnEgoOnTheRoadGetsNoDistanceWarning) {
  auto run = simulate_text(on_straight(kEgo), [] {
    SimulationOptions options;
    options.duration = 1;
    return options;
  }());
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_EQ(run.errors.find("nearest lane"), std::string::npos) << run.errors;
}

}  // namespace
}  // namespace scenfuzz
