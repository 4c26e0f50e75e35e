#include "fuzz/search_outputs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/coverage_summary.hpp"
#include "fuzz/law_coverage_report.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_language.hpp"
#include "fuzz/search_identity.hpp"
#include "fuzz/tmin_finding.hpp"
#include "lang/number_format.hpp"
#include "oracle/failure_mode.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/trace/trace_export.hpp"
#include "physics/trace/trace_svg.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;

std::string file_stem(const std::string& name) {
  std::string stem;
  for (char c : name)
    stem += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return stem;
}

// One line of a header comment: a plugin's message may hold line breaks.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// The options a replay of a finding needs to simulate exactly as the search did.
std::string simulation_flags(const SimulationCommandOptions& options) {
  const SimulationCommandOptions defaults;
  std::string flags;
  for (const std::string& path : options.map_paths) flags += " --map-path " + shell_quote(path);
  if (!options.ego_plugin.empty()) flags += " --ego-plugin " + shell_quote(options.ego_plugin);
  if (options.duration) flags += " --duration " + format_number(*options.duration);
  if (options.dt != defaults.dt) flags += " --dt " + format_number(options.dt);
  if (options.continue_after_collision) flags += " --continue-after-collision";
  if (!options.npc_behaviour.empty()) flags += " --npc-behaviour " + options.npc_behaviour;
  if (options.all_collisions) flags += " --all-collisions";
  for (const std::string& setting : options.rss) flags += " --rss " + shell_quote(setting);
  if (options.ego_step_timeout != defaults.ego_step_timeout)
    flags += " --ego-step-timeout " + format_number(options.ego_step_timeout);
  if (options.ego_start_timeout != defaults.ego_start_timeout)
    flags += " --ego-start-timeout " + format_number(options.ego_start_timeout);
  return flags;
}

// What the mode's key leaves out (the other's class, the ego's fine activity and road feature,
// the touching sides): a line of the finding's header, empty when there is nothing to describe.
std::string seen_as_line(const ScenarioRun& run, const std::string& comment) {
  const std::vector<std::size_t> order = violation_order(run.verdicts);
  if (order.empty() || !run.trace || !run.map) return "";
  return comment + "seen as: " +
         failure_mode_details(describe_failure(*run.trace, *run.map, run.verdicts[order.front()])) +
         "\n";
}

std::string seconds_text(double seconds) {
  return format_number(std::round(seconds * 1000) / 1000) + " s";
}

// " (from the start state -6 at 0 s)" when a verdict's robustness and time are the driver's share
// of a violation the start state made worse (SpecVerdict::start_excused), else nothing.
std::string start_state_note(const SpecVerdict& verdict) {
  if (!verdict.start_excused) return "";
  return " (from the start state " + format_number(verdict.robustness_as_observed) + " at " +
         seconds_text(verdict.time_as_observed) + ")";
}

}  // namespace

nlohmann::json finding_json(const Finding& finding) {
  nlohmann::json entry = {{"number", finding.number}, {"evaluation", finding.evaluation}};
  if (finding.ego_failure()) {
    entry["kind"] = finding.objective_name;
    entry["reason"] = finding.failure;
  } else {
    entry["kind"] = "violation";
    entry["spec"] = finding.objective_name;
    entry["robustness"] = robustness_json(finding.robustness);
    if (!finding.ending.empty()) entry["ending"] = finding.ending;
  }
  entry["mode"] = finding.mode;
  entry["count"] = finding.count;
  if (!finding.responsibility.empty()) {
    entry["responsibility"] = finding.responsibility;
    entry["collision_reason"] = finding.collision_reason;
  }
  return entry;
}

std::string finding_number_text(std::size_t number) {
  std::ostringstream text;
  text << std::setw(3) << std::setfill('0') << number;
  return text.str();
}

namespace {

std::vector<std::string> sub_target_names(const Evaluator& evaluator) {
  std::vector<std::string> names;
  for (const SubTarget& target : evaluator.sub_targets()) names.push_back(target.name);
  return names;
}

}  // namespace

SearchOutputs::SearchOutputs(const FuzzCommandOptions& options, const SourceFile& file,
                             const ScenarioTemplate& scenario, const ScenarioEvaluator& evaluator)
    : options_(options),
      file_(file),
      scenario_(scenario),
      evaluator_(evaluator),
      dir_(options.out_dir),
      objectives_(evaluator.objectives()),
      journal_(evaluator.space(), objectives_, sub_target_names(evaluator)),
      time_outs_(objectives_.size(), 0),
      stuck_(objectives_.size(), 0),
      start_states_(objectives_.size(), 0),
      other_faults_(objectives_.size(), 0),
      design_violations_(objectives_.size(), 0),
      design_first_violation_(objectives_.size()) {
  collisions_.not_counted = scenario.specs.empty() && !options.simulation.all_collisions;
}

std::string SearchOutputs::start() {
  std::error_code error;
  fs::create_directories(dir_ / "findings", error);
  if (error) return "cannot create '" + (dir_ / "findings").string() + "': " + error.message();
  const std::string identity = search_identity(options_, file_).dump(2) + "\n";
  if (std::string failure = write_file_atomically(dir_ / "search.json", identity); !failure.empty())
    return failure;
  return write_file_atomically(dir_ / "evaluations.csv", journal_.header());
}

std::string SearchOutputs::resume(std::vector<EvaluationRecord>& journal) {
  std::ifstream in(dir_ / "search.json");
  nlohmann::json stored = nlohmann::json::parse(in, nullptr, false);
  if (!in || stored.is_discarded() || !stored.is_object())
    return "'" + (dir_ / "search.json").string() +
           "' is missing or unreadable: there is no search to resume there (use --force to "
           "replace what is there)";
  if (std::string difference = identity_difference(stored, search_identity(options_, file_));
      !difference.empty())
    return "cannot resume the search in '" + dir_.string() + "': " + difference +
           "; resume with the options it was started with, or replace it with --force";
  std::error_code error;
  fs::create_directories(dir_ / "findings", error);
  if (error) return "cannot create '" + (dir_ / "findings").string() + "': " + error.message();
  // Killed between search.json and the journal's header: nothing was evaluated yet.
  if (!fs::exists(dir_ / "evaluations.csv", error))
    return write_file_atomically(dir_ / "evaluations.csv", journal_.header());
  std::string failure;
  std::optional<std::vector<EvaluationRecord>> records =
      journal_.read(dir_ / "evaluations.csv", failure);
  if (!records) return failure;
  journal = std::move(*records);
  return {};
}

void SearchOutputs::record(const EvaluationRecord& record, bool replayed) {
  const Evaluation& evaluation = record.evaluation;
  if (!replayed) batch_rows_ += journal_.row(record);
  if (!evaluation.feasible() && first_infeasible_.empty())
    first_infeasible_ = evaluation.infeasible;
  if (evaluation.feasible() && !evaluation.judged() && first_failure_.empty())
    first_failure_ = evaluation.failure;
  if (!evaluation.failure_kind.empty()) ++ego_failures_;
  if (audit_totals_.size() < evaluation.audit.size()) audit_totals_.resize(evaluation.audit.size());
  for (std::size_t k = 0; k < evaluation.audit.size(); ++k) audit_totals_[k] += evaluation.audit[k];
  if (std::any_of(evaluation.audit.begin(), evaluation.audit.end(),
                  [](std::size_t count) { return count > 0; }))
    ++audited_with_issues_;
  for (std::size_t k = 0; k < objectives_.size() && evaluation.judged(); ++k) {
    if (best_.size() < objectives_.size()) best_.assign(objectives_.size(), INFINITY);
    best_[k] = std::min(best_[k], evaluation.robustness[k]);
  }
  for (std::size_t k = 0; k < evaluation.endings.size() && k < objectives_.size(); ++k) {
    if (evaluation.endings[k] == verdict_ending_name(VerdictEnding::time_out)) ++time_outs_[k];
    if (evaluation.endings[k] == verdict_ending_name(VerdictEnding::stuck)) ++stuck_[k];
    if (evaluation.endings[k] == verdict_ending_name(VerdictEnding::start)) ++start_states_[k];
    if (evaluation.endings[k] == verdict_ending_name(VerdictEnding::other_fault))
      ++other_faults_[k];
  }
  record_design(record);
  record_collision(evaluation, record.index);
  coverage_.insert(evaluation.coverage.begin(), evaluation.coverage.end());
  note_first_reached(evaluation.coverage, record.index, law_first_);
}

std::string SearchOutputs::law_coverage_lines() const {
  return law_coverage_text(scenario_, evaluator_.law_sub_violations(), law_first_);
}

void SearchOutputs::record_collision(const Evaluation& evaluation, std::size_t index) {
  if (!evaluation.judged() || evaluation.responsibility.empty()) return;
  if (evaluation.responsibility == responsibility_name(Responsibility::ego)) ++collisions_.ego;
  if (evaluation.responsibility == responsibility_name(Responsibility::shared))
    ++collisions_.shared;
  if (evaluation.responsibility != responsibility_name(Responsibility::other)) return;
  ++collisions_.other;
  if (collisions_.first_others.size() < kListedOtherCollisions)
    collisions_.first_others.emplace_back(index, evaluation.collision_reason);
}

void SearchOutputs::record_design(const EvaluationRecord& record) {
  const Evaluation& evaluation = record.evaluation;
  if (!record.first_design) {
    design_over_ = true;
    return;
  }
  if (!evaluation.judged()) return;
  ++design_points_;
  for (std::size_t k = 0; k < objectives_.size(); ++k) {
    if (!(evaluation.robustness[k] < 0)) continue;
    ++design_violations_[k];
    if (!design_first_violation_[k]) design_first_violation_[k] = record;
  }
}

std::vector<std::string> SearchOutputs::take_design_warnings(bool search_over) {
  if (design_warned_ || !(design_over_ || search_over) || design_points_ == 0) return {};
  design_warned_ = true;
  std::vector<std::string> warnings;
  for (std::size_t k = 0; k < objectives_.size(); ++k) {
    if (2 * design_violations_[k] <= design_points_) continue;
    const EvaluationRecord& first = *design_first_violation_[k];
    const ScenarioRun run = evaluator_.run(first.point, first.seed);
    std::string atom;
    if (k < run.verdicts.size() && !run.verdicts[k].atom_text.empty())
      atom = " (at evaluation " + std::to_string(first.index) +
             ", the first of them: " + one_line(run.verdicts[k].atom_text) + ")";
    warnings.push_back("spec '" + objectives_[k] + "' is violated at " +
                       std::to_string(design_violations_[k]) + " of the " +
                       std::to_string(design_points_) + " points of the search's first design (" +
                       format_number(std::round(100.0 * static_cast<double>(design_violations_[k]) /
                                                static_cast<double>(design_points_))) +
                       " %)" + atom + ": its ranges or thresholds are probably wrong");
  }
  return warnings;
}

fs::path SearchOutputs::finding_path(const Finding& finding, const std::string& extension) const {
  std::string own = extension;
  if (own.empty()) {
    own = fs::path(file_.path()).extension().string();
    if (own.empty()) own = ".avu";
  }
  return dir_ / "findings" /
         (finding_number_text(finding.number) + "-" + file_stem(finding.objective_name) + own);
}

std::string SearchOutputs::finding_header(const Finding& finding, const ScenarioRun& run,
                                          const fs::path& scenario_path) const {
  const std::string comment = comment_prefix(file_.path());
  std::string header = comment + "scenfuzz finding " + std::to_string(finding.number) + ": ";
  std::string origin = "from " + file_.path() + ", search seed " + std::to_string(options_.seed) +
                       ", evaluation " + std::to_string(finding.evaluation) + " (" +
                       options_.algorithm + ")";
  if (finding.ego_failure()) {
    const std::optional<EgoFailure>& failure = run.trace->ego_failure;
    header += finding.objective_name + ": " + one_line(failure ? failure->reason : finding.failure);
    if (failure)
      origin = "at step " + std::to_string(failure->step) + ", " + seconds_text(failure->time) +
               " simulated; " + origin;
    header += "\n" + comment + origin + "\n";
    if (failure && !failure->last_observation.empty())
      header += comment + "last observation handed to the plugin: " +
                finding_path(finding, ".observation.json").string() + "\n";
  } else {
    const SpecVerdict& verdict = run.verdicts[finding.objective];
    header += "spec " + finding.objective_name + " violated, robustness " +
              format_number(verdict.robustness) + " at " + seconds_text(verdict.time);
    if (!verdict.atom_text.empty()) header += " (" + verdict.atom_text + ")";
    header += start_state_note(verdict);
    if (verdict.ending == VerdictEnding::stuck)
      header += "; stuck: the run ended before it could hold, and the ego " + verdict.progress;
    header += "\n" + comment + origin + "\n";
    header += also_violated_lines(finding, run, comment);
  }
  header += comment + "failure mode: " + finding.mode + "\n";
  if (!finding.ego_failure()) header += seen_as_line(run, comment);
  if (!run.responsibilities.empty()) {
    const CollisionResponsibility& first = run.responsibilities.front();
    header += comment + "collision with " + run.trace->actors[first.other].name + ", " +
              responsibility_words(std::string(responsibility_name(first.responsibility))) + ": " +
              one_line(first.reason) + "\n";
  }
  // The file the finding is written in keeps every scenario of its source: name the one it is of.
  const std::string scenario_flag = options_.choice.scenario.empty()
                                        ? ""
                                        : " --scenario " + shell_quote(options_.choice.scenario);
  return header + comment + "replay: scenfuzz run " + shell_quote(scenario_path.string()) +
         scenario_flag + " --seed " + std::to_string(finding.seed) +
         simulation_flags(options_.simulation) + "\n";
}

// The finding's other violations (later specs, and a conjunction's later conjuncts), a line
// each, in time order.
std::string SearchOutputs::also_violated_lines(const Finding& finding, const ScenarioRun& run,
                                               const std::string& comment) const {
  std::string lines;
  const SpecVerdict& first = run.verdicts[finding.objective];
  for (std::size_t c = 1; c < first.conjuncts.size(); ++c)
    lines += comment + "also violated: " + first.conjuncts[c].atom_text + " at " +
             seconds_text(first.conjuncts[c].time) + "\n";
  for (std::size_t k : finding.violated) {
    if (k == finding.objective || k >= run.verdicts.size()) continue;
    const SpecVerdict& verdict = run.verdicts[k];
    lines += comment + "also violated: spec " + verdict.name + ", robustness " +
             format_number(verdict.robustness) + " at " + seconds_text(verdict.time) +
             (verdict.atom_text.empty() ? "" : " (" + verdict.atom_text + ")") +
             start_state_note(verdict) + "\n";
  }
  return lines;
}

namespace {

// Whether the finding file at `path` was written for `evaluation` (its header says so): a
// resumed search finds it in place; a mode's new representative replaces it.
bool written_for(const fs::path& path, std::size_t evaluation) {
  std::ifstream in(path);
  std::string line;
  const std::string mark = ", evaluation " + std::to_string(evaluation) + " (";
  for (int i = 0; i < 4 && std::getline(in, line); ++i)
    if (line.find(mark) != std::string::npos) return true;
  return false;
}

}  // namespace

std::string SearchOutputs::write_finding(const Finding& finding, std::string& failure,
                                         bool& fatal) {
  fatal = false;
  const fs::path scenario_path = finding_path(finding, "");
  std::error_code error;
  if (fs::exists(scenario_path, error) && written_for(scenario_path, finding.evaluation)) {
    // A resumed search: the scenario file is written last, so the finding is whole.
    written_[finding.number] = scenario_path.string();
    return scenario_path.string();
  }
  // A mode's new representative: the minimised file of the one it replaces (--tmin) goes first.
  fs::remove(default_minimised_path(scenario_path.string()), error);
  const ScenarioRun run = evaluator_.run(finding.point, finding.seed);
  const bool replayed =
      run.trace && (finding.ego_failure() ? run.trace->ego_failure.has_value()
                                          : run.verdicts.size() > finding.objective);
  if (!replayed) {
    failure = "finding " + std::to_string(finding.number) + " did not replay: " + run.infeasible +
              (run.failure.empty() ? "the run went differently" : run.failure);
    return "";
  }
  std::vector<std::pair<fs::path, std::string>> files;
  if (run.trace->sample_count() > 0) {
    std::vector<std::string> lane_ids;
    for (const Lane& lane : run.map->lanes()) lane_ids.push_back(lane.id);
    files.emplace_back(finding_path(finding, ".csv"), trace_csv(*run.trace, lane_ids));
    TraceSvgOptions picture;  // the title names the finding's spec; ego failures have no verdict
    picture.caption.spec = finding.objective_name;
    if (!finding.ego_failure()) {
      const SpecVerdict& verdict = run.verdicts[finding.objective];
      picture.caption = {verdict.name,
                         verdict.robustness,
                         verdict.time,
                         verdict.atom_text,
                         finding.responsibility,
                         finding.collision_reason,
                         ""};
    }
    files.emplace_back(finding_path(finding, ".svg"),
                       render_trace_svg(*run.map, *run.trace, picture));
  }
  if (finding.ego_failure() && !run.trace->ego_failure->last_observation.empty())
    files.emplace_back(finding_path(finding, ".observation.json"),
                       run.trace->ego_failure->last_observation + "\n");
  files.emplace_back(scenario_path, finding_header(finding, run, scenario_path) +
                                        print_concrete_scenario(file_, scenario_, run.values));
  for (const auto& [path, content] : files) {
    failure = write_file_atomically(path, content);
    fatal = !failure.empty();
    if (fatal) {
      lost_.insert(finding.number);
      return "";
    }
  }
  written_[finding.number] = scenario_path.string();
  if (finding.ego_failure() &&
      ego_failure_kind_name(run.trace->ego_failure->kind) != finding.objective_name)
    failure = "finding " + std::to_string(finding.number) + " replays as " +
              std::string(ego_failure_kind_name(run.trace->ego_failure->kind)) + " instead of " +
              finding.objective_name + " (the plugin does not fail deterministically)";
  if (!finding.ego_failure() && run.verdicts[finding.objective].robustness != finding.robustness)
    failure = "finding " + std::to_string(finding.number) + " replays with robustness " +
              format_number(run.verdicts[finding.objective].robustness) + " instead of " +
              format_number(finding.robustness) + " (please report this)";
  return scenario_path.string();
}

nlohmann::json SearchOutputs::summary(const SearchSummary& search, const FindingLog& log,
                                      bool complete, const std::string& error) const {
  nlohmann::json findings = nlohmann::json::array();
  for (const Finding& finding : log.findings()) {
    if (lost(finding)) continue;
    nlohmann::json entry = finding_json(finding);
    entry["seed"] = finding.seed;
    if (!finding.ego_failure()) {
      nlohmann::json violated = nlohmann::json::array();
      for (std::size_t k : finding.violated) violated.push_back(objectives_[k]);
      entry["violated"] = violated;
    }
    if (auto file = written_.find(finding.number); file != written_.end())
      entry["file"] = file->second;
    if (auto tmin = minimised_.find(finding.number); tmin != minimised_.end())
      entry.update(tmin->second);
    findings.push_back(entry);
  }
  nlohmann::json best = nlohmann::json::object();
  for (std::size_t k = 0; k < best_.size(); ++k) best[objectives_[k]] = robustness_json(best_[k]);
  nlohmann::json document = {
      {"scenario", file_.path()},
      {"algorithm", options_.algorithm},
      {"seed", options_.seed},
      {"budget", options_.budget},
      {"specs", objectives_},
      {"evaluations", search.evaluations},
      {"judged", search.judged},
      {"failed", search.failed},
      {"ego_failures", ego_failures_},
      {"infeasible", search.infeasible},
      {"best", best},
      {"findings", findings},
      {"duplicates", log.duplicates()},
      {"wall_seconds", search.wall_seconds},
      {"stop", complete ? std::string(stop_reason_name(search.stop)) : "running"},
      {"complete", complete}};
  nlohmann::json issues = nlohmann::json::object();
  for (std::size_t k = 0; k < audit_totals_.size(); ++k)
    issues[std::string(audit_kind_name(static_cast<AuditKind>(k)))] = audit_totals_[k];
  document["audit"] = {{"simulations_with_issues", audited_with_issues_}, {"issues", issues}};
  nlohmann::json others = nlohmann::json::array();
  for (const auto& [evaluation, reason] : collisions_.first_others)
    others.push_back({{"evaluation", evaluation}, {"reason", reason}});
  document["ego_collisions"] = {{"ego", collisions_.ego},
                                {"shared", collisions_.shared},
                                {"other", collisions_.other},
                                {"other_are_findings", !collisions_.not_counted},
                                {"first_other", others}};
  std::map<std::string, std::size_t> by_responsibility;
  for (const Finding& finding : log.findings())
    if (!lost(finding))
      ++by_responsibility[finding.responsibility.empty() ? "none" : finding.responsibility];
  document["failure_modes"] = {{"count", log.findings().size()},
                               {"evaluations", log.findings().size() + log.duplicates()},
                               {"by_responsibility", by_responsibility}};
  nlohmann::json time_outs = nlohmann::json::object(), stuck = nlohmann::json::object(),
                 start_states = nlohmann::json::object(), other_faults = nlohmann::json::object(),
                 rates = nlohmann::json::object();
  for (std::size_t k = 0; k < objectives_.size(); ++k) {
    time_outs[objectives_[k]] = time_outs_[k];
    start_states[objectives_[k]] = start_states_[k];
    other_faults[objectives_[k]] = other_faults_[k];
    stuck[objectives_[k]] = stuck_[k];
    if (design_points_ > 0)
      rates[objectives_[k]] =
          static_cast<double>(design_violations_[k]) / static_cast<double>(design_points_);
  }
  document["coverage"] = coverage_summary_json(coverage_);
  document["law_coverage"] =
      law_coverage_json(scenario_, evaluator_.law_sub_violations(), law_first_);
  document["time_outs"] = time_outs;
  document["stuck"] = stuck;
  document["start_state"] = start_states;
  document["other_fault"] = other_faults;
  document["first_design"] = {
      {"points", design_points_}, {"over", design_over_ || complete}, {"violation_rate", rates}};
  if (!error.empty()) document["error"] = error;
  return document;
}

std::string SearchOutputs::end_batch(const SearchSummary& search, const FindingLog& log) {
  if (!batch_rows_.empty()) {
    if (std::string failure = append_to_file(dir_ / "evaluations.csv", batch_rows_);
        !failure.empty())
      return failure;
    batch_rows_.clear();
  }
  // The GA's descents make batches of one or two simulations: the summary (with an fsync of the
  // journal before it) follows every new finding at once, and otherwise every second.
  const bool new_findings = log.findings().size() != findings_in_summary_;
  if (!new_findings && Clock::now() - last_summary_ < std::chrono::seconds(1)) return {};
  return write_summary(search, log, false, "");
}

std::string SearchOutputs::finish(const SearchSummary& search, const FindingLog& log,
                                  const std::string& error) {
  std::string failure;
  if (!batch_rows_.empty()) {
    failure = append_to_file(dir_ / "evaluations.csv", batch_rows_);
    if (failure.empty()) batch_rows_.clear();
  }
  std::string summary_failure = write_summary(search, log, true, error.empty() ? failure : error);
  return failure.empty() ? summary_failure : failure;
}

std::string SearchOutputs::write_summary(const SearchSummary& search, const FindingLog& log,
                                         bool complete, const std::string& error) {
  // The journal reaches the disk before a summary that counts its rows.
  std::string failure = sync_file(dir_ / "evaluations.csv");
  const std::string written = write_file_atomically(
      dir_ / "summary.json",
      summary(search, log, complete, error.empty() ? failure : error).dump(2) + "\n");
  last_summary_ = Clock::now();
  findings_in_summary_ = log.findings().size();
  return failure.empty() ? written : failure;
}

void SearchOutputs::set_minimised(std::size_t number, const std::string& file,
                                  const std::string& reason) {
  minimised_[number] = file.empty()
                           ? nlohmann::json{{"minimised", nullptr}, {"not_minimised", reason}}
                           : nlohmann::json{{"minimised", file}};
}

std::string SearchOutputs::rewrite_summary(const SearchSummary& search, const FindingLog& log) {
  return write_summary(search, log, true, "");
}

std::string SearchOutputs::why_nothing_judged(const SearchSummary& search) const {
  if (search.judged > 0) return "";
  std::string text = "no evaluation could be judged: " + std::to_string(search.evaluations) +
                     " proposed, " + std::to_string(search.infeasible) + " infeasible";
  if (!first_infeasible_.empty()) text += " (the first: " + first_infeasible_ + ")";
  text += ", " + std::to_string(search.failed) + " failed";
  if (!first_failure_.empty()) text += " (the first: " + first_failure_ + ")";
  return text;
}

}  // namespace scenfuzz
