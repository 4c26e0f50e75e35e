// Every corpus seed and benchmark scenario, simulated at several points of its search space, passes
// the trace audit's limits: no actor beats its class's speed, acceleration, grip or steering lock,
// and every recorded yaw rate is its heading's derivative. Off-road driving and NPC overlaps are
// counted and printed but not asserted here: the tests of the reactive NPCs and the lane-true paths
// hold those. Seeds on Apollo maps need the shared folder and are skipped, loudly, without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "../support/corpus_seeds.hpp"
#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// The corners and the middle of each space, and points between: different enough to take the
// NPCs through their scripts at different speeds and timings.
constexpr double kPoints[] = {0.0, 0.25, 0.5, 0.75, 1.0};

constexpr AuditKind kLimits[] = {AuditKind::speed_limit, AuditKind::lateral_acceleration,
                                 AuditKind::acceleration, AuditKind::turning_radius,
                                 AuditKind::yaw_rate_inconsistent};

using test::corpus_seeds;
using test::parse_seed;

bool is_limit(AuditKind kind) {
  return std::find(std::begin(kLimits), std::end(kLimits), kind) != std::end(kLimits);
}

TEST(CorpusAuditTest, NoSeedsActorBeatsItsClassOrTurnsWithoutItsHeading) {
  std::ostringstream limits, others, skipped;
  std::size_t runs = 0;
  for (const fs::path& path : corpus_seeds()) {
    const std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file) << path;
    const std::optional<ScenarioTemplate> scenario = parse_seed(*file);
    ASSERT_TRUE(scenario) << path << " does not parse";
    const ParameterSpace space = parameter_space(*scenario);
    for (double point : kPoints) {
      const std::vector<double> values =
          decode(space, std::vector<double>(space.dimensions.size(), point));
      const test::SeedRun run = test::simulate_seed(*file, *scenario, values);
      if (run.map_missing) {
        ASSERT_FALSE(test::have_shared_dir()) << run.error;
        skipped << "  " << path.filename().string() << " (its map is in the shared folder)\n";
        break;
      }
      ASSERT_TRUE(run.trace) << run.error;
      const Trace& trace = *run.trace;
      const RoadMap& map = *run.map;
      ++runs;
      for (const AuditIssue& issue : audit_trace(trace, map).issues)
        (is_limit(issue.kind) ? limits : others)
            << "  " << path.filename().string() << " at " << point << ": " << issue.actor_name
            << " " << audit_kind_name(issue.kind) << " " << issue.worst << " (limit " << issue.limit
            << ") at " << issue.worst_time << " s\n";
    }
  }
  if (!skipped.str().empty())
    std::printf("SKIPPED, shared folder %s not found:\n%s", SCENFUZZ_SHARED_DIR,
                skipped.str().c_str());
  if (!others.str().empty()) std::printf("other audit issues:\n%s", others.str().c_str());
  EXPECT_GT(runs, 0u);
  EXPECT_EQ(limits.str(), "") << "limits exceeded or yaw rates inconsistent";
}

}  // namespace
}  // namespace scenfuzz
