// `scenfuzz` on a file that executes several scenarios, as LawBreaker's scenest files may
// (tests/fuzz/data/two_scenarios.scenest): `run`, the search, `space` and `check` take
// --scenario NAME, a campaign's [[seed]] table `scenario = "NAME"`; without it a file with
// several is bad usage (exit 2) naming the option and the scenarios; a finding names its scenario
// in its replay command, which replays it and which `tmin` and a campaign's replay follow
// (issue 21).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {
namespace {

namespace fs = std::filesystem;

const std::string kScenarios = "scenario1 (trace1), scenario2 (trace2)";

// Short runs: the specs are decided (or not) within seconds of simulated time.
const std::vector<std::string> kShort{"--duration", "4"};

std::string two_scenarios() { return source_file("tests/fuzz/data/two_scenarios.scenest"); }

class SeveralScenariosCommand : public CommandTest {
 protected:
  Outcome run(std::vector<std::string> args) {
    args.insert(args.begin(), {"run", "--out", (dir_ / "run").string()});
    args.insert(args.end(), kShort.begin(), kShort.end());
    return scenfuzz(args);
  }
};

TEST_F(SeveralScenariosCommand, RunWithoutAChoiceIsBadUsageNamingTheOptionAndTheScenarios) {
  const Outcome outcome = run({two_scenarios(), "--at", "mid"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("two_scenarios.scenest:42:7: error: this file executes 2 scenarios: " +
                             kScenarios + ": choose one with --scenario NAME"),
            std::string::npos)
      << outcome.err;
  EXPECT_EQ(outcome.err.find("terminate"), std::string::npos);
}

TEST_F(SeveralScenariosCommand, AnUnknownScenarioIsAnErrorListingThoseThatExist) {
  const Outcome outcome = run({two_scenarios(), "--at", "mid", "--scenario", "scenario3"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("there is no scenario 'scenario3' (--scenario): this file has " +
                             kScenarios),
            std::string::npos)
      << outcome.err;
}

TEST_F(SeveralScenariosCommand, RunJudgesOnlyTheChosenScenariosSpecs) {
  const Outcome second = run({two_scenarios(), "--at", "mid", "--scenario", "scenario2"});
  EXPECT_EQ(second.exit_code, 1) << second.out << second.err;
  EXPECT_NE(second.out.find("ped_far_away"), std::string::npos) << second.out;
  EXPECT_EQ(second.out.find("npc_kept_away"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("ped.init.speed = 1"), std::string::npos) << second.out;

  const Outcome first = run({two_scenarios(), "--at", "mid", "--scenario", "scenario1"});
  EXPECT_NE(first.exit_code, 2) << first.err;
  EXPECT_NE(first.out.find("npc_kept_away"), std::string::npos) << first.out;
  EXPECT_EQ(first.out.find("ped_far_away"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("npc1.init.position.s = 60"), std::string::npos) << first.out;
}

TEST_F(SeveralScenariosCommand, SpaceAndCheckKnowTheScenarios) {
  const Outcome space = scenfuzz({"space", two_scenarios(), "--scenario", "scenario1"});
  EXPECT_EQ(space.exit_code, 0) << space.err;
  EXPECT_NE(space.out.find("npc1.init.position.s"), std::string::npos) << space.out;
  EXPECT_EQ(space.out.find("ped.init.speed"), std::string::npos) << space.out;
  const Outcome unchosen = scenfuzz({"space", two_scenarios()});
  EXPECT_EQ(unchosen.exit_code, 2);
  EXPECT_NE(unchosen.err.find("choose one with --scenario NAME"), std::string::npos)
      << unchosen.err;

  // `check` checks every scenario and lists them; the file is good.
  const Outcome check = scenfuzz({"check", two_scenarios()});
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.err.find("note: this file executes 2 scenarios: " + kScenarios),
            std::string::npos)
      << check.err;
  const Outcome wrong = scenfuzz({"check", two_scenarios(), "--scenario", "scenario3"});
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_NE(wrong.err.find("there is no scenario 'scenario3'"), std::string::npos) << wrong.err;
}

// The words of a finding's replay line after `scenfuzz run `, split at spaces (paths here have
// none that matter: the scratch folder's name has no spaces or quotes).
std::vector<std::string> replay_words(const std::string& finding) {
  const std::string mark = "// replay: scenfuzz run ";
  const std::size_t at = finding.find(mark);
  if (at == std::string::npos) return {};
  const std::string line =
      finding.substr(at + mark.size(), finding.find('\n', at) - at - mark.size());
  std::vector<std::string> words;
  std::string word;
  for (char c : line) {
    if (c == ' ') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else if (c != '\'') {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

TEST_F(SeveralScenariosCommand, ASearchOfTheSecondScenarioWritesFindingsThatReplay) {
  const Outcome unchosen =
      scenfuzz({"--budget", "2", "--out", (dir_ / "none").string(), two_scenarios()});
  EXPECT_EQ(unchosen.exit_code, 2);
  EXPECT_NE(unchosen.err.find("choose one with --scenario NAME"), std::string::npos)
      << unchosen.err;

  // A name is one file's: not for a corpus.
  const Outcome corpus = scenfuzz({"--budget", "4", "--out", (dir_ / "corpus").string(),
                                   "--scenario", "scenario2", two_scenarios(), two_scenarios()});
  EXPECT_EQ(corpus.exit_code, 2);
  EXPECT_NE(corpus.err.find("--scenario chooses a scenario of one FILE, not of a corpus"),
            std::string::npos)
      << corpus.err;

  const fs::path out = dir_ / "search";
  const Outcome search = scenfuzz({"--budget", "2", "-j", "1", "--quiet", "--out", out.string(),
                                   "--scenario", "scenario2", "--duration", "4", two_scenarios()});
  ASSERT_EQ(search.exit_code, 1) << search.err;
  std::vector<fs::path> findings;
  for (const auto& entry : fs::directory_iterator(out / "findings"))
    if (entry.path().extension() == ".scenest") findings.push_back(entry.path());
  ASSERT_FALSE(findings.empty());
  const std::string finding = slurp(findings.front());
  EXPECT_NE(finding.find("ped_far_away"), std::string::npos);
  // The whole file, with only scenario2's numbers fixed: scenario1's range is still there.
  EXPECT_NE(finding.find("scenario1 = CreateScenario{"), std::string::npos) << finding;
  EXPECT_NE(finding.find("(\"east_0\"->range(50.0, 70.0), , 8.0)"), std::string::npos) << finding;
  EXPECT_EQ(finding.find("range(0.5, 1.5)"), std::string::npos) << finding;

  // Its replay command names the scenario, and replays the violation.
  std::vector<std::string> words = replay_words(finding);
  ASSERT_GE(words.size(), 3u) << finding;
  EXPECT_EQ(words[1], "--scenario");
  EXPECT_EQ(words[2], "scenario2");
  words.insert(words.begin(), {"run", "--out", (dir_ / "replay").string()});
  const Outcome replay = scenfuzz(words);
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("ped_far_away"), std::string::npos) << replay.out;

  // --resume continues only the same scenario's search.
  const Outcome other =
      scenfuzz({"--budget", "2", "-j", "1", "--quiet", "--out", out.string(), "--scenario",
                "scenario1", "--duration", "4", "--resume", two_scenarios()});
  EXPECT_EQ(other.exit_code, 2) << other.err;
  EXPECT_NE(other.err.find("its scenario_choice was \"scenario2\", now \"scenario1\""),
            std::string::npos)
      << other.err;

  // tmin reads the choice from the replay line, and its output's replay keeps it.
  const std::string minimised = (dir_ / "min.scenest").string();
  const Outcome tmin = scenfuzz({"tmin", findings.front().string(), "-o", minimised});
  EXPECT_EQ(tmin.exit_code, 0) << tmin.out << tmin.err;
  EXPECT_NE(tmin.out.find(" --scenario scenario2"), std::string::npos) << tmin.out;
}

TEST_F(SeveralScenariosCommand, ACampaignSeedTableChoosesTheScenarioAndItsModesReplayIt) {
  const fs::path folder = dir_ / "c";
  fs::create_directories(folder);
  fs::copy_file(two_scenarios(), folder / "two.scenest");
  const std::string toml =
      "seeds = [\"two.scenest\"]\n\n[budget]\nsimulations = 32\n\n[search]\nseed = 7\n";
  write("c/campaign.toml", toml);
  const Outcome unchosen = scenfuzz({"campaign", "run", folder.string(), "-j", "1"});
  EXPECT_EQ(unchosen.exit_code, 2);
  EXPECT_NE(unchosen.err.find("this file executes 2 scenarios: " + kScenarios), std::string::npos)
      << unchosen.err;
  EXPECT_FALSE(fs::exists(folder / "campaign.db"));

  write("c/campaign.toml", toml + "\n[[seed]]\npath = \"two.scenest\"\nscenario = \"scenario2\"\n");
  const Outcome first = scenfuzz({"campaign", "run", folder.string(), "-j", "1"});
  ASSERT_EQ(first.exit_code, 1) << first.out << first.err;
  // Only scenario2's spec is searched.
  EXPECT_NE(first.out.find("two.scenest ped_far_away"), std::string::npos) << first.out;
  EXPECT_EQ(first.out.find("npc_kept_away"), std::string::npos) << first.out;
  std::size_t modes = 0;
  for (const auto& entry : fs::directory_iterator(folder / "modes")) {
    if (entry.path().extension() != ".scenest") continue;
    ++modes;
    EXPECT_NE(slurp(entry.path()).find(" --scenario scenario2 --seed "), std::string::npos);
  }
  EXPECT_GT(modes, 0u);
  // The next run replays the stored whole file's scenario2: the mode still fails.
  const Outcome second = scenfuzz({"campaign", "run", folder.string(), "-j", "1"});
  EXPECT_EQ(second.exit_code, 0) << second.out << second.err;
  EXPECT_NE(second.out.find("regression replay: still_failing " + std::to_string(modes)),
            std::string::npos)
      << second.out << second.err;
  const Outcome report = scenfuzz({"campaign", "report", folder.string()});
  EXPECT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(slurp(folder / "report.html").find("scenfuzz run --scenario scenario2 --seed "),
            std::string::npos);
}

}  // namespace
}  // namespace scenfuzz::test
