// `scenfuzz campaign run DIR`: one run of the campaign DIR/campaign.toml describes. It locks the
// campaign, continues the run a kill or a signal left unfinished (or begins one), replays the
// known failure modes against the current ego, then searches the seeds x specs in rounds whose
// budgets the schedule (budget_schedule.hpp) decides from complete earlier rounds, several
// searches side by side, each recorded with its failure modes in one transaction in the round's
// order, so that the database ends the same for any -j and after any number of kills.
// docs/campaigns.md describes the run, its folder layout, signals and exit statuses.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>

#include "fuzz/campaign/campaign_config.hpp"
#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/mpi_pool.hpp"
#include "fuzz/campaign/replay_outcome.hpp"

namespace scenfuzz {

struct CampaignRunOptions {
  std::string dir;                    // DIR: the campaign folder
  std::optional<std::uint64_t> jobs;  // -j: searches at once; overrides [search] jobs; 0: cores
  std::string junit;                  // --junit FILE: the run as JUnit XML; empty: none
  // --json: the run's summary (run_json.hpp) as the one line on `out`; the progress lines go to
  // `err` instead, so that a script can read `out` whole.
  bool json = false;
  // --worker-timeout: under mpirun, seconds a worker rank may stay silent before its search goes
  // to another (mpi_pool.hpp).
  double worker_timeout = MpiPoolTimes{}.dead_after_seconds;
};

// Replays one known failure mode against the current ego (called with the campaign folder as
// the current folder).
using ModeReplayer = std::function<ReplayOutcome(const CampaignFailureMode&)>;

// The regression replay a campaign's run makes: each mode replayed (regression_replay.hpp) with
// the options its searches simulate with (its map paths and ego plugin, campaign_simulation).
ModeReplayer campaign_replayer(const CampaignConfig& config);

// Runs the campaign. kExitSuccess: the run ended (or was interrupted) without a new failure mode
// or a regression; kExitViolated: it found one (run_exit_status.hpp); kExitBadInput:
// campaign.toml or a seed has errors, another run holds the campaign, the run failed, or the
// JUnit file cannot be written (the reason on `err`). SIGINT and SIGTERM stop it after the
// batches in flight with every finished search recorded; the next run continues it. The current
// folder is the campaign folder while it runs, and restored after.
int run_campaign(const CampaignRunOptions& options, std::ostream& out, std::ostream& err);

// The same with another replayer than campaign_replayer's (tests: a replay whose verdicts they
// choose).
int run_campaign(const CampaignRunOptions& options, const ModeReplayer& replay, std::ostream& out,
                 std::ostream& err);

}  // namespace scenfuzz
