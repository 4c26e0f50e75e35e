// A scenario as the search sees it: the template's parameters are the dimensions, its specs the
// objectives (or the collision oracle's `no_collision` when it has none), and evaluating a point
// means placing and planning the scenario there (rejecting it as infeasible when that fails or
// bodies overlap at t = 0), simulating it and judging the trace.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"
#include "oracle/judge.hpp"
#include "oracle/law_coverage.hpp"
#include "physics/map/map_source.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {

// One point simulated in full: what a finding is written from.
struct ScenarioRun {
  std::vector<double> values;  // parameter values at the point
  std::shared_ptr<const RoadMap> map;
  std::optional<Trace> trace;  // none when the point was infeasible
  std::vector<SpecVerdict> verdicts;
  // Whose fault each of the ego's collisions was, in the trace's order.
  std::vector<CollisionResponsibility> responsibilities;
  Conditions conditions;   // the weather and darkness it ran in (the setup's)
  std::string infeasible;  // why the point was rejected before simulating
  std::string failure;     // why it ran but could not be judged
};

// What setting a scenario up at one point says before any simulation.
struct SetupProbe {
  Diagnostics warnings;            // an ego far from every lane, ...; the evaluations keep none
  std::optional<double> duration;  // the scenario's own, s; none when the point is infeasible
};

class ScenarioEvaluator : public Evaluator {
 public:
  // `file` and `scenario` must outlive the evaluator. The map is loaded once when it has no
  // search parameters (throws MapError when it cannot be), else at every evaluation.
  // `simulation.seed` is replaced by each evaluation's seed.
  ScenarioEvaluator(const SourceFile& file, const ScenarioTemplate& scenario,
                    MapSearchPath search_path, SimulationOptions simulation);

  std::vector<SearchDimension> dimensions() const override;
  std::vector<std::string> objectives() const override;
  // A space derived around a concrete file (every dimension has an origin): its written values.
  std::optional<std::vector<double>> start_point() const override;
  // The sub-violations of the scenario's law specs (oracle/law_coverage.hpp), in their order.
  std::vector<SubTarget> sub_targets() const override;
  const std::vector<LawSubViolation>& law_sub_violations() const { return law_subs_; }
  // Throws OracleError when a spec cannot be judged on the trace (the same for every point).
  Evaluation evaluate(std::span<const double> unit_point, std::uint64_t seed) const override;

  // The same evaluation, keeping everything it produced.
  ScenarioRun run(std::span<const double> unit_point, std::uint64_t seed) const;

  // The scenario set up at `unit_point`, for what is checked and shown once before a search.
  SetupProbe probe(std::span<const double> unit_point) const;

  const ParameterSpace& space() const { return space_; }

  // How the verdicts treat collisions (--rss, --all-collisions); the defaults until set.
  void set_judge_options(JudgeOptions options) { judge_options_ = std::move(options); }
  const JudgeOptions& judge_options() const { return judge_options_; }

 private:
  // The map and the setup at run.values; nullopt with run.infeasible set when they fail.
  std::optional<SimulationSetup> set_up(ScenarioRun& run, std::uint64_t seed,
                                        Diagnostics& diagnostics) const;

  const SourceFile& file_;
  const ScenarioTemplate& scenario_;
  ParameterSpace space_;
  MapSearchPath search_path_;
  SimulationOptions simulation_;
  JudgeOptions judge_options_;
  std::shared_ptr<const RoadMap> fixed_map_;
  std::vector<LawSubViolation> law_subs_;  // worked out once: every evaluation measures them
};

// Whether an ego plugin's failure is a finding (it crashed or hung, or returned an error once
// running) rather than a plugin that could not be loaded or created at all.
bool is_finding(const EgoFailure& failure);

// The failure mode of a judged run with a violated verdict (oracle/failure_mode.hpp): the earliest
// violation's, with the responsibility of the ego's first collision; empty when nothing is
// violated.
std::string failure_mode_signature(const ScenarioRun& run);

// The failure mode the search files a run under (Evaluation::signature): for a judged run,
// failure_mode_signature; for one the ego plugin cut short (is_finding), its kind and signal.
std::string run_signature(const ScenarioRun& run);

}  // namespace scenfuzz
