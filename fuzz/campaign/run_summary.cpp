// What a run learnt about each failure mode (run_summary.hpp).
#include "fuzz/campaign/run_summary.hpp"

#include <map>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

std::map<std::int64_t, ReplayOutcome> replays_in(CampaignDb& db, std::int64_t run_id) {
  std::map<std::int64_t, ReplayOutcome> outcomes;
  for (const CampaignReplay& replay : db.list_replays())
    if (replay.run_id == run_id)
      outcomes[replay.failure_mode_id] = {replay.tried, replay.failing, replay.error};
  return outcomes;
}

std::uint64_t simulations_in(CampaignDb& db, std::int64_t run_id) {
  std::uint64_t simulations = 0;
  for (const CampaignSearch& search : db.list_searches())
    if (search.record.run_id == run_id) simulations += search.record.simulations;
  for (const CampaignReplay& replay : db.list_replays())
    if (replay.run_id == run_id) simulations += static_cast<std::uint64_t>(replay.tried);
  return simulations;
}

}  // namespace

RunSummary load_run_summary(CampaignDb& db, std::int64_t run_id, const std::string& campaign) {
  RunSummary summary;
  summary.campaign = campaign;
  bool found = false;
  for (const CampaignRun& run : db.list_runs())
    if (run.id == run_id) {
      summary.run = run;
      found = true;
    }
  SCENFUZZ_DEMAND(found);  // the caller's own run
  summary.simulations = simulations_in(db, run_id);
  std::map<std::int64_t, std::string> seed_paths;
  for (const CampaignSeed& seed : db.list_seeds()) seed_paths[seed.id] = seed.path;
  std::map<std::int64_t, ReplayOutcome> replays = replays_in(db, run_id);
  for (const CampaignFailureMode& mode : db.list_failure_modes()) {
    if (mode.first_seen_run > run_id) continue;
    RunFailureMode entry{mode, seed_paths[mode.record.seed_id], std::nullopt};
    if (const auto replay = replays.find(mode.id); replay != replays.end())
      entry.replay = replay->second;
    summary.failure_modes.push_back(std::move(entry));
  }
  return summary;
}

RunEvidence run_evidence(const RunSummary& summary, const RunFailureMode& mode) {
  if (mode.mode.last_seen_run == summary.run.id) return RunEvidence::found;
  if (!mode.replay) return RunEvidence::none;
  if (!mode.replay->error.empty() || mode.replay->tried == 0) return RunEvidence::replay_failed;
  return RunEvidence::replayed;
}

}  // namespace scenfuzz
