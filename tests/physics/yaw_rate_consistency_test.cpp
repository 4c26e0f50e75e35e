// Every actor's recorded yaw rate is its heading's derivative, as the trace convention has it
// (physics/actors/kinematics.cpp, and the trace audit's yaw_rate_inconsistent check): sample i's
// yaw rate is the wrapped heading change from sample i - 1 to i over the time between them.
// Checked here from the trace itself, so that physics tests need no oracle, over every AVUnit
// and WMG corpus seed at the middle of its space: scripted NPCs on paths, wandering pedestrians,
// manoeuvre-driven actors and the ego.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/map_point.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

constexpr double kTolerance = 1e-6;  // rad/s, the audit's yaw_rate_tolerance

std::vector<fs::path> corpus_files(const std::string& folder, const std::string& extension) {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / folder))
    if (entry.path().extension() == extension) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

ScenarioTemplate parse_seed(const SourceFile& file) {
  Diagnostics diagnostics;
  ScenarioTemplate scenario;
  if (file.path().ends_with(".sdl")) {
    wmg::ParseResult parsed = wmg::parse(file);
    diagnostics = std::move(parsed.diagnostics);
    scenario = std::move(parsed.scenario);
  } else {
    avunit::ParseResult parsed = avunit::parse(file);
    diagnostics = std::move(parsed.diagnostics);
    scenario = std::move(parsed.scenario);
  }
  EXPECT_FALSE(diagnostics.has_errors()) << format_diagnostics(file, diagnostics);
  return scenario;
}

// Each actor's samples whose yaw rate is off the heading's derivative: how many, and the first.
std::string inconsistencies(const Trace& trace) {
  std::ostringstream out;
  for (const TraceActor& actor : trace.actors) {
    std::size_t failures = 0;
    for (std::size_t i = 1; i < trace.sample_count(); ++i) {
      const double dt = trace.time[i] - trace.time[i - 1];
      const double derivative = angle_difference(actor.heading[i], actor.heading[i - 1]) / dt;
      const double gap = std::abs(actor.yaw_rate[i] - derivative);
      if (!(gap <= kTolerance) && failures++ == 0)
        out << actor.name << " at t = " << trace.time[i] << ": yaw rate " << actor.yaw_rate[i]
            << ", heading's derivative " << derivative;
    }
    if (failures > 0) out << " (" << failures << " samples)\n";
  }
  return out.str();
}

// Simulates one seed at the middle of its space; returns what inconsistencies it records.
std::string simulate_middle(const fs::path& path, const MapSearchPath& search_path) {
  const std::optional<SourceFile> file = read_source_file(path.string());
  EXPECT_TRUE(file);
  if (!file) return {};
  const ScenarioTemplate scenario = parse_seed(*file);
  const ParameterSpace space = parameter_space(scenario);
  const std::vector<double> values =
      decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  const RoadMap map = load_scenario_map(scenario.map, search_path, values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(scenario, values, map, 1, diagnostics);
  EXPECT_TRUE(setup) << format_diagnostics(*file, diagnostics);
  if (!setup) return {};
  const Trace trace = simulate(map, *setup, {});
  EXPECT_GT(trace.sample_count(), 1u);
  EXPECT_GT(trace.actors.size(), 1u) << "a seed with no actor but the ego checks little";
  return inconsistencies(trace);
}

TEST(YawRateConsistencyTest, EveryCorpusSeedRecordsTheHeadingsDerivativeAsItsYawRate) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // four AVUnit seeds drive on san_francisco
  const MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  std::vector<fs::path> files = corpus_files("avunit", ".avu");
  ASSERT_GE(files.size(), 17u);
  const std::vector<fs::path> wmg = corpus_files("wmg", ".sdl");
  ASSERT_GE(wmg.size(), 10u);
  files.insert(files.end(), wmg.begin(), wmg.end());
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    const std::string found = simulate_middle(path, search_path);
    EXPECT_TRUE(found.empty()) << found;
  }
}

}  // namespace
}  // namespace scenfuzz
