// Reactive lane-following NPCs in whole simulations: they stop behind a stopped car, queue at a
// red light and leave on green, and cross a signalised junction for two minutes without touching
// each other; scripted, the same NPCs drive into what is in their way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::closest_approach;
using test::simulate_text;

std::string scenario_text(const std::string& map, const std::string& definitions,
                          const std::string& npcs) {
  return definitions + "\nscenario = CreateScenario{load(\"" + map + "\");\nego;\n{" + npcs +
         "};\n{};\n{};\n};\n";
}

// An ego out of the way: it drives 20 m on the east arm's inbound lane and stands at its target.
const std::string kQuietEgo = "ego = AV((\"east_in_0\"->10, , 0), (\"east_in_0\"->30));\n";

// Runs for the whole duration: the ego standing at its target does not end the run.
SimulationOptions lasting(double duration) {
  SimulationOptions options;
  options.duration = duration;
  options.target_reach = -1;
  return options;
}

int npc_collisions(const Trace& trace) {
  int count = 0;
  for (const Collision& collision : trace.collisions)
    if (collision.first != kEgo && collision.second != kEgo) ++count;
  return count;
}

// Between its looks at every actor (every 0.2 s) a follower measures the gap to its leader along
// the lanes (the leader's lane position less its own): behind a slower car it settles at IDM's
// desired gap, standstill gap plus time gap at the car's speed, and never touches it.
TEST(LaneFollowerTest, KeepsItsTimeGapBehindASlowerCar) {
  std::string text =
      scenario_text("straight?two_way=0&lanes=2&length=1000",
                    "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->30));\n"
                    "slow = Vehicle((\"east_0\"->60, , 8), , (\"east_0\"->990));\n"
                    "follower = Vehicle((\"east_0\"->10, , 15), , (\"east_0\"->990));\n",
                    "slow, follower");
  auto run = simulate_text(text, lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_EQ(npc_collisions(trace), 0);
  const std::size_t last = trace.sample_count() - 1;
  const double speed = trace.actors[1].speed[last];
  EXPECT_NEAR(trace.actors[2].speed[last], speed, 0.2);
  // Bumper to bumper along the road (both drive east along one lane).
  const double gap = trace.actors[1].x[last] - trace.actors[2].x[last] -
                     (trace.actors[1].length + trace.actors[2].length) / 2;
  const double desired = 2.0 + 1.5 * speed;  // FollowerSettings' standstill and time gap
  EXPECT_NEAR(gap, desired, 1.0) << "speed " << speed;
  EXPECT_GT(test::closest_approach(trace, 1, 2), desired - 1.0);
}

TEST(LaneFollowerTest, StopsBehindAStoppedCarWithoutContact) {
  std::string text = scenario_text("straight?two_way=0&lanes=2",
                                   "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->30));\n"
                                   "parked = Vehicle((\"east_0\"->200, , 0));\n"
                                   "follower = Vehicle((\"east_0\"->40, , 15));\n",
                                   "parked, follower");
  SimulationOptions options = lasting(30);
  auto run = simulate_text(text, options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_EQ(npc_collisions(trace), 0);
  double gap = closest_approach(trace, 1, 2);
  EXPECT_GT(gap, 0.5);
  EXPECT_LT(gap, 6.0) << "it should close up behind the car, not stop far away";
  EXPECT_LT(trace.actors[2].speed.back(), 0.1);
  for (double a : trace.actors[2].acceleration) EXPECT_GE(a, -8.0 - 1e-9);

  options.npc_behaviour = NpcBehaviour::scripted;
  auto scripted = simulate_text(text, options);
  ASSERT_TRUE(scripted.trace) << scripted.errors;
  EXPECT_EQ(npc_collisions(*scripted.trace), 1) << "scripted, it drives on into the car";
}

// A truck whose target lies 5 m behind a sedan's: the sedan stops at its target first, its rear
// reaching back over the truck's target (stationary_obstacle_in_lane's npc1 and npc2, seed 2). The
// truck sees the sedan beyond the end of its own path and stops behind it, short of its target.
TEST(LaneFollowerTest, StopsBehindACarStandingBeyondItsTarget) {
  std::string text = scenario_text("straight?two_way=0&lanes=2",
                                   "ego = AV((\"east_1\"->10, , 0), (\"east_1\"->30));\n"
                                   "sedan = Vehicle((\"east_0\"->150, , 12), "
                                   "uniform((\"east_0\"->150, , 12)), (\"east_0\"->300), "
                                   "(\"Sedan\", blue));\n"
                                   "truck = Vehicle((\"east_0\"->100, , 14), "
                                   "uniform((\"east_0\"->100, , 14)), (\"east_0\"->295), "
                                   "(\"Truck\", red));\n",
                                   "sedan, truck");
  auto run = simulate_text(text, lasting(40));
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_EQ(npc_collisions(trace), 0);
  const TraceActor& sedan = trace.actors[1];
  const TraceActor& truck = trace.actors[2];
  EXPECT_NEAR(sedan.x.back(), 300, 0.5);
  EXPECT_LT(truck.speed.back(), 0.1);
  EXPECT_GT(closest_approach(trace, 1, 2), 0.5);
  EXPECT_LT(truck.x.back(), 295 - 1.0) << "it should stop short of its target, behind the sedan";
}

TEST(LaneFollowerTest, FiveQueueAtARedLightAndLeaveOnGreen) {
  // On `crossroads` east-west traffic has red for the first 30 s; the stop line of west_in_0 is at
  // x = -16.
  std::string definitions = kQuietEgo;
  std::string names;
  for (int k = 0; k < 5; ++k) {
    std::string name = "car" + std::to_string(k);
    definitions += name + " = Vehicle((\"west_in_0\"->" + std::to_string(100 - 18 * k) +
                   ", , 10), , (\"east_out_0\"->" + std::to_string(150 - 18 * k) + "));\n";
    names += (k ? ", " : "") + name;
  }
  SimulationOptions options = lasting(28);
  auto red = simulate_text(scenario_text("crossroads", definitions, names), options);
  ASSERT_TRUE(red.trace) << red.errors;
  EXPECT_EQ(npc_collisions(*red.trace), 0);
  for (ActorId k = 1; k <= 5; ++k) {
    const TraceActor& car = red.trace->actors[k];
    EXPECT_LT(car.speed.back(), 0.1) << car.name << " should wait in the queue";
    for (std::size_t i = 0; i < car.x.size(); ++i)
      ASSERT_LT(car.x[i] + car.length / 2, -16.0) << car.name << " crossed the line on red";
    if (k > 1) {
      EXPECT_GT(closest_approach(*red.trace, k - 1, k), 0.5);
    }
  }
  EXPECT_LT(red.trace->actors[1].x.back() + red.trace->actors[1].length / 2, -16.0);
  EXPECT_GT(red.trace->actors[1].x.back() + red.trace->actors[1].length / 2, -20.0)
      << "the first should stop at the line";

  options.duration = 75;
  auto green = simulate_text(scenario_text("crossroads", definitions, names), options);
  ASSERT_TRUE(green.trace) << green.errors;
  EXPECT_EQ(npc_collisions(*green.trace), 0);
  for (ActorId k = 1; k <= 5; ++k)
    EXPECT_GT(green.trace->actors[k].x.back(), 16.0)
        << green.trace->actors[k].name << " should have crossed on green";
}

TEST(LaneFollowerTest, CrossingTrafficAtASignalisedJunctionNeverCollidesOverTwoMinutes) {
  // Three cars on each inbound arm, going straight on, turning left and turning right.
  const std::string arms[] = {"north", "east", "south", "west"};
  const std::string left_of[] = {"east", "north", "west", "south"};
  const std::string right_of[] = {"west", "south", "east", "north"};
  const std::string straight[] = {"south", "west", "north", "east"};
  std::string definitions = "ego = AV((\"east_in_0\"->5, , 0), (\"east_in_0\"->25));\n";
  std::string names;
  for (int arm = 0; arm < 4; ++arm) {
    const std::string exits[] = {straight[arm], left_of[arm], right_of[arm]};
    for (int k = 0; k < 3; ++k) {
      std::string name = arms[arm] + std::to_string(k);
      double s = 40 + 30 * k + (arm == 1 ? 30 : 0);  // the ego waits at the east arm's start
      definitions += name + " = Vehicle((\"" + arms[arm] + "_in_0\"->" + std::to_string(s) +
                     ", , 11), , (\"" + exits[k] + "_out_0\"->100));\n";
      names += (names.empty() ? "" : ", ") + name;
    }
  }
  SimulationOptions options = lasting(120);
  auto run = simulate_text(scenario_text("crossroads", definitions, names), options);
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_EQ(npc_collisions(*run.trace), 0);
  int crossed = 0;
  for (ActorId k = 1; k < run.trace->actors.size(); ++k) {
    const TraceActor& car = run.trace->actors[k];
    // Through: out on an outbound lane, heading away from the junction's centre at (0, 0).
    double x = car.x.back(), y = car.y.back(), heading = car.heading.back();
    if (std::hypot(x, y) > 60 && x * std::cos(heading) + y * std::sin(heading) > 0) ++crossed;
  }
  EXPECT_EQ(crossed, 12) << "every car should have got through the junction in two minutes";
}

// A follower's lane comes from its route, not from asking the map: turning left through the
// crossroads it is on the route's lanes in the route's order (the left-turn connector, not the
// straight-on one that begins at the same point with the same heading), and its s is where it
// projects onto that lane's centre line.
TEST(LaneFollowerTest, KnowsItsLaneFromItsRouteThroughAJunction) {
  std::string text = scenario_text(
      "crossroads",
      kQuietEgo + "turner = Vehicle((\"west_in_1\"->60, , 10), , (\"north_out_1\"->60));\n",
      "turner");
  auto run = simulate_text(text, lasting(60));
  ASSERT_TRUE(run.trace) << run.errors;
  const TraceActor& turner = run.trace->actors[1];
  const RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  std::vector<std::string> visited;
  for (std::size_t i = 0; i < turner.lane.size(); ++i) {
    ASSERT_GE(turner.lane[i], 0) << "sample " << i;
    const Lane& lane = map.lane(static_cast<LaneIndex>(turner.lane[i]));
    if (visited.empty() || visited.back() != lane.id) visited.push_back(lane.id);
    const PolylineProjection on = lane.centre_line.project({turner.x[i], turner.y[i]});
    EXPECT_NEAR(turner.s[i], on.s, 0.02) << lane.id << " sample " << i;
  }
  EXPECT_EQ(visited, (std::vector<std::string>{"west_in_1", "west_north_1", "north_out_1"}));
}

// At a roundabout's entry a follower gives way to a car coming round the ring to where its entry
// joins it, not to one anywhere on the ring: it waited at its yield line while a car 60 m round
// drove away from it, until that car left the ring (corpus seed roundabout_entry, npc2).
TEST(LaneFollowerTest, EntersARoundaboutAheadOfACarFarRoundTheRingAndGivesWayToOneComing) {
  const RoadMap map = build_road_map(generate_builtin_map("roundabout", {}));
  const auto ring = static_cast<std::int32_t>(*map.find_lane("ring_0"));
  const std::string ego = "ego = AV((\"south_in_0\"->10, , 0), (\"south_in_0\"->20));\n";
  // The west entry joins the ring at about s = 68; the circulating car starts at s = 0 (east), 68
  // m and 13.6 s away at 5 m/s, or at s = 48, 4 s away.
  auto entered_at = [&](double ring_start, double* closest) {
    std::string text = scenario_text(
        "roundabout",
        ego + "circling = Vehicle((\"ring_0\"->" + std::to_string(ring_start) +
            ", , 5), , (\"east_out_0\"->50));\n"
            "entering = Vehicle((\"west_in_0\"->80, , 8), , (\"north_out_0\"->80));\n",
        "circling, entering");
    auto run = simulate_text(text, lasting(40));
    EXPECT_TRUE(run.trace) << run.errors;
    if (!run.trace) return -1.0;
    EXPECT_EQ(npc_collisions(*run.trace), 0);
    *closest = closest_approach(*run.trace, 1, 2);
    const TraceActor& entering = run.trace->actors[2];
    for (std::size_t i = 0; i < entering.lane.size(); ++i)
      if (entering.lane[i] == ring) return run.trace->time[i];
    return -1.0;
  };
  double closest = 0;
  const double early = entered_at(0, &closest);
  EXPECT_GE(early, 0) << "it never entered the ring";
  EXPECT_LT(early, 8) << "it waited for a car far round the ring";
  EXPECT_GT(closest, 5);
  const double late = entered_at(48, &closest);
  EXPECT_GT(late, early + 2) << "it did not give way to the car coming round";
  EXPECT_GT(closest, 3);
}

}  // namespace
}  // namespace scenfuzz
