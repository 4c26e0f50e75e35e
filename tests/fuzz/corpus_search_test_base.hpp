// The fixture of the end-to-end tests of a corpus folder (corpora/wmg, corpora/ch): a search of a
// corpus file with the issues' budget of 500, as a user runs it, and the expectation every corpus
// file meets, that such a search finishes cleanly at its budget with most points simulated.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz::test {

// The files of `folder` ending in `extension`, sorted.
inline std::vector<std::filesystem::path> corpus_files(const std::filesystem::path& folder,
                                                       const std::string& extension) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == extension) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

class CorpusSearchTest : public CommandTest {
 protected:
  // `scenfuzz --budget 500 --seed SEED -j 2 --quiet --out DIR/out EXTRA... SCENARIO`.
  Outcome fuzz(const std::filesystem::path& scenario, const std::string& seed,
               const std::vector<std::string>& extra = {}) {
    std::vector<std::string> arguments = {
        "--budget", "500", "--seed", seed, "-j", "2", "--quiet", "--out", (dir_ / "out").string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    arguments.push_back(scenario.string());
    return scenfuzz(arguments);
  }

  nlohmann::json summary() const {
    return nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  }

  // Each file searched to its budget: exit 0 or 1 (never bad input or an internal error), the
  // search complete, stopped by the budget, at least 400 of its 500 points simulated.
  void expect_searched_to_budget(const std::vector<std::filesystem::path>& files) {
    for (const std::filesystem::path& file : files) {
      std::filesystem::remove_all(dir_ / "out");
      const Outcome run = fuzz(file, "1");
      EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 1) << file << "\n" << run.err;
      if (run.exit_code > 1) continue;
      const nlohmann::json summary = this->summary();
      EXPECT_EQ(summary["complete"], true) << file;
      EXPECT_EQ(summary["stop"], "budget") << file;
      EXPECT_GE(summary["judged"].get<int>(), 400) << file << ": most points should simulate";
    }
  }
};

}  // namespace scenfuzz::test
