// load_report_data: the database's lists joined in memory (a campaign has thousands of rows, not
// millions, apart from evaluations, which are read one search at a time and reduced at once).
#include "fuzz/campaign/campaign_report_data.hpp"

#include <map>
#include <system_error>
#include <utility>

namespace scenfuzz {

namespace fs = std::filesystem;

std::vector<BestSoFar> best_so_far(const std::vector<std::optional<double>>& robustness) {
  std::vector<BestSoFar> steps;
  for (std::size_t i = 0; i < robustness.size(); ++i) {
    if (!robustness[i]) continue;
    if (steps.empty() || *robustness[i] < steps.back().best)
      steps.push_back({i + 1, *robustness[i]});
  }
  return steps;
}

namespace {

// modes/<hash>.svg beside modes/<hash>.<ext>, when it exists.
std::string picture_of(const fs::path& dir, const std::string& scenario_file) {
  if (scenario_file.empty()) return {};
  const fs::path picture = fs::path(scenario_file).replace_extension(".svg");
  std::error_code error;
  if (!fs::is_regular_file(dir / picture, error)) return {};
  return picture.generic_string();
}

// Each seed's searches in order, their robustness values concatenated: the seed's chart, its
// counts and where each run began; and each run's searches and simulations.
void add_searches(CampaignDb& db, std::map<std::int64_t, ReportSeed*>& seeds,
                  std::map<std::int64_t, ReportRun*>& runs) {
  std::map<std::int64_t, std::vector<std::optional<double>>> robustness;
  for (const CampaignSearch& search : db.list_searches()) {
    const std::vector<CampaignEvaluation> evaluations = db.list_evaluations(search.id);
    if (const auto run = runs.find(search.record.run_id); run != runs.end()) {
      ++run->second->searches;
      run->second->simulations += evaluations.size();
    }
    const auto seed = seeds.find(search.record.seed_id);
    if (seed == seeds.end()) continue;
    ReportSeed& shown = *seed->second;
    std::vector<std::optional<double>>& values = robustness[search.record.seed_id];
    if (shown.run_starts.empty() || shown.run_starts.back().run_id != search.record.run_id)
      shown.run_starts.push_back({search.record.run_id, values.size()});
    ++shown.searches;
    for (const CampaignEvaluation& evaluation : evaluations) {
      values.push_back(evaluation.robustness);
      if (evaluation.robustness) ++shown.judged;
    }
  }
  for (auto& [seed_id, values] : robustness) {
    seeds[seed_id]->simulations = values.size();
    seeds[seed_id]->best = best_so_far(values);
  }
}

// A mode's contribution to each run's counts (ReportRun says what they mean).
void count_in_runs(const CampaignFailureMode& mode, std::vector<ReportRun>& runs) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::int64_t id = runs[i].run.id;
    if (mode.first_seen_run == id) ++runs[i].modes_first_seen;
    if (mode.first_seen_run <= id && id <= mode.last_seen_run) ++runs[i].modes_seen;
    if (mode.status == FailureModeStatus::regressed && mode.last_seen_run == id)
      ++runs[i].regressed;
    const bool first_after_last_seen =
        runs[i].run.id > mode.last_seen_run && (i == 0 || runs[i - 1].run.id <= mode.last_seen_run);
    if (mode.status == FailureModeStatus::fixed && first_after_last_seen) ++runs[i].fixed;
  }
}

}  // namespace

ReportData load_report_data(CampaignDb& db, const fs::path& dir, const std::string& name) {
  ReportData data;
  data.name = name;
  std::map<std::int64_t, std::string> run_started;
  for (CampaignRun& run : db.list_runs()) {
    run_started[run.id] = run.started;
    ReportRun shown;
    shown.run = std::move(run);
    data.runs.push_back(std::move(shown));
  }
  for (CampaignSeed& seed : db.list_seeds()) {
    ReportSeed shown;
    shown.seed = std::move(seed);
    data.seeds.push_back(std::move(shown));
  }
  std::map<std::int64_t, ReportSeed*> seeds;
  for (ReportSeed& seed : data.seeds) seeds[seed.seed.id] = &seed;
  std::map<std::int64_t, ReportRun*> runs;
  for (ReportRun& run : data.runs) runs[run.run.id] = &run;
  add_searches(db, seeds, runs);
  for (CampaignFailureMode& mode : db.list_failure_modes()) {
    ReportFailureMode shown;
    shown.mode = std::move(mode);
    if (const auto seed = seeds.find(shown.mode.record.seed_id); seed != seeds.end()) {
      shown.seed_path = seed->second->seed.path;
      ++seed->second->failure_modes;
    }
    shown.first_seen_started = run_started[shown.mode.first_seen_run];
    shown.last_seen_started = run_started[shown.mode.last_seen_run];
    shown.picture = picture_of(dir, shown.mode.record.scenario_file);
    count_in_runs(shown.mode, data.runs);
    data.failure_modes.push_back(std::move(shown));
  }
  return data;
}

}  // namespace scenfuzz
