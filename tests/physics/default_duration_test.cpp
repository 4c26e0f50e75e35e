// The default duration (physics/simulation/default_duration.hpp): long enough for a spec that
// reads 40 s ahead, and for the ego to reach a far target at a low speed limit; a scenario's own
// duration shorter than a spec reads is warned of, naming the spec.
#include "physics/simulation/default_duration.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "lang/avunit/avunit.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/simulation.hpp"

namespace scenfuzz {
namespace {

struct Prepared {
  std::optional<SimulationSetup> setup;
  std::optional<RoadMap> map;
  std::string diagnostics;
};

Prepared prepare(const std::string& text, std::optional<double> own_duration = std::nullopt) {
  Prepared prepared;
  const SourceFile file("inline.avu", text);
  avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  if (own_duration) parsed.scenario.duration = constant_value(*own_duration);
  prepared.map = load_scenario_map(parsed.scenario.map, map_search_path({}), {});
  Diagnostics diagnostics;
  prepared.setup = prepare_simulation(parsed.scenario, {}, *prepared.map, 1, diagnostics);
  prepared.diagnostics = format_diagnostics(file, diagnostics);
  return prepared;
}

// A short route (100 m at 22.2 m/s) and a spec; `spec` is the formula.
std::string short_route_with(const std::string& spec) {
  return R"(
ego_target = "east_0"->120;
ego = AV((("east_0"->20), , 10), (ego_target, , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
)" + spec +
         "\n";
}

TEST(DefaultDurationTest, IsThirtySecondsForAShortRouteAndNoTimedSpec) {
  const Prepared prepared =
      prepare(short_route_with("reach = F (dis(ego_state, ego_target) <= 2.0);\ntrace |= reach;"));
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_DOUBLE_EQ(prepared.setup->duration, kDefaultDuration);
}

TEST(DefaultDurationTest, CoversASpecThatReadsFortySeconds) {
  const Prepared prepared = prepare(
      short_route_with("reach = F[0:40] (dis(ego_state, ego_target) <= 2.0);\ntrace |= reach;"));
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_GE(prepared.setup->duration, 40.0);
}

TEST(DefaultDurationTest, AddsUpNestedIntervals) {
  const Prepared prepared =
      prepare(short_route_with("calm = G[0:30] F[0:15] (ego_state.speed < 30.0);\ntrace |= calm;"));
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_GE(prepared.setup->duration, 45.0);
}

TEST(DefaultDurationTest, GivesTheEgoTimeToReachAFarTargetAtALowLimit) {
  // 460 m at 10 m/s: 46 s at the limit.
  const Prepared prepared = prepare(R"(
ego = AV((("east_0"->20), , 0), (("east_0"->480), , ));
scenario = CreateScenario{load("straight?speed_limit=10"); ego; {}; {}; {};};
)");
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_NEAR(prepared.setup->duration, kRouteTimeMargin * 46 + kStartStopAllowance, 0.5);
  // And the reference driver gets there within it, from a standstill.
  const Trace trace = simulate(*prepared.map, *prepared.setup, {});
  EXPECT_EQ(trace.end, EndReason::target_reached) << trace.time.back();
}

TEST(DefaultDurationTest, AScenarioDurationShorterThanASpecReadsIsWarnedNamingTheSpec) {
  const Prepared prepared = prepare(
      short_route_with("reach = F[0:40] (dis(ego_state, ego_target) <= 2.0);\ntrace |= reach;"),
      20.0);
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_DOUBLE_EQ(prepared.setup->duration, 20.0);
  EXPECT_EQ(prepared.diagnostics.find("lies"), std::string::npos) << prepared.diagnostics;
  EXPECT_NE(prepared.diagnostics.find("warning"), std::string::npos) << prepared.diagnostics;
  EXPECT_NE(prepared.diagnostics.find("spec 'reach'"), std::string::npos) << prepared.diagnostics;
  EXPECT_NE(prepared.diagnostics.find("40 s"), std::string::npos) << prepared.diagnostics;
}

TEST(DefaultDurationTest, LeavesTimeToWaitAtTheJunctionAndItsLightOnTheRoute) {
  // West to east through the built-in crossroads: west_in_0 from s = 20 (130 m), the 20 m
  // connector and 100 m of east_out_0 at 13.9 m/s, through one junction whose light shows red and
  // amber 35 s of its 60 s cycle.
  const Prepared prepared = prepare(R"(
ego = AV((("west_in_0"->20), , 0), (("east_out_0"->100), , ));
scenario = CreateScenario{load("crossroads"); ego; {}; {}; {};};
)");
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  const double at_limit = 250 / 13.9;
  EXPECT_NEAR(prepared.setup->duration,
              kRouteTimeMargin * at_limit + kStartStopAllowance + kJunctionWait + 35, 0.5);
  // Arriving as the light turns red, the reference driver still gets there within it.
  const Trace trace = simulate(*prepared.map, *prepared.setup, {});
  EXPECT_EQ(trace.end, EndReason::target_reached) << trace.time.back();
}

TEST(DefaultDurationTest, LeavesTimeToPassAnObstacleInTheEgosLaneOnly) {
  // 460 m at 10 m/s as above; a crate in the ego's lane, a wreck in the oncoming one.
  const Prepared prepared = prepare(R"(
ego = AV((("east_0"->20), , 0), (("east_0"->480), , ));
crate = Obstacle("east_0"->200, (box, 1.2, 1.0, 0.8));
wreck = Obstacle("west_0"->100, (box, 4.5, 1.9, 1.5));
scenario = CreateScenario{load("straight?speed_limit=10"); ego; {}; {}; {crate, wreck};};
)");
  ASSERT_TRUE(prepared.setup) << prepared.diagnostics;
  EXPECT_NEAR(prepared.setup->duration, kRouteTimeMargin * 46 + kStartStopAllowance + kJunctionWait,
              0.5);
}

}  // namespace
}  // namespace scenfuzz
