// A WMG actor in a manoeuvre phase drives its script, but not into the traffic ahead of it: it
// brakes at the last firm moment for an actor other than the ego (lane_cruise.hpp,
// phase_leader_limit), and still drives into the ego when its script takes it there.
#include <gtest/gtest.h>

#include "manoeuvre_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::lane_state;
using test::manoeuvring;
using test::phase;
using test::run_manoeuvres;
using test::three_lane_road;

const TraceActor& actor_named(const Trace& trace, const std::string& name) {
  return trace.actors[*trace.find_actor(name)];
}

TEST(PhaseLeaderTest, APhaseBrakesForAStandingCarAheadAndThenStandsBehindIt) {
  ScenarioTemplate scenario = three_lane_road(10, 0, 20);
  scenario.vehicles.push_back(manoeuvring(ActorKind::vehicle, "Standing",
                                          lane_state("east_1", 200, 0), {phase("Stopped", 0, 0)}));
  // 25 m/s held for 15 s: its script would take it 375 m, through the standing car.
  scenario.vehicles.push_back(manoeuvring(
      ActorKind::vehicle, "Runner", lane_state("east_1", 40, 25), {phase("Drive_Away", 25, 15)}));
  test::ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  EXPECT_TRUE(run.trace->collisions.empty());
  const TraceActor& standing = actor_named(*run.trace, "Standing");
  const TraceActor& runner = actor_named(*run.trace, "Runner");
  const double gap = standing.x.back() - runner.x.back() - (standing.length + runner.length) / 2;
  EXPECT_GT(gap, 0.5);
  EXPECT_LT(gap, 6.0);
  EXPECT_LT(runner.speed.back(), 0.01);
  // Until firm braking is needed, the script runs as written.
  EXPECT_NEAR(runner.speed[test::sample_at(*run.trace, 2.0)], 25, 0.01);
}

TEST(PhaseLeaderTest, APhaseStillDrivesIntoTheEgoAhead) {
  ScenarioTemplate scenario = three_lane_road(200, 0, 20);
  scenario.ego.initial = lane_state("east_1", 200, 0);
  scenario.vehicles.push_back(manoeuvring(
      ActorKind::vehicle, "Runner", lane_state("east_1", 40, 25), {phase("Drive_Away", 25, 15)}));
  test::ManoeuvreRun run = run_manoeuvres(scenario);
  ASSERT_TRUE(run.trace) << run.messages;
  ASSERT_FALSE(run.trace->collisions.empty());
  EXPECT_EQ(run.trace->collisions.front().first, kEgo);
}

}  // namespace
}  // namespace scenfuzz
