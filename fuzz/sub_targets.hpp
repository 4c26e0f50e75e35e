// The budget of a search that targets law sub-violations (--target sub-violations), as
// LawBreaker spends it: a sub-violation's target is dropped once any evaluation reaches it
// (robustness >= 0 at the trace's start), and what it had left is shared among the targets still
// unreached; once none is, among the law specs' own targets. Plain structs and free functions,
// so that the search loop (search.cpp) stays one loop; everything here runs between batches in
// index order, so the plan is the same for any -j and when a journal is replayed.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fuzz/evaluator.hpp"

namespace scenfuzz {

// What one target of the search aims at, before its strategy exists.
struct TargetPlan {
  std::size_t id = 0;              // EvaluationRecord::target
  std::optional<std::size_t> sub;  // the sub-target's index, when it is one
  std::size_t objective = 0;       // the spec whose robustness (or sub-violation) it reads
};

// The targets for `objectives` (indices into the evaluator's objectives): each objective as
// itself, or, with `by_sub_violation`, each law spec as its sub-targets (`subs`).
std::vector<TargetPlan> plan_targets(std::span<const std::size_t> objectives,
                                     std::span<const SubTarget> subs, std::size_t objective_count,
                                     bool by_sub_violation);

// Marks in `reached` (one per sub-target) the sub-violations `evaluation` reached; true when one
// was not marked before.
bool mark_reached(const Evaluation& evaluation, std::vector<bool>& reached);

// What the strategy of `plan` minimises for a judged `evaluation`: the objective's guide (or
// robustness), or minus its sub-violation's robustness (reached at <= 0); nullopt when the
// evaluation says nothing of it (not judged, or no trace to measure the sub-violation on).
std::optional<double> target_objective(const TargetPlan& plan, const Evaluation& evaluation);

// `freed` evaluations shared out over `shares` (the receivers' budgets) equally, the first
// receivers taking the remainder.
void share_budget(std::size_t freed, std::span<std::size_t*> shares);

}  // namespace scenfuzz
