// The start-state rule of judge_trace (docs/oracle.md, "Start state"): a spec violated within the
// grace and not once those first seconds are excused is the scenario's start state's doing, not
// a violation; one the trace still violates afterwards is decided, and reported by the driver's
// share when the start state made it worse. Traces built by hand: the ego alone on `straight`,
// at 10 m/s for its first seconds and slower after.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "oracle/judge.hpp"
#include "tests/oracle/hand_traces.hpp"

namespace scenfuzz {
namespace {

using test::along_lanes;

// 8 m/s is the limit; the target lies far beyond what 12 s bring.
constexpr const char* kScenario = R"(
ego_target = "east_0"->400;
ego = AV((("east_0"->20), , 10), (ego_target, , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
slow = G (ego_state.speed <= 8.0);
slow_then_stopped = G (ego_state.speed <= 8.0) & F (ego_state.speed < 1.0);
slow_and_there = G (ego_state.speed <= 8.0) & F (dis(ego_state, ego_target) <= 2.0);
slow_and_near = G (ego_state.speed <= 8.0) & G (dis(ego_state, ego_target) <= 370.0);
trace |= slow;
trace |= slow_then_stopped;
trace |= slow_and_there;
trace |= slow_and_near;
)";

// Piecewise constant speeds: 10 m/s from the start, each step's speed from its time on.
struct Profile {
  struct Step {
    double from = 0;
    double speed = 0;
  };
  std::vector<Step> steps{{0, 10}};

  Profile then(double from, double speed) const {
    Profile next = *this;
    next.steps.push_back({from, speed});
    return next;
  }
  double at(double t) const {
    double speed = steps.front().speed;
    for (const Step& step : steps)
      if (t >= step.from - 1e-9) speed = step.speed;
    return speed;
  }
  double distance(double t) const {
    double distance = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const double end = std::min(t, k + 1 < steps.size() ? steps[k + 1].from : t);
      distance += steps[k].speed * std::max(0.0, end - steps[k].from);
    }
    return distance;
  }
};
// 10 m/s until `until` seconds, then `after` m/s.
Profile fast_until(double until, double after) { return Profile{}.then(until, after); }

struct Judged {
  Trace trace;
  std::vector<SpecVerdict> verdicts;
};

Judged judge(const Profile& profile, EndReason end, const JudgeOptions& options = {},
             double seconds = 12) {
  const RoadMap map = test::builtin("straight");
  Judged judged{test::empty_trace(static_cast<std::size_t>(seconds / test::kDt) + 1, test::kDt),
                {}};
  judged.trace.actors.push_back(test::still_actor(judged.trace, "ego", TraceActorKind::ego,
                                                  BodyShape::box, test::kCarLength, test::kCarWidth,
                                                  0, 0));
  test::move(judged.trace, map, judged.trace.actors[0],
             along_lanes(map, {"east_0"}, 20, [profile](double t) { return profile.distance(t); }));
  // The speeds exactly (a central difference of the positions rounds them).
  TraceActor& ego = judged.trace.actors[0];
  for (std::size_t i = 0; i < judged.trace.sample_count(); ++i)
    ego.speed[i] = profile.at(judged.trace.time[i]);
  judged.trace.end = end;
  const test::ParsedScenario parsed = test::parse_scenario(kScenario);
  judged.verdicts = judge_trace(parsed.scenario, parsed.parameters, judged.trace, map,
                                SourceFile("inline.avu", kScenario), options);
  return judged;
}

TEST(JudgeStartStateTest, AViolationOnlyTheStartStateMadeIsStartStateNotAViolation) {
  const Judged run = judge(fast_until(1, 7.5), EndReason::target_reached);
  ASSERT_EQ(run.verdicts.size(), 4u);
  const SpecVerdict& slow = run.verdicts[0];
  EXPECT_EQ(slow.ending, VerdictEnding::start);
  EXPECT_EQ(verdict_ending_name(slow.ending), "start-state");
  EXPECT_FALSE(slow.violated());
  EXPECT_NEAR(slow.robustness, 0.5, 1e-6);  // 7.5 m/s from 2 s on
  EXPECT_NEAR(slow.guide, 0.5, 1e-6);
  EXPECT_NEAR(slow.robustness_as_observed, -2, 1e-6);  // 10 m/s at the start
  EXPECT_LT(slow.time, 1.0);
  EXPECT_EQ(slow.atom_text, "ego_state.speed <= 8.0");
  EXPECT_TRUE(slow.conjuncts.empty());
}

TEST(JudgeStartStateTest, AViolationThatPersistsIsDecided) {
  const Judged run = judge(fast_until(5, 7.5), EndReason::target_reached);
  const SpecVerdict& slow = run.verdicts[0];
  EXPECT_EQ(slow.ending, VerdictEnding::decided);
  EXPECT_TRUE(slow.violated());
  EXPECT_NEAR(slow.robustness, -2, 1e-6);
  // Back within the limit only at 2 s: the sample at 2 s is no longer the start's.
  const Judged late = judge(fast_until(2.05, 7.5), EndReason::target_reached);
  EXPECT_EQ(late.verdicts[0].ending, VerdictEnding::decided);
  EXPECT_TRUE(late.verdicts[0].violated());
}

TEST(JudgeStartStateTest, AViolationTheStartStateMadeWorseReportsTheDriversShare) {
  // Slowed from 10 m/s to 8.2 m/s, not to the limit of 8: -2 at 0 s as observed, all of it the
  // start state's but the 0.2 m/s the driver kept from 2 s on.
  const Judged run = judge(fast_until(1, 8.2), EndReason::target_reached);
  const SpecVerdict& slow = run.verdicts[0];
  EXPECT_EQ(slow.ending, VerdictEnding::decided);
  EXPECT_TRUE(slow.violated());
  EXPECT_TRUE(slow.start_excused);
  EXPECT_NEAR(slow.robustness, -0.2, 1e-6);
  EXPECT_NEAR(slow.time, 2.0, 1e-9);  // the first sample the grace does not excuse
  EXPECT_EQ(slow.atom_text, "ego_state.speed <= 8.0");
  EXPECT_NEAR(slow.robustness_as_observed, -2, 1e-6);
  EXPECT_EQ(slow.time_as_observed, 0.0);
  // The search still follows the trace as observed: negative as the robustness is.
  EXPECT_NEAR(slow.guide, -2, 1e-6);
}

TEST(JudgeStartStateTest, AConjunctionReportsItsSharesConjunctByConjunct) {
  const Judged run = judge(fast_until(1, 8.2), EndReason::target_reached);
  // Too far from the target only at the start (within 370 m of it from about 1 s on): a
  // start-state conjunct, whose -8 or so as observed was once reported with the speed's atom.
  const SpecVerdict& near = run.verdicts[3];
  EXPECT_EQ(near.ending, VerdictEnding::decided);
  EXPECT_TRUE(near.start_excused);
  EXPECT_NEAR(near.robustness, -0.2, 1e-6);
  EXPECT_LT(near.robustness_as_observed, -5);
  EXPECT_EQ(near.time_as_observed, 0.0);
  EXPECT_NEAR(near.time, 2.0, 1e-9);
  EXPECT_EQ(near.atom_text, "ego_state.speed <= 8.0");
  ASSERT_EQ(near.conjuncts.size(), 1u);
  EXPECT_NEAR(near.conjuncts[0].robustness, -0.2, 1e-6);
  EXPECT_NEAR(near.conjuncts[0].time, 2.0, 1e-9);
  // The G named by its share, at 2 s, before the F that closes at the end; the spec's worst is
  // the F's, which the start did not make worse: its robustness stands as observed.
  const SpecVerdict& stopped = run.verdicts[1];
  EXPECT_EQ(stopped.ending, VerdictEnding::decided);
  EXPECT_FALSE(stopped.start_excused);
  EXPECT_NEAR(stopped.robustness, -7.2, 1e-6);  // never below 8.2 m/s
  ASSERT_EQ(stopped.conjuncts.size(), 2u);
  EXPECT_EQ(stopped.conjuncts[0].atom_text, "ego_state.speed <= 8.0");
  EXPECT_NEAR(stopped.conjuncts[0].robustness, -0.2, 1e-6);
  EXPECT_NEAR(stopped.conjuncts[0].time, 2.0, 1e-9);
  EXPECT_EQ(stopped.conjuncts[1].atom_text, "ego_state.speed < 1.0");
  EXPECT_NEAR(stopped.time, 2.0, 1e-9);
  EXPECT_EQ(stopped.atom_text, "ego_state.speed <= 8.0");
}

TEST(JudgeStartStateTest, AWorstAfterTheGraceIsReportedAsObserved) {
  // Back to 11 m/s at 5 s: the driver's worst, after the grace; the start's 10 m/s plays no part.
  const Judged run = judge(fast_until(1, 8.2).then(5, 11), EndReason::target_reached);
  const SpecVerdict& slow = run.verdicts[0];
  EXPECT_EQ(slow.ending, VerdictEnding::decided);
  EXPECT_FALSE(slow.start_excused);
  EXPECT_NEAR(slow.robustness, -3, 1e-6);
  EXPECT_NEAR(slow.time, 5.0, 1e-9);
  EXPECT_NEAR(slow.guide, -3, 1e-6);
  EXPECT_EQ(slow.atom_text, "ego_state.speed <= 8.0");
}

TEST(JudgeStartStateTest, AViolationAsBadThroughoutStandsAsObserved) {
  // 10 m/s from the first sample to the last: the start state made it no worse than the driver
  // kept it, so it is reported where it first was, as before the driver's share was told apart.
  const Judged run = judge(fast_until(20, 10), EndReason::target_reached);
  const SpecVerdict& slow = run.verdicts[0];
  EXPECT_EQ(slow.ending, VerdictEnding::decided);
  EXPECT_FALSE(slow.start_excused);
  EXPECT_NEAR(slow.robustness, -2, 1e-6);
  EXPECT_EQ(slow.time, 0.0);
}

TEST(JudgeStartStateTest, ARunThatEndedWithinTheGraceIsDecided) {
  // Ended at 1.5 s (say, by a collision): there is no "from 2 s on" for the spec to hold in.
  const Judged run = judge(fast_until(1, 7.5), EndReason::collision, {}, 1.5);
  ASSERT_NEAR(run.trace.time.back(), 1.5, 1e-9);
  EXPECT_EQ(run.verdicts[0].ending, VerdictEnding::decided);
  EXPECT_TRUE(run.verdicts[0].violated());
  // Ended at 2 s: the sample at 2 s holds.
  EXPECT_EQ(judge(fast_until(1, 7.5), EndReason::collision, {}, 2).verdicts[0].ending,
            VerdictEnding::start);
}

TEST(JudgeStartStateTest, AnotherConjunctTheTraceViolatesKeepsItDecided) {
  // The G is the start's, but the ego never slows below 1 m/s: the F is the driver's.
  const Judged run = judge(fast_until(1, 7.5), EndReason::target_reached);
  const SpecVerdict& both = run.verdicts[1];
  EXPECT_EQ(both.ending, VerdictEnding::decided);
  EXPECT_TRUE(both.violated());
  // Only the driver's violation is named: the G the start broke is not among the conjuncts.
  ASSERT_EQ(both.conjuncts.size(), 1u);
  EXPECT_EQ(both.conjuncts[0].atom_text, "ego_state.speed < 1.0");
  EXPECT_EQ(both.atom_text, "ego_state.speed < 1.0");
  EXPECT_NEAR(both.robustness, -6.5, 1e-6);  // never below 7.5 m/s
}

TEST(JudgeStartStateTest, ViolationAtZeroCountsAnExcusedZeroAsViolated) {
  const Judged at_limit = judge(fast_until(1, 8.0), EndReason::target_reached);
  EXPECT_EQ(at_limit.verdicts[0].ending, VerdictEnding::start);
  EXPECT_NEAR(at_limit.verdicts[0].robustness, 0, 1e-9);
  JudgeOptions lawbreaker;
  lawbreaker.violation_at_zero = true;
  const Judged zero = judge(fast_until(1, 8.0), EndReason::target_reached, lawbreaker);
  EXPECT_EQ(zero.verdicts[0].ending, VerdictEnding::decided);
  EXPECT_TRUE(zero.verdicts[0].violated());
  // The driver's share is the 0 at the limit (a violation here), the start state's the -2.
  EXPECT_TRUE(zero.verdicts[0].start_excused);
  EXPECT_EQ(zero.verdicts[0].robustness, 0);
  EXPECT_EQ(zero.verdicts[0].robustness_as_observed, -2);
  EXPECT_LT(zero.verdicts[0].guide, 0);
  // A wider grace reaches the persisting violation's end: start-state again.
  JudgeOptions five_seconds;
  five_seconds.start_grace = 5.5;
  EXPECT_EQ(judge(fast_until(5, 7.5), EndReason::target_reached, five_seconds).verdicts[0].ending,
            VerdictEnding::start);
}

TEST(JudgeStartStateTest, ARunBothStartedAndEndedOutOfLineIsStartStateWhileTheEgoProgressed) {
  // Ended at its duration 300 m short of the target, too fast at the start: neither end alone
  // explains the violation of `slow_and_there`, both together do.
  const Judged run = judge(fast_until(1, 7.5), EndReason::duration);
  const SpecVerdict& both = run.verdicts[2];
  EXPECT_EQ(both.ending, VerdictEnding::start);
  EXPECT_FALSE(both.violated());
  EXPECT_NEAR(both.robustness, 0.5, 1e-6);
  EXPECT_LT(both.robustness_as_observed, 0);
  EXPECT_NE(both.progress.find("drove"), std::string::npos) << both.progress;
  // Standing still from 1 s on: the end's part is the ego's, stuck.
  const Judged stopped = judge(fast_until(1, 0), EndReason::duration);
  EXPECT_EQ(stopped.verdicts[2].ending, VerdictEnding::stuck);
  EXPECT_TRUE(stopped.verdicts[2].violated());
  ASSERT_EQ(stopped.verdicts[2].conjuncts.size(), 1u);  // the G is the start's
  EXPECT_EQ(stopped.verdicts[2].conjuncts[0].atom_text, "dis(ego_state, ego_target) <= 2.0");
}

TEST(JudgeStartStateTest, TheCollisionOracleIsNotAffected) {
  // Two cars overlapping from t = 0 on: the start state's doing, and a collision all the same.
  const RoadMap map = test::builtin("straight");
  Trace trace = test::two_actor_trace(5);
  test::move(trace, map, trace.actors[0], [](double) { return test::State{0, -1.75, 0, 0}; });
  test::move(trace, map, trace.actors[1], [](double) { return test::State{3, -1.75, 0, 0}; });
  const std::vector<SpecVerdict> verdicts =
      judge_trace(ScenarioTemplate{}, {}, trace, map, SourceFile("inline.avu", ""));
  ASSERT_EQ(verdicts.size(), 1u);
  EXPECT_EQ(verdicts[0].ending, VerdictEnding::decided);
  EXPECT_TRUE(verdicts[0].violated());
  EXPECT_EQ(verdicts[0].time, 0.0);
}

}  // namespace
}  // namespace scenfuzz
