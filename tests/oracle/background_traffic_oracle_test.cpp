// Background traffic in the oracle: a flow vehicle's samples outside its presence interval
// (TraceActor::present_from/until) are parked values, so the collision oracle, the audit and the
// traffic-law signals that look at "any vehicle" must not read them as the vehicle being there.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "oracle/collision_oracle.hpp"
#include "oracle/trace_audit.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_source.hpp"
#include "trace_fixtures.hpp"

namespace scenfuzz {
namespace {

constexpr std::size_t kSamples = 20;

// The ego at the origin, and a car whose columns put it 1 m in front of the ego throughout (at
// an absurd 90 m/s), but which is on the map only for samples [8, 12).
Trace trace_with_a_passing_car() {
  Trace trace = test::empty_trace(kSamples, 0.05);
  trace.actors.push_back(
      test::still_actor(trace, "ego", TraceActorKind::ego, BodyShape::box, 4.5, 1.8, 0, -1.75));
  TraceActor car = test::still_actor(trace, "flow1.1", TraceActorKind::vehicle, BodyShape::box, 4.5,
                                     1.8, 5.5, -1.75, 0, 90);
  car.category = ActorCategory::car;
  car.present_from = 8;
  car.present_until = 12;
  trace.actors.push_back(std::move(car));
  return trace;
}

TEST(BackgroundTrafficOracleTest, TheEgosClearanceIgnoresAVehicleOffTheMap) {
  const Trace trace = trace_with_a_passing_car();
  const std::vector<double> clearance = ego_clearance(trace);
  for (std::size_t i = 0; i < kSamples; ++i) {
    if (i >= 8 && i < 12)
      EXPECT_NEAR(clearance[i], 1.0, 1e-9) << i;
    else
      EXPECT_EQ(clearance[i], std::numeric_limits<double>::infinity()) << i;
  }
  const CollisionVerdict verdict = collision_verdict(trace);
  EXPECT_NEAR(verdict.robustness, 1.0, 1e-9);
  EXPECT_EQ(verdict.sample, 8u);
}

TEST(BackgroundTrafficOracleTest, TheAuditReadsOnlyTheSamplesOnTheMap) {
  const RoadMap map = build_road_map(generate_builtin_map("straight", {{"lanes", 1}}));
  Trace trace = trace_with_a_passing_car();
  trace.actors[1].speed.assign(kSamples, 10);  // plausible while there
  for (std::size_t i = 0; i < kSamples; ++i)
    if (!present_at(trace.actors[1], i)) trace.actors[1].speed[i] = 90;  // parked garbage
  const TraceAudit clean = audit_trace(trace, map);
  for (const AuditIssue& issue : clean.issues)
    EXPECT_NE(issue.actor, 1u) << audit_kind_name(issue.kind) << " at " << issue.time;

  trace.actors[1].speed[9] = 90;  // on the map: reported
  const TraceAudit found = audit_trace(trace, map);
  bool speeding = false;
  for (const AuditIssue& issue : found.issues)
    if (issue.actor == 1 && issue.kind == AuditKind::speed_limit) speeding = issue.samples == 1;
  EXPECT_TRUE(speeding);
}

}  // namespace
}  // namespace scenfuzz
