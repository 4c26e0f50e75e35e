// Points of corpus seeds where a 300-simulation search found implausible actors (issue 17's
// corpus pass): each point is what `scenfuzz run --at random --seed S FILE` simulates, and the
// trace audit must find nothing wrong with it. One test per seed, each naming the flaw it guards:
// the cutter ramming background traffic, the lead car driving into the parked one, the cyclist
// turning on the spot, the drifting waypoint car looping off the road, the two jaywalkers walking
// through each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// As fuzz/run_command.cpp's --at random: 53 bits of mt19937_64(seed) per dimension.
std::vector<double> random_unit_point(std::size_t dimensions, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<double> point(dimensions);
  for (double& u : point) u = static_cast<double>(random() >> 11) * 0x1.0p-53;
  return point;
}

ScenarioTemplate parse_seed(const SourceFile& file) {
  if (file.path().ends_with(".sdl")) {
    wmg::ParseResult parsed = wmg::parse(file);
    EXPECT_FALSE(parsed.diagnostics.has_errors()) << file.path();
    return std::move(parsed.scenario);
  }
  avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_TRUE(parsed.ok()) << file.path();
  return std::move(parsed.scenario);
}

// Every audit issue of the seed at each --at random point (of the kinds asked for; all when none
// is), one line each; empty when clean.
std::string audit_issues(const std::string& seed_file, const std::vector<std::uint64_t>& seeds,
                         const std::vector<AuditKind>& kinds = {}) {
  const fs::path path = fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / seed_file;
  const std::optional<SourceFile> file = read_source_file(path.string());
  EXPECT_TRUE(file) << path;
  if (!file) return "unreadable";
  const ScenarioTemplate scenario = parse_seed(*file);
  const ParameterSpace space = parameter_space(scenario);
  std::ostringstream issues;
  for (std::uint64_t seed : seeds) {
    const std::vector<double> values =
        decode(space, random_unit_point(space.dimensions.size(), seed));
    const RoadMap map = load_scenario_map(scenario.map, map_search_path({}), values);
    Diagnostics diagnostics;
    auto setup = prepare_simulation(scenario, values, map, seed, diagnostics);
    EXPECT_TRUE(setup) << format_diagnostics(*file, diagnostics);
    if (!setup) continue;
    SimulationOptions options;
    options.seed = seed;
    const Trace trace = simulate(map, *setup, options);
    for (const AuditIssue& issue : audit_trace(trace, map).issues) {
      if (!kinds.empty() && std::find(kinds.begin(), kinds.end(), issue.kind) == kinds.end())
        continue;
      issues << "  seed " << seed << ": " << issue.actor_name << " " << audit_kind_name(issue.kind);
      if (!issue.other_name.empty()) issues << " with " << issue.other_name;
      issues << " at " << issue.worst_time << " s\n";
    }
  }
  return issues.str();
}

TEST(CorpusSeedPointsAuditTest, TheMotorwayCutterDoesNotRamTheTrafficItCutsInto) {
  EXPECT_EQ(audit_issues("wmg/motorway_cut_in_level1.sdl", {0, 1, 2, 3, 5, 8, 10, 11}), "");
}

TEST(CorpusSeedPointsAuditTest, TheCutOutLeadCarDoesNotDriveIntoTheParkedOne) {
  EXPECT_EQ(audit_issues("wmg/cut_out.sdl", {1, 4, 19, 20}), "");
}

TEST(CorpusSeedPointsAuditTest, TheRoundaboutCyclistDoesNotTurnOnTheSpot) {
  EXPECT_EQ(audit_issues("wmg/roundabout_cyclist_level1.sdl", {0, 4}), "");
}

// Its waypoint across the centre line used to face the oncoming lane's way, and the car looped
// round off the road to meet it. (Where its path bends at that waypoint a few points still turn
// tighter than full lock for a step, e.g. seed 23: not asserted here yet.)
TEST(CorpusSeedPointsAuditTest, TheDriftingOncomingCarStaysOnTheRoad) {
  EXPECT_EQ(audit_issues("avunit/overtaking_oncoming.avu", {1, 2, 4, 13, 23},
                         {AuditKind::off_road, AuditKind::npc_overlap}),
            "");
  EXPECT_EQ(audit_issues("avunit/overtaking_oncoming.avu", {1, 2, 4, 13}), "");
}

TEST(CorpusSeedPointsAuditTest, TheTwoJaywalkersDoNotWalkThroughEachOther) {
  EXPECT_EQ(audit_issues("avunit/jaywalker_night_rain.avu", {10, 11, 27, 43, 44, 47}), "");
}

}  // namespace
}  // namespace scenfuzz
