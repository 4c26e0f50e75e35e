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
#include "sampler/random.hpp"

namespace scenfuzz {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One targeted objective: its strategy and what is left of its share of the budget.
struct Target {
  std::size_t objective = 0;
  std::unique_ptr<SearchStrategy> strategy;
  std::size_t remaining = 0;
  bool exhausted = false;
};

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
  std::vector<Target> targets;
  std::vector<bool> first_batch_done(objectives.size(), false);
  for (std::size_t k = 0; k < objectives.size(); ++k) {
    if (objectives[k] >= objective_count)
      throw std::invalid_argument("search target " + std::to_string(objectives[k]) +
                                  " out of range");
    Target target;
    target.objective = objectives[k];
    // Equal shares; the first targets take the remainder.
    target.remaining =
        options.budget / objectives.size() + (k < options.budget % objectives.size());
    // Each target's strategy draws from its own stream of the run seed. A concrete seed's own
    // values are the first target's first point.
    const std::optional<UnitPoint> written = k == 0 ? evaluator.start_point() : std::nullopt;
    const std::size_t strategy_budget = target.remaining - (written && target.remaining > 1);
    target.strategy =
        make_search_strategy(options.algorithm, dimensions,
                             derive_seed(options.seed, ~std::uint64_t{k}), strategy_budget);
    if (written)
      target.strategy = std::make_unique<StartPointStrategy>(*written, std::move(target.strategy));
    targets.push_back(std::move(target));
  }

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
      Target& target = targets[t];
      if (target.remaining == 0 || target.exhausted) continue;
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
        records[i].target = target.objective;
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
        observations[i].judged = evaluation.judged();
        if (evaluation.judged())
          observations[i].objective = evaluation.guide.empty()
                                          ? evaluation.robustness[target.objective]
                                          : evaluation.guide[target.objective];
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
    }
    if (!stopped && !any_left) {
      bool all_exhausted = true;
      for (const Target& target : targets)
        if (target.remaining > 0 && !target.exhausted) all_exhausted = false;
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
