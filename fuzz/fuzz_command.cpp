// `scenfuzz [--budget N] FILE`: the main job. Searches the scenario's parameter space for points
// that violate its specs or make the ego under test fail, writes every (de-duplicated) finding as
// a concrete, replayable scenario with its trace and picture, and journals every evaluation so
// that a killed search can be resumed (--resume) to exactly the findings of an uninterrupted one.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/journal_replay.hpp"
#include "fuzz/options.hpp"
#include "fuzz/output_folder.hpp"
#include "fuzz/progress_report.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_outputs.hpp"
#include "fuzz/search_strategy.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "oracle/robustness.hpp"
#include "oracle/trace_audit.hpp"

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
        << "' has no parameter ranges: there is nothing to search (simulate it with 'scenfuzz "
           "run')\n";
    return std::nullopt;
  }
  return evaluator;
}

// The search's options, or nullopt after a usage error on `err` (an unknown --spec or --algo).
std::optional<SearchOptions> search_options(const FuzzCommandOptions& options,
                                            const Evaluator& evaluator, std::ostream& err) {
  SCENFUZZ_DEMAND(options.budget > 0);  // the command line checks it
  const std::vector<std::string> objectives = evaluator.objectives();
  SearchOptions search;
  search.algorithm = options.algorithm;
  search.budget = options.budget;
  search.time_limit = options.time_limit;
  search.seed = options.seed;
  search.jobs = options.jobs;
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

// Locks --out and decides what happens to an earlier search there: resumed (its journal read
// into `journal`), replaced (--force) or refused. An error message, empty when the search may
// start.
std::string claim_output_folder(const FuzzCommandOptions& options, OutputFolderLock& lock,
                                SearchOutputs& outputs, std::vector<EvaluationRecord>& journal,
                                std::ostream& err) {
  const fs::path dir = options.out_dir;
  if (std::string failure = lock.acquire(dir); !failure.empty()) return failure;
  remove_temporary_files(dir);
  if (holds_search(dir)) {
    if (options.resume) return outputs.resume(journal);
    if (!options.force)
      return "'" + dir.string() +
             "' holds an earlier search: continue it with --resume, write into another folder "
             "with --out DIR, or replace it with --force";
    if (std::string failure = remove_search(dir); !failure.empty()) return failure;
  } else if (options.resume) {
    err << "scenfuzz: note: there is no search to resume in '" << dir.string()
        << "'; starting a new one\n";
  }
  return outputs.start();
}

// What the search's callbacks share: the findings, the outputs and the progress line.
class SearchSession {
 public:
  SearchSession(const FuzzCommandOptions& options, SearchOutputs& outputs,
                const JournalReplay& replay, std::vector<std::string> objectives, std::ostream& out,
                std::ostream& err)
      : options_(options),
        outputs_(outputs),
        replay_(replay),
        objectives_(objectives),
        log_(std::move(objectives)),
        progress_(options, out, err),
        out_(out),
        err_(err) {}

  SearchCallbacks callbacks() {
    SearchCallbacks callbacks;
    callbacks.on_evaluation = [this](const EvaluationRecord& record) { take(record); };
    callbacks.on_batch_end = [this] { end_batch(); };
    callbacks.interrupted = [this] {
      return StopSignalGuard::stop_requested() || !write_failure_.empty();
    };
    return callbacks;
  }

  // After the search: the final summary.json, and the stop reason "error" after a failed write.
  void finish(SearchSummary& summary) {
    if (!write_failure_.empty()) summary.stop = StopReason::error;
    warn_of_design(true);
    progress_.update(summary.judged, outputs_.best(), objectives_, log_.findings().size(), true);
    progress_.finish();
    std::string failure = outputs_.finish(summary, log_, write_failure_);
    if (write_failure_.empty()) write_failure_ = failure;
  }

  const FindingLog& log() const { return log_; }
  const std::string& write_failure() const { return write_failure_; }

 private:
  void take(const EvaluationRecord& record) {
    outputs_.record(record, replay_.replayed(record.index));
    ++so_far_.evaluations;
    if (!record.evaluation.feasible())
      ++so_far_.infeasible;
    else if (record.evaluation.judged())
      ++so_far_.judged;
    else
      ++so_far_.failed;
    if (const std::optional<FindingUpdate> update = log_.add(record)) write(*update);
    progress_.update(so_far_.judged, outputs_.best(), objectives_, log_.findings().size(), false);
  }

  void write(const FindingUpdate& update) {
    const Finding& finding = update.finding;
    if (!write_failure_.empty()) return;
    std::string failure;
    bool fatal = false;
    const std::string path = outputs_.write_finding(finding, failure, fatal);
    if (fatal) {
      write_failure_ = failure;
    } else if (!failure.empty()) {
      progress_.finish();
      err_ << "scenfuzz: warning: " << failure << "\n";
    }
    if (!options_.json) return;
    nlohmann::json event = finding_json(finding);
    event["event"] = "finding";
    // A later, more violating evaluation of the same failure mode: it replaces the finding.
    if (update.replaced) event["replaces"] = finding.number;
    event["file"] = path;
    out_ << event.dump() << "\n" << std::flush;
  }

  void end_batch() {
    if (!write_failure_.empty()) return;
    so_far_.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    write_failure_ = outputs_.end_batch(so_far_, log_);
    warn_of_design(false);
  }

  void warn_of_design(bool search_over) {
    for (const std::string& warning : outputs_.take_design_warnings(search_over)) {
      progress_.finish();
      err_ << "scenfuzz: warning: " << warning << "\n";
    }
  }

  const FuzzCommandOptions& options_;
  SearchOutputs& outputs_;
  const JournalReplay& replay_;
  std::vector<std::string> objectives_;
  FindingLog log_;
  ProgressReport progress_;
  std::ostream& out_;
  std::ostream& err_;
  SearchSummary so_far_;
  std::string write_failure_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

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

void print_report(const FuzzCommandOptions& options, const SearchSummary& summary,
                  const SearchOutputs& outputs, const FindingLog& log,
                  const std::vector<std::string>& objectives, std::ostream& out) {
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
  for (const Finding* finding : kept) out << finding_line(*finding) << "\n";
  for (std::size_t k = 0; k < objectives.size() && k < outputs.time_outs().size(); ++k)
    if (outputs.time_outs()[k] > 0)
      out << "  " << objectives[k] << ": " << outputs.time_outs()[k]
          << " time-outs (the run ended while the ego still made progress; not findings)\n";
  if (outputs.audited_with_issues() > 0) out << audit_line(outputs, summary) << "\n";
  if (const std::string line = collisions_line(outputs); !line.empty()) out << line << "\n";
  out << "wrote " << (fs::path(options.out_dir) / "summary.json").string() << "\n";
}

// The exit status once the search has ended, with the reason on `err` when it is an error.
int exit_status(const SearchSession& session, const SearchOutputs& outputs,
                const SearchSummary& summary, std::ostream& err) {
  if (!session.write_failure().empty()) {
    err << "scenfuzz: error: " << session.write_failure()
        << "; the search stopped (what is in the output folder is consistent: resume it with "
           "--resume once there is room)\n";
    return kExitBadInput;
  }
  if (!session.log().findings().empty()) return kExitViolated;
  if (std::string why = outputs.why_nothing_judged(summary); !why.empty()) {
    err << "scenfuzz: error: " << why << "\n";
    return kExitBadInput;
  }
  return kExitSuccess;
}

}  // namespace

int run_fuzz(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<ScenarioFile> input = read_scenario(options.path, "search", err);
  if (!input) return kExitBadInput;
  apply_scenario_overrides(options.simulation, input->scenario);
  std::optional<ScenarioEvaluator> evaluator = make_evaluator(options, *input, err);
  if (!evaluator) return kExitBadInput;
  std::optional<SearchOptions> search = search_options(options, *evaluator, err);
  if (!search) return kExitUsage;
  if (!check_setup(options, *input, *evaluator, err)) return kExitUsage;

  OutputFolderLock lock;
  SearchOutputs outputs(options, input->file, input->scenario, *evaluator);
  std::vector<EvaluationRecord> journal;
  if (std::string failure = claim_output_folder(options, lock, outputs, journal, err);
      !failure.empty()) {
    err << "scenfuzz: error: " << failure << "\n";
    return kExitBadInput;
  }

  const std::vector<std::string> objectives = evaluator->objectives();
  const JournalReplay replay(*evaluator, std::move(journal));
  SearchSession session(options, outputs, replay, objectives, out, err);
  SearchSummary summary;
  {
    StopSignalGuard guard;
    try {
      summary = run_search(replay, *search, session.callbacks());
    } catch (const OracleError& error) {
      Diagnostics diagnostics;
      diagnostics.error(error.location(), error.what());
      err << format_diagnostics(input->file, diagnostics);
      return kExitBadInput;
    } catch (const JournalMismatch& error) {
      err << "scenfuzz: error: cannot resume the search in '" << options.out_dir
          << "': " << error.what() << "; replace it with --force\n";
      return kExitBadInput;
    }
  }
  session.finish(summary);
  print_report(options, summary, outputs, session.log(), objectives, out);
  return exit_status(session, outputs, summary, err);
}

}  // namespace scenfuzz
