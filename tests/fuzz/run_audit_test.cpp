// `scenfuzz run` reports the trace audit: one `audit:` line per issue after the collisions (or a
// line saying every actor drove plausibly), and an "audit" array in --json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

using test::Outcome;

// Two scripted NPCs in one lane, the faster behind: it drives through the slower one.
constexpr const char* kRamming =
    "ego = AV((\"east_0\"->20, , 0), (\"east_0\"->480));\n"
    "slow = Vehicle((\"east_1\"->100, , 2), Waypoint((\"east_1\"->150, , 2)), "
    "(\"east_1\"->400));\n"
    "fast = Vehicle((\"east_1\"->40, , 15), Waypoint((\"east_1\"->300, , 15)), "
    "(\"east_1\"->400));\n"
    "scenario = CreateScenario{load(\"straight\"); ego; {slow, fast}; {}; {};};\n"
    "Trace trace = EXE(scenario);\n";

class RunAuditTest : public test::CommandTest {
 protected:
  Outcome run(const std::string& path, bool json) {
    std::vector<std::string> args = {"run", path, "--at", "mid", "--out", (dir_ / "out").string()};
    if (json) args.push_back("--json");
    return scenfuzz(args);
  }
};

TEST_F(RunAuditTest, TextNamesEachIssueAfterTheCollisions) {
  const Outcome outcome = run(write("ramming.avu", kRamming), false);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::size_t collision = outcome.out.find("collision at 4.3 s: slow rear / fast front");
  const std::size_t overlap = outcome.out.find("audit: slow overlaps fast from 4.3 s\n");
  ASSERT_NE(collision, std::string::npos) << outcome.out;
  ASSERT_NE(overlap, std::string::npos) << outcome.out;
  EXPECT_LT(collision, overlap);
  EXPECT_LT(overlap, outcome.out.find("ego reached its target: "));
  EXPECT_EQ(outcome.out.find("every actor drove plausibly"), std::string::npos);
}

TEST_F(RunAuditTest, JsonHasAnAuditArray) {
  const Outcome outcome = run(write("ramming.avu", kRamming), true);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json summary = nlohmann::json::parse(outcome.out);
  ASSERT_TRUE(summary["audit"].is_array());
  ASSERT_EQ(summary["audit"].size(), 1u) << outcome.out;
  const nlohmann::json& issue = summary["audit"][0];
  EXPECT_EQ(issue["actor"], "slow");
  EXPECT_EQ(issue["kind"], "npc_overlap");
  EXPECT_EQ(issue["other"], "fast");
  EXPECT_NEAR(issue["time"].get<double>(), 4.3, 1e-9);
  for (const char* key : {"worst_time", "worst", "limit", "samples"})
    EXPECT_TRUE(issue.contains(key)) << key;
}

TEST_F(RunAuditTest, APlausibleRunSaysSo) {
  // The ego passes the wreck and reaches its target within the default duration: exit 0.
  const Outcome text =
      run(test::source_file("corpora/avunit/stationary_obstacle_in_lane.avu"), false);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("no collision\naudit: every actor drove plausibly\n"), std::string::npos)
      << text.out;
  const Outcome json =
      run(test::source_file("corpora/avunit/stationary_obstacle_in_lane.avu"), true);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json summary = nlohmann::json::parse(json.out);
  ASSERT_TRUE(summary["audit"].is_array());
  EXPECT_TRUE(summary["audit"].empty());
}

// corpora/avunit/overtaking_oncoming.avu at one point of its space: an oncoming car drifts to
// the centre line and back into west_1 over 23.5 m, both legs planned (Dubins). The planner's
// last pose fell 3 cm before the waypoint, and the car, slowed to 2 m/s there, turned through
// that vertex in one step at 1.1 rad/s, tighter than full lock.
constexpr const char* kDriftBack =
    "ego = AV((\"east_0\"->30, , 14), ((400.0, -5.25)));\n"
    "truck = Vehicle((\"east_0\"->100, , 8), uniform((\"east_0\"->100, , 8)), "
    "(\"east_0\"->495));\n"
    "car = Vehicle((\"west_1\"->171.06232483593, , 16.562891084606733), "
    "Waypoint(((103.461715147, -0.032532884349), , 16.562891084606733), "
    "(\"west_1\"->420, , 16.562891084606733)), (\"west_1\"->490), (\"Sedan\", red));\n"
    "scenario = CreateScenario{load(\"straight\"); ego; {truck, car}; {}; {};};\n"
    "Trace trace = EXE(scenario);\n";

TEST_F(RunAuditTest, APlannedLegEndsWithoutASliverThatTurnsTooTightly) {
  const Outcome outcome = run(write("drift.avu", kDriftBack), false);
  ASSERT_NE(outcome.exit_code, 2) << outcome.err;
  EXPECT_EQ(outcome.out.find("tighter than full lock"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("every actor drove plausibly"), std::string::npos) << outcome.out;
}

}  // namespace
}  // namespace scenfuzz
