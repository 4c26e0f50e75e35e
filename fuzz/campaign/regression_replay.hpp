// The regression replay that starts every campaign run: each known failure mode's representative
// concrete scenario (DIR/modes/<hash>.<ext>) is simulated again against the current ego with
// several perception seeds (scenario_replay.hpp), and replay_status.hpp turns the tally into its
// status for this run. docs/campaigns.md, "Regression replay and CI outputs".
#pragma once

#include <filesystem>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/replay_outcome.hpp"
#include "fuzz/campaign/scenario_replay.hpp"

namespace scenfuzz {

// Replays `mode` (its scenario_file, signature and spec) with `settings`. Relative paths, in the
// mode's scenario_file and in settings' ego plugin and map paths, are relative to `campaign_dir`,
// as the database and campaign.toml write them. Never throws (replay_scenario).
ReplayOutcome replay_failure_mode(const std::filesystem::path& campaign_dir,
                                  const CampaignFailureMode& mode, const ReplaySettings& settings);

}  // namespace scenfuzz
