// --tmin: a search minimises each finding it keeps, beside it (findings/NNN-SPEC.min.avu), the
// same files for any -j; summary.json says what became of each; a finding that cannot be
// minimised is a warning, not a failure of the search; a finished search resumed with --tmin
// added minimises it; and minimise_findings stops without writing when asked to.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "fuzz/findings_tmin.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;

// The ego waits in east_0 and a scripted car (rammer, at a speed searched) drives into it from
// behind; far1 (starting where the search says) and far2 drive in east_1 and a box stands by the
// road. Two failure modes in a few evaluations: the collision with the rammer, and far1 within
// 15 m of the ego (from the start, when it starts beside it).
constexpr const char* kTwoModes = R"(
ego = AV(("east_0"->60.123456, , 0), ("east_0"->480));
rammer = Vehicle(("east_0"->10.987654, , range(11, 14)),
                 Waypoint(("east_0"->200.4321, , 12.345678), ("east_0"->300.5, , 11.75)),
                 ("east_0"->400));
far1 = Vehicle(("east_1"->range(40, 300), , 5.5), Waypoint(("east_1"->455, , 5.5)),
               ("east_1"->460));
far2 = Vehicle(("east_1"->250.125, , 6.25), Waypoint(("east_1"->320.5, , 6.25)), ("east_1"->440));
box = Obstacle("east_1"->470.5, (box, 1.25, 1.0, 0.8));
env = Environment(21:30, {rain: 0.7, fog: 0.25});
scenario = CreateScenario{load("straight"); ego; {rammer, far1, far2}; {}; {box}; env;
                          {NPCBehaviour(scripted)};};
Trace trace = EXE(scenario);
no_rammer_collision = G (dis(trace[ego], trace[truth][rammer]) > 0.5);
keeps_clear_of_far1 = G (dis(trace[ego], trace[truth][far1]) > 15);
trace |= no_rammer_collision;
trace |= keeps_clear_of_far1;
)";

// "failure mode: ..." of a file's text.
std::string mode_line(const std::string& text) {
  const std::size_t at = text.find("failure mode: ");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

// The seed of a file's "replay: scenfuzz run FILE --seed N ..." line.
std::string replay_seed(const std::string& text) {
  const std::size_t at = text.find(" --seed ");
  if (at == std::string::npos) return "";
  const std::size_t from = at + 8;
  return text.substr(from, text.find_first_of(" \n", from) - from);
}

class SearchTminTest : public test::CommandTest {
 protected:
  Outcome search(const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"--budget", "4",       "--seed",          "3", "--out", out,
                                     input_,     "--quiet", "--all-collisions"};
    args.insert(args.end(), extra.begin(), extra.end());
    return scenfuzz(args);
  }

  // The summary's findings: scenario file -> the finding's entry.
  static std::map<std::string, nlohmann::json> findings(const fs::path& out) {
    const nlohmann::json summary = nlohmann::json::parse(test::slurp(out / "summary.json"));
    std::map<std::string, nlohmann::json> by_file;
    for (const nlohmann::json& finding : summary.at("findings"))
      by_file[finding.at("file").get<std::string>()] = finding;
    return by_file;
  }

  // findings/*.min.avu by name -> content.
  static std::map<std::string, std::string> minimised_files(const fs::path& out) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(out / "findings"))
      if (entry.path().string().ends_with(".min.avu"))
        files[entry.path().filename().string()] = test::slurp(entry.path());
    return files;
  }

  void SetUp() override {
    CommandTest::SetUp();
    input_ = write("two_modes.avu", kTwoModes);
  }

  std::string input_;
};

TEST_F(SearchTminTest, EachFindingIsMinimisedBesideItAndReplaysToItsMode) {
  const fs::path out = dir_ / "search";
  const Outcome run = search(out.string(), {"--tmin", "-j", "2"});
  ASSERT_EQ(run.exit_code, 1) << run.out << run.err;
  const std::map<std::string, nlohmann::json> found = findings(out);
  ASSERT_EQ(found.size(), 2u) << test::slurp(out / "summary.json");
  for (const auto& [file, entry] : found) {
    const fs::path finding(file);
    const fs::path minimised = finding.parent_path() / (finding.stem().string() + ".min.avu");
    ASSERT_TRUE(entry.contains("minimised")) << entry.dump();
    EXPECT_EQ(entry.at("minimised"), minimised.string()) << entry.dump();
    ASSERT_TRUE(fs::exists(minimised));
    const std::string text = test::slurp(minimised);
    // The header keeps the finding's mode, and the scenario lost what plays no part in it.
    EXPECT_EQ(mode_line(text), mode_line(test::slurp(finding))) << text;
    const std::string body = text.substr(text.find("// AVUnit printed by scenfuzz"));
    for (const char* gone : {"far2", "box", "rain", "fog"})
      EXPECT_EQ(body.find(gone), std::string::npos) << gone << "\n" << text;
    // Replayed with its seed it violates the finding's spec; and tmin, which replays it and
    // refuses a file that no longer fails as its header's mode says, finds nothing to remove.
    const Outcome replay = scenfuzz({"run", minimised.string(), "--seed", replay_seed(text),
                                     "--out", (dir_ / "replay").string(), "--all-collisions"});
    EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
    EXPECT_NE(replay.out.find("spec " + entry.at("spec").get<std::string>() + ": robustness -"),
              std::string::npos)
        << replay.out;
    const Outcome again =
        scenfuzz({"tmin", minimised.string(), "-o", (dir_ / "again.avu").string()});
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(mode_line(again.out), mode_line(text)) << again.out;
  }
}

TEST_F(SearchTminTest, TheMinimisedFilesAreTheSameForAnyJobs) {
  const fs::path one = dir_ / "one", two = dir_ / "two";
  ASSERT_EQ(search(one.string(), {"--tmin", "-j", "1"}).exit_code, 1);
  ASSERT_EQ(search(two.string(), {"--tmin", "-j", "2"}).exit_code, 1);
  const std::map<std::string, std::string> first = minimised_files(one);
  ASSERT_EQ(first.size(), 2u);
  std::map<std::string, std::string> second = minimised_files(two);
  // The header names the finding it came from, in its own folder.
  for (auto& [name, text] : second) {
    std::string::size_type at;
    while ((at = text.find(two.string())) != std::string::npos)
      text.replace(at, two.string().size(), one.string());
  }
  EXPECT_EQ(first, second);
}

TEST_F(SearchTminTest, AFinishedSearchResumedWithTminIsMinimised) {
  const fs::path out = dir_ / "search";
  ASSERT_EQ(search(out.string(), {}).exit_code, 1);
  EXPECT_TRUE(minimised_files(out).empty());
  for (const auto& [file, entry] : findings(out)) EXPECT_FALSE(entry.contains("minimised"));
  // --tmin is not part of what the search is: resuming with it is the same search.
  const Outcome resumed = search(out.string(), {"--resume", "--tmin"});
  ASSERT_EQ(resumed.exit_code, 1) << resumed.err;
  EXPECT_EQ(resumed.err.find("cannot resume"), std::string::npos) << resumed.err;
  EXPECT_EQ(minimised_files(out).size(), 2u);
  for (const auto& [file, entry] : findings(out))
    EXPECT_TRUE(entry.contains("minimised") && entry.at("minimised").is_string()) << entry.dump();
  // Once more: what is in place is kept, byte for byte.
  const std::map<std::string, std::string> before = minimised_files(out);
  ASSERT_EQ(search(out.string(), {"--resume", "--tmin"}).exit_code, 1);
  EXPECT_EQ(minimised_files(out), before);
}

// When the search writes a finding anew (a mode's new representative; here: a finding whose header
// no longer names its evaluation, which a resumed search writes again), the minimised file of the
// one it replaces goes: it is minimised again, not kept.
TEST_F(SearchTminTest, AFindingWrittenAnewIsMinimisedAnew) {
  const fs::path out = dir_ / "search";
  ASSERT_EQ(search(out.string(), {"--tmin"}).exit_code, 1);
  const std::map<std::string, std::string> minimised = minimised_files(out);
  ASSERT_EQ(minimised.size(), 2u);
  const fs::path finding = out / "findings" / "001-no_rammer_collision.avu";
  const fs::path stale = out / "findings" / "001-no_rammer_collision.min.avu";
  std::string text = test::slurp(finding);
  ASSERT_NE(text.find(", evaluation "), std::string::npos) << text;
  text.replace(text.find(", evaluation "), 13, ", evaluation 1000");
  std::ofstream(finding, std::ios::binary) << text;
  std::ofstream(stale, std::ios::binary) << "// stale\n";

  ASSERT_EQ(search(out.string(), {"--resume", "--tmin"}).exit_code, 1);
  EXPECT_EQ(test::slurp(finding).find(", evaluation 1000"), std::string::npos);
  EXPECT_EQ(minimised_files(out), minimised);
}

// A finding that no longer fails on replay (here: its spec edited after the search) cannot be
// minimised: a warning and its reason in summary.json, the other finding minimised, and the
// search's exit status unchanged.
TEST_F(SearchTminTest, AFindingThatCannotBeMinimisedIsAWarning) {
  const fs::path out = dir_ / "search";
  ASSERT_EQ(search(out.string(), {}).exit_code, 1);
  const fs::path edited = out / "findings" / "001-no_rammer_collision.avu";
  std::string text = test::slurp(edited);
  const std::string threshold = "= G (dis(trace[ego], trace[truth][rammer]) > 0.5)";
  ASSERT_NE(text.find(threshold), std::string::npos) << text;
  text.replace(text.find(threshold), threshold.size(),
               "= G (dis(trace[ego], trace[truth][rammer]) > -1)");
  std::ofstream(edited, std::ios::binary) << text;

  const Outcome resumed = search(out.string(), {"--resume", "--tmin"});
  ASSERT_EQ(resumed.exit_code, 1) << resumed.err;
  EXPECT_NE(resumed.err.find("scenfuzz: warning: finding 001 is not minimised: "),
            std::string::npos)
      << resumed.err;
  const std::map<std::string, nlohmann::json> found = findings(out);
  ASSERT_EQ(found.size(), 2u);
  const nlohmann::json& refused = found.at(edited.string());
  EXPECT_TRUE(refused.at("minimised").is_null()) << refused.dump();
  EXPECT_NE(refused.at("not_minimised").get<std::string>().find("does not fail when replayed"),
            std::string::npos)
      << refused.dump();
  EXPECT_FALSE(fs::exists(out / "findings" / "001-no_rammer_collision.min.avu"));
  EXPECT_TRUE(fs::exists(out / "findings" / "002-keeps_clear_of_far1.min.avu"));
}

TEST_F(SearchTminTest, AStopEndsTheMinimisationWithoutWritingAndLeavesTheRest) {
  const fs::path out = dir_ / "search";
  ASSERT_EQ(search(out.string(), {}).exit_code, 1);
  std::vector<TminJob> jobs;
  for (const auto& [file, entry] : findings(out)) jobs.push_back({file, ""});
  ASSERT_EQ(jobs.size(), 2u);
  // A stop asked for after a few replays of the first finding, one job at a time.
  std::atomic<int> asked{0};
  const std::vector<TminJobResult> stopped =
      minimise_findings(jobs, 1, [&] { return ++asked > 5; });
  ASSERT_EQ(stopped.size(), 2u);
  for (const TminJobResult& result : stopped) {
    EXPECT_TRUE(result.interrupted);
    EXPECT_TRUE(result.minimised_file.empty());
    EXPECT_NE(result.reason.find("interrupted"), std::string::npos) << result.reason;
  }
  EXPECT_TRUE(minimised_files(out).empty());
  // Without a stop, both are written; a second call finds them in place.
  const std::vector<TminJobResult> done = minimise_findings(jobs, 2, {});
  for (const TminJobResult& result : done) EXPECT_FALSE(result.minimised_file.empty());
  EXPECT_EQ(minimised_files(out).size(), 2u);
  for (const TminJobResult& result : minimise_findings(jobs, 2, {})) EXPECT_TRUE(result.reused);
}

}  // namespace
}  // namespace scenfuzz
