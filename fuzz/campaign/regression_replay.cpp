// The regression replay of one known failure mode (regression_replay.hpp).
#include "fuzz/campaign/regression_replay.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;

// A path as the campaign writes it: relative to the campaign folder unless absolute.
std::string in_campaign(const fs::path& campaign_dir, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (campaign_dir / path).string();
}

}  // namespace

ReplayOutcome replay_failure_mode(const fs::path& campaign_dir, const CampaignFailureMode& mode,
                                  const ReplaySettings& settings) {
  ReplaySettings resolved = settings;
  SimulationCommandOptions& simulation = resolved.simulation;
  simulation.ego_plugin = in_campaign(campaign_dir, simulation.ego_plugin);
  for (std::string& path : simulation.map_paths) path = in_campaign(campaign_dir, path);
  const ReplayTarget target{in_campaign(campaign_dir, mode.record.scenario_file), mode.record.spec,
                            mode.record.signature};
  if (mode.record.scenario_file.empty())
    return {0, 0, "failure mode " + std::to_string(mode.id) + " has no scenario file"};
  return replay_scenario(target, resolved);
}

}  // namespace scenfuzz
