#include "fuzz/scenario_evaluator.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "fuzz/run_coverage.hpp"
#include "oracle/failure_mode.hpp"
#include "oracle/robustness.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/simulation/initial_overlap.hpp"
#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {

namespace {

bool map_has_parameters(const MapReference& map) {
  std::vector<int> parameters;
  for (const NamedValue& parameter : map.parameters)
    collect_parameters(parameter.value, parameters);
  return !parameters.empty();
}

// Whether the ends of an angle's interval are one heading: only then may a search wrap from
// one end to the other (a heading in range(25, 45) deg is not next to 45 at 25).
bool spans_one_turn(const Dimension& dimension) {
  const double turn = dimension.unit == "rad" ? 2.0 * std::numbers::pi : 360.0;
  return std::abs((dimension.upper - dimension.lower) - turn) <= 1e-9 * turn;
}

GeneKind gene_kind(const Dimension& dimension) {
  switch (dimension.kind) {
    case ParameterKind::continuous: return GeneKind::continuous;
    case ParameterKind::angle:
      return spans_one_turn(dimension) ? GeneKind::angle : GeneKind::continuous;
    case ParameterKind::discrete: return GeneKind::discrete;
  }
  return GeneKind::continuous;
}

// The first error, placed in the file ("base.avu:3:9: lane 'x' is not in map 'straight'").
std::string first_error(const SourceFile& file, const Diagnostics& diagnostics) {
  for (const Diagnostic& diagnostic : diagnostics.all()) {
    if (diagnostic.severity != Severity::error) continue;
    if (!diagnostic.location.known()) return diagnostic.message;
    return file.path() + ":" + std::to_string(diagnostic.location.line) + ":" +
           std::to_string(diagnostic.location.column) + ": " + diagnostic.message;
  }
  return "the scenario cannot be set up at this point";
}

std::string ego_failure_reason(const Trace& trace) {
  if (trace.ego_failure) return trace.ego_failure->reason;
  return trace.events.empty() ? "the ego plugin failed" : trace.events.back().message;
}

}  // namespace

bool is_finding(const EgoFailure& failure) {
  // An error before the first step is a plugin that cannot be loaded or created: a bad
  // --ego-plugin (every evaluation fails the same way), not something the scenario found.
  return !(failure.kind == EgoFailureKind::error && failure.step == 0);
}

std::string failure_mode_signature(const ScenarioRun& run) {
  const std::vector<std::size_t> order = violation_order(run.verdicts);
  if (order.empty() || !run.trace || !run.map) return "";
  const CollisionResponsibility* first =
      run.responsibilities.empty() ? nullptr : &run.responsibilities.front();
  FailureMode mode = describe_failure(*run.trace, *run.map, run.verdicts[order.front()],
                                      first ? first->danger_began : std::nullopt);
  if (first) mode.responsibility = responsibility_name(first->responsibility);
  return failure_mode_key(mode);
}

std::string run_signature(const ScenarioRun& run) {
  const bool judged = run.infeasible.empty() && run.failure.empty();
  if (judged) return failure_mode_signature(run);
  if (!run.trace || !run.trace->ego_failure || !is_finding(*run.trace->ego_failure)) return "";
  const EgoFailure& failure = *run.trace->ego_failure;
  return std::string(ego_failure_kind_name(failure.kind)) +
         (failure.signal.empty() ? "" : " " + failure.signal);
}

ScenarioEvaluator::ScenarioEvaluator(const SourceFile& file, const ScenarioTemplate& scenario,
                                     MapSearchPath search_path, SimulationOptions simulation)
    : file_(file),
      scenario_(scenario),
      space_(parameter_space(scenario)),
      search_path_(std::move(search_path)),
      simulation_(std::move(simulation)),
      law_subs_(scenfuzz::law_sub_violations(scenario)) {
  if (!map_has_parameters(scenario.map))
    fixed_map_ = std::make_shared<const RoadMap>(load_scenario_map(
        scenario.map, search_path_, std::vector<double>(space_.dimensions.size())));
}

std::vector<SearchDimension> ScenarioEvaluator::dimensions() const {
  std::vector<SearchDimension> dimensions;
  for (const Dimension& dimension : space_.dimensions) {
    SearchDimension gene;
    gene.name = dimension.name;
    gene.kind = gene_kind(dimension);
    gene.choices = dimension.choices.size();
    gene.group = dimension.name.substr(0, dimension.name.find('.'));
    dimensions.push_back(std::move(gene));
  }
  return dimensions;
}

std::optional<std::vector<double>> ScenarioEvaluator::start_point() const {
  if (space_.dimensions.empty()) return std::nullopt;
  std::vector<double> written;
  for (const Dimension& dimension : space_.dimensions) {
    if (!dimension.origin) return std::nullopt;
    written.push_back(*dimension.origin);
  }
  return encode(space_, written);
}

std::vector<SubTarget> ScenarioEvaluator::sub_targets() const {
  std::vector<SubTarget> targets;
  for (const LawSubViolation& sub : law_subs_) targets.push_back({sub.spec, sub.name});
  return targets;
}

std::vector<std::string> ScenarioEvaluator::objectives() const {
  if (scenario_.specs.empty()) return {kNoCollisionSpec};
  std::vector<std::string> names;
  for (const Spec& spec : scenario_.specs) names.push_back(spec.name);
  return names;
}

std::optional<SimulationSetup> ScenarioEvaluator::set_up(ScenarioRun& run, std::uint64_t seed,
                                                         Diagnostics& diagnostics) const {
  run.map = fixed_map_;
  if (!run.map) {
    try {
      run.map = std::make_shared<const RoadMap>(
          load_scenario_map(scenario_.map, search_path_, run.values));
    } catch (const MapError& error) {
      run.infeasible = error.what();
      return std::nullopt;
    }
  }
  std::optional<SimulationSetup> setup =
      prepare_simulation(scenario_, run.values, *run.map, seed, diagnostics);
  if (!setup) run.infeasible = first_error(file_, diagnostics);
  return setup;
}

SetupProbe ScenarioEvaluator::probe(std::span<const double> unit_point) const {
  ScenarioRun run;
  run.values = decode(space_, unit_point);
  Diagnostics diagnostics;
  SetupProbe probe;
  if (std::optional<SimulationSetup> setup = set_up(run, 0, diagnostics))
    probe.duration = setup->duration;
  for (const Diagnostic& diagnostic : diagnostics.all())
    if (diagnostic.severity == Severity::warning)
      probe.warnings.warning(diagnostic.location, diagnostic.message);
  return probe;
}

ScenarioRun ScenarioEvaluator::run(std::span<const double> unit_point, std::uint64_t seed) const {
  ScenarioRun run;
  run.values = decode(space_, unit_point);
  Diagnostics diagnostics;
  const std::optional<SimulationSetup> setup = set_up(run, seed, diagnostics);
  if (!setup) return run;
  run.conditions = setup->conditions;
  if (std::optional<std::string> overlap = initial_overlap(*setup)) {
    run.infeasible = *overlap;
    return run;
  }
  SimulationOptions options = simulation_;
  options.seed = seed;
  try {
    run.trace = simulate(*run.map, *setup, options);
  } catch (const std::exception& error) {
    // One point the simulation cannot run costs that evaluation, not the search and its output.
    run.failure = std::string("the simulation failed: ") + error.what();
    return run;
  }
  if (run.trace->end == EndReason::ego_failure) {
    // A trace cut short by the driver under test says nothing about its specs.
    run.failure = ego_failure_reason(*run.trace);
    return run;
  }
  run.verdicts = judge_trace(scenario_, run.values, *run.trace, *run.map, file_, judge_options_);
  // A spec the trace cannot answer cannot be searched on (run_fuzz leaves out beforehand those
  // known not to be judgeable): the search stops with the reason, as before.
  for (const SpecVerdict& verdict : run.verdicts)
    if (!verdict.judged()) throw OracleError(verdict.not_judged_at, verdict.not_judged);
  run.responsibilities = ego_collision_responsibilities(*run.trace, *run.map, judge_options_.rss);
  return run;
}

Evaluation ScenarioEvaluator::evaluate(std::span<const double> unit_point,
                                       std::uint64_t seed) const {
  const ScenarioRun run = this->run(unit_point, seed);
  Evaluation evaluation;
  evaluation.infeasible = run.infeasible;
  evaluation.failure = run.failure;
  if (run.trace) {
    const TraceAudit audit = audit_trace(*run.trace, *run.map);
    evaluation.audit.assign(audit.counts.begin(), audit.counts.end());
  }
  RunCoverage coverage = run_coverage(run, scenario_, law_subs_);
  evaluation.coverage = std::move(coverage.features);
  evaluation.sub_robustness = std::move(coverage.law_robustness);
  if (run.trace && run.trace->ego_failure && is_finding(*run.trace->ego_failure)) {
    const EgoFailure& failure = *run.trace->ego_failure;
    evaluation.failure_kind = ego_failure_kind_name(failure.kind);
    evaluation.signature = run_signature(run);
  }
  if (!evaluation.judged()) return evaluation;
  for (const SpecVerdict& verdict : run.verdicts) {
    // --violation-at-zero: a violated 0 enters the search as the largest number below 0, which
    // the search's "robustness < 0" counts as the violation it is.
    const bool zero_violated = verdict.violated() && verdict.robustness == 0;
    const double below_zero = -std::numeric_limits<double>::denorm_min();
    evaluation.robustness.push_back(zero_violated ? below_zero : verdict.robustness);
    evaluation.guide.push_back(zero_violated && verdict.guide >= 0 ? below_zero : verdict.guide);
  }
  for (std::size_t k = 0; k < run.verdicts.size(); ++k) {
    if (run.verdicts[k].ending == VerdictEnding::decided) continue;
    evaluation.endings.resize(run.verdicts.size());
    evaluation.endings[k] = verdict_ending_name(run.verdicts[k].ending);
  }
  evaluation.violated = violation_order(run.verdicts);
  if (!run.responsibilities.empty()) {
    evaluation.responsibility = responsibility_name(run.responsibilities.front().responsibility);
    evaluation.collision_reason = run.responsibilities.front().reason;
  }
  evaluation.signature = run_signature(run);
  return evaluation;
}

}  // namespace scenfuzz
