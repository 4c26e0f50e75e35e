// The search for one reconstruction (reconstruction_search.hpp).
#include "fuzz/reconstruction_search.hpp"

namespace scenfuzz {

ReconstructionSearch search_reconstruction(const ReconstructionEvaluator& evaluator,
                                           const SearchOptions& options,
                                           const std::function<bool()>& interrupted) {
  ReconstructionSearch result;
  std::size_t simulations = 0;
  SearchCallbacks callbacks;
  callbacks.on_evaluation = [&](const EvaluationRecord& record) {
    if (!record.evaluation.feasible()) return;
    ++simulations;
    if (result.reconstructed || record.evaluation.robustness.empty()) return;
    const double robustness = record.evaluation.robustness.front();
    if (result.best && robustness >= result.best->evaluation.robustness.front()) return;
    result.best = record;
    result.simulations = simulations;
    result.reconstructed = robustness < 0;
  };
  callbacks.interrupted = [&] { return result.reconstructed || (interrupted && interrupted()); };
  result.summary = run_search(evaluator, options, callbacks);
  return result;
}

}  // namespace scenfuzz
