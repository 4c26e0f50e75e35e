// A reactive lane follower does not brake for a faster car closing on it from behind in its own
// lane: that car's predicted point (1.5 s on) lies ahead of the follower, and the follower used to
// stop for it at full braking (a flow car on a motorway braking from 20 m/s to 1 m/s, then
// rear-ended by the scripted car behind: lead_vehicle_braking_level1's NPC overlaps).
#include <gtest/gtest.h>

#include <algorithm>

#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

TEST(FollowerPredictionTest, AFasterCarBehindInTheSameLaneIsNotAStop) {
  // A reactive car at 15 m/s in east_1; a scripted car (waypoints: it sees nothing) 40 m behind
  // it at 27 m/s in the same lane.
  SimulationOptions options;
  options.duration = 4;
  options.stop_at_collision = false;
  const test::SimulatedRun run = test::simulate_text(R"(
ego = AV(("west_0"->20, , 0), ("west_0"->40));
calm = Vehicle(("east_1"->100, , 15), , ("east_1"->480));
fast = Vehicle(("east_1"->60, , 27), Waypoint(("east_1"->300, , 27)), ("east_1"->480));
scenario = CreateScenario{load("straight"); ego; {calm, fast}; {}; {};};
)",
                                                     options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  const TraceActor& calm = trace.actors[*trace.find_actor("calm")];
  double first_contact = trace.time.back() + 1;
  for (const Collision& collision : trace.collisions)
    first_contact = std::min(first_contact, collision.time);
  for (std::size_t i = 0; i < trace.sample_count() && trace.time[i] < first_contact; ++i)
    EXPECT_GT(calm.acceleration[i], -1.0) << "at " << trace.time[i] << " s";
}

}  // namespace
}  // namespace scenfuzz
