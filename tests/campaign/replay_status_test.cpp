// The regression replay's status rule on every case: all seeds failing, none, some, nothing
// tried, and an error, from every status before.
#include "fuzz/campaign/replay_status.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace scenfuzz {
namespace {

const std::vector<FailureModeStatus> kEveryStatus = {
    FailureModeStatus::new_mode, FailureModeStatus::still_failing, FailureModeStatus::fixed,
    FailureModeStatus::flaky, FailureModeStatus::regressed};

TEST(ReplayStatus, EverySeedFailingIsStillFailingAndAFixedModeRegressed) {
  const ReplayOutcome all{3, 3, ""};
  EXPECT_EQ(replay_status(FailureModeStatus::new_mode, all), FailureModeStatus::still_failing);
  EXPECT_EQ(replay_status(FailureModeStatus::still_failing, all), FailureModeStatus::still_failing);
  EXPECT_EQ(replay_status(FailureModeStatus::flaky, all), FailureModeStatus::still_failing);
  EXPECT_EQ(replay_status(FailureModeStatus::regressed, all), FailureModeStatus::still_failing);
  EXPECT_EQ(replay_status(FailureModeStatus::fixed, all), FailureModeStatus::regressed);
  EXPECT_EQ(replay_status(FailureModeStatus::fixed, {1, 1, ""}), FailureModeStatus::regressed);
}

TEST(ReplayStatus, NoSeedFailingIsFixed) {
  for (FailureModeStatus before : kEveryStatus)
    EXPECT_EQ(replay_status(before, {3, 0, ""}), FailureModeStatus::fixed) << status_name(before);
}

TEST(ReplayStatus, SomeSeedsFailingIsFlaky) {
  for (FailureModeStatus before : kEveryStatus) {
    EXPECT_EQ(replay_status(before, {3, 1, ""}), FailureModeStatus::flaky) << status_name(before);
    EXPECT_EQ(replay_status(before, {3, 2, ""}), FailureModeStatus::flaky) << status_name(before);
  }
}

TEST(ReplayStatus, NothingTriedOrAnErrorLeavesTheStatus) {
  for (FailureModeStatus before : kEveryStatus) {
    EXPECT_EQ(replay_status(before, {0, 0, ""}), before) << status_name(before);
    EXPECT_EQ(replay_status(before, {0, 0, "modes/x.avu: cannot read"}), before)
        << status_name(before);
    // An error after some seeds ran still tells nothing for certain.
    EXPECT_EQ(replay_status(before, {2, 2, "seed 9: the ego could not start"}), before)
        << status_name(before);
  }
}

TEST(ReplayStatusDeathTest, MoreFailingThanTriedIsABug) {
  EXPECT_DEATH(replay_status(FailureModeStatus::new_mode, {1, 2, ""}), "failing");
}

}  // namespace
}  // namespace scenfuzz
