// A plugin's failure as the trace records it for a finding (Trace::ego_failure): its kind,
// signal, step, time and the last observation it was handed; and the wall time a hanging plugin
// costs a whole simulation, which the start and step limits bound.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "simulation_fixtures.hpp"

#if !defined(SCENFUZZ_EXAMPLE_EGO_PLUGIN) || !defined(SCENFUZZ_TEST_PLUGIN_DIR)
#error "tests/CMakeLists.txt passes the plugins' paths"
#endif

namespace scenfuzz {
namespace {

using Clock = std::chrono::steady_clock;

std::string test_plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

// A scenario prepared once, so that a test can time simulate() alone.
struct Prepared {
  RoadMap map;
  SimulationSetup setup;
};

Prepared straight_drive() {
  const SourceFile file("inline.avu",
                        "ego = AV((\"east_0\"->10, , 5), (\"east_0\"->300));\n"
                        "scenario = CreateScenario{load(\"straight\");\nego;\n{};\n{};\n{};\n};\n");
  avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  std::vector<double> values;
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, 0, diagnostics);
  EXPECT_TRUE(setup) << format_diagnostics(file, diagnostics);
  return {std::move(map), std::move(*setup)};
}

SimulationOptions with_plugin(const std::string& library) {
  SimulationOptions options;
  options.ego_plugin = library;
  options.plugin_step_timeout = 0.3;
  options.plugin_start_timeout = 0.5;
  return options;
}

// Runs and times simulate().
Trace timed_simulation(const Prepared& prepared, const SimulationOptions& options,
                       double& seconds) {
  const auto start = Clock::now();
  Trace trace = simulate(prepared.map, prepared.setup, options);
  seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return trace;
}

TEST(SimulationEgoFailure, ACrashRecordsItsSignalStepTimeAndLastObservation) {
  const Prepared prepared = straight_drive();
  SimulationOptions options = with_plugin(test_plugin("crashing"));
  const Trace trace = simulate(prepared.map, prepared.setup, options);
  ASSERT_EQ(trace.end, EndReason::ego_failure);
  ASSERT_TRUE(trace.ego_failure);
  const EgoFailure& failure = *trace.ego_failure;
  EXPECT_EQ(failure.kind, EgoFailureKind::crash);
  EXPECT_EQ(failure.signal, "SIGSEGV");
  EXPECT_EQ(failure.step, 3);
  EXPECT_DOUBLE_EQ(failure.time, 2 * options.dt) << "step 3 is handed the state at t = 2 dt";
  EXPECT_EQ(failure.reason, trace.events.back().message);
  EXPECT_NE(failure.reason.find("crashed (SIGSEGV) at step 3"), std::string::npos);
  const auto observation = nlohmann::json::parse(failure.last_observation);
  EXPECT_DOUBLE_EQ(observation["ego"]["time"].get<double>(), 2 * options.dt);
  EXPECT_NEAR(observation["ego"]["x"].get<double>(), trace.actors[0].x.back(), 1e-9);
  EXPECT_FALSE(observation["route"].empty());
  EXPECT_TRUE(observation["distance_to_target"].is_number()) << "the scenario has a target";
}

TEST(SimulationEgoFailure, AnErrorAtStartHasStepZeroAndNoObservation) {
  const Prepared prepared = straight_drive();
  const Trace trace =
      simulate(prepared.map, prepared.setup, with_plugin(test_plugin("missing_symbol")));
  ASSERT_TRUE(trace.ego_failure);
  EXPECT_EQ(trace.end, EndReason::ego_failure);
  EXPECT_EQ(trace.ego_failure->kind, EgoFailureKind::error);
  EXPECT_EQ(trace.ego_failure->step, 0);
  EXPECT_EQ(trace.ego_failure->time, 0);
  EXPECT_EQ(trace.ego_failure->signal, "");
  EXPECT_EQ(trace.ego_failure->last_observation, "");
  EXPECT_NE(trace.ego_failure->reason.find("lacks symbol scenfuzz_ego_step"), std::string::npos);
}

TEST(SimulationEgoFailure, AReturnedErrorIsAnErrorAtItsStep) {
  const Prepared prepared = straight_drive();
  const SimulationOptions options = with_plugin(test_plugin("failing"));
  const Trace trace = simulate(prepared.map, prepared.setup, options);
  ASSERT_TRUE(trace.ego_failure);
  EXPECT_EQ(trace.ego_failure->kind, EgoFailureKind::error);
  EXPECT_EQ(trace.ego_failure->step, 2);
  EXPECT_DOUBLE_EQ(trace.ego_failure->time, options.dt);
  EXPECT_FALSE(trace.ego_failure->last_observation.empty());
}

TEST(SimulationEgoFailure, AHangingStepCostsTheStepLimit) {
  const Prepared prepared = straight_drive();
  double seconds = 0;
  const Trace trace = timed_simulation(prepared, with_plugin(test_plugin("hanging")), seconds);
  ASSERT_TRUE(trace.ego_failure);
  EXPECT_EQ(trace.ego_failure->kind, EgoFailureKind::hang);
  EXPECT_EQ(trace.ego_failure->step, 1);
  EXPECT_EQ(trace.ego_failure->time, 0);
  EXPECT_FALSE(trace.ego_failure->last_observation.empty());
  EXPECT_GE(seconds, 0.3);
  EXPECT_LE(seconds, 1.1 * 0.3 + 0.15);
}

TEST(SimulationEgoFailure, AHangingCreateCostsTheStartLimit) {
  const Prepared prepared = straight_drive();
  double seconds = 0;
  const Trace trace =
      timed_simulation(prepared, with_plugin(test_plugin("hanging_create")), seconds);
  ASSERT_TRUE(trace.ego_failure);
  EXPECT_EQ(trace.ego_failure->kind, EgoFailureKind::hang);
  EXPECT_EQ(trace.ego_failure->step, 0);
  EXPECT_EQ(trace.ego_failure->last_observation, "");
  EXPECT_NE(trace.ego_failure->reason.find("did not start within 0.5 s"), std::string::npos)
      << trace.ego_failure->reason;
  EXPECT_GE(seconds, 0.5);
  EXPECT_LE(seconds, 1.1 * 0.5 + 0.15);
}

TEST(SimulationEgoFailure, ARunWithoutFailureHasNone) {
  const Prepared prepared = straight_drive();
  SimulationOptions options = with_plugin(SCENFUZZ_EXAMPLE_EGO_PLUGIN);
  options.duration = 2;
  const Trace trace = simulate(prepared.map, prepared.setup, options);
  EXPECT_EQ(trace.end, EndReason::duration);
  EXPECT_FALSE(trace.ego_failure);
}

}  // namespace
}  // namespace scenfuzz
