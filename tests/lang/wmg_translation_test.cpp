// WMG SDL to the scenario IR (docs/wmg-semantics.md): the map and its parameters, lane ids,
// parameters' names, bounds and locations, actors and relative initial states, manoeuvre phases,
// WHEN/WHILE/END formulas, the environment, errors with line:column, the corpus, and concrete
// scenarios printed back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/walk_values.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::expect_spans;
using test::Parts;
using test::road_text;

std::string straight_road(int lanes = 2,
                          const std::string& tail = "Length [200 to 400] AND Lane width [3.5]") {
  return road_text("R1", lanes, "Horizontal road geometry [Straight]", tail);
}

std::string scenery(const std::string& roads, const std::string& junctions = "None\n") {
  return "SCENERY ELEMENTS:\nDO: 'd' [S] as:\nJunctions: " + junctions + "Roads:\n" + roads;
}

ParseResult parse_text(const std::string& text) {
  SourceFile file("t.sdl", text);
  return parse(file);
}

ParseResult parse_ok(const std::string& text) {
  SourceFile file("t.sdl", text);
  ParseResult result = parse(file);
  EXPECT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics) << text;
  return result;
}

const NamedValue* map_parameter(const ScenarioTemplate& scenario, const std::string& name) {
  for (const NamedValue& parameter : scenario.map.parameters)
    if (parameter.name == name) return &parameter;
  return nullptr;
}

int parameter_index(const ScenarioTemplate& scenario, const std::string& name) {
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].name == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> midpoint(const ScenarioTemplate& scenario) {
  std::vector<double> values;
  for (const Parameter& parameter : scenario.parameters)
    values.push_back((parameter.lower + parameter.upper) / 2);
  return values;
}

// The value of `value` with every parameter at `values` (all zero when none are given).
double at(const Value& value, const std::vector<double>& values) { return evaluate(value, values); }

// The 1-based line and column of the first occurrence of `piece` in `text`.
std::pair<std::uint32_t, std::uint32_t> position_of(const std::string& text,
                                                    const std::string& piece) {
  const std::size_t offset = text.find(piece);
  std::uint32_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// The first error's line and column.
std::pair<std::uint32_t, std::uint32_t> first_error(const ParseResult& result) {
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    if (diagnostic.severity == Severity::error)
      return {diagnostic.location.line, diagnostic.location.column};
  return {0, 0};
}

std::string first_error_message(const ParseResult& result) {
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    if (diagnostic.severity == Severity::error) return diagnostic.message;
  return "";
}

// --- map ------------------------------------------------------------------------------------

TEST(WmgTranslationTest, StraightRoadIsAOneWayStraightMapWithItsRangesAsParameters) {
  Parts parts;
  parts.scenery = scenery(straight_road(2, "Length [200 to 400] AND Lane width [3.0 to 3.5]"));
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.language, SourceLanguage::wmg_sdl);
  EXPECT_TRUE(scenario.has_scenario);
  EXPECT_EQ(scenario.map.name, "straight");
  ASSERT_NE(map_parameter(scenario, "lanes"), nullptr);
  EXPECT_EQ(at(map_parameter(scenario, "lanes")->value, {}), 2.0);
  ASSERT_NE(map_parameter(scenario, "two_way"), nullptr);
  EXPECT_EQ(at(map_parameter(scenario, "two_way")->value, {}), 0.0);
  ASSERT_NE(map_parameter(scenario, "speed_limit"), nullptr);
  EXPECT_DOUBLE_EQ(at(map_parameter(scenario, "speed_limit")->value, {}), 100 / 3.6);

  const int length = parameter_index(scenario, "R1.length");
  ASSERT_GE(length, 0);
  const Parameter& parameter = scenario.parameters[static_cast<std::size_t>(length)];
  EXPECT_EQ(parameter.kind, ParameterKind::continuous);
  EXPECT_EQ(parameter.lower, 200.0);
  EXPECT_EQ(parameter.upper, 400.0);
  EXPECT_EQ(parameter.unit, "m");
  expect_spans(parameter.location, text, "200 to 400");
  ASSERT_NE(map_parameter(scenario, "length"), nullptr);
  std::vector<double> values = midpoint(scenario);
  values[static_cast<std::size_t>(length)] = 321;
  EXPECT_EQ(at(map_parameter(scenario, "length")->value, values), 321.0);

  const int width = parameter_index(scenario, "R1.lane_width");
  ASSERT_GE(width, 0);
  expect_spans(scenario.parameters[static_cast<std::size_t>(width)].location, text, "3.0 to 3.5");
  EXPECT_EQ(at(map_parameter(scenario, "lane_width")->value, values), 3.25);
}

TEST(WmgTranslationTest, CurvedRoadIsACurveMapWithRadiusAndThirdsOfTheLength) {
  Parts parts;
  parts.scenery = scenery(road_text(
      "R1", 2, "Horizontal road geometry [Curved]\nwith curvature radius of [S1: 500 to 900]",
      "Length [300] AND Lane width [3.5]"));
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L2]\nWHEN: [Ego] is [Going Ahead]\n"
      "DO: AUTO\nEND\n";
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.map.name, "curve");
  const int radius = parameter_index(scenario, "R1.curvature_radius.S1");
  ASSERT_GE(radius, 0);
  expect_spans(scenario.parameters[static_cast<std::size_t>(radius)].location, text, "500 to 900");
  std::vector<double> values = midpoint(scenario);
  ASSERT_NE(map_parameter(scenario, "radius"), nullptr);
  EXPECT_EQ(at(map_parameter(scenario, "radius")->value, values), 700.0);
  ASSERT_NE(map_parameter(scenario, "straight_before"), nullptr);
  EXPECT_EQ(at(map_parameter(scenario, "straight_before")->value, values), 100.0);
  EXPECT_EQ(at(map_parameter(scenario, "straight_after")->value, values), 100.0);
  EXPECT_EQ(map_parameter(scenario, "two_way"), nullptr);
  EXPECT_EQ(scenario.ego.initial.position.lane, "fwd_1");
}

std::string crossroads_scenery(
    const std::string& type = "Crossroads",
    const std::string& angles =
        "[R1 -> R2, R2 -> R3, R3 -> R4, R4 -> R1]\n[80 to 100, 90, 90, 90]") {
  const std::string junction =
      "\nJ1: Junction type [" + type +
      "] as [X1]\nwhich has [Traffic light] connection control and [4] connections\n"
      "with [R1, R2, R3, R4]\nAngles between roads " +
      angles +
      "\nRoad lane connections [R1.L1 -> R3.L1]\n"
      "Dimensions [Width: 15 to 25, Depth: 20]\n"
      "Traffic light [With pedestrian crossing] as [TL1 -> R1.L1, TL3 -> R3]\n";
  std::string roads;
  for (int r = 1; r <= 4; ++r) {
    const std::string id = "R" + std::to_string(r);
    roads += road_text(
        id, 2, "Horizontal road geometry [Straight]",
        r == 1 ? "Length [100 to 150] AND Lane width [3.5]" : "Length [100] AND Lane width [3.5]",
        r == 1 ? "START" : "START: [J1]", r == 1 ? "END: [J1]" : "END", "48");
  }
  return scenery(roads, junction);
}

TEST(WmgTranslationTest, CrossroadsNamesArmsWestSouthEastNorthAndItsLightsByArm) {
  Parts parts;
  parts.scenery = crossroads_scenery();
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Vehicle [Crosser] in [R2.L1] with a [Longitudinal] offset of [30] AND at relative "
      "position [FSR] with relative heading angle [-90] to [Ego]\n"
      "WHEN: [TL1] is [Green]\nDO: [Crosser] PHASE 1: [Drive_Towards] [-, 30, 2] [Ego: 20, "
      "FSR]\nEND\n";
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.map.name, "crossroads");
  EXPECT_EQ(scenario.ego.initial.position.lane, "west_in_0");
  ASSERT_EQ(scenario.vehicles.size(), 1u);
  // Two lanes a road, one each way: R2.L1 is named by no connection, so it runs into the junction.
  EXPECT_EQ(scenario.vehicles[0].initial.position.lane, "south_in_0");
  ASSERT_NE(map_parameter(scenario, "arm_length"), nullptr);
  ASSERT_NE(map_parameter(scenario, "lanes"), nullptr);
  EXPECT_EQ(at(map_parameter(scenario, "lanes")->value, {}), 1.0);
  EXPECT_EQ(at(map_parameter(scenario, "arm_length")->value, midpoint(scenario)), 125.0);
  const int angle = parameter_index(scenario, "J1.angle.R1_R2");
  ASSERT_GE(angle, 0);
  EXPECT_EQ(scenario.parameters[static_cast<std::size_t>(angle)].kind, ParameterKind::angle);
  expect_spans(scenario.parameters[static_cast<std::size_t>(angle)].location, text, "80 to 100");
  EXPECT_GE(parameter_index(scenario, "J1.width"), 0);
  // The file gives no initial colour: the map's signal plan decides.
  EXPECT_TRUE(scenario.traffic.lights.empty());
  // [TL1] is [Green], TL1 on R1 (the west arm) -> light(light_west) == green
  const Formula& when = *scenario.vehicles[0].motion.phases.at(0).start_when;
  EXPECT_EQ(when.kind, FormulaKind::comparison);
  EXPECT_EQ(when.terms.at(0).kind, TermKind::signal);
  EXPECT_EQ(when.terms[0].name, "light");
  EXPECT_EQ(when.terms[0].operands.at(0).name, "light_west");
  EXPECT_EQ(when.terms.at(1).kind, TermKind::word);
  EXPECT_EQ(when.terms[1].name, "green");
}

// The file gives no signal timing: the approach of the first light a WHEN names green has the
// first green (the crossing one for red), else the ego's (the crossroads map's
// `east_west_first`; TL1 is on R1, the west arm; TL3 on R3, the east arm).
TEST(WmgTranslationTest, TheFirstGreenGoesToTheLightAWhenNamesGreenElseToTheEgosApproach) {
  struct Case {
    std::string ego_lane, when;
    double east_west_first;
  };
  for (const Case& c : std::vector<Case>{{"R2.L1", "[TL1] is [Green]", 1},
                                         {"R1.L1", "[TL3] is [Red]", 0},
                                         {"R1.L1", "[TL3] is [Amber]", 1},
                                         {"R1.L1", "[Ego] is [Going Ahead]", 1},
                                         {"R2.L1", "[Ego] is [Going Ahead]", 0}}) {
    SCOPED_TRACE(c.ego_lane + ", " + c.when);
    Parts parts;
    parts.scenery = crossroads_scenery();
    parts.dynamics = "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [" + c.ego_lane +
                     "]\nWHEN: " + c.when + "\nDO: AUTO\nEND\n";
    ParseResult result = parse_ok(parts.text());
    const NamedValue* first = map_parameter(result.scenario, "east_west_first");
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(at(first->value, {}), c.east_west_first);
  }
}

// The ego leaves the junction by the first lane connection written from its lane, to the out lane
// of the number written; an ego in a lane no connection leaves from has no target.
TEST(WmgTranslationTest, TheEgoLeavesTheJunctionByTheFirstConnectionFromItsLane) {
  Parts parts;
  parts.scenery = crossroads_scenery();
  ASSERT_NE(parts.scenery.find("Road lane connections [R1.L1 -> R3.L1]"), std::string::npos)
      << parts.scenery;
  for (const std::string lane : {"R1.L1", "R3.L1"}) {
    SCOPED_TRACE(lane);
    parts.dynamics = "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [" + lane +
                     "]\nWHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
    ParseResult result = parse_ok(parts.text());
    const std::optional<State>& target = result.scenario.ego.target;
    if (lane == "R3.L1") {
      EXPECT_FALSE(target.has_value());
      continue;
    }
    ASSERT_TRUE(target.has_value());
    EXPECT_EQ(target->position.kind, PositionKind::lane);
    EXPECT_EQ(target->position.lane, "east_out_0");  // R3, the east arm
    EXPECT_EQ(at(target->position.s, {}), 20.0);
  }
}

// `[Walk_Cross] [R2, ...]`: the phase carries every lane the map generates for R2 (the south
// arm); a road the scenery does not have is an error at its name.
TEST(WmgTranslationTest, APhaseNamingARoadCarriesThatRoadsLanes) {
  Parts parts;
  parts.scenery = crossroads_scenery();
  const std::string dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Pedestrian [Walker] in [R1.P1] with a [Longitudinal] offset of [30] AND at relative "
      "position [FSR] with relative heading angle [90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: [Walker] PHASE 1: [Walk_Cross] [ROAD, 5, 2] [Ego: 20, "
      "FSR]\nEND\n";
  parts.dynamics = dynamics;
  parts.dynamics.replace(parts.dynamics.find("ROAD"), 4, "R2");
  ParseResult result = parse_ok(parts.text());
  ASSERT_EQ(result.scenario.pedestrians.size(), 1u);
  EXPECT_EQ(result.scenario.pedestrians[0].motion.phases.at(0).road_lanes,
            (std::vector<std::string>{"south_in_0", "south_out_0"}));

  parts.dynamics = dynamics;
  parts.dynamics.replace(parts.dynamics.find("ROAD"), 4, "R9");
  const std::string text = parts.text();
  ParseResult unknown = parse_text(text);
  EXPECT_FALSE(unknown.ok());
  EXPECT_NE(first_error_message(unknown).find("the phase names road 'R9', which is not in the "
                                              "scenery"),
            std::string::npos)
      << first_error_message(unknown);
  EXPECT_EQ(first_error(unknown), position_of(text, "R9, 5"));
}

TEST(WmgTranslationTest, TheFirstPairsAngleTurnsTheCrossingRoadAndStaysASearchDimension) {
  Parts parts;
  parts.scenery = crossroads_scenery();
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  const NamedValue* angle = map_parameter(scenario, "angle");
  ASSERT_NE(angle, nullptr);
  expect_spans(angle->location, text, "80 to 100");
  const int dimension = parameter_index(scenario, "J1.angle.R1_R2");
  ASSERT_GE(dimension, 0);
  std::vector<double> values = midpoint(scenario);
  for (double sampled : {80.0, 87.5, 100.0}) {
    values[static_cast<std::size_t>(dimension)] = sampled;
    EXPECT_EQ(at(angle->value, values), sampled);
  }
  // The other pairs stay parameters (fixed here), but the map has one angle.
  EXPECT_EQ(std::count_if(scenario.map.parameters.begin(), scenario.map.parameters.end(),
                          [](const NamedValue& parameter) { return parameter.name == "angle"; }),
            1);
}

TEST(WmgTranslationTest, APairOfTheOtherCornerGivesTheSupplementOfItsAngle) {
  // R2 (south) -> R3 (east) meet at 180° - angle; a pair of opposite arms says nothing.
  Parts parts;
  parts.scenery =
      crossroads_scenery("Crossroads", "[R1 -> R3, R2 -> R3, R3 -> R4]\n[180, 60 to 80, 100]");
  ParseResult result = parse_ok(parts.text());
  const ScenarioTemplate& scenario = result.scenario;
  const NamedValue* angle = map_parameter(scenario, "angle");
  ASSERT_NE(angle, nullptr);
  std::vector<double> values = midpoint(scenario);
  values[static_cast<std::size_t>(parameter_index(scenario, "J1.angle.R2_R3"))] = 65;
  EXPECT_EQ(at(angle->value, values), 115.0);

  Parts wrapping;
  wrapping.scenery = crossroads_scenery("Crossroads", "[R1 -> R4]\n[70]");
  ParseResult wrapped = parse_ok(wrapping.text());
  ASSERT_NE(map_parameter(wrapped.scenario, "angle"), nullptr);
  EXPECT_EQ(at(map_parameter(wrapped.scenario, "angle")->value, {}), 110.0);
}

TEST(WmgTranslationTest, TJunctionSideRoadAngleComesFromTheFirstTwoRoads) {
  std::string roads;
  for (int r = 1; r <= 3; ++r) {
    const std::string id = "R" + std::to_string(r);
    roads +=
        road_text(id, 2, "Horizontal road geometry [Straight]", "Length [100] AND Lane width [3.5]",
                  r == 1 ? "START" : "START: [J1]", r == 1 ? "END: [J1]" : "END", "48");
  }
  Parts parts;
  parts.scenery =
      scenery(roads,
              "\nJ1: Junction type [T-Junction] as [T1]\n"
              "which has [Give way] connection control and [3] connections with [R1, R2, R3]\n"
              "Angles between roads [R2 -> R1, R2 -> R3] [70 to 110, 90]\n"
              "Road lane connections [R1.L1 -> R3.L1]\nDimensions [Width: 10, Depth: 10]\n");
  ParseResult result = parse_ok(parts.text());
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.map.name, "t_junction");
  const NamedValue* angle = map_parameter(scenario, "angle");
  ASSERT_NE(angle, nullptr);
  std::vector<double> values = midpoint(scenario);
  values[static_cast<std::size_t>(parameter_index(scenario, "J1.angle.R2_R1"))] = 75;
  EXPECT_EQ(at(angle->value, values), 75.0);
}

TEST(WmgTranslationTest, EveryRoundaboutSizeIsARoundaboutMapWithHalfItsDiameter) {
  for (std::string type :
       {"Mini roundabout", "Compact roundabout", "Normal roundabout", "Large roundabout"}) {
    SCOPED_TRACE(type);
    std::string roads;
    for (int r = 1; r <= 4; ++r) {
      const std::string id = "R" + std::to_string(r);
      roads += road_text(id, 1, "Horizontal road geometry [Straight]",
                         "Length [100] AND Lane width [2.75 to 3.25]",
                         r == 1 ? "START" : "START: [J1]", r == 1 ? "END: [J1]" : "END", "48");
    }
    Parts parts;
    parts.scenery = scenery(
        roads, "\nJ1: Junction type [" + type +
                   "] as [O1]\nwhich has [Give way] connection control and [4] connections\n"
                   "with [R1, R2, R3, R4]\nAngles between roads [R1 -> R2] [60 to 120]\n"
                   "Road lane connections [R1.L1 -> R3.L1]\nDimensions [Diameter: 10 to 200]\n");
    ParseResult result = parse_ok(parts.text());
    const ScenarioTemplate& scenario = result.scenario;
    EXPECT_EQ(scenario.map.name, "roundabout");
    const NamedValue* ring_radius = map_parameter(scenario, "ring_radius");
    ASSERT_NE(ring_radius, nullptr);
    std::vector<double> values = midpoint(scenario);
    values[static_cast<std::size_t>(parameter_index(scenario, "J1.diameter"))] = 13;
    EXPECT_EQ(at(ring_radius->value, values), 6.5);
    // The arms are a quarter turn apart whatever the file says: no angle for the map.
    EXPECT_EQ(map_parameter(scenario, "angle"), nullptr);
    EXPECT_GE(parameter_index(scenario, "J1.angle.R1_R2"), 0);
  }
}

TEST(WmgTranslationTest, LightThatNoJunctionPlacesIsAnError) {
  Parts parts;
  parts.scenery = crossroads_scenery();
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\nWHEN: [TL9] is [Red]\nDO: AUTO\nEND\n";
  const std::string text = parts.text();
  ParseResult result = parse_text(text);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("unknown traffic light 'TL9'"), std::string::npos)
      << first_error_message(result);
  EXPECT_EQ(first_error(result), position_of(text, "TL9"));
}

TEST(WmgTranslationTest, JunctionTypeWithoutGeneratorIsAnErrorAtTheType) {
  Parts parts;
  parts.scenery = crossroads_scenery("Y-Junction");
  const std::string text = parts.text();
  ParseResult result = parse_text(text);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("junction type 'Y-Junction' has no map generator"),
            std::string::npos)
      << first_error_message(result);
  EXPECT_EQ(first_error(result), position_of(text, "Y-Junction"));
  // It names what is built, and a staggered junction is told the same.
  EXPECT_NE(first_error_message(result).find("there are generators for Crossroads, T-Junction"),
            std::string::npos);
  Parts staggered;
  staggered.scenery = crossroads_scenery("Staggered");
  const ParseResult offset = parse_text(staggered.text());
  EXPECT_NE(first_error_message(offset).find("junction type 'Staggered' has no map generator yet"),
            std::string::npos)
      << first_error_message(offset);
  EXPECT_NE(first_error_message(offset).find("staggered junction's two offset T-junctions"),
            std::string::npos);
}

TEST(WmgTranslationTest, TwoRoadsWithoutAJunctionAreAnError) {
  Parts parts;
  parts.scenery =
      scenery(straight_road() + road_text("R2", 1, "Horizontal road geometry [Straight]",
                                          "Length [100] AND Lane width [3.5]"));
  ParseResult result = parse_text(parts.text());
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("more than one road"), std::string::npos);
}

// --- lanes and actors -----------------------------------------------------------------------

std::string cut_in_dynamics(const std::string& end = "END: [Clock] >= [30] OR Collision\n") {
  return "DYNAMIC ELEMENTS:\nINITIAL:\nVehicle [Ego] in [R1.L1] at heading angle [0 to 5]\n"
         "AND Vehicle [Cutter] in [R1.L2] with a [Longitudinal] offset of [10 to 30] AND at "
         "relative position [FSL] with relative heading angle [0] to [Ego]\n"
         "AND Global timer [Clock] = [0]\n"
         "WHEN: [Ego] is [Going Ahead] in [R1.L1] at a speed of [60 to 100]\n"
         "DO: [Cutter]\n"
         "PHASE 1: [Drive_Away] [-, 72 to 108, 1 to 3] [Ego: 10 to 40, FSL]\n"
         "WHILE: [Clock] < [2]\n"
         "PHASE 2: [LaneChangeRight_CutIn] [-, 36, 2] [Ego: 5 to 30, F]\n"
         "WHILE: [Cutter] [Lateral] offset to [Ego] > [0.2]\n" +
         end;
}

TEST(WmgTranslationTest, LanesMapToTheStraightMapsEastLanes) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  ParseResult result = parse_ok(parts.text());
  EXPECT_EQ(result.scenario.ego.kind, ActorKind::ego);
  EXPECT_EQ(result.scenario.ego.name, "Ego");
  EXPECT_EQ(result.scenario.ego.initial.position.kind, PositionKind::lane);
  EXPECT_EQ(result.scenario.ego.initial.position.lane, "east_0");
  EXPECT_EQ(at(result.scenario.ego.initial.position.s, {}), 30.0);
  ASSERT_EQ(result.scenario.vehicles.size(), 1u);
  EXPECT_EQ(result.scenario.vehicles[0].initial.position.lane, "east_1");
}

TEST(WmgTranslationTest, UnknownLaneIsAnErrorAtTheLane) {
  Parts parts;
  parts.scenery = scenery(straight_road(1));
  parts.dynamics = cut_in_dynamics();
  const std::string text = parts.text();
  ParseResult result = parse_text(text);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("unknown lane 'R1.L2'"), std::string::npos)
      << first_error_message(result);
  EXPECT_EQ(first_error(result), position_of(text, "R1.L2]"));
}

TEST(WmgTranslationTest, RelativeInitKeepsReferenceSectorAndSignedOffsets) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  const Position& position = scenario.vehicles.at(0).initial.position;
  EXPECT_EQ(position.kind, PositionKind::relative);
  EXPECT_EQ(position.reference, "Ego");
  EXPECT_EQ(position.relative_location, "FSL");
  EXPECT_EQ(position.lane, "east_1");
  const int offset = parameter_index(scenario, "Cutter.init.longitudinal_offset");
  ASSERT_GE(offset, 0);
  expect_spans(scenario.parameters[static_cast<std::size_t>(offset)].location, text, "10 to 30");
  EXPECT_EQ(at(position.s, midpoint(scenario)), 20.0);
  const Heading& heading = *scenario.vehicles[0].initial.heading;
  ASSERT_TRUE(heading.relative_to.has_value());
  EXPECT_EQ(heading.relative_to->kind, Direction::Kind::actor);
  EXPECT_EQ(heading.relative_to->actor, "Ego");
  const int ego_heading = parameter_index(scenario, "Ego.init.heading");
  ASSERT_GE(ego_heading, 0);
  EXPECT_EQ(scenario.parameters[static_cast<std::size_t>(ego_heading)].kind, ParameterKind::angle);
}

TEST(WmgTranslationTest, RearSectorPlacesTheActorBehind) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Vehicle [Follower] in [R1.L1] with a [Longitudinal] offset of [15] AND at relative "
      "position [R] with relative heading angle [0] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  ParseResult result = parse_ok(parts.text());
  EXPECT_EQ(at(result.scenario.vehicles.at(0).initial.position.s, {}), -15.0);
}

TEST(WmgTranslationTest, PavementIsTheKerbLaneAndItsLateralOffsetPointsAtThePavement) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Pedestrian [Walker] in [R1.P1] with a [Longitudinal] offset of [20] AND with a "
      "[Lateral] offset of [3] AND at relative position [FSL] with relative heading angle [90] "
      "to [Ego]\nWHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  ParseResult result = parse_ok(parts.text());
  const Position& position = result.scenario.pedestrians.at(0).initial.position;
  EXPECT_EQ(position.lane, "east_0");
  ASSERT_TRUE(position.lateral.has_value());
  EXPECT_EQ(at(*position.lateral, {}), -3.0);
}

TEST(WmgTranslationTest, RelativeInitToAnActorNotYetInitialisedIsAnError) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Vehicle [Cutter] in [R1.L2] with a [Longitudinal] offset of [10] AND at relative "
      "position [F] with relative heading angle [0] to [Ghost]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  const std::string text = parts.text();
  ParseResult result = parse_text(text);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("'Ghost'"), std::string::npos);
  EXPECT_EQ(first_error(result), position_of(text, "Ghost"));
}

TEST(WmgTranslationTest, SequenceOfAnActorNotInitialisedIsAnError) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: [Nobody] PHASE 1: [Stop] [-, 0, 2] [Ego: 10, F]\nEND\n";
  ParseResult result = parse_text(parts.text());
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("'Nobody' is referenced but not initialised"),
            std::string::npos)
      << first_error_message(result);
}

TEST(WmgTranslationTest, CyclistsAreVehiclesOfKindCyclistAndPedestriansArePedestrians) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "AND Cyclist [Rider] in [R1.L2] with a [Longitudinal] offset of [10] AND at relative "
      "position [F] with relative heading angle [0] to [Ego]\n"
      "AND Pedestrian [Walker] in [R1.L1] with a [Longitudinal] offset of [20] AND at relative "
      "position [F] with relative heading angle [90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  ParseResult result = parse_ok(parts.text());
  ASSERT_EQ(result.scenario.vehicles.size(), 1u);
  EXPECT_EQ(result.scenario.vehicles[0].kind, ActorKind::cyclist);
  ASSERT_TRUE(result.scenario.vehicles[0].type.has_value());
  EXPECT_EQ(result.scenario.vehicles[0].type->model, "bicycle");
  ASSERT_EQ(result.scenario.pedestrians.size(), 1u);
  EXPECT_EQ(result.scenario.pedestrians[0].kind, ActorKind::pedestrian);
  EXPECT_EQ(result.scenario.pedestrians[0].name, "Walker");
}

// --- phases and conditions ------------------------------------------------------------------

double named(const std::vector<NamedValue>& values, const std::string& name,
             const std::vector<double>& point) {
  for (const NamedValue& value : values)
    if (value.name == name) return at(value.value, point);
  ADD_FAILURE() << "no " << name;
  return 0;
}

TEST(WmgTranslationTest, PhasesCarrySpeedDurationGapInSIAndTheirReference) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  ParseResult result = parse_ok(parts.text());
  const ScenarioTemplate& scenario = result.scenario;
  const Actor& cutter = scenario.vehicles.at(0);
  EXPECT_EQ(cutter.motion.kind, MotionKind::manoeuvres);
  ASSERT_EQ(cutter.motion.phases.size(), 2u);
  const std::vector<double> mid = midpoint(scenario);
  const ManoeuvrePhase& first = cutter.motion.phases[0];
  EXPECT_EQ(first.manoeuvre, "Drive_Away");
  EXPECT_DOUBLE_EQ(named(first.parameters, "speed", mid), 90 / 3.6);
  EXPECT_DOUBLE_EQ(named(first.parameters, "duration", mid), 2.0);
  EXPECT_DOUBLE_EQ(named(first.parameters, "gap", mid), 25.0);
  EXPECT_EQ(first.reference, "Ego");
  EXPECT_EQ(first.relative_location, "FSL");
  EXPECT_GE(parameter_index(scenario, "Cutter.phase1.speed"), 0);
  EXPECT_EQ(
      scenario
          .parameters[static_cast<std::size_t>(parameter_index(scenario, "Cutter.phase1.speed"))]
          .unit,
      "km/h");
  const ManoeuvrePhase& second = cutter.motion.phases[1];
  EXPECT_EQ(second.manoeuvre, "LaneChangeRight_CutIn");
  EXPECT_DOUBLE_EQ(named(second.parameters, "speed", mid), 10.0);
  EXPECT_EQ(second.relative_location, "F");
  EXPECT_TRUE(first.start_when.has_value());
  EXPECT_FALSE(second.start_when.has_value());
  // The initial speed of an actor is its first phase's speed; the ego's is its WHEN speed.
  ASSERT_TRUE(cutter.initial.speed.has_value());
  EXPECT_DOUBLE_EQ(at(*cutter.initial.speed, mid), 90 / 3.6);
  ASSERT_TRUE(scenario.ego.initial.speed.has_value());
  EXPECT_DOUBLE_EQ(at(*scenario.ego.initial.speed, mid), 80 / 3.6);
}

// The conjuncts of a formula built with `&`, left to right.
void flatten(const Formula& formula, std::vector<const Formula*>& out) {
  if (formula.kind == FormulaKind::conjunction) {
    flatten(formula.operands.at(0), out);
    flatten(formula.operands.at(1), out);
  } else {
    out.push_back(&formula);
  }
}

TEST(WmgTranslationTest, WhenBecomesManoeuvreLaneAndSpeedBandOverSignals) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  ParseResult result = parse_ok(parts.text());
  const ScenarioTemplate& scenario = result.scenario;
  std::vector<const Formula*> parts_of_when;
  flatten(*scenario.vehicles.at(0).motion.phases.at(0).start_when, parts_of_when);
  ASSERT_EQ(parts_of_when.size(), 4u);
  const Formula& manoeuvre = *parts_of_when[0];
  EXPECT_EQ(manoeuvre.compare, CompareOp::equal);
  EXPECT_EQ(manoeuvre.terms.at(0).name, "manoeuvre");
  EXPECT_EQ(manoeuvre.terms[0].operands.at(0).kind, TermKind::word);
  EXPECT_EQ(manoeuvre.terms[0].operands[0].name, "Ego");
  EXPECT_EQ(manoeuvre.terms.at(1).name, "GoingAhead");
  const Formula& lane = *parts_of_when[1];
  EXPECT_EQ(lane.terms.at(0).name, "lane");
  EXPECT_EQ(lane.terms.at(1).name, "east_0");
  const std::vector<double> mid = midpoint(scenario);
  EXPECT_EQ(parts_of_when[2]->terms.at(0).name, "speed");
  EXPECT_EQ(parts_of_when[2]->compare, CompareOp::greater_equal);
  EXPECT_DOUBLE_EQ(at(parts_of_when[2]->terms.at(1).value, mid), 80 / 3.6);
  EXPECT_EQ(parts_of_when[3]->compare, CompareOp::less_equal);
  EXPECT_GE(parameter_index(scenario, "when1.Ego.speed"), 0);
}

TEST(WmgTranslationTest, WhileConstraintsBecomeTimerAndOffsetComparisons) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  ParseResult result = parse_ok(parts.text());
  const auto& phases = result.scenario.vehicles.at(0).motion.phases;
  const Formula& timer = *phases.at(0).continue_while;
  EXPECT_EQ(timer.kind, FormulaKind::comparison);
  EXPECT_EQ(timer.compare, CompareOp::less);
  EXPECT_EQ(timer.terms.at(0).name, "timer");
  EXPECT_EQ(timer.terms[0].operands.at(0).name, "Clock");
  EXPECT_EQ(at(timer.terms.at(1).value, {}), 2.0);
  const Formula& offset = *phases.at(1).continue_while;
  EXPECT_EQ(offset.compare, CompareOp::greater);
  EXPECT_EQ(offset.terms.at(0).name, "lateral_offset");
  ASSERT_EQ(offset.terms[0].operands.size(), 2u);
  EXPECT_EQ(offset.terms[0].operands[0].name, "Cutter");
  EXPECT_EQ(offset.terms[0].operands[1].name, "Ego");
  EXPECT_DOUBLE_EQ(at(offset.terms.at(1).value, {}), 0.2);
}

TEST(WmgTranslationTest, EndConditionsAndTimers) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics();
  ParseResult result = parse_ok(parts.text());
  const ScenarioTemplate& scenario = result.scenario;
  ASSERT_EQ(scenario.timers.size(), 1u);
  EXPECT_EQ(scenario.timers[0].name, "Clock");
  EXPECT_EQ(at(scenario.timers[0].value, {}), 0.0);
  ASSERT_EQ(scenario.end_conditions.size(), 2u);
  EXPECT_EQ(scenario.end_conditions[0].compare, CompareOp::greater_equal);
  EXPECT_EQ(scenario.end_conditions[0].terms.at(0).name, "timer");
  EXPECT_EQ(at(scenario.end_conditions[0].terms.at(1).value, {}), 30.0);
  EXPECT_EQ(scenario.end_conditions[1].kind, FormulaKind::predicate);
  EXPECT_EQ(scenario.end_conditions[1].terms.at(0).name, "collision");
  EXPECT_TRUE(scenario.end_conditions[1].terms[0].operands.empty());
  EXPECT_FALSE(scenario.duration.has_value());
  EXPECT_TRUE(scenario.specs.empty());
}

TEST(WmgTranslationTest, ALocalTimerInAPhaseCountsFromThatActorsFirstPhase) {
  std::string dynamics = cut_in_dynamics();
  dynamics.replace(dynamics.find("Global timer"), 12, "Local timer");
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = dynamics;
  ParseResult result = parse_ok(parts.text());
  const Formula& timer = *result.scenario.vehicles.at(0).motion.phases.at(0).continue_while;
  ASSERT_EQ(timer.terms.at(0).name, "timer");
  ASSERT_EQ(timer.terms[0].operands.size(), 2u);
  EXPECT_EQ(timer.terms[0].operands[0].name, "Clock");
  EXPECT_EQ(timer.terms[0].operands[1].name, "Cutter");
  // In END, outside every phase, it counts from the start: one operand, and a warning.
  EXPECT_EQ(result.scenario.end_conditions.at(0).terms.at(0).operands.size(), 1u);
  std::size_t warnings = 0;
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    if (diagnostic.severity == Severity::warning &&
        diagnostic.message.find("local timer 'Clock'") != std::string::npos)
      ++warnings;
  EXPECT_EQ(warnings, 1u);
}

TEST(WmgTranslationTest, WithoutEndTheRunLastsThirtySeconds) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics("END\n");
  ParseResult result = parse_ok(parts.text());
  EXPECT_TRUE(result.scenario.end_conditions.empty());
  ASSERT_TRUE(result.scenario.duration.has_value());
  EXPECT_EQ(at(*result.scenario.duration, {}), 30.0);
}

TEST(WmgTranslationTest, TimerThatIsNotInitialisedIsAnError) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.dynamics = cut_in_dynamics("END: [Stopwatch] >= [30]\n");
  ParseResult result = parse_text(parts.text());
  EXPECT_FALSE(result.ok());
  EXPECT_NE(first_error_message(result).find("timer 'Stopwatch'"), std::string::npos);
}

// --- environment ----------------------------------------------------------------------------

double weather(const ScenarioTemplate& scenario, const std::string& kind,
               const std::vector<double>& point) {
  for (const WeatherComponent& component : scenario.environment->weather)
    if (component.kind == kind) return at(component.intensity, point);
  ADD_FAILURE() << "no weather " << kind;
  return -1;
}

TEST(WmgTranslationTest, EnvironmentScalesWeatherToFractionsAndKeepsTheTimeOfDay) {
  Parts parts;
  parts.scenery = scenery(straight_road());
  parts.environment =
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nWind [40 to 60]\nCloudiness [4]\n"
      "Particulates [Mist and Fog]\nRainfall [Moderate Rain: 10]\n"
      "Snowfall [Heavy Snow (visibility: 400)]\nTime of the day [08:00 to 18:00]\n"
      "Illumination [Night Dark] with [Headlamp] as light source\n";
  const std::string text = parts.text();
  ParseResult result = parse_ok(text);
  const ScenarioTemplate& scenario = result.scenario;
  ASSERT_TRUE(scenario.environment.has_value());
  const std::vector<double> mid = midpoint(scenario);
  EXPECT_DOUBLE_EQ(weather(scenario, "wind", mid), 0.5);
  EXPECT_DOUBLE_EQ(weather(scenario, "cloudiness", mid), 0.5);
  EXPECT_DOUBLE_EQ(weather(scenario, "rain", mid), 0.2);
  EXPECT_DOUBLE_EQ(weather(scenario, "snow", mid), 0.9);
  int fogs = 0;
  for (const WeatherComponent& component : scenario.environment->weather)
    if (component.kind == "fog") {
      ++fogs;
      const double fog = at(component.intensity, mid);
      EXPECT_TRUE(fog == 0.5 || std::abs(fog - 0.6) < 1e-12) << fog;
    }
  EXPECT_EQ(fogs, 2);
  const int time = parameter_index(scenario, "environment.time_of_day");
  ASSERT_GE(time, 0);
  EXPECT_EQ(scenario.parameters[static_cast<std::size_t>(time)].lower, 8 * 3600.0);
  expect_spans(scenario.parameters[static_cast<std::size_t>(time)].location, text,
               "08:00 to 18:00");
  ASSERT_TRUE(scenario.environment->time_of_day.has_value());
  EXPECT_EQ(at(*scenario.environment->time_of_day, mid), 13 * 3600.0);
  bool night = false;
  for (const Attribute& attribute : scenario.environment->attributes)
    night = night || (attribute.key == "illumination" && attribute.value == "Night Dark");
  EXPECT_TRUE(night);
}

// --- the corpus and concrete scenarios ------------------------------------------------------

std::vector<std::filesystem::path> corpus_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(test::wmg_corpus_dir()))
    if (entry.path().extension() == ".sdl") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(WmgTranslationTest, EveryCorpusFileTranslatesWithoutErrors) {
  const std::vector<std::filesystem::path> files = corpus_files();
  ASSERT_GE(files.size(), 10u);
  int level1 = 0;
  for (const auto& path : files) {
    std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file.has_value()) << path;
    if (detect_wmg_level(*file) == 1) ++level1;
    ParseResult result = parse(*file);
    EXPECT_TRUE(result.ok()) << format_diagnostics(*file, result.diagnostics);
    EXPECT_TRUE(result.scenario.has_scenario) << path;
    EXPECT_FALSE(result.scenario.map.name.empty()) << path;
    EXPECT_FALSE(result.scenario.parameters.empty()) << path;
    EXPECT_FALSE(result.scenario.ego.name.empty()) << path;
  }
  EXPECT_GE(level1, 1);
}

// Every numeric slot of the template, evaluated at `point`, in walk order.
std::vector<double> all_values(const ScenarioTemplate& scenario, const std::vector<double>& point) {
  std::vector<double> values;
  for_each_value(scenario, [&](const Value& value, const std::string&, const std::string&) {
    values.push_back(evaluate(value, point));
  });
  return values;
}

void expect_concrete_round_trip(const std::filesystem::path& path) {
  std::optional<SourceFile> file = read_source_file(path.string());
  ASSERT_TRUE(file.has_value()) << path;
  ParseResult logical = parse(*file);
  ASSERT_TRUE(logical.ok()) << format_diagnostics(*file, logical.diagnostics);
  const std::vector<double> mid = midpoint(logical.scenario);
  const std::string text = print_concrete(*file, logical.scenario, mid);
  SourceFile concrete_file("concrete.sdl", text);
  EXPECT_EQ(detect_wmg_level(concrete_file), 2);
  ParseResult concrete = parse(concrete_file);
  ASSERT_TRUE(concrete.ok()) << format_diagnostics(concrete_file, concrete.diagnostics) << text;
  EXPECT_TRUE(concrete.scenario.parameters.empty()) << text;
  // Level 2 writes a time of day as HH:MM: the concrete file holds the time to the minute.
  std::vector<double> written = mid;
  for (std::size_t i = 0; i < written.size(); ++i)
    if (logical.scenario.parameters[i].unit == "time of day")
      written[i] = std::round(written[i] / 60) * 60;
  const std::vector<double> expected = all_values(logical.scenario, written);
  const std::vector<double> actual = all_values(concrete.scenario, {});
  ASSERT_EQ(actual.size(), expected.size()) << text;
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_DOUBLE_EQ(actual[i], expected[i]) << path << " value " << i;
}

TEST(WmgTranslationTest, ConcreteLevel2ScenarioAtTheMidpointParsesBackWithItsValues) {
  int level2 = 0;
  for (const auto& path : corpus_files()) {
    std::optional<SourceFile> file = read_source_file(path.string());
    ASSERT_TRUE(file.has_value());
    if (detect_wmg_level(*file) != 2) continue;
    ++level2;
    SCOPED_TRACE(path.string());
    expect_concrete_round_trip(path);
  }
  EXPECT_GE(level2, 5);
}

TEST(WmgTranslationTest, ConcreteLevel1ScenarioIsItsLevel2ConversionWithValues) {
  int level1 = 0;
  for (const auto& corpus_path : corpus_files()) {
    std::optional<SourceFile> file = read_source_file(corpus_path.string());
    ASSERT_TRUE(file.has_value());
    if (detect_wmg_level(*file) != 1) continue;
    ++level1;
    SCOPED_TRACE(corpus_path.string());
    expect_concrete_round_trip(corpus_path);
  }
  EXPECT_GE(level1, 4);
  const std::filesystem::path path = test::wmg_corpus_dir() / "motorway_cut_in_level1.sdl";
  std::optional<SourceFile> file = read_source_file(path.string());
  ASSERT_TRUE(file.has_value());
  ParseResult logical = parse(*file);
  const std::string text = print_concrete(*file, logical.scenario, midpoint(logical.scenario));
  EXPECT_NE(text.find("level-1"), std::string::npos);
  EXPECT_NE(text.find("SCENERY ELEMENTS"), std::string::npos);
}

TEST(WmgTranslationTest, ConcreteValuesReplaceExactlyTheRangeText) {
  Parts parts;
  parts.scenery = scenery(straight_road(2, "Length [200 to 400] AND Lane width [3.5]"));
  const std::string text = parts.text();
  SourceFile file("t.sdl", text);
  ParseResult result = parse(file);
  ASSERT_TRUE(result.ok());
  std::vector<double> values = midpoint(result.scenario);
  values[static_cast<std::size_t>(parameter_index(result.scenario, "R1.length"))] = 250.5;
  const std::string concrete = print_concrete(file, result.scenario, values);
  EXPECT_NE(concrete.find("Length [250.5] AND Lane width [3.5]"), std::string::npos) << concrete;
  EXPECT_NE(concrete.find("#   R1.length = 250.5 m"), std::string::npos) << concrete;
}

}  // namespace
}  // namespace scenfuzz::wmg
