// Junction gridlock: vehicles arriving at an unsignalled junction at once from every arm, some
// turning left across the others, must all get through (nobody stands in the box waiting on
// someone who waits on it), without touching; and LawBreaker's own AVUnit sample of five NPCs
// and the ego crossing one san_francisco junction lets the ego reach its target.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lang/avunit/avunit.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"
#include "simulation_fixtures.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

// The built-in crossroads without its signals: every arm may always go, as at a junction whose
// lights all show green (or that has none), so that only the give-way rules order the traffic.
RoadMap unsignalled_crossroads() {
  MapDescription description = generate_builtin_map("crossroads", {});
  description.traffic_lights.clear();
  return build_road_map(std::move(description));
}

std::optional<Trace> simulate_on(const RoadMap& map, const std::string& text,
                                 SimulationOptions options, std::string& errors) {
  SourceFile file("inline.avu", text);
  avunit::ParseResult parsed = avunit::parse(file);
  errors = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok()) return std::nullopt;
  ParameterSpace space = parameter_space(parsed.scenario);
  std::vector<double> values = decode(space, std::vector<double>(space.dimensions.size(), 0.5));
  Diagnostics diagnostics;
  auto setup = prepare_simulation(parsed.scenario, values, map, options.seed, diagnostics);
  errors += format_diagnostics(file, diagnostics);
  if (!setup) return std::nullopt;
  return simulate(map, *setup, options);
}

std::string scenario(const std::string& ego, const std::string& npcs, const std::string& names) {
  return ego + npcs + "scenario = CreateScenario{load(\"crossroads\");\nego;\n{" + names +
         "};\n{};\n{};\n};\n";
}

// Out of the junction on an outbound lane, heading away from its centre at (0, 0).
bool cleared(const Trace& trace, ActorId k) {
  const TraceActor& car = trace.actors[k];
  double x = car.x.back(), y = car.y.back(), heading = car.heading.back();
  return std::hypot(x, y) > 30 && x * std::cos(heading) + y * std::sin(heading) > 0;
}

// One car on each arm's inbound lane, all as far from the box and as fast, so that they reach it
// together, and every one turns left across the others (a pinwheel). Without a rule for who goes
// first, they all drive in and stand in the box, each in another's way, until the run ends.
const std::string kFourArms =
    "north = Vehicle((\"north_in_0\"->100, , 8), , (\"east_out_0\"->60));\n"
    "east = Vehicle((\"east_in_0\"->100, , 8), , (\"south_out_0\"->60));\n"
    "south = Vehicle((\"south_in_0\"->100, , 8), , (\"west_out_0\"->60));\n"
    "west = Vehicle((\"west_in_0\"->100, , 8), , (\"north_out_0\"->60));\n";

TEST(JunctionDeadlockTest, FourCarsArrivingTogetherOnEveryArmAllClearTheBox) {
  const RoadMap map = unsignalled_crossroads();
  // The ego waits far out on the east arm's second lane, in nobody's way.
  const std::string ego = "ego = AV((\"east_in_1\"->5, , 0), (\"east_in_1\"->10));\n";
  SimulationOptions options;
  options.duration = 60;
  options.target_reach = -1;
  std::string errors;
  auto trace =
      simulate_on(map, scenario(ego, kFourArms, "north, east, south, west"), options, errors);
  ASSERT_TRUE(trace) << errors;
  EXPECT_TRUE(trace->collisions.empty());
  for (ActorId k = 1; k <= 4; ++k)
    EXPECT_TRUE(cleared(*trace, k))
        << trace->actors[k].name << " is still in or before the box, at ("
        << trace->actors[k].x.back() << ", " << trace->actors[k].y.back() << ")";
}

// The reference ego as the car from the south going straight on, arriving a little after two of
// the others: the car from the north turns left across it, the one from the east turns left into
// the south arm, the one from the west goes straight on. Without the rule all four stand in the
// box.
TEST(JunctionDeadlockTest, TheEgoArrivingWithThreeCarsGetsThroughTheBox) {
  const RoadMap map = unsignalled_crossroads();
  const std::string ego = "ego = AV((\"south_in_0\"->60, , 8), (\"north_out_0\"->60));\n";
  const std::string npcs =
      "north = Vehicle((\"north_in_0\"->80, , 8), , (\"east_out_0\"->60));\n"
      "east = Vehicle((\"east_in_0\"->80, , 8), , (\"south_out_0\"->60));\n"
      "west = Vehicle((\"west_in_0\"->100, , 8), , (\"east_out_0\"->60));\n";
  SimulationOptions options;
  options.duration = 60;
  options.target_reach = -1;  // the run goes on after the ego's arrival, for the others
  std::string errors;
  auto trace = simulate_on(map, scenario(ego, npcs, "north, east, west"), options, errors);
  ASSERT_TRUE(trace) << errors;
  EXPECT_TRUE(trace->collisions.empty());
  for (ActorId k = 0; k <= 3; ++k)
    EXPECT_TRUE(cleared(*trace, k))
        << trace->actors[k].name << " is still in or before the box, at ("
        << trace->actors[k].x.back() << ", " << trace->actors[k].y.back() << ")";
}

// LawBreaker's sample: the ego northbound, npc1 turning left from the north across it, npc2 and
// npc3 eastbound, npc4 and npc5 westbound, all at one junction without signals.
TEST(JunctionDeadlockTest, LawBreakerIntersectionSampleLetsTheEgoReachItsTarget) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  const auto path = test::shared_dir() / "examples" / "avunit" /
                    "lawbreaker__Samples_of_AVUnit__Intersection_with_Double-Direction_Roads.avu";
  auto file = read_source_file(path.string());
  ASSERT_TRUE(file);
  auto run =
      test::simulate_file(*file, {}, map_search_path({test::shared_dir() / "maps" / "apollo"}));
  ASSERT_TRUE(run.trace) << run.errors;
  EXPECT_TRUE(run.trace->collisions.empty());
  EXPECT_EQ(run.trace->end, EndReason::target_reached)
      << "the ego is held in the junction until the end";
}

}  // namespace
}  // namespace scenfuzz
