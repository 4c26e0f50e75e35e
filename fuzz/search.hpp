// The search loop (the whole of it, as libFuzzer's FuzzerLoop): ask the strategies for batches of
// points, evaluate each batch in parallel, hand the results back in proposal order, report every
// evaluation, and stop at the budget, the time limit or an interrupt.
//
// Determinism: evaluation i is seeded with derive_seed(seed, i), batches have a fixed size that
// does not depend on the thread count, and results are fed back and reported in index order, so
// the same seed gives the same evaluations, and so the same findings, for any number of threads
// (a time limit or an interrupt may cut the run at a different place).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "sampler/point_samplers.hpp"

namespace scenfuzz {

struct SearchOptions {
  std::string algorithm = "ga";  // see search_algorithm_names()
  std::size_t budget = 500;      // judged and failed evaluations; infeasible points are free
  double time_limit = 0;         // seconds of wall time; 0: none
  std::uint64_t seed = 0;
  std::size_t jobs = 0;  // worker threads; 0: all cores
  // The objectives the search targets (indices into Evaluator::objectives()); empty: all of them,
  // each with its own strategy and an equal share of the budget. Every evaluation is judged on
  // every objective whatever its target.
  std::vector<std::size_t> targets;
  // --target sub-violations: each targeted law spec is searched as one target per law
  // sub-violation (Evaluator::sub_targets(), objective -robustness: reached at <= 0), as
  // LawBreaker does; a target is dropped once any evaluation reaches its sub-violation and its
  // budget goes to the unreached ones (fuzz/sub_targets.hpp). Findings are the specs' as ever.
  bool sub_violation_targets = false;
  std::size_t batch = 16;  // points handed out at once; fixed, so that -j never changes results
  // The search gives up when this many times the budget of proposed points were infeasible.
  std::size_t infeasible_factor = 20;
};

struct EvaluationRecord {
  std::size_t index = 0;   // in proposal order, from 0
  std::uint64_t seed = 0;  // derive_seed(options.seed, index)
  // What the strategy that proposed the point targets: an objective, or for sub-violation j of
  // Evaluator::sub_targets(), objectives().size() + j.
  std::size_t target = 0;
  UnitPoint point;
  Evaluation evaluation;
  // Whether the point is of its target's first batch (the GA's first generation, a sampler's
  // first points): the survey a spec's violation rate is measured on.
  bool first_design = false;
};

// error: the caller stopped the search because it could not record it (a full disk); the search
// itself never returns it.
enum class StopReason { budget, time_limit, interrupted, infeasible, exhausted, error };

struct SearchSummary {
  std::size_t evaluations = 0;  // proposed and evaluated, infeasible ones included
  std::size_t judged = 0;
  std::size_t failed = 0;
  std::size_t infeasible = 0;
  double wall_seconds = 0;
  StopReason stop = StopReason::budget;
};

struct SearchCallbacks {
  // Every evaluation, in index order, on the thread that called run_search.
  std::function<void(const EvaluationRecord&)> on_evaluation;
  // After each batch's on_evaluation calls: where a journal makes the batch durable.
  std::function<void()> on_batch_end;
  // Asked between batches: true ends the search (SIGINT, SIGTERM, a failed write).
  std::function<bool()> interrupted;
};

// Runs the search. Exceptions from the evaluator (a spec the oracle cannot judge) propagate.
// Throws std::invalid_argument for an unknown algorithm or a target out of range.
SearchSummary run_search(const Evaluator& evaluator, const SearchOptions& options,
                         const SearchCallbacks& callbacks);

std::string_view stop_reason_name(StopReason reason);

}  // namespace scenfuzz
