// A campaign run's exit status: 1 only for a failure mode new in this run or regressed in this
// run; modes whose status is older (a failed replay, no replay) do not count.
#include "fuzz/campaign/run_exit_status.hpp"

#include <gtest/gtest.h>

#include "tests/campaign/sample_run.hpp"

namespace scenfuzz::test {
namespace {

const std::string kSeed = "corpora/avunit/cut_in_straight.avu";

RunSummary with(std::vector<RunFailureMode> modes) {
  RunSummary summary = empty_run();
  summary.failure_modes = std::move(modes);
  return summary;
}

RunFailureMode replayed(RunFailureMode entry, ReplayOutcome outcome) {
  entry.replay = std::move(outcome);
  return entry;
}

TEST(RunExitStatus, NoModeIsSuccess) {
  EXPECT_EQ(run_exit_status(empty_run()), 0);
  EXPECT_EQ(run_exit_reason(empty_run()), "0: no new failure mode and no regression");
}

TEST(RunExitStatus, StillFailingFixedAndFlakyAreSuccess) {
  const RunSummary summary =
      with({replayed(sample_mode(1, kSeed, FailureModeStatus::still_failing, 1, 2), {3, 3, ""}),
            replayed(sample_mode(2, kSeed, FailureModeStatus::fixed, 1, 1), {3, 0, ""}),
            replayed(sample_mode(3, kSeed, FailureModeStatus::flaky, 1, 2), {3, 1, ""}),
            sample_mode(4, kSeed, FailureModeStatus::still_failing, 1, 3)});
  EXPECT_EQ(run_exit_status(summary), 0);
}

TEST(RunExitStatus, ANewModeFoundInThisRunFails) {
  const RunSummary summary = with({sample_mode(1, kSeed, FailureModeStatus::new_mode, 3, 3)});
  EXPECT_TRUE(new_in_run(summary, summary.failure_modes[0]));
  EXPECT_EQ(run_exit_status(summary), 1);
  EXPECT_EQ(run_exit_reason(summary), "1: 1 new failure mode, 0 regressions");
}

TEST(RunExitStatus, ANewModeOfAnEarlierRunWhoseReplayFailedDoesNotCount) {
  const RunSummary summary = with({replayed(
      sample_mode(1, kSeed, FailureModeStatus::new_mode, 2, 2), {0, 0, "modes/x.avu: missing"})});
  EXPECT_FALSE(new_in_run(summary, summary.failure_modes[0]));
  EXPECT_EQ(run_exit_status(summary), 0);
}

TEST(RunExitStatus, ARegressionByTheReplayOrBySearchFails) {
  const RunSummary by_replay =
      with({replayed(sample_mode(1, kSeed, FailureModeStatus::regressed, 1, 1), {3, 3, ""})});
  EXPECT_EQ(run_exit_status(by_replay), 1);
  const RunSummary by_search = with({sample_mode(1, kSeed, FailureModeStatus::regressed, 1, 3)});
  EXPECT_EQ(run_exit_status(by_search), 1);
  const RunSummary both = with({sample_mode(1, kSeed, FailureModeStatus::regressed, 1, 3),
                                sample_mode(2, kSeed, FailureModeStatus::new_mode, 3, 3),
                                sample_mode(3, kSeed, FailureModeStatus::new_mode, 3, 3)});
  EXPECT_EQ(run_exit_reason(both), "1: 2 new failure modes, 1 regression");
}

TEST(RunExitStatus, AnOlderRegressionThisRunLearntNothingAboutDoesNotCount) {
  const RunSummary replay_failed =
      with({replayed(sample_mode(1, kSeed, FailureModeStatus::regressed, 1, 2),
                     {0, 0, "seed 1: cannot be set up"})});
  EXPECT_EQ(run_exit_status(replay_failed), 0);
  const RunSummary not_replayed = with({sample_mode(1, kSeed, FailureModeStatus::regressed, 1, 2)});
  EXPECT_EQ(run_exit_status(not_replayed), 0);
}

}  // namespace
}  // namespace scenfuzz::test
