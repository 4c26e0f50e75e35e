// CH-Scenario tracks simulated (docs/ch-scenario.md, "Entities"): a vehicle whose track says
// `overtake` pulls out round the slower vehicle ahead of it and comes back once past it, and one
// whose track says `turn right` takes the junction's right turn on a named map. The files are
// read as a user's, through the CH-Scenario front end, and run as `scenfuzz run` would.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lang/chs/chs.hpp"
#include "manoeuvre_fixtures.hpp"

namespace scenfuzz {
namespace {

using namespace test;

// A blank 600 m map with east_road along y = 30, its halves `half` m wide; the ego drives west on
// the far half, out of the way; a slow truck (20 km/h) at x = 100 and a van (54 km/h) 60 m behind
// it, both in the kerb lane of the eastbound half, the van's track saying it overtakes.
std::string overtaking_file(double half, double kerb_y) {
  const std::string top = std::to_string(30 + half), bottom = std::to_string(30 - half);
  const std::string y = std::to_string(kerb_y);
  return "import from MAP\n  length: 600\n  width: 60\n"
         "RoadNetwork\n  road east_road\n"
         "    left boundary: (0, " +
         top + ") (600, " + top +
         ")\n"
         "    center lines: (0, 30) (600, 30)\n"
         "    right boundary: (0, " +
         bottom + ") (600, " + bottom +
         ")\n"
         "Entity\n"
         "  DynamicEntity1\n    name: ego\n    speed: 36\n    track: to the west\n"
         "  DynamicEntity2\n    name: truck\n    speed: 20\n    position: (100, " +
         y +
         ")\n"
         "  DynamicEntity3\n    name: van\n    speed: 54\n    position: (40, " +
         y +
         ")\n"
         "    track: overtakes the slow truck\n";
}

struct ChsRun {
  ManoeuvreRun run;
  std::string said;  // the front end's diagnostics
};

ChsRun run_chs(const std::string& text, double duration) {
  chs::ScenarioParse parsed = chs::parse_scenario(SourceFile("test.chs", text));
  ChsRun result;
  result.said = format_diagnostics(SourceFile("test.chs", text), parsed.diagnostics);
  EXPECT_TRUE(parsed.ok()) << result.said;
  if (!parsed.ok()) return result;
  parsed.scenario.duration = constant_value(duration);
  result.run = run_manoeuvres(parsed.scenario);
  return result;
}

// Out into the lane on the left (`out_y`) while beside the truck, at its own speed, and back into
// the kerb lane well ahead of it, without touching anything.
void expect_overtakes(const ChsRun& chs, double kerb_y, double out_y) {
  ASSERT_TRUE(chs.run.trace) << chs.said << chs.run.messages;
  const Trace& trace = *chs.run.trace;
  const TraceActor& van = trace.actors[*trace.find_actor("van")];
  const TraceActor& truck = trace.actors[*trace.find_actor("truck")];
  EXPECT_NEAR(van.y[0], kerb_y, 0.05);
  bool passed = false;
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    const double along = van.x[i] - truck.x[i];
    if (std::abs(along) < 6) {
      passed = true;
      EXPECT_NEAR(van.y[i], out_y, 0.3) << "beside the truck at t = " << trace.time[i];
      EXPECT_GT(van.speed[i], 13) << "not held back behind it, at t = " << trace.time[i];
    }
    ASSERT_NEAR(truck.y[i], kerb_y, 0.05) << "the truck keeps its lane";
    ASSERT_LT(std::abs(van.heading[i]), 0.3) << "the van drives east at t = " << trace.time[i];
  }
  EXPECT_TRUE(passed) << "the van came abreast of the truck";
  EXPECT_NEAR(van.y.back(), kerb_y, 0.05) << "back in the kerb lane";
  EXPECT_GT(van.x.back() - truck.x.back(), 20) << "ahead of the truck";
  EXPECT_TRUE(trace.collisions.empty());
}

TEST(ChsTrackManoeuvres, AnOvertakingVanPassesTheSlowTruckInTheLaneOnItsLeftAndComesBack) {
  // Two lanes each way: the kerb lane at y = 24.75, the lane beside the centre line at 28.25.
  const ChsRun chs = run_chs(overtaking_file(7, 24.75), 25);
  EXPECT_EQ(chs.said.find("not simulated"), std::string::npos) << chs.said;
  expect_overtakes(chs, 24.75, 28.25);
}

// With a lane each way the van pulls out onto the oncoming lane (y = 31.75; its own is at 28.25).
// Out there it still drives in its own lane's frame, but follows what is in the band of road it
// covers (physics/simulation/lane_cruise.hpp, LeaderScope), not the truck in the lane beside it:
// it passes the truck and comes back ahead of it.
TEST(ChsTrackManoeuvres, WithALaneEachWayTheVanPassesOnTheOncomingLane) {
  expect_overtakes(run_chs(overtaking_file(3.5, 28.25), 25), 28.25, 31.75);
}

TEST(ChsTrackManoeuvres, WithNothingSlowerAheadTheVanFollowsItsLane) {
  // The truck as fast as the van: nothing to overtake.
  std::string text = overtaking_file(7, 24.75);
  text.replace(text.find("speed: 20"), 9, "speed: 54");
  const ChsRun chs = run_chs(text, 15);
  ASSERT_TRUE(chs.run.trace) << chs.said << chs.run.messages;
  const Trace& trace = *chs.run.trace;
  const TraceActor& van = trace.actors[*trace.find_actor("van")];
  for (double y : van.y) ASSERT_NEAR(y, 24.75, 0.05);
}

// The built-in T junction: the main road west-east through (0, 0), two lanes each way 3.5 m wide,
// the side road from the south. A taxi in the eastbound kerb lane of the west arm
// turns right into the side road; the ego comes the other way on the main road.
TEST(ChsTrackManoeuvres, ATurningTaxiTakesTheJunctionsRightTurnOnANamedMap) {
  const std::string text =
      "map: t_junction\n"
      "Entity\n"
      "  DynamicEntity1\n    name: ego\n    speed: 30\n    position: (100, 5.25)\n"
      "  DynamicEntity2\n    name: taxi\n    speed: 30\n    position: (-100, -5.25)\n"
      "    track: turn right\n";
  const ChsRun chs = run_chs(text, 25);
  ASSERT_TRUE(chs.run.trace) << chs.said << chs.run.messages;
  const Trace& trace = *chs.run.trace;
  const TraceActor& taxi = trace.actors[*trace.find_actor("taxi")];
  EXPECT_NEAR(taxi.heading[0], 0, 0.05) << "east at the start";
  EXPECT_LT(taxi.y.back(), -30) << "down the side road";
  EXPECT_NEAR(std::abs(taxi.x.back()), 5.25, 1) << "in its southbound lane";
  EXPECT_NEAR(taxi.heading.back(), -std::numbers::pi / 2, 0.1) << "heading south";
  EXPECT_TRUE(trace.collisions.empty());
}

// The built-in crossroads, two lanes each way, north and south green from the start: a taxi
// coming north turns left while a truck comes south straight on, both reaching the junction
// about 7 s in. The left turn gives way to the oncoming truck (physics/simulation/
// phase_junction.hpp): it waits at the entry until the truck is through, then turns.
TEST(ChsTrackManoeuvres, ALeftTurnGivesWayToOncomingTrafficInTheJunction) {
  const std::string text =
      "map: crossroads\n"
      "Entity\n"
      "  DynamicEntity1\n    name: ego\n    speed: 30\n    position: (-120, -1.75)\n"
      "  DynamicEntity2\n    name: taxi\n    speed: 36\n    position: (1.75, -80)\n"
      "    track: turn left\n"
      "  DynamicEntity3\n    name: truck\n    speed: 36\n    position: (-1.75, 82)\n";
  const ChsRun chs = run_chs(text, 25);
  ASSERT_TRUE(chs.run.trace) << chs.said << chs.run.messages;
  const Trace& trace = *chs.run.trace;
  const TraceActor& taxi = trace.actors[*trace.find_actor("taxi")];
  const TraceActor& truck = trace.actors[*trace.find_actor("truck")];
  EXPECT_TRUE(trace.collisions.empty());
  // The taxi crosses the truck's lane (x = -1.75) only once the truck is out of the junction.
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    if (taxi.x[i] < -0.5 && taxi.y[i] > -10) {
      ASSERT_LT(truck.y[i], -10) << "the taxi crossed in front of the truck at t = "
                                 << trace.time[i];
    }
  }
  EXPECT_LT(truck.y.back(), -40) << "the truck went on south";
  EXPECT_LT(taxi.x.back(), -30) << "the taxi turned left, west";
  EXPECT_NEAR(std::abs(taxi.heading.back()), std::numbers::pi, 0.1) << "heading west";
}

}  // namespace
}  // namespace scenfuzz
