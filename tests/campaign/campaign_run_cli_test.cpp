// `scenfuzz campaign run` on the command line: its usage errors and a folder without a campaign
// exit 2 with a message naming the problem; its help names DIR, -j, --junit, --json and the exit
// statuses.
#include <gtest/gtest.h>

#include <string>

#include "fuzz/cli.hpp"
#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {
namespace {

class CampaignRunCliTest : public CommandTest {};

TEST_F(CampaignRunCliTest, UsageErrorsExitTwoNamingTheProblem) {
  Outcome outcome = scenfuzz({"campaign", "run"});
  EXPECT_EQ(outcome.exit_code, kExitUsage);
  EXPECT_NE(outcome.err.find("DIR is required"), std::string::npos) << outcome.err;
  outcome = scenfuzz({"campaign", "run", dir_.string(), "-j", "-1"});
  EXPECT_EQ(outcome.exit_code, kExitUsage);
  EXPECT_NE(outcome.err.find("-j"), std::string::npos) << outcome.err;
}

TEST_F(CampaignRunCliTest, AFolderWithoutACampaignIsRefused) {
  const Outcome outcome = scenfuzz({"campaign", "run", dir_.string()});
  EXPECT_EQ(outcome.exit_code, kExitBadInput);
  EXPECT_NE(outcome.err.find("cannot read '" + (dir_ / "campaign.toml").string() + "'"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("scenfuzz campaign init"), std::string::npos) << outcome.err;
}

TEST_F(CampaignRunCliTest, ACampaignTomlWithErrorsIsReportedAtItsLine) {
  write("campaign.toml", "seeds = []\n");
  const Outcome outcome = scenfuzz({"campaign", "run", dir_.string()});
  EXPECT_EQ(outcome.exit_code, kExitBadInput);
  EXPECT_NE(outcome.err.find("campaign.toml:1:"), std::string::npos) << outcome.err;
}

TEST_F(CampaignRunCliTest, HelpNamesTheFolderTheOptionsAndTheExitStatuses) {
  const Outcome outcome = scenfuzz({"campaign", "run", "--help"});
  EXPECT_EQ(outcome.exit_code, kExitSuccess);
  EXPECT_NE(outcome.out.find("DIR"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("-j,--jobs"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("--junit FILE"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("--json"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("Exit status: 0"), std::string::npos) << outcome.out;
}

}  // namespace
}  // namespace scenfuzz::test
