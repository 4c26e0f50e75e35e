// Accident reconstruction as a search problem (reconstruction_evaluator.hpp).
#include "fuzz/reconstruction_evaluator.hpp"

namespace scenfuzz {

namespace {

// The whole accident, however many collisions it takes: a run does not end at the first, and
// the vehicles an impact throws on carry on into the next.
SimulationOptions through_collisions(SimulationOptions options) {
  options.stop_at_collision = false;
  options.slide_after_impact = true;
  return options;
}

}  // namespace

ReconstructionEvaluator::ReconstructionEvaluator(const SourceFile& file,
                                                 const ScenarioTemplate& scenario,
                                                 MapSearchPath search_path,
                                                 SimulationOptions simulation)
    : scenario_(scenario),
      runner_(file, scenario, std::move(search_path), through_collisions(std::move(simulation))) {}

ReconstructionRun ReconstructionEvaluator::reconstruct(std::span<const double> unit_point,
                                                       std::uint64_t seed) const {
  ReconstructionRun result{runner_.run(unit_point, seed), std::nullopt};
  if (result.run.trace && result.run.failure.empty())
    result.score =
        score_reconstruction(*result.run.trace, scenario_.expected_collisions, result.run.values);
  return result;
}

Evaluation ReconstructionEvaluator::evaluate(std::span<const double> unit_point,
                                             std::uint64_t seed) const {
  const ReconstructionRun result = reconstruct(unit_point, seed);
  Evaluation evaluation;
  evaluation.infeasible = result.run.infeasible;
  evaluation.failure = result.run.failure;
  if (!result.score) return evaluation;
  evaluation.robustness = {result.score->robustness};
  if (result.score->robustness < 0) {
    evaluation.violated = {0};
    evaluation.signature = kReconstructionObjective;
  }
  return evaluation;
}

}  // namespace scenfuzz
