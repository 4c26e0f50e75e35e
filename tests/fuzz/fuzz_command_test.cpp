// End-to-end tests of the main job, `scenfuzz [--budget N] FILE`, run as a user runs it: a cut-in
// yields findings within the budget and a scenario safe by construction none; findings replay to
// their robustness; the same seed gives the same evaluations and findings for any -j; exit codes
// and errors for bad input; SIGINT stops cleanly with everything written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "command_runner.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;
using test::Outcome;
using test::read_csv;
using test::slurp;

using test::source_file;

const std::string kCutIn = source_file("corpora/avunit/cut_in_straight.avu");
const std::string kSafe = source_file("tests/fuzz/data/safe_by_construction.avu");

// evaluations.csv without its wall_seconds column, which is the one thing allowed to differ.
std::string without_wall_times(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, header, result;
  std::getline(in, header);
  std::vector<std::string> names;
  std::stringstream fields(header);
  for (std::string name; std::getline(fields, name, ',');) names.push_back(name);
  const auto wall = static_cast<std::size_t>(std::find(names.begin(), names.end(), "wall_seconds") -
                                             names.begin());
  for (result = header + "\n"; std::getline(in, line);) {
    // Split on commas outside quotes: a collision_reason may hold a quoted comma.
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (const char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted)
        cells.emplace_back();
      else
        cells.back() += c;
    }
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (i != wall) result += cells[i] + ",";
    result += "\n";
  }
  return result;
}

class FuzzCommandTest : public test::CommandTest {
 protected:
  Outcome fuzz(const std::string& scenario, std::vector<std::string> extra) {
    // cut_in_straight's collisions are mostly the cutter's fault, other-fault without
    // --all-collisions; these tests are of the search's outputs, so they count them.
    std::vector<std::string> args = {"--out", (dir_ / "out").string(), "--all-collisions"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(scenario);
    return scenfuzz(args);
  }
  nlohmann::json summary() const {
    return nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  }
};

TEST_F(FuzzCommandTest, ACutInYieldsFindingsWithinTheBudget) {
  const Outcome run = fuzz(kCutIn, {"--budget", "60", "--seed", "3"});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json summary = this->summary();
  EXPECT_EQ(summary["complete"], true);
  EXPECT_EQ(summary["stop"], "budget");
  EXPECT_EQ(summary["judged"].get<int>() + summary["failed"].get<int>(), 60);
  ASSERT_GE(summary["findings"].size(), 1u);
  for (const auto& finding : summary["findings"]) {
    EXPECT_EQ(finding["spec"], "no_collision");
    EXPECT_LT(finding["robustness"].get<double>(), 0.0);
    const fs::path scenario = finding["file"].get<std::string>();
    EXPECT_TRUE(fs::exists(scenario)) << scenario;
    fs::path trace = scenario, picture = scenario;
    EXPECT_TRUE(fs::exists(trace.replace_extension(".csv")));
    EXPECT_TRUE(fs::exists(picture.replace_extension(".svg")));
  }
  // Every evaluation is a row of evaluations.csv (and the header names the parameters).
  const std::string csv = slurp(dir_ / "out" / "evaluations.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + summary["evaluations"].get<int>());
  EXPECT_NE(csv.find("ego.init.speed"), std::string::npos);
  EXPECT_NE(run.out.find("finding"), std::string::npos) << run.out;
}

// A finding's header gives what the mode's key leaves out, and names a dimension whose range sits
// in an expression (`cut_speed = ego_speed + range(-5, 2)`) by the speed it sets, not by the draw.
TEST_F(FuzzCommandTest, AFindingsHeaderDescribesItsModeAndShowsTheValuesTheFileSets) {
  ASSERT_EQ(fuzz(kCutIn, {"--budget", "60", "--seed", "3"}).exit_code, 1);
  const nlohmann::json summary = this->summary();
  ASSERT_GE(summary["findings"].size(), 1u);
  const std::string text = slurp(summary["findings"][0]["file"].get<std::string>());
  const std::string mode = summary["findings"][0]["mode"].get<std::string>();
  EXPECT_NE(text.find("failure mode: " + mode + "\n// seen as: car cutter"), std::string::npos)
      << text.substr(0, 600);
  const std::size_t speed = text.find("//   cutter.init.speed = ");
  ASSERT_NE(speed, std::string::npos) << text.substr(0, 1200);
  const std::string line = text.substr(speed, text.find('\n', speed) - speed);
  EXPECT_NE(line.find(" m/s, where range(-5, 2) drew "), std::string::npos) << line;
  EXPECT_NE(line.find("(" + kCutIn + ":14:25)"), std::string::npos) << line;
  // The speed is the ego's plus the draw, the ego's speed a dimension of its own.
  const std::size_t ego = text.find("//   ego.init.speed = ");
  ASSERT_NE(ego, std::string::npos);
  const double ego_speed = std::stod(text.substr(ego + 22));
  const double cutter_speed = std::stod(line.substr(25));
  const double drawn = std::stod(line.substr(line.find(" drew ") + 6));
  EXPECT_NEAR(cutter_speed, ego_speed + drawn, 1e-9) << line;
  EXPECT_GE(drawn, -5.0);
  EXPECT_LE(drawn, 2.0);
}

TEST_F(FuzzCommandTest, OneFindingPerFailureModeItsMostViolatingEvaluation) {
  // Seed 1: a search in which some mode's first evaluation is later outdone (asserted below).
  ASSERT_EQ(fuzz(kCutIn, {"--budget", "200", "--seed", "1"}).exit_code, 1);
  const nlohmann::json summary = this->summary();
  // The journal's evaluations by failure mode: how many, and the most violating (the earliest
  // among equals).
  const auto rows = read_csv(slurp(dir_ / "out" / "evaluations.csv"));
  const auto& header = rows.front();
  auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t mode_column = column("signature"),
                    robustness = column("robustness.no_collision");
  ASSERT_LT(mode_column, header.size());
  std::map<std::string, std::pair<std::size_t, double>> best;  // mode -> evaluation, robustness
  std::map<std::string, std::size_t> counts, first;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][mode_column].empty()) continue;
    first.try_emplace(rows[r][mode_column], std::stoul(rows[r][0]));
    const double value = std::stod(rows[r][robustness]);
    ++counts[rows[r][mode_column]];
    auto [it, inserted] = best.try_emplace(rows[r][mode_column], std::stoul(rows[r][0]), value);
    if (!inserted && value < it->second.second) it->second = {std::stoul(rows[r][0]), value};
  }
  ASSERT_GE(counts.size(), 2u);
  ASSERT_EQ(summary["findings"].size(), counts.size());
  EXPECT_EQ(summary["failure_modes"]["count"].get<std::size_t>(), counts.size());
  std::size_t evaluations = 0;
  for (const auto& finding : summary["findings"]) {
    const std::string mode = finding["mode"].get<std::string>();
    ASSERT_TRUE(best.count(mode)) << mode;
    EXPECT_EQ(finding["count"].get<std::size_t>(), counts[mode]) << mode;
    EXPECT_EQ(finding["evaluation"].get<std::size_t>(), best[mode].first) << mode;
    EXPECT_EQ(finding["robustness"].get<double>(), best[mode].second) << mode;
    evaluations += counts[mode];
    // The file on disk is the representative's, and names its mode.
    const std::string text = slurp(finding["file"].get<std::string>());
    EXPECT_NE(text.find(", evaluation " + std::to_string(best[mode].first) + " ("),
              std::string::npos)
        << text.substr(0, 400);
    EXPECT_NE(text.find("failure mode: " + mode + "\n"), std::string::npos) << text.substr(0, 400);
  }
  EXPECT_EQ(summary["failure_modes"]["evaluations"].get<std::size_t>(), evaluations);
  // Some mode's first evaluation was later outdone: the replacement was exercised.
  EXPECT_TRUE(std::any_of(best.begin(), best.end(), [&](const auto& mode) {
    return mode.second.first != first[mode.first];
  }));
}

TEST_F(FuzzCommandTest, AScenarioSafeByConstructionHasNone) {
  const Outcome run = fuzz(kSafe, {"--budget", "40"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json summary = this->summary();
  EXPECT_EQ(summary["findings"].size(), 0u);
  EXPECT_GT(summary["best"]["no_collision"].get<double>(), 0.0);
  EXPECT_TRUE(fs::is_empty(dir_ / "out" / "findings"));
}

TEST_F(FuzzCommandTest, AFindingReplaysToItsRobustness) {
  ASSERT_EQ(fuzz(kCutIn, {"--budget", "40", "--seed", "5"}).exit_code, 1);
  const nlohmann::json finding = summary()["findings"][0];
  const std::string scenario = finding["file"].get<std::string>();
  // The replay command in the finding's header comment, run as written.
  const std::string text = slurp(scenario);
  std::smatch replay;
  ASSERT_TRUE(
      std::regex_search(text, replay, std::regex("// replay: scenfuzz run (\\S+) --seed (\\d+)")));
  EXPECT_EQ(replay[1].str(), scenario);
  const Outcome run = scenfuzz(
      {"run", scenario, "--seed", replay[2].str(), "--json", "--out", (dir_ / "replay").string(),
       "--all-collisions"});
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json replayed = nlohmann::json::parse(run.out);
  EXPECT_NEAR(replayed["specs"][0]["robustness"].get<double>(), finding["robustness"].get<double>(),
              1e-9);
  EXPECT_EQ(finding["seed"].get<std::uint64_t>(), std::stoull(replay[2].str()));
}

TEST_F(FuzzCommandTest, TheSameSeedGivesTheSameFindingsForAnyThreadCount) {
  for (const char* algorithm : {"ga", "nlopt:GN_ISRES"}) {
    SCOPED_TRACE(algorithm);
    std::vector<std::string> results;
    for (const char* jobs : {"1", "2", "4"}) {
      const fs::path out = dir_ / (std::string(algorithm).substr(0, 2) + jobs);
      const Outcome run = scenfuzz({"--budget", "40", "--seed", "11", "--algo", algorithm, "-j",
                                    jobs, "--out", out.string(), kCutIn});
      ASSERT_NE(run.exit_code, 2) << run.err;
      nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
      nlohmann::json findings = summary["findings"];
      for (auto& finding : findings) finding.erase("file");  // the folder differs
      results.push_back(without_wall_times(slurp(out / "evaluations.csv")) + findings.dump());
    }
    EXPECT_EQ(results[0], results[1]);
    EXPECT_EQ(results[0], results[2]);
  }
}

TEST_F(FuzzCommandTest, OverlappingStartsAreRejectedWithoutSpendingTheBudget) {
  // Both cars start somewhere on the same 40 m of east_0: about a fifth of the points put them
  // on top of each other.
  const std::string scenario =
      write("overlap.avu",
            "ego = AV((\"east_0\"->range(20, 60), , 10), (\"east_0\"->300));\n"
            "npc = Vehicle((\"east_0\"->range(20, 60), , 10));\n"
            "s = CreateScenario{load(\"straight\"); ego; {npc}; {}; {};};\n");
  const Outcome run = fuzz(scenario, {"--budget", "30", "--algo", "random", "--json"});
  ASSERT_NE(run.exit_code, 2) << run.err;
  const nlohmann::json summary = this->summary();
  EXPECT_EQ(summary["judged"].get<int>() + summary["failed"].get<int>(), 30);
  EXPECT_GT(summary["infeasible"].get<int>(), 0);
  EXPECT_EQ(summary["evaluations"].get<int>(), 30 + summary["infeasible"].get<int>());
  const std::string csv = slurp(dir_ / "out" / "evaluations.csv");
  EXPECT_NE(csv.find("infeasible"), std::string::npos);
  EXPECT_NE(csv.find("overlaps"), std::string::npos);
  // --json: one JSON object per line, ending with the summary.
  std::istringstream lines(run.out);
  std::string line, last;
  while (std::getline(lines, line)) {
    ASSERT_NO_THROW(last = nlohmann::json::parse(line)["event"].get<std::string>()) << line;
  }
  EXPECT_EQ(last, "summary");
}

TEST_F(FuzzCommandTest, BadInputIsAClearErrorWithExitTwo) {
  const std::string inverted = write("inverted.avu",
                                     "ego = AV((\"east_0\"->range(60, 20)), (\"east_0\"->400));\n"
                                     "s = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\n");
  Outcome run = fuzz(inverted, {"--budget", "10"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("inverted.avu:1:"), std::string::npos) << run.err;

  run = fuzz(kCutIn, {"--spec", "no_such_spec"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("no spec named 'no_such_spec'; its specs are: no_collision"),
            std::string::npos)
      << run.err;

  run = fuzz(kCutIn, {"--budget", "0"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--budget: expected a whole number from 1 to"), std::string::npos)
      << run.err;

  // The scenario's own duration at a tiny --dt: too many steps, known only once it is read.
  run = fuzz(kCutIn, {"--dt", "0.00001"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("the scenario's duration of"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--dt"), std::string::npos) << run.err;

  run = fuzz(kCutIn, {"--algo", "simulated_annealing"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown search algorithm 'simulated_annealing'"), std::string::npos)
      << run.err;

  // An output folder that cannot be created: a file stands where it should go.
  const std::string blocker = write("blocker", "");
  run = scenfuzz({"--budget", "5", "--out", blocker + "/out", kCutIn});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cannot create"), std::string::npos) << run.err;

  run = scenfuzz({"--budget", "5", (dir_ / "missing.avu").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("missing.avu"), std::string::npos) << run.err;
}

TEST_F(FuzzCommandTest, AnEgoFarFromEveryLaneIsWarnedOnceBeforeTheSearch) {
  const std::string far = write("far.avu",
                                "ego = AV(((-4210000, -5), , range(4, 6)), (\"east_0\"->300));\n"
                                "s = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\n");
  const Outcome run = fuzz(far, {"--budget", "4", "--duration", "1", "--quiet"});
  EXPECT_NE(run.exit_code, 3) << run.err;
  EXPECT_NE(run.err.find("far.avu:1:11: warning"), std::string::npos) << run.err;
  const std::string warning = "km from the nearest lane";
  const std::size_t first = run.err.find(warning);
  ASSERT_NE(first, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(warning, first + 1), std::string::npos) << "warned more than once";
}

// The reference driver gives way at a stop sign to traffic with priority (physics/ego/
// priority_traffic.hpp): it used to go after its one-second stop whatever came, and a search of
// the give-way T-junction found it pulling out in front of the car from its left in 22 of 150
// simulations (83 of 300), every one its fault.
TEST_F(FuzzCommandTest, TheReferenceDriverGivesWayAtAStopSign) {
  const Outcome run =
      fuzz(source_file("corpora/wmg/give_way_t_junction.sdl"), {"--budget", "150", "--seed", "3"});
  ASSERT_NE(run.exit_code, 2) << run.err;
  const nlohmann::json collisions = summary()["ego_collisions"];
  EXPECT_EQ(collisions["ego"], 0) << collisions.dump();
  EXPECT_EQ(collisions["shared"], 0) << collisions.dump();
}

// An NPC sent through a waypoint off the road leaves the lanes in every simulation: every
// simulation's audit says so, and the search counts it where a user sees it. (The roundabout seed
// used to serve, while its waypoint NPCs cut across the island.)
TEST_F(FuzzCommandTest, TheTraceAuditIsCountedPerSearch) {
  const Outcome run =
      fuzz(source_file("tests/fuzz/data/off_road_waypoint.avu"), {"--budget", "20", "--seed", "2"});
  ASSERT_NE(run.exit_code, 2) << run.err;
  const nlohmann::json audit = summary()["audit"];
  EXPECT_EQ(audit["simulations_with_issues"], 20) << audit.dump();
  EXPECT_GE(audit["issues"]["off_road"].get<int>(), 20) << audit.dump();
  EXPECT_NE(run.out.find("audit: 20 of 20 simulations"), std::string::npos) << run.out;
  EXPECT_NE(slurp(dir_ / "out" / "evaluations.csv").find("off_road="), std::string::npos);

  // A scenario whose actors all behave has a clean audit and no audit line.
  const Outcome safe = scenfuzz({"--budget", "8", "--out", (dir_ / "safe").string(), kSafe});
  const nlohmann::json clean =
      nlohmann::json::parse(slurp(dir_ / "safe" / "summary.json"))["audit"];
  EXPECT_EQ(clean["simulations_with_issues"], 0) << clean.dump();
  EXPECT_EQ(safe.out.find("audit:"), std::string::npos) << safe.out;
}

TEST_F(FuzzCommandTest, InterruptStopsCleanlyWithEverythingWritten) {
  const fs::path out = dir_ / "out";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Quiet output into files; a budget far beyond what the test waits for.
    const std::string log = (dir_ / "child.txt").string();
    std::freopen(log.c_str(), "w", stdout);
    std::freopen(log.c_str(), "a", stderr);
    ::execl(SCENFUZZ_EXECUTABLE, SCENFUZZ_EXECUTABLE, "--budget", "10000000", "--algo", "random",
            "--out", out.c_str(), kCutIn.c_str(), static_cast<char*>(nullptr));
    std::_Exit(127);
  }
  // Wait until the search is under way (its evaluations.csv has rows), then interrupt it.
  for (int i = 0; i < 200; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (fs::exists(out / "evaluations.csv") && fs::file_size(out / "evaluations.csv") > 0) break;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(::kill(child, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of stopping";
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["complete"], true);
  EXPECT_EQ(summary["stop"], "interrupted");
  EXPECT_EQ(WEXITSTATUS(status), summary["findings"].empty() ? 0 : 1);
  for (const auto& finding : summary["findings"])
    EXPECT_TRUE(fs::exists(finding["file"].get<std::string>()));
  const std::string csv = slurp(out / "evaluations.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + summary["evaluations"].get<int>());
}

}  // namespace
}  // namespace scenfuzz
