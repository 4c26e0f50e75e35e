// An accident's reconstruction as a search problem: the accident template's unknowns (speeds,
// start distances, event timings) are the dimensions, and its one objective is the described
// collisions' robustness (oracle/collision_reconstruction.hpp), negative exactly when a run
// reproduces them. The run goes on after a collision, since an accident may be a chain of them.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "oracle/collision_reconstruction.hpp"

namespace scenfuzz {

inline constexpr const char* kReconstructionObjective = "reconstruction";

// One point simulated and scored in full: what a reconstruction is written from.
struct ReconstructionRun {
  ScenarioRun run;
  std::optional<ReconstructionScore> score;  // none when the run was infeasible or failed
};

class ReconstructionEvaluator : public Evaluator {
 public:
  // `file` and `scenario` (an accident description's, with expected collisions) must outlive it.
  ReconstructionEvaluator(const SourceFile& file, const ScenarioTemplate& scenario,
                          MapSearchPath search_path, SimulationOptions simulation);

  std::vector<SearchDimension> dimensions() const override { return runner_.dimensions(); }
  std::vector<std::string> objectives() const override { return {kReconstructionObjective}; }
  Evaluation evaluate(std::span<const double> unit_point, std::uint64_t seed) const override;

  ReconstructionRun reconstruct(std::span<const double> unit_point, std::uint64_t seed) const;
  const ParameterSpace& space() const { return runner_.space(); }

 private:
  const ScenarioTemplate& scenario_;
  ScenarioEvaluator runner_;
};

}  // namespace scenfuzz
