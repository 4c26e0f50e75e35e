// `scenfuzz campaign run` through the executable with the real regression replay and its CI
// outputs: over four runs a failure mode moves new -> still failing -> fixed -> regressed as the
// ego changes, and the exit status, the --json summary (parsed with nlohmann) and the --junit
// file (parsed with pugixml) say so each time; usage errors of the outputs exit 2. In process: a
// run interrupted during its replay and continued still reports the first part's replays (they
// are read back from the database).
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_run.hpp"
#include "fuzz/cli.hpp"
#include "tests/campaign/campaign_fixture.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

// The last line of `text` (the JSON summary on stdout).
std::string last_line(const std::string& text) {
  std::string line, last;
  std::istringstream lines(text);
  while (std::getline(lines, line))
    if (!line.empty()) last = line;
  return last;
}

// The modes of group `group` whose signature is `signature`.
std::vector<nlohmann::json> in_group(const nlohmann::json& summary, const std::string& group,
                                     const std::string& signature) {
  std::vector<nlohmann::json> modes;
  for (const nlohmann::json& mode : summary.at("failure_modes").at(group))
    if (mode.at("signature") == signature) modes.push_back(mode);
  return modes;
}

// The <testcase> whose name ends with `signature`, and its first child's name and type
// ("failure"/"new", "error"/"replay_error", "skipped", or "" when it passes).
struct JunitCase {
  bool present = false;
  std::string outcome, type;
};

JunitCase junit_case(const pugi::xml_document& document, const std::string& signature) {
  for (const pugi::xpath_node& node : document.select_nodes("//testcase")) {
    const std::string name = node.node().attribute("name").value();
    if (name.size() < signature.size() ||
        name.compare(name.size() - signature.size(), signature.size(), signature) != 0)
      continue;
    for (const char* outcome : {"failure", "error", "skipped"})
      if (const pugi::xml_node child = node.node().child(outcome))
        return {true, outcome, child.attribute("type").value()};
    return {true, "", ""};
  }
  return {};
}

class CampaignRunOutputsTest : public CommandTest {
 protected:
  // campaign.toml over cut_in_straight.avu, with `ego` as its [ego] table (empty: the reference
  // driver).
  void write_campaign(const std::string& ego) {
    fs::create_directories(dir_ / "c");
    write("c/campaign.toml", campaign_toml({source_file("corpora/avunit/cut_in_straight.avu")},
                                           "simulations = 64", ego));
  }

  // One run with --json and --junit; the summary parsed, the JUnit file loaded into `junit_`.
  nlohmann::json run(int& exit_code) {
    const std::string junit = (dir_ / "junit.xml").string();
    fs::remove(junit);
    const Outcome outcome =
        scenfuzz({"campaign", "run", (dir_ / "c").string(), "--json", "--junit", junit});
    exit_code = outcome.exit_code;
    EXPECT_TRUE(outcome.exit_code == 0 || outcome.exit_code == 1) << outcome.err;
    // stdout is the summary alone; the progress went to stderr.
    EXPECT_EQ(outcome.out.find('\n'), outcome.out.size() - 1) << outcome.out;
    EXPECT_NE(outcome.err.find("round 0: "), std::string::npos) << outcome.err;
    const pugi::xml_parse_result parsed = junit_.load_file(junit.c_str());
    EXPECT_TRUE(parsed) << parsed.description();
    return nlohmann::json::parse(last_line(outcome.out));
  }

  pugi::xml_document junit_;
};

#ifdef SCENFUZZ_TEST_PLUGIN_DIR
// The plugin crashes at its third step in every scenario: one failure mode, ego_crash SIGSEGV,
// that replays exactly with the plugin and never without it.
TEST_F(CampaignRunOutputsTest, AModeMovesFromNewToRegressedAsTheEgoChanges) {
  const std::string crashing =
      "[ego]\nplugin = \"" + std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/libcrashing.so\"\n";
  const std::string crash = "ego_crash SIGSEGV";
  int status = -1;

  write_campaign(crashing + "version = \"crash-1\"\n");
  nlohmann::json summary = run(status);
  EXPECT_EQ(status, 1);
  EXPECT_EQ(summary.at("exit_status"), 1);
  EXPECT_EQ(summary.at("run").at("id"), 1);
  ASSERT_EQ(in_group(summary, "new", crash).size(), 1u) << summary.dump(2);
  EXPECT_TRUE(in_group(summary, "new", crash)[0].at("replay").is_null());
  EXPECT_EQ(junit_case(junit_, crash).outcome, "failure");
  EXPECT_EQ(junit_case(junit_, crash).type, "new");

  // The same ego: the replay fails on every perception seed; nothing new, so exit 0.
  summary = run(status);
  EXPECT_EQ(status, 0) << summary.dump(2);
  EXPECT_EQ(summary.at("exit_status"), 0);
  EXPECT_EQ(summary.at("exit_reason"), "0: no new failure mode and no regression");
  ASSERT_EQ(in_group(summary, "still_failing", crash).size(), 1u) << summary.dump(2);
  const nlohmann::json replay = in_group(summary, "still_failing", crash)[0].at("replay");
  EXPECT_EQ(replay.at("tried"), 3);
  EXPECT_EQ(replay.at("failing"), 3);
  EXPECT_TRUE(summary.at("failure_modes").at("new").empty());
  EXPECT_EQ(junit_case(junit_, crash).type, "still_failing");

  // A new ego, the reference driver, no longer crashes: fixed (its searches may find collisions,
  // new modes that alone decide the exit status).
  write_campaign("");
  summary = run(status);
  ASSERT_EQ(in_group(summary, "fixed", crash).size(), 1u) << summary.dump(2);
  EXPECT_EQ(in_group(summary, "fixed", crash)[0].at("replay").at("failing"), 0);
  EXPECT_EQ(junit_case(junit_, crash).outcome, "");  // passes
  const std::size_t run3_new = summary.at("failure_modes").at("new").size();
  EXPECT_EQ(status, run3_new > 0 ? 1 : 0);
  EXPECT_EQ(summary.at("exit_status"), status);

  // The crashing ego again: the fixed mode fails every replay seed and the searches find it too;
  // it stays regressed, and the run exits 1 for it.
  write_campaign(crashing + "version = \"crash-2\"\n");
  summary = run(status);
  EXPECT_EQ(status, 1);
  ASSERT_EQ(in_group(summary, "regressed", crash).size(), 1u) << summary.dump(2);
  EXPECT_EQ(in_group(summary, "regressed", crash)[0].at("last_seen_run"), 4);
  EXPECT_NE(summary.at("exit_reason").get<std::string>().find("1 regression"), std::string::npos)
      << summary.at("exit_reason");
  EXPECT_EQ(junit_case(junit_, crash).type, "regressed");
  // Run 3's collisions cannot be judged with an ego that crashes first: replay errors, with the
  // reason, keeping their status (new, of run 3: not this run's, so not counted).
  EXPECT_EQ(summary.at("failure_modes").at("replay_errors").size(), run3_new);
  for (const nlohmann::json& mode : summary.at("failure_modes").at("replay_errors")) {
    EXPECT_FALSE(mode.at("replay").at("error").get<std::string>().empty()) << mode.dump();
    EXPECT_EQ(mode.at("status"), "new");
    EXPECT_EQ(junit_case(junit_, mode.at("signature")).type, "replay_error");
  }
  EXPECT_TRUE(summary.at("failure_modes").at("new").empty());
}
#endif

TEST_F(CampaignRunOutputsTest, OutputUsageErrorsExitTwoBeforeTheRun) {
  write_campaign("");
  Outcome outcome = scenfuzz({"campaign", "run", (dir_ / "c").string(), "--junit",
                              (dir_ / "missing" / "junit.xml").string()});
  EXPECT_EQ(outcome.exit_code, kExitBadInput);
  EXPECT_NE(outcome.err.find("--junit"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("folder does not exist"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(dir_ / "c" / "campaign.db"));
  outcome = scenfuzz({"campaign", "run", (dir_ / "c").string(), "--junit"});
  EXPECT_EQ(outcome.exit_code, kExitUsage);
  EXPECT_NE(outcome.err.find("--junit"), std::string::npos) << outcome.err;
  // A campaign.toml with errors: exit 2 and nothing on stdout for a script to misread.
  write("c/campaign.toml", "seeds = []\n");
  outcome = scenfuzz({"campaign", "run", (dir_ / "c").string(), "--json"});
  EXPECT_EQ(outcome.exit_code, kExitBadInput);
  EXPECT_EQ(outcome.out, "");
  EXPECT_NE(outcome.err.find("campaign.toml:1:"), std::string::npos) << outcome.err;
}

// SIGINT during the regression replay: the run stops, unfinished, after the mode in hand. The
// next run continues it, replays only the modes not replayed yet, and its summary has the first
// part's replays too, read back from the replays table.
TEST_F(CampaignRunOutputsTest, AContinuedRunKnowsTheReplaysOfItsFirstPart) {
  fs::create_directories(dir_ / "c");
  write("c/campaign.toml", campaign_toml(small_campaign_seeds(), "simulations = 320"));
  std::ostringstream out, err;
  const ModeReplayer unused = [](const CampaignFailureMode&) { return ReplayOutcome{}; };
  CampaignRunOptions options{(dir_ / "c").string(), 2, "", true};
  ASSERT_EQ(run_campaign(options, unused, out, err), kExitViolated) << err.str();
  const std::size_t known =
      nlohmann::json::parse(last_line(out.str())).at("failure_modes").at("new").size();
  ASSERT_GE(known, 2u);

  std::vector<std::int64_t> first_part;
  const ModeReplayer fixed_then_stop = [&](const CampaignFailureMode& mode) {
    first_part.push_back(mode.id);
    std::raise(SIGINT);  // as Ctrl-C: the guard asks the run to stop
    return ReplayOutcome{3, 0, ""};
  };
  out.str("");
  err.str("");
  EXPECT_EQ(run_campaign(options, fixed_then_stop, out, err), kExitSuccess) << err.str();
  EXPECT_NE(err.str().find("interrupted"), std::string::npos) << err.str();
  ASSERT_EQ(first_part.size(), 1u);
  nlohmann::json summary = nlohmann::json::parse(last_line(out.str()));
  EXPECT_EQ(summary.at("failure_modes").at("fixed").size(), 1u) << summary.dump(2);
  EXPECT_TRUE(summary.at("run").at("ended").is_null()) << summary.dump(2);

  std::vector<std::int64_t> second_part;
  const ModeReplayer still_failing = [&](const CampaignFailureMode& mode) {
    second_part.push_back(mode.id);
    return ReplayOutcome{3, 3, ""};
  };
  out.str("");
  err.str("");
  const int status = run_campaign(options, still_failing, out, err);
  EXPECT_NE(err.str().find("continuing run 2"), std::string::npos) << err.str();
  EXPECT_EQ(second_part.size(), known - 1);
  EXPECT_EQ(std::count(second_part.begin(), second_part.end(), first_part[0]), 0);
  summary = nlohmann::json::parse(last_line(out.str()));
  EXPECT_EQ(summary.at("run").at("id"), 2);
  EXPECT_EQ(summary.at("exit_status"), status);
  // The first part's mode: fixed by its replay, or regressed when a search found it after.
  bool seen = false;
  for (const char* group : {"fixed", "regressed"})
    for (const nlohmann::json& mode : summary.at("failure_modes").at(group))
      if (mode.at("id") == first_part[0]) {
        seen = true;
        EXPECT_EQ(mode.at("replay").at("tried"), 3);
        EXPECT_EQ(mode.at("replay").at("failing"), 0);
      }
  EXPECT_TRUE(seen) << summary.dump(2);
  // 3 simulations per replayed mode, all of them counted in the run.
  std::uint64_t searched = 0;
  {
    CampaignDbOpening opening = CampaignDb::open(dir_ / "c");
    ASSERT_TRUE(opening.db) << opening.error;
    for (const CampaignSearch& search : opening.db->list_searches())
      if (search.record.run_id == 2) searched += search.record.simulations;
  }
  EXPECT_EQ(summary.at("simulations"), searched + 3 * known);
}

}  // namespace
}  // namespace scenfuzz::test
