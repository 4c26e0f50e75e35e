// `scenfuzz [--budget N] FILE`: the main job. Searches the scenario's parameter space for points
// that violate its specs or make the ego under test fail, writes every (de-duplicated) finding as
// a concrete, replayable scenario with its trace and picture, and journals every evaluation so
// that a killed search can be resumed (--resume) to exactly the findings of an uninterrupted one.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/findings_tmin.hpp"
#include "fuzz/folder_search.hpp"
#include "fuzz/journal_replay.hpp"
#include "fuzz/not_judged_specs.hpp"
#include "fuzz/options.hpp"
#include "fuzz/output_folder.hpp"
#include "fuzz/progress_report.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/scenario_language.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_outputs.hpp"
#include "fuzz/search_strategy.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "oracle/actor_interaction.hpp"
#include "oracle/robustness.hpp"
#include "oracle/trace_audit.hpp"
#include "sampler/mutation_space.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;

std::optional<ScenarioEvaluator> make_evaluator(const FuzzCommandOptions& options,
                                                const ScenarioFile& input, std::ostream& err) {
  const SimulationCommandOptions& flags = options.simulation;
  SimulationOptions simulation = simulation_options(flags);
  std::optional<ScenarioEvaluator> evaluator;
  try {
    std::vector<fs::path> map_paths(flags.map_paths.begin(), flags.map_paths.end());
    evaluator.emplace(input.file, input.scenario, map_search_path(map_paths), simulation);
    evaluator->set_judge_options(judge_options(flags));
  } catch (const MapError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return std::nullopt;
  }
  if (evaluator->space().dimensions.empty()) {
    err << "scenfuzz: error: '" << options.path
        << "' has neither parameter ranges nor values to mutate (--mutate): there is nothing to "
           "search (simulate it with 'scenfuzz run')\n";
    return std::nullopt;
  }
  return evaluator;
}

// The search's options, or nullopt after a usage error on `err` (an unknown --spec or --algo).
std::optional<SearchOptions> search_options(const FuzzCommandOptions& options,
                                            const Evaluator& evaluator, std::ostream& err) {
  SCENFUZZ_DEMAND(options.budget > 0);  // the command line checks it
  const std::vector<std::string> objectives = evaluator.objectives();
  SearchOptions search = search_plan(options);
  for (const std::string& name : options.specs) {
    auto found = std::find(objectives.begin(), objectives.end(), name);
    if (found == objectives.end()) {
      std::string names;
      for (const std::string& objective : objectives)
        names += (names.empty() ? "" : ", ") + objective;
      err << "scenfuzz: error: '" << options.path << "' has no spec named '" << name
          << "'; its specs are: " << names << "\n";
      return std::nullopt;
    }
    search.targets.push_back(static_cast<std::size_t>(found - objectives.begin()));
  }
  try {
    (void)make_search_strategy(options.algorithm, evaluator.dimensions(), 0, options.budget);
  } catch (const std::invalid_argument& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return std::nullopt;
  }
  return search;
}

// Checks what setting the scenario up at the centre of its space says: its warnings (an ego far
// from every lane) are shown once, and its own duration must fit --dt (the command line could not
// know it); a --duration shorter than a spec reads is warned of. False after an error on `err`.
bool check_setup(const FuzzCommandOptions& options, const ScenarioFile& input,
                 const ScenarioEvaluator& evaluator, std::ostream& err) {
  const SetupProbe probe =
      evaluator.probe(std::vector<double>(evaluator.space().dimensions.size(), 0.5));
  err << format_diagnostics(input.file, probe.warnings);
  for (const std::string& warning : duration_warnings(options.simulation, input.scenario.specs))
    err << "scenfuzz: warning: " << warning << "\n";
  if (options.simulation.duration || !probe.duration) return true;
  const std::optional<std::string> problem =
      check_step_count(*probe.duration, options.simulation.dt,
                       "the scenario's duration of " + format_number(*probe.duration) + " s");
  if (problem) err << "scenfuzz: error: " << *problem << "\n";
  return !problem;
}

// Simulates the search's first point (a concrete seed's values, else the centre of the space) once:
// actors that never come near the ego's path there, a layout read otherwise than the author meant,
// are warned of before the budget is spent on a space where nothing can fail.
void warn_if_actors_never_interact(const ScenarioEvaluator& evaluator, std::uint64_t seed,
                                   std::ostream& err) {
  const std::vector<double> point = evaluator.start_point().value_or(
      std::vector<double>(evaluator.space().dimensions.size(), 0.5));
  ScenarioRun run;
  try {
    run = evaluator.run(point, seed);
  } catch (const OracleError&) {
    return;  // a spec the traces cannot answer: the search stops with the reason
  }
  if (!run.trace) return;
  const std::string warning = no_interaction_warning(*run.trace, actor_approaches(*run.trace));
  if (!warning.empty())
    err << "scenfuzz: warning: at "
        << (evaluator.start_point() ? "the seed's values" : "the centre of the space") << ", "
        << warning << "\n";
}

std::string finding_line(const Finding& finding) {
  std::string line = "  " + finding_number_text(finding.number) + " ";
  if (finding.ego_failure()) return line + finding.objective_name + ": " + finding.failure;
  line += finding.objective_name + " robustness " +
          format_number(std::round(finding.robustness * 1e6) / 1e6);
  if (!finding.ending.empty()) line += " " + finding.ending;
  line += ", " + std::to_string(finding.count) +
          (finding.count == 1 ? " evaluation" : " evaluations") + ": " + finding.mode;
  if (!finding.responsibility.empty())
    line +=
        "\n      " + responsibility_words(finding.responsibility) + ": " + finding.collision_reason;
  return line;
}

// "audit: 64 of 300 simulations had actors that no real road user would be (off_road 64, ...)".
std::string audit_line(const SearchOutputs& outputs, const SearchSummary& summary) {
  std::string kinds;
  for (std::size_t k = 0; k < outputs.audit_totals().size(); ++k)
    if (outputs.audit_totals()[k] > 0)
      kinds += (kinds.empty() ? "" : ", ") +
               std::string(audit_kind_name(static_cast<AuditKind>(k))) + " " +
               std::to_string(outputs.audit_totals()[k]);
  return "audit: " + std::to_string(outputs.audited_with_issues()) + " of " +
         std::to_string(summary.judged + summary.failed) +
         " simulations had actors that moved as no road user does (" + kinds + "; docs/oracle.md)";
}

// "collisions of the ego: 12 its fault, 3 shared, 40 not its fault (...)"; empty without any.
std::string collisions_line(const SearchOutputs& outputs) {
  const CollisionCounts& counts = outputs.collisions();
  if (counts.ego + counts.shared + counts.other == 0) return "";
  std::string line =
      "collisions of the ego in " + std::to_string(counts.ego + counts.shared + counts.other) +
      " simulations: " + std::to_string(counts.ego) + " its fault, " +
      std::to_string(counts.shared) + " shared, " + std::to_string(counts.other) + " not its fault";
  if (counts.other > 0 && counts.not_counted)
    line += " (those are not findings without specs; --all-collisions counts them)";
  return line;
}

// --tmin's outcome per finding number.
using Minimised = std::map<std::size_t, TminJobResult>;

// "  SPEC: N WHAT" for each objective with evaluations of an ending that is no finding.
void count_lines(std::ostream& out, const std::vector<std::string>& objectives,
                 const std::vector<std::size_t>& counts, const char* what) {
  for (std::size_t k = 0; k < objectives.size() && k < counts.size(); ++k)
    if (counts[k] > 0) out << "  " << objectives[k] << ": " << counts[k] << what << "\n";
}

void print_report(const FuzzCommandOptions& options, const SearchSummary& summary,
                  const SearchOutputs& outputs, const FindingLog& log,
                  const std::vector<std::string>& objectives, const Minimised& minimised,
                  std::ostream& out) {
  if (options.json) {
    out << nlohmann::json{{"event", "summary"}, {"summary", outputs.summary(summary, log, true)}}
               .dump()
        << "\n";
    return;
  }
  if (options.quiet) return;
  out << summary.judged << " simulations (" << summary.infeasible << " infeasible points skipped, "
      << summary.failed << " failed) in "
      << format_number(std::round(summary.wall_seconds * 10) / 10)
      << " s, stopped: " << stop_reason_name(summary.stop) << "\n";
  for (std::size_t k = 0; k < objectives.size() && k < outputs.best().size(); ++k)
    out << "  best " << objectives[k] << ": " << format_number(outputs.best()[k]) << "\n";
  std::vector<const Finding*> kept;
  for (const Finding& finding : log.findings())
    if (!outputs.lost(finding)) kept.push_back(&finding);
  out << kept.size() << (kept.size() == 1 ? " finding" : " findings") << ", one per failure mode";
  if (log.duplicates() > 0)
    out << " (" << log.duplicates() << " more evaluations of the same modes)";
  out << (kept.empty() ? "\n" : ":\n");
  for (const Finding* finding : kept) {
    out << finding_line(*finding) << "\n";
    if (auto tmin = minimised.find(finding->number);
        tmin != minimised.end() && !tmin->second.minimised_file.empty())
      out << "      minimised: " << tmin->second.minimised_file << "\n";
  }
  count_lines(out, objectives, outputs.time_outs(),
              " time-outs (the run ended while the ego still made progress; not findings)");
  count_lines(out, objectives, outputs.start_states(),
              " start-state (violated only by the scenario's start state; not findings)");
  count_lines(out, objectives, outputs.other_faults(),
              " other-fault (violated only once another road user brought a collision that was"
              " not the ego's fault; not findings)");
  if (outputs.audited_with_issues() > 0) out << audit_line(outputs, summary) << "\n";
  if (const std::string line = collisions_line(outputs); !line.empty()) out << line << "\n";
  out << outputs.law_coverage_lines();
  out << "wrote " << (fs::path(options.out_dir) / "summary.json").string() << "\n";
}

// The specs set aside before the search, after its report (and in --json an event of them).
void print_not_judged(const FuzzCommandOptions& options, const std::vector<NotJudgedSpec>& specs,
                      std::ostream& out) {
  if (specs.empty() || (options.quiet && !options.json)) return;
  if (options.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const NotJudgedSpec& spec : specs)
      list.push_back({{"name", spec.name}, {"reason", spec.reason}});
    out << nlohmann::json{{"event", "not_judged"}, {"specs", list}}.dump() << "\n";
    return;
  }
  for (const NotJudgedSpec& spec : specs)
    out << "not judged: spec " << spec.name << ": " << spec.reason << "\n";
}

// The exit status once the search has ended, with the reason on `err` when it is an error.
int exit_status(const FolderSearch& search, const FolderSearchEnd& end, std::ostream& err) {
  if (end.problem == FolderSearchProblem::write_failed) {
    err << "scenfuzz: error: " << end.message
        << "; the search stopped (what is in the output folder is consistent: resume it with "
           "--resume once there is room)\n";
    return kExitBadInput;
  }
  if (!search.log().findings().empty()) return kExitViolated;
  if (std::string why = search.outputs().why_nothing_judged(end.summary); !why.empty()) {
    err << "scenfuzz: error: " << why << "\n";
    return kExitBadInput;
  }
  return kExitSuccess;
}

// What the user sees of the search: the progress line, warnings, and --json finding events.
FolderSearchEvents console_events(const FuzzCommandOptions& options, ProgressReport& progress,
                                  const std::vector<std::string>& objectives, std::ostream& out,
                                  std::ostream& err) {
  FolderSearchEvents events;
  events.interrupted = [] { return StopSignalGuard::stop_requested(); };
  events.warning = [&progress, &err](const std::string& warning) {
    progress.finish();
    err << "scenfuzz: warning: " << warning << "\n";
  };
  events.progress = [&progress, &objectives](std::size_t judged, const std::vector<double>& best,
                                             std::size_t findings, bool final) {
    progress.update(judged, best, objectives, findings, final);
    if (final) progress.finish();
  };
  if (options.json)
    events.finding = [&out](const FindingUpdate& update, const std::string& path) {
      nlohmann::json event = finding_json(update.finding);
      event["event"] = "finding";
      // A later, more violating evaluation of the same failure mode: it replaces the finding.
      if (update.replaced) event["replaces"] = update.finding.number;
      event["file"] = path;
      out << event.dump() << "\n" << std::flush;
    };
  return events;
}

// A concrete scenario is searched by mutation: its space is derived around its values (with a
// note saying so). False after a bad --mutate on `err`.
bool derive_space_if_concrete(const FuzzCommandOptions& options, ScenarioFile& input,
                              std::ostream& err) {
  const MutationSizesOrError sizes = mutation_sizes(options.mutation);
  if (!sizes.error.empty()) {
    err << "scenfuzz: error: " << sizes.error << "\n";
    return false;
  }
  if (!searched_by_mutation(input.scenario)) return true;
  input.scenario = derive_mutation_space(input.scenario, sizes.sizes);
  if (!options.quiet && !options.json && !input.scenario.parameters.empty())
    err << "scenfuzz: note: '" << options.path << "' has no parameter ranges: searching "
        << input.scenario.parameters.size()
        << " of its values within --mutate's neighbourhoods (scenfuzz space shows them)\n";
  return true;
}

// --tmin after a search that ended as it should (not stopped by a signal or a failed write):
// each finding minimised beside it, what became of each recorded for summary.json, and a warning
// for each that could not be. An interruption leaves the rest for --resume.
Minimised minimise_search_findings(const FuzzCommandOptions& options, FolderSearch& folder,
                                   const FolderSearchEnd& end, std::ostream& err) {
  if (!options.tmin || end.problem != FolderSearchProblem::none ||
      end.summary.stop == StopReason::interrupted || end.summary.stop == StopReason::error)
    return {};
  std::vector<std::size_t> numbers;
  std::vector<TminJob> jobs;
  for (const auto& [number, file] : folder.finding_files()) {
    numbers.push_back(number);
    jobs.push_back({file, ""});
  }
  if (jobs.empty()) return {};
  if (!options.quiet && !options.json)
    err << "scenfuzz: minimising " << jobs.size() << (jobs.size() == 1 ? " finding" : " findings")
        << " (--tmin)\n";
  const std::vector<TminJobResult> results =
      minimise_findings(jobs, options.jobs, [] { return StopSignalGuard::stop_requested(); });
  Minimised minimised;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const TminJobResult& result = results[k];
    minimised[numbers[k]] = result;
    folder.outputs().set_minimised(numbers[k], result.minimised_file, result.reason);
    if (result.minimised_file.empty() && !result.interrupted)
      err << "scenfuzz: warning: finding " << finding_number_text(numbers[k])
          << " is not minimised: " << result.reason << "\n";
  }
  if (std::any_of(results.begin(), results.end(), [](const auto& r) { return r.interrupted; }))
    err << "scenfuzz: note: minimising was interrupted; --resume --tmin minimises the rest\n";
  if (std::string failure = folder.outputs().rewrite_summary(end.summary, folder.log());
      !failure.empty())
    err << "scenfuzz: warning: " << failure << "\n";
  return minimised;
}

}  // namespace

int run_fuzz(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err) {
  if (is_accident_file(options.path)) {
    // An accident describes what happened, not a space of scenarios to falsify a driver in.
    err << "scenfuzz: error: '" << options.path
        << "' is an accident description: 'scenfuzz reconstruct " << options.path
        << "' reconstructs it and writes a scenario that puts a driver in the victim's place\n";
    return kExitBadInput;
  }
  std::optional<ScenarioFile> input = read_scenario(options.path, "search", err, options.choice);
  if (!input) return kExitBadInput;
  // The search targets the specs the oracle can judge; the others are named, with the reason.
  const std::vector<NotJudgedSpec> not_judged =
      set_aside_unjudgeable_specs(input->scenario, options.path);
  for (const NotJudgedSpec& spec : not_judged)
    err << "scenfuzz: note: spec " << spec.name << " is not judged: " << spec.reason << "\n";
  if (!not_judged.empty() && input->scenario.specs.empty()) {
    err << "scenfuzz: error: no spec of '" << options.path
        << "' can be judged on simulated traces: nothing to search for\n";
    return kExitBadInput;
  }
  if (!derive_space_if_concrete(options, *input, err)) return kExitUsage;
  apply_scenario_overrides(options.simulation, input->scenario);
  std::optional<ScenarioEvaluator> evaluator = make_evaluator(options, *input, err);
  if (!evaluator) return kExitBadInput;
  std::optional<SearchOptions> search = search_options(options, *evaluator, err);
  if (!search) return kExitUsage;
  if (!check_setup(options, *input, *evaluator, err)) return kExitUsage;
  warn_if_actors_never_interact(*evaluator, options.seed, err);

  const std::vector<std::string> objectives = evaluator->objectives();
  ProgressReport progress(options, out, err);
  FolderSearch folder(options, *input, *evaluator,
                      console_events(options, progress, objectives, out, err));
  bool nothing_to_resume = false;
  if (std::string failure = folder.claim(nothing_to_resume); !failure.empty()) {
    err << "scenfuzz: error: " << failure << "\n";
    return kExitBadInput;
  }
  if (nothing_to_resume)
    err << "scenfuzz: note: there is no search to resume in '" << options.out_dir
        << "'; starting a new one\n";

  FolderSearchEnd end;
  Minimised minimised;
  {
    // One guard for both: a stop during the search skips --tmin, one during --tmin ends it.
    StopSignalGuard guard;
    end = folder.run(*search);
    minimised = minimise_search_findings(options, folder, end, err);
  }
  if (end.problem == FolderSearchProblem::unjudgeable) {
    err << end.message;
    return kExitBadInput;
  }
  if (end.problem == FolderSearchProblem::journal_mismatch) {
    err << "scenfuzz: error: cannot resume the search in '" << options.out_dir
        << "': " << end.message << "; replace it with --force\n";
    return kExitBadInput;
  }
  print_report(options, end.summary, folder.outputs(), folder.log(), objectives, minimised, out);
  print_not_judged(options, not_judged, out);
  return exit_status(folder, end, err);
}

}  // namespace scenfuzz
