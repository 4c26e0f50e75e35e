// Tests of FindingLog, the rule that turns evaluations into findings: only judged evaluations with
// a robustness strictly below zero count, one finding per evaluation listing every violated
// objective, one per failure mode (the evaluation's signature), numbered in the order the modes
// appear; a later evaluation of a known mode is counted, and replaces the mode's finding when it
// violates more.
#include "fuzz/findings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "fuzz/search.hpp"

namespace scenfuzz {
namespace {

EvaluationRecord judged_record(std::size_t index, UnitPoint point, std::vector<double> robustness,
                               std::string signature = "") {
  EvaluationRecord record;
  record.index = index;
  record.seed = 1000 + index;
  record.point = std::move(point);
  record.evaluation.robustness = std::move(robustness);
  record.evaluation.signature = std::move(signature);
  return record;
}

TEST(FindingLogTest, OneFindingPerEvaluationListingEveryViolatedObjective) {
  FindingLog log({"no_collision", "standstill_gap", "reach_goal"});

  EvaluationRecord record = judged_record(4, {0.1, 0.1}, {-1.5, 2.0, -0.25}, "mode A");
  record.evaluation.violated = {2, 0};  // reach_goal was violated first
  const std::optional<FindingUpdate> first = log.add(record);
  ASSERT_TRUE(first);
  EXPECT_FALSE(first->replaced);
  EXPECT_EQ(first->finding.number, 1u);
  EXPECT_EQ(first->finding.objective, 2u);
  EXPECT_EQ(first->finding.objective_name, "reach_goal");
  EXPECT_EQ(first->finding.violated, (std::vector<std::size_t>{2, 0}));
  EXPECT_EQ(first->finding.robustness, -0.25);
  EXPECT_EQ(first->finding.evaluation, 4u);
  EXPECT_EQ(first->finding.seed, 1004u);
  EXPECT_EQ(first->finding.point, (UnitPoint{0.1, 0.1}));
  EXPECT_EQ(first->finding.mode, "mode A");
  EXPECT_EQ(first->finding.count, 1u);

  EXPECT_FALSE(log.add(judged_record(5, {0.5, 0.5}, {1.0, 1.0, 1.0}, "")));

  const std::optional<FindingUpdate> second =
      log.add(judged_record(9, {0.9, 0.9}, {1.0, -3.0, 0.5}, "mode B"));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->finding.number, 2u);
  EXPECT_EQ(second->finding.objective, 1u);
  EXPECT_EQ(second->finding.violated, (std::vector<std::size_t>{1}));

  ASSERT_EQ(log.findings().size(), 2u);
  EXPECT_EQ(log.duplicates(), 0u);
}

TEST(FindingLogTest, TheSameModeAnywhereIsOneFindingCounted) {
  FindingLog log({"no_collision"});
  ASSERT_TRUE(log.add(judged_record(0, {0.1, 0.1}, {-1.0}, "collision | car npc1 | ego")));
  // Far away in the space, less violating: counted, not written again.
  EXPECT_FALSE(log.add(judged_record(1, {0.9, 0.9}, {-0.5}, "collision | car npc1 | ego")));
  EXPECT_FALSE(log.add(judged_record(2, {0.5, 0.5}, {-1.0}, "collision | car npc1 | ego")));
  EXPECT_EQ(log.duplicates(), 2u);
  ASSERT_EQ(log.findings().size(), 1u);
  EXPECT_EQ(log.findings()[0].count, 3u);
  EXPECT_EQ(log.findings()[0].evaluation, 0u);  // ties go to the earliest

  // Another mode next to it is a finding of its own.
  const std::optional<FindingUpdate> other =
      log.add(judged_record(3, {0.1, 0.1}, {-1.0}, "collision | car npc1 | other"));
  ASSERT_TRUE(other);
  EXPECT_EQ(other->finding.number, 2u);
}

TEST(FindingLogTest, AMoreViolatingEvaluationBecomesItsModesFinding) {
  FindingLog log({"no_collision"});
  ASSERT_TRUE(log.add(judged_record(0, {0.1}, {-0.2}, "m")));
  const std::optional<FindingUpdate> better = log.add(judged_record(7, {0.6}, {-0.9}, "m"));
  ASSERT_TRUE(better);
  EXPECT_TRUE(better->replaced);
  EXPECT_EQ(better->finding.number, 1u);
  EXPECT_EQ(better->finding.evaluation, 7u);
  EXPECT_EQ(better->finding.count, 2u);
  ASSERT_EQ(log.findings().size(), 1u);
  EXPECT_EQ(log.findings()[0].evaluation, 7u);
  EXPECT_EQ(log.findings()[0].point, (UnitPoint{0.6}));
  EXPECT_EQ(log.duplicates(), 1u);
}

// An evaluator that names no modes: findings go by the first violated objective.
TEST(FindingLogTest, WithoutSignaturesTheFirstViolatedObjectiveIsTheMode) {
  FindingLog log({"a", "b"});
  EXPECT_TRUE(log.add(judged_record(0, {0.1}, {-1.0, 1.0})));
  EXPECT_FALSE(log.add(judged_record(1, {0.9}, {-0.5, -1.0})));
  EXPECT_TRUE(log.add(judged_record(2, {0.5}, {1.0, -1.0})));
  EXPECT_EQ(log.findings().size(), 2u);
  EXPECT_EQ(log.duplicates(), 1u);
}

TEST(FindingLogTest, EgoFailuresAreOneFindingPerKindAndSignal) {
  FindingLog log({"no_collision"});
  EvaluationRecord crash = judged_record(0, {0.1}, {});
  crash.evaluation.failure = "the plugin died";
  crash.evaluation.failure_kind = "ego_crash";
  crash.evaluation.signature = "ego_crash SIGSEGV";
  const std::optional<FindingUpdate> first = log.add(crash);
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->finding.ego_failure());
  EXPECT_TRUE(std::isnan(first->finding.robustness));
  crash.index = 1;
  EXPECT_FALSE(log.add(crash));
  crash.index = 2;
  crash.evaluation.signature = "ego_crash SIGABRT";
  EXPECT_TRUE(log.add(crash));
  EXPECT_EQ(log.findings().size(), 2u);
  EXPECT_EQ(log.findings()[0].count, 2u);
}

TEST(FindingLogTest, UnjudgedEvaluationsAreNeverFindings) {
  FindingLog log({"no_collision"});

  // A robustness left on an unjudged evaluation must not be read.
  EvaluationRecord infeasible = judged_record(0, {0.5, 0.5}, {-1.0}, "m");
  infeasible.evaluation.infeasible = "bodies overlap at t = 0";
  EXPECT_FALSE(log.add(infeasible));

  EvaluationRecord failed = judged_record(1, {0.2, 0.2}, {-1.0}, "m");
  failed.evaluation.failure = "no path to the target";
  EXPECT_FALSE(log.add(failed));

  EXPECT_TRUE(log.findings().empty());
  EXPECT_EQ(log.duplicates(), 0u);

  // And they leave no mode behind that would make a later one a duplicate.
  EXPECT_TRUE(log.add(judged_record(3, {0.5, 0.5}, {-1.0}, "m")));
}

TEST(FindingLogTest, RobustnessOfExactlyZeroIsNotAFinding) {
  FindingLog log({"a", "b"});
  EXPECT_FALSE(log.add(judged_record(0, {0.5}, {0.0, -0.0})));
  EXPECT_TRUE(log.findings().empty());

  // The smallest negative double is a violation.
  const std::optional<FindingUpdate> smallest =
      log.add(judged_record(1, {0.5}, {-std::numeric_limits<double>::denorm_min(), 0.0}));
  ASSERT_TRUE(smallest);
  EXPECT_EQ(smallest->finding.objective, 0u);
}

TEST(FindingLogTest, NanIsNotAFinding) {
  FindingLog log({"a", "b"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(log.add(judged_record(0, {0.5, 0.5}, {nan, nan})));

  const std::optional<FindingUpdate> one = log.add(judged_record(1, {0.1, 0.1}, {nan, -1.0}));
  ASSERT_TRUE(one);
  EXPECT_EQ(one->finding.objective, 1u);
  EXPECT_EQ(one->finding.number, 1u);
}

}  // namespace
}  // namespace scenfuzz
