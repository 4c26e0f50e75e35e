// `scenfuzz coverage`, run as a user would: two corpus files on built-in maps covered with their
// features and the seeds covering each, the same output for -j 1 and -j 2, a concrete seed as one
// simulation, and bad seeds listed with their errors without stopping the run.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "fuzz/seed_coverage.hpp"

namespace scenfuzz {
namespace {

using CoverageCommandTest = test::CommandTest;
using test::source_file;

const std::string kCutIn = "corpora/avunit/cut_in_straight.avu";
const std::string kRoundabout = "corpora/avunit/roundabout_entry.avu";

// A concrete scenario on the built-in `straight`: the ego comes up behind a slower car.
const char* const kConcrete = R"(ego_init_state = ("east_0"->10, , 8);
ego_target_state = ("east_0"->180);
ego_vehicle = AV(ego_init_state, ego_target_state, ("Lincoln2017MKZ", white));
npc_state = ("east_0"->40, , 4);
npc = Vehicle(npc_state, uniform(npc_state), ("east_0"->190), ("Sedan", red));
scenario = CreateScenario{load("straight");
                          ego_vehicle;
                          {npc};
                          {};
                          {};
};
Trace trace = EXE(scenario);
)";

// A syntax error on line 2, column 53.
const char* const kBad =
    "ego_init_state = (\"east_0\"->10, , 8);\n"
    "ego_vehicle = AV(ego_init_state, , (\"Lincoln2017MKZ\" white));\n";

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

TEST_F(CoverageCommandTest, TwoCorpusFilesEachFeatureNamesTheSeedsCoveringIt) {
  const auto run =
      scenfuzz({"coverage", "--json", "-j", "2", source_file(kCutIn), source_file(kRoundabout)});
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  ASSERT_EQ(report["seeds"].size(), 2u);
  for (const nlohmann::json& seed : report["seeds"]) {
    EXPECT_FALSE(seed.contains("error")) << seed.dump();
    EXPECT_TRUE(seed["logical"].get<bool>());
    EXPECT_EQ(seed["simulations"].get<int>(), 9);  // the centre and 8 Halton points
    // Every feature of the seed lists the seed, and nothing else does.
    for (const std::string feature : seed["features"])
      EXPECT_TRUE(contains(report["features"][feature], seed["path"])) << feature;
  }
  const std::string cut_in = report["seeds"][0]["path"];
  const std::string roundabout = report["seeds"][1]["path"];
  EXPECT_EQ(cut_in, source_file(kCutIn));
  EXPECT_EQ(report["features"]["road.roundabout"], nlohmann::json({roundabout}));
  EXPECT_TRUE(report["features"].contains("ego.lane_change_left"));
  EXPECT_FALSE(contains(report["features"]["ego.lane_change_left"], roundabout));
  EXPECT_EQ(report["features"]["weather.clear"], nlohmann::json({cut_in, roundabout}));
}

TEST_F(CoverageCommandTest, TheOutputIsTheSameForAnyJobs) {
  const std::string concrete = write("concrete.avu", kConcrete);
  for (const char* json : {"--json", "--seed=0"}) {
    const auto one = scenfuzz(
        {"coverage", json, "-j", "1", source_file(kCutIn), source_file(kRoundabout), concrete});
    const auto two = scenfuzz(
        {"coverage", json, "-j", "2", source_file(kCutIn), source_file(kRoundabout), concrete});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(one.out, two.out);
    EXPECT_NE(one.out.find("road.roundabout"), std::string::npos);
  }
}

TEST_F(CoverageCommandTest, AConcreteSeedIsOneSimulation) {
  const std::string concrete = write("concrete.avu", kConcrete);
  const SeedCoverage coverage = cover_seed(concrete, {});
  ASSERT_EQ(coverage.error, "");
  EXPECT_FALSE(coverage.logical);
  EXPECT_EQ(coverage.simulations, 1u);
  EXPECT_GT(coverage.simulated_steps, 0u);
  EXPECT_GT(coverage.file_size, 0u);
  EXPECT_TRUE(std::is_sorted(coverage.features.begin(), coverage.features.end()));
  EXPECT_TRUE(contains(coverage.features, "light.day"));
  EXPECT_TRUE(
      std::any_of(coverage.features.begin(), coverage.features.end(),
                  [](const std::string& f) { return f.rfind("interaction.car.F.", 0) == 0; }));
  // Deterministic: the same again.
  EXPECT_EQ(cover_seed(concrete, {}).features, coverage.features);
}

TEST_F(CoverageCommandTest, BadSeedsAreListedWithTheirErrorsAndDoNotStopTheRun) {
  const std::string bad = write("bad.avu", kBad);
  const std::string missing = (dir_ / "missing.avu").string();
  const auto run = scenfuzz({"coverage", bad, source_file(kRoundabout), missing});
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_NE(run.out.find("covered by 1 of 3 seeds"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(bad + ":2:53: error: expected ')'"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("'" + missing + "' does not exist"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("road.roundabout"), std::string::npos) << run.out;

  const SeedCoverage direct = cover_seed(bad, {});
  EXPECT_NE(direct.error.find(bad + ":2:53:"), std::string::npos) << direct.error;
  EXPECT_TRUE(direct.features.empty());
}

TEST_F(CoverageCommandTest, NoSeedCoveredIsExitTwo) {
  const std::string bad = write("bad.avu", kBad);
  const auto run = scenfuzz({"coverage", "--json", bad});
  EXPECT_EQ(run.exit_code, 2);
  const nlohmann::json report = nlohmann::json::parse(run.out);
  EXPECT_NE(report["seeds"][0]["error"].get<std::string>().find(":2:53:"), std::string::npos);
  EXPECT_NE(run.err.find("no seed could be covered"), std::string::npos);
}

TEST_F(CoverageCommandTest, AFolderStandsForItsScenarioFiles) {
  write("a.avu", kConcrete);
  write("notes.txt", "not a scenario");
  const auto run = scenfuzz({"coverage", "--json", dir_.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  ASSERT_EQ(report["seeds"].size(), 1u);
  EXPECT_NE(report["seeds"][0]["path"].get<std::string>().find("a.avu"), std::string::npos);
}

}  // namespace
}  // namespace scenfuzz
