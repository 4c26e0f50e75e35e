// Vehicle signals through whole simulations: the reference driver indicates before a lane change,
// an overtaking manoeuvre and a turn and not on a straight drive, uses its lights as the time of
// day and the weather ask, dips its high beam for an oncoming car and shows brake lights; lane
// following NPCs and waypoint NPCs indicate before their lane changes and turns (and a waypoint
// NPC driving straight never does, a pedestrian has no lamps); a version 1 plugin still runs
// with its signals off, and a version 2 plugin's signals reach the trace and it is told the
// signals of the vehicles it perceives.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "physics/ego/route_indications.hpp"
#include "simulation_fixtures.hpp"

#if !defined(SCENFUZZ_TEST_PLUGIN_DIR)
#error "tests/CMakeLists.txt passes the plugins' paths"
#endif

namespace scenfuzz {
namespace {

namespace sig = vehicle_signal;
using test::simulate_text;

std::string scenario(const std::string& map, const std::string& npcs, const std::string& body,
                     const std::string& environment = "") {
  return body + (environment.empty() ? "" : "env = Environment(" + environment + ");\n") +
         "scenario = CreateScenario{load(\"" + map + "\");\nego;\n{" + npcs + "};\n{};\n{};\n" +
         (environment.empty() ? "" : "env;\n") + "};\n";
}

Trace run(const std::string& text, double seconds, const std::string& plugin = "") {
  SimulationOptions options;
  options.duration = seconds;
  options.ego_plugin = plugin;
  auto simulated = simulate_text(text, options);
  EXPECT_TRUE(simulated.trace) << simulated.errors;
  return simulated.trace ? *simulated.trace : Trace{};
}

bool on(const TraceActor& actor, std::size_t i, VehicleSignals signal) {
  return signal_on(actor.signals, i, signal);
}

// The first sample at which `signal` is on, or nullopt.
std::optional<std::size_t> first_on(const TraceActor& actor, VehicleSignals signal) {
  for (std::size_t i = 0; i < actor.signals.size(); ++i)
    if (on(actor, i, signal)) return i;
  return std::nullopt;
}

bool ever_on(const TraceActor& actor, VehicleSignals signal) {
  return first_on(actor, signal).has_value();
}

// The first sample at which the actor's y has moved more than `by` from where it started.
std::optional<std::size_t> first_moved_sideways(const TraceActor& actor, double by) {
  for (std::size_t i = 0; i < actor.y.size(); ++i)
    if (std::abs(actor.y[i] - actor.y[0]) > by) return i;
  return std::nullopt;
}

void expect_column_complete(const Trace& trace) {
  for (const TraceActor& actor : trace.actors) {
    if (actor.kind == TraceActorKind::ego || actor.kind == TraceActorKind::vehicle)
      EXPECT_EQ(actor.signals.size(), trace.sample_count()) << actor.name;
    else
      EXPECT_TRUE(actor.signals.empty()) << actor.name;
  }
}

// straight?two_way=0: east_0 at y = -5.25, east_1 at y = -1.75. The ego's route changes lane
// 40 m after its start (kLaneChangePreparation), within its notice from the start: it indicates
// from its first decision (sample 0), before it moves over.
TEST(VehicleSignalsTest, TheEgoIndicatesLeftBeforeItsLaneChangeUntilItEnds) {
  const Trace trace = run(
      scenario("straight?two_way=0", "", "ego = AV((\"east_0\"->20, , 10), (\"east_1\"->300));\n"),
      60);
  expect_column_complete(trace);
  const TraceActor& ego = trace.actors[0];
  const auto indicating = first_on(ego, sig::left_indicator);
  const auto moving = first_moved_sideways(ego, 0.1);
  ASSERT_TRUE(indicating);
  ASSERT_TRUE(moving);
  EXPECT_EQ(*indicating, 0u);
  EXPECT_LT(*indicating, *moving);
  EXPECT_FALSE(ever_on(ego, sig::right_indicator));
  EXPECT_FALSE(on(ego, trace.sample_count() - 1, sig::left_indicator)) << "ended with the change";
  // Still on until the ego is most of the way over.
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (ego.y[i] > -5.0 && ego.y[i] < -2.5) {
      ASSERT_TRUE(on(ego, i, sig::left_indicator)) << i;
    }
}

TEST(VehicleSignalsTest, TheEgoDoesNotIndicateOnAStraightDrive) {
  const Trace trace = run(
      scenario("straight?two_way=0", "", "ego = AV((\"east_0\"->20, , 10), (\"east_0\"->300));\n"),
      40);
  const TraceActor& ego = trace.actors[0];
  ASSERT_EQ(ego.signals.size(), trace.sample_count());
  EXPECT_FALSE(ever_on(ego, sig::left_indicator | sig::right_indicator | sig::hazard_lights |
                                sig::horn | sig::low_beam | sig::high_beam | sig::fog_lights |
                                sig::wipers));
}

TEST(VehicleSignalsTest, TheEgoIndicatesOutAndBackWhenItOvertakes) {
  const Trace trace = run(scenario("straight?two_way=0", "parked",
                                   "ego = AV((\"east_0\"->20, , 15), (\"east_0\"->400));\n"
                                   "parked = Vehicle((\"east_0\"->150, , 0));\n"),
                          60);
  const TraceActor& ego = trace.actors[0];
  const auto out = first_on(ego, sig::left_indicator);
  const auto back = first_on(ego, sig::right_indicator);
  ASSERT_TRUE(out);
  ASSERT_TRUE(back);
  EXPECT_LT(*out, *back);
  const auto moving = first_moved_sideways(ego, 0.1);
  ASSERT_TRUE(moving);
  EXPECT_LE(*out, *moving) << "on before it moves over";
  EXPECT_GT(ego.y[*back], -2.5) << "the move back starts from the passing lane";
  EXPECT_FALSE(on(ego, trace.sample_count() - 1, sig::left_indicator | sig::right_indicator));
}

// crossroads?lanes=1: north-south has green first; south_in_0 runs north at x = 1.75 up to the
// junction, whose one-lane arms begin at y = -10. Turning left leads west, right leads east.
void expect_turn_indicated(const std::string& target, VehicleSignals indicator,
                           VehicleSignals other) {
  const Trace trace =
      run(scenario("crossroads?lanes=1", "",
                   "ego = AV((\"south_in_0\"->20, , 8), (\"" + target + "\"->60));\n"),
          50);
  const TraceActor& ego = trace.actors[0];
  EXPECT_EQ(trace.end, EndReason::target_reached);
  const auto first = first_on(ego, indicator);
  ASSERT_TRUE(first);
  EXPECT_FALSE(on(ego, 0, indicator)) << "130 m before the junction is too early";
  // From kTurnNotice before the junction's entry: where the oracle's `direction` (100 m from the
  // front bumper) asks law57's indicator.
  constexpr double kEntry = -10;
  EXPECT_LE(ego.y[*first], kEntry - (100 + ego.length / 2));
  EXPECT_GE(ego.y[*first], kEntry - kTurnNotice - 1);
  EXPECT_FALSE(ever_on(ego, other));
  EXPECT_FALSE(on(ego, trace.sample_count() - 1, indicator)) << "off once the turn is done";
}

TEST(VehicleSignalsTest, TheEgoIndicatesBeforeALeftTurnAtAJunction) {
  expect_turn_indicated("west_out_0", sig::left_indicator, sig::right_indicator);
}

TEST(VehicleSignalsTest, TheEgoIndicatesBeforeARightTurnAtAJunction) {
  expect_turn_indicated("east_out_0", sig::right_indicator, sig::left_indicator);
}

TEST(VehicleSignalsTest, TheEgoGoingStraightThroughAJunctionDoesNotIndicate) {
  const Trace trace = run(scenario("crossroads?lanes=1", "",
                                   "ego = AV((\"south_in_0\"->60, , 8), (\"north_out_0\"->60));\n"),
                          40);
  EXPECT_FALSE(ever_on(trace.actors[0], sig::left_indicator | sig::right_indicator));
}

const std::string kOpenRoad = "ego = AV((\"east_0\"->20, , 10), (\"east_0\"->300));\n";

TEST(VehicleSignalsTest, LowBeamsAtNightNotAtNoonAndTheHighBeamOnAnEmptyRoad) {
  const Trace night = run(scenario("straight?two_way=0", "", kOpenRoad, "23:00"), 10);
  const Trace noon = run(scenario("straight?two_way=0", "", kOpenRoad, "12:00"), 10);
  for (std::size_t i = 0; i < night.sample_count(); ++i)
    ASSERT_TRUE(on(night.actors[0], i, sig::low_beam)) << i;
  EXPECT_TRUE(on(night.actors[0], night.sample_count() - 1, sig::high_beam));
  EXPECT_FALSE(ever_on(noon.actors[0], sig::low_beam | sig::high_beam));
}

TEST(VehicleSignalsTest, FogLightsInFogWipersInRain) {
  const Trace fog = run(scenario("straight?two_way=0", "", kOpenRoad, "12:00, {fog: 0.8}"), 5);
  const Trace rain = run(scenario("straight?two_way=0", "", kOpenRoad, "12:00, {rain: 0.5}"), 5);
  const std::size_t last = fog.sample_count() - 1;
  EXPECT_TRUE(on(fog.actors[0], last, sig::fog_lights));
  EXPECT_TRUE(on(fog.actors[0], last, sig::low_beam));
  EXPECT_FALSE(on(fog.actors[0], last, sig::wipers));
  EXPECT_TRUE(on(rain.actors[0], last, sig::wipers));
  EXPECT_FALSE(ever_on(rain.actors[0], sig::fog_lights));
}

// Two-way straight road: west_0 runs west beside east_0.
TEST(VehicleSignalsTest, TheHighBeamIsDippedForAnOncomingCar) {
  const Trace trace =
      run(scenario("straight", "car",
                   "ego = AV((\"east_0\"->20, , 10), (\"east_0\"->450));\n"
                   "car = Vehicle((\"west_0\"->100, , 10), uniform((\"west_0\"->100, , 10)), "
                   "(\"west_0\"->499));\n",
                   "23:00"),
          30);
  const TraceActor& ego = trace.actors[0];
  const TraceActor& car = trace.actors[1];
  bool dipped = false, full = false;
  for (std::size_t i = 1; i < trace.sample_count(); ++i) {
    const double ahead = car.x[i] - ego.x[i];
    // Within 60 m perception at night misses it too rarely to let the beam flick up.
    if (ahead > 5 && ahead < 60) {
      ASSERT_FALSE(on(ego, i, sig::high_beam)) << "at " << trace.time[i] << " s";
      dipped = true;
    }
    if (ahead < -20) {
      EXPECT_TRUE(on(ego, i, sig::high_beam)) << "passed at " << trace.time[i] << " s";
      full = true;
    }
    ASSERT_TRUE(on(ego, i, sig::low_beam));
  }
  EXPECT_TRUE(dipped);
  EXPECT_TRUE(full);
  EXPECT_TRUE(ever_on(car, sig::low_beam)) << "the NPC has its lights on too";
}

TEST(VehicleSignalsTest, BrakeLightsWhileTheEgoBrakesAndStands) {
  const Trace trace = run(scenario("straight?two_way=0&lanes=1", "parked",
                                   "ego = AV((\"east_0\"->20, , 20), (\"east_0\"->480));\n"
                                   "parked = Vehicle((\"east_0\"->250, , 0));\n"),
                          30);
  const TraceActor& ego = trace.actors[0];
  bool braked = false;
  for (std::size_t i = 1; i < trace.sample_count(); ++i) {
    // The acceleration recorded at i is what the driver chose at i - 1 (or less, stopping).
    if (ego.acceleration[i] < -0.5) {
      ASSERT_TRUE(on(ego, i - 1, sig::brake_lights)) << "at " << trace.time[i - 1] << " s";
      braked = true;
    }
  }
  EXPECT_TRUE(braked);
  EXPECT_TRUE(on(ego, trace.sample_count() - 1, sig::brake_lights)) << "held standing";
  EXPECT_FALSE(on(ego, 1, sig::brake_lights)) << "cruising at first";
}

// The NPC's route changes lane where it starts (find_route does): it indicates from its start.
TEST(VehicleSignalsTest, ALaneFollowingNpcIndicatesThroughItsLaneChange) {
  const Trace trace =
      run(scenario("straight?two_way=0", "npc",
                   "ego = AV((\"east_0\"->5, , 0), (\"east_0\"->480));\n"
                   "npc = Vehicle((\"east_0\"->40, , 10), uniform((\"east_0\"->40, , 10)), "
                   "(\"east_1\"->400));\n"),
          30);
  expect_column_complete(trace);
  const TraceActor& npc = trace.actors[1];
  const auto indicating = first_on(npc, sig::left_indicator);
  const auto moving = first_moved_sideways(npc, 0.1);
  ASSERT_TRUE(indicating);
  ASSERT_TRUE(moving);
  EXPECT_LE(*indicating, *moving);
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (npc.y[i] > -5.0 && npc.y[i] < -2.0) {
      ASSERT_TRUE(on(npc, i, sig::left_indicator)) << i;
    }
  EXPECT_FALSE(ever_on(npc, sig::right_indicator));
  EXPECT_FALSE(on(npc, trace.sample_count() - 1, sig::left_indicator));
}

TEST(VehicleSignalsTest, ALaneFollowingNpcIndicatesBeforeItsTurnAndShowsBrakeLights) {
  const Trace trace =
      run(scenario("crossroads?lanes=1", "npc",
                   "ego = AV((\"east_in_0\"->100, , 0), (\"west_out_0\"->100));\n"
                   "npc = Vehicle((\"south_in_0\"->60, , 8), uniform((\"south_in_0\"->60, , 8)), "
                   "(\"west_out_0\"->60));\n"),
          25);
  const TraceActor& npc = trace.actors[1];
  const auto first = first_on(npc, sig::left_indicator);
  ASSERT_TRUE(first);
  EXPECT_LT(npc.y[*first], -20.0);
  EXPECT_FALSE(ever_on(npc, sig::right_indicator));
  EXPECT_FALSE(on(npc, trace.sample_count() - 1, sig::left_indicator));
  EXPECT_TRUE(ever_on(npc, sig::brake_lights)) << "it slows for the bend";
}

// A waypoint NPC on straight?two_way=0 from east_0 (y = -5.25) or east_1 (y = -1.75) at 40 m,
// 10 m/s, through a waypoint in the other lane at 160 m: its lane leg moves over in the 30 m
// before (3 s at 10 m/s), from x = 130, so the indicator goes on 30 m (3 s) before that.
void expect_waypoint_lane_change_indicated(const std::string& from, const std::string& to,
                                           VehicleSignals indicator, VehicleSignals other) {
  const Trace trace = run(scenario("straight?two_way=0", "npc",
                                   "ego = AV((\"east_0\"->5, , 0), (\"east_0\"->480));\n"
                                   "npc = Vehicle((\"" +
                                       from + "\"->40, , 10), Waypoint(((\"" + to +
                                       "\"->160, , 10))), (\"" + to + "\"->300));\n"),
                          30);
  expect_column_complete(trace);
  const TraceActor& npc = trace.actors[1];
  const auto indicating = first_on(npc, indicator);
  const auto moving = first_moved_sideways(npc, 0.1);
  const auto crossing = first_moved_sideways(npc, 1.75);  // its centre on the lane line
  ASSERT_TRUE(indicating);
  ASSERT_TRUE(moving);
  ASSERT_TRUE(crossing);
  EXPECT_LT(*indicating, *crossing);
  EXPECT_LT(*indicating, *moving);
  // The notice: 3 s or 30 m before the move begins (at 10 m/s both), give or take where the
  // path is seen to begin moving sideways.
  EXPECT_NEAR(npc.x[*moving] - npc.x[*indicating], 30.0, 4.0);
  for (std::size_t i = *indicating; i <= *crossing; ++i) ASSERT_TRUE(on(npc, i, indicator)) << i;
  EXPECT_FALSE(ever_on(npc, other));
  EXPECT_FALSE(on(npc, trace.sample_count() - 1, indicator)) << "off once it is over";
}

TEST(VehicleSignalsTest, AWaypointNpcIndicatesLeftBeforeItsLaneChange) {
  expect_waypoint_lane_change_indicated("east_0", "east_1", sig::left_indicator,
                                        sig::right_indicator);
}

TEST(VehicleSignalsTest, AWaypointNpcIndicatesRightBeforeItsLaneChange) {
  expect_waypoint_lane_change_indicated("east_1", "east_0", sig::right_indicator,
                                        sig::left_indicator);
}

TEST(VehicleSignalsTest, AWaypointNpcDrivingStraightNeverIndicates) {
  const Trace trace = run(scenario("straight?two_way=0", "npc",
                                   "ego = AV((\"east_0\"->5, , 0), (\"east_0\"->480));\n"
                                   "npc = Vehicle((\"east_1\"->40, , 10), Waypoint(((\"east_1\""
                                   "->160, , 10))), (\"east_1\"->300));\n"),
                          30);
  const TraceActor& npc = trace.actors[1];
  ASSERT_GT(npc.x.back() - npc.x.front(), 200.0) << "it drove";
  EXPECT_FALSE(ever_on(npc, sig::left_indicator | sig::right_indicator));
}

// crossroads?lanes=1 (as for the ego above): from south_in_0 at 20 m, 130 m before the junction,
// through a waypoint on the arm it turns into or crosses to.
Trace waypoint_junction_run(const std::string& arm) {
  Trace trace = run(scenario("crossroads?lanes=1", "npc",
                             "ego = AV((\"east_in_0\"->100, , 0), (\"west_out_0\"->100));\n"
                             "npc = Vehicle((\"south_in_0\"->20, , 8), Waypoint(((\"" +
                                 arm + "\"->30, , 8))), (\"" + arm + "\"->60));\n"),
                    30);
  expect_column_complete(trace);
  return trace;
}

TEST(VehicleSignalsTest, AWaypointNpcIndicatesLeftBeforeItsLeftTurnAtAJunction) {
  const Trace trace = waypoint_junction_run("west_out_0");
  const TraceActor& npc = trace.actors[1];
  const auto first = first_on(npc, sig::left_indicator);
  ASSERT_TRUE(first);
  constexpr double kEntry = -10;
  EXPECT_FALSE(on(npc, 0, sig::left_indicator)) << "130 m before the junction is too early";
  EXPECT_LE(npc.y[*first], kEntry - 100) << "the ego's rule: kTurnNotice before the entry";
  EXPECT_GE(npc.y[*first], kEntry - kTurnNotice - 1);
  for (std::size_t i = *first; i < trace.sample_count() && npc.y[i] < kEntry; ++i)
    ASSERT_TRUE(on(npc, i, sig::left_indicator)) << i;
  EXPECT_LT(npc.x.back(), -20.0) << "it turned west";
  EXPECT_FALSE(ever_on(npc, sig::right_indicator));
  EXPECT_FALSE(on(npc, trace.sample_count() - 1, sig::left_indicator)) << "off once turned";
}

TEST(VehicleSignalsTest, AWaypointNpcGoingStraightThroughAJunctionNeverIndicates) {
  const Trace trace = waypoint_junction_run("north_out_0");
  const TraceActor& npc = trace.actors[1];
  EXPECT_GT(npc.y.back(), 20.0) << "it went through";
  EXPECT_FALSE(ever_on(npc, sig::left_indicator | sig::right_indicator));
}

// A pedestrian has no lamps: its signals column stays empty, whatever its path crosses.
TEST(VehicleSignalsTest, AWaypointPedestrianCrossingLanesHasNoSignals) {
  const Trace trace =
      run("ego = AV((\"east_0\"->5, , 0), (\"east_0\"->480));\n"
          "ped = Pedestrian((\"east_0\"->100, , 1.4), Waypoint(((\"east_1\"->104, , 1.4))), "
          "(\"east_1\"->110));\n"
          "scenario = CreateScenario{load(\"straight?two_way=0\");\nego;\n{};\n{ped};\n{};\n};\n",
          10);
  expect_column_complete(trace);
  EXPECT_TRUE(trace.actors[1].signals.empty());
}

std::string test_plugin(const std::string& name) {
  return std::string(SCENFUZZ_TEST_PLUGIN_DIR) + "/lib" + name + ".so";
}

TEST(VehicleSignalsTest, AVersion1PluginStillRunsAndItsSignalsReadOff) {
  const Trace trace = run(scenario("straight?two_way=0", "", kOpenRoad, "23:00, {rain: 0.5}"), 5,
                          test_plugin("version1"));
  EXPECT_FALSE(trace.ego_failure) << trace.ego_failure->reason;
  EXPECT_EQ(trace.end, EndReason::duration);
  const TraceActor& ego = trace.actors[0];
  ASSERT_EQ(ego.signals.size(), trace.sample_count());
  for (std::size_t i = 0; i < trace.sample_count(); ++i) ASSERT_EQ(ego.signals[i], 0) << i;
}

// npc drives ahead of the ego at night with its low beams on; the plugin shows hazard lights
// while it perceives a vehicle with its low beams on.
std::string night_follow(const std::string& time) {
  return scenario("straight?two_way=0", "npc",
                  "ego = AV((\"east_0\"->20, , 5), (\"east_0\"->400));\n"
                  "npc = Vehicle((\"east_0\"->50, , 12), uniform((\"east_0\"->50, , 12)), "
                  "(\"east_0\"->499));\n",
                  time);
}

TEST(VehicleSignalsTest, AVersion2PluginsSignalsReachTheTraceAndItSeesOthersLights) {
  const Trace night = run(night_follow("23:00"), 5, test_plugin("signalling"));
  EXPECT_FALSE(night.ego_failure) << night.ego_failure->reason;
  const TraceActor& ego = night.actors[0];
  const std::size_t last = night.sample_count() - 1;
  EXPECT_TRUE(on(ego, last, sig::left_indicator));
  EXPECT_TRUE(on(ego, last, sig::wipers));
  EXPECT_TRUE(on(ego, last, sig::hazard_lights)) << "the NPC's low beams were in the observation";
  EXPECT_FALSE(on(ego, last, sig::brake_lights)) << "it accelerates";

  const Trace day = run(night_follow("12:00"), 5, test_plugin("signalling"));
  EXPECT_FALSE(ever_on(day.actors[0], sig::hazard_lights));
  EXPECT_TRUE(on(day.actors[0], day.sample_count() - 1, sig::left_indicator));
}

}  // namespace
}  // namespace scenfuzz
