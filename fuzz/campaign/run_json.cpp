// The --json summary of a campaign run (run_json.hpp).
#include "fuzz/campaign/run_json.hpp"

#include <string>

#include "fuzz/campaign/run_exit_status.hpp"

namespace scenfuzz {

namespace {

nlohmann::json optional_text(const std::string& text) {
  return text.empty() ? nlohmann::json(nullptr) : nlohmann::json(text);
}

nlohmann::json replay_json(const ReplayOutcome& replay) {
  if (!replay.error.empty()) return {{"error", replay.error}};
  return {{"tried", replay.tried}, {"failing", replay.failing}};
}

nlohmann::json mode_json(const RunFailureMode& entry) {
  const FailureModeRecord& record = entry.mode.record;
  nlohmann::json mode = {{"id", entry.mode.id},
                         {"seed", entry.seed_path},
                         {"spec", record.spec},
                         {"signature", record.signature},
                         {"responsibility", optional_text(record.responsibility)},
                         {"status", std::string(status_name(entry.mode.status))},
                         {"scenario_file", record.scenario_file},
                         {"replay_command", record.replay_command},
                         {"first_seen_run", entry.mode.first_seen_run},
                         {"last_seen_run", entry.mode.last_seen_run}};
  mode["replay"] = entry.replay ? replay_json(*entry.replay) : nlohmann::json(nullptr);
  return mode;
}

// The group a mode is listed in.
std::string group_of(const RunSummary& summary, const RunFailureMode& entry) {
  switch (run_evidence(summary, entry)) {
    case RunEvidence::replay_failed: return "replay_errors";
    case RunEvidence::none: return "not_replayed";
    case RunEvidence::found:
    case RunEvidence::replayed: break;
  }
  return std::string(status_name(entry.mode.status));
}

}  // namespace

nlohmann::json run_json(const RunSummary& summary) {
  nlohmann::json groups = nlohmann::json::object();
  for (FailureModeStatus status :
       {FailureModeStatus::new_mode, FailureModeStatus::still_failing, FailureModeStatus::fixed,
        FailureModeStatus::flaky, FailureModeStatus::regressed})
    groups[std::string(status_name(status))] = nlohmann::json::array();
  groups["replay_errors"] = nlohmann::json::array();
  groups["not_replayed"] = nlohmann::json::array();
  for (const RunFailureMode& entry : summary.failure_modes)
    groups[group_of(summary, entry)].push_back(mode_json(entry));

  const CampaignRun& run = summary.run;
  return {{"campaign", summary.campaign},
          {"run",
           {{"id", run.id},
            {"started", run.started},
            {"ended", optional_text(run.ended)},
            {"ego_version", run.ego_version}}},
          {"simulations", summary.simulations},
          {"exit_status", run_exit_status(summary)},
          {"exit_reason", run_exit_reason(summary)},
          {"failure_modes", groups}};
}

}  // namespace scenfuzz
