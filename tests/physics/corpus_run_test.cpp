// Every seed scenario in corpora/avunit, and every complete program among the shared examples
// (written by others for Apollo and LGSVL), simulates at the middle of its search space on its
// map: it places, plans and runs to an end without an error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "../support/shared_dir.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

fs::path repository() {
  return fs::path(SCENFUZZ_TEST_DATA_DIR).parent_path().parent_path().parent_path();
}

std::vector<fs::path> scenario_files(const fs::path& folder) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folder)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    auto extension = entry.path().extension();
    if (extension == ".avu" || extension == ".scenest") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Simulates one file; returns false when its map is not available here.
bool runs(const fs::path& file, const MapSearchPath& search_path) {
  SCOPED_TRACE(file.string());
  auto source = read_source_file(file.string());
  EXPECT_TRUE(source);
  if (!source) return true;
  avunit::ParseResult parsed = avunit::parse(*source);
  if (!parsed.scenario.has_scenario) return true;  // a fragment: nothing to run
  test::SimulatedRun run;
  try {
    run = test::simulate_file(*source, {}, search_path);
  } catch (const MapError& error) {
    return false;
  }
  EXPECT_TRUE(run.trace) << run.errors;
  if (!run.trace) return true;
  EXPECT_GT(run.trace->sample_count(), 1u);
  EXPECT_NE(run.trace->end, EndReason::ego_failure);
  return true;
}

TEST(CorpusRunTest, EverySeedScenarioRunsAtTheMiddleOfItsSpace) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // four seeds drive on san_francisco
  MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  auto files = scenario_files(repository() / "corpora" / "avunit");
  ASSERT_GE(files.size(), 17u);
  for (const fs::path& file : files) EXPECT_TRUE(runs(file, search_path)) << file;
}

// Every seed at random points of its space: whatever the point, a run ends normally and every
// recorded number is finite (or NaN only where the ego did not perceive an actor).
TEST(CorpusRunTest, SeedsRunAtRandomPointsWithFiniteTraces) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  std::mt19937_64 random(2026);
  for (const fs::path& file : scenario_files(repository() / "corpora" / "avunit")) {
    SCOPED_TRACE(file.string());
    auto source = read_source_file(file.string());
    ASSERT_TRUE(source);
    avunit::ParseResult parsed = avunit::parse(*source);
    ASSERT_TRUE(parsed.ok());
    ParameterSpace space = parameter_space(parsed.scenario);
    RoadMap map =
        load_scenario_map(parsed.scenario.map, search_path,
                          decode(space, std::vector<double>(space.dimensions.size(), 0.5)));
    for (int point = 0; point < 3; ++point) {
      std::vector<double> unit(space.dimensions.size());
      for (double& u : unit) u = static_cast<double>(random() >> 11) * 0x1.0p-53;
      std::vector<double> values = decode(space, unit);
      Diagnostics diagnostics;
      auto setup = prepare_simulation(parsed.scenario, values, map, random(), diagnostics);
      ASSERT_TRUE(setup) << format_diagnostics(*source, diagnostics);
      SimulationOptions options;
      options.seed = random();
      Trace trace = simulate(map, *setup, options);
      ASSERT_GT(trace.sample_count(), 0u);
      for (const TraceActor& actor : trace.actors)
        for (const auto* column : {&actor.x, &actor.y, &actor.heading, &actor.speed,
                                   &actor.acceleration, &actor.yaw_rate, &actor.s})
          for (double value : *column) ASSERT_TRUE(std::isfinite(value)) << actor.name;
      ASSERT_FALSE(trace.events.empty()) << "a run ends with an event";
    }
  }
}

TEST(CorpusRunTest, TheSharedExamplesRunOnTheRealApolloMaps) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  std::vector<std::string> unavailable;
  for (const fs::path& file : scenario_files(test::shared_dir() / "examples"))
    if (!runs(file, search_path)) unavailable.push_back(file.filename().string());
  // The one example written for CARLA's Town03, which no Apollo map provides.
  EXPECT_EQ(unavailable.size(), 1u);
}

}  // namespace
}  // namespace scenfuzz
