// Waypoint NPCs of the corpus seeds through the whole simulation and the trace audit: they drive
// round the roundabout's ring (not across its island) and change lane as a calm driver would.
// Here rather than in tests/physics because the audit lives in oracle/.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

struct AuditedRun {
  RoadMap map;
  Trace trace;
  TraceAudit audit;
};

// A corpus seed simulated at `point` of its search space (every coordinate in [0, 1]).
AuditedRun run_seed(const fs::path& path, double point) {
  const std::optional<SourceFile> file = read_source_file(path.string());
  if (!file) throw std::runtime_error("cannot read " + path.string());
  const avunit::ParseResult parsed = avunit::parse(*file);
  if (!parsed.ok()) throw std::runtime_error(format_diagnostics(*file, parsed.diagnostics));
  const ParameterSpace space = parameter_space(parsed.scenario);
  const std::vector<double> values =
      decode(space, std::vector<double>(space.dimensions.size(), point));
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, 1, diagnostics);
  if (!setup) throw std::runtime_error(format_diagnostics(*file, diagnostics));
  Trace trace = simulate(map, *setup, {});
  TraceAudit audit = audit_trace(trace, map);
  return {std::move(map), std::move(trace), std::move(audit)};
}

AuditedRun run_corpus_seed(const std::string& name, double point) {
  return run_seed(fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit" / name, point);
}

ActorId actor_named(const Trace& trace, const std::string& name) {
  for (ActorId id = 0; id < trace.actors.size(); ++id)
    if (trace.actors[id].name == name) return id;
  throw std::runtime_error("no actor " + name);
}

std::vector<AuditIssue> issues_of(const TraceAudit& audit, ActorId actor, AuditKind kind) {
  std::vector<AuditIssue> found;
  for (const AuditIssue& issue : audit.issues)
    if (issue.actor == actor && issue.kind == kind) found.push_back(issue);
  return found;
}

TEST(WaypointLanePathsAuditTest, RoundaboutNpcsDriveRoundTheRingNotAcrossTheIsland) {
  // roundabout: the ring_0 centre line is a 20 m circle about (0, 0), 3.5 m wide, so the island
  // ends 18.25 m from the centre. npc1 circulates and leaves east; npc2 enters from the west, goes
  // two thirds round (ring_0 -> 110 -> 10, over the ring's seam) and leaves north.
  for (double point : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    SCOPED_TRACE("point " + std::to_string(point));
    const AuditedRun run = run_seed(
        fs::path(SCENFUZZ_SOURCE_DIR) / "tests" / "oracle" / "data" / "roundabout_waypoints.avu",
        point);
    const auto ring = run.map.find_lane("ring_0");
    ASSERT_TRUE(ring);
    for (const std::string name : {"npc1", "npc2"}) {
      SCOPED_TRACE(name);
      const ActorId id = actor_named(run.trace, name);
      EXPECT_TRUE(issues_of(run.audit, id, AuditKind::off_road).empty());
      const TraceActor& npc = run.trace.actors[id];
      bool on_ring = false;
      for (std::size_t i = 0; i < npc.x.size(); ++i) {
        EXPECT_GT(std::hypot(npc.x[i], npc.y[i]), 18.25)
            << "on the island at " << run.trace.time[i] << " s";
        if (npc.lane[i] == static_cast<std::int32_t>(*ring)) on_ring = true;
      }
      EXPECT_TRUE(on_ring);
    }
    // npc2 passes the ring's seam (s = 0) on the lane, between its waypoints at s = 110 and 10,
    // when the run lasts that long.
    const TraceActor& npc2 = run.trace.actors[actor_named(run.trace, "npc2")];
    bool near_seam = false, past_seam = false;
    for (std::size_t i = 0; i < npc2.x.size(); ++i) {
      if (npc2.lane[i] != static_cast<std::int32_t>(*ring)) continue;
      if (npc2.s[i] > 110) near_seam = true;
      if (near_seam && npc2.s[i] < 10) past_seam = true;
    }
    if (run.trace.time.back() > 25) {
      EXPECT_TRUE(past_seam);
    }
  }
}

TEST(WaypointLanePathsAuditTest, TheCutInStraightCutterChangesLaneWithinItsComfortableLimit) {
  // Points where the cut-in leg has room for a comfortable lane change (57.5, 65 and 72.5 m at
  // 12, 17 and 22 m/s); the car's comfortable lateral acceleration is 3 m/s^2.
  const double comfortable = actor_class(ActorCategory::car).comfortable_lateral_acceleration;
  for (double point : {0.25, 0.5, 0.75}) {
    SCOPED_TRACE("point " + std::to_string(point));
    const AuditedRun run = run_corpus_seed("cut_in_straight.avu", point);
    const ActorId id = actor_named(run.trace, "cutter");
    const TraceActor& cutter = run.trace.actors[id];
    double largest = 0;
    for (std::size_t i = 0; i < cutter.x.size(); ++i)
      largest = std::max(largest, cutter.speed[i] * std::abs(cutter.yaw_rate[i]));
    // A 5 % allowance for the 1 m polyline the heading turns along.
    EXPECT_LE(largest, comfortable * 1.05);
    EXPECT_GT(largest, 0.5) << "it did change lane";
    for (const AuditIssue& issue : run.audit.issues)
      EXPECT_NE(issue.actor, id) << audit_kind_name(issue.kind) << " at " << issue.time << " s";
    EXPECT_TRUE(issues_of(run.audit, id, AuditKind::off_road).empty());
  }
}

}  // namespace
}  // namespace scenfuzz
