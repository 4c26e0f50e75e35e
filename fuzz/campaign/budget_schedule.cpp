// plan_round and the energies behind it; docs/campaigns.md ("Sharing the budget") states the
// rule in words, and tests/campaign/budget_schedule_test.cpp pins it.
#include "fuzz/campaign/budget_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

// An arm's search was productive when it found a new failure mode or lowered the arm's best
// robustness below every earlier round's (its first search always counts as lowering it).
bool productive(const std::vector<std::vector<ArmRound>>& rounds, std::size_t round,
                std::size_t arm) {
  const ArmRound& now = rounds[round][arm];
  if (now.new_modes > 0) return true;
  std::optional<double> before;
  for (std::size_t k = 0; k < round; ++k)
    if (const std::optional<double>& best = rounds[k][arm].best)
      before = before ? std::min(*before, *best) : *best;
  if (!now.best) return false;
  return !before || *now.best < *before;
}

// The smallest search the budget affords.
std::uint64_t minimum_search(const ScheduleInput& input) {
  return input.total ? std::min(kMinSearchBudget, *input.total) : kMinSearchBudget;
}

// The round's simulations: a quarter of the budget, but enough for a minimal search per arm,
// and never more than what is left. Without a simulation budget: two minimal searches per arm.
std::uint64_t round_size(const ScheduleInput& input, std::uint64_t remaining) {
  const std::uint64_t minimum = minimum_search(input);
  const std::uint64_t arms = input.weights.size();
  if (!input.total) return 2 * minimum * arms;
  return std::min(remaining, std::max(minimum * arms, (*input.total + 3) / 4));
}

// Splits `size` over `arms` in proportion to `scores`, by largest remainder (ties to the
// earlier arm), so that the shares add up to `size` exactly.
void share_out(std::uint64_t size, const std::vector<std::size_t>& arms,
               const std::vector<double>& scores, std::vector<std::uint64_t>& budgets) {
  double sum = 0;
  for (std::size_t arm : arms) sum += scores[arm];
  std::uint64_t given = 0;
  std::vector<std::pair<double, std::size_t>> remainders;
  for (std::size_t arm : arms) {
    const double exact = static_cast<double>(size) * scores[arm] / sum;
    budgets[arm] = static_cast<std::uint64_t>(std::floor(exact));
    given += budgets[arm];
    remainders.emplace_back(exact - std::floor(exact), arm);
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; given < size; ++i, ++given) ++budgets[remainders[i % arms.size()].second];
}

}  // namespace

double arm_energy(const std::vector<std::vector<ArmRound>>& rounds, std::size_t arm) {
  int unproductive = 0;
  for (std::size_t k = rounds.size(); k-- > 0;) {
    if (!rounds[k][arm].ran) continue;
    if (rounds[k][arm].new_modes > 0 && unproductive == 0) return 2;
    if (productive(rounds, k, arm)) break;
    ++unproductive;
  }
  return std::max(1.0 / 8, std::pow(0.5, unproductive));
}

std::uint64_t spent_simulations(const std::vector<std::vector<ArmRound>>& rounds) {
  std::uint64_t spent = 0;
  for (const std::vector<ArmRound>& round : rounds)
    for (const ArmRound& arm : round) spent += arm.spent;
  return spent;
}

std::vector<std::uint64_t> plan_round(const ScheduleInput& input) {
  const std::size_t arms = input.weights.size();
  std::vector<std::uint64_t> budgets(arms, 0);
  for (const std::vector<ArmRound>& round : input.rounds) SCENFUZZ_DEMAND(round.size() == arms);
  if (arms == 0) return budgets;
  if (!input.rounds.empty() && spent_simulations({input.rounds.back()}) == 0) return budgets;
  const std::uint64_t spent = spent_simulations(input.rounds);
  const std::uint64_t remaining = input.total ? *input.total - std::min(*input.total, spent) : 0;
  const std::uint64_t minimum = minimum_search(input);
  if (input.total && remaining < minimum) return budgets;
  const std::uint64_t size = round_size(input, remaining);

  std::vector<double> scores(arms);
  for (std::size_t arm = 0; arm < arms; ++arm) {
    SCENFUZZ_DEMAND(input.weights[arm] > 0);
    scores[arm] = input.weights[arm] * arm_energy(input.rounds, arm);
  }
  // The arms by score, the earlier first on ties; the least eager leave the round while their
  // share would be smaller than a minimal search.
  std::vector<std::size_t> order(arms);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  double sum = 0;
  for (std::size_t arm : order) sum += scores[arm];
  while (order.size() > 1 &&
         static_cast<double>(size) * scores[order.back()] / sum < static_cast<double>(minimum)) {
    sum -= scores[order.back()];
    order.pop_back();
  }
  std::sort(order.begin(), order.end());
  share_out(size, order, scores, budgets);
  return budgets;
}

}  // namespace scenfuzz
