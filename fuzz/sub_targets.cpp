// Sub-violation targets: planning, reached sub-violations and the objective a strategy sees.
#include "fuzz/sub_targets.hpp"

namespace scenfuzz {

std::vector<TargetPlan> plan_targets(std::span<const std::size_t> objectives,
                                     std::span<const SubTarget> subs, std::size_t objective_count,
                                     bool by_sub_violation) {
  std::vector<TargetPlan> plans;
  for (std::size_t objective : objectives) {
    bool has_subs = false;
    if (by_sub_violation)
      for (std::size_t j = 0; j < subs.size(); ++j)
        if (subs[j].objective == objective) {
          plans.push_back({objective_count + j, j, objective});
          has_subs = true;
        }
    // A spec that is no law (or one too large to expand) is searched as itself.
    if (!has_subs) plans.push_back({objective, std::nullopt, objective});
  }
  return plans;
}

bool mark_reached(const Evaluation& evaluation, std::vector<bool>& reached) {
  bool news = false;
  for (std::size_t j = 0; j < evaluation.sub_robustness.size() && j < reached.size(); ++j)
    if (evaluation.sub_robustness[j] >= 0 && !reached[j]) {
      reached[j] = true;
      news = true;
    }
  return news;
}

std::optional<double> target_objective(const TargetPlan& plan, const Evaluation& evaluation) {
  if (!evaluation.judged()) return std::nullopt;
  if (plan.sub) {
    if (*plan.sub >= evaluation.sub_robustness.size()) return std::nullopt;
    return -evaluation.sub_robustness[*plan.sub];
  }
  return evaluation.guide.empty() ? evaluation.robustness[plan.objective]
                                  : evaluation.guide[plan.objective];
}

void share_budget(std::size_t freed, std::span<std::size_t*> shares) {
  if (shares.empty()) return;
  for (std::size_t k = 0; k < shares.size(); ++k)
    *shares[k] += freed / shares.size() + (k < freed % shares.size());
}

}  // namespace scenfuzz
