// The trace audit: each kind of implausibility found on a trace built by hand, with a plausible
// actor beside it that must not be reported; then every corpus seed at the middle of its space,
// whose findings are printed for the reader.
#include "oracle/trace_audit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>

#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"
#include "trace_fixtures.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

constexpr double kDt = 0.05;
constexpr std::size_t kSamples = 100;  // 5 s
// `straight` with one lane each way, 3.5 m wide: east_0 along y = -1.75, the road y in [-3.5,
// 3.5] and x in [0, 500].
constexpr double kEastLaneY = -1.75;

RoadMap straight_map() { return build_road_map(generate_builtin_map("straight", {{"lanes", 1}})); }

// An actor whose heading integrates its yaw rate and whose position integrates its speed along
// the heading (the trace's convention: sample i's rates cover the step from i - 1 to i), on no
// recorded lane (the audit asks the map). Acceleration is the speed's backward difference.
TraceActor integrated(const Trace& trace, std::string name, TraceActorKind kind,
                      ActorCategory category, MapPoint start, const std::vector<double>& speed,
                      const std::vector<double>& yaw_rate, double heading = 0) {
  TraceActor actor = test::still_actor(trace, std::move(name), kind, BodyShape::box, 4.7, 1.85,
                                       start.x, start.y, heading, speed[0]);
  actor.category = category;
  actor.yaw_rate = yaw_rate;
  actor.speed = speed;
  for (std::size_t i = 1; i < trace.sample_count(); ++i) {
    actor.heading[i] = angle_difference(actor.heading[i - 1] + yaw_rate[i] * trace.dt, 0);
    actor.x[i] = actor.x[i - 1] + speed[i] * std::cos(actor.heading[i]) * trace.dt;
    actor.y[i] = actor.y[i - 1] + speed[i] * std::sin(actor.heading[i]) * trace.dt;
    actor.acceleration[i] = (speed[i] - speed[i - 1]) / trace.dt;
  }
  return actor;
}

std::vector<double> constant(double value) { return std::vector<double>(kSamples, value); }

// A car weaving along its lane: yaw rate 0.4 cos(pi t) at 10 m/s (4 m/s^2 at most sideways).
TraceActor weaving_car(const Trace& trace, std::string name) {
  std::vector<double> yaw_rate(kSamples);
  for (std::size_t i = 0; i < kSamples; ++i)
    yaw_rate[i] = 0.4 * std::cos(std::numbers::pi * trace.time[i]);
  return integrated(trace, std::move(name), TraceActorKind::vehicle, ActorCategory::car,
                    {10, kEastLaneY}, constant(10), yaw_rate);
}

// A car driving east on east_0 at `speed`, its lane and s recorded as the simulation does.
TraceActor lane_car(const Trace& trace, std::string name, double x0, double speed) {
  TraceActor actor = test::still_actor(trace, std::move(name), TraceActorKind::vehicle,
                                       BodyShape::box, 4.7, 1.85, x0, kEastLaneY);
  test::drive_east(trace, actor, x0, speed, 0, kEastLaneY);
  return actor;
}

Trace trace_with(std::vector<TraceActor> actors) {
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = std::move(actors);
  return trace;
}

std::vector<AuditIssue> issues_of(const TraceAudit& audit, AuditKind kind) {
  std::vector<AuditIssue> found;
  for (const AuditIssue& issue : audit.issues)
    if (issue.kind == kind) found.push_back(issue);
  return found;
}

std::string describe(const TraceAudit& audit) {
  std::ostringstream text;
  for (const AuditIssue& issue : audit.issues)
    text << issue.actor_name << " " << audit_kind_name(issue.kind) << " from " << issue.time
         << " s, worst " << issue.worst << " at " << issue.worst_time << " s (limit " << issue.limit
         << "), " << issue.samples << " samples"
         << (issue.other_name.empty() ? "" : " with " + issue.other_name) << "\n";
  return text.str();
}

// The plausible cast every test starts from: an ego and a car on their lane, a weaving car, a
// pedestrian crossing the road from the pavement and turning back, a parked obstacle on the
// verge, and a car that cuts a corner off the road for less than the grace time.
std::vector<TraceActor> plausible_cast(const Trace& timing) {
  TraceActor ego = lane_car(timing, "ego", 0, 8);
  ego.kind = TraceActorKind::ego;
  std::vector<double> walk = constant(1.4), turn = constant(0);
  turn[50] = 0.75 * std::numbers::pi / kDt;  // turning on the spot, as pedestrians do
  TraceActor pedestrian =
      integrated(timing, "ped", TraceActorKind::pedestrian, ActorCategory::pedestrian, {60, -6},
                 walk, turn, std::numbers::pi / 2);
  TraceActor obstacle = test::still_actor(timing, "cone", TraceActorKind::obstacle, BodyShape::cone,
                                          0.5, 0.5, 80, -8);
  TraceActor corner = lane_car(timing, "corner", 30, 10);
  for (std::size_t i = 40; i < 60; ++i) {  // 1 s at y = -5: the grace time, not more
    corner.y[i] = -5;
    corner.lane[i] = -1;
    corner.s[i] = 0;
  }
  return {
      ego,   lane_car(timing, "npc1", 20, 12), weaving_car(timing, "weaver"), pedestrian, obstacle,
      corner};
}

TEST(TraceAuditTest, PlausibleActorsAreNotReported) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = plausible_cast(trace);
  // The ego's contacts are findings of the search, not flaws of the simulated world.
  trace.collisions.push_back({1.0, kEgo, 1, {}, BodySide::front, BodySide::rear});
  const TraceAudit audit = audit_trace(trace, map);
  EXPECT_TRUE(audit.clean()) << describe(audit);
  for (std::size_t kind = 0; kind < kAuditKindCount; ++kind) EXPECT_EQ(audit.counts[kind], 0u);
}

TEST(TraceAuditTest, AVehicleOffEveryLaneLongerThanTheGraceTimeIsOffRoad) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = plausible_cast(trace);
  TraceActor npc = lane_car(trace, "npc2", 40, 10);
  for (std::size_t i = 10; i < 20; ++i) npc.y[i] = -6;  // 0.5 s: forgiven
  for (std::size_t i = 40; i < 90; ++i) npc.y[i] = -6;  // 2.5 s on the verge
  // Whatever lane the trace recorded: the map says where the road is.
  TraceActor liar = lane_car(trace, "liar", 40, 10);
  for (std::size_t i = 0; i < 30; ++i) liar.y[i] = -20;  // recorded on east_0 all along
  TraceActor untracked = lane_car(trace, "untracked", 40, 10);
  std::fill(untracked.lane.begin(), untracked.lane.end(), -1);  // on the lane all along
  TraceActor ped = trace.actors[3];
  ped.name = "ped2";
  ped.y = std::vector<double>(kSamples, -30);  // pedestrians are not held to lanes
  for (TraceActor* actor : {&npc, &liar, &untracked, &ped}) trace.actors.push_back(*actor);

  const TraceAudit audit = audit_trace(trace, map);
  const std::vector<AuditIssue> off_road = issues_of(audit, AuditKind::off_road);
  ASSERT_EQ(off_road.size(), 2u) << describe(audit);
  EXPECT_EQ(audit.count(AuditKind::off_road), 2u);
  EXPECT_EQ(off_road[0].actor_name, "npc2");
  EXPECT_DOUBLE_EQ(off_road[0].time, 2.0);
  EXPECT_DOUBLE_EQ(off_road[0].worst_time, 2.0);
  EXPECT_NEAR(off_road[0].worst, 2.5, 1e-9);
  EXPECT_EQ(off_road[0].limit, kAuditThresholds.off_road_grace);
  EXPECT_EQ(off_road[0].samples, 50u);
  EXPECT_EQ(off_road[1].actor_name, "liar");
  EXPECT_DOUBLE_EQ(off_road[1].time, 0.0);
  EXPECT_NEAR(off_road[1].worst, 1.5, 1e-9);
  EXPECT_EQ(audit.issues.size(), 2u) << describe(audit);
}

TEST(TraceAuditTest, AnActorFasterThanItsClassBreaksItsSpeedLimit) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = plausible_cast(trace);
  TraceActor bicycle = lane_car(trace, "bike", 10, 12);  // a bicycle's top speed: allowed
  bicycle.category = ActorCategory::bicycle;
  TraceActor racer = lane_car(trace, "racer", 10, 40);
  racer.speed[30] = 55;
  racer.speed[31] = 60;
  racer.speed[32] = 52;
  trace.actors.push_back(bicycle);
  trace.actors.push_back(racer);

  const TraceAudit audit = audit_trace(trace, map);
  ASSERT_EQ(audit.issues.size(), 1u) << describe(audit);
  const AuditIssue& issue = audit.issues[0];
  EXPECT_EQ(issue.actor_name, "racer");
  EXPECT_EQ(issue.actor, 7u);
  EXPECT_EQ(issue.kind, AuditKind::speed_limit);
  EXPECT_DOUBLE_EQ(issue.time, trace.time[30]);
  EXPECT_DOUBLE_EQ(issue.worst_time, trace.time[31]);
  EXPECT_EQ(issue.worst, 60);
  EXPECT_EQ(issue.limit, actor_class(ActorCategory::car).max_speed);
  EXPECT_EQ(issue.samples, 3u);
  EXPECT_EQ(audit.count(AuditKind::speed_limit), 1u);
}

TEST(TraceAuditTest, AccelerationAndBrakingBeyondTheClassAreReportedWithTheWorstSigned) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = plausible_cast(trace);
  const ActorClass& car = actor_class(ActorCategory::car);
  TraceActor hard = lane_car(trace, "hard", 10, 10);  // at both limits: allowed
  hard.acceleration[10] = car.max_acceleration;
  hard.acceleration[20] = -car.max_deceleration;
  TraceActor jumpy = lane_car(trace, "jumpy", 10, 10);
  jumpy.acceleration[10] = car.max_acceleration + 1.5;
  jumpy.acceleration[20] = -car.max_deceleration - 2;  // the worst: 2 beyond
  trace.actors.push_back(hard);
  trace.actors.push_back(jumpy);

  const TraceAudit audit = audit_trace(trace, map);
  ASSERT_EQ(audit.issues.size(), 1u) << describe(audit);
  const AuditIssue& issue = audit.issues[0];
  EXPECT_EQ(issue.actor_name, "jumpy");
  EXPECT_EQ(issue.kind, AuditKind::acceleration);
  EXPECT_DOUBLE_EQ(issue.time, trace.time[10]);
  EXPECT_DOUBLE_EQ(issue.worst_time, trace.time[20]);
  EXPECT_EQ(issue.worst, -car.max_deceleration - 2);
  EXPECT_EQ(issue.limit, -car.max_deceleration);
  EXPECT_EQ(issue.samples, 2u);
}

TEST(TraceAuditTest, CorneringHarderThanTheTyresHoldIsALateralAcceleration) {
  const RoadMap map = straight_map();
  Trace timing = test::empty_trace(kSamples, kDt);
  // 20 m/s through an S at 0.3 rad/s: 6 m/s^2, within a car's 8; at 0.5 rad/s: 10 m/s^2.
  std::vector<double> gentle = constant(0), harsh = constant(0);
  std::fill(gentle.begin() + 10, gentle.begin() + 20, 0.3);
  std::fill(gentle.begin() + 20, gentle.begin() + 30, -0.3);
  std::fill(harsh.begin() + 10, harsh.begin() + 20, 0.5);
  std::fill(harsh.begin() + 20, harsh.begin() + 30, -0.5);
  Trace trace = trace_with({integrated(timing, "gentle", TraceActorKind::vehicle,
                                       ActorCategory::car, {10, -2.5}, constant(20), gentle),
                            integrated(timing, "harsh", TraceActorKind::vehicle, ActorCategory::car,
                                       {10, -2.5}, constant(20), harsh)});

  const TraceAudit audit = audit_trace(trace, map);
  for (const AuditIssue& issue : audit.issues) EXPECT_NE(issue.actor_name, "gentle");
  const std::vector<AuditIssue> lateral = issues_of(audit, AuditKind::lateral_acceleration);
  ASSERT_EQ(lateral.size(), 1u) << describe(audit);
  EXPECT_EQ(lateral[0].actor_name, "harsh");
  EXPECT_DOUBLE_EQ(lateral[0].time, trace.time[10]);
  EXPECT_NEAR(lateral[0].worst, 10, 1e-9);
  EXPECT_EQ(lateral[0].limit, actor_class(ActorCategory::car).max_deceleration);
  EXPECT_EQ(lateral[0].samples, 20u);
  // At 20 m/s a car's full lock turns far faster than 0.5 rad/s.
  EXPECT_EQ(audit.count(AuditKind::turning_radius), 0u);
}

TEST(TraceAuditTest, TurningTighterThanFullLockIsATurningRadiusIssue) {
  const RoadMap map = straight_map();
  Trace timing = test::empty_trace(kSamples, kDt);
  const double min_radius = actor_class(ActorCategory::car).min_turning_radius();
  // At 1 m/s: a circle of 1.2 times the smallest (allowed), and one of a metre (not).
  std::vector<double> wide = constant(0), tight = constant(0);
  std::fill(wide.begin() + 10, wide.begin() + 30, 1 / (1.2 * min_radius));
  std::fill(tight.begin() + 10, tight.begin() + 30, 1.0);
  Trace trace = trace_with({integrated(timing, "wide", TraceActorKind::vehicle, ActorCategory::car,
                                       {10, kEastLaneY}, constant(1), wide),
                            integrated(timing, "tight", TraceActorKind::vehicle, ActorCategory::car,
                                       {10, kEastLaneY}, constant(1), tight)});

  const TraceAudit audit = audit_trace(trace, map);
  ASSERT_EQ(audit.issues.size(), 1u) << describe(audit);
  const AuditIssue& issue = audit.issues[0];
  EXPECT_EQ(issue.actor_name, "tight");
  EXPECT_EQ(issue.kind, AuditKind::turning_radius);
  EXPECT_DOUBLE_EQ(issue.time, trace.time[10]);
  EXPECT_EQ(issue.worst, 1.0);
  EXPECT_NEAR(issue.limit, 1 / min_radius, 1e-12);
  EXPECT_EQ(issue.samples, 20u);
}

TEST(TraceAuditTest, AYawRateThatIsNotTheHeadingsDerivativeIsFoundToAMillionthOfARadian) {
  const RoadMap map = straight_map();
  Trace timing = test::empty_trace(kSamples, kDt);
  // Driving west and turning left through +-pi for 2 s: the wrap must not look like a spike.
  std::vector<double> turning = constant(0);
  std::fill(turning.begin() + 1, turning.begin() + 41, 0.25);
  TraceActor consistent =
      integrated(timing, "consistent", TraceActorKind::vehicle, ActorCategory::car, {400, 1.5},
                 constant(3), turning, std::numbers::pi - 0.25);
  TraceActor nudged = consistent;
  nudged.name = "nudged";
  nudged.yaw_rate[40] += 3e-6;
  nudged.yaw_rate[70] -= 5e-6;  // the worst
  // The rate of the step after a sample instead of the one before it: off by every change.
  TraceActor shifted = consistent;
  shifted.name = "shifted";
  for (std::size_t i = 0; i + 1 < kSamples; ++i) shifted.yaw_rate[i] = consistent.yaw_rate[i + 1];
  shifted.yaw_rate[10] = 0.55;  // the worst: 0.3 off
  Trace trace = trace_with({consistent, nudged, shifted});

  const TraceAudit audit = audit_trace(trace, map);
  const std::vector<AuditIssue> yaw = issues_of(audit, AuditKind::yaw_rate_inconsistent);
  ASSERT_EQ(yaw.size(), 2u) << describe(audit);
  EXPECT_EQ(yaw[0].actor_name, "nudged");
  EXPECT_DOUBLE_EQ(yaw[0].time, trace.time[40]);
  EXPECT_DOUBLE_EQ(yaw[0].worst_time, trace.time[70]);
  EXPECT_NEAR(yaw[0].worst, 5e-6, 1e-9);
  EXPECT_EQ(yaw[0].limit, kAuditThresholds.yaw_rate_tolerance);
  EXPECT_EQ(yaw[0].samples, 2u);
  EXPECT_EQ(yaw[1].actor_name, "shifted");
  EXPECT_NEAR(yaw[1].worst, 0.3, 1e-9);
  for (const AuditIssue& issue : audit.issues) EXPECT_NE(issue.actor_name, "consistent");
}

TEST(TraceAuditTest, ContactsBetweenActorsOtherThanTheEgoAreNpcOverlaps) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  trace.actors = plausible_cast(trace);
  trace.collisions.push_back({0.5, kEgo, 2, {}, BodySide::front, BodySide::rear});
  trace.collisions.push_back({1.5, 1, 4, {}, BodySide::front, BodySide::left});
  trace.collisions.push_back({2.5, 1, 2, {}, BodySide::left, BodySide::right});

  const TraceAudit audit = audit_trace(trace, map);
  ASSERT_EQ(audit.issues.size(), 2u) << describe(audit);
  EXPECT_EQ(audit.count(AuditKind::npc_overlap), 2u);
  // By actor, then by kind, then by time.
  EXPECT_EQ(audit.issues[0].kind, AuditKind::npc_overlap);
  EXPECT_EQ(audit.issues[0].actor_name, "npc1");
  EXPECT_EQ(audit.issues[0].other_name, "cone");
  EXPECT_EQ(audit.issues[0].other, 4u);
  EXPECT_DOUBLE_EQ(audit.issues[0].time, 1.5);
  EXPECT_EQ(audit.issues[1].other_name, "weaver");
  EXPECT_DOUBLE_EQ(audit.issues[1].time, 2.5);
}

TEST(TraceAuditTest, IssuesAreOrderedByActorThenKindAndCountedPerKind) {
  const RoadMap map = straight_map();
  Trace trace = test::empty_trace(kSamples, kDt);
  TraceActor wild = lane_car(trace, "wild", 10, 10);
  wild.y[50] = wild.y[51] = -30;  // two samples off the road: within the grace
  for (std::size_t i = 60; i < kSamples; ++i) wild.y[i] = -30;
  wild.speed[70] = 80;
  wild.acceleration[5] = 20;
  wild.yaw_rate[3] = 3;
  TraceActor other = lane_car(trace, "other", 10, 10);
  other.speed[1] = 51;
  trace.actors = {other, wild};
  trace.collisions.push_back({0.2, 0, 1, {}, BodySide::front, BodySide::rear});  // other is ego 0

  const TraceAudit audit = audit_trace(trace, map);
  std::vector<std::pair<std::string, AuditKind>> order;
  for (const AuditIssue& issue : audit.issues) order.emplace_back(issue.actor_name, issue.kind);
  const std::vector<std::pair<std::string, AuditKind>> expected = {
      {"other", AuditKind::speed_limit},
      {"wild", AuditKind::off_road},
      {"wild", AuditKind::speed_limit},
      {"wild", AuditKind::lateral_acceleration},  // 10 m/s at 3 rad/s
      {"wild", AuditKind::acceleration},
      {"wild", AuditKind::turning_radius},
      {"wild", AuditKind::yaw_rate_inconsistent}};
  EXPECT_EQ(order, expected) << describe(audit);
  EXPECT_EQ(audit.count(AuditKind::speed_limit), 2u);
  EXPECT_EQ(audit.count(AuditKind::npc_overlap), 0u);
  std::size_t total = 0;
  for (std::size_t n : audit.counts) total += n;
  EXPECT_EQ(total, audit.issues.size());
  EXPECT_NEAR(issues_of(audit, AuditKind::off_road)[0].worst, 2.0, 1e-9);
}

// Every AVUnit seed simulated at the middle of its space: the audit runs on each, the same twice,
// and what it finds is printed (the simulation is known to have flaws it should show).
TEST(TraceAuditTest, EveryCorpusSeedIsAuditedAtTheMiddleOfItsSpace) {
  SCENFUZZ_REQUIRE_SHARED_DIR();  // four seeds drive on san_francisco
  const MapSearchPath search_path{{test::shared_dir() / "maps" / "apollo"}};
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(fs::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "avunit"))
    if (entry.path().extension() == ".avu") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 17u);
  std::array<std::size_t, kAuditKindCount> totals{};
  for (const fs::path& path : files) {
    SCOPED_TRACE(path.filename().string());
    const std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file);
    const avunit::ParseResult parsed = avunit::parse(*file);
    ASSERT_TRUE(parsed.ok());
    const ParameterSpace space = parameter_space(parsed.scenario);
    const std::vector<double> values =
        decode(space, std::vector<double>(space.dimensions.size(), 0.5));
    const RoadMap map = load_scenario_map(parsed.scenario.map, search_path, values);
    Diagnostics diagnostics;
    auto setup = prepare_simulation(parsed.scenario, values, map, 1, diagnostics);
    ASSERT_TRUE(setup) << format_diagnostics(*file, diagnostics);
    const Trace trace = simulate(map, *setup, {});
    ASSERT_GT(trace.sample_count(), 1u);

    const TraceAudit audit = audit_trace(trace, map);
    const TraceAudit again = audit_trace(trace, map);
    EXPECT_EQ(describe(audit), describe(again));
    EXPECT_EQ(audit.counts, again.counts);
    std::size_t counted = 0;
    for (std::size_t kind = 0; kind < kAuditKindCount; ++kind) {
      counted += audit.counts[kind];
      totals[kind] += audit.counts[kind];
    }
    EXPECT_EQ(counted, audit.issues.size());
    for (const AuditIssue& issue : audit.issues) {
      EXPECT_LT(issue.actor, trace.actors.size());
      EXPECT_LE(issue.time, issue.worst_time);
      EXPECT_LE(issue.worst_time, trace.time.back());
      if (issue.kind == AuditKind::npc_overlap) continue;
      EXPECT_GT(issue.samples, 0u);
      // The worst is beyond its limit, on the side the limit is on.
      EXPECT_GT(issue.limit < 0 ? -issue.worst : issue.worst, std::abs(issue.limit));
    }
    std::cout << "[ audit    ] " << path.filename().string() << ": " << audit.issues.size()
              << " issue(s) on " << trace.actors.size() << " actors, " << trace.sample_count()
              << " samples\n"
              << describe(audit);
  }
  std::cout << "[ audit    ] all seeds:";
  for (std::size_t kind = 0; kind < kAuditKindCount; ++kind)
    std::cout << " " << audit_kind_name(static_cast<AuditKind>(kind)) << " " << totals[kind];
  std::cout << "\n";
}

}  // namespace
}  // namespace scenfuzz
