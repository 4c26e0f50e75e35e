// run_campaign_search: a FolderSearch with the campaign's options for one arm, and the compact
// result the database records.
#include "fuzz/campaign/campaign_search.hpp"

#include "fuzz/folder_search.hpp"
#include "sampler/random.hpp"

namespace scenfuzz {

namespace {

FuzzCommandOptions search_command(const LoadedSeed& seed, const CampaignArm& arm,
                                  const SimulationCommandOptions& simulation,
                                  const CampaignSearchTask& task) {
  FuzzCommandOptions options;
  options.path = seed.path;
  options.budget = static_cast<std::size_t>(task.budget);
  options.algorithm = seed.algorithm;
  options.seed = task.seed;
  options.jobs = task.threads;
  options.time_limit = task.time_limit;
  options.specs = {arm.spec_name};
  options.out_dir = task.folder;
  options.resume = true;  // a search killed earlier continues from its journal
  options.quiet = true;
  options.simulation = simulation;
  options.choice.scenario = seed.scenario;
  return options;
}

// The compact record of one evaluation: the robustness of the arm's spec when judged, and
// whether it failed (a violated spec or an ego failure).
CampaignEvaluation compact(const EvaluationRecord& record, std::size_t spec) {
  CampaignEvaluation evaluation;
  evaluation.index = static_cast<std::int64_t>(record.index);
  if (record.evaluation.judged() && spec < record.evaluation.robustness.size())
    evaluation.robustness = record.evaluation.robustness[spec];
  evaluation.finding =
      !record.evaluation.violated.empty() || !record.evaluation.failure_kind.empty();
  return evaluation;
}

std::string problem_text(const FolderSearchEnd& end, const std::string& folder) {
  switch (end.problem) {
    case FolderSearchProblem::none: return "";
    case FolderSearchProblem::write_failed:
      return "scenfuzz: error: " + end.message + " (search in '" + folder + "')\n";
    case FolderSearchProblem::unjudgeable: return end.message;
    case FolderSearchProblem::journal_mismatch:
      return "scenfuzz: error: cannot continue the search in '" + folder + "': " + end.message +
             "; remove that folder to search afresh\n";
  }
  return "";
}

}  // namespace

std::uint64_t campaign_search_seed(std::uint64_t base, std::int64_t run, std::int64_t round,
                                   std::int64_t seed_id, std::size_t spec) {
  std::uint64_t seed = derive_seed(base, static_cast<std::uint64_t>(run));
  seed = derive_seed(seed, static_cast<std::uint64_t>(round));
  seed = derive_seed(seed, static_cast<std::uint64_t>(seed_id));
  return derive_seed(seed, spec);
}

std::string campaign_search_folder(std::int64_t run, std::int64_t round, std::int64_t seed_id,
                                   std::size_t spec) {
  return "searches/run-" + std::to_string(run) + "/round-" + std::to_string(round) + "/" +
         std::to_string(seed_id) + "-" + std::to_string(spec);
}

CampaignSearchResult run_campaign_search(const CampaignSeeds& seeds,
                                         const SimulationCommandOptions& simulation,
                                         const CampaignSearchTask& task,
                                         const std::function<bool()>& stop) {
  const CampaignArm& arm = seeds.arms[task.arm];
  const LoadedSeed& seed = seeds.seeds[arm.seed];
  const FuzzCommandOptions options = search_command(seed, arm, simulation, task);
  CampaignSearchResult result;
  FolderSearchEvents events;
  events.interrupted = stop;
  events.evaluation = [&result, &arm](const EvaluationRecord& record) {
    result.evaluations.push_back(compact(record, arm.spec));
  };
  FolderSearch search(options, *seed.input, *seed.evaluator, std::move(events));
  bool nothing_to_resume = false;
  if (std::string failure = search.claim(nothing_to_resume); !failure.empty()) {
    result.error = "scenfuzz: error: " + failure + "\n";
    return result;
  }
  SearchOptions plan = search_plan(options);
  plan.targets = {arm.spec};
  const FolderSearchEnd end = search.run(plan);
  result.summary = end.summary;
  result.error = problem_text(end, task.folder);
  result.interrupted = end.summary.stop == StopReason::interrupted;
  if (arm.spec < search.outputs().best().size()) result.best = search.outputs().best()[arm.spec];
  result.coverage.assign(search.outputs().coverage().begin(), search.outputs().coverage().end());
  for (const Finding& finding : search.log().findings()) {
    const auto file = search.finding_files().find(finding.number);
    if (search.outputs().lost(finding) || file == search.finding_files().end()) continue;
    result.modes.push_back({finding.mode.empty() ? finding.objective_name : finding.mode,
                            finding.objective_name, finding.responsibility, file->second,
                            finding.seed});
  }
  return result;
}

}  // namespace scenfuzz
