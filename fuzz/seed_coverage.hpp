// What one seed scenario covers of the behaviour-coverage features (docs/coverage.md): a concrete
// seed by one simulation, a logical seed by a fixed, documented sample of its parameter space. The
// corpus tools (`scenfuzz coverage`, `scenfuzz cmin`) and the search's summary build on it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"

namespace scenfuzz {

struct SeedCoverageOptions {
  SimulationCommandOptions simulation;  // map paths, ego plugin, dt, ... as for `run`
  std::uint64_t seed = 0;               // --seed: the perception seed and the sample's
};

struct SeedCoverage {
  std::string path;
  // Sorted, unique feature names ("ego.turn_left", "interaction.pedestrian.FSR.closing_2_5.near").
  std::vector<std::string> features;
  std::size_t simulations = 0;        // how many simulations covering it took
  std::uint64_t simulated_steps = 0;  // their steps together: the seed's cost (cmin's tie-break)
  std::uintmax_t file_size = 0;       // bytes (cmin's first tie-break: smaller wins)
  bool logical = false;               // it has parameter ranges (covered by a sample)
  // Non-empty when the seed could not be covered: unreadable, parse errors (file:line:column),
  // no scenario, a map that cannot be loaded. Never thrown.
  std::string error;
};

// Covers one seed. Deterministic for given options; safe to call from several threads at once.
SeedCoverage cover_seed(const std::string& path, const SeedCoverageOptions& options);

}  // namespace scenfuzz
