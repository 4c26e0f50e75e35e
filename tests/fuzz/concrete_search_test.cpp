// Searching a concrete scenario (no ranges) by mutation, end to end: the search derives the space,
// finds a failure, writes the user's file with the mutated numbers, and that file replays to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/fuzz/command_runner.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

// A cut-in on the built-in straight road written with plain numbers, as LawBreaker's files are.
constexpr const char* kConcreteCutIn = R"(// concrete cut-in
ego_init_state = ("east_0"->50, , 20);
ego_vehicle = AV(ego_init_state, ("east_0"->450), ("Lincoln2017MKZ", white));
cut_start = ("east_1"->70, , 17);
cut_merge = ("east_0"->80, , 17);
cut_slow = ("east_0"->250, , 12);
cutter = Vehicle(cut_start, Waypoint(cut_merge, cut_slow), ("east_0"->480), ("Sedan", red));
scenario = CreateScenario{load("straight"); ego_vehicle; {cutter}; {}; {}; };
Trace trace = EXE(scenario);
no_collision = G (dis(trace[ego], trace[truth][cutter]) >= 0.5);
trace |= no_collision;
)";

using scenfuzz::test::Outcome;
using scenfuzz::test::slurp;
using ConcreteSearchTest = scenfuzz::test::CommandTest;

// The line of `text` that starts with `prefix`, or "".
std::string line_starting(const std::string& text, const std::string& prefix) {
  const std::size_t at = text.find("\n" + prefix);
  if (at == std::string::npos) return "";
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST_F(ConcreteSearchTest, AConcreteFileIsSearchedByMutationAndItsFindingsReplay) {
  const std::string path = write("cut_in.avu", kConcreteCutIn);
  const std::string out = (dir_ / "out").string();
  const Outcome search = scenfuzz(
      {"--budget", "40", "--seed", "2", "-j", "2", "--out", out, path, "--all-collisions"});
  ASSERT_EQ(search.exit_code, 1) << search.out << search.err;
  EXPECT_NE(search.err.find("has no parameter ranges: searching 8 of its values"),
            std::string::npos)
      << search.err;
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  ASSERT_FALSE(summary.at("findings").empty());
  const std::string finding = slurp(dir_ / "out" / "findings" / "001-no_collision.avu");
  ASSERT_FALSE(finding.empty());
  // The user's file, comment and layout kept, with mutated numbers in place of the written ones.
  EXPECT_NE(finding.find("// concrete cut-in\nego_init_state = (\"east_0\"->"), std::string::npos)
      << finding;
  const std::string start = line_starting(finding, "cut_start = ");
  EXPECT_NE(start, "") << finding;
  EXPECT_NE(start, "cut_start = (\"east_1\"->70, , 17);") << "mutated";
  EXPECT_NE(finding.find("//   cutter.init.speed = "), std::string::npos) << finding;
  // The first evaluation is the file as written.
  const auto rows = scenfuzz::test::read_csv(slurp(dir_ / "out" / "evaluations.csv"));
  ASSERT_GE(rows.size(), 2u);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) -
                                    rows[0].begin());
  };
  EXPECT_EQ(rows[1].at(column("evaluation")), "0");
  EXPECT_EQ(rows[1].at(column("ego.init.position.s")), "50");
  EXPECT_EQ(rows[1].at(column("cutter.init.speed")), "17");
  EXPECT_EQ(rows[1].at(column("cutter.waypoint[1].speed")), "12");

  // Its replay line reproduces the collision.
  const std::string replay = line_starting(finding, "// replay: scenfuzz run ");
  ASSERT_NE(replay, "") << finding;
  const std::string seed = replay.substr(replay.find("--seed ") + 7);
  const Outcome run = scenfuzz(
      {"run", "--seed", seed.substr(0, seed.find(' ')), "--out", (dir_ / "replay").string(),
       (dir_ / "out" / "findings" / "001-no_collision.avu").string(), "--all-collisions"});
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("collision at "), std::string::npos) << run.out;
}

TEST_F(ConcreteSearchTest, MutationOptionsAreCheckedAndPartOfTheSearch) {
  const std::string path = write("cut_in.avu", kConcreteCutIn);
  const Outcome bad = scenfuzz({"--budget", "5", "--mutate", "speed=-2", path});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--mutate speed=-2"), std::string::npos) << bad.err;
  std::vector<std::string> nothing = {"--budget", "5", "--out", (dir_ / "none").string()};
  for (const char* kind :
       {"position", "waypoint", "lateral", "heading", "speed", "weather", "time"})
    nothing.insert(nothing.end(), {"--mutate", std::string(kind) + "=0"});
  nothing.push_back(path);
  const Outcome none = scenfuzz(nothing);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("nothing to search"), std::string::npos) << none.err;
  // A resumed search must mutate as the first did.
  const std::string out = (dir_ / "out").string();
  ASSERT_EQ(scenfuzz({"--budget", "4", "--out", out, path}).exit_code / 2, 0);
  const Outcome resumed =
      scenfuzz({"--budget", "4", "--resume", "--mutate", "speed=1", "--out", out, path});
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.err.find("mutate"), std::string::npos) << resumed.err;
}

// Every concrete AVUnit and scenest file in ../shared/examples is searched by mutation: each either
// runs, or stops with a diagnostic saying why it cannot (no spec the oracle can judge, a map we
// do not have, no scenario); at least one gives findings.
TEST_F(ConcreteSearchTest, TheSharedConcreteExamplesAreMutated) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const std::filesystem::path examples = scenfuzz::test::shared_dir() / "examples";
  const std::string maps = (scenfuzz::test::shared_dir() / "maps" / "apollo").string();
  std::size_t searched = 0, with_findings = 0, concrete = 0;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(examples))
    if (entry.path().extension() == ".avu" || entry.path().extension() == ".scenest")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const std::filesystem::path& file : files) {
    const Outcome space = scenfuzz({"space", "--json", file.string()});
    if (space.exit_code != 0 || !nlohmann::json::parse(space.out).value("derived", false))
      continue;  // has ranges, or no scenario: not a concrete seed
    ++concrete;
    const std::string out = (dir_ / ("out-" + file.stem().string())).string();
    const Outcome search =
        scenfuzz({"--budget", "30", "-j", "2", "--map-path", maps, "--out", out, file.string()});
    SCOPED_TRACE(file.string() + "\n" + search.err);
    ASSERT_TRUE(search.exit_code == 0 || search.exit_code == 1 || search.exit_code == 2);
    if (search.exit_code == 2) {
      // The reasons the examples cannot all run today, each a clear error.
      const bool known =
          search.err.find("can be judged on simulated traces") != std::string::npos ||
          search.err.find("map 'Town03' not found") != std::string::npos;
      EXPECT_TRUE(known);
      continue;
    }
    EXPECT_NE(search.err.find("has no parameter ranges: searching"), std::string::npos);
    ++searched;
    if (search.exit_code == 1) ++with_findings;
  }
  EXPECT_GE(concrete, 5u) << "the shared examples hold concrete AVUnit and scenest files";
  EXPECT_GE(searched, 2u);
  EXPECT_GE(with_findings, 1u);
}

}  // namespace
}  // namespace scenfuzz
