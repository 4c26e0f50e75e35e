// One round of a campaign run: its searches run side by side on a pool of workers, and each
// finished one recorded (its failure modes' files copied into DIR/modes/ first) in the round's
// order whatever order they finish in, so that ids, "new" counts and statuses do not depend on
// the number of workers. A search stopped by a signal is left to be continued; one stopped by
// the wall time is recorded as stopped.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/campaign_search.hpp"
#include "fuzz/campaign/campaign_seeds.hpp"

namespace scenfuzz {

struct RoundContext {
  CampaignDb& db;
  const CampaignSeeds& seeds;
  const SimulationCommandOptions& simulation;
  std::int64_t run = 0;
  std::size_t workers = 1;                                        // searches at once
  std::optional<std::chrono::steady_clock::time_point> deadline;  // the wall-time budget's end
  std::ostream& out;
  std::ostream& err;
};

enum class RoundEnd { complete, wall_time, interrupted, failed };

// Runs and records `tasks` (the round's searches not recorded yet, in arm order), each given
// the wall time left; `threads` of a task are filled in here.
RoundEnd run_round(RoundContext& context, std::int64_t round,
                   std::vector<CampaignSearchTask> tasks);

// The command that replays a mode's representative scenario from the campaign folder.
std::string replay_command(const SimulationCommandOptions& simulation,
                           const std::string& scenario_file, std::uint64_t seed);

}  // namespace scenfuzz
