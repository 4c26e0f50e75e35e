// greedy_set_cover, lazily: a seed's count of uncovered features only falls as seeds are kept, so
// a seed whose stale count is still right when it tops the queue is the round's best (Minoux's
// lazy greedy); the result is exactly the eager greedy's, in far fewer counts.
#include "fuzz/set_cover.hpp"

#include <algorithm>
#include <map>
#include <queue>

#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

// The seeds' features as small integers, so counting uncovered ones is a table look-up.
std::vector<std::vector<std::size_t>> interned_features(const std::vector<SeedCoverage>& seeds,
                                                        std::vector<std::string>& names) {
  std::map<std::string, std::size_t> ids;
  std::vector<std::vector<std::size_t>> features(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (!seeds[i].error.empty()) continue;
    for (const std::string& feature : seeds[i].features) {
      auto [at, added] = ids.emplace(feature, names.size());
      if (added) names.push_back(feature);
      features[i].push_back(at->second);
    }
    std::sort(features[i].begin(), features[i].end());
    features[i].erase(std::unique(features[i].begin(), features[i].end()), features[i].end());
  }
  return features;
}

struct Candidate {
  std::size_t gain = 0;  // uncovered features when last counted
  std::size_t seed = 0;
};

// Whether `a` is a worse choice than `b`: fewer new features, then larger, costlier, later path.
struct WorseChoice {
  const std::vector<SeedCoverage>* seeds;
  bool operator()(const Candidate& a, const Candidate& b) const {
    if (a.gain != b.gain) return a.gain < b.gain;
    const SeedCoverage& x = (*seeds)[a.seed];
    const SeedCoverage& y = (*seeds)[b.seed];
    if (x.file_size != y.file_size) return x.file_size > y.file_size;
    if (x.simulated_steps != y.simulated_steps) return x.simulated_steps > y.simulated_steps;
    return x.path > y.path;
  }
};

std::size_t uncovered(const std::vector<std::size_t>& features, const std::vector<char>& covered) {
  return static_cast<std::size_t>(std::count_if(features.begin(), features.end(),
                                                [&covered](std::size_t f) { return !covered[f]; }));
}

// Which kept seeds (in the order chosen) first cover the features of each seed.
void explain_drops(const std::vector<std::vector<std::size_t>>& features,
                   const std::vector<std::size_t>& first_cover, SetCover& cover) {
  std::vector<std::size_t> rank(features.size(), 0);
  for (std::size_t k = 0; k < cover.kept.size(); ++k) rank[cover.kept[k]] = k;
  for (std::size_t i = 0; i < features.size(); ++i) {
    std::vector<std::size_t>& by = cover.covered_by[i];
    for (std::size_t f : features[i]) by.push_back(first_cover[f]);
    std::sort(by.begin(), by.end(),
              [&rank](std::size_t a, std::size_t b) { return rank[a] < rank[b]; });
    by.erase(std::unique(by.begin(), by.end()), by.end());
  }
}

}  // namespace

SetCover greedy_set_cover(const std::vector<SeedCoverage>& seeds) {
  std::vector<std::string> names;
  const std::vector<std::vector<std::size_t>> features = interned_features(seeds, names);
  SetCover cover;
  cover.features = names.size();
  cover.new_features.resize(seeds.size());
  cover.covered_by.resize(seeds.size());
  std::vector<char> covered(names.size(), 0);
  std::vector<std::size_t> first_cover(names.size(), 0);
  std::priority_queue<Candidate, std::vector<Candidate>, WorseChoice> queue(WorseChoice{&seeds});
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (!features[i].empty()) queue.push({features[i].size(), i});
  while (!queue.empty()) {
    Candidate best = queue.top();
    queue.pop();
    const std::size_t gain = uncovered(features[best.seed], covered);
    SCENFUZZ_DEMAND(gain <= best.gain);
    if (gain == 0) continue;  // it can only fall further: dropped
    if (gain < best.gain) {
      queue.push({gain, best.seed});
      continue;
    }
    cover.kept.push_back(best.seed);
    for (std::size_t f : features[best.seed]) {
      if (covered[f]) continue;
      covered[f] = 1;
      first_cover[f] = best.seed;
      cover.new_features[best.seed].push_back(names[f]);
    }
    std::sort(cover.new_features[best.seed].begin(), cover.new_features[best.seed].end());
  }
  explain_drops(features, first_cover, cover);
  return cover;
}

}  // namespace scenfuzz
