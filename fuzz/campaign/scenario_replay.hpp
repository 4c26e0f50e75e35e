// Replaying a finding's concrete scenario file against the current ego with several perception
// seeds, judging each run exactly as the search judges an evaluation (ScenarioEvaluator, then
// FindingLog for the failure-mode key), and counting the runs that fail the same way: the same
// failure-mode key for the same spec. The regression replay of a campaign's known failure modes
// (regression_replay.hpp) is built on it; docs/campaigns.md, "Regression replay and CI outputs".
//
// This header deliberately includes neither fuzz/search.hpp nor campaign_db.hpp: both declare a
// scenfuzz::EvaluationRecord, so no file may include the two.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/campaign/replay_outcome.hpp"
#include "fuzz/commands.hpp"

namespace scenfuzz {

// Perception seeds per replay: enough to tell a failure that depends on the perception noise
// (only some seeds fail) from one that does not, at three simulations per known mode.
inline constexpr int kReplaySeeds = 3;

struct ReplaySettings {
  // The options the campaign's searches simulate with: map_paths (--map-path), ego_plugin
  // (--ego-plugin; empty: the reference driver) and the rest, as `scenfuzz run` takes them.
  SimulationCommandOptions simulation;
  int seeds = kReplaySeeds;
};

// What a replay looks for: the failure as the search recorded it.
struct ReplayTarget {
  std::filesystem::path scenario;  // the finding's concrete scenario file
  std::string spec;                // the violated spec (an ego failure: its kind, not compared)
  std::string signature;           // the failure-mode key, Finding::mode
};

// The seed the finding was simulated with, read from the `--seed N` of the scenario file's
// "replay: scenfuzz run ..." header line (search_outputs.cpp writes it); 0 when there is none
// (a scenario written by hand).
std::uint64_t finding_seed(std::string_view scenario_text);

// Which of the file's scenarios the finding is of: the `--scenario NAME` of the same line; empty
// when there is none (a file of one scenario).
std::string finding_scenario(std::string_view scenario_text);

// The perception seeds of a replay: the finding's own first, so that a failure that does not
// depend on the noise replays exactly, then derive_seed(own, 1), derive_seed(own, 2), ...
std::vector<std::uint64_t> replay_seeds(std::uint64_t own, int count);

// Simulates `target.scenario` once per replay seed and counts the runs that fail the same way.
// Never throws: a file that is missing or no longer reads, a map that cannot be loaded, a
// scenario that cannot be set up, or a run that cannot be judged (an ego plugin that cannot
// start, or one that crashes or hangs where the target is a spec's violation) is an error in the
// outcome, naming the file or the seed.
ReplayOutcome replay_scenario(const ReplayTarget& target, const ReplaySettings& settings);

}  // namespace scenfuzz
