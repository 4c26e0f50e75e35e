// load_campaign_seeds: every seed read, parsed, set up and checked once, and the run's arms.
#include "fuzz/campaign/campaign_seeds.hpp"

#include <filesystem>

#include "fuzz/content_hash.hpp"
#include "fuzz/options.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/seed_paths.hpp"
#include "lang/number_format.hpp"
#include "physics/map/map_source.hpp"
#include "sampler/mutation_space.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

const CampaignSeedOverride* override_of(const CampaignConfig& config, const std::string& path) {
  for (const CampaignSeedOverride& entry : config.seed_overrides)
    if (seed_key(entry.path) == seed_key(path)) return &entry;
  return nullptr;
}

// The seed set up for searching; nullopt after an error on `err`. `searchable` is false (and
// a warning printed) for a concrete scenario.
std::optional<LoadedSeed> load_seed(const CampaignConfig& config,
                                    const SimulationCommandOptions& simulation,
                                    const std::string& path, bool& searchable, std::ostream& err) {
  LoadedSeed seed;
  seed.path = path;
  const CampaignSeedOverride* own = override_of(config, path);
  if (own) seed.scenario = own->scenario;
  std::optional<ScenarioFile> input =
      read_scenario(path, "search", err, ScenarioChoiceOptions{seed.scenario});
  if (!input) return std::nullopt;
  if (searched_by_mutation(input->scenario))
    input->scenario =
        derive_mutation_space(input->scenario, mutation_sizes({config.search.mutate}).sizes);
  seed.input = std::make_unique<ScenarioFile>(std::move(*input));
  seed.content_hash = content_hash(seed.input->file.text());
  apply_scenario_overrides(simulation, seed.input->scenario);
  try {
    std::vector<fs::path> map_paths(simulation.map_paths.begin(), simulation.map_paths.end());
    seed.evaluator = std::make_unique<ScenarioEvaluator>(seed.input->file, seed.input->scenario,
                                                         map_search_path(map_paths),
                                                         simulation_options(simulation));
    seed.evaluator->set_judge_options(judge_options(simulation));
  } catch (const MapError& error) {
    err << "scenfuzz: error: " << path << ": " << error.what() << "\n";
    return std::nullopt;
  }
  searchable = !seed.evaluator->space().dimensions.empty();
  if (!searchable) {
    err << "scenfuzz: warning: seed '" << path
        << "' has neither parameter ranges nor values to mutate: it is left out of the run\n";
    return seed;
  }
  const SetupProbe probe =
      seed.evaluator->probe(std::vector<double>(seed.evaluator->space().dimensions.size(), 0.5));
  err << format_diagnostics(seed.input->file, probe.warnings);
  if (probe.duration && !simulation.duration)
    if (const std::optional<std::string> problem =
            check_step_count(*probe.duration, simulation.dt,
                             path + "'s duration of " + format_number(*probe.duration) + " s")) {
      err << "scenfuzz: error: " << *problem << "\n";
      return std::nullopt;
    }
  seed.algorithm = own && own->algorithm ? *own->algorithm : config.search.algorithm;
  seed.budget_share = own ? own->budget_share : 1;
  return seed;
}

}  // namespace

SimulationCommandOptions campaign_simulation(const CampaignConfig& config) {
  SimulationCommandOptions simulation;
  simulation.map_paths = config.map_paths;
  simulation.ego_plugin = config.ego_plugin;
  return simulation;
}

std::optional<CampaignSeeds> load_campaign_seeds(const CampaignConfig& config,
                                                 const SimulationCommandOptions& simulation,
                                                 std::ostream& err) {
  CampaignSeeds seeds;
  bool failed = false;
  for (const std::string& path : config.seed_files) {
    bool searchable = false;
    std::optional<LoadedSeed> seed = load_seed(config, simulation, path, searchable, err);
    if (!seed) failed = true;
    if (seed && searchable) seeds.seeds.push_back(std::move(*seed));
  }
  if (failed) return std::nullopt;
  for (std::size_t s = 0; s < seeds.seeds.size(); ++s) {
    const std::vector<std::string> specs = seeds.seeds[s].evaluator->objectives();
    for (std::size_t k = 0; k < specs.size(); ++k)
      seeds.arms.push_back(
          {s, k, specs[k], seeds.seeds[s].budget_share / static_cast<double>(specs.size())});
  }
  return seeds;
}

}  // namespace scenfuzz
