#include "fuzz/search.hpp"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>

#include "fuzz/search_strategy.hpp"
#include "fuzz/start_point_strategy.hpp"
#include "fuzz/sub_targets.hpp"
#include "sampler/random.hpp"

namespace scenfuzz {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One target: what it aims at, its strategy and what is left of its share of the budget.
struct Target {
  TargetPlan plan;
  std::unique_ptr<SearchStrategy> strategy;
  std::size_t remaining = 0;
  bool exhausted = false;
  bool dropped = false;  // its sub-violation was reached: its budget went to the others
};

// A target with `budget` evaluations whose strategy draws from stream `stream` of the run seed;
// `written` (a concrete seed's own values) is its first point.
Target make_target(const TargetPlan& plan, const SearchOptions& options,
                   const std::vector<SearchDimension>& dimensions, std::size_t stream,
                   std::size_t budget, const std::optional<UnitPoint>& written) {
  Target target;
  target.plan = plan;
  target.remaining = budget;
  const std::size_t strategy_budget = std::max<std::size_t>(budget - (written && budget > 1), 1);
  target.strategy =
      make_search_strategy(options.algorithm, dimensions,
                           derive_seed(options.seed, ~std::uint64_t{stream}), strategy_budget);
  if (written)
    target.strategy = std::make_unique<StartPointStrategy>(*written, std::move(target.strategy));
  return target;
}

// New targets for the law specs `objectives` themselves, sharing `budget`; their strategies take
// the next streams of the seed.
void add_law_targets(std::vector<Target>& targets, const std::vector<std::size_t>& objectives,
                     std::size_t budget, const SearchOptions& options,
                     const std::vector<SearchDimension>& dimensions) {
  for (std::size_t k = 0; k < objectives.size(); ++k) {
    const std::size_t share = budget / objectives.size() + (k < budget % objectives.size());
    const TargetPlan plan{objectives[k], std::nullopt, objectives[k]};
    targets.push_back(make_target(plan, options, dimensions, targets.size(), share, std::nullopt));
  }
}

// Drops the targets whose sub-violation is reached and shares out their budgets: among the
// sub-targets still unreached; once none is, the rest searches the law specs themselves.
void drop_reached(std::vector<Target>& targets, const std::vector<bool>& reached,
                  const SearchOptions& options, const std::vector<SearchDimension>& dimensions) {
  std::size_t freed = 0;
  std::vector<std::size_t> laws;  // the specs of the dropped targets
  for (Target& target : targets) {
    if (!target.plan.sub || target.dropped || !reached[*target.plan.sub]) continue;
    target.dropped = true;
    freed += target.remaining;
    target.remaining = 0;
    if (std::find(laws.begin(), laws.end(), target.plan.objective) == laws.end())
      laws.push_back(target.plan.objective);
  }
  if (freed == 0) return;
  std::vector<std::size_t*> unreached, law_targets;
  for (Target& target : targets) {
    if (target.exhausted || target.dropped) continue;
    if (target.plan.sub) unreached.push_back(&target.remaining);
    if (!target.plan.sub &&
        std::find(laws.begin(), laws.end(), target.plan.objective) != laws.end())
      law_targets.push_back(&target.remaining);
  }
  if (!unreached.empty()) return share_budget(freed, unreached);
  if (!law_targets.empty()) return share_budget(freed, law_targets);
  add_law_targets(targets, laws, freed, options, dimensions);
}

}  // namespace

std::string_view stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::budget: return "budget";
    case StopReason::time_limit: return "time_limit";
    case StopReason::interrupted: return "interrupted";
    case StopReason::infeasible: return "infeasible";
    case StopReason::exhausted: return "exhausted";
    case StopReason::error: return "error";
  }
  return "budget";
}

SearchSummary run_search(const Evaluator& evaluator, const SearchOptions& options,
                         const SearchCallbacks& callbacks) {
  const Clock::time_point start = Clock::now();
  const std::vector<SearchDimension> dimensions = evaluator.dimensions();
  const std::size_t objective_count = evaluator.objectives().size();

  std::vector<std::size_t> objectives = options.targets;
  if (objectives.empty())
    for (std::size_t i = 0; i < objective_count; ++i) objectives.push_back(i);
  for (std::size_t objective : objectives)
    if (objective >= objective_count)
      throw std::invalid_argument("search target " + std::to_string(objective) + " out of range");
  const std::vector<SubTarget> subs = evaluator.sub_targets();
  const std::vector<TargetPlan> plans =
      plan_targets(objectives, subs, objective_count, options.sub_violation_targets);
  std::vector<Target> targets;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    // Equal shares; the first targets take the remainder. A concrete seed's own values are the
    // first target's first point.
    const std::size_t budget = options.budget / plans.size() + (k < options.budget % plans.size());
    targets.push_back(make_target(plans[k], options, dimensions, k, budget,
                                  k == 0 ? evaluator.start_point() : std::nullopt));
  }
  std::vector<bool> first_batch_done(targets.size(), false);
  std::vector<bool> reached(subs.size(), false);

  const int threads =
      options.jobs == 0 ? tbb::info::default_concurrency() : static_cast<int>(options.jobs);
  tbb::task_arena arena(threads);
  const std::size_t batch_size = std::max<std::size_t>(options.batch, 1);
  const std::size_t infeasible_limit =
      options.infeasible_factor * std::max<std::size_t>(options.budget, 1);

  SearchSummary summary;
  summary.stop = StopReason::budget;
  std::size_t next_index = 0;
  bool stopped = false;
  while (!stopped) {
    bool any_left = false;
    // Round robin over the targets, one batch each.
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (t >= first_batch_done.size()) first_batch_done.resize(targets.size(), false);
      Target& target = targets[t];
      if (target.remaining == 0 || target.exhausted || target.dropped) continue;
      if (callbacks.interrupted && callbacks.interrupted()) {
        summary.stop = StopReason::interrupted;
        stopped = true;
        break;
      }
      if (options.time_limit > 0 && seconds_since(start) >= options.time_limit) {
        summary.stop = StopReason::time_limit;
        stopped = true;
        break;
      }
      if (summary.infeasible >= infeasible_limit) {
        summary.stop = StopReason::infeasible;
        stopped = true;
        break;
      }
      const std::vector<UnitPoint> points =
          target.strategy->propose(std::min(batch_size, target.remaining));
      if (points.empty()) {
        target.exhausted = true;
        continue;
      }
      any_left = true;
      std::vector<EvaluationRecord> records(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) {
        records[i].index = next_index + i;
        records[i].seed = derive_seed(options.seed, records[i].index);
        records[i].target = target.plan.id;
        records[i].point = points[i];
        records[i].first_design = !first_batch_done[t];
      }
      first_batch_done[t] = true;
      next_index += points.size();
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, records.size(), 1),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                              const Clock::time_point began = Clock::now();
                              records[i].evaluation =
                                  evaluator.evaluate(records[i].point, records[i].seed);
                              records[i].evaluation.wall_seconds = seconds_since(began);
                            }
                          });
      });

      std::vector<Observation> observations(records.size());
      for (std::size_t i = 0; i < records.size(); ++i) {
        const Evaluation& evaluation = records[i].evaluation;
        observations[i].point = records[i].point;
        const std::optional<double> objective = target_objective(target.plan, evaluation);
        observations[i].judged = objective.has_value();
        if (objective) observations[i].objective = *objective;
        mark_reached(evaluation, reached);
        ++summary.evaluations;
        if (!evaluation.feasible()) {
          ++summary.infeasible;
        } else {
          evaluation.judged() ? ++summary.judged : ++summary.failed;
          --target.remaining;  // the batch never exceeds what is left
        }
        if (callbacks.on_evaluation) callbacks.on_evaluation(records[i]);
      }
      if (callbacks.on_batch_end) callbacks.on_batch_end();
      target.strategy->observe(observations);
      // After the batch, in index order: the same plan for any -j and on a replayed journal.
      if (options.sub_violation_targets) drop_reached(targets, reached, options, dimensions);
    }
    if (!stopped && !any_left) {
      bool all_exhausted = true;
      for (const Target& target : targets)
        if (target.remaining > 0 && !target.exhausted && !target.dropped) all_exhausted = false;
      summary.stop = all_exhausted && std::any_of(targets.begin(), targets.end(),
                                                  [](const Target& t) { return t.remaining > 0; })
                         ? StopReason::exhausted
                         : StopReason::budget;
      stopped = true;
    }
  }
  summary.wall_seconds = seconds_since(start);
  return summary;
}

}  // namespace scenfuzz
