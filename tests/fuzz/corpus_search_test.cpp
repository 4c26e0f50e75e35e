// `scenfuzz --budget N DIR/` and several files: the corpus's seeds searched one by one with even
// budget shares, each in its own folder, corpus.json listing them; bad corpora stop before any
// search.
#include "fuzz/corpus_search.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using scenfuzz::test::Outcome;
using scenfuzz::test::slurp;
using CorpusSearchTest = scenfuzz::test::CommandTest;

TEST(CorpusBudget, SharesAreEvenAndTheRemainderGoesToTheFirstSeeds) {
  EXPECT_EQ(corpus_budget_shares(10, 3), (std::vector<std::size_t>{4, 3, 3}));
  EXPECT_EQ(corpus_budget_shares(9, 3), (std::vector<std::size_t>{3, 3, 3}));
  EXPECT_EQ(corpus_budget_shares(2, 2), (std::vector<std::size_t>{1, 1}));
}

TEST(CorpusFolders, NamesAreStemsMadeUnique) {
  EXPECT_EQ(corpus_folder_names({"a/x.avu", "b/x.avu", "c/y.sdl", "d/x.scenest"}),
            (std::vector<std::string>{"x", "x-2", "y", "x-3"}));
  EXPECT_EQ(corpus_folder_names({"a/x-2.avu", "b/x.avu", "c/x.avu"}),
            (std::vector<std::string>{"x-2", "x", "x-3"}));
}

TEST(CorpusSearch, OneFileIsNotACorpusButAFolderOrSeveralAre) {
  const fs::path corpus = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit";
  EXPECT_FALSE(is_corpus_search({(corpus / "cut_in_straight.avu").string()}));
  EXPECT_TRUE(is_corpus_search({corpus.string()}));
  EXPECT_TRUE(is_corpus_search(
      {(corpus / "cut_in_straight.avu").string(), (corpus / "cyclist_ahead.avu").string()}));
}

TEST_F(CorpusSearchTest, AFolderIsSearchedSeedBySeed) {
  const fs::path source = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit";
  const fs::path folder = dir_ / "seeds";
  fs::create_directories(folder / "more");
  fs::copy_file(source / "cut_in_straight.avu", folder / "cut_in_straight.avu");
  fs::copy_file(source / "cyclist_ahead.avu", folder / "more" / "cyclist_ahead.avu");
  std::ofstream(folder / "notes.txt") << "not a scenario";
  const std::string out = (dir_ / "out").string();
  const Outcome run = scenfuzz({"--budget", "25", "--seed", "3", "--out", out, folder.string()});
  ASSERT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.out << run.err;
  const nlohmann::json corpus = nlohmann::json::parse(slurp(dir_ / "out" / "corpus.json"));
  ASSERT_EQ(corpus.at("seeds").size(), 2u) << corpus.dump();
  EXPECT_EQ(corpus.at("seeds")[0].at("folder"), "cut_in_straight");
  EXPECT_EQ(corpus.at("seeds")[0].at("budget"), 13);
  EXPECT_EQ(corpus.at("seeds")[1].at("folder"), "cyclist_ahead");
  EXPECT_EQ(corpus.at("seeds")[1].at("budget"), 12);
  std::size_t findings = 0;
  for (const char* seed : {"cut_in_straight", "cyclist_ahead"}) {
    const nlohmann::json summary =
        nlohmann::json::parse(slurp(dir_ / "out" / seed / "summary.json"));
    findings += summary.at("findings").size();
  }
  EXPECT_EQ(run.exit_code, findings > 0 ? 1 : 0);
  EXPECT_NE(run.out.find("corpus: "), std::string::npos) << run.out;
}

TEST_F(CorpusSearchTest, ABadSeedStopsTheCorpusBeforeAnySearch) {
  const std::string good =
      (fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit" / "cut_in_straight.avu").string();
  const std::string bad = write("bad.avu", "ego_init_state = (\"east_0\"->);\n");
  const std::string out = (dir_ / "out").string();
  const Outcome run = scenfuzz({"--budget", "10", "--out", out, good, bad});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.avu:1:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nothing was searched"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "cut_in_straight"));
  const Outcome missing =
      scenfuzz({"--budget", "10", "--out", out, good, (dir_ / "missing.avu").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("missing.avu' does not exist"), std::string::npos) << missing.err;
  const Outcome small = scenfuzz({"--budget", "1", "--out", out, good, good + ""});
  // The same file twice is one seed: a budget of 1 is enough.
  EXPECT_TRUE(small.exit_code == 0 || small.exit_code == 1) << small.err;
  const Outcome too_small = scenfuzz(
      {"--budget", "1", "--out", (dir_ / "out2").string(), good,
       (fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit" / "cyclist_ahead.avu").string()});
  EXPECT_EQ(too_small.exit_code, 2);
  EXPECT_NE(too_small.err.find("--budget 1 is less than one simulation for each of the 2 seeds"),
            std::string::npos)
      << too_small.err;
}

}  // namespace
}  // namespace scenfuzz
