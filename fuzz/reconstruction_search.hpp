// The search for one reconstruction: run_search over a ReconstructionEvaluator until a run
// reproduces the described collisions (robustness < 0) or the budget is spent. The first such
// run in evaluation order is the reconstruction, so the same seed gives the same one for any
// thread count; without one, the closest run found.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "fuzz/reconstruction_evaluator.hpp"
#include "fuzz/search.hpp"

namespace scenfuzz {

struct ReconstructionSearch {
  SearchSummary summary;
  bool reconstructed = false;
  // The reconstruction, or the run with the lowest robustness; none when no run was judged.
  std::optional<EvaluationRecord> best;
  // Simulations (judged or failed evaluations) spent up to and including the best run.
  std::size_t simulations = 0;
};

// `interrupted` is asked between batches (a stop signal); the search also stops after the batch
// in which the first reconstruction appeared.
ReconstructionSearch search_reconstruction(const ReconstructionEvaluator& evaluator,
                                           const SearchOptions& options,
                                           const std::function<bool()>& interrupted);

}  // namespace scenfuzz
