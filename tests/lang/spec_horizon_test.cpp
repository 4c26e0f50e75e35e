// Spec horizons (lang/spec_horizon.hpp): how far ahead a formula reads, nested intervals adding
// up, operators over the rest of the trace adding nothing.
#include "lang/spec_horizon.hpp"

#include <gtest/gtest.h>

#include <string>

#include "lang/avunit/avunit.hpp"

namespace scenfuzz {
namespace {

// The horizon of `formula`, written in AVUnit over the ego's speed.
double horizon_of(const std::string& formula) {
  const SourceFile file("inline.avu", R"(
ego = AV((("east_0"->20), , 10), (("east_0"->120), , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
spec = )" + formula + ";\ntrace |= spec;\n");
  const avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok() || parsed.scenario.specs.size() != 1) return -1;
  return formula_horizon(parsed.scenario.specs[0].formula);
}

TEST(SpecHorizonTest, ABoundedOperatorReadsToItsIntervalsEnd) {
  EXPECT_DOUBLE_EQ(horizon_of("F[0:40] (ego_state.speed > 1.0)"), 40);
  EXPECT_DOUBLE_EQ(horizon_of("G[5:12] (ego_state.speed > 1.0)"), 12);
  EXPECT_DOUBLE_EQ(horizon_of("ego_state.speed > 1.0"), 0);
}

TEST(SpecHorizonTest, NestedIntervalsAddUp) {
  EXPECT_DOUBLE_EQ(horizon_of("G[0:10] F[0:5] (ego_state.speed > 1.0)"), 15);
  EXPECT_DOUBLE_EQ(
      horizon_of("F[0:20] (G[0:10] (ego_state.speed > 1.0) & F[2:3] (ego_state.speed < 9.0))"), 30);
  EXPECT_DOUBLE_EQ(
      horizon_of("~(F[0:4] G[1:2] (ego_state.speed > 1.0)) | G[0:3] (ego_state.speed < 9.0)"), 6);
  EXPECT_DOUBLE_EQ(horizon_of("(ego_state.speed > 1.0) U[0:8] (F[0:4] (ego_state.speed < 9.0))"),
                   12);
}

TEST(SpecHorizonTest, OperatorsOverTheRestOfTheTraceAddNothing) {
  EXPECT_DOUBLE_EQ(horizon_of("F (ego_state.speed > 1.0)"), 0);
  EXPECT_DOUBLE_EQ(horizon_of("G (F[0:7] (ego_state.speed > 1.0))"), 7);
  EXPECT_DOUBLE_EQ(horizon_of("F[0:7] (G (ego_state.speed > 1.0))"), 7);
}

TEST(SpecHorizonTest, TheLongestSpecAndTheSpecsBeyondADurationAreNamed) {
  const SourceFile file("inline.avu", R"(
ego = AV((("east_0"->20), , 10), (("east_0"->120), , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
short_one = F[0:10] (ego_state.speed > 1.0);
long_one = G[0:30] F[0:20] (ego_state.speed > 1.0);
trace |= short_one;
trace |= long_one;
)");
  const avunit::ParseResult parsed = avunit::parse(file);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  const std::optional<SpecHorizon> longest = longest_horizon(parsed.scenario.specs);
  ASSERT_TRUE(longest);
  EXPECT_EQ(longest->spec, "long_one");
  EXPECT_DOUBLE_EQ(longest->seconds, 50);
  const std::vector<SpecHorizon> beyond = horizons_beyond(parsed.scenario.specs, 30);
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_EQ(beyond[0].spec, "long_one");
  EXPECT_TRUE(horizons_beyond(parsed.scenario.specs, 50).empty());
}

}  // namespace
}  // namespace scenfuzz
