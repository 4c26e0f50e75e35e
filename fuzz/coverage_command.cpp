// `scenfuzz coverage FILE|DIR...`: the behaviour coverage of a corpus. Every entry is expanded to
// its scenario files (fuzz/seed_paths), each file covered on its own (fuzz/seed_coverage, in
// parallel with -j, each result kept in its seed's slot so the output never depends on -j), then
// the features are listed with the seeds that cover them, and the seeds with errors with those.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/seed_coverage.hpp"
#include "fuzz/seed_paths.hpp"

namespace scenfuzz {
namespace {

// Every file the entries stand for, in the order given (each folder's files sorted), each once;
// an entry that stands for none is a seed with an error.
std::vector<SeedCoverage> expand_entries(const std::vector<std::string>& entries) {
  std::vector<SeedCoverage> seeds;
  std::vector<std::string> seen;
  for (const std::string& entry : entries) {
    std::error_code missing;
    SeedExpansion expansion;
    if (!std::filesystem::exists(entry, missing))
      expansion.error = "'" + entry + "' does not exist";
    else
      expansion = expand_seed_entry(".", entry);
    if (!expansion.error.empty()) {
      SeedCoverage bad;
      bad.path = entry;
      bad.error = expansion.error;
      seeds.push_back(std::move(bad));
      continue;
    }
    for (const std::string& file : expansion.files) {
      if (std::find(seen.begin(), seen.end(), file) != seen.end()) continue;
      seen.push_back(file);
      SeedCoverage seed;
      seed.path = file;
      seeds.push_back(std::move(seed));
    }
  }
  return seeds;
}

void cover_all(std::vector<SeedCoverage>& seeds, const CoverageCommandOptions& options) {
  const SeedCoverageOptions seed_options{options.simulation, options.seed};
  const int threads =
      options.jobs == 0 ? tbb::info::default_concurrency() : static_cast<int>(options.jobs);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t k) {
      if (seeds[k].error.empty()) seeds[k] = cover_seed(seeds[k].path, seed_options);
    });
  });
}

// Feature -> the seeds covering it, in seed order.
std::map<std::string, std::vector<std::string>> covering_seeds(
    const std::vector<SeedCoverage>& seeds) {
  std::map<std::string, std::vector<std::string>> by_feature;
  for (const SeedCoverage& seed : seeds)
    for (const std::string& feature : seed.features) by_feature[feature].push_back(seed.path);
  return by_feature;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::string padded(std::string text, std::size_t width) {
  if (text.size() < width) text.append(width - text.size(), ' ');
  return text;
}

void print_seeds(const std::vector<SeedCoverage>& seeds, std::ostream& out) {
  std::size_t width = 4;
  for (const SeedCoverage& seed : seeds) width = std::max(width, seed.path.size());
  out << padded("SEED", width) << "  KIND      SIMULATIONS  FEATURES\n";
  for (const SeedCoverage& seed : seeds) {
    if (!seed.error.empty()) continue;
    out << padded(seed.path, width) << "  " << padded(seed.logical ? "logical" : "concrete", 8)
        << "  " << padded(std::to_string(seed.simulations), 11) << "  " << seed.features.size()
        << "\n";
  }
}

void print_errors(const std::vector<SeedCoverage>& seeds, std::ostream& out) {
  bool any = false;
  for (const SeedCoverage& seed : seeds) {
    if (seed.error.empty()) continue;
    if (!any) out << "\nseeds with errors (not covered):\n";
    any = true;
    out << "  " << seed.path << ":\n";
    std::string line;
    for (char c : seed.error + "\n") {
      if (c != '\n') {
        line += c;
        continue;
      }
      out << "    " << line << "\n";
      line.clear();
    }
  }
}

void print_features(const std::map<std::string, std::vector<std::string>>& by_feature,
                    std::ostream& out) {
  std::size_t width = 7;
  for (const auto& [feature, paths] : by_feature) width = std::max(width, feature.size());
  out << "\n" << padded("FEATURE", width) << "  SEEDS  COVERED BY\n";
  for (const auto& [feature, paths] : by_feature)
    out << padded(feature, width) << "  " << padded(std::to_string(paths.size()), 5) << "  "
        << joined(paths) << "\n";
}

void print_table(const std::vector<SeedCoverage>& seeds, std::ostream& out) {
  const auto by_feature = covering_seeds(seeds);
  const auto covered = static_cast<std::size_t>(std::count_if(
      seeds.begin(), seeds.end(), [](const SeedCoverage& s) { return s.error.empty(); }));
  out << by_feature.size() << " features covered by " << covered << " of " << seeds.size()
      << " seeds\n";
  if (covered > 0) {
    out << "\n";
    print_seeds(seeds, out);
  }
  if (!by_feature.empty()) print_features(by_feature, out);
  print_errors(seeds, out);
}

void print_json(const std::vector<SeedCoverage>& seeds, std::ostream& out) {
  nlohmann::json entries = nlohmann::json::array();
  for (const SeedCoverage& seed : seeds) {
    nlohmann::json entry = {{"path", seed.path}};
    if (!seed.error.empty()) {
      entry["error"] = seed.error;
    } else {
      entry["logical"] = seed.logical;
      entry["simulations"] = seed.simulations;
      entry["simulated_steps"] = seed.simulated_steps;
      entry["file_size"] = seed.file_size;
      entry["features"] = seed.features;
    }
    entries.push_back(std::move(entry));
  }
  nlohmann::json features = nlohmann::json::object();
  for (const auto& [feature, paths] : covering_seeds(seeds)) features[feature] = paths;
  out << nlohmann::json{{"seeds", entries}, {"features", features}}.dump(2) << "\n";
}

}  // namespace

int run_coverage(const CoverageCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<SeedCoverage> seeds = expand_entries(options.paths);
  cover_all(seeds, options);
  if (options.json)
    print_json(seeds, out);
  else
    print_table(seeds, out);
  const bool any_covered = std::any_of(seeds.begin(), seeds.end(),
                                       [](const SeedCoverage& s) { return s.error.empty(); });
  if (!any_covered) {
    err << "scenfuzz: error: no seed could be covered\n";
    return kExitBadInput;
  }
  return kExitSuccess;
}

}  // namespace scenfuzz
