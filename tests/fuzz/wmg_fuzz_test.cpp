// WMG SDL end to end, through the real executable as a user runs it: every corpora/wmg file (both
// levels) is searched with the budget of 500 and finishes cleanly, and its actors meet
// the ego at the centre of its space; the cut-in yields findings, written as .sdl files that
// replay to their robustness.
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

const fs::path kCorpus = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "wmg";

class WmgFuzzTest : public test::CorpusSearchTest {};

TEST_F(WmgFuzzTest, EveryCorpusFileIsSearchedToTheEndOfItsBudget) {
  const std::vector<fs::path> files = test::corpus_files(kCorpus, ".sdl");
  ASSERT_GE(files.size(), 10u);
  expect_searched_to_budget(files);
}

// Issue 24: at the centre of its space every corpus scenario's actors come near the ego's path
// (oracle/actor_interaction.hpp); a scenery read otherwise than its author drew it (actors on
// the wrong arm, an ego held at red for the whole run) fails this first.
TEST_F(WmgFuzzTest, EveryCorpusScenariosActorsMeetTheEgoAtTheCentreOfItsSpace) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    if (entry.path().extension() != ".sdl") continue;
    ++files;
    const Outcome run = scenfuzz({"run", entry.path().string(), "--at", "mid", "--json"});
    ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << entry.path() << "\n" << run.err;
    const nlohmann::json interaction = nlohmann::json::parse(run.out)["interaction"];
    EXPECT_EQ(interaction["actors_interact"], true) << entry.path() << "\n" << interaction.dump();
  }
  EXPECT_GE(files, 10);
}

TEST_F(WmgFuzzTest, TheCutInYieldsFindingsThatReplay) {
  // Its one collision is the cutter's fault (a side swipe), which the collision oracle leaves out
  // unless told to count every collision.
  const Outcome run = fuzz(kCorpus / "cut_in.sdl", "1", {"--all-collisions"});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json findings = summary()["findings"];
  ASSERT_GE(findings.size(), 1u);
  const std::string scenario = findings[0]["file"].get<std::string>();
  EXPECT_EQ(fs::path(scenario).extension(), ".sdl");
  const std::string text = slurp(scenario);
  // The concrete file has no range (`a to b`) left outside comments, and says how to replay it
  // in a `#` comment.
  EXPECT_FALSE(
      std::regex_search(text, std::regex("^[^#\\n]*[0-9] to -?[0-9]", std::regex::multiline)))
      << text;
  std::smatch replay;
  ASSERT_TRUE(
      std::regex_search(text, replay, std::regex("# replay: scenfuzz run (\\S+) --seed (\\d+)")));
  // The replay judges as the search did.
  EXPECT_NE(text.find("--all-collisions"), std::string::npos) << text;
  const Outcome replayed = scenfuzz({"run", scenario, "--seed", replay[2].str(), "--all-collisions",
                                     "--json", "--out", (dir_ / "replay").string()});
  ASSERT_EQ(replayed.exit_code, 1) << replayed.err;
  EXPECT_NEAR(nlohmann::json::parse(replayed.out)["specs"][0]["robustness"].get<double>(),
              findings[0]["robustness"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace scenfuzz
