// WMG SDL junctions as generated maps (docs/wmg-semantics.md, "Map"): a junction angle given as a
// range turns the crossing road of the crossroads and T-junction maps as the search samples it,
// every roundabout type builds its ring from the diameter, and every WMG corpus file's map builds
// at the lowest, middle and highest values of its parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/simulation.hpp"
#include "tests/lang/wmg_test_files.hpp"
#include "tests/support/parameter_points.hpp"

namespace scenfuzz {
namespace {

double heading_degrees(const Polyline& line, double s) {
  return line.heading_at(s) * 180 / std::numbers::pi;
}

// A two-lane road joined to J1 (the first road ends there, the others start there).
std::string junction_road(int number, const std::string& lane_width = "3.5", int lanes = 2) {
  const std::string id = "R" + std::to_string(number);
  std::string lane_list;
  for (int k = 1; k <= lanes; ++k) lane_list += (k > 1 ? ", " : "") + id + ".L" + std::to_string(k);
  return id + ": " + (number == 1 ? "START" : "START: [J1]") + "\nRoad type [Minor road] as [" +
         id +
         "] with zone as [N/A] AND speed limit of [48]\nin an [Urban] environment with Number of "
         "lanes [" +
         std::to_string(lanes) + "] as [" + lane_list +
         "]\nRoad traffic direction [Left-handed] Lane type [Traffic lane] Lane markings [Broken "
         "line]\nHorizontal road geometry [Straight] Vertical road geometry [Level plane]\n"
         "Transverse road geometry [Undivided] Road banking angle [Level Plane]\n"
         "with [No] roadside feature\nLength [100] AND Lane width [" +
         lane_width + "]\n" + (number == 1 ? "END: [J1]" : "END") + "\n";
}

std::string junction_file(const std::string& type, int roads, const std::string& angles,
                          const std::string& dimensions, const std::string& lane_width = "3.5",
                          int lanes = 2) {
  std::string road_ids;
  std::string road_text;
  for (int r = 1; r <= roads; ++r) {
    road_ids += (r > 1 ? ", R" : "R") + std::to_string(r);
    road_text += junction_road(r, lane_width, lanes);
  }
  wmg::test::Parts parts;
  parts.scenery = wmg::test::scenery_with_roads(
      road_text, "\nJ1: Junction type [" + type + "] as [J]\nwhich has [Give way] connection " +
                     "control and [" + std::to_string(roads) + "] connections with [" + road_ids +
                     "]\nAngles between roads " + angles +
                     "\nRoad lane connections [R1.L1 -> R2.L1]\nDimensions [" + dimensions + "]\n");
  return parts.text();
}

wmg::ParseResult parse_ok(const std::string& text) {
  SourceFile file("t.sdl", text);
  wmg::ParseResult result = wmg::parse(file);
  EXPECT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics) << text;
  return result;
}

std::size_t parameter_index(const ScenarioTemplate& scenario, const std::string& name) {
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].name == name) return i;
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

std::vector<double> midpoint(const ScenarioTemplate& scenario) {
  std::vector<double> values;
  for (const Parameter& parameter : scenario.parameters)
    values.push_back((parameter.lower + parameter.upper) / 2);
  return values;
}

using test::corner_points;

RoadMap map_at(const ScenarioTemplate& scenario, const std::vector<double>& values) {
  return load_scenario_map(scenario.map, map_search_path({}), values);
}

TEST(WmgJunctionMaps, TheSampledAngleTurnsTheCrossroadsCrossingRoad) {
  wmg::ParseResult result = parse_ok(junction_file(
      "Crossroads", 4, "[R1 -> R2, R2 -> R3, R3 -> R4, R4 -> R1]\n[60 to 120, 90, 90, 90]",
      "Width: 15 to 25, Depth: 20"));
  const ScenarioTemplate& scenario = result.scenario;
  ASSERT_EQ(scenario.map.name, "crossroads");
  const std::size_t angle = parameter_index(scenario, "J1.angle.R1_R2");
  std::vector<double> values = midpoint(scenario);
  for (double sampled : {60.0, 75.0, 90.0, 112.5, 120.0}) {
    SCOPED_TRACE(sampled);
    values[angle] = sampled;
    RoadMap map = map_at(scenario, values);
    // R2 is the south arm: its traffic heads `sampled` degrees from east, towards the centre.
    auto south_in = map.find_lane("south_in_0");
    auto north_out = map.find_lane("north_out_0");
    auto west_in = map.find_lane("west_in_0");
    ASSERT_TRUE(south_in && north_out && west_in);
    EXPECT_NEAR(heading_degrees(map.lane(*south_in).centre_line, 0), sampled, 1e-9);
    EXPECT_NEAR(heading_degrees(map.lane(*north_out).centre_line, 0), sampled, 1e-9);
    EXPECT_NEAR(heading_degrees(map.lane(*west_in).centre_line, 0), 0, 1e-9);
    // Whatever the angle, R1 traffic can still turn onto R2 and go on to R3.
    auto south_out = map.find_lane("south_out_0");
    auto east_out = map.find_lane("east_out_0");
    ASSERT_TRUE(south_out && east_out);
    EXPECT_TRUE(find_route(map, LanePosition{*west_in, 10, 0}, LanePosition{*south_out, 10, 0}));
    EXPECT_TRUE(find_route(map, LanePosition{*west_in, 10, 0}, LanePosition{*east_out, 10, 0}));
  }
}

TEST(WmgJunctionMaps, TheSampledAngleTurnsTheTJunctionsSideRoad) {
  wmg::ParseResult result = parse_ok(
      junction_file("T-Junction", 3, "[R1 -> R2, R2 -> R3, R3 -> R1]\n[80 to 100, 90, 180]",
                    "Width: 10 to 20, Depth: 10 to 20"));
  const ScenarioTemplate& scenario = result.scenario;
  ASSERT_EQ(scenario.map.name, "t_junction");
  std::vector<double> values = midpoint(scenario);
  values[parameter_index(scenario, "J1.angle.R1_R2")] = 83;
  RoadMap map = map_at(scenario, values);
  auto side_road = map.find_lane("south_in_0");
  ASSERT_TRUE(side_road);
  EXPECT_NEAR(heading_degrees(map.lane(*side_road).centre_line, 0), 83, 1e-9);
  EXPECT_EQ(map.stop_sign_count(), 1u);
}

// A right-angled T-junction (R1, R2 through, R3 the stem) with `dynamics`, set up at the centre
// of its space.
struct TJunction {
  explicit TJunction(const std::string& dynamics)
      : text(with_dynamics(dynamics)),
        result(parse_ok(text)),
        values(midpoint(result.scenario)),
        map(map_at(result.scenario, values)),
        setup(prepare_simulation(result.scenario, values, map, 1, diagnostics)) {}

  static std::string with_dynamics(const std::string& dynamics) {
    std::string text = junction_file(
        "T-Junction", 3, "[R1 -> R2, R2 -> R3]\n[170 to 190, 80 to 100]", "Width: 10, Depth: 10");
    const std::string placeholder = wmg::test::Parts{}.dynamics;
    EXPECT_NE(text.find(placeholder), std::string::npos);
    return text.replace(text.find(placeholder), placeholder.size(), dynamics);
  }
  std::string told() const { return format_diagnostics(SourceFile("t.sdl", text), diagnostics); }

  std::string text;
  wmg::ParseResult result;
  std::vector<double> values;
  RoadMap map;
  Diagnostics diagnostics;
  std::optional<SimulationSetup> setup;
};

// Issue 24: a vehicle whose relative heading runs against the lane it is placed on (here -90 to
// the ego driving north on the stem: east-bound, on the east arm's west-bound in lane) would start
// backwards in its lane; it takes the lane's direction, and the file is told. A pedestrian crosses
// as written.
TEST(WmgJunctionMaps, AVehicleHeadedAgainstItsLaneTakesTheLanesDirectionWithAWarning) {
  const TJunction t(
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\n"
      "AND Vehicle [Car] in [R1.L1] with a [Longitudinal] offset of [10] AND at relative "
      "position [FSR] with relative heading angle [-90] to [Ego]\n"
      "AND Pedestrian [Walker] in [R3.L2] with a [Longitudinal] offset of [10] AND at "
      "relative position [FSL] with relative heading angle [-90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n");
  const std::optional<SimulationSetup>& setup = t.setup;
  const RoadMap& map = t.map;
  ASSERT_TRUE(setup) << t.told();
  ASSERT_EQ(setup->actors.size(), 2u);
  const KinematicState car = setup->actors[0].trajectory.state_at(0);
  const auto lane = project_to_lane(map, {car.x, car.y}, car.heading);
  ASSERT_TRUE(lane);
  EXPECT_EQ(map.lane(lane->lane).id, "east_in_0");  // FSR of the ego on the stem
  EXPECT_NEAR(car.heading, map.lane(lane->lane).centre_line.heading_at(lane->s), 1e-9);
  const std::string told = t.told();
  EXPECT_NE(told.find("warning: Car's heading (0 deg) runs 180 deg against the direction of the "
                      "lane it is placed on (180 deg); it takes the lane's"),
            std::string::npos)
      << told;
  EXPECT_EQ(told.find("Walker's heading"), std::string::npos) << told;
  EXPECT_NEAR(setup->actors[1].trajectory.state_at(0).heading, 0, 1e-9);  // north - 90
}

// Issue 24: `[Walk_Cross] [R3, ...]` crosses the road it names. A walker on the T's west arm,
// short of the junction, crosses the arm it stands on when the phase names the ego; named R3
// (the stem, running north-south), it walks east, across the stem's lanes.
TEST(WmgJunctionMaps, AWalkCrossCrossesTheRoadItNames) {
  for (const std::string target : {"Ego", "R3"}) {
    SCOPED_TRACE(target);
    const TJunction t(
        "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
        "AND Pedestrian [Walker] in [R1.L1] with a [Longitudinal] offset of [40] AND at "
        "relative position [F] with relative heading angle [0] to [Ego]\n"
        "WHEN: [Ego] is [Going Ahead]\nDO: [Walker]\nPHASE 1: [Walk_Cross] [" +
        target + ", 5, 20] [Ego: 10, F]\nEND\n");
    ASSERT_TRUE(t.setup) << t.told();
    SimulationOptions options;
    options.duration = 3;
    const Trace trace = simulate(t.map, *t.setup, options);
    const TraceActor& walker = trace.actors[*trace.find_actor("Walker")];
    const double heading = walker.heading.back() * 180 / std::numbers::pi;
    if (target == "Ego") {
      EXPECT_NEAR(heading, 90, 1) << "north, across the west arm it stands on";
    } else {
      EXPECT_NEAR(heading, 0, 1) << "east, towards the stem it names";
      EXPECT_GT(walker.x.back(), walker.x.front() + 3);
    }
  }
}

// The file's `Road lane connections` in place of junction_file's.
std::string with_connections(std::string text, const std::string& connections) {
  const std::string written = "Road lane connections [R1.L1 -> R2.L1]";
  EXPECT_NE(text.find(written), std::string::npos);
  return text.replace(text.find(written), written.size(),
                      "Road lane connections [" + connections + "]");
}

// What setting `text` up at the centre of its space says: whether it could, its diagnostics
// formatted, and where the first of them points.
struct SetUpTold {
  bool ok = false;
  std::string told;
  SourceLocation first;
};

SetUpTold set_up(const std::string& text) {
  const SourceFile file("t.sdl", text);
  const wmg::ParseResult result = parse_ok(text);
  const std::vector<double> values = midpoint(result.scenario);
  const RoadMap map = map_at(result.scenario, values);
  Diagnostics diagnostics;
  SetUpTold set_up;
  set_up.ok = prepare_simulation(result.scenario, values, map, 1, diagnostics).has_value();
  set_up.told = format_diagnostics(file, diagnostics);
  if (!diagnostics.all().empty()) set_up.first = diagnostics.all().front().location;
  return set_up;
}

// Issue 24: every lane connection is a way through the junction the map must have; one the
// generator does not build is an error at the lane it leads to, saying where the lane does lead.
TEST(WmgJunctionMaps, AConnectionTheMapHasNoWayForIsAnErrorAtItsLane) {
  struct Case {
    int lanes;
    std::string connections, told;
  };
  for (const Case& c : std::vector<Case>{
           // Two lanes each way: R2 (east) leads L1 in, L3 in; the kerb lane does not turn left.
           {4, "R2.L1 -> R3.L3",
            "error: map 't_junction' has no way through the junction from 'east_in_0' to "
            "'south_out_0': 'east_in_0' leads to 'west_out_0' (straight on)"},
           // No U-turns.
           {2, "R3.L1 -> R3.L2",
            "error: map 't_junction' has no way through the junction from 'south_in_0' to "
            "'south_out_0': 'south_in_0' leads to "}}) {
    SCOPED_TRACE(c.connections);
    const std::string text = with_connections(
        junction_file("T-Junction", 3, "[R1 -> R2, R2 -> R3]\n[170 to 190, 80 to 100]",
                      "Width: 10, Depth: 10", "3.5", c.lanes),
        c.connections);
    const SetUpTold told = set_up(text);
    EXPECT_FALSE(told.ok);
    EXPECT_NE(told.told.find(c.told), std::string::npos) << told.told;
    // At the lane the connection leads to.
    const std::string target = c.connections.substr(c.connections.find("-> ") + 3);
    EXPECT_EQ(told.first.offset, text.find(target, text.find("Road lane connections")))
        << told.told;
  }
}

// Issue 24: turns follow the junction's lane connections. A car on the T's west arm turning right
// into the stem, where the connections lead its lane only straight on, is told so; led there too,
// it is not.
TEST(WmgJunctionMaps, ATurnWhereTheConnectionsDoNotLeadIsAWarning) {
  const std::string dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\n"
      "AND Vehicle [Car] in [R1.L1] with a [Longitudinal] offset of [10] AND at relative "
      "position [FSL] with relative heading angle [-90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: [Car]\nPHASE 1: [TurnRight_Away] [J1, 30, 3] [Ego: 10, "
      "FSL]\nEND\n";
  for (const std::string connections : {"R1.L1 -> R2.L1", "R1.L1 -> R2.L1 + R3.L2"}) {
    SCOPED_TRACE(connections);
    const SetUpTold set = set_up(with_connections(TJunction::with_dynamics(dynamics), connections));
    ASSERT_TRUE(set.ok) << set.told;
    const std::string& told = set.told;
    const std::string warning =
        "warning: Car's 'TurnRight_Away' turns right from 'west_in_0' into 'south_out_0' "
        "(turning right), where the junction's lane connections from that lane do not lead (they "
        "lead to 'east_out_0' (straight on)); it turns as its phase says";
    if (connections == "R1.L1 -> R2.L1")
      EXPECT_NE(told.find(warning), std::string::npos) << told;
    else
      EXPECT_EQ(told.find("lane connections from that lane"), std::string::npos) << told;
  }
}

// A vehicle without a turn phase takes the lanes ahead, straight on: where its lane's connections
// lead it only right, it is told so.
TEST(WmgJunctionMaps, AWayStraightOnWhereTheConnectionsDoNotLeadIsAWarning) {
  const std::string dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\n"
      "AND Vehicle [Car] in [R1.L1] with a [Longitudinal] offset of [10] AND at relative "
      "position [FSL] with relative heading angle [-90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  for (const std::string connections : {"R1.L1 -> R3.L2", "R1.L1 -> R3.L2 + R2.L1"}) {
    SCOPED_TRACE(connections);
    const SetUpTold set = set_up(with_connections(TJunction::with_dynamics(dynamics), connections));
    ASSERT_TRUE(set.ok) << set.told;
    const std::string& told = set.told;
    if (connections == "R1.L1 -> R3.L2")
      EXPECT_NE(told.find("warning: Car goes straight on from 'west_in_0' into 'east_out_0' "
                          "(straight on), where the junction's lane connections from that lane "
                          "do not lead (they lead to 'south_out_0' (turning right)); it takes the "
                          "lanes ahead"),
                std::string::npos)
          << told;
    else
      EXPECT_EQ(told.find("lane connections from that lane"), std::string::npos) << told;
  }
}

TEST(WmgJunctionMaps, EveryRoundaboutTypeBuildsOverItsDefaultDiameters) {
  // The level-1 defaults' diameters (docs/wmg-sdl.md), with the lane widths of a minor road and
  // of a motorway.
  struct Roundabout {
    std::string type;
    std::string diameter;
  };
  for (const Roundabout& roundabout : std::vector<Roundabout>{{"Mini roundabout", "10 to 28"},
                                                              {"Compact roundabout", "28 to 36"},
                                                              {"Normal roundabout", "36 to 100"},
                                                              {"Large roundabout", "100 to 200"}})
    for (std::string lane_width : {"2.75 to 3.25", "3.5 to 3.75"}) {
      SCOPED_TRACE(roundabout.type + ", lane width " + lane_width);
      wmg::ParseResult result = parse_ok(junction_file(
          roundabout.type, 4, "[R1 -> R2, R2 -> R3, R3 -> R4, R4 -> R1]\n[60 to 120, 90, 90, 90]",
          "Diameter: " + roundabout.diameter, lane_width, 1));
      const ScenarioTemplate& scenario = result.scenario;
      ASSERT_EQ(scenario.map.name, "roundabout");
      const std::size_t diameter = parameter_index(scenario, "J1.diameter");
      for (const std::vector<double>& values : corner_points(scenario)) {
        RoadMap map = map_at(scenario, values);
        auto ring = map.find_lane("ring_0");
        auto in = map.find_lane("west_in_0");
        auto out = map.find_lane("north_out_0");
        ASSERT_TRUE(ring && in && out);
        EXPECT_NEAR(map.lane(*ring).centre_line.length(), std::numbers::pi * values[diameter],
                    1e-3 * values[diameter]);
        EXPECT_TRUE(find_route(map, LanePosition{*in, 10, 0}, LanePosition{*out, 10, 0}));
      }
    }
}

TEST(WmgJunctionMaps, ALevel1MiniRoundaboutBuilds) {
  const std::string text =
      "VERSION: 1.0\nAUTHOR: 'scenfuzz'\n\n"
      "During the day, there is a bright, clear sky, with no particulates.\n"
      "There is a mini roundabout, J1, which has connections with R1, R2 and R3.\n"
      "R1 to R2 is to the left.\n"
      "R1, R2 and R3 are straight, minor roads.\n"
      "There is 1 vehicle, Ego.\n"
      "Ego is in R1.\n"
      "When Ego is driving towards J1, Ego turns left onto R2.\n"
      "Ego operates autonomously.\n";
  wmg::ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  ASSERT_EQ(scenario.map.name, "roundabout");
  for (const std::vector<double>& values : corner_points(scenario)) {
    RoadMap map = map_at(scenario, values);
    EXPECT_TRUE(map.find_lane("ring_0"));
    EXPECT_TRUE(map.warnings().empty());
  }
}

TEST(WmgJunctionMaps, EveryCorpusFilesMapBuildsAtItsLowestMiddleAndHighestPoint) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(wmg::test::wmg_corpus_dir())) {
    if (entry.path().extension() != ".sdl") continue;
    SCOPED_TRACE(entry.path().string());
    std::optional<SourceFile> file = read_source_file(entry.path().string());
    ASSERT_TRUE(file);
    wmg::ParseResult result = wmg::parse(*file);
    ASSERT_TRUE(result.ok()) << format_diagnostics(*file, result.diagnostics);
    ++files;
    // An ego placed `at [x, y]` has no lane to look for; building the map is the check then.
    const std::string& ego_lane = result.scenario.ego.initial.position.lane;
    for (const std::vector<double>& values : corner_points(result.scenario)) {
      RoadMap map = map_at(result.scenario, values);
      if (!ego_lane.empty()) {
        EXPECT_TRUE(map.find_lane(ego_lane)) << ego_lane;
      }
    }
  }
  EXPECT_GE(files, 10);
}

}  // namespace
}  // namespace scenfuzz
