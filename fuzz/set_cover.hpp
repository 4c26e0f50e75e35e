// cmin's choice of seeds: a greedy set cover of the seeds' features. Each round keeps the seed that
// covers the most features not yet covered; ties go to the smaller file, then the cheaper seed
// (fewer simulated steps), then the path, so the choice is the same for the same coverage whatever
// order the coverage was computed in. Greedy is the classic approximation (within ln n of the
// smallest cover), as libFuzzer's -set_cover_merge.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fuzz/seed_coverage.hpp"

namespace scenfuzz {

struct SetCover {
  std::vector<std::size_t> kept;  // indices of the kept seeds, in the order they were chosen
  // Per seed: the features it was the first kept seed to cover (empty for a dropped seed).
  std::vector<std::vector<std::string>> new_features;
  // Per seed: the kept seeds (indices, in the order chosen) that first cover its features; for a
  // dropped seed, why it was dropped. Empty for a seed without features.
  std::vector<std::vector<std::size_t>> covered_by;
  std::size_t features = 0;  // how many features the seeds cover together
};

// The cover of `seeds` (their paths distinct); seeds with an error take no part.
SetCover greedy_set_cover(const std::vector<SeedCoverage>& seeds);

}  // namespace scenfuzz
