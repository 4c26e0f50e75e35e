// One search of a campaign: one arm (a seed and one of its specs) in one round, run in its own
// output folder exactly as `scenfuzz --out FOLDER --resume` runs it (a search killed earlier is
// continued from its journal, which gives the results of an uninterrupted one), and what the
// campaign records of it: the compact evaluations, the failure modes with their files, the
// simulations spent and the best robustness. It prints nothing and may run beside others.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/campaign_seeds.hpp"
#include "fuzz/search.hpp"

namespace scenfuzz {

struct CampaignSearchTask {
  std::size_t arm = 0;  // index into CampaignSeeds::arms
  std::uint64_t budget = 0;
  std::uint64_t seed = 0;   // the search's --seed
  std::size_t threads = 1;  // evaluations at once within the search
  std::string folder;       // its output folder, relative to the campaign folder
  double time_limit = 0;    // seconds of wall time left to the run; 0: none
};

// A failure mode as the search found it: its finding's scenario file (in the search's folder).
struct FoundMode {
  std::string signature;
  std::string spec;
  std::string responsibility;
  std::string finding_file;
  std::uint64_t seed = 0;  // the finding's evaluation seed, for the replay command
};

struct CampaignSearchResult {
  bool interrupted = false;  // stopped by `stop`: not to be recorded, continued next time
  std::string error;         // a message for the user: the search could not run or be written
  SearchSummary summary;
  std::vector<CampaignEvaluation> evaluations;
  std::vector<FoundMode> modes;  // in finding order
  std::optional<double> best;    // lowest robustness of the arm's spec
  // The behaviour-coverage features the search reached, sorted (its summary.json's "coverage").
  std::vector<std::string> coverage;
};

// The search's --seed: derived from [search] seed, the run, the round and the arm, so that each
// run explores anew and the same database content gives the same searches.
std::uint64_t campaign_search_seed(std::uint64_t base, std::int64_t run, std::int64_t round,
                                   std::int64_t seed_id, std::size_t spec);

// "searches/run-<run>/round-<round>/<seed id>-<spec index>".
std::string campaign_search_folder(std::int64_t run, std::int64_t round, std::int64_t seed_id,
                                   std::size_t spec);

// Runs `task`; `stop` is asked between batches (a signal, another search's error).
CampaignSearchResult run_campaign_search(const CampaignSeeds& seeds,
                                         const SimulationCommandOptions& simulation,
                                         const CampaignSearchTask& task,
                                         const std::function<bool()>& stop);

}  // namespace scenfuzz
