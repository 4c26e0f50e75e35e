// `scenfuzz [--budget N] FILE`: the main job. Searches the scenario's parameter space for points
// that violate its specs, writes every (de-duplicated) finding as a concrete, replayable scenario
// with its trace and picture, and keeps evaluations.csv and summary.json up to date.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/progress_report.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_outputs.hpp"
#include "fuzz/search_strategy.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/number_format.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Set by SIGINT; the search looks at it between batches.
std::atomic<bool> interrupt_requested{false};

extern "C" void on_interrupt(int) {
  interrupt_requested.store(true);
  // A second Ctrl-C ends the process at once.
  std::signal(SIGINT, SIG_DFL);
}

// Installs the SIGINT handler for its lifetime.
class InterruptGuard {
 public:
  InterruptGuard() {
    interrupt_requested.store(false);
    previous_ = std::signal(SIGINT, on_interrupt);
  }
  ~InterruptGuard() { std::signal(SIGINT, previous_); }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*previous_)(int) = SIG_DFL;
};

}  // namespace

int run_fuzz(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<ScenarioFile> input = read_scenario(options.path, "search", err);
  if (!input) return kExitBadInput;
  const SourceFile& file = input->file;
  const ScenarioTemplate& scenario = input->scenario;
  if (options.budget == 0) {
    err << "scenfuzz: error: --budget must be at least 1 simulation\n";
    return kExitUsage;
  }

  SimulationOptions simulation;
  simulation.dt = options.simulation.dt;
  simulation.duration = options.simulation.duration;
  simulation.stop_at_collision = !options.simulation.continue_after_collision;
  simulation.ego_plugin = options.simulation.ego_plugin;
  simulation.plugin_step_timeout = options.simulation.ego_step_timeout;
  simulation.plugin_start_timeout = options.simulation.ego_start_timeout;
  std::optional<ScenarioEvaluator> evaluator;
  try {
    std::vector<fs::path> map_paths(options.simulation.map_paths.begin(), options.simulation.map_paths.end());
    evaluator.emplace(file, scenario, map_search_path(map_paths), simulation);
  } catch (const MapError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitBadInput;
  }
  if (evaluator->space().dimensions.empty()) {
    err << "scenfuzz: error: '" << options.path
        << "' has no parameter ranges: there is nothing to search (simulate it with 'scenfuzz "
           "run')\n";
    return kExitBadInput;
  }

  const std::vector<std::string> objectives = evaluator->objectives();
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
      return kExitUsage;
    }
    search.targets.push_back(static_cast<std::size_t>(found - objectives.begin()));
  }
  try {
    (void)make_search_strategy(options.algorithm, evaluator->dimensions(), 0, options.budget);
  } catch (const std::invalid_argument& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitUsage;
  }

  SearchOutputs outputs(options, file, scenario, *evaluator);
  if (std::string failure = outputs.prepare(); !failure.empty()) {
    err << "scenfuzz: error: " << failure << "\n";
    return kExitBadInput;
  }

  FindingLog log(objectives);
  ProgressReport progress(options, out, err);
  SearchSummary so_far;
  std::string write_failure;
  Clock::time_point last_flush = Clock::now();
  SearchCallbacks callbacks;
  callbacks.interrupted = [] { return interrupt_requested.load(); };
  callbacks.on_evaluation = [&](const EvaluationRecord& record) {
    outputs.record(record);
    ++so_far.evaluations;
    if (record.evaluation.judged()) ++so_far.judged;
    for (const Finding& finding : log.add(record)) {
      std::string failure;
      const std::string path = outputs.write_finding(finding, failure);
      if (!failure.empty()) {
        progress.finish();
        err << "scenfuzz: warning: " << failure << "\n";
      }
      if (options.json)
        out << nlohmann::json{{"event", "finding"},
                              {"number", finding.number},
                              {"spec", finding.objective_name},
                              {"robustness", robustness_json(finding.robustness)},
                              {"evaluation", finding.evaluation},
                              {"file", path}}
                   .dump()
            << "\n"
            << std::flush;
    }
    progress.update(so_far.judged, outputs.best(), objectives, log.findings().size(), false);
    if (std::chrono::duration<double>(Clock::now() - last_flush).count() > 5) {
      last_flush = Clock::now();
      write_failure = outputs.flush(so_far, log, false);
    }
  };

  SearchSummary summary;
  {
    InterruptGuard guard;
    try {
      summary = run_search(*evaluator, search, callbacks);
    } catch (const OracleError& error) {
      progress.finish();
      Diagnostics diagnostics;
      diagnostics.error(error.location(), error.what());
      err << format_diagnostics(file, diagnostics);
      return kExitBadInput;
    }
  }
  progress.update(summary.judged, outputs.best(), objectives, log.findings().size(), true);
  progress.finish();
  if (std::string failure = outputs.flush(summary, log, true); !failure.empty())
    write_failure = failure;
  if (!write_failure.empty()) {
    err << "scenfuzz: error: " << write_failure << "\n";
    return kExitBadInput;
  }

  if (options.json) {
    out << nlohmann::json{{"event", "summary"}, {"summary", outputs.summary(summary, log, true)}}
               .dump()
        << "\n";
  } else if (!options.quiet) {
    out << summary.judged << " simulations (" << summary.infeasible
        << " infeasible points skipped, " << summary.failed << " failed) in "
        << format_number(std::round(summary.wall_seconds * 10) / 10)
        << " s, stopped: " << stop_reason_name(summary.stop) << "\n";
    for (std::size_t k = 0; k < objectives.size() && k < outputs.best().size(); ++k)
      out << "  best " << objectives[k] << ": " << format_number(outputs.best()[k]) << "\n";
    out << log.findings().size() << (log.findings().size() == 1 ? " finding" : " findings");
    if (log.duplicates() > 0) out << " (" << log.duplicates() << " duplicates skipped)";
    out << (log.findings().empty() ? "\n" : ":\n");
    for (const Finding& finding : log.findings())
      out << "  " << finding_number_text(finding.number) << " " << finding.objective_name
          << " robustness " << format_number(std::round(finding.robustness * 1e6) / 1e6)
          << (finding.signature.empty() ? "" : " (" + finding.signature + ")") << "\n";
    out << "wrote " << (fs::path(options.out_dir) / "summary.json").string() << "\n";
  }
  return log.findings().empty() ? kExitSuccess : kExitViolated;
}

}  // namespace scenfuzz
