// The --json summary of a campaign run: the run, its simulations, the exit status and its
// reason, and every failure mode in the group of its status in this run, with its fields.
#include "fuzz/campaign/run_json.hpp"

#include <gtest/gtest.h>

#include "tests/campaign/sample_run.hpp"

namespace scenfuzz::test {
namespace {

const std::string kSeed = "corpora/avunit/cut_in_straight.avu";

TEST(RunJson, TheRunAndItsExitStatus) {
  RunSummary summary = empty_run();
  summary.run.ended.clear();  // killed
  const nlohmann::json json = run_json(summary);
  EXPECT_EQ(json.at("campaign"), "nightly");
  EXPECT_EQ(json.at("run").at("id"), 3);
  EXPECT_EQ(json.at("run").at("started"), "2026-11-27T02:00:00Z");
  EXPECT_TRUE(json.at("run").at("ended").is_null());
  EXPECT_EQ(json.at("run").at("ego_version"), "3f2c9e1");
  EXPECT_EQ(json.at("simulations"), 2000);
  EXPECT_EQ(json.at("exit_status"), 0);
  EXPECT_EQ(json.at("exit_reason"), "0: no new failure mode and no regression");
  for (const char* group :
       {"new", "still_failing", "fixed", "flaky", "regressed", "replay_errors", "not_replayed"})
    EXPECT_EQ(json.at("failure_modes").at(group), nlohmann::json::array()) << group;
}

TEST(RunJson, ModesByTheirStatusInThisRunWithTheirFields) {
  RunSummary summary = empty_run();
  RunFailureMode replayed = sample_mode(2, kSeed, FailureModeStatus::flaky, 1, 2);
  replayed.replay = ReplayOutcome{3, 1, ""};
  RunFailureMode failed = sample_mode(3, kSeed, FailureModeStatus::fixed, 1, 1);
  failed.replay = ReplayOutcome{0, 0, "modes/13.avu: cannot read"};
  RunFailureMode no_collision = sample_mode(4, kSeed, FailureModeStatus::fixed, 1, 1);
  no_collision.mode.record.responsibility.clear();
  summary.failure_modes = {sample_mode(1, kSeed, FailureModeStatus::new_mode, 3, 3), replayed,
                           failed, no_collision};
  const nlohmann::json json = run_json(summary);
  EXPECT_EQ(json.at("exit_status"), 1);
  const nlohmann::json& groups = json.at("failure_modes");
  ASSERT_EQ(groups.at("new").size(), 1u);
  const nlohmann::json& added = groups.at("new")[0];
  EXPECT_EQ(added.at("id"), 1);
  EXPECT_EQ(added.at("seed"), kSeed);
  EXPECT_EQ(added.at("spec"), "no_collision");
  EXPECT_EQ(added.at("signature"),
            "collision | car cutter | ego | cruising | straight | rear-front #1");
  EXPECT_EQ(added.at("responsibility"), "ego");
  EXPECT_EQ(added.at("status"), "new");
  EXPECT_EQ(added.at("scenario_file"), "modes/0000000000000011.avu");
  EXPECT_EQ(added.at("replay_command"), "scenfuzz run --map-path maps modes/0000000000000011.avu");
  EXPECT_EQ(added.at("first_seen_run"), 3);
  EXPECT_EQ(added.at("last_seen_run"), 3);
  EXPECT_TRUE(added.at("replay").is_null());
  ASSERT_EQ(groups.at("flaky").size(), 1u);
  EXPECT_EQ(groups.at("flaky")[0].at("replay"), (nlohmann::json{{"tried", 3}, {"failing", 1}}));
  ASSERT_EQ(groups.at("replay_errors").size(), 1u);
  EXPECT_EQ(groups.at("replay_errors")[0].at("status"), "fixed");  // older, kept
  EXPECT_EQ(groups.at("replay_errors")[0].at("replay"),
            (nlohmann::json{{"error", "modes/13.avu: cannot read"}}));
  ASSERT_EQ(groups.at("not_replayed").size(), 1u);
  EXPECT_TRUE(groups.at("not_replayed")[0].at("responsibility").is_null());
  EXPECT_TRUE(groups.at("fixed").empty());
}

}  // namespace
}  // namespace scenfuzz::test
