// A campaign run as its CI outputs describe it (the JUnit XML, --json and the exit status): the
// run, and every known failure mode with its status as this run left it and what this run
// learnt about it (found by a search, replayed, or neither).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/replay_outcome.hpp"

namespace scenfuzz {

struct RunFailureMode {
  CampaignFailureMode mode;  // as the database holds it at the end of the run
  std::string seed_path;     // its seed's, relative to the campaign folder
  // The regression replay's outcome, when the mode was replayed in this run (before a kill too).
  std::optional<ReplayOutcome> replay;
};

struct RunSummary {
  std::string campaign;  // [campaign] name
  CampaignRun run;
  std::uint64_t simulations = 0;  // in this run, the replay's included
  std::vector<RunFailureMode> failure_modes;
};

// Run `run_id` as the database holds it now: its failure modes (those known by the end of it)
// with their seeds' paths and this run's replay outcomes, read back from the replays table so
// that a run continued after a kill still knows the replays of its first part; and its
// simulations, its searches' plus its replays' perception seeds.
RunSummary load_run_summary(CampaignDb& db, std::int64_t run_id, const std::string& campaign);

// What this run learnt about a mode, which says whether its status is this run's verdict.
enum class RunEvidence {
  found,          // a search of this run found it (its status: new, still_failing or regressed)
  replayed,       // the replay simulated it (its status: the replay's, replay_status.hpp)
  replay_failed,  // the replay met an error and no search found it: its status is older
  none,           // neither replayed nor found in this run: its status is older
};

RunEvidence run_evidence(const RunSummary& summary, const RunFailureMode& mode);

}  // namespace scenfuzz
