// `scenfuzz campaign run`, in process: a small campaign runs end to end and fills its database and
// DIR/modes/; a second run replays the known modes (injected verdicts, and the campaign's own
// replay) and moves their statuses; -j 1 and -j 2 leave the same database; a seed with errors stops
// everything before it runs, a concrete one is searched by mutation, one with nothing to mutate is
// left out with a warning; a wall-time budget ends the run.
#include "fuzz/campaign/campaign_run.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/campaign/budget_schedule.hpp"
#include "fuzz/campaign/scenario_replay.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/content_hash.hpp"
#include "tests/campaign/campaign_fixture.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

class CampaignRunTest : public CommandTest {
 protected:
  // A campaign folder `name` under the scratch folder with this campaign.toml.
  fs::path campaign(const std::string& name, const std::string& toml) {
    fs::create_directories(dir_ / name);
    write(name + "/campaign.toml", toml);
    return dir_ / name;
  }

  // With the campaign's own regression replay unless `replay` is given.
  int run(const fs::path& folder, std::optional<std::uint64_t> jobs = 2,
          const ModeReplayer& replay = {}) {
    out_.str("");
    err_.str("");
    return run_campaign({folder.string(), jobs, "", false}, replay, out_, err_);
  }

  std::unique_ptr<CampaignDb> open(const fs::path& folder) {
    CampaignDbOpening opening = CampaignDb::open(folder);
    EXPECT_TRUE(opening.db) << opening.error;
    return std::move(opening.db);
  }

  std::ostringstream out_, err_;
};

constexpr const char* kBudget = "simulations = 320";

TEST_F(CampaignRunTest, RunsASmallCampaignEndToEnd) {
  const fs::path folder = campaign("c", campaign_toml(small_campaign_seeds(), kBudget));
  ASSERT_EQ(run(folder), kExitViolated) << err_.str();  // its first run: every mode is new
  EXPECT_NE(out_.str().find("round 0: "), std::string::npos) << out_.str();
  auto db = open(folder);
  ASSERT_TRUE(db);
  ASSERT_EQ(db->list_runs().size(), 1u);
  EXPECT_FALSE(db->list_runs()[0].ended.empty());
  EXPECT_EQ(db->list_seeds().size(), 3u);
  const std::vector<CampaignSearch> searches = db->list_searches();
  ASSERT_GE(searches.size(), 4u);
  std::uint64_t spent = 0;
  for (const CampaignSearch& search : searches) {
    spent += search.record.simulations;
    EXPECT_EQ(search.record.status, SearchStatus::done);
    EXPECT_GE(search.record.budget, kMinSearchBudget);
    EXPECT_TRUE(fs::exists(folder / search.record.output_folder / "summary.json"));
    // Every evaluation of the search, infeasible ones included, in index order.
    const std::vector<CampaignEvaluation> evaluations = db->list_evaluations(search.id);
    ASSERT_GE(evaluations.size(), search.record.simulations);
    for (std::size_t i = 0; i < evaluations.size(); ++i)
      EXPECT_EQ(evaluations[i].index, static_cast<std::int64_t>(i));
    // The coverage its summary.json reports, stored with it.
    const nlohmann::json summary = nlohmann::json::parse(
        slurp(folder / search.record.output_folder / "summary.json"))["coverage"];
    const std::vector<std::string> coverage = db->list_coverage(search.id);
    EXPECT_FALSE(coverage.empty());
    EXPECT_EQ(coverage, summary["names"].get<std::vector<std::string>>());
  }
  EXPECT_LE(spent, 320u);
  EXPECT_GE(spent, 320u - kMinSearchBudget);  // what is left is less than a minimal search
  const std::vector<CampaignFailureMode> modes = db->list_failure_modes();
  ASSERT_FALSE(modes.empty());
  for (const CampaignFailureMode& mode : modes) {
    EXPECT_EQ(mode.status, FailureModeStatus::new_mode);
    EXPECT_EQ(mode.record.scenario_file.rfind("modes/", 0), 0u) << mode.record.scenario_file;
    const fs::path file = folder / mode.record.scenario_file;
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_TRUE(fs::exists(fs::path(file).replace_extension(".svg"))) << file;
    EXPECT_EQ(content_hash(slurp(file)) + ".avu", file.filename().string());
    EXPECT_EQ(mode.record.replay_command.rfind("scenfuzz run --seed ", 0), 0u);
    EXPECT_NE(mode.record.replay_command.find(" " + mode.record.scenario_file), std::string::npos);
  }
  // The searches that found modes first are credited with them, and only them.
  std::int64_t credited = 0;
  for (const CampaignSearch& search : searches) credited += search.record.new_modes;
  EXPECT_EQ(credited, static_cast<std::int64_t>(modes.size()));
}

TEST_F(CampaignRunTest, LaterRunsReplayKnownModesAndMoveTheirStatuses) {
  const fs::path folder = campaign("c", campaign_toml(small_campaign_seeds(), kBudget));
  ASSERT_EQ(run(folder), kExitViolated) << err_.str();
  std::size_t first_modes = open(folder)->list_failure_modes().size();

  // Run 2 replays nothing: the modes its searches find again are still failing.
  const ModeReplayer replay_nothing = [](const CampaignFailureMode&) { return ReplayOutcome{}; };
  const int second = run(folder, 2, replay_nothing);
  {
    auto db = open(folder);
    int still = 0, fresh = 0;
    for (const CampaignFailureMode& mode : db->list_failure_modes()) {
      still += mode.status == FailureModeStatus::still_failing;
      fresh += mode.first_seen_run == 2;
    }
    EXPECT_GT(still, 0);
    EXPECT_EQ(second, fresh > 0 ? kExitViolated : kExitSuccess);
    ASSERT_EQ(db->list_replays().size(), first_modes);
    for (const CampaignReplay& replay : db->list_replays())
      EXPECT_EQ(replay.verdict, "not_replayed");
    first_modes = db->list_failure_modes().size();
  }

  // Run 3's replay finds every known mode fixed; those its searches find again regressed.
  std::vector<std::int64_t> replayed;
  const ModeReplayer all_pass = [&](const CampaignFailureMode& mode) {
    replayed.push_back(mode.id);
    return ReplayOutcome{3, 0, ""};
  };
  const int third = run(folder, 2, all_pass);
  EXPECT_EQ(replayed.size(), first_modes);
  auto db = open(folder);
  int regressed = 0, fixed = 0;
  for (const CampaignFailureMode& mode : db->list_failure_modes()) {
    if (mode.first_seen_run == 3) continue;
    regressed += mode.status == FailureModeStatus::regressed;
    fixed += mode.status == FailureModeStatus::fixed;
    EXPECT_TRUE(mode.status == FailureModeStatus::regressed ||
                mode.status == FailureModeStatus::fixed)
        << status_name(mode.status);
  }
  EXPECT_GT(fixed + regressed, 0);
  EXPECT_EQ(third, regressed > 0 || db->list_failure_modes().size() > first_modes ? kExitViolated
                                                                                  : kExitSuccess);
}

// The campaign's own replay, with the same ego: every mode of run 1 is replayed on 3 perception
// seeds in run 2 without an error; those failing on every seed are still failing, those failing
// on some are flaky (found again by a search of the run: still failing), none is fixed by a
// replay that reproduces nothing.
TEST_F(CampaignRunTest, TheRealReplayFindsTheModesOfTheSameEgoStillFailing) {
  const fs::path folder = campaign("c", campaign_toml(small_campaign_seeds(), kBudget));
  ASSERT_EQ(run(folder), kExitViolated) << err_.str();
  const std::size_t known = open(folder)->list_failure_modes().size();
  run(folder);
  EXPECT_NE(out_.str().find("regression replay: "), std::string::npos) << out_.str();
  auto db = open(folder);
  const std::vector<CampaignReplay> replays = db->list_replays();
  ASSERT_EQ(replays.size(), known);
  int still = 0;
  for (const CampaignReplay& replay : replays) {
    EXPECT_EQ(replay.run_id, 2);
    EXPECT_EQ(replay.error, "");
    EXPECT_EQ(replay.tried, kReplaySeeds);
    EXPECT_GT(replay.failing, 0) << replay.failure_mode_id;
    EXPECT_EQ(replay.verdict, replay.failing == replay.tried ? "still_failing" : "flaky");
    still += replay.verdict == "still_failing";
  }
  EXPECT_GT(still, 0);
  for (const CampaignFailureMode& mode : db->list_failure_modes()) {
    if (mode.first_seen_run != 1) continue;
    EXPECT_TRUE(mode.status == FailureModeStatus::still_failing ||
                mode.status == FailureModeStatus::flaky)
        << status_name(mode.status);
  }
}

TEST_F(CampaignRunTest, TheDatabaseIsTheSameForAnyNumberOfJobs) {
  const fs::path one = campaign("one", campaign_toml(small_campaign_seeds(), kBudget));
  const fs::path two = campaign("two", campaign_toml(small_campaign_seeds(), kBudget));
  ASSERT_EQ(run(one, 1), kExitViolated) << err_.str();
  ASSERT_EQ(run(two, 2), kExitViolated) << err_.str();
  const std::string dump = canonical_dump(one);
  EXPECT_NE(dump.find("\nmode "), std::string::npos) << dump;
  // Each seed's searches cover its interactions: the cut-in's car, the step-out's pedestrian.
  EXPECT_NE(dump.find("  covers interaction.car."), std::string::npos) << dump;
  EXPECT_NE(dump.find("  covers interaction.pedestrian."), std::string::npos) << dump;
  const std::string other = canonical_dump(two);
  EXPECT_TRUE(dump == other) << first_difference(dump, other);
}

TEST_F(CampaignRunTest, ASeedWithErrorsStopsTheRunBeforeAnything) {
  const std::string bad = write("bad.avu", "ego = AV(;\n");
  std::vector<std::string> seeds = small_campaign_seeds();
  seeds.push_back(bad);
  const fs::path folder = campaign("c", campaign_toml(seeds, kBudget));
  EXPECT_EQ(run(folder), kExitBadInput);
  EXPECT_NE(err_.str().find("bad.avu:1:"), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("nothing was run"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(folder / "campaign.db"));
  EXPECT_FALSE(fs::exists(folder / "searches"));
}

// A concrete scenario's values, on the built-in straight road.
std::string concrete_seed_text() {
  return "ego_vehicle = AV((\"east_0\"->30, , 15), (\"east_0\"->450), (\"Lincoln2017MKZ\", "
         "white));\n"
         "other_start = (\"west_0\"->100, , 10);\n"
         "other = Vehicle(other_start, uniform(other_start), (\"west_0\"->495), (\"Sedan\", "
         "red));\n"
         "scenario = CreateScenario{load(\"straight\"); ego_vehicle; {other}; {}; {};};\n"
         "Trace trace = EXE(scenario);\n";
}

TEST_F(CampaignRunTest, AConcreteSeedIsSearchedByMutation) {
  const std::string concrete = write("concrete.avu", concrete_seed_text());
  const fs::path folder =
      campaign("c", campaign_toml({concrete, source_file("corpora/avunit/cut_in_straight.avu")},
                                  "simulations = 64"));
  const int status = run(folder);
  EXPECT_TRUE(status == kExitSuccess || status == kExitViolated) << err_.str();
  auto db = open(folder);
  ASSERT_EQ(db->list_seeds().size(), 2u);
  std::set<std::int64_t> searched;
  for (const CampaignSearch& search : db->list_searches()) searched.insert(search.record.seed_id);
  EXPECT_EQ(searched.size(), 2u) << "both seeds were searched";
}

TEST_F(CampaignRunTest, ASeedWithNothingToMutateIsLeftOutWithAWarning) {
  const std::string concrete = write("concrete.avu", concrete_seed_text());
  std::string mutate = "mutate = [";
  for (const char* kind :
       {"position", "waypoint", "lateral", "heading", "speed", "weather", "time"})
    mutate += "\"" + std::string(kind) + "=0\", ";
  mutate += "]\n";
  const fs::path folder = campaign(
      "c",
      campaign_toml({concrete, (fs::path(SCENFUZZ_TEST_DATA_DIR) / "cut_in_close.avu").string()},
                    "simulations = 64", mutate));
  // The cut-in's collisions are mostly the cutter's fault (other-fault): findings or none.
  const int status = run(folder);
  EXPECT_TRUE(status == kExitSuccess || status == kExitViolated) << err_.str();
  EXPECT_NE(err_.str().find("warning: seed '" + concrete +
                            "' has neither parameter ranges nor values to mutate"),
            std::string::npos)
      << err_.str();
  auto db = open(folder);
  ASSERT_EQ(db->list_seeds().size(), 1u);
  EXPECT_NE(db->list_seeds()[0].path.find("cut_in_close.avu"), std::string::npos);
}

// The wall time ends the run (rounds would go on for ever without a simulation budget): it is
// recorded as ended, and every search recorded is done or stopped at the wall time.
TEST_F(CampaignRunTest, AWallTimeBudgetEndsTheRun) {
  const fs::path folder =
      campaign("c", campaign_toml(small_campaign_seeds(), "wall_seconds = 1.5"));
  const int status = run(folder);
  EXPECT_TRUE(status == kExitSuccess || status == kExitViolated) << err_.str();
  EXPECT_NE(out_.str().find("ended at the wall time"), std::string::npos) << out_.str();
  auto db = open(folder);
  ASSERT_EQ(db->list_runs().size(), 1u);
  EXPECT_FALSE(db->list_runs()[0].ended.empty());
  for (const CampaignSearch& search : db->list_searches())
    EXPECT_TRUE(search.record.status == SearchStatus::done ||
                search.record.status == SearchStatus::stopped);
}

}  // namespace
}  // namespace scenfuzz::test
