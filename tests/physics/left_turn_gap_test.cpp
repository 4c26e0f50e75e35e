// The reference driver's left turn across oncoming traffic on the built-in crossroads, whose
// north-south lights are green from 0 to 25 s (the ego in south_in_1 and the oncoming traffic in
// north_in_* both have a permissive green): the ego waits for an oncoming car that would reach
// the conflict area within the critical gap and turns behind it, turns at once when the oncoming
// car is far, and does not stop inside the oncoming lanes once it has gone; and the gap rule
// itself (left_turn_gap.hpp) on perceived objects.
#include "physics/ego/left_turn_gap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::closest_approach;
using test::simulate_text;

// The ego turns left from south_in_1 (heading north at x = 1.75) through south_west_1 into
// west_out_1; `npcs` are the vehicle statements of actors named npc1, npc2...
test::SimulatedRun turn_left_with(const std::string& npc_statements, const std::string& npcs) {
  SimulationOptions options;
  options.duration = 40;
  return simulate_text(
      "ego = AV((\"south_in_1\"->100, , 8), (\"west_out_1\"->40));\n" + npc_statements +
          "scenario = CreateScenario{load(\"crossroads\");\nego;\n{" + npcs + "};\n{};\n{};\n};\n",
      options);
}

// The ego's body reaches into the oncoming (west) half of the north arm's carriageway, x < 0, in
// the junction box or the crosswalk before it (y > -16): it is in the oncoming lanes' path.
bool in_oncoming_half(const TraceActor& ego, std::size_t i) {
  const double c = std::cos(ego.heading[i]), s = std::sin(ego.heading[i]);
  double least_x = ego.x[i];
  for (double along : {-ego.length / 2, ego.length / 2})
    for (double across : {-ego.width / 2, ego.width / 2})
      least_x = std::min(least_x, ego.x[i] + along * c - across * s);
  return least_x < 0 && ego.x[i] > -14 && ego.y[i] > -16 && ego.y[i] < 12;
}

// Every sample at which the ego stands (under 0.5 m/s) in the oncoming half.
std::vector<double> standing_in_oncoming_half(const Trace& trace) {
  std::vector<double> times;
  const TraceActor& ego = trace.actors[0];
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (in_oncoming_half(ego, i) && ego.speed[i] < 0.5) times.push_back(trace.time[i]);
  return times;
}

// The first sample at which the ego is in the oncoming half (the sample count if never).
std::size_t first_in_oncoming_half(const Trace& trace) {
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (in_oncoming_half(trace.actors[0], i)) return i;
  return trace.sample_count();
}

// An oncoming car going straight on in the inner lane (north_in_1 -> north_south_1 ->
// south_out_1) at 10 m/s, timed to cross the ego's turn just as the ego gets there.
TEST(LeftTurnGapTest, WaitsForAnOncomingCarWithinTheGapAndTurnsBehindIt) {
  auto run = turn_left_with(
      "npc1 = Vehicle((\"north_in_1\"->90, , 10), , (\"south_out_1\"->60));\n", "npc1");
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  EXPECT_GT(closest_approach(trace, 0, 1), 0.5);
  const std::size_t entered = first_in_oncoming_half(trace);
  ASSERT_LT(entered, trace.sample_count()) << "the ego never turned";
  const TraceActor& npc = trace.actors[1];
  // Behind it: the oncoming car's rear had passed the ego's turn (y = -1.6 at x = -1.75) by then.
  EXPECT_LT(npc.y[entered] + npc.length / 2, -4.0)
      << "the ego entered the oncoming lanes at " << trace.time[entered]
      << " s with the oncoming car at y = " << npc.y[entered];
  EXPECT_TRUE(standing_in_oncoming_half(trace).empty());
}

// The same car 150 m farther away: it reaches the junction some 20 s later, so the ego turns
// without waiting (it slows for the bend only, to the bend's 4.8 m/s).
TEST(LeftTurnGapTest, TurnsWithoutWaitingWhenTheOncomingCarIsFar) {
  auto run = turn_left_with("npc1 = Vehicle((\"north_in_1\"->0, , 8), , (\"south_out_1\"->60));\n",
                            "npc1");
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const TraceActor& ego = trace.actors[0];
  double slowest = INFINITY;  // until it is out of the junction (it stops at its target after)
  for (std::size_t i = 0; i < trace.sample_count() && ego.x[i] > -12; ++i)
    slowest = std::min(slowest, ego.speed[i]);
  EXPECT_GT(slowest, 3.0);
}

// The ego is already entering the junction at 5 m/s, too close to stop short of the oncoming
// lanes, as an oncoming car at 13 m/s comes within 15 m of the junction: committed, the ego
// clears the oncoming lanes (the car passes behind it) instead of stopping in the car's path, as
// it used to when the car came towards its path.
TEST(LeftTurnGapTest, DoesNotStopInsideTheOncomingLanesOnceCommitted) {
  SimulationOptions options;
  options.duration = 40;
  auto run = simulate_text(
      "ego = AV((\"south_in_1\"->149, , 5), (\"west_out_1\"->40));\n"
      "npc1 = Vehicle((\"north_in_1\"->135, , 13), , (\"south_out_1\"->60));\n"
      "scenario = CreateScenario{load(\"crossroads\");\nego;\n{npc1};\n{};\n{};\n};\n",
      options);
  ASSERT_TRUE(run.trace) << run.errors;
  const Trace& trace = *run.trace;
  const std::vector<double> standing = standing_in_oncoming_half(trace);
  EXPECT_TRUE(standing.empty()) << "the ego stood in the oncoming lanes from " << standing.front()
                                << " s";
  EXPECT_TRUE(trace.collisions.empty());
  EXPECT_EQ(trace.end, EndReason::target_reached);
}

// The rule itself, on the crossroads' route from south_in_1 left into west_out_1.
struct LeftTurnFixture {
  RoadMap map = load_map("crossroads", MapSearchPath{});
  LaneRoute route = *find_route(map, LanePosition{*map.find_lane("south_in_1"), 100, 0},
                                LanePosition{*map.find_lane("west_out_1"), 40, 0});
  RouteTracker tracker{map, route, {}, 13.9};
  const ActorClass& car = actor_class(ActorCategory::car);

  // A car heading south on north_in_1 (x = -1.75), `metres` before its end (y = 10).
  WorldObject oncoming(double metres, double speed) const {
    WorldObject car_ahead;
    car_ahead.id = 1;
    car_ahead.x = -1.75;
    car_ahead.y = 10 + metres;
    car_ahead.heading = -std::numbers::pi / 2;
    car_ahead.speed = speed;
    car_ahead.length = 4.7;
    car_ahead.width = 2.0;
    return car_ahead;
  }
};

std::vector<std::string> conflict_lanes(const RoadMap& map, const LeftTurn& turn) {
  std::vector<std::string> ids;
  for (const OncomingConflict& conflict : turn.conflicts) ids.push_back(map.lane(conflict.lane).id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

TEST(LeftTurnGapRuleTest, FindsTheOncomingStraightLanesTheLeftTurnCrosses) {
  LeftTurnFixture f;
  std::vector<LeftTurn> turns = find_left_turns(f.map, f.tracker, f.car);
  ASSERT_EQ(turns.size(), 1u);
  EXPECT_EQ(conflict_lanes(f.map, turns[0]),
            (std::vector<std::string>{"north_south_0", "north_south_1"}));
  // The ego waits with its centre about at the junction's edge (south_in_1 ends at s = 150).
  EXPECT_NEAR(turns[0].wait, 150 - 100, 3.0);
  for (const OncomingConflict& conflict : turns[0].conflicts) {
    EXPECT_LT(conflict.ego_enter, conflict.ego_exit);
    EXPECT_LT(conflict.lane_enter, conflict.lane_exit);
  }
  // Going straight on, or turning right, crosses no oncoming lane.
  LaneRoute straight = *find_route(f.map, LanePosition{*f.map.find_lane("south_in_1"), 100, 0},
                                   LanePosition{*f.map.find_lane("north_out_1"), 40, 0});
  RouteTracker straight_on(f.map, straight, {}, 13.9);
  EXPECT_TRUE(find_left_turns(f.map, straight_on, f.car).empty());
  LaneRoute right = *find_route(f.map, LanePosition{*f.map.find_lane("south_in_0"), 100, 0},
                                LanePosition{*f.map.find_lane("east_out_0"), 40, 0});
  RouteTracker turning_right(f.map, right, {}, 13.9);
  EXPECT_TRUE(find_left_turns(f.map, turning_right, f.car).empty());
}

TEST(LeftTurnGapRuleTest, WaitsWhileAnOncomingCarWouldArriveWithinTheGap) {
  LeftTurnFixture f;
  LeftTurnGap gap(f.map, f.tracker, f.car);
  // The ego stands 1 m short of where it waits, as the driver stops.
  const double stand = gap.turns().at(0).wait - 1;
  for (double s = 0; s < stand; s += 2) f.tracker.update(f.tracker.path().point_at(s));
  const MapPoint at = f.tracker.path().point_at(stand);
  f.tracker.update(at);
  ASSERT_NEAR(f.tracker.progress(), stand, 0.01);
  KinematicState ego;
  ego.x = at.x;
  ego.y = at.y;
  ego.heading = f.tracker.heading_at(stand);
  // 40 m away at 10 m/s: some 5 s, within the critical gap.
  std::vector<WorldObject> near{f.oncoming(40, 10)};
  GapDecision wait = gap.decide(ego, near, {}, 13.9, f.car.max_deceleration);
  EXPECT_TRUE(wait.wait_gap);
  EXPECT_FALSE(wait.committed);
  // 140 m away at 10 m/s: the ego clears both oncoming lanes long before it arrives.
  std::vector<WorldObject> far{f.oncoming(140, 10)};
  GapDecision go = gap.decide(ego, far, {}, 13.9, f.car.max_deceleration);
  EXPECT_FALSE(go.wait_gap);
  // Standing at its stop line (6 m before the junction) it is not coming; one that has passed
  // the ego's path (its rear at y = -12) is gone.
  std::vector<WorldObject> standing{f.oncoming(6, 0)};
  EXPECT_FALSE(gap.decide(ego, standing, {}, 13.9, f.car.max_deceleration).wait_gap);
  std::vector<WorldObject> gone{f.oncoming(-24, 10)};
  EXPECT_FALSE(gap.decide(ego, gone, {}, 13.9, f.car.max_deceleration).wait_gap);
  EXPECT_TRUE(gap.is_oncoming(near[0]));
}

TEST(LeftTurnGapRuleTest, TheTimeToArriveIsThePerceivedDistanceToTheAreaOverTheSpeed) {
  LeftTurnFixture f;
  LeftTurnGap gap(f.map, f.tracker, f.car);
  const OncomingConflict* inner = nullptr;
  for (const OncomingConflict& conflict : gap.turns().at(0).conflicts)
    if (f.map.lane(conflict.lane).id == "north_south_1") inner = &conflict;
  ASSERT_TRUE(inner);
  // 50 m before north_in_1's end: its front is 50 - 2.35 m from north_south_1's start.
  double expected = (50 - 4.7 / 2 + inner->lane_enter) / 10;
  EXPECT_NEAR(gap.time_to_arrive(*inner, f.oncoming(50, 10)), expected, 1e-6);
  EXPECT_EQ(gap.time_to_arrive(*inner, f.oncoming(50, 0)), INFINITY);
  WorldObject walker = f.oncoming(50, 1);
  walker.kind = TraceActorKind::pedestrian;
  EXPECT_EQ(gap.time_to_arrive(*inner, walker), INFINITY);
}

}  // namespace
}  // namespace scenfuzz
