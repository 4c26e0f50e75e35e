#include "fuzz/search_outputs.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_language.hpp"
#include "lang/number_format.hpp"
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

// The options a replay of a finding needs to simulate exactly as the search did.
std::string simulation_flags(const FuzzCommandOptions& options) {
  std::string flags;
  for (const std::string& path : options.simulation.map_paths) flags += " --map-path " + shell_quote(path);
  if (!options.simulation.ego_plugin.empty()) flags += " --ego-plugin " + shell_quote(options.simulation.ego_plugin);
  if (options.simulation.duration) flags += " --duration " + format_number(*options.simulation.duration);
  if (options.simulation.dt != 0.05) flags += " --dt " + format_number(options.simulation.dt);
  if (options.simulation.continue_after_collision) flags += " --continue-after-collision";
  return flags;
}

}  // namespace

std::string finding_number_text(std::size_t number) {
  std::ostringstream text;
  text << std::setw(3) << std::setfill('0') << number;
  return text.str();
}

SearchOutputs::SearchOutputs(const FuzzCommandOptions& options, const SourceFile& file,
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

std::string SearchOutputs::prepare() {
  std::error_code error;
  fs::create_directories(dir_ / "findings", error);
  if (error) return "cannot create '" + (dir_ / "findings").string() + "': " + error.message();
  return write_file_atomically(dir_ / "evaluations.csv", header_);
}

void SearchOutputs::record(const EvaluationRecord& record) {
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
    row += "," + (evaluation.judged() ? format_number(evaluation.robustness[k]) : std::string());
  row += "," + format_number(std::round(evaluation.wall_seconds * 1e6) / 1e6) + "," +
         csv_field(evaluation.feasible() ? evaluation.failure : evaluation.infeasible) + "\n";
  rows_ += row;
  for (std::size_t k = 0; k < objectives_.size() && evaluation.judged(); ++k) {
    if (best_.size() < objectives_.size()) best_.assign(objectives_.size(), INFINITY);
    best_[k] = std::min(best_[k], evaluation.robustness[k]);
  }
}

std::string SearchOutputs::write_finding(const Finding& finding, std::string& failure) {
  const ScenarioRun run = evaluator_.run(finding.point, finding.seed);
  if (!run.trace || run.verdicts.size() <= finding.objective) {
    failure = "finding " + std::to_string(finding.number) + " did not replay: " + run.infeasible +
              run.failure;
    return "";
  }
  const SpecVerdict& verdict = run.verdicts[finding.objective];
  const std::string extension = fs::path(file_.path()).extension().string();
  const std::string stem =
      finding_number_text(finding.number) + "-" + file_stem(finding.objective_name);
  const fs::path scenario_path =
      dir_ / "findings" / (stem + (extension.empty() ? ".avu" : extension));
  const std::string comment = comment_prefix(file_.path());
  std::string header = comment + "scenfuzz finding " + std::to_string(finding.number) + ": spec " +
                       finding.objective_name + " violated, robustness " +
                       format_number(verdict.robustness) + " at " +
                       format_number(std::round(verdict.time * 1000) / 1000) + " s";
  if (!verdict.atom_text.empty()) header += " (" + verdict.atom_text + ")";
  header += "\n" + comment + "from " + file_.path() + ", search seed " +
            std::to_string(options_.seed) + ", evaluation " + std::to_string(finding.evaluation) +
            " (" + options_.algorithm + ")";
  if (!finding.signature.empty()) header += ", collision " + finding.signature;
  header += "\n" + comment + "replay: scenfuzz run " + shell_quote(scenario_path.string()) +
            " --seed " + std::to_string(finding.seed) + simulation_flags(options_) + "\n";
  std::vector<std::string> lane_ids;
  for (const Lane& lane : run.map->lanes()) lane_ids.push_back(lane.id);
  const std::vector<std::pair<fs::path, std::string>> files = {
      {scenario_path, header + print_concrete_scenario(file_, scenario_, run.values)},
      {dir_ / "findings" / (stem + ".csv"), trace_csv(*run.trace, lane_ids)},
      {dir_ / "findings" / (stem + ".svg"), render_trace_svg(*run.map, *run.trace)},
  };
  for (const auto& [path, content] : files) {
    failure = write_file_atomically(path, content);
    if (!failure.empty()) return "";
  }
  if (verdict.robustness != finding.robustness)
    failure = "finding " + std::to_string(finding.number) + " replays with robustness " +
              format_number(verdict.robustness) + " instead of " +
              format_number(finding.robustness) + " (please report this)";
  written_.push_back(scenario_path.string());
  return scenario_path.string();
}

nlohmann::json SearchOutputs::summary(const SearchSummary& search, const FindingLog& log,
                                      bool complete) const {
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

std::string SearchOutputs::flush(const SearchSummary& search, const FindingLog& log,
                                 bool complete) {
  std::string failure = write_file_atomically(dir_ / "evaluations.csv", header_ + rows_);
  if (failure.empty())
    failure =
        write_file_atomically(dir_ / "summary.json", summary(search, log, complete).dump(2) + "\n");
  return failure;
}

}  // namespace scenfuzz
