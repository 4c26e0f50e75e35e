// Tests of FindingLog, the rule that turns evaluations into findings: only judged evaluations with
// a robustness strictly below zero count, one finding per violated objective, numbered in the
// order they come; a later violation of the same objective is a duplicate when its point is near
// (in the normalised distance) or its non-empty signature is the same.
#include "fuzz/findings.hpp"

#include <gtest/gtest.h>

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

TEST(FindingLogTest, NumbersFindingsInOrderOnePerViolatedObjective) {
  FindingLog log({"no_collision", "standstill_gap", "reach_goal"});

  const std::vector<Finding> first = log.add(judged_record(4, {0.1, 0.1}, {-1.5, 2.0, -0.25}));
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].number, 1u);
  EXPECT_EQ(first[0].objective, 0u);
  EXPECT_EQ(first[0].objective_name, "no_collision");
  EXPECT_EQ(first[0].robustness, -1.5);
  EXPECT_EQ(first[0].evaluation, 4u);
  EXPECT_EQ(first[0].seed, 1004u);
  EXPECT_EQ(first[0].point, (UnitPoint{0.1, 0.1}));
  EXPECT_EQ(first[1].number, 2u);
  EXPECT_EQ(first[1].objective, 2u);
  EXPECT_EQ(first[1].objective_name, "reach_goal");
  EXPECT_EQ(first[1].robustness, -0.25);

  EXPECT_TRUE(log.add(judged_record(5, {0.5, 0.5}, {1.0, 1.0, 1.0})).empty());

  const std::vector<Finding> second = log.add(judged_record(9, {0.9, 0.9}, {1.0, -3.0, 0.5}));
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].number, 3u);
  EXPECT_EQ(second[0].objective, 1u);
  EXPECT_EQ(second[0].evaluation, 9u);

  ASSERT_EQ(log.findings().size(), 3u);
  for (std::size_t i = 0; i < log.findings().size(); ++i)
    EXPECT_EQ(log.findings()[i].number, i + 1);
  EXPECT_EQ(log.duplicates(), 0u);
}

TEST(FindingLogTest, NearPointOfTheSameObjectiveIsADuplicate) {
  FindingLog log({"no_collision"}, 0.05);
  ASSERT_EQ(log.add(judged_record(0, {0.5, 0.5}, {-1.0})).size(), 1u);

  EXPECT_TRUE(log.add(judged_record(1, {0.51, 0.5}, {-2.0})).empty());
  EXPECT_EQ(log.duplicates(), 1u);
  EXPECT_TRUE(log.add(judged_record(2, {0.5, 0.5}, {-0.1})).empty());
  EXPECT_EQ(log.duplicates(), 2u);

  const std::vector<Finding> far = log.add(judged_record(3, {0.8, 0.2}, {-1.0}));
  ASSERT_EQ(far.size(), 1u);
  EXPECT_EQ(far[0].number, 2u);
  EXPECT_EQ(log.duplicates(), 2u);
  EXPECT_EQ(log.findings().size(), 2u);
}

// The distance is divided by the square root of the dimension count, so in four dimensions a
// step of 0.08 along one axis is 0.04 (near) and along all four 0.08 (far).
TEST(FindingLogTest, DistanceIsNormalisedByTheDimensionCount) {
  FindingLog log({"no_collision"}, 0.05);
  ASSERT_EQ(log.add(judged_record(0, {0.5, 0.5, 0.5, 0.5}, {-1.0})).size(), 1u);

  EXPECT_TRUE(log.add(judged_record(1, {0.58, 0.5, 0.5, 0.5}, {-1.0})).empty());
  EXPECT_EQ(log.duplicates(), 1u);

  EXPECT_EQ(log.add(judged_record(2, {0.42, 0.42, 0.42, 0.42}, {-1.0})).size(), 1u);
  EXPECT_EQ(log.duplicates(), 1u);
}

TEST(FindingLogTest, NearPointOfAnotherObjectiveIsNotADuplicate) {
  FindingLog log({"no_collision", "standstill_gap"}, 0.05);
  ASSERT_EQ(log.add(judged_record(0, {0.3, 0.3}, {-1.0, 1.0})).size(), 1u);

  const std::vector<Finding> other = log.add(judged_record(1, {0.3, 0.3}, {1.0, -1.0}));
  ASSERT_EQ(other.size(), 1u);
  EXPECT_EQ(other[0].objective, 1u);
  EXPECT_EQ(other[0].number, 2u);
  EXPECT_EQ(log.duplicates(), 0u);

  // Both objectives now have a finding there: violating both again is two duplicates.
  EXPECT_TRUE(log.add(judged_record(2, {0.31, 0.3}, {-1.0, -1.0})).empty());
  EXPECT_EQ(log.duplicates(), 2u);
}

TEST(FindingLogTest, FarPointWithTheSameSignatureIsADuplicate) {
  FindingLog log({"no_collision", "standstill_gap"}, 0.05);
  const std::string signature = "ego front / npc1 rear";
  ASSERT_EQ(log.add(judged_record(0, {0.1, 0.1}, {-1.0, 1.0}, signature)).size(), 1u);

  EXPECT_TRUE(log.add(judged_record(1, {0.9, 0.9}, {-1.0, 1.0}, signature)).empty());
  EXPECT_EQ(log.duplicates(), 1u);

  // Another signature, no signature at all, or another objective: new findings.
  EXPECT_EQ(log.add(judged_record(2, {0.9, 0.1}, {-1.0, 1.0}, "ego left / npc2 right")).size(), 1u);
  EXPECT_EQ(log.add(judged_record(3, {0.1, 0.9}, {-1.0, 1.0})).size(), 1u);
  EXPECT_EQ(log.add(judged_record(4, {0.5, 0.5}, {1.0, -1.0}, signature)).size(), 1u);
  EXPECT_EQ(log.duplicates(), 1u);
  EXPECT_EQ(log.findings().size(), 4u);
}

// An empty signature says nothing: two far findings without one are both kept.
TEST(FindingLogTest, EmptySignaturesDoNotMakeDuplicates) {
  FindingLog log({"no_collision"}, 0.05);
  EXPECT_EQ(log.add(judged_record(0, {0.1, 0.1}, {-1.0})).size(), 1u);
  EXPECT_EQ(log.add(judged_record(1, {0.9, 0.9}, {-1.0})).size(), 1u);
  EXPECT_EQ(log.duplicates(), 0u);
}

TEST(FindingLogTest, UnjudgedEvaluationsAreNeverFindings) {
  FindingLog log({"no_collision"});

  // A robustness left on an unjudged evaluation must not be read.
  EvaluationRecord infeasible = judged_record(0, {0.5, 0.5}, {-1.0});
  infeasible.evaluation.infeasible = "bodies overlap at t = 0";
  EXPECT_TRUE(log.add(infeasible).empty());

  EvaluationRecord failed = judged_record(1, {0.2, 0.2}, {-1.0});
  failed.evaluation.failure = "no path to the target";
  EXPECT_TRUE(log.add(failed).empty());

  EvaluationRecord empty = judged_record(2, {0.7, 0.7}, {});
  empty.evaluation.failure = "could not judge";
  EXPECT_TRUE(log.add(empty).empty());

  EXPECT_TRUE(log.findings().empty());
  EXPECT_EQ(log.duplicates(), 0u);

  // And they leave no trace that would make a later point near them a duplicate.
  EXPECT_EQ(log.add(judged_record(3, {0.5, 0.5}, {-1.0})).size(), 1u);
}

TEST(FindingLogTest, RobustnessOfExactlyZeroIsNotAFinding) {
  FindingLog log({"a", "b"});
  EXPECT_TRUE(log.add(judged_record(0, {0.5}, {0.0, -0.0})).empty());
  EXPECT_TRUE(log.findings().empty());
  EXPECT_EQ(log.duplicates(), 0u);

  // The smallest negative double is a violation.
  const std::vector<Finding> smallest =
      log.add(judged_record(1, {0.5}, {-std::numeric_limits<double>::denorm_min(), 0.0}));
  ASSERT_EQ(smallest.size(), 1u);
  EXPECT_EQ(smallest[0].objective, 0u);
}

TEST(FindingLogTest, NanIsNotAFinding) {
  FindingLog log({"a", "b"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(log.add(judged_record(0, {0.5, 0.5}, {nan, nan})).empty());
  EXPECT_EQ(log.duplicates(), 0u);

  const std::vector<Finding> one = log.add(judged_record(1, {0.1, 0.1}, {nan, -1.0}));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].objective, 1u);
  EXPECT_EQ(one[0].number, 1u);
}

}  // namespace
}  // namespace scenfuzz
