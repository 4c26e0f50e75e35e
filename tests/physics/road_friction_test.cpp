// The road's friction (Environment::road_friction) through the whole simulation: on a road with a
// fifth of dry asphalt's grip the ego and the NPCs, scripted or reactive, never brake harder than
// a fifth of their class's limit, so a stop at the limit takes five times the distance; the
// reference driver knows the road and drives slower and farther back; a friction of 1 is a dry
// road to the last bit; a friction outside (0, 1] is an error that names it.
#include "physics/actors/road_friction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lang/number_format.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/ego/sight_distance.hpp"
#include "physics/trace/trace_export.hpp"
#include "simulation_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::SimulatedRun;

constexpr double kIce = 0.2;
// What a trace's acceleration may exceed a limit by: the integration is exact, so rounding only.
constexpr double kTolerance = 1e-9;

std::string scenario_text(const std::string& map, const std::string& vehicles,
                          const std::string& body) {
  return body + "scenario = CreateScenario{load(\"" + map + "\");\nego;\n{" + vehicles +
         "};\n{};\n{};\n};\n";
}

// As test::simulate_file, with the road's friction set (AVUnit has no words for it), written at
// the file's first line.
SimulatedRun simulate_on_road(const std::string& text, std::optional<double> friction,
                              const SimulationOptions& options = {}) {
  const SourceFile file("inline.avu", text);
  SimulatedRun run;
  avunit::ParseResult parsed = avunit::parse(file);
  run.errors = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok()) return run;
  if (friction) {
    if (!parsed.scenario.environment) parsed.scenario.environment.emplace();
    parsed.scenario.environment->road_friction = constant_value(*friction, {1, 1, 0, 3});
  }
  ParameterSpace space = parameter_space(parsed.scenario);
  std::vector<double> values = decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  RoadMap map = load_scenario_map(parsed.scenario.map, map_search_path({}), values);
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, options.seed, diagnostics);
  run.errors += format_diagnostics(file, diagnostics);
  if (setup) run.trace = simulate(map, *setup, options);
  return run;
}

double hardest_braking(const TraceActor& actor) {
  double hardest = 0;
  for (double a : actor.acceleration) hardest = std::max(hardest, -a);
  return hardest;
}

double hardest_acceleration(const TraceActor& actor) {
  double hardest = 0;
  for (double a : actor.acceleration) hardest = std::max(hardest, a);
  return hardest;
}

// A stop from the step braking began: the speed then and the distance to where it first stood.
struct Stop {
  double speed = NAN;
  double distance = NAN;
};

Stop first_stop(const TraceActor& actor) {
  std::size_t braking = 1;
  while (braking < actor.acceleration.size() && !(actor.acceleration[braking] < 0)) ++braking;
  for (std::size_t i = braking; i < actor.speed.size(); ++i)
    if (actor.speed[i] == 0) return {actor.speed[braking - 1], actor.x[i] - actor.x[braking - 1]};
  return {};
}

// The ego at 15 m/s and a car parked `ahead` metres in front of it in its lane, beyond where it
// stops on this road but within what it looks at while it brakes: told to brake fully whenever it
// closes on something, and perceiving perfectly, it brakes at its limit from the first step to a
// stop.
std::string full_stop_scenario(double ahead) {
  return scenario_text("straight?two_way=0&lanes=1", "parked",
                       "ego = AV((\"east_0\"->20, , 15), (\"east_0\"->480));\n"
                       "parked = Vehicle((\"east_0\"->" +
                           format_number(20 + ahead) + ", , 0));\n");
}

SimulationOptions full_braking_options() {
  SimulationOptions options;
  options.duration = 15;
  options.driver.emergency_time_to_collision = std::numeric_limits<double>::infinity();
  options.perception.miss_probability = 0;  // nothing but the road decides
  options.perception.position_noise = 0;
  options.perception.heading_noise = 0;
  options.perception.speed_noise = 0;
  return options;
}

TEST(RoadFriction, TheEgoStopsInFiveTimesTheDistanceOnAFifthOfTheGrip) {
  const SimulatedRun dry =
      simulate_on_road(full_stop_scenario(40), std::nullopt, full_braking_options());
  const SimulatedRun icy = simulate_on_road(full_stop_scenario(100), kIce, full_braking_options());
  ASSERT_TRUE(dry.trace) << dry.errors;
  ASSERT_TRUE(icy.trace) << icy.errors;
  const double limit = actor_class(ActorCategory::car).max_deceleration;
  const TraceActor& dry_ego = dry.trace->actors[0];
  const TraceActor& icy_ego = icy.trace->actors[0];
  EXPECT_GT(hardest_braking(dry_ego), limit - 1e-6) << "the dry run brakes at the dry limit";
  EXPECT_LE(hardest_braking(icy_ego), kIce * limit + kTolerance);
  EXPECT_GT(hardest_braking(icy_ego), kIce * limit - 1e-6) << "and the icy one at the icy limit";

  const Stop dry_stop = first_stop(dry_ego);
  const Stop icy_stop = first_stop(icy_ego);
  ASSERT_TRUE(std::isfinite(dry_stop.distance) && std::isfinite(icy_stop.distance));
  EXPECT_DOUBLE_EQ(icy_stop.speed, dry_stop.speed) << "both brake from the same speed";
  EXPECT_NEAR(dry_stop.distance, dry_stop.speed * dry_stop.speed / (2 * limit), 0.05);
  EXPECT_NEAR(icy_stop.distance, icy_stop.speed * icy_stop.speed / (2 * kIce * limit), 0.05);
  EXPECT_NEAR(icy_stop.distance / dry_stop.distance, 1 / kIce, 0.05);
  EXPECT_TRUE(icy.trace->collisions.empty()) << "it stops short of the car all the same";
}

// npc1 is scripted through its waypoints: 2 -> 12 m/s over 40 m, then 12 -> 0 over 12 m (6 m/s^2).
// npc2 follows its lane reactively at 15 m/s towards `parked` 40 m ahead (3.2 m/s^2 to stop).
std::string braking_npcs_scenario() {
  return scenario_text(
      "straight", "npc1, npc2, parked",
      "ego = AV((\"west_0\"->10, , 0), (\"west_0\"->200));\n"
      "npc1 = Vehicle((\"east_0\"->100, , 2), Waypoint(((\"east_0\"->140, , 12), (\"east_0\"->152, "
      ", 0))), (\"east_0\"->300));\n"
      "npc2 = Vehicle((\"east_1\"->100, , 15), , (\"east_1\"->450));\n"
      "parked = Vehicle((\"east_1\"->140, , 0));\n");
}

TEST(RoadFriction, NpcsScriptedOrReactiveKeepToTheIcyLimits) {
  SimulationOptions options;
  options.duration = 15;
  const SimulatedRun dry = simulate_on_road(braking_npcs_scenario(), std::nullopt, options);
  const SimulatedRun icy = simulate_on_road(braking_npcs_scenario(), kIce, options);
  ASSERT_TRUE(dry.trace) << dry.errors;
  ASSERT_TRUE(icy.trace) << icy.errors;
  const ActorClass& car = actor_class(ActorCategory::car);
  for (ActorId npc : {1, 2}) {
    EXPECT_GT(hardest_braking(dry.trace->actors[npc]), 3.0)
        << dry.trace->actors[npc].name << " brakes harder than the ice allows on a dry road";
    EXPECT_LE(hardest_braking(icy.trace->actors[npc]), kIce * car.max_deceleration + kTolerance)
        << icy.trace->actors[npc].name;
    EXPECT_LE(hardest_acceleration(icy.trace->actors[npc]),
              kIce * car.max_acceleration + kTolerance)
        << icy.trace->actors[npc].name;
  }
  EXPECT_GT(hardest_acceleration(dry.trace->actors[1]), kIce * car.max_acceleration)
      << "npc1's script asks for more than the ice gives";
  // The script keeps what the ice allows of it: slower at waypoint 1, to stop at waypoint 2.
  EXPECT_NE(icy.errors.find("npc1 cannot keep 12 m/s at its waypoint 1"), std::string::npos)
      << icy.errors;
  EXPECT_NE(icy.errors.find("passes there at 6.1 m/s"), std::string::npos) << icy.errors;
}

TEST(RoadFriction, TheReferenceDriverDrivesSlowerOnIce) {
  // The straight's 22.2 m/s limit: dry, the ego drives up towards it; on ice no faster than it can
  // stop from within what it sees (80 m of pedestrian range) braking at a fifth of its limit.
  const std::string text = scenario_text("straight?length=3000", "",
                                         "ego = AV((\"east_0\"->10, , 0), (\"east_0\"->2990));\n");
  SimulationOptions options;
  options.duration = 120;
  const SimulatedRun dry = simulate_on_road(text, std::nullopt, options);
  const SimulatedRun icy = simulate_on_road(text, kIce, options);
  ASSERT_TRUE(dry.trace) << dry.errors;
  ASSERT_TRUE(icy.trace) << icy.errors;
  const auto fastest = [](const TraceActor& actor) {
    return *std::max_element(actor.speed.begin(), actor.speed.end());
  };
  const ActorClass& car = actor_class(ActorCategory::car);
  const double icy_sight_speed =
      sight_speed(PerceptionSettings{}, car.length / 2, kIce * car.max_deceleration);
  EXPECT_LT(icy_sight_speed, 15.0);
  EXPECT_GT(fastest(dry.trace->actors[0]), 21.0);
  EXPECT_LE(fastest(icy.trace->actors[0]), icy_sight_speed + 1e-9);
  EXPECT_GT(fastest(icy.trace->actors[0]), icy_sight_speed - 1.0) << "it still drives";
}

TEST(RoadFriction, TheReferenceDriverFollowsFartherBackOnIce) {
  // A lead at 8 m/s 50 m ahead: the ego settles behind it at its time gap, which ice lengthens.
  const std::string text = scenario_text("straight?two_way=0&lanes=1", "lead",
                                         "ego = AV((\"east_0\"->10, , 8), (\"east_0\"->490));\n"
                                         "lead = Vehicle((\"east_0\"->60, , 8));\n");
  SimulationOptions options;
  options.duration = 40;
  const SimulatedRun dry = simulate_on_road(text, std::nullopt, options);
  const SimulatedRun icy = simulate_on_road(text, kIce, options);
  ASSERT_TRUE(dry.trace) << dry.errors;
  ASSERT_TRUE(icy.trace) << icy.errors;
  const auto final_gap = [](const Trace& trace) {
    return trace.actors[1].x.back() - trace.actors[0].x.back();
  };
  EXPECT_TRUE(dry.trace->collisions.empty());
  EXPECT_TRUE(icy.trace->collisions.empty());
  EXPECT_LT(final_gap(*dry.trace), 30.0) << "dry, it closes up to about 1.5 s";
  EXPECT_GT(final_gap(*icy.trace), 3 * final_gap(*dry.trace)) << "7.5 s instead of 1.5 s";
}

TEST(RoadFriction, AFrictionOfOneIsADryRoadToTheLastBit) {
  for (const std::string& text : {full_stop_scenario(40), braking_npcs_scenario()}) {
    const SimulatedRun dry = simulate_on_road(text, std::nullopt, full_braking_options());
    const SimulatedRun one = simulate_on_road(text, 1.0, full_braking_options());
    ASSERT_TRUE(dry.trace) << dry.errors;
    ASSERT_TRUE(one.trace) << one.errors;
    EXPECT_EQ(trace_json(*one.trace), trace_json(*dry.trace));
    EXPECT_EQ(trace_csv(*one.trace), trace_csv(*dry.trace));
  }
}

TEST(RoadFriction, AFrictionOutsideZeroToOneIsAnErrorNamingIt) {
  for (double friction : {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity()}) {
    const SimulatedRun run = simulate_on_road(full_stop_scenario(40), friction);
    EXPECT_FALSE(run.trace) << friction;
    EXPECT_NE(run.errors.find("inline.avu:1:1"), std::string::npos) << run.errors;
    EXPECT_NE(run.errors.find("road's friction"), std::string::npos) << run.errors;
    EXPECT_NE(run.errors.find("(0, 1]"), std::string::npos) << run.errors;
  }
}

TEST(RoadFriction, OnlyAVehicleLosesItsGrip) {
  const ActorClass& car = actor_class(ActorCategory::car);
  const ActorClass icy = on_road(car, kIce);
  EXPECT_DOUBLE_EQ(icy.max_deceleration, kIce * car.max_deceleration);
  EXPECT_DOUBLE_EQ(icy.max_acceleration, kIce * car.max_acceleration);
  EXPECT_DOUBLE_EQ(icy.comfortable_deceleration, kIce * car.comfortable_deceleration);
  EXPECT_DOUBLE_EQ(icy.comfortable_lateral_acceleration,
                   kIce * car.comfortable_lateral_acceleration);
  EXPECT_EQ(icy.max_speed, car.max_speed);
  EXPECT_EQ(icy.max_steering_angle, car.max_steering_angle);
  const ActorClass& walker = actor_class(ActorCategory::pedestrian);
  EXPECT_EQ(on_road(walker, kIce).max_deceleration, walker.max_deceleration);
  EXPECT_EQ(on_road(walker, kIce).max_acceleration, walker.max_acceleration);
}

}  // namespace
}  // namespace scenfuzz
