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
#include "fuzz/campaign/mpi_pool.hpp"

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
  MpiSession* mpi = nullptr;  // under mpirun: the searches go to the other ranks (mpi_round.hpp)
  MpiPoolTimes mpi_times;
  bool tmin = false;  // [search] tmin: each new mode's representative minimised before recording
};

enum class RoundEnd { complete, wall_time, interrupted, failed };

// What became of one of a round's searches: its result, or that it never started (a stop or the
// wall time came first).
struct RoundSlot {
  bool skipped = false;
  CampaignSearchResult result;
};

// Records a round's searches in the round's order, whoever ran them and in whatever order they
// finished: after one left to be continued (interrupted, or cut by the wall time before it
// started) or one that failed, the later ones are not recorded either (their folders hold them,
// finished or not), so the database keeps the round's order.
class RoundRecorder {
 public:
  RoundRecorder(RoundContext& context, std::int64_t round) : context_(context), round_(round) {}

  // The next search of the round, in order.
  void take(const CampaignSearchTask& task, const RoundSlot& slot);

  RoundEnd end() const { return end_; }
  bool failed() const { return end_ == RoundEnd::failed; }

 private:
  RoundContext& context_;
  std::int64_t round_;
  RoundEnd end_ = RoundEnd::complete;
};

// Runs and records `tasks` (the round's searches not recorded yet, in arm order), each given
// the wall time left; `threads` of a task are filled in here.
RoundEnd run_round(RoundContext& context, std::int64_t round,
                   std::vector<CampaignSearchTask> tasks);

// The command that replays a mode's representative scenario from the campaign folder; `scenario`
// names which of the file's scenarios it is (empty: its only one).
std::string replay_command(const SimulationCommandOptions& simulation,
                           const std::string& scenario_file, std::uint64_t seed,
                           const std::string& scenario = "");

}  // namespace scenfuzz
