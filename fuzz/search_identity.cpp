#include "fuzz/search_identity.hpp"

#include "fuzz/content_hash.hpp"

namespace scenfuzz {

nlohmann::json search_identity(const FuzzCommandOptions& options, const SourceFile& file) {
  const SimulationCommandOptions& simulation = options.simulation;
  nlohmann::json identity = {
      {"version", SCENFUZZ_VERSION},
      {"scenario", file.path()},
      {"scenario_hash", content_hash(file.text())},
      {"algorithm", options.algorithm},
      {"seed", options.seed},
      {"budget", options.budget},
      {"specs", options.specs},
      {"target", options.target},
      {"mutate", options.mutation.mutate},
      {"map_paths", simulation.map_paths},
      {"ego_plugin", simulation.ego_plugin},
      {"duration", simulation.duration ? nlohmann::json(*simulation.duration) : nullptr},
      {"dt", simulation.dt},
      {"continue_after_collision", simulation.continue_after_collision},
      {"npc_behaviour", simulation.npc_behaviour},
      {"all_collisions", simulation.all_collisions},
      {"rss", simulation.rss},
      {"ego_step_timeout", simulation.ego_step_timeout},
      {"ego_start_timeout", simulation.ego_start_timeout}};
  // Only when given, so that the searches of files with one scenario keep their identity.
  if (!options.choice.scenario.empty()) identity["scenario_choice"] = options.choice.scenario;
  return identity;
}

std::string identity_difference(const nlohmann::json& stored, const nlohmann::json& now) {
  for (const auto& [key, value] : now.items()) {
    if (key == "scenario") continue;  // the same file may be named from another folder
    if (!stored.contains(key)) return "it has no " + key;
    if (stored[key] == value) continue;
    if (key == "scenario_hash") return "the scenario file has changed since";
    return "its " + key + " was " + stored[key].dump() + ", now " + value.dump();
  }
  return {};
}

}  // namespace scenfuzz
