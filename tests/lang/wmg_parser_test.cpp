// The WMG SDL level-2 syntax layer on valid input: every construct of chapter 2 with its values
// and source locations, the bundled corpus, and the printer's round trip (print, parse again,
// compare).
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "lang/source_file.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/lexer.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "tests/lang/test_files.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::expect_spans;
using test::Parts;
using test::road;
using test::scenery_with_roads;

// Parses `text` and fails the test (showing every diagnostic) unless it is accepted.
Level2File parse_ok(const std::string& text) {
  SourceFile file("t.sdl", text);
  Level2ParseResult result = parse_level2(file);
  EXPECT_TRUE(result.file.has_value()) << format_diagnostics(file, result.diagnostics) << text;
  EXPECT_EQ(result.diagnostics.all().size(), 0u) << format_diagnostics(file, result.diagnostics);
  return result.file.value_or(Level2File{});
}

// The tree printed and parsed again equals the tree.
void expect_round_trip(const Level2File& tree) {
  std::string printed = print_level2(tree);
  SourceFile file("printed.sdl", printed);
  Level2ParseResult again = parse_level2(file);
  ASSERT_TRUE(again.file.has_value()) << format_diagnostics(file, again.diagnostics) << printed;
  EXPECT_TRUE(*again.file == tree) << printed;
  EXPECT_EQ(print_level2(*again.file), printed) << "printing is not stable";
}

void expect_range(const NumberRange& range, double low, double high, bool is_range) {
  EXPECT_DOUBLE_EQ(range.low, low);
  EXPECT_DOUBLE_EQ(range.high, high);
  EXPECT_EQ(range.is_range, is_range);
}

// ---- lexer -----------------------------------------------------------------------------------

TEST(WmgLexer, SplitsWordsNumbersStringsAndPunctuation) {
  Diagnostics diagnostics;
  SourceFile file("t.sdl",
                  "R1.L2 -> 20.5 'a b' <= # comment\n\xE2\x80\x98typographic\xE2\x80\x99 N/A");
  std::vector<Token> tokens = tokenize(file, diagnostics);
  ASSERT_FALSE(diagnostics.has_errors());
  std::vector<TokenKind> kinds;
  for (const Token& token : tokens) kinds.push_back(token.kind);
  EXPECT_EQ(kinds,
            (std::vector<TokenKind>{TokenKind::word, TokenKind::dot, TokenKind::word,
                                    TokenKind::arrow, TokenKind::number, TokenKind::string,
                                    TokenKind::less_equal, TokenKind::string, TokenKind::word,
                                    TokenKind::slash, TokenKind::word, TokenKind::end_of_file}));
  EXPECT_DOUBLE_EQ(tokens[4].number, 20.5);
  EXPECT_EQ(tokens[5].text, "a b");
  EXPECT_EQ(tokens[7].text, "typographic");
  EXPECT_EQ(tokens[7].location.line, 2u);
  EXPECT_EQ(tokens[7].location.column, 1u);
  EXPECT_EQ(tokens[8].location.column, 15u);  // columns count characters, not bytes
}

// ---- header ----------------------------------------------------------------------------------

TEST(WmgParser, MinimalFileAndHeader) {
  Parts parts;
  parts.header = "VERSION: 2.10\nEXTENSION: None\nAUTHOR: 'Ada'\nAUTHOR: 'Grace Hopper'\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  EXPECT_EQ(file.header.version.major_part.value, 2);
  EXPECT_EQ(file.header.version.minor_part.value, 10);
  expect_spans(file.header.version.minor_part.location, text, "10");
  ASSERT_EQ(file.header.authors.size(), 2u);
  EXPECT_EQ(file.header.authors[1].text, "Grace Hopper");
  expect_spans(file.header.authors[1].location, text, "'Grace Hopper'");
  ASSERT_TRUE(file.header.extension.has_value());
  EXPECT_EQ(file.header.extension->text, "None");
  EXPECT_FALSE(file.header.extension->is_string);
  EXPECT_EQ(file.scenery.description.text, "d");
  EXPECT_EQ(file.scenery.id.name, "S");
  EXPECT_TRUE(file.scenery.junctions.empty());
  EXPECT_TRUE(file.scenery.roads.empty());
  EXPECT_FALSE(file.internal_elements.has_value());
  EXPECT_FALSE(file.traffic.has_value());
  expect_round_trip(file);
}

TEST(WmgParser, ExtensionAfterTheAuthorsMayBeAString) {
  Parts parts;
  parts.header = "VERSION: 1.0\nAUTHOR: 'a'\nEXTENSION: 'ALKS'\n";
  Level2File file = parse_ok(parts.text());
  ASSERT_TRUE(file.header.extension.has_value());
  EXPECT_EQ(file.header.extension->text, "ALKS");
  EXPECT_TRUE(file.header.extension->is_string);
}

TEST(WmgParser, CommentsAndBlankLinesAreIgnored) {
  Parts parts;
  parts.header = "# a scenario\n\n  VERSION: 1.0 # the version\nAUTHOR: 'a'  # me\n";
  EXPECT_EQ(parse_ok(parts.text()).header.version.major_part.value, 1);
}

// ---- ranges ----------------------------------------------------------------------------------

TEST(WmgParser, RangesSpanExactlyTheirTextAndLoneNumbersAreFixedValues) {
  Parts parts;
  parts.scenery = scenery_with_roads(road("", "Length [  -20.5 to -3 ] AND Lane width [3.25]\n"));
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  ASSERT_EQ(file.scenery.roads.size(), 1u);
  const Road& r = file.scenery.roads[0];
  expect_range(r.length, -20.5, -3, true);
  expect_spans(r.length.location, text, "-20.5 to -3");
  ASSERT_TRUE(r.lane_width.whole_road.has_value());
  expect_range(*r.lane_width.whole_road, 3.25, 3.25, false);
  expect_spans(r.lane_width.whole_road->location, text, "3.25");
  ASSERT_TRUE(r.speed_limit.has_value());
  expect_range(*r.speed_limit, 100, 100, false);
  expect_spans(r.speed_limit->location, text, "100");
}

TEST(WmgParser, EqualBoundsAreARange) {
  Parts parts;
  parts.scenery = scenery_with_roads(road("", "Length [50 to 50] AND Lane width [3.5]\n"));
  expect_range(parse_ok(parts.text()).scenery.roads[0].length, 50, 50, true);
}

// ---- roads -----------------------------------------------------------------------------------

TEST(WmgParser, RoadWithEveryMandatoryPart) {
  Parts parts;
  parts.scenery = scenery_with_roads(road());
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  const Road& r = file.scenery.roads.at(0);
  EXPECT_EQ(r.id.name, "R1");
  expect_spans(r.id.location, text, "R1", text.find("R1: START"));
  EXPECT_FALSE(r.start_junction.has_value());
  EXPECT_EQ(r.road_type.text, "Motorway");
  EXPECT_EQ(r.named_as.name, "R1");
  EXPECT_EQ(r.zone.text, "N/A");
  expect_spans(r.zone.location, text, "N/A");
  EXPECT_EQ(r.environment.text, "Rural");
  EXPECT_EQ(r.lane_count.value, 1);
  ASSERT_EQ(r.lanes.size(), 1u);
  EXPECT_EQ(r.lanes[0].road.name, "R1");
  EXPECT_EQ(r.lanes[0].lane.name, "L1");
  expect_spans(r.lanes[0].location, text, "R1.L1");
  EXPECT_EQ(r.traffic_direction.text, "Left-handed");
  expect_spans(r.traffic_direction.location, text, "Left-handed");
  EXPECT_EQ(r.lane_type.text, "Traffic lane");
  EXPECT_EQ(r.lane_markings.text, "Solid line");
  expect_spans(r.lane_markings.location, text, "Solid line");
  EXPECT_FALSE(r.surface_type || r.surface_condition || r.surface_feature);
  ASSERT_TRUE(r.horizontal_geometry.whole_road.has_value());
  EXPECT_EQ(r.horizontal_geometry.whole_road->text, "Straight");
  EXPECT_FALSE(r.curvature_radius.has_value());
  EXPECT_EQ(r.vertical_geometry.text, "Level plane");
  ASSERT_EQ(r.transverse_geometry.size(), 1u);
  EXPECT_EQ(r.transverse_geometry[0].text, "Divided");
  EXPECT_EQ(r.banking_angle.text, "Level Plane");
  EXPECT_EQ(r.roadside_feature.text, "No");
  EXPECT_FALSE(r.edge_feature.has_value());
  EXPECT_TRUE(r.special_structures.empty() && r.fixed_structures.empty() &&
              r.temporary_structures.empty() && r.road_signs.empty());
  EXPECT_FALSE(r.end_junction.has_value());
  expect_round_trip(file);
}

TEST(WmgParser, RoadWithEveryOptionalPart) {
  const std::string text_of_road =
      "R2: START: [J1]\n"
      "Road type ['Slip road'] as [R2] with zone as ['School zone'] AND speed limit of [N/A]\n"
      "in an [Urban] environment with Number of lanes [2] as [R2.L1, R2.P1]\n"
      "Road traffic direction [Right-handed] Lane type [Traffic lane] Lane markings [Broken "
      "line]\n"
      "Road surface type [Segmented] with surface condition [Icy] AND surface feature [Ruts]\n"
      "Horizontal road geometry [S1: Straight, S2: Curved]\n"
      "with curvature radius of [S1: N/A, S2: 200 to 400]\n"
      "Vertical road geometry [Down-slope]\n"
      "Transverse road geometry [Undivided, Pavement, 'Central reservation']\n"
      "Road banking angle [Right Bank - Deep]\n"
      "with ['Hedges'] roadside feature\n"
      "Roadway edge features [Shoulder (paved or gravel)]\n"
      "Special road structures [Tunnel] as [T1] at [350.5] distance from START\n"
      "Fixed road structures [Street lights: {spacing: 20 to 30, height: 6}, Vegetation at [S1, "
      "S2]]\n"
      "Temporary road structures [Road works, 'Cones'] at R2.L1\n"
      "Road sign [Speed limit] as [Sign1] at [10] distance from START\n"
      "Special road structures ['Gantry'] as [G1] at [20] distance from START\n"
      "Length [500 to 900]\n"
      "AND Lane width [S1: 3 to 3.5, S2: 3.75]\n"
      "END: [J2]\n";
  Parts parts;
  parts.scenery = scenery_with_roads(text_of_road);
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  const Road& r = file.scenery.roads.at(0);
  ASSERT_TRUE(r.start_junction.has_value());
  EXPECT_EQ(r.start_junction->name, "J1");
  EXPECT_EQ(r.road_type.text, "Slip road");
  EXPECT_TRUE(r.road_type.is_string);
  expect_spans(r.road_type.location, text, "'Slip road'");
  EXPECT_EQ(r.zone.text, "School zone");
  EXPECT_FALSE(r.speed_limit.has_value());
  EXPECT_EQ(r.environment.text, "Urban");
  EXPECT_EQ(r.lanes.at(1).lane.name, "P1");
  EXPECT_EQ(r.surface_type->text, "Segmented");
  EXPECT_EQ(r.surface_condition->text, "Icy");
  EXPECT_EQ(r.surface_feature->text, "Ruts");
  ASSERT_EQ(r.horizontal_geometry.segments.size(), 2u);
  EXPECT_EQ(r.horizontal_geometry.segments[1].segment.name, "S2");
  EXPECT_EQ(r.horizontal_geometry.segments[1].value.text, "Curved");
  ASSERT_TRUE(r.curvature_radius.has_value());
  ASSERT_EQ(r.curvature_radius->segments.size(), 2u);
  EXPECT_FALSE(r.curvature_radius->segments[0].range.has_value());
  expect_range(*r.curvature_radius->segments[1].range, 200, 400, true);
  expect_spans(r.curvature_radius->segments[1].range->location, text, "200 to 400");
  EXPECT_EQ(r.vertical_geometry.text, "Down-slope");
  ASSERT_EQ(r.transverse_geometry.size(), 3u);
  EXPECT_EQ(r.transverse_geometry[2].text, "Central reservation");
  EXPECT_EQ(r.banking_angle.text, "Right Bank - Deep");
  expect_spans(r.banking_angle.location, text, "Right Bank - Deep");
  EXPECT_EQ(r.roadside_feature.text, "Hedges");
  EXPECT_EQ(r.edge_feature->text, "Shoulder (paved or gravel)");
  ASSERT_EQ(r.special_structures.size(), 2u);
  EXPECT_EQ(r.special_structures[0].type.text, "Tunnel");
  EXPECT_EQ(r.special_structures[0].id.name, "T1");
  expect_range(r.special_structures[0].distance_from_start, 350.5, 350.5, false);
  EXPECT_EQ(r.special_structures[1].type.text, "Gantry");
  ASSERT_EQ(r.fixed_structures.size(), 2u);
  ASSERT_TRUE(r.fixed_structures[0].street_lights.has_value());
  EXPECT_EQ(r.fixed_structures[0].type.text, "Street lights");
  expect_range(r.fixed_structures[0].street_lights->spacing, 20, 30, true);
  expect_range(r.fixed_structures[0].street_lights->height, 6, 6, false);
  EXPECT_EQ(r.fixed_structures[1].type.text, "Vegetation");
  ASSERT_EQ(r.fixed_structures[1].at.size(), 2u);
  EXPECT_EQ(r.fixed_structures[1].at[1].name, "S2");
  ASSERT_EQ(r.temporary_structures.size(), 1u);
  EXPECT_EQ(r.temporary_structures[0].types.at(0).text, "Road works");
  EXPECT_EQ(r.temporary_structures[0].types.at(1).text, "Cones");
  EXPECT_EQ(r.temporary_structures[0].lane.lane.name, "L1");
  ASSERT_EQ(r.road_signs.size(), 1u);
  EXPECT_EQ(r.road_signs[0].type.text, "Speed limit");
  EXPECT_EQ(r.road_signs[0].id.name, "Sign1");
  expect_range(r.length, 500, 900, true);
  ASSERT_EQ(r.lane_width.segments.size(), 2u);
  expect_range(*r.lane_width.segments[0].range, 3, 3.5, true);
  expect_range(*r.lane_width.segments[1].range, 3.75, 3.75, false);
  ASSERT_TRUE(r.end_junction.has_value());
  EXPECT_EQ(r.end_junction->name, "J2");
  expect_round_trip(file);
}

TEST(WmgParser, CurvatureRadiusMayBeNotApplicable) {
  Parts parts;
  parts.scenery = scenery_with_roads(road("", "Length [100] AND Lane width [3.5]\n"));
  parts.scenery.replace(parts.scenery.find("Vertical"), 0, "with curvature radius of [N/A]\n");
  Level2File file = parse_ok(parts.text());
  ASSERT_TRUE(file.scenery.roads.at(0).curvature_radius.has_value());
  EXPECT_TRUE(file.scenery.roads[0].curvature_radius->not_applicable);
  expect_round_trip(file);
}

TEST(WmgParser, SeveralRoadsInOrder) {
  Parts parts;
  std::string second = road();
  second.replace(second.find("R1: START"), 2, "R7");
  parts.scenery = scenery_with_roads(road() + second);
  Level2File file = parse_ok(parts.text());
  ASSERT_EQ(file.scenery.roads.size(), 2u);
  EXPECT_EQ(file.scenery.roads[1].id.name, "R7");
}

// ---- junctions -------------------------------------------------------------------------------

const std::string kJunction =
    "J1: Junction type [Mini roundabout] as [Round1]\n"
    "which has [Give way] connection control and [3] connections with [R1, R2, R3]\n"
    "Angles between roads [R1 -> R2, R2 -> R3] [100 to 140, 90]\n"
    "Road lane connections [R1.L1 -> R2.L1 + R3.L1, R2.L2 -> R1.L2]\n"
    "Dimensions [Diameter: 12 to 20]\n";

TEST(WmgParser, JunctionWithDiameter) {
  Parts parts;
  parts.scenery = scenery_with_roads(road(), kJunction);
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  ASSERT_EQ(file.scenery.junctions.size(), 1u);
  const Junction& j = file.scenery.junctions[0];
  EXPECT_EQ(j.id.name, "J1");
  EXPECT_EQ(j.type.text, "Mini roundabout");
  expect_spans(j.type.location, text, "Mini roundabout");
  EXPECT_EQ(j.named_as.name, "Round1");
  EXPECT_EQ(j.connection_control.text, "Give way");
  EXPECT_EQ(j.connection_count.value, 3);
  ASSERT_EQ(j.connected_roads.size(), 3u);
  EXPECT_EQ(j.connected_roads[2].name, "R3");
  ASSERT_EQ(j.angle_pairs.size(), 2u);
  EXPECT_EQ(j.angle_pairs[1].from.name, "R2");
  EXPECT_EQ(j.angle_pairs[1].to.name, "R3");
  ASSERT_EQ(j.angles.size(), 2u);
  expect_range(j.angles[0], 100, 140, true);
  expect_spans(j.angles[0].location, text, "100 to 140");
  expect_range(j.angles[1], 90, 90, false);
  ASSERT_EQ(j.lane_connections.size(), 2u);
  EXPECT_EQ(j.lane_connections[0].from.road.name, "R1");
  ASSERT_EQ(j.lane_connections[0].to.size(), 2u);
  EXPECT_EQ(j.lane_connections[0].to[1].road.name, "R3");
  ASSERT_TRUE(j.dimensions.diameter.has_value());
  EXPECT_FALSE(j.dimensions.width.has_value());
  expect_range(*j.dimensions.diameter, 12, 20, true);
  EXPECT_FALSE(j.road_signs.has_value());
  EXPECT_FALSE(j.traffic_lights.has_value());
  expect_round_trip(file);
}

TEST(WmgParser, JunctionWithWidthDepthSignsAndTrafficLights) {
  const std::string junction =
      "X: Junction type ['Five-way'] as [Star]\n"
      "which has [Traffic light] connection control and [1] connection with [R1]\n"
      "Angles between roads [R1 -> R1] [0]\n"
      "Road lane connections [R1.L1 -> R1.L2]\n"
      "Dimensions [Width: 10 to 15, Depth: 8]\n"
      "Road signs [Stop, 'No entry', Traffic Light] at [R1.L1, R1.L2]\n"
      "Traffic light [Without pedestrian crossing] as [TL1 -> R1.L1, TL2 -> R1]\n"
      "Y: Junction type [T-Junction] as [Tee]\n"
      "which has [No] connection control and [1] connection with [R1]\n"
      "Angles between roads [R1 -> R1] [0] Road lane connections [R1.L1 -> R1.L1]\n"
      "Dimensions [Diameter: 5]\n";
  Parts parts;
  parts.scenery = scenery_with_roads(road(), junction);
  Level2File file = parse_ok(parts.text());
  ASSERT_EQ(file.scenery.junctions.size(), 2u);
  const Junction& j = file.scenery.junctions[0];
  EXPECT_TRUE(j.type.is_string);
  EXPECT_EQ(j.type.text, "Five-way");
  expect_range(*j.dimensions.width, 10, 15, true);
  expect_range(*j.dimensions.depth, 8, 8, false);
  ASSERT_TRUE(j.road_signs.has_value());
  ASSERT_EQ(j.road_signs->signs.size(), 3u);
  EXPECT_EQ(j.road_signs->signs[1].text, "No entry");
  EXPECT_EQ(j.road_signs->signs[2].text, "Traffic Light");
  EXPECT_EQ(j.road_signs->lanes.at(1).lane.name, "L2");
  ASSERT_TRUE(j.traffic_lights.has_value());
  EXPECT_EQ(j.traffic_lights->type.text, "Without pedestrian crossing");
  ASSERT_EQ(j.traffic_lights->lights.size(), 2u);
  EXPECT_EQ(j.traffic_lights->lights[0].light.name, "TL1");
  ASSERT_TRUE(j.traffic_lights->lights[0].lane.has_value());
  EXPECT_EQ(j.traffic_lights->lights[0].lane->name, "L1");
  EXPECT_EQ(j.traffic_lights->lights[1].road.name, "R1");
  EXPECT_FALSE(j.traffic_lights->lights[1].lane.has_value());
  EXPECT_EQ(file.scenery.junctions[1].type.text, "T-Junction");
  expect_round_trip(file);
}

// ---- dynamics --------------------------------------------------------------------------------

TEST(WmgParser, InitialisationOfAbsoluteAndRelativeActorsAndTimers) {
  Parts parts;
  parts.dynamics =
      "DYNAMIC ELEMENTS:\n"
      "INITIAL: Vehicle [Ego] in [R1.L1] at [10.5, -2] at heading angle [-5 to 5]\n"
      "AND Pedestrian [Walker] in [R1.P1] with a [Lateral] offset of [1 to 2]\n"
      "  AND with a [Longitudinal] offset of [30]\n"
      "  AND at relative position [FSL] with relative heading angle [90] to [Ego]\n"
      "AND Global timer [Clock] = [0]\n"
      "AND Cyclist [Bike] in [R1.L1] AND at relative position [R] with relative heading angle "
      "[0] to [Walker]\n"
      "AND Local timer [Countdown] = [-3.5]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  const Initialisation& init = file.dynamics.initialisation;
  EXPECT_EQ(init.first.type.value, ActorType::vehicle);
  expect_spans(init.first.type.location, text, "Vehicle");
  EXPECT_EQ(init.first.actor.name, "Ego");
  EXPECT_EQ(init.first.lane.lane.name, "L1");
  ASSERT_TRUE(init.first.position.has_value());
  expect_range(init.first.position->x, 10.5, 10.5, false);
  expect_range(init.first.position->y, -2, -2, false);
  expect_spans(init.first.position->y.location, text, "-2");
  ASSERT_TRUE(init.first.heading.has_value());
  expect_range(*init.first.heading, -5, 5, true);
  ASSERT_EQ(init.relative.size(), 2u);
  const RelativeActorInit& walker = init.relative[0];
  EXPECT_EQ(walker.type.value, ActorType::pedestrian);
  ASSERT_EQ(walker.offsets.size(), 2u);
  EXPECT_EQ(walker.offsets[0].relation.value, PositionRelation::lateral);
  expect_range(walker.offsets[0].offset, 1, 2, true);
  EXPECT_EQ(walker.offsets[1].relation.value, PositionRelation::longitudinal);
  EXPECT_EQ(walker.relative_position.value, RelativeLocation::front_side_left);
  expect_spans(walker.relative_position.location, text, "FSL");
  expect_range(walker.relative_heading, 90, 90, false);
  EXPECT_EQ(walker.reference.name, "Ego");
  EXPECT_EQ(init.relative[1].type.value, ActorType::cyclist);
  EXPECT_TRUE(init.relative[1].offsets.empty());
  EXPECT_EQ(init.relative[1].relative_position.value, RelativeLocation::rear);
  ASSERT_EQ(init.timers.size(), 2u);
  EXPECT_EQ(init.timers[0].scope.value, TimerScope::global);
  EXPECT_EQ(init.timers[0].timer.name, "Clock");
  EXPECT_EQ(init.timers[1].scope.value, TimerScope::local);
  expect_range(init.timers[1].value, -3.5, -3.5, false);
  expect_round_trip(file);
}

TEST(WmgParser, WhenConditionsOfActorsAndTrafficLights) {
  Parts parts;
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "WHEN: [Ego] is [LaneChangeLeft] in [R1.L2] at a speed of [50 to 70]\n"
      "  AND [TL1] is [Red] AND [TL2, TL3] are [Amber] AND [Ego] is ['Overtaking'] in [J1]\n"
      "DO: AUTO\nEND\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  const std::vector<WhenCondition>& conditions = file.dynamics.sequences.at(0).conditions;
  ASSERT_EQ(conditions.size(), 4u);
  const auto& actor = std::get<ActorCondition>(conditions[0]);
  EXPECT_EQ(actor.actor.name, "Ego");
  EXPECT_EQ(actor.observed.text, "LaneChangeLeft");
  ASSERT_TRUE(actor.in_lane.has_value());
  EXPECT_EQ(actor.in_lane->lane.name, "L2");
  ASSERT_TRUE(actor.speed.has_value());
  expect_range(*actor.speed, 50, 70, true);
  expect_spans(actor.speed->location, text, "50 to 70");
  const auto& red = std::get<TrafficLightCondition>(conditions[1]);
  ASSERT_EQ(red.lights.size(), 1u);
  EXPECT_EQ(red.colour.value, TrafficLightColour::red);
  const auto& amber = std::get<TrafficLightCondition>(conditions[2]);
  ASSERT_EQ(amber.lights.size(), 2u);
  EXPECT_EQ(amber.lights[1].name, "TL3");
  EXPECT_EQ(amber.colour.value, TrafficLightColour::amber);
  const auto& overtaking = std::get<ActorCondition>(conditions[3]);
  EXPECT_TRUE(overtaking.observed.is_string);
  ASSERT_TRUE(overtaking.in_element.has_value());
  EXPECT_EQ(overtaking.in_element->name, "J1");
  EXPECT_FALSE(overtaking.in_lane.has_value());
  EXPECT_TRUE(file.dynamics.sequences[0].autonomous);
  expect_round_trip(file);
}

TEST(WmgParser, ManoeuvrePhasesSequencesAndWhileConstraints) {
  Parts parts;
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
      "WHEN: [Ego] is [Going Ahead]\n"
      "DO: [Cutter]\n"
      "  PHASE 1: [Drive_CutIn] [-, 60 to 80, 1 to 2] [Ego: 10 to 30, FSL] WHILE: [Clock] <= [3]\n"
      "  PHASE 2: [LaneChangeLeft_Away] [Ego, 70, 2] [Ego: 5, F]\n"
      "    WHILE: [Cutter] [Longitudinal] offset to [Ego] != [12.5]\n"
      "  PHASE 3: [Misc_Cutout] [-, 1, 2] [Ego: 1, R]\n"
      "    WHILE: [Cutter] in [R1.L2] with a [Lateral] offset of [0 to 1]\n"
      "      AND at relative position [SR] with relative heading angle [0 to 10] to [Ego]\n"
      "AND: [Walker]\n"
      "  PHASE 1: [Walk_Cross] [-, 1 to 2, 0] [Ego: 20 to 40, FSR] WHILE: [Walker] in [R1.P1]\n"
      "WHEN: [TL1] is [Green] DO: [Ego] PHASE 1: [Stop] [-, 0, 5] [TL1: 2 to 10, F]\n"
      "END\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  ASSERT_EQ(file.dynamics.sequences.size(), 2u);
  const Ssms& first = file.dynamics.sequences[0];
  EXPECT_FALSE(first.autonomous);
  ASSERT_EQ(first.sequences.size(), 2u);
  EXPECT_EQ(first.sequences[0].actor.name, "Cutter");
  ASSERT_EQ(first.sequences[0].phases.size(), 3u);

  const ManoeuvrePhase& cut_in = first.sequences[0].phases[0];
  EXPECT_EQ(cut_in.number.value, 1);
  EXPECT_EQ(cut_in.type.text, "Drive_CutIn");
  expect_spans(cut_in.type.location, text, "Drive_CutIn");
  EXPECT_FALSE(cut_in.agent.agent.has_value());
  expect_range(cut_in.agent.first, 60, 80, true);
  expect_spans(cut_in.agent.first.location, text, "60 to 80");
  expect_range(cut_in.agent.second, 1, 2, true);
  EXPECT_EQ(cut_in.relative.reference.name, "Ego");
  expect_range(cut_in.relative.distance, 10, 30, true);
  EXPECT_EQ(cut_in.relative.relative_location.value, RelativeLocation::front_side_left);
  ASSERT_TRUE(cut_in.while_constraint.has_value());
  const auto& timer = std::get<TimerConstraint>(*cut_in.while_constraint);
  EXPECT_EQ(timer.timer.name, "Clock");
  EXPECT_EQ(timer.comparison.value, Comparison::less_equal);
  expect_range(timer.value, 3, 3, false);

  const ManoeuvrePhase& away = first.sequences[0].phases[1];
  ASSERT_TRUE(away.agent.agent.has_value());
  EXPECT_EQ(away.agent.agent->name, "Ego");
  const auto& offset = std::get<OffsetConstraint>(*away.while_constraint);
  EXPECT_EQ(offset.actor.name, "Cutter");
  EXPECT_EQ(offset.relation.value, PositionRelation::longitudinal);
  EXPECT_EQ(offset.reference.name, "Ego");
  EXPECT_EQ(offset.comparison.value, Comparison::not_equal);
  expect_range(offset.value, 12.5, 12.5, false);

  const ManoeuvrePhase& cut_out = first.sequences[0].phases[2];
  EXPECT_EQ(cut_out.type.text, "Misc_CutOut");  // the grammar document's spelling, read
  const auto& lane = std::get<LaneConstraint>(*cut_out.while_constraint);
  EXPECT_EQ(lane.lane.lane.name, "L2");
  ASSERT_TRUE(lane.placement.has_value());
  ASSERT_EQ(lane.placement->offsets.size(), 1u);
  EXPECT_EQ(lane.placement->relative_position->value, RelativeLocation::side_right);
  expect_range(*lane.placement->relative_heading, 0, 10, true);
  EXPECT_EQ(lane.placement->reference.name, "Ego");

  const ManoeuvrePhase& walk = first.sequences[1].phases.at(0);
  EXPECT_EQ(walk.type.text, "Walk_Cross");
  EXPECT_FALSE(std::get<LaneConstraint>(*walk.while_constraint).placement.has_value());
  EXPECT_EQ(file.dynamics.sequences[1].sequences.at(0).phases.at(0).type.text, "Stop");
  EXPECT_TRUE(file.dynamics.end_conditions.empty());
  expect_round_trip(file);
}

TEST(WmgParser, EndConditionsJoinedByOr) {
  Parts parts;
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\nWHEN: [Ego] is [Stopped]\n"
      "DO: AUTO\n"
      "END: [Clock] > [30] OR Collision OR [Ego] [Lateral] offset to [Npc] < [0.5]\n"
      "  OR [Ego] in [R1.L2] AND at relative position [RSL] to [Npc]\n";
  Level2File file = parse_ok(parts.text());
  const std::vector<EndCondition>& ends = file.dynamics.end_conditions;
  ASSERT_EQ(ends.size(), 4u);
  EXPECT_EQ(std::get<TimerConstraint>(ends[0]).comparison.value, Comparison::greater);
  EXPECT_TRUE(std::holds_alternative<CollisionCondition>(ends[1]));
  EXPECT_EQ(std::get<OffsetConstraint>(ends[2]).reference.name, "Npc");
  const auto& lane = std::get<LaneConstraint>(ends[3]);
  EXPECT_TRUE(lane.placement->offsets.empty());
  EXPECT_EQ(lane.placement->relative_position->value, RelativeLocation::rear_side_left);
  EXPECT_FALSE(lane.placement->relative_heading.has_value());
  expect_round_trip(file);
}

// ---- environment, internal elements, traffic -------------------------------------------------

TEST(WmgParser, EnvironmentWithEveryPart) {
  Parts parts;
  parts.environment =
      "ENVIRONMENT ELEMENTS:\nDO: [Storm]\n"
      "Wind [5 to 25] Cloudiness [6 to 8] Particulates [Smoke and Pollution]\n"
      "Rainfall [Heavy Rain: 8 to 30]\n"
      "Snowfall [Moderate Snow (visibility: 50 to 400)]\n"
      "Time of the day [05:30 to 9:05]\n"
      "Illumination [Night Dark] with ['Moonlight'] as light source\n"
      "at [-5 to 10] degree elevation AND [RSR] position\n"
      "Connectivity [Communication: V2V: WiFi, Positioning: Galileo]\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  const Environment& e = file.environment;
  EXPECT_EQ(e.id.name, "Storm");
  expect_range(*e.wind, 5, 25, true);
  expect_range(e.cloudiness, 6, 8, true);
  EXPECT_EQ(e.particulates->text, "Smoke and Pollution");
  EXPECT_EQ(e.rainfall.type.text, "Heavy Rain");
  expect_range(e.rainfall.intensity, 8, 30, true);
  EXPECT_EQ(e.snowfall->type.text, "Moderate Snow");
  expect_range(e.snowfall->visibility, 50, 400, true);
  ASSERT_TRUE(e.time_of_day.has_value());
  expect_range(*e.time_of_day, 5 * 3600 + 30 * 60, 9 * 3600 + 5 * 60, true);
  expect_spans(e.time_of_day->location, text, "05:30 to 9:05");
  EXPECT_EQ(e.illumination.text, "Night Dark");
  EXPECT_TRUE(e.light_source.is_string);
  ASSERT_TRUE(e.light_source_position.has_value());
  expect_range(e.light_source_position->elevation, -5, 10, true);
  EXPECT_EQ(e.light_source_position->position.value, RelativeLocation::rear_side_right);
  ASSERT_TRUE(e.connectivity.has_value());
  EXPECT_FALSE(e.connectivity->none);
  EXPECT_EQ(e.connectivity->link->text, "V2V");
  EXPECT_EQ(e.connectivity->technology->text, "WiFi");
  EXPECT_EQ(e.connectivity->positioning->text, "Galileo");
  expect_round_trip(file);
}

TEST(WmgParser, EnvironmentMinimalParts) {
  Parts parts;
  parts.environment =
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nCloudiness [3]\nRainfall [Light Rain: 0]\n"
      "Time of the day [12:00]\nIllumination [Artificial] with [Headlamp] as light source\n"
      "Connectivity [None]\n";
  Level2File file = parse_ok(parts.text());
  EXPECT_FALSE(file.environment.wind.has_value());
  EXPECT_FALSE(file.environment.snowfall.has_value());
  expect_range(*file.environment.time_of_day, 12 * 3600, 12 * 3600, false);
  EXPECT_TRUE(file.environment.connectivity->none);
  expect_round_trip(file);
}

TEST(WmgParser, InternalElementsAndTrafficModel) {
  Parts parts;
  parts.internal = "INTERNAL ELEMENTS: 'ego sensors nominal'\n";
  parts.traffic =
      "TRAFFIC ELEMENTS:\nINITIAL CENTROID [C1] in [R1] at [50 to 100] to [J1]\n"
      "AND CENTROID [C2] in [R2] at [20] to [J1]\n"
      "DO: TRAFFIC [F1]: [C1: R1.L1, C2: R2.L2] at [300 to 900, 30 to 50]\n"
      "TRAFFIC [F2]: [C2: R2.L1, C1: R1.L2] at [100, 40]\n";
  std::string text = parts.text();
  Level2File file = parse_ok(text);
  ASSERT_TRUE(file.internal_elements.has_value());
  EXPECT_EQ(file.internal_elements->text, "ego sensors nominal");
  ASSERT_TRUE(file.traffic.has_value());
  ASSERT_EQ(file.traffic->centroids.size(), 2u);
  EXPECT_EQ(file.traffic->centroids[0].id.name, "C1");
  EXPECT_EQ(file.traffic->centroids[0].road.name, "R1");
  expect_range(file.traffic->centroids[0].distance, 50, 100, true);
  EXPECT_EQ(file.traffic->centroids[1].reference.name, "J1");
  ASSERT_EQ(file.traffic->flows.size(), 2u);
  const TrafficFlow& flow = file.traffic->flows[0];
  EXPECT_EQ(flow.source.name, "C1");
  EXPECT_EQ(flow.destination_lane.lane.name, "L2");
  expect_range(flow.first, 300, 900, true);
  expect_spans(flow.second.location, text, "30 to 50");
  expect_range(file.traffic->flows[1].second, 40, 40, false);
  expect_round_trip(file);
}

// ---- enumerations ----------------------------------------------------------------------------

TEST(WmgParser, TheLongestMatchingPhraseWins) {
  Parts parts;
  parts.scenery = scenery_with_roads(road("Roadway edge features [Shoulder (grass)]\n"));
  Level2File file = parse_ok(parts.text());
  EXPECT_EQ(file.scenery.roads.at(0).edge_feature->text, "Shoulder (grass)");
}

// ---- corpus and round trip -------------------------------------------------------------------

// The level-2 files of the corpus (the level-1 ones, *_level1.sdl, are tested in
// wmg_level1_test.cpp).
std::vector<std::filesystem::path> level2_corpus() {
  std::vector<std::filesystem::path> files;
  for (const auto& path : scenfuzz::test::files_in(test::wmg_corpus_dir(), {".sdl"}))
    if (detect_wmg_level(scenfuzz::test::load(path)) == 2) files.push_back(path);
  return files;
}

TEST(WmgCorpus, HasTheTenScenariosAndEachParsesWithoutDiagnostics) {
  std::vector<std::filesystem::path> files = level2_corpus();
  std::vector<std::string> names;
  for (const auto& path : files) names.push_back(path.filename().string());
  EXPECT_EQ(
      names,
      (std::vector<std::string>{
          "cut_in.sdl", "cut_out.sdl", "give_way_t_junction.sdl", "lead_vehicle_decelerating.sdl",
          "oblique_crossroads.sdl", "pedestrian_crossing.sdl", "pedestrian_past_side_road.sdl",
          "side_road_pull_out.sdl", "signalised_junction.sdl", "stationary_obstacle.sdl"}));
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    SourceFile file = scenfuzz::test::load(path);
    Level2ParseResult result = parse_level2(file);
    EXPECT_TRUE(result.file.has_value()) << format_diagnostics(file, result.diagnostics);
    EXPECT_TRUE(result.diagnostics.all().empty()) << format_diagnostics(file, result.diagnostics);
  }
}

TEST(WmgCorpus, EveryFileRoundTripsThroughThePrinter) {
  std::vector<std::filesystem::path> files = level2_corpus();
  ASSERT_FALSE(files.empty());
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    Level2ParseResult result = parse_level2(scenfuzz::test::load(path));
    ASSERT_TRUE(result.file.has_value());
    expect_round_trip(*result.file);
  }
}

TEST(WmgCorpus, TheCutInSearchesSpeedsAndGaps) {
  Level2ParseResult result =
      parse_level2(scenfuzz::test::load(test::wmg_corpus_dir() / "cut_in.sdl"));
  ASSERT_TRUE(result.file.has_value());
  const Dynamics& dynamics = result.file->dynamics;
  EXPECT_EQ(dynamics.initialisation.relative.at(0).actor.name, "Cutter");
  EXPECT_TRUE(dynamics.initialisation.relative.at(0).offsets.at(0).offset.is_range);
  const ManoeuvrePhase& cut_in = dynamics.sequences.at(0).sequences.at(0).phases.at(1);
  EXPECT_EQ(cut_in.type.text, "LaneChangeRight_CutIn");
  EXPECT_TRUE(cut_in.agent.first.is_range);
  EXPECT_TRUE(cut_in.relative.distance.is_range);
}

// ---- printer ---------------------------------------------------------------------------------

TEST(WmgPrinter, WritesNumbersAsPlainDecimals) {
  EXPECT_EQ(range_text(NumberRange{20, 40.5, true, {}}), "20 to 40.5");
  EXPECT_EQ(range_text(NumberRange{-3, -3, false, {}}), "-3");
  EXPECT_EQ(range_text(NumberRange{0.0000001, 1e21, true, {}}),
            "0.0000001 to 1000000000000000000000");
}

TEST(WmgPrinter, ADifferentValueMakesADifferentTree) {
  Parts parts;
  Level2File file = parse_ok(parts.text());
  Level2File changed = file;
  changed.environment.cloudiness.high = 1;
  EXPECT_FALSE(changed == file);
  changed = file;
  changed.environment.cloudiness.is_range = true;
  EXPECT_FALSE(changed == file);
}

}  // namespace
}  // namespace scenfuzz::wmg
