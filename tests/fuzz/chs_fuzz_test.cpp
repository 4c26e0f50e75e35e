// CH-Scenario end to end, through the real executable as a user runs it: every corpora/ch file is
// searched by concrete-seed mutation with the budget of 500 and finishes cleanly, its
// other road users meet the ego as written, a finding is the user's file with its numbers
// replaced, which replays to its robustness, and an event's outcomes are both searched.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "corpus_search_test_base.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::slurp;

const fs::path kCorpus = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "ch";

std::vector<fs::path> corpus_files() { return test::corpus_files(kCorpus, ".chs"); }

class ChsFuzzTest : public test::CorpusSearchTest {};

TEST_F(ChsFuzzTest, EveryCorpusFileIsSearchedToTheEndOfItsBudget) {
  const std::vector<fs::path> files = corpus_files();
  ASSERT_GE(files.size(), 6u);
  expect_searched_to_budget(files);
}

TEST_F(ChsFuzzTest, EveryCorpusScenariosRoadUsersMeetTheEgoAsWritten) {
  for (const fs::path& file : corpus_files()) {
    const Outcome run = scenfuzz({"run", file.string(), "--json"});
    ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << file << "\n" << run.err;
    const nlohmann::json interaction = nlohmann::json::parse(run.out)["interaction"];
    EXPECT_EQ(interaction["actors_interact"], true) << file << "\n" << interaction.dump();
  }
}

TEST_F(ChsFuzzTest, AFindingIsTheUsersFileWithItsNumbersReplacedAndReplays) {
  const Outcome run = fuzz(kCorpus / "typhoon_narrow_road_minibus.chs", "1");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json findings = summary()["findings"];
  ASSERT_GE(findings.size(), 1u);
  const std::string scenario = findings[0]["file"].get<std::string>();
  EXPECT_EQ(fs::path(scenario).extension(), ".chs");
  const std::string text = slurp(scenario);
  // The user's own lines, the Chinese of the timestamp included, after the `#` header.
  EXPECT_NE(text.find("  road → name narrow_road\n"), std::string::npos) << text;
  EXPECT_NE(text.find("timestamp: 2022 年 1 月 30 日 "), std::string::npos) << text;
  EXPECT_NE(text.find("#   ego.init.speed = "), std::string::npos) << text;
  std::smatch replay;
  ASSERT_TRUE(
      std::regex_search(text, replay, std::regex("# replay: scenfuzz run (\\S+) --seed (\\d+)")));
  const Outcome replayed = scenfuzz(
      {"run", scenario, "--seed", replay[2].str(), "--json", "--out", (dir_ / "replay").string()});
  ASSERT_EQ(replayed.exit_code, 1) << replayed.err;
  const nlohmann::json judged = nlohmann::json::parse(replayed.out);
  bool same = false;
  for (const nlohmann::json& spec : judged["specs"])
    same |=
        std::abs(spec["robustness"].get<double>() - findings[0]["robustness"].get<double>()) < 1e-9;
  EXPECT_TRUE(same) << replayed.out << "\n" << findings[0].dump();
}

// A probabilistic event is a dimension of the search: both of its outcomes are simulated, and a
// finding says which it needed, written as a certainty so that it replays without a search.
TEST_F(ChsFuzzTest, BothOutcomesOfAnEventAreSearchedAndAFindingStatesItsProbability) {
  const Outcome run = fuzz(kCorpus / "parked_van_pulls_out.chs", "1");
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
  const std::string evaluations = slurp(dir_ / "out" / "evaluations.csv");
  for (const char* outcome : {",fires,", ",does not fire,"})
    EXPECT_NE(evaluations.find(outcome), std::string::npos) << outcome;
  for (const nlohmann::json& finding : summary()["findings"]) {
    const std::string text = slurp(finding["file"].get<std::string>());
    EXPECT_TRUE(std::regex_search(
        text,
        std::regex("#   constraint1\\.event = (fires|does not fire) \\(probability 0\\.[37]\\)")))
        << text;
    EXPECT_NE(text.find("# the events' outcomes chosen have probability "), std::string::npos);
    EXPECT_TRUE(std::regex_search(text, std::regex("\n    probability: [01]\n"))) << text;
  }
}

}  // namespace
}  // namespace scenfuzz
