// A campaign's seeds as a run searches them: every seed file read, parsed and set up once (all
// of them checked before anything runs), and the arms of the run, one per searchable seed and
// spec. A concrete seed (no parameter ranges) is searched by mutation ([search] mutate); one with
// nothing to mutate either is named in a warning and left out.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_config.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/scenario_evaluator.hpp"

namespace scenfuzz {

struct LoadedSeed {
  std::string path;          // as in the config: relative to the campaign folder
  std::string content_hash;  // of the bytes read
  std::string algorithm;     // [[seed]] algo, else [search] algo
  std::string scenario;      // [[seed]] scenario: which of the file's scenarios (--scenario)
  double budget_share = 1;
  std::int64_t id = 0;  // in the database; set once it is open
  // Behind pointers: the evaluator keeps references to the file and the scenario.
  std::unique_ptr<ScenarioFile> input;
  std::unique_ptr<ScenarioEvaluator> evaluator;
};

// One search target of the run: a seed and one of its specs (the evaluator's objectives).
struct CampaignArm {
  std::size_t seed = 0;  // index into CampaignSeeds::seeds
  std::size_t spec = 0;  // index into the seed's objectives
  std::string spec_name;
  double weight = 1;  // the seed's budget_share, split evenly over its specs
};

struct CampaignSeeds {
  std::vector<LoadedSeed> seeds;  // the searchable ones, in the config's order
  std::vector<CampaignArm> arms;  // by seed, then spec
};

// The simulation options every search of the campaign runs with: its maps and its ego.
SimulationCommandOptions campaign_simulation(const CampaignConfig& config);

// Reads and sets up every seed file (paths relative to the current folder, which the run makes
// the campaign folder). Every problem is printed to `err` (file:line:column for a scenario
// error); nullopt when there was an error in any of them.
std::optional<CampaignSeeds> load_campaign_seeds(const CampaignConfig& config,
                                                 const SimulationCommandOptions& simulation,
                                                 std::ostream& err);

}  // namespace scenfuzz
