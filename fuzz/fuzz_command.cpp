// `scenfuzz [--budget N] FILE`: the main job. Searches the scenario's parameter space for points
// that violate its specs, writes every (de-duplicated) finding as a concrete, replayable scenario
// with its trace and picture, and keeps evaluations.csv and summary.json up to date.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_strategy.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/number_format.hpp"
#include "oracle/robustness.hpp"
#include "physics/trace/trace_export.hpp"
#include "physics/trace/trace_svg.hpp"

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

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Robustness as text: shortest round trip, `inf` and `-inf` for infinities.
std::string robustness_text(double robustness) { return format_number(robustness); }

nlohmann::json robustness_json(double robustness) {
  if (std::isinf(robustness)) return robustness > 0 ? "inf" : "-inf";
  return robustness;
}

std::string file_stem(const std::string& name) {
  std::string stem;
  for (char c : name)
    stem += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return stem;
}

std::string numbered(std::size_t number) {
  std::ostringstream text;
  text << std::setw(3) << std::setfill('0') << number;
  return text.str();
}

std::string shell_quote(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_-./:=+") == std::string::npos)
    return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The options a replay of a finding needs to simulate exactly as the search did.
std::string simulation_flags(const FuzzCommandOptions& options) {
  std::string flags;
  for (const std::string& path : options.map_paths) flags += " --map-path " + shell_quote(path);
  if (!options.ego_plugin.empty()) flags += " --ego-plugin " + shell_quote(options.ego_plugin);
  if (options.duration) flags += " --duration " + format_number(*options.duration);
  if (options.dt != 0.05) flags += " --dt " + format_number(options.dt);
  if (options.continue_after_collision) flags += " --continue-after-collision";
  return flags;
}

// Everything the command writes into --out, rewritten atomically as it changes.
class Outputs {
 public:
  Outputs(const FuzzCommandOptions& options, const SourceFile& file,
          const ScenarioTemplate& scenario, const ScenarioEvaluator& evaluator)
      : options_(options),
        file_(file),
        scenario_(scenario),
        evaluator_(evaluator),
        dir_(options.out_dir),
        objectives_(evaluator.objectives()) {
    for (const Dimension& dimension : evaluator.space().dimensions)
      header_ += "," + csv_field(dimension.name);
    for (const Dimension& dimension : evaluator.space().dimensions)
      header_ += "," + csv_field("u." + dimension.name);
    for (const std::string& objective : objectives_)
      header_ += "," + csv_field("robustness." + objective);
    header_ = "evaluation,seed,target,status" + header_ + ",wall_seconds,reason\n";
  }

  // Creates the folders; an error message when it cannot.
  std::string prepare() {
    std::error_code error;
    fs::create_directories(dir_ / "findings", error);
    if (error) return "cannot create '" + (dir_ / "findings").string() + "': " + error.message();
    return write_file_atomically(dir_ / "evaluations.csv", header_);
  }

  void record(const EvaluationRecord& record) {
    const Evaluation& evaluation = record.evaluation;
    const char* status = !evaluation.feasible() ? "infeasible"
                         : !evaluation.judged() ? "failed"
                                                : "judged";
    std::string row = std::to_string(record.index) + "," + std::to_string(record.seed) + "," +
                      csv_field(objectives_[record.target]) + "," + status;
    const std::vector<double> values = decode(evaluator_.space(), record.point);
    const std::vector<Dimension>& dimensions = evaluator_.space().dimensions;
    for (std::size_t i = 0; i < dimensions.size(); ++i)
      row += "," + (dimensions[i].kind == ParameterKind::discrete
                        ? csv_field(dimensions[i].choices[static_cast<std::size_t>(values[i])])
                        : format_number(values[i]));
    for (double u : record.point) row += "," + format_number(u);
    for (std::size_t k = 0; k < objectives_.size(); ++k)
      row +=
          "," + (evaluation.judged() ? robustness_text(evaluation.robustness[k]) : std::string());
    row += "," + format_number(std::round(evaluation.wall_seconds * 1e6) / 1e6) + "," +
           csv_field(evaluation.feasible() ? evaluation.failure : evaluation.infeasible) + "\n";
    rows_ += row;
    for (std::size_t k = 0; k < objectives_.size() && evaluation.judged(); ++k) {
      if (best_.size() < objectives_.size()) best_.assign(objectives_.size(), INFINITY);
      best_[k] = std::min(best_[k], evaluation.robustness[k]);
    }
  }

  // Writes finding `finding` (re-simulating its point, which gives the same run) and returns the
  // path of its scenario, or an error message in `failure`.
  std::string write_finding(const Finding& finding, std::string& failure) {
    const ScenarioRun run = evaluator_.run(finding.point, finding.seed);
    if (!run.trace || run.verdicts.size() <= finding.objective) {
      failure = "finding " + std::to_string(finding.number) + " did not replay: " + run.infeasible +
                run.failure;
      return "";
    }
    const SpecVerdict& verdict = run.verdicts[finding.objective];
    const std::string extension = fs::path(file_.path()).extension().string();
    const std::string stem = numbered(finding.number) + "-" + file_stem(finding.objective_name);
    const fs::path scenario_path =
        dir_ / "findings" / (stem + (extension.empty() ? ".avu" : extension));
    std::string header = "// scenfuzz finding " + std::to_string(finding.number) + ": spec " +
                         finding.objective_name + " violated, robustness " +
                         robustness_text(verdict.robustness) + " at " +
                         format_number(std::round(verdict.time * 1000) / 1000) + " s";
    if (!verdict.atom_text.empty()) header += " (" + verdict.atom_text + ")";
    header += "\n// from " + file_.path() + ", search seed " + std::to_string(options_.seed) +
              ", evaluation " + std::to_string(finding.evaluation) + " (" + options_.algorithm +
              ")";
    if (!finding.signature.empty()) header += ", collision " + finding.signature;
    header += "\n// replay: scenfuzz run " + shell_quote(scenario_path.string()) + " --seed " +
              std::to_string(finding.seed) + simulation_flags(options_) + "\n";
    std::vector<std::string> lane_ids;
    for (const Lane& lane : run.map->lanes()) lane_ids.push_back(lane.id);
    const std::vector<std::pair<fs::path, std::string>> files = {
        {scenario_path, header + avunit::print_concrete(file_, scenario_, run.values)},
        {dir_ / "findings" / (stem + ".csv"), trace_csv(*run.trace, lane_ids)},
        {dir_ / "findings" / (stem + ".svg"), render_trace_svg(*run.map, *run.trace)},
    };
    for (const auto& [path, content] : files) {
      failure = write_file_atomically(path, content);
      if (!failure.empty()) return "";
    }
    if (verdict.robustness != finding.robustness)
      failure = "finding " + std::to_string(finding.number) + " replays with robustness " +
                robustness_text(verdict.robustness) + " instead of " +
                robustness_text(finding.robustness) + " (please report this)";
    written_.push_back(scenario_path.string());
    return scenario_path.string();
  }

  nlohmann::json summary(const SearchSummary& search, const FindingLog& log, bool complete) const {
    nlohmann::json findings = nlohmann::json::array();
    for (std::size_t i = 0; i < log.findings().size(); ++i) {
      const Finding& finding = log.findings()[i];
      nlohmann::json entry = {{"number", finding.number},
                              {"spec", finding.objective_name},
                              {"robustness", robustness_json(finding.robustness)},
                              {"evaluation", finding.evaluation},
                              {"seed", finding.seed}};
      if (i < written_.size()) entry["file"] = written_[i];
      if (!finding.signature.empty()) entry["collision"] = finding.signature;
      findings.push_back(entry);
    }
    nlohmann::json best = nlohmann::json::object();
    for (std::size_t k = 0; k < best_.size(); ++k) best[objectives_[k]] = robustness_json(best_[k]);
    return {{"scenario", file_.path()},
            {"algorithm", options_.algorithm},
            {"seed", options_.seed},
            {"budget", options_.budget},
            {"specs", objectives_},
            {"evaluations", search.evaluations},
            {"judged", search.judged},
            {"failed", search.failed},
            {"infeasible", search.infeasible},
            {"best", best},
            {"findings", findings},
            {"duplicates", log.duplicates()},
            {"wall_seconds", search.wall_seconds},
            {"stop", complete ? std::string(stop_reason_name(search.stop)) : "running"},
            {"complete", complete}};
  }

  std::string flush(const SearchSummary& search, const FindingLog& log, bool complete) {
    std::string failure = write_file_atomically(dir_ / "evaluations.csv", header_ + rows_);
    if (failure.empty())
      failure = write_file_atomically(dir_ / "summary.json",
                                      summary(search, log, complete).dump(2) + "\n");
    return failure;
  }

  const std::vector<double>& best() const { return best_; }

 private:
  const FuzzCommandOptions& options_;
  const SourceFile& file_;
  const ScenarioTemplate& scenario_;
  const ScenarioEvaluator& evaluator_;
  fs::path dir_;
  std::vector<std::string> objectives_;
  std::string header_;
  std::string rows_;
  std::vector<double> best_;
  std::vector<std::string> written_;
};

// The progress report: a line rewritten in place on a terminal, a plain line every few seconds
// otherwise, JSON lines with --json, nothing with --quiet.
class Progress {
 public:
  Progress(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err)
      : options_(options), out_(out), err_(err), terminal_(::isatty(STDERR_FILENO) != 0) {}

  void update(std::size_t judged, const std::vector<double>& best,
              const std::vector<std::string>& objectives, std::size_t findings, bool force) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double since = std::chrono::duration<double>(Clock::now() - last_).count();
    if (!force && since < (terminal_ ? 0.2 : 5.0)) return;
    last_ = Clock::now();
    double best_value = INFINITY;
    std::string best_name;
    for (std::size_t k = 0; k < best.size(); ++k)
      if (best[k] < best_value) best_value = best[k], best_name = objectives[k];
    const double rate = elapsed > 0 ? static_cast<double>(judged) / elapsed : 0;
    if (options_.json) {
      out_ << nlohmann::json{{"event", "progress"},
                             {"evaluations", judged},
                             {"budget", options_.budget},
                             {"rate", std::round(rate * 100) / 100},
                             {"best", robustness_json(best_value)},
                             {"findings", findings}}
                  .dump()
           << "\n"
           << std::flush;
      return;
    }
    if (options_.quiet) return;
    std::ostringstream line;
    line << judged << "/" << options_.budget << " simulations, " << std::fixed
         << std::setprecision(1) << rate << "/s, best "
         << (best_name.empty()
                 ? std::string("-")
                 : format_number(std::round(best_value * 1000) / 1000) + " (" + best_name + ")")
         << ", " << findings << (findings == 1 ? " finding" : " findings");
    if (terminal_)
      err_ << "\r\033[K" << line.str() << std::flush;
    else
      err_ << line.str() << "\n";
  }

  void finish() {
    if (terminal_ && !options_.quiet && !options_.json) err_ << "\n";
  }

 private:
  const FuzzCommandOptions& options_;
  std::ostream& out_;
  std::ostream& err_;
  bool terminal_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_{};
};

}  // namespace

int run_fuzz(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<SourceFile> file = read_input(options.path, err);
  if (!file) return kExitBadInput;
  const avunit::ParseResult parsed = avunit::parse(*file);
  err << format_diagnostics(*file, parsed.diagnostics);
  if (!parsed.ok()) return kExitBadInput;
  const ScenarioTemplate& scenario = parsed.scenario;
  if (!scenario.has_scenario) {
    err << "scenfuzz: error: '" << options.path
        << "' builds no scenario (no CreateScenario): nothing to search\n";
    return kExitBadInput;
  }
  if (options.budget == 0) {
    err << "scenfuzz: error: --budget must be at least 1 simulation\n";
    return kExitUsage;
  }

  SimulationOptions simulation;
  simulation.dt = options.dt;
  simulation.duration = options.duration;
  simulation.stop_at_collision = !options.continue_after_collision;
  simulation.ego_plugin = options.ego_plugin;
  std::optional<ScenarioEvaluator> evaluator;
  try {
    std::vector<fs::path> map_paths(options.map_paths.begin(), options.map_paths.end());
    evaluator.emplace(*file, scenario, map_search_path(map_paths), simulation);
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

  Outputs outputs(options, *file, scenario, *evaluator);
  if (std::string failure = outputs.prepare(); !failure.empty()) {
    err << "scenfuzz: error: " << failure << "\n";
    return kExitBadInput;
  }

  FindingLog log(objectives);
  Progress progress(options, out, err);
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
      err << format_diagnostics(*file, diagnostics);
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
      out << "  best " << objectives[k] << ": " << robustness_text(outputs.best()[k]) << "\n";
    out << log.findings().size() << (log.findings().size() == 1 ? " finding" : " findings");
    if (log.duplicates() > 0) out << " (" << log.duplicates() << " duplicates skipped)";
    out << (log.findings().empty() ? "\n" : ":\n");
    for (const Finding& finding : log.findings())
      out << "  " << numbered(finding.number) << " " << finding.objective_name << " robustness "
          << format_number(std::round(finding.robustness * 1e6) / 1e6)
          << (finding.signature.empty() ? "" : " (" + finding.signature + ")") << "\n";
    out << "wrote " << (fs::path(options.out_dir) / "summary.json").string() << "\n";
  }
  return log.findings().empty() ? kExitSuccess : kExitViolated;
}

}  // namespace scenfuzz
