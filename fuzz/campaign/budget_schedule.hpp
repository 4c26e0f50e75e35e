// How a campaign run shares its budget over its arms (seed x spec) round by round: a pure
// function of the complete earlier rounds of the run, so that the same database gives the same
// next round whatever the number of workers, and a killed run re-plans its current round exactly.
// The rule, after AFL++'s power schedules (energy to what is still productive) and ClusterFuzz's
// strategy selection (more trials to what found crashes, some to the rest), is documented in
// docs/campaigns.md ("Sharing the budget").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace scenfuzz {

// Every search gets at least this many simulations (two GA generations of 16), unless the whole
// budget is smaller.
inline constexpr std::uint64_t kMinSearchBudget = 32;

// What one arm's search did in one complete round; `ran` false when it sat the round out.
struct ArmRound {
  bool ran = false;
  std::uint64_t spent = 0;     // simulations (judged and failed; infeasible points are free)
  std::size_t new_modes = 0;   // failure modes unknown to the campaign before this search
  std::optional<double> best;  // lowest robustness of its spec; none when nothing was judged
};

struct ScheduleInput {
  std::vector<double> weights;                // per arm, > 0: [[seed]] budget_share / its specs
  std::vector<std::vector<ArmRound>> rounds;  // complete earlier rounds, each one entry per arm
  std::optional<std::uint64_t> total;         // [budget] simulations; none: wall time only
};

// How eager an arm is, from its history: 1 before it ran; 2 when its last search found a new
// failure mode; 1 when its last search lowered its best robustness (or was its first); else
// halved for each consecutive unproductive search, at least 1/8.
double arm_energy(const std::vector<std::vector<ArmRound>>& rounds, std::size_t arm);

// Simulations spent over the given rounds.
std::uint64_t spent_simulations(const std::vector<std::vector<ArmRound>>& rounds);

// The next round's budget per arm (0: it sits the round out). All zero when the run is over: the
// remaining simulations are fewer than a minimal search, or the last round spent none.
std::vector<std::uint64_t> plan_round(const ScheduleInput& input);

}  // namespace scenfuzz
