// The other-fault rule of judge_trace (docs/oracle.md, "Not the ego's fault"): a spec violated
// only once another road user brought a collision that was not the ego's fault is that road
// user's doing, not a violation; what the ego did before still counts. Traces built by hand on
// `straight`: the ego cruising in east_0, a car from behind running into it, or the ego running
// into a car standing far ahead.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "oracle/judge.hpp"
#include "tests/oracle/hand_traces.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::along_lanes;
using test::steady;

constexpr const char* kScenario = R"(
ego = AV((("east_0"->100), , 10), (("east_0"->400), , ));
npc = Vehicle(("east_0"->40, , 20));
scenario = CreateScenario{load("straight"); ego; {npc}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
npc_truth = trace[truth][npc];
gap = G (dis(ego_state, npc_truth) >= 2.0);
slow = G (ego_state.speed <= 8.0);
gap_and_slow = G (dis(ego_state, npc_truth) >= 2.0) & G (ego_state.speed <= 12.0);
trace |= gap;
trace |= slow;
trace |= gap_and_slow;
)";

struct Judged {
  Trace trace;
  std::vector<SpecVerdict> verdicts;
};

// The ego at `ego_speed` from s = 100 m, the car at `npc_speed` from `npc_s`, both in east_0,
// until they touch.
Judged judge(double ego_speed, double npc_s, double npc_speed, const JudgeOptions& options = {}) {
  const RoadMap map = test::builtin("straight");
  Judged judged{test::two_actor_trace(20), {}};
  test::move(judged.trace, map, judged.trace.actors[0],
             along_lanes(map, {"east_0"}, 100, steady(ego_speed)));
  test::move(judged.trace, map, judged.trace.actors[1],
             along_lanes(map, {"east_0"}, npc_s, steady(npc_speed)));
  test::end_at_contact(judged.trace);
  const test::ParsedScenario parsed = test::parse_scenario(kScenario);
  judged.verdicts = judge_trace(parsed.scenario, parsed.parameters, judged.trace, map,
                                SourceFile("inline.avu", kScenario), options);
  return judged;
}

TEST(JudgeOtherFaultTest, AViolationOnlyTheOthersCollisionBroughtIsNotAViolation) {
  // Rear-ended at 10 m/s by a car doing 20 m/s that started 60 m behind.
  const Judged run = judge(10, 40, 20);
  ASSERT_EQ(run.verdicts.size(), 3u);
  const SpecVerdict& gap = run.verdicts[0];
  EXPECT_EQ(gap.ending, VerdictEnding::other_fault);
  EXPECT_EQ(verdict_ending_name(gap.ending), "other-fault");
  EXPECT_FALSE(gap.violated());
  EXPECT_GE(gap.robustness, 0);
  EXPECT_GE(gap.guide, 0);
  EXPECT_LT(gap.robustness_as_observed, 0) << "closer than 2 m before the contact, as observed";
  EXPECT_EQ(gap.other, "npc");
  EXPECT_GT(gap.danger_from, 0);
  EXPECT_LT(gap.danger_from, run.trace.time.back());
  EXPECT_TRUE(gap.conjuncts.empty());
}

TEST(JudgeOtherFaultTest, WhatTheEgoDidBeforeStillCounts) {
  // Over 8 m/s from the start: the ego's own, whoever ran into it later.
  const Judged run = judge(10, 40, 20);
  const SpecVerdict& slow = run.verdicts[1];
  EXPECT_EQ(slow.ending, VerdictEnding::decided);
  EXPECT_TRUE(slow.violated());
  EXPECT_NEAR(slow.robustness, -2, 1e-6);
  // Within 12 m/s the whole time: the conjunction is broken only by the gap, the other's doing.
  EXPECT_EQ(run.verdicts[2].ending, VerdictEnding::other_fault);
  EXPECT_FALSE(run.verdicts[2].violated());
}

TEST(JudgeOtherFaultTest, AllCollisionsJudgesTheTraceAsObserved) {
  JudgeOptions all;
  all.all_collisions = true;
  const Judged run = judge(10, 40, 20, all);
  EXPECT_EQ(run.verdicts[0].ending, VerdictEnding::decided);
  EXPECT_TRUE(run.verdicts[0].violated());
  EXPECT_EQ(run.verdicts[2].ending, VerdictEnding::decided);
  EXPECT_TRUE(run.verdicts[2].violated());
}

TEST(JudgeOtherFaultTest, ACollisionTheEgoCausedLeavesItsViolationsDecided) {
  // The ego at 10 m/s running into a car standing 100 m ahead: its own fault.
  const Judged run = judge(10, 200, 0);
  const SpecVerdict& gap = run.verdicts[0];
  EXPECT_EQ(gap.ending, VerdictEnding::decided);
  EXPECT_TRUE(gap.violated());
  EXPECT_TRUE(gap.other.empty());
}

}  // namespace
}  // namespace scenfuzz
