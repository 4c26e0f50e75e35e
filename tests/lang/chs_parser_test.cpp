// CH-Scenario's entity module: the grammar's worked example, laid out as docs/ch-scenario.md
// reads it, gives every value at its place; the grammar's own key spellings and a file without
// section headers read the same; each single mistake is reported first at its line and column
// with what was expected; independent mistakes are all reported; no truncation crashes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/chs/parser.hpp"
#include "lang/chs/printer.hpp"
#include "lang/source_file.hpp"
#include "tests/lang/malformed_harness.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz::chs {
namespace {

using scenfuzz::test::error_lines;
using scenfuzz::test::MalformedCase;
using scenfuzz::test::replaced;

// Line numbers in the comments: the malformed cases below point into them.
const std::string kExample =
    "# The grammar's worked example: a minibus on a narrow road in a typhoon.\n"  // 1
    "import from MAP\n"                                                           // 2
    "  length: 400\n"                                                             // 3
    "  width: 50\n"                                                               // 4
    "RoadNetwork\n"                                                               // 5
    "  road → name narrow_road\n"                                                 // 6
    "    left boundary: (0.0, 50.0) (400.0, 50.0)\n"                              // 7
    "    center lines: (0.0, 25.0) (400.0, 25.0)\n"                               // 8
    "    right boundary: (0.0, 0.0)\n"                                            // 9
    "                    (400.0, 0.0)\n"                                          // 10
    "Weather\n"                                                                   // 11
    "  cloudiness: 1.0\n"                                                         // 12
    "  wetness: 1.0\n"                                                            // 13
    "  air_pressure: 1.0\n"                                                       // 14
    "  precipitation: 1.0\n"                                                      // 15
    "  wind_intensity: 1.0\n"                                                     // 16
    "  visibility: 0.4\n"                                                         // 17
    "NaturalDisaster\n"                                                           // 18
    "  MeteorologicalDisaster\n"                                                  // 19
    "    rainstorm: 0\n"                                                          // 20
    "    sandstorm: 0\n"                                                          // 21
    "    typhoon: 1\n"                                                            // 22
    "    tornado: 0\n"                                                            // 23
    "  GeologicalDisaster\n"                                                      // 24
    "    debrisflow: 0\n"                                                         // 25
    "    landslide: 0\n"                                                          // 26
    "    collapse: 0\n"                                                           // 27
    "SpecialHighRisk\n"                                                           // 28
    "  rough: 0\n"                                                                // 29
    "  iceRoad: 0\n"                                                              // 30
    "  steepDescentAhead: 1\n"                                                    // 31
    "  muddy: 0\n"                                                                // 32
    "  wade: 1\n"                                                                 // 33
    "Entity\n"                                                                    // 34
    "  StaticEntity1\n"                                                           // 35
    "    name: pedestrians\n"                                                     // 36
    "    overview: little boy\n"                                                  // 37
    "  StaticEntity2\n"                                                           // 38
    "    name: traffic_light\n"                                                   // 39
    "    overview: red light\n"                                                   // 40
    "  DynamicEntity1\n"                                                          // 41
    "    name: minibus\n"                                                         // 42
    "    timestamp: 2022 年 1 月 30 日 17:30:42\n"                                // 43
    "    speed: 45.0\n"                                                           // 44
    "    acceleration: 0.0\n"                                                     // 45
    "    track: curve to the east\n"                                              // 46
    "    aim: The First People's Hospital\n";                                     // 47

// The grammar's two constraints (its "concrete syntax related cases"), a statement a line.
const std::string kConstraints =
    "ConstraintList\n"                                                                     // 48
    "  constraint1 relate with forward_vehicle, current_vehicle\n"                         // 49
    "    safety_protocol: (wiper = true) && (lighton = true) && (hazardlighton = true)\n"  // 50
    "    event: when guard do action\n"                                                    // 51
    "    action: position++\n"                                                             // 52
    "    guard: first_car_parked == false || second_car_parked == false\n"                 // 53
    "    probability: 0.2\n"                                                               // 54
    "  constraint2 relate with currentvehicle, edge\n"                                     // 55
    "    safety_protocol: ((dist > safedistance) = true) && (emergencybreak = false)\n"    // 56
    "    event: when guard do action\n"                                                    // 57
    "    action: parked = false\n"                                                         // 58
    "    guard: wait > 5\n"                                                                // 59
    "    probability: 0.8\n";                                                              // 60

ParseResult parse_text(const std::string& text) { return parse(SourceFile("t.chs", text)); }

std::string messages(const Diagnostics& diagnostics) {
  std::string all;
  for (const Diagnostic& d : diagnostics.all())
    all += std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
           d.message + "\n";
  return all;
}

TEST(ChsParser, TheGrammarsWorkedExampleGivesEveryValueAtItsPlace) {
  ParseResult result = parse_text(kExample);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  const File& file = *result.file;
  EXPECT_EQ(file.map.kind, MapSource::Kind::blank);
  EXPECT_EQ(file.map.length.value, 400);
  EXPECT_EQ(file.map.width.value, 50);
  ASSERT_EQ(file.roads.size(), 1u);
  const Road& road = file.roads[0];
  EXPECT_EQ(road.name.text, "narrow_road");
  EXPECT_EQ(road.name.location.line, 6u);
  EXPECT_EQ(road.name.location.column, 15u);  // "→" is one character
  ASSERT_EQ(road.left_boundary.size(), 2u);
  EXPECT_EQ(road.left_boundary[1].x, 400);
  EXPECT_EQ(road.left_boundary[1].y, 50);
  ASSERT_EQ(road.centre_lines.size(), 2u);
  EXPECT_EQ(road.centre_lines[0].y, 25);
  ASSERT_EQ(road.right_boundary.size(), 2u);  // the second point on a line of its own
  EXPECT_EQ(road.right_boundary[1].x, 400);
  EXPECT_EQ(road.right_boundary[1].location.line, 10u);
  EXPECT_EQ(road.right_boundary[1].location.column, 21u);
  EXPECT_EQ(file.weather.cloudiness.value, 1);
  EXPECT_EQ(file.weather.air_pressure.value, 1);
  EXPECT_EQ(file.weather.visibility.value, 0.4);
  EXPECT_EQ(file.weather.visibility.location.line, 17u);
  EXPECT_TRUE(file.disaster.typhoon.value);
  EXPECT_FALSE(file.disaster.rainstorm.value);
  EXPECT_FALSE(file.disaster.landslide.value);
  EXPECT_TRUE(file.high_risk.steep_descent_ahead.value);
  EXPECT_TRUE(file.high_risk.wade.value);
  EXPECT_FALSE(file.high_risk.ice_road.value);
  ASSERT_EQ(file.static_entities.size(), 2u);
  EXPECT_EQ(file.static_entities[0].name.text, "pedestrians");
  EXPECT_EQ(file.static_entities[0].overview.text, "little boy");
  EXPECT_EQ(file.static_entities[1].overview.text, "red light");
  ASSERT_EQ(file.dynamic_entities.size(), 1u);
  const DynamicEntity& minibus = file.dynamic_entities[0];
  EXPECT_EQ(minibus.name.text, "minibus");
  EXPECT_EQ(minibus.timestamp.text, "2022 年 1 月 30 日 17:30:42");
  EXPECT_EQ(minibus.speed.value, 45);
  EXPECT_EQ(minibus.speed.location.line, 44u);
  EXPECT_EQ(minibus.speed.location.column, 12u);
  EXPECT_EQ(minibus.acceleration.value, 0);
  EXPECT_EQ(minibus.track.text, "curve to the east");
  EXPECT_EQ(minibus.aim.text, "The First People's Hospital");
}

// The fuzzer's seed (scripts/fuzz.sh) is the example and the grammar's constraints: it must read.
TEST(ChsParser, TheFuzzersSeedFileReadsWithoutAMistake) {
  const auto path = scenfuzz::test::lang_data_dir() / "chs" / "typhoon_minibus.chs";
  std::optional<SourceFile> source = read_source_file(path.string());
  ASSERT_TRUE(source) << path;
  ParseResult result = parse(*source);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  EXPECT_EQ(result.file->constraints.size(), 2u);
  EXPECT_EQ(result.file->dynamic_entities.size(), 1u);
}

// What the printer writes reads back as the same tree, and prints the same again.
TEST(ChsPrinter, TheExamplePrintsBackToTheSameTree) {
  ParseResult first = parse_text(kExample + kConstraints);
  ASSERT_TRUE(first.file) << messages(first.diagnostics);
  const std::string printed = print(*first.file);
  ParseResult again = parse_text(printed);
  ASSERT_TRUE(again.file) << messages(again.diagnostics) << printed;
  EXPECT_TRUE(*again.file == *first.file) << printed;
  EXPECT_EQ(print(*again.file), printed);
  EXPECT_THAT(printed, ::testing::HasSubstr("  road → name narrow_road\n"
                                            "    left boundary: (0, 50) (400, 50)\n"));
  EXPECT_THAT(printed, ::testing::HasSubstr("    guard: ((first_car_parked) == (false)) || "
                                            "((second_car_parked) == (false))\n"));
  // A changed value is a different tree.
  File changed = *first.file;
  changed.dynamic_entities[0].speed.value = 50;
  EXPECT_FALSE(changed == *first.file);
}

// The BNF's form: a named map, no section headers for the weather and the conditions, entities
// told apart by their keys, and the defaults for what is not given.
TEST(ChsParser, ANamedMapWithoutSectionHeadersReadsTheSame) {
  ParseResult result = parse_text(
      "map: san_francisco\n"
      "cloudiness: 0.2\n"
      "iceroad: true\n"
      "Entities\n"
      "name: truck\n"
      "speed: 30\n"
      "name: tree\n"
      "overview: an old oak\n");
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  const File& file = *result.file;
  EXPECT_EQ(file.map.kind, MapSource::Kind::named);
  EXPECT_EQ(file.map.name.text, "san_francisco");
  EXPECT_EQ(file.weather.cloudiness.value, 0.2);
  EXPECT_EQ(file.weather.visibility.value, 1);  // a clear day unless said otherwise
  EXPECT_EQ(file.weather.air_pressure.value, 1);
  EXPECT_TRUE(file.high_risk.ice_road.value);
  ASSERT_EQ(file.dynamic_entities.size(), 1u);
  EXPECT_EQ(file.dynamic_entities[0].name.text, "truck");
  EXPECT_EQ(file.dynamic_entities[0].speed.value, 30);
  ASSERT_EQ(file.static_entities.size(), 1u);
  EXPECT_EQ(file.static_entities[0].overview.text, "an old oak");
}

TEST(ChsParser, ARoadLineOpensTheRoadNetworkAndAnEntityMayHaveAPosition) {
  ParseResult result = parse_text(
      "import from MAP\n  length: 100\n  width: 20\n"
      "road r\n  left boundary: (0, 17) (100, 17)\n  centre line: (0, 10) (100, 10)\n"
      "  right boundary: (0, 3) (100, 3)\n"
      "Entity\n  name: car\n  speed: 40\n  position: (5.5, 8)\n"
      "  name: cone\n  overview: a traffic cone\n  position: (60, 9)\n");
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  ASSERT_EQ(result.file->roads.size(), 1u);
  EXPECT_EQ(result.file->roads[0].right_boundary[1].y, 3);
  ASSERT_TRUE(result.file->dynamic_entities[0].position);
  const Point& car = *result.file->dynamic_entities[0].position;
  EXPECT_EQ(car.x, 5.5);
  EXPECT_EQ(car.x_at.column, 14u);
  EXPECT_EQ(car.x_at.length, 3u);
  EXPECT_EQ(car.y_at.column, 19u);
  ASSERT_TRUE(result.file->static_entities[0].position);
  EXPECT_EQ(result.file->static_entities[0].position->x, 60);
  // The printer writes positions back.
  const ParseResult back = parse_text(print(*result.file));
  ASSERT_TRUE(back.file) << messages(back.diagnostics);
  EXPECT_EQ(*back.file, *result.file);
}

// An expression as text, fully bracketed: what the parser made of the precedence.
std::string shown(const Expression& e) {
  switch (e.kind) {
    case Expression::Kind::name: return e.text;
    case Expression::Kind::number: return std::to_string(static_cast<int>(e.number));
    case Expression::Kind::boolean: return e.boolean ? "true" : "false";
    case Expression::Kind::negation: return "!" + shown(e.operands[0]);
    case Expression::Kind::binary:
      return "(" + shown(e.operands[0]) + " " + e.text + " " + shown(e.operands[1]) + ")";
  }
  return "?";
}

TEST(ChsParser, TheGrammarsConstraintsGiveTheirProtocolsEventsAndProbabilities) {
  ParseResult result = parse_text(kExample + kConstraints);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  const std::vector<Constraint>& constraints = result.file->constraints;
  ASSERT_EQ(constraints.size(), 2u);
  const Constraint& first = constraints[0];
  EXPECT_EQ(first.name.text, "constraint1");
  ASSERT_EQ(first.related.size(), 2u);
  EXPECT_EQ(first.related[1].text, "current_vehicle");
  EXPECT_EQ(first.related[1].location.column, 44u);
  ASSERT_EQ(first.safety_protocols.size(), 1u);
  EXPECT_EQ(shown(first.safety_protocols[0]),
            "(((wiper == true) && (lighton == true)) && (hazardlighton == true))");
  ASSERT_EQ(first.events.size(), 1u);  // its guard and action on lines of their own
  const Event& parked = first.events[0];
  EXPECT_EQ(shown(parked.guard), "((first_car_parked == false) || (second_car_parked == false))");
  ASSERT_EQ(parked.action.size(), 1u);
  EXPECT_EQ(parked.action[0].kind, Statement::Kind::increment);
  EXPECT_EQ(parked.action[0].target.text, "position");
  EXPECT_EQ(parked.probability.value, 0.2);
  const Constraint& second = constraints[1];
  EXPECT_EQ(shown(second.safety_protocols[0]),
            "(((dist > safedistance) == true) && (emergencybreak == false))");
  ASSERT_EQ(second.events.size(), 1u);
  EXPECT_EQ(shown(second.events[0].guard), "(wait > 5)");
  ASSERT_EQ(second.events[0].action.size(), 1u);
  EXPECT_EQ(second.events[0].action[0].kind, Statement::Kind::assign);
  EXPECT_EQ(shown(second.events[0].action[0].value), "false");
  EXPECT_EQ(second.events[0].probability.value, 0.8);
}

TEST(ChsParser, AnEventWrittenOnOneLineAndAListsOwnProtocol) {
  ParseResult result =
      parse_text(kExample +
                 "ConstraintList\n"
                 "  safety_protocol: not (speed > 60)\n"
                 "  c1 relate with minibus\n"
                 "    event: when wait > 5 and not parked do position++; speed = 3\n"
                 "    event: when (a < 1 or b) do c--\n");
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  ASSERT_EQ(result.file->safety_protocols.size(), 1u);
  EXPECT_EQ(shown(result.file->safety_protocols[0]), "!(speed > 60)");
  const std::vector<Event>& events = result.file->constraints.at(0).events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(shown(events[0].guard), "((wait > 5) && !parked)");
  ASSERT_EQ(events[0].action.size(), 2u);
  EXPECT_EQ(events[0].action[1].target.text, "speed");
  EXPECT_EQ(shown(events[0].action[1].value), "3");
  EXPECT_EQ(events[0].probability.value, 1);  // fires whenever its guard holds
  EXPECT_EQ(shown(events[1].guard), "((a < 1) || b)");
  EXPECT_EQ(events[1].action.at(0).kind, Statement::Kind::decrement);
}

std::vector<MalformedCase> malformed_cases() {
  const std::string& b = kExample;
  return {
      {"boundary_outside_a_road",
       replaced(b, "Weather\n", "Weather\n  left boundary: (0, 1) (2, 1)\n"), 12, 3,
       "a boundary belongs to a road: start one with 'road NAME'"},
      {"position_of_two_points",
       replaced(b, "speed: 45.0\n", "speed: 45.0\n    position: (1, 2) (3, 4)\n"), 45, 22,
       "an entity's position is one point, (x, y)"},
      {"position_not_a_point", replaced(b, "speed: 45.0\n", "speed: 45.0\n    position: 12\n"), 45,
       15, "expected '(' to start a point such as (0.0, 25.0), found '1'"},
      {"misspelt_key", replaced(b, "acceleration: 0.0", "acceleratiobn: 0.0"), 45, 5,
       "unknown key 'acceleratiobn' in an entity; did you mean 'acceleration'?"},
      {"weather_out_of_range", replaced(b, "cloudiness: 1.0", "cloudiness: 1.5"), 12, 15,
       "the cloudiness must be from 0 to 1, not 1.5"},
      {"speed_not_a_number", replaced(b, "speed: 45.0", "speed: fast"), 44, 12,
       "expected a number for the speed in km/h, found 'fast'"},
      {"speed_nan", replaced(b, "speed: 45.0", "speed: nan"), 44, 12,
       "the speed in km/h must be a finite number"},
      {"flag_not_a_flag", replaced(b, "typhoon: 1", "typhoon: 2"), 22, 14,
       "expected 0, 1, true or false for typhoon, found '2'"},
      {"no_map", replaced(b, "import from MAP\n  length: 400\n  width: 50\n", ""), 1, 1,
       "the file gives no map"},
      {"blank_map_without_width", replaced(b, "  width: 50\n", ""), 2, 1,
       "'import from MAP' needs the map's 'length:' and 'width:'"},
      {"map_too_long", replaced(b, "length: 400", "length: 4e9"), 3, 11,
       "the map's length in metres must be from 1 to 100000"},
      {"road_with_one_point", replaced(b, " (400.0, 25.0)", ""), 6, 3,
       "road narrow_road needs at least two points in its centre line"},
      {"point_without_comma", replaced(b, "(400.0, 50.0)", "(400.0 50.0)"), 7, 39,
       "expected ',' between the point's x and y, found '5'"},
      {"point_not_closed", replaced(b, "(400.0, 25.0)\n", "(400.0, 25.0\n"), 8, 43,
       "expected ')' to end the point, found the end of the line"},
      {"key_given_twice", replaced(b, "  wetness: 1.0\n", "  wetness: 1.0\n  wetness: 0.5\n"), 14,
       3, "'wetness' is given twice"},
      {"entity_named_twice", replaced(b, "name: traffic_light", "name: pedestrians"), 39, 11,
       "entity 'pedestrians' is described twice"},
      {"overview_of_a_dynamic_entity",
       replaced(b, "    speed: 45.0\n", "    speed: 45.0\n    overview: a bus\n"), 45, 5,
       "'overview' belongs to a static entity, and this one is dynamic"},
      {"speed_of_a_static_entity",
       replaced(b, "    overview: red light\n", "    overview: red light\n    speed: 3\n"), 41, 5,
       "'speed' belongs to a dynamic entity, and this one is static"},
      {"dynamic_entity_without_speed", replaced(b, "    speed: 45.0\n", ""), 41, 3,
       "dynamic entity 'minibus' needs a 'speed:' in km/h"},
      {"entity_without_name", replaced(b, "    name: minibus\n", ""), 41, 3,
       "this entity has no 'name:'"},
      {"points_without_a_boundary",
       replaced(b, "    left boundary: (0.0, 50.0)", "    (0.0, 50.0)"), 7, 5,
       "points belong to a road's boundary or centre line"},
      {"line_that_is_nothing", replaced(b, "Weather\n", "Weather report\n"), 11, 1,
       "expected a section (such as 'Weather'), 'key: value' or a road's points"},
      {"event_without_when", b + kConstraints + "    event: if wait > 5 do action\n", 61, 12,
       "expected 'when' to start the event, found 'if'"},
      {"guard_never_given",
       b + "ConstraintList\n  c1 relate with minibus\n    event: when guard do position++\n", 50, 5,
       "this event's guard is never given: add 'guard: ...'"},
      {"probability_above_one", replaced(b + kConstraints, "probability: 0.8", "probability: 1.5"),
       60, 18, "the probability must be from 0 to 1"},
      {"probability_without_event",
       b + "ConstraintList\n  c1 relate with minibus\n    probability: 0.5\n", 50, 5,
       "a probability belongs to an event"},
      {"action_with_a_bad_operator", replaced(b + kConstraints, "position++", "position+"), 52, 21,
       "unexpected character '+'"},
      {"unclosed_parenthesis",
       replaced(b + kConstraints, "(hazardlighton = true)", "(hazardlighton = true"), 50, 81,
       "expected ')' to close the '(', found the end of the line"},
      {"constraint_without_name", replaced(b + kConstraints, "constraint1 relate", "relate"), 49, 3,
       "expected the constraint's name before 'relate with'"},
      {"relate_with_nobody",
       replaced(b + kConstraints, "forward_vehicle, current_vehicle", "forward_vehicle,"), 49, 43,
       "expected an entity's name after 'relate with'"},
      {"constraint_named_twice",
       replaced(b + kConstraints, "constraint2 relate", "constraint1 relate"), 55, 3,
       "constraint constraint1 is described twice"},
      {"guard_outside_a_constraint", b + "ConstraintList\n  guard: wait > 5\n", 49, 3,
       "a guard belongs to a constraint"},
      {"guard_with_a_dangling_operator",
       replaced(b + kConstraints, "guard: wait > 5", "guard: wait >"), 59, 18,
       "expected a name, a number, true, false or '(', found the end of the line"},
      {"road_network_on_a_named_map",
       replaced(b, "import from MAP\n  length: 400\n  width: 50\n", "map: san_francisco\n"), 4, 3,
       "a road network is laid on a blank map ('import from MAP') only"},
      {"map_given_twice", replaced(b, "  width: 50\n", "  width: 50\nmap: san_francisco\n"), 5, 1,
       "the map is given twice"},
      {"road_without_a_name", replaced(b, "road → name narrow_road", "road →"), 6, 9,
       "expected the road's name, one word, after 'road'"},
      {"road_name_of_two_words", replaced(b, "road → name narrow_road", "road → name narrow road"),
       6, 15, "expected the road's name, one word, after 'road'"},
      {"empty_text", replaced(b, "track: curve to the east", "track:"), 46, 11,
       "expected the entity's track after the colon"},
  };
}

class ChsMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(ChsMalformed, FirstErrorIsAtTheMistake) {
  const MalformedCase& c = GetParam();
  ASSERT_TRUE(scenfuzz::test::parse_survives({c.text}, c.name,
                                             [](const std::string& t) { (void)parse_text(t); }));
  ParseResult result = parse_text(c.text);
  EXPECT_FALSE(result.file);
  scenfuzz::test::expect_first_error(c, result.diagnostics, messages(result.diagnostics));
}

INSTANTIATE_TEST_SUITE_P(Chs, ChsMalformed, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) {
                           return case_info.param.name;
                         });

TEST(ChsParser, IndependentMistakesAreAllReported) {
  std::string text = replaced(kExample, "cloudiness: 1.0", "cloudiness: 7");
  text = replaced(text, "typhoon: 1", "typhon: 1");
  text = replaced(text, "speed: 45.0", "speed: -3");
  ParseResult result = parse_text(text);
  EXPECT_THAT(error_lines(result.diagnostics), ::testing::ElementsAre(12, 22, 44))
      << messages(result.diagnostics);
}

TEST(ChsParser, NoTruncationOfTheExampleCrashes) {
  std::vector<std::string> texts;
  for (std::size_t n = 0; n <= kExample.size(); ++n) texts.push_back(kExample.substr(0, n));
  ASSERT_TRUE(scenfuzz::test::parse_survives(texts, "truncations",
                                             [](const std::string& t) { (void)parse_text(t); }));
  // Cut within the last line, the file misses only its aim, which it does not need.
  for (std::size_t n = 0; n < kExample.size(); ++n) {
    ParseResult result = parse_text(kExample.substr(0, n));
    if (!result.file) {
      EXPECT_TRUE(result.diagnostics.has_errors()) << n;
    }
  }
}

}  // namespace
}  // namespace scenfuzz::chs
