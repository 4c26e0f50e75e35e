// The round planner: shares follow the weights, every search gets at least the minimum, the
// budget is never exceeded, arms that found new modes or whose robustness still falls get more
// than exhausted ones, and a run ends when what is left is too little.
#include "fuzz/campaign/budget_schedule.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace scenfuzz {
namespace {

std::uint64_t sum(const std::vector<std::uint64_t>& budgets) {
  return std::accumulate(budgets.begin(), budgets.end(), std::uint64_t{0});
}

// A round in which every arm spent its budget, with these outcomes.
std::vector<ArmRound> spent(const std::vector<std::uint64_t>& budgets,
                            const std::vector<std::size_t>& new_modes,
                            const std::vector<double>& best) {
  std::vector<ArmRound> round;
  for (std::size_t a = 0; a < budgets.size(); ++a)
    round.push_back({budgets[a] > 0, budgets[a], new_modes[a],
                     budgets[a] > 0 ? std::optional<double>(best[a]) : std::nullopt});
  return round;
}

TEST(BudgetScheduleTest, TheFirstRoundFollowsTheWeights) {
  ScheduleInput input;
  input.weights = {1, 1, 2};
  input.total = 1000;
  const std::vector<std::uint64_t> budgets = plan_round(input);
  // A quarter of the budget, by weight.
  EXPECT_EQ(budgets, (std::vector<std::uint64_t>{63, 62, 125}));
}

TEST(BudgetScheduleTest, EverySearchGetsAtLeastTheMinimum) {
  ScheduleInput input;
  input.weights = {1, 0.5, 0.5, 0.5, 0.5};
  input.total = 320;
  const std::vector<std::uint64_t> budgets = plan_round(input);
  // 160 by weight would give the half-weight arms 26.7 each: the last one sits out.
  EXPECT_EQ(budgets, (std::vector<std::uint64_t>{64, 32, 32, 32, 0}));
  for (std::uint64_t budget : budgets)
    EXPECT_TRUE(budget == 0 || budget >= kMinSearchBudget) << budget;
}

TEST(BudgetScheduleTest, TheBudgetIsNeverExceededAndARemainderTooSmallIsLeft) {
  for (std::uint64_t total : {1u, 10u, 31u, 32u, 33u, 100u, 321u, 1000u, 4099u}) {
    ScheduleInput input;
    input.weights = {1, 1, 3};
    input.total = total;
    for (int round = 0; round < 100; ++round) {
      const std::vector<std::uint64_t> budgets = plan_round(input);
      if (sum(budgets) == 0) break;
      input.rounds.push_back(spent(budgets, {0, 0, 0}, {1, 1, 1}));
      ASSERT_LE(spent_simulations(input.rounds), total);
    }
    const std::uint64_t used = spent_simulations(input.rounds);
    EXPECT_LE(used, total);
    // What is left is less than a minimal search.
    EXPECT_LT(total - used, kMinSearchBudget) << total;
  }
}

TEST(BudgetScheduleTest, ProductiveArmsGetMoreThanExhaustedOnes) {
  ScheduleInput input;
  input.weights = {1, 1, 1};
  input.total = 2000;
  const std::vector<std::uint64_t> first = plan_round(input);
  // Arm 0 found a new mode, arm 1 lowered its best robustness, arm 2 did neither... in its
  // second round; in the first round every arm was new.
  input.rounds.push_back(spent(first, {0, 0, 0}, {1, 1, 1}));
  input.rounds.push_back(spent(first, {1, 0, 0}, {1, 0.5, 1}));
  EXPECT_EQ(arm_energy(input.rounds, 0), 2);
  EXPECT_EQ(arm_energy(input.rounds, 1), 1);
  EXPECT_EQ(arm_energy(input.rounds, 2), 0.5);
  const std::vector<std::uint64_t> next = plan_round(input);
  EXPECT_GT(next[0], next[1]);
  EXPECT_GT(next[1], next[2]);
  EXPECT_EQ(next[0], 2 * next[1]);
}

TEST(BudgetScheduleTest, EnergyHalvesPerUnproductiveSearchDownToAnEighth) {
  std::vector<std::vector<ArmRound>> rounds;
  rounds.push_back({{true, 50, 0, -1.0}});
  EXPECT_EQ(arm_energy(rounds, 0), 1);  // a first search counts as lowering the best
  const double expected[] = {0.5, 0.25, 0.125, 0.125};
  for (double energy : expected) {
    rounds.push_back({{true, 50, 0, -1.0}});  // the same best: no progress
    EXPECT_EQ(arm_energy(rounds, 0), energy);
  }
  rounds.push_back({{false, 0, 0, std::nullopt}});  // sitting a round out changes nothing
  EXPECT_EQ(arm_energy(rounds, 0), 0.125);
  rounds.push_back({{true, 50, 0, -1.5}});  // lower than ever: back to 1
  EXPECT_EQ(arm_energy(rounds, 0), 1);
  rounds.push_back({{true, 50, 2, -1.5}});  // new modes: 2
  EXPECT_EQ(arm_energy(rounds, 0), 2);
}

TEST(BudgetScheduleTest, TheRunEndsWhenARoundSpentNothing) {
  ScheduleInput input;
  input.weights = {1, 1};
  input.total = 1000;
  input.rounds.push_back({{true, 0, 0, std::nullopt}, {true, 0, 0, std::nullopt}});
  EXPECT_EQ(sum(plan_round(input)), 0u);
}

TEST(BudgetScheduleTest, AWallTimeBudgetAloneGivesRoundsOfTwoMinimalSearchesPerArm) {
  ScheduleInput input;
  input.weights = {1, 1, 1};
  std::vector<std::uint64_t> budgets = plan_round(input);
  EXPECT_EQ(budgets, (std::vector<std::uint64_t>(3, 2 * kMinSearchBudget)));
  for (int round = 0; round < 20; ++round) {
    input.rounds.push_back(spent(budgets, {0, 0, 0}, {1, 1, 1}));
    budgets = plan_round(input);
    EXPECT_EQ(sum(budgets), 6 * kMinSearchBudget);  // never over: the wall time ends the run
  }
}

TEST(BudgetScheduleTest, ABudgetSmallerThanAMinimalSearchGoesToOneSearch) {
  ScheduleInput input;
  input.weights = {1, 1};
  input.total = 10;
  EXPECT_EQ(plan_round(input), (std::vector<std::uint64_t>{10, 0}));
}

}  // namespace
}  // namespace scenfuzz
