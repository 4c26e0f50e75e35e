// load_report_data: the database's lists joined in memory (a campaign has thousands of rows, not
// millions, apart from evaluations, which are read one search at a time and reduced at once).
#include "fuzz/campaign/campaign_report_data.hpp"

#include <map>
#include <set>
#include <system_error>
#include <utility>

#include "fuzz/campaign/mode_files.hpp"

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

// modes/<hash>.min.<ext> beside modes/<hash>.<ext> ([search] tmin), when it exists.
std::string minimised_of(const fs::path& dir, const std::string& scenario_file) {
  if (scenario_file.empty()) return {};
  const std::string minimised = minimised_mode_file(scenario_file);
  std::error_code error;
  return fs::is_regular_file(dir / minimised, error) ? minimised : std::string();
}

// The features each seed's searches reached together, and the whole corpus's.
void add_coverage(CampaignDb& db, const std::vector<CampaignSearch>& searches,
                  std::map<std::int64_t, ReportSeed*>& seeds, ReportData& data) {
  std::map<std::int64_t, std::set<std::string>> by_seed;
  std::set<std::string> corpus;
  for (const CampaignSearch& search : searches) {
    const std::vector<std::string> features = db.list_coverage(search.id);
    by_seed[search.record.seed_id].insert(features.begin(), features.end());
    corpus.insert(features.begin(), features.end());
  }
  for (const auto& [seed_id, features] : by_seed)
    if (const auto seed = seeds.find(seed_id); seed != seeds.end())
      seed->second->features = features.size();
  data.corpus_features = corpus.size();
}

// Each seed's searches in order, their robustness values concatenated: the seed's chart, its
// counts and where each run began; and each run's searches and simulations.
void add_searches(CampaignDb& db, const std::vector<CampaignSearch>& searches,
                  std::map<std::int64_t, ReportSeed*>& seeds,
                  std::map<std::int64_t, ReportRun*>& runs) {
  std::map<std::int64_t, std::vector<std::optional<double>>> robustness;
  for (const CampaignSearch& search : searches) {
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

// What the database recorded a run doing to the modes: the replay verdicts and the sightings.
struct RunEvents {
  std::map<std::int64_t, std::map<std::int64_t, std::string>> verdicts;  // run -> mode -> verdict
  std::map<std::int64_t, std::set<std::int64_t>> found;                  // run -> modes found
};

RunEvents run_events(CampaignDb& db) {
  RunEvents events;
  for (const CampaignReplay& replay : db.list_replays())
    events.verdicts[replay.run_id][replay.failure_mode_id] = replay.verdict;
  for (const CampaignSighting& sighting : db.list_sightings())
    events.found[sighting.run_id].insert(sighting.failure_mode_id);
  return events;
}

bool found_in(const RunEvents& events, const CampaignFailureMode& mode, std::int64_t run) {
  // A mode is first and last seen by being found, whether or not its sighting was recorded.
  if (run == mode.first_seen_run || run == mode.last_seen_run) return true;
  const auto found = events.found.find(run);
  return found != events.found.end() && found->second.count(mode.id) > 0;
}

// The verdict of the mode's replay in `run` when it set a status (not "error", "not_replayed").
std::optional<FailureModeStatus> replay_set(const RunEvents& events, std::int64_t mode,
                                            std::int64_t run) {
  const auto in_run = events.verdicts.find(run);
  if (in_run == events.verdicts.end()) return std::nullopt;
  const auto verdict = in_run->second.find(mode);
  if (verdict == in_run->second.end()) return std::nullopt;
  for (const FailureModeStatus status :
       {FailureModeStatus::still_failing, FailureModeStatus::regressed, FailureModeStatus::fixed,
        FailureModeStatus::flaky})
    if (verdict->second == status_name(status)) return status;
  return std::nullopt;
}

void count_status(ReportRun& run, FailureModeStatus status) {
  switch (status) {
    case FailureModeStatus::new_mode:
      ++run.modes_first_seen;
      ++run.modes_seen;
      break;
    case FailureModeStatus::still_failing: ++run.modes_seen; break;
    case FailureModeStatus::regressed:
      ++run.regressed;
      ++run.modes_seen;
      break;
    case FailureModeStatus::fixed: ++run.fixed; break;
    case FailureModeStatus::flaky: ++run.flaky; break;
  }
}

// A mode's contribution to each run's counts: its statuses replayed run by run, the replay's
// verdict first, then a search's finding (campaign_db.hpp's upsert_failure_mode rule).
void count_in_runs(const CampaignFailureMode& mode, const RunEvents& events,
                   std::vector<ReportRun>& runs) {
  FailureModeStatus status = FailureModeStatus::new_mode;
  for (ReportRun& run : runs) {
    const std::int64_t id = run.run.id;
    if (id < mode.first_seen_run) continue;
    const std::optional<FailureModeStatus> replayed = replay_set(events, mode.id, id);
    if (replayed) status = *replayed;
    const bool regressed_by_replay = replayed == FailureModeStatus::regressed;
    const bool found = found_in(events, mode, id);
    if (found && id == mode.first_seen_run)
      status = FailureModeStatus::new_mode;
    else if (found && status == FailureModeStatus::fixed)
      status = FailureModeStatus::regressed;
    else if (found && !(status == FailureModeStatus::regressed && regressed_by_replay))
      status = FailureModeStatus::still_failing;
    if (found || replayed) count_status(run, status);
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
  const std::vector<CampaignSearch> searches = db.list_searches();
  add_searches(db, searches, seeds, runs);
  add_coverage(db, searches, seeds, data);
  const RunEvents events = run_events(db);
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
    shown.minimised = minimised_of(dir, shown.mode.record.scenario_file);
    count_in_runs(shown.mode, events, data.runs);
    data.failure_modes.push_back(std::move(shown));
  }
  return data;
}

}  // namespace scenfuzz
