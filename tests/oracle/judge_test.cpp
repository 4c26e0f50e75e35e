// Judging whole runs: every spec of every corpus seed evaluated on its simulated trace, a violated
// spec reported with its atom and time, and the collision oracle for a scenario without specs.
#include "oracle/judge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "oracle/robustness.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

fs::path repository() { return SCENFUZZ_SOURCE_DIR; }

struct JudgedRun {
  std::optional<Trace> trace;
  std::vector<SpecVerdict> verdicts;
  std::string errors;
};

// Parses, simulates at `unit_point` (the middle when empty) and judges.
JudgedRun judge_file(const SourceFile& file, std::vector<double> unit_point = {},
                     const MapSearchPath& search_path = map_search_path({}),
                     const SimulationOptions& options = {},
                     const JudgeOptions& judge_options = {}) {
  JudgedRun run;
  const avunit::ParseResult parsed = avunit::parse(file);
  run.errors = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok()) return run;
  const ParameterSpace space = parameter_space(parsed.scenario);
  if (unit_point.empty()) unit_point.assign(space.dimensions.size(), 0.5);
  const std::vector<double> values = decode(space, unit_point);
  const RoadMap map = load_scenario_map(parsed.scenario.map, search_path, values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, 1, diagnostics);
  run.errors += format_diagnostics(file, diagnostics);
  if (!setup) return run;
  run.trace = simulate(map, *setup, options);
  try {
    run.verdicts = judge_trace(parsed.scenario, values, *run.trace, map, file, judge_options);
  } catch (const OracleError& error) {
    Diagnostics oracle;
    oracle.error(error.location(), error.what());
    run.errors += format_diagnostics(file, oracle);
  }
  return run;
}

JudgedRun judge_text(const std::string& text) { return judge_file(SourceFile("inline.avu", text)); }

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(repository() / "corpora" / "avunit"))
    if (entry.path().extension() == ".avu") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(JudgeTest, EverySpecOfEveryCorpusSeedIsJudgedOnItsTrace) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // four seeds drive on san_francisco
  const MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  const std::vector<fs::path> files = corpus_files();
  ASSERT_GE(files.size(), 17u);
  std::mt19937_64 random(5);
  std::size_t judged = 0;
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    const std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file);
    const avunit::ParseResult parsed = avunit::parse(*file);
    ASSERT_TRUE(parsed.ok());
    const std::size_t dimensions = parameter_space(parsed.scenario).dimensions.size();
    // The middle of the space and one random point.
    std::vector<double> random_point(dimensions);
    for (double& u : random_point) u = std::uniform_real_distribution<double>(0, 1)(random);
    for (const std::vector<double>& point : {std::vector<double>{}, random_point}) {
      const JudgedRun run = judge_file(*file, point, search_path);
      ASSERT_TRUE(run.trace) << run.errors;
      // Warnings are allowed: a point of the space may script speeds an NPC cannot drive.
      ASSERT_EQ(run.errors.find(": error:"), std::string::npos) << run.errors;
      ASSERT_EQ(run.verdicts.size(), parsed.scenario.specs.size());
      for (std::size_t i = 0; i < run.verdicts.size(); ++i) {
        const SpecVerdict& verdict = run.verdicts[i];
        EXPECT_EQ(verdict.name, parsed.scenario.specs[i].name);
        EXPECT_FALSE(std::isnan(verdict.robustness)) << verdict.name;
        // What the search minimises violates exactly where the spec does.
        EXPECT_EQ(verdict.guide < 0, verdict.robustness < 0) << verdict.name;
        if (std::isfinite(verdict.robustness)) {
          EXPECT_TRUE(verdict.atom.known()) << verdict.name;
          EXPECT_FALSE(verdict.atom_text.empty()) << verdict.name;
        }
        EXPECT_GE(verdict.time, 0.0);
        EXPECT_LE(verdict.time, run.trace->time.back());
        ++judged;
      }
    }
  }
  EXPECT_GE(judged, 2 * 17u);
}

constexpr const char* kRearEnd = R"(
ego = AV((("east_0" -> 20.0), , 20.0), (("east_0" -> 400.0), , ));
npc = Vehicle(("east_0" -> 60.0, , 0.0));
scenario = CreateScenario{load("straight?two_way=0&lanes=1"); ego; {npc}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
npc_truth = trace[truth][npc];
gap = G (dis(ego_state, npc_truth) >= 20.0);
keeps_moving = G (ego_state.speed > 1.0);
trace |= gap;
trace |= keeps_moving;
)";

TEST(JudgeTest, AViolatedSpecNamesItsAtomAndTime) {
  const JudgedRun run = judge_text(kRearEnd);
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_EQ(run.errors, "");
  ASSERT_EQ(run.verdicts.size(), 2u);
  // The ego brakes behind a stopped car it cannot pass (one lane between kerbs): it gets closer
  // than 20 m, and it stops.
  const SpecVerdict& gap = run.verdicts[0];
  EXPECT_EQ(gap.name, "gap");
  EXPECT_TRUE(gap.violated());
  EXPECT_EQ(gap.atom_text, "dis(ego_state, npc_truth) >= 20.0");
  EXPECT_GT(gap.time, 0.0);
  const SpecVerdict& moving = run.verdicts[1];
  EXPECT_EQ(moving.name, "keeps_moving");
  EXPECT_TRUE(moving.violated());
  EXPECT_DOUBLE_EQ(moving.robustness, -1.0);  // speed 0 at the stop
  EXPECT_EQ(moving.atom_text, "ego_state.speed > 1.0");
}

// A violated distance between two road users is a near miss in the failure mode (failure_mode.hpp);
// another atom is not, even when it reads the same actors.
TEST(JudgeTest, AVerdictSaysWhetherItsAtomIsADistanceBetweenRoadUsers) {
  const JudgedRun run = judge_text(kRearEnd);
  ASSERT_EQ(run.verdicts.size(), 2u) << run.errors;
  EXPECT_TRUE(run.verdicts[0].actor_distance);   // dis(ego_state, npc_truth) >= 20.0
  EXPECT_FALSE(run.verdicts[1].actor_distance);  // ego_state.speed > 1.0
}

TEST(JudgeTest, WithoutSpecsTheCollisionOracleJudges) {
  // A stopped car 5 m ahead of an ego at 20 m/s: it cannot stop in time.
  const JudgedRun crash = judge_text(R"(
ego = AV((("east_0" -> 20.0), , 20.0), (("east_0" -> 400.0), , ));
npc = Vehicle(("east_0" -> 30.0, , 0.0));
scenario = CreateScenario{load("straight"); ego; {npc}; {}; {};};
)");
  ASSERT_TRUE(crash.trace) << crash.errors;
  ASSERT_EQ(crash.verdicts.size(), 1u);
  EXPECT_EQ(crash.verdicts[0].name, kNoCollisionSpec);
  EXPECT_FALSE(crash.trace->collisions.empty());
  // Placed 0.3 s from impact at t = 0, braking at its limit: not the ego's fault (RSS), so the
  // oracle leaves the collision out (--all-collisions counts it: responsibility_test.cpp).
  EXPECT_GE(crash.verdicts[0].robustness, 0.0);
  EXPECT_EQ(crash.verdicts[0].atom_text,
            "the ego and npc (not counted: a collision not the ego's fault with npc)");

  const JudgedRun safe = judge_text(R"(
ego = AV((("east_0" -> 20.0), , 20.0), (("east_0" -> 400.0), , ));
npc = Vehicle(("east_0" -> 150.0, , 0.0));
scenario = CreateScenario{load("straight"); ego; {npc}; {}; {};};
)");
  ASSERT_TRUE(safe.trace) << safe.errors;
  ASSERT_EQ(safe.verdicts.size(), 1u);
  EXPECT_TRUE(safe.trace->collisions.empty());
  EXPECT_GT(safe.verdicts[0].robustness, 0.0);
}

// An ego driving 460 m down an empty road, with a spec to get there and one it breaks at once.
constexpr const char* kLongDrive = R"(
ego_target = "east_0"->480;
ego = AV((("east_0"->20), , 10), (ego_target, , ));
scenario = CreateScenario{load("straight"); ego; {}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
reach = F (dis(ego_state, ego_target) <= 2.0);
slow = G (ego_state.speed < 5.0);
safe_and_there = G (ego_state.speed < 40.0) & F (dis(ego_state, ego_target) <= 2.0);
trace |= reach;
trace |= slow;
trace |= safe_and_there;
)";

TEST(JudgeTest, ARunCutShortWhileTheEgoProgressesIsATimeOutNotAViolation) {
  SimulationOptions ten_seconds;
  ten_seconds.duration = 10;
  const JudgedRun run =
      judge_file(SourceFile("inline.avu", kLongDrive), {}, map_search_path({}), ten_seconds);
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_EQ(run.trace->end, EndReason::duration);
  ASSERT_EQ(run.verdicts.size(), 3u);
  const SpecVerdict& reach = run.verdicts[0];
  EXPECT_EQ(reach.ending, VerdictEnding::time_out);
  EXPECT_FALSE(reach.violated());
  EXPECT_LT(reach.robustness_as_observed, -100);  // hundreds of metres short
  EXPECT_GE(reach.guide, 0.0);
  EXPECT_NE(reach.progress.find("drove"), std::string::npos) << reach.progress;
  EXPECT_EQ(reach.atom_text, "dis(ego_state, ego_target) <= 2.0");
  // A G the trace already broke is decided, time-out or not.
  EXPECT_EQ(run.verdicts[1].ending, VerdictEnding::decided);
  EXPECT_TRUE(run.verdicts[1].violated());
  // A conjunction whose only violated part is the F the end cut off: a time-out whose
  // robustness is the rest's.
  const SpecVerdict& both = run.verdicts[2];
  EXPECT_EQ(both.ending, VerdictEnding::time_out);
  EXPECT_GT(both.robustness, 0.0);
  EXPECT_LT(both.robustness, 40.0);
  EXPECT_GE(both.guide, 0.0);
}

TEST(JudgeTest, AnEgoThatStoppedMakingProgressIsStuckAndViolates) {
  // A stopped car in the only lane (kerbs on both sides): the ego stops behind it for good.
  const JudgedRun run = judge_text(R"(
ego_target = "east_0"->400;
ego = AV((("east_0"->20), , 15), (ego_target, , ));
npc = Vehicle(("east_0"->80, , 0.0));
scenario = CreateScenario{load("straight?two_way=0&lanes=1"); ego; {npc}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
reach = F (dis(ego_state, ego_target) <= 2.0);
trace |= reach;
)");
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_EQ(run.trace->end, EndReason::duration);
  ASSERT_EQ(run.verdicts.size(), 1u);
  EXPECT_EQ(run.verdicts[0].ending, VerdictEnding::stuck);
  EXPECT_TRUE(run.verdicts[0].violated());
  EXPECT_NE(run.verdicts[0].progress.find("no red light"), std::string::npos)
      << run.verdicts[0].progress;
}

TEST(JudgeTest, AConjunctionNamesEveryViolatedConjunctTheEarliestFirst) {
  // A scripted car runs into the back of the ego, which is left short of its target: the
  // collision is named first, then the target the run never reached, whatever the file's order.
  // (Counted with --all-collisions: the collision is not the ego's fault, other-fault otherwise.)
  JudgeOptions all_collisions;
  all_collisions.all_collisions = true;
  const std::string text = R"(
ego_target = "east_0"->400;
ego = AV((("east_0"->60), , 2), (ego_target, , ));
npc = Vehicle(("east_0"->20, , 20.0), uniform(("east_0"->20, , 20.0)), ("east_0"->450));
scenario = CreateScenario{load("straight?two_way=0&lanes=1"); ego; {npc}; {}; {}; {}; {NPCBehaviour(scripted)};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
npc_truth = trace[truth][npc];
reach = F (dis(ego_state, ego_target) <= 2.0);
clear = G (dis(ego_state, npc_truth) > 0.5);
trace |= reach & clear;
)";
  const JudgedRun run =
      judge_file(SourceFile("inline.avu", text), {}, map_search_path({}), {}, all_collisions);
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_EQ(run.trace->end, EndReason::collision);
  EXPECT_EQ(judge_text(text).verdicts.at(0).ending, VerdictEnding::other_fault);
  ASSERT_EQ(run.verdicts.size(), 1u);
  const SpecVerdict& verdict = run.verdicts[0];
  ASSERT_TRUE(verdict.violated());
  ASSERT_EQ(verdict.conjuncts.size(), 2u);
  EXPECT_EQ(verdict.conjuncts[0].atom_text, "dis(ego_state, npc_truth) > 0.5");
  EXPECT_EQ(verdict.conjuncts[1].atom_text, "dis(ego_state, ego_target) <= 2.0");
  EXPECT_EQ(verdict.atom_text, verdict.conjuncts[0].atom_text);
  EXPECT_EQ(verdict.time, verdict.conjuncts[0].time);
  EXPECT_LE(verdict.conjuncts[0].time, verdict.conjuncts[1].time);
}

TEST(JudgeTest, AnImplicationNamesTheFailureModeWholeNotBySide) {
  // `near -> slow` is violated by being near and fast together: which comparison the witness
  // lands on is happenstance, so the mode is named by the implication.
  const JudgedRun run = judge_text(R"(
ego = AV((("east_0"->20), , 15), (("east_0"->400), , ));
npc = Vehicle(("east_0"->80, , 10.0));
scenario = CreateScenario{load("straight?two_way=0&lanes=1"); ego; {npc}; {}; {};};
Trace trace = EXE(scenario);
ego_state = trace[ego];
npc_truth = trace[truth][npc];
calm = G ((dis(ego_state, npc_truth) < 60.0) -> (spd(ego_state, 0) < 1.0));
trace |= calm;
)");
  ASSERT_TRUE(run.trace) << run.errors;
  ASSERT_EQ(run.verdicts.size(), 1u);
  ASSERT_TRUE(run.verdicts[0].violated());
  EXPECT_EQ(run.verdicts[0].mode_text,
            "(dis(ego_state, npc_truth) < 60.0) -> (spd(ego_state, 0) < 1.0)");
  EXPECT_NE(run.verdicts[0].atom_text, run.verdicts[0].mode_text);
}

}  // namespace
}  // namespace scenfuzz
