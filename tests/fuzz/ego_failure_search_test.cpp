// End-to-end: a search whose ego plugin crashes, hangs or returns an error reports each as a
// finding of its own kind (never a judged trace), de-duplicated by kind and signal, with the
// step, the simulated time, the last observation and a replay command that reproduces it, and
// exits 1; a plugin that cannot be loaded at all is a bad option (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::slurp;

const std::string kCutIn = test::source_file("corpora/avunit/cut_in_straight.avu");

std::string plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

class EgoFailureSearchTest : public test::CommandTest {
 protected:
  Outcome search(const std::string& plugin_name, std::vector<std::string> extra,
                 const std::string& budget = "12") {
    std::vector<std::string> args = {"--budget", budget, "--seed", "3", "--quiet"};
    for (const std::string& arg : {std::string("--ego-plugin"), plugin(plugin_name),
                                   std::string("--out"), (dir_ / "out").string()})
      args.push_back(arg);
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(kCutIn);
    return scenfuzz(args);
  }
  nlohmann::json summary() const {
    return nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  }
};

TEST_F(EgoFailureSearchTest, ACrashIsOneFindingWithEverythingToReplayIt) {
  const Outcome run = search("crashing", {});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json summary = this->summary();
  EXPECT_EQ(summary["judged"], 0);
  EXPECT_EQ(summary["failed"], 12);
  EXPECT_EQ(summary["ego_failures"], 12);
  // Twelve crashes with one signal are one finding.
  ASSERT_EQ(summary["findings"].size(), 1u) << summary.dump(2);
  const nlohmann::json& finding = summary["findings"][0];
  EXPECT_EQ(finding["kind"], "ego_crash");
  EXPECT_NE(finding["reason"].get<std::string>().find("SIGSEGV"), std::string::npos);
  EXPECT_FALSE(finding.contains("robustness"));

  const std::string path = finding["file"].get<std::string>();
  EXPECT_NE(path.find("001-ego_crash.avu"), std::string::npos);
  const std::string text = slurp(path);
  EXPECT_NE(text.find("// scenfuzz finding 1: ego_crash:"), std::string::npos) << text;
  EXPECT_NE(text.find("at step 3, 0.1 s simulated"), std::string::npos) << text;
  EXPECT_NE(text.find("// last observation handed to the plugin: "), std::string::npos) << text;
  const nlohmann::json observation =
      nlohmann::json::parse(slurp(dir_ / "out" / "findings" / "001-ego_crash.observation.json"));
  EXPECT_DOUBLE_EQ(observation["ego"]["time"].get<double>(), 0.1);

  const std::string csv = slurp(dir_ / "out" / "evaluations.csv");
  EXPECT_NE(csv.find(",failed,ego_crash,"), std::string::npos);
  EXPECT_EQ(csv.find(",judged,"), std::string::npos);

  // The replay command in the header, run as written, crashes the same way: exit 1.
  std::smatch replay;
  ASSERT_TRUE(std::regex_search(
      text, replay,
      std::regex("// replay: scenfuzz run (\\S+) --seed (\\d+) --ego-plugin (\\S+)")));
  const Outcome replayed =
      scenfuzz({"run", replay[1].str(), "--seed", replay[2].str(), "--ego-plugin", replay[3].str(),
                "--out", (dir_ / "replay").string()});
  EXPECT_EQ(replayed.exit_code, 1) << replayed.out << replayed.err;
  EXPECT_NE((replayed.out + replayed.err).find("SIGSEGV"), std::string::npos)
      << replayed.out << replayed.err;
}

TEST_F(EgoFailureSearchTest, AHangAndAnErrorAreFindingsOfTheirKinds) {
  Outcome run = search("hanging", {"--ego-step-timeout", "0.2"}, "4");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  ASSERT_EQ(summary()["findings"].size(), 1u);
  EXPECT_EQ(summary()["findings"][0]["kind"], "ego_hang");
  const std::string text = slurp(summary()["findings"][0]["file"].get<std::string>());
  EXPECT_NE(text.find("--ego-step-timeout 0.2"), std::string::npos) << text;

  run = search("failing", {"--force"});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  ASSERT_EQ(summary()["findings"].size(), 1u);
  EXPECT_EQ(summary()["findings"][0]["kind"], "ego_error");
}

TEST_F(EgoFailureSearchTest, APluginThatCannotBeLoadedIsABadOption) {
  const Outcome run = search("missing_symbol", {});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no evaluation could be judged"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("missing_symbol"), std::string::npos) << run.err;
  EXPECT_TRUE(summary()["findings"].empty());
}

}  // namespace
}  // namespace scenfuzz
