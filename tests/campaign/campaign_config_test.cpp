// campaign.toml: a complete file read into CampaignConfig, folders of seeds expanded, defaults,
// and malformed files, each giving one diagnostic at the expected file:line:column.
#include "fuzz/campaign/campaign_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// A campaign folder with seed files: a.avu, c.scenest, notes.txt, corpus/{z.sdl, b.avu,
// readme.md, deep/d.avu}, and an empty folder.
class CampaignConfigTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("scenfuzz_campaign_config_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "corpus" / "deep");
    fs::create_directories(dir_ / "empty");
    for (const char* name : {"a.avu", "c.scenest", "notes.txt", "corpus/z.sdl", "corpus/b.avu",
                             "corpus/readme.md", "corpus/deep/d.avu"})
      std::ofstream(dir_ / name) << "// " << name << "\n";
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::string path() const { return (dir_ / "campaign.toml").string(); }

  CampaignConfigResult parse(const std::string& text) const {
    return parse_campaign_config(text, path());
  }

  // The diagnostics as a user sees them.
  std::string messages(const std::string& text) const {
    const CampaignConfigResult result = parse(text);
    return format_diagnostics(SourceFile(path(), text), result.diagnostics);
  }

  fs::path dir_;
};

TEST_F(CampaignConfigTest, ReadsEveryKey) {
  const CampaignConfigResult result = parse(R"toml(
seeds = ["a.avu", "corpus/"]
map_paths = ["maps/", "/opt/maps"]

[campaign]
name = "nightly"

[ego]
plugin = "build/libdriver.so"
version = "0123abc"

[budget]
simulations = 5000
wall_seconds = 1800.5

[search]
algo = "nlopt:GN_ISRES"
seed = 7
jobs = 2
tmin = true

[[seed]]
path = "corpus/b.avu"
budget_share = 2.5
algo = "random"
scenario = "scenario2"

[[seed]]
path = "./a.avu"
)toml");
  ASSERT_TRUE(result.config) << format_diagnostics(SourceFile(path(), ""), result.diagnostics);
  const CampaignConfig& config = *result.config;
  EXPECT_EQ(config.folder, dir_);
  EXPECT_EQ(config.name, "nightly");
  EXPECT_EQ(config.seed_entries, (std::vector<std::string>{"a.avu", "corpus/"}));
  EXPECT_EQ(config.seed_files, (std::vector<std::string>{"a.avu", "corpus/b.avu",
                                                         "corpus/deep/d.avu", "corpus/z.sdl"}));
  EXPECT_EQ(config.map_paths, (std::vector<std::string>{"maps/", "/opt/maps"}));
  EXPECT_EQ(config.ego_plugin, "build/libdriver.so");
  EXPECT_EQ(config.ego_version, "0123abc");
  EXPECT_EQ(config.budget_simulations, 5000u);
  EXPECT_EQ(config.budget_wall_seconds, 1800.5);
  EXPECT_EQ(config.search.algorithm, "nlopt:GN_ISRES");
  EXPECT_EQ(config.search.seed, 7u);
  EXPECT_EQ(config.search.jobs, 2u);
  EXPECT_TRUE(config.search.tmin);
  ASSERT_EQ(config.seed_overrides.size(), 2u);
  EXPECT_EQ(config.seed_overrides[0].path, "corpus/b.avu");
  EXPECT_EQ(config.seed_overrides[0].budget_share, 2.5);
  EXPECT_EQ(config.seed_overrides[0].algorithm, "random");
  EXPECT_EQ(config.seed_overrides[0].location.line, 23u);
  EXPECT_EQ(config.seed_overrides[0].scenario, "scenario2");
  EXPECT_EQ(config.seed_overrides[1].path, "a.avu");
  EXPECT_EQ(config.seed_overrides[1].budget_share, 1.0);
  EXPECT_FALSE(config.seed_overrides[1].algorithm);
  EXPECT_EQ(config.seed_overrides[1].scenario, "");
  EXPECT_TRUE(result.diagnostics.all().empty());
}

TEST_F(CampaignConfigTest, DefaultsWhatItLeavesOut) {
  const CampaignConfigResult result = parse("seeds = [\"a.avu\"]\n[budget]\nwall_seconds = 60\n");
  ASSERT_TRUE(result.config);
  const CampaignConfig& config = *result.config;
  EXPECT_EQ(config.name, dir_.filename().string());
  EXPECT_EQ(config.ego_plugin, "");
  EXPECT_EQ(config.ego_version, kReferenceEgoVersion);
  EXPECT_FALSE(config.budget_simulations);
  EXPECT_EQ(config.budget_wall_seconds, 60.0);
  EXPECT_EQ(config.search.algorithm, "ga");
  EXPECT_EQ(config.search.seed, 0u);
  EXPECT_EQ(config.search.jobs, 0u);
  EXPECT_FALSE(config.search.tmin);
  EXPECT_TRUE(config.seed_overrides.empty());
  EXPECT_TRUE(config.map_paths.empty());
}

TEST_F(CampaignConfigTest, ListsAFileOnceWhenTwoEntriesNameIt) {
  const CampaignConfigResult result = parse(
      "seeds = [\"corpus/b.avu\", \"corpus\", \"./a.avu\", \"a.avu\"]\n"
      "[budget]\nsimulations = 10\n");
  ASSERT_TRUE(result.config);
  EXPECT_EQ(
      result.config->seed_files,
      (std::vector<std::string>{"corpus/b.avu", "corpus/deep/d.avu", "corpus/z.sdl", "a.avu"}));
}

TEST_F(CampaignConfigTest, TakesAbsoluteSeedPaths) {
  const std::string absolute = (dir_ / "c.scenest").string();
  const CampaignConfigResult result =
      parse("seeds = [\"" + absolute + "\"]\n[budget]\nsimulations = 10\n");
  ASSERT_TRUE(result.config);
  EXPECT_EQ(result.config->seed_files, (std::vector<std::string>{absolute}));
}

struct Malformed {
  const char* what;
  std::string text;
  const char* place;    // "line:column"; for TOML's own errors, where toml++ puts them is
                        // toml++'s choice: "line" only
  const char* message;  // part of the message there
};

// Seeds, a budget and a search table to break one thing at a time in.
const std::string kSeeds = "seeds = [\"a.avu\"]\n";
const std::string kBudget = "[budget]\nsimulations = 100\n";

std::vector<Malformed> malformed_files() {
  return {
      {"an unknown top-level key", kSeeds + "seedz = 1\n" + kBudget, "2:1",
       "unknown key 'seedz' in campaign.toml; expected one of: seeds, map_paths, campaign"},
      {"an unknown key in [budget]", kSeeds + "[budget]\nsimulation = 100\n", "3:1",
       "unknown key 'simulation' in [budget]; expected one of: simulations, wall_seconds"},
      {"a string for a number", kSeeds + "[budget]\nsimulations = \"500\"\n", "3:15",
       "'budget.simulations': expected a whole number from 1 to 1000000000, found a string"},
      {"a negative budget", kSeeds + "[budget]\nsimulations = -5\n", "3:15",
       "'budget.simulations': expected a whole number from 1 to 1000000000, found -5"},
      {"a fractional simulation count", kSeeds + "[budget]\nsimulations = 2.5\n", "3:15",
       "'budget.simulations': expected a whole number from 1 to 1000000000, found 2.5"},
      {"a zero wall time", kSeeds + "[budget]\nwall_seconds = 0\n", "3:16",
       "'budget.wall_seconds': expected a finite number greater than 0, found 0"},
      {"NaN", kSeeds + "[budget]\nwall_seconds = nan\n", "3:16",
       "'budget.wall_seconds': expected a finite number greater than 0, found nan"},
      {"infinity", kSeeds + "[budget]\nwall_seconds = -inf\n", "3:16",
       "'budget.wall_seconds': expected a finite number greater than 0, found -inf"},
      {"an empty [budget]", kSeeds + "[budget]\n", "2:1",
       "[budget] is empty: expected simulations (a total) and/or wall_seconds"},
      {"no [budget]", kSeeds, "1:1", "no [budget]: expected a [budget] table"},
      {"an unknown algorithm", kSeeds + kBudget + "[search]\nalgo = \"gaa\"\n", "5:8",
       "'search.algo': unknown search algorithm 'gaa'; expected ga, random, halton, lhs or "
       "nlopt:NAME"},
      {"a bad mutation size", kSeeds + kBudget + "[search]\nmutate = [\"speed=1\", \"colour=2\"]\n",
       "5:22", "'search.mutate': --mutate: expected KIND=SIZE with KIND one of position"},
      {"an unknown NLopt algorithm", kSeeds + kBudget + "[search]\nalgo = \"nlopt:XX_FOO\"\n",
       "5:8", "'search.algo': NLopt algorithm 'XX_FOO' is unknown or not supported"},
      {"a fractional job count", kSeeds + kBudget + "[search]\njobs = 1.5\n", "5:8",
       "'search.jobs': expected a whole number from 0 to 1024, found 1.5"},
      {"tmin as a string", kSeeds + kBudget + "[search]\ntmin = \"yes\"\n", "5:8",
       "'search.tmin': expected true or false, found a string"},
      {"a negative search seed", kSeeds + kBudget + "[search]\nseed = -1\n", "5:8",
       "'search.seed': expected a whole number from 0 to 9223372036854775807, found -1"},
      {"a seed that does not exist", "seeds = [\"a.avu\", \"missing.avu\"]\n" + kBudget, "1:19",
       "'seeds': 'missing.avu' does not exist (seed paths are relative to the campaign folder"},
      {"a seed that is no scenario", "seeds = [\"notes.txt\"]\n" + kBudget, "1:10",
       "'seeds': 'notes.txt' is not a scenario file: expected a .avu, .scenest or .sdl file"},
      {"a folder without scenarios", "seeds = [\"empty/\"]\n" + kBudget, "1:10",
       "'seeds': the folder 'empty/' holds no scenario file"},
      {"no seeds at all", kBudget, "1:1", "no seeds: expected `seeds = ["},
      {"an empty seed list", "seeds = []\n" + kBudget, "1:9",
       "'seeds': expected at least one file or folder"},
      {"seeds as a string", "seeds = \"a.avu\"\n" + kBudget, "1:9",
       "'seeds': expected an array of strings ([\"...\", ...]), found a string"},
      {"a number as the name", kSeeds + "[campaign]\nname = 3\n" + kBudget, "3:8",
       "'campaign.name': expected a string, found an integer"},
      {"a plugin without a version", kSeeds + "[ego]\nplugin = \"libx.so\"\n" + kBudget, "2:1",
       "[ego] names a plugin but no version: expected `version = \"...\"`"},
      {"a [[seed]] not among the seeds", kSeeds + kBudget + "[[seed]]\npath = \"c.scenest\"\n",
       "5:8", "'seed.path': 'c.scenest' is not one of the 1 scenario files `seeds` stands for"},
      {"two [[seed]] for one file",
       kSeeds + kBudget + "[[seed]]\npath = \"a.avu\"\n[[seed]]\npath = \"./a.avu\"\n", "7:8",
       "a second [[seed]] for './a.avu' (the first is on line 5)"},
      {"a negative budget share",
       kSeeds + kBudget + "[[seed]]\npath = \"a.avu\"\nbudget_share = -1\n", "6:16",
       "'seed.budget_share': expected a finite number greater than 0, found -1"},
      {"an unknown key in [[seed]]",
       kSeeds + kBudget + "[[seed]]\npath = \"a.avu\"\ncolour = \"red\"\n", "6:1",
       "unknown key 'colour' in [[seed]]; expected one of: path, budget_share, algo, scenario"},
      {"an empty scenario name in [[seed]]",
       kSeeds + kBudget + "[[seed]]\npath = \"a.avu\"\nscenario = \"\"\n", "6:12",
       "'seed.scenario': expected a non-empty string"},
      {"seed as a number", kSeeds + "seed = 3\n" + kBudget, "2:8",
       "'seed': expected [[seed]] tables (path = ..., budget_share = ..., algo = ...), found an "
       "integer"},
      {"a key twice (TOML itself)", kSeeds + kBudget + "simulations = 200\n", "4",
       "not valid TOML: "},
      {"a value missing (TOML itself)", kSeeds + "[budget]\nsimulations =\n", "3",
       "not valid TOML: "},
  };
}

TEST_F(CampaignConfigTest, EveryMalformedFileGetsItsPlaceAndWhatWasExpected) {
  for (const Malformed& file : malformed_files()) {
    SCOPED_TRACE(file.what);
    const CampaignConfigResult result = parse(file.text);
    EXPECT_FALSE(result.config);
    const std::string shown = messages(file.text);
    const std::string place = std::string(file.place).find(':') == std::string::npos
                                  ? std::string(file.place) + ":"  // any column
                                  : std::string(file.place) + ": error: " + file.message;
    EXPECT_NE(shown.find(path() + ":" + place), std::string::npos) << shown;
    EXPECT_NE(shown.find(": error: " + std::string(file.message)), std::string::npos) << shown;
    // The line is quoted with a caret under the place.
    EXPECT_NE(shown.find('^'), std::string::npos) << shown;
  }
}

TEST_F(CampaignConfigTest, ReportsEveryProblemOfAFileAtOnce) {
  const CampaignConfigResult result = parse(
      "seeds = [\"missing.avu\"]\n[budget]\nsimulations = 0\nwall_seconds = nan\n"
      "[search]\nalgo = \"x\"\n");
  EXPECT_FALSE(result.config);
  EXPECT_EQ(result.diagnostics.error_count(), 4u);
}

TEST_F(CampaignConfigTest, UnderlinesTheValueItBlames) {
  const std::string text = kSeeds + "[budget]\nsimulations = -5\n";
  EXPECT_NE(messages(text).find("  simulations = -5\n                ^~\n"), std::string::npos)
      << messages(text);
}

}  // namespace
}  // namespace scenfuzz
