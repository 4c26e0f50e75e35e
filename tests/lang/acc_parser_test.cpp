// The accident formalism (.acc, CarSim's templates): the CarSim worked example, laid out as
// docs/accident.md reads it, gives every value at its place and prints back to an equal tree;
// keywords and values read in any case, properties in any order, comments and a one-line layout;
// each single mistake is reported first at its line and column with what was expected;
// independent mistakes are all reported; no truncation of the example crashes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "lang/accident/parser.hpp"
#include "lang/accident/printer.hpp"
#include "lang/source_file.hpp"
#include "tests/lang/malformed_harness.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz::accident {
namespace {

using scenfuzz::test::error_lines;
using scenfuzz::test::MalformedCase;
using scenfuzz::test::replaced;

// Line numbers in the comments: the malformed cases below point into them.
const std::string kExample =
    "// CarSim's worked example: at a crossroad, a truck coming from a car's left hits it on "
    "its\n"                                               // 1
    "// left side; the car then skids into a tree.\n"     // 2
    "// Static objects\n"                                 // 3
    "STATIC [\n"                                          // 4
    "  ROAD [\n"                                          // 5
    "    KIND = crossroad;\n"                             // 6
    "  ]\n"                                               // 7
    "  TREE [\n"                                          // 8
    "    ID = tree1;\n"                                   // 9
    "    COORD = ( 8.5, 9 );\n"                           // 10
    "  ]\n"                                               // 11
    "]\n"                                                 // 12
    "// Dynamic objects\n"                                // 13
    "DYNAMIC [\n"                                         // 14
    "  VEHICLE [\n"                                       // 15
    "    ID = car1;\n"                                    // 16
    "    KIND = car;\n"                                   // 17
    "    INITDIRECTION = north;\n"                        // 18
    "    CHAIN [\n"                                       // 19
    "      EVENT [ KIND = driving_forward; ]\n"           // 20
    "    ]\n"                                             // 21
    "  ]\n"                                               // 22
    "  VEHICLE [\n"                                       // 23
    "    ID = truck1;\n"                                  // 24
    "    KIND = truck;\n"                                 // 25
    "    INITDIRECTION = east;\n"                         // 26
    "    CHAIN [\n"                                       // 27
    "      CRITICAL_EVENT [ KIND = driving_forward; ]\n"  // 28
    "    ]\n"                                             // 29
    "  ]\n"                                               // 30
    "]\n"                                                 // 31
    "// Collisions\n"                                     // 32
    "ACCIDENT [\n"                                        // 33
    "  COLLISION [\n"                                     // 34
    "    ACTOR = truck1, front;\n"                        // 35
    "    VICTIM = car1, leftside;\n"                      // 36
    "    COORD = ( 1.75, -1.75 );\n"                      // 37
    "  ]\n"                                               // 38
    "  COLLISION [\n"                                     // 39
    "    ACTOR = car1, front;\n"                          // 40
    "    VICTIM = tree1, unknown;\n"                      // 41
    "  ]\n"                                               // 42
    "]\n";                                                // 43

ParseResult parse_text(const std::string& text) { return parse(SourceFile("t.acc", text)); }

std::string messages(const Diagnostics& diagnostics) {
  std::string all;
  for (const Diagnostic& d : diagnostics.all())
    all += std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " +
           d.message + "\n";
  return all;
}

TEST(AccParser, TheCarSimWorkedExampleGivesEveryValueAtItsPlace) {
  ParseResult result = parse_text(kExample);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  EXPECT_TRUE(result.diagnostics.all().empty()) << messages(result.diagnostics);
  const File& file = *result.file;
  EXPECT_EQ(file.road.kind.value, RoadKind::crossroad);
  EXPECT_EQ(file.road.kind.location.line, 6u);
  EXPECT_EQ(file.road.kind.location.column, 12u);
  EXPECT_EQ(file.static_at.line, 4u);
  EXPECT_EQ(file.dynamic_at.line, 14u);
  EXPECT_EQ(file.accident_at.line, 33u);
  ASSERT_EQ(file.trees.size(), 1u);
  const Tree& tree = file.trees[0];
  EXPECT_EQ(tree.id.text, "tree1");
  EXPECT_EQ(tree.id.location.line, 9u);
  EXPECT_EQ(tree.id.location.column, 10u);
  EXPECT_EQ(tree.coords.x, 8.5);
  EXPECT_EQ(tree.coords.y, 9);
  EXPECT_EQ(tree.coords.x_at.line, 10u);
  EXPECT_EQ(tree.coords.x_at.column, 15u);
  EXPECT_EQ(tree.coords.x_at.length, 3u);
  EXPECT_EQ(tree.coords.y_at.column, 20u);
  EXPECT_EQ(tree.coords.location.column, 13u);
  EXPECT_EQ(tree.coords.location.length, 10u);  // ( 8.5, 9 )
  EXPECT_TRUE(file.lights.empty());
  EXPECT_TRUE(file.crossings.empty());
  EXPECT_TRUE(file.stop_signs.empty());
  ASSERT_EQ(file.vehicles.size(), 2u);
  const Vehicle& car = file.vehicles[0];
  EXPECT_EQ(car.id.text, "car1");
  EXPECT_EQ(car.kind.value, VehicleKind::car);
  EXPECT_EQ(car.kind.location.line, 17u);
  ASSERT_TRUE(car.init_direction);
  EXPECT_EQ(car.init_direction->value, Direction::north);
  EXPECT_EQ(car.init_direction->location.column, 21u);
  EXPECT_FALSE(car.start_sign);
  EXPECT_FALSE(car.end_sign);
  ASSERT_EQ(car.chain.size(), 1u);
  EXPECT_EQ(car.chain[0].kind.value, EventKind::driving_forward);
  EXPECT_FALSE(car.chain[0].critical);
  EXPECT_EQ(car.location.line, 15u);
  const Vehicle& truck = file.vehicles[1];
  EXPECT_EQ(truck.id.text, "truck1");
  EXPECT_EQ(truck.kind.value, VehicleKind::truck);
  EXPECT_EQ(truck.init_direction->value, Direction::east);
  ASSERT_EQ(truck.chain.size(), 1u);
  EXPECT_TRUE(truck.chain[0].critical);
  EXPECT_EQ(truck.chain[0].location.line, 28u);
  EXPECT_EQ(truck.chain[0].location.column, 7u);
  ASSERT_EQ(file.collisions.size(), 2u);
  const Collision& side = file.collisions[0];
  EXPECT_EQ(side.actor.id.text, "truck1");
  EXPECT_EQ(side.actor.part.value, Part::front);
  EXPECT_EQ(side.victim.id.text, "car1");
  EXPECT_EQ(side.victim.id.location.column, 14u);
  EXPECT_EQ(side.victim.part.value, Part::leftside);
  EXPECT_EQ(side.victim.part.location.line, 36u);
  EXPECT_EQ(side.victim.part.location.column, 20u);
  ASSERT_TRUE(side.coords);
  EXPECT_EQ(side.coords->x, 1.75);
  EXPECT_EQ(side.coords->y, -1.75);
  EXPECT_EQ(side.coords->y_at.column, 21u);
  EXPECT_EQ(side.coords->y_at.length, 5u);
  const Collision& tree_hit = file.collisions[1];
  EXPECT_EQ(tree_hit.actor.id.text, "car1");
  EXPECT_EQ(tree_hit.victim.id.text, "tree1");
  EXPECT_EQ(tree_hit.victim.part.value, Part::unknown);
  EXPECT_FALSE(tree_hit.coords);
}

TEST(AccPrinter, TheExamplePrintsBackToTheSameTree) {
  ParseResult first = parse_text(kExample);
  ASSERT_TRUE(first.file) << messages(first.diagnostics);
  const std::string printed = print(*first.file);
  ParseResult again = parse_text(printed);
  ASSERT_TRUE(again.file) << messages(again.diagnostics) << printed;
  EXPECT_TRUE(again.diagnostics.all().empty()) << messages(again.diagnostics);
  EXPECT_TRUE(*again.file == *first.file) << printed;
  EXPECT_EQ(print(*again.file), printed);
  EXPECT_THAT(printed, ::testing::HasSubstr("  TREE [ ID = tree1; COORD = (8.5, 9); ]\n"));
  EXPECT_THAT(printed, ::testing::HasSubstr("      CRITICAL_EVENT [ KIND = driving_forward; ]\n"));
  EXPECT_THAT(printed, ::testing::HasSubstr("    VICTIM = car1, leftside;\n"
                                            "    COORD = (1.75, -1.75);\n"));
  // A changed value is a different tree.
  File changed = *first.file;
  changed.collisions[0].victim.part.value = Part::rear;
  EXPECT_FALSE(changed == *first.file);
}

// Every kind of static object, signs by ID and by place, every event kind, in one file whose
// keywords and values are in mixed case, with `#` comments and properties in any order.
const std::string kEverything =
    "# every construct\n"
    "static [ road [ kind = Straightroad; ]\n"
    "  Light [ coord = (-6, -6); color = RED; id = light1; ]  // properties in any order\n"
    "  LIGHT [ ID = light2; COLOR = inactive; COORD = (6, 6); ]\n"
    "  CROSSING [ COORD = (0, 40.5); ]\n"
    "  STOPSIGN [ COORD = (-4, -12); ] STOPSIGN [ COORD = (4, 12); ]\n"
    "  TREE [ ID = oak; COORD = (1e2, -3.25e1); ] ]\n"
    "DYNAMIC [ VEHICLE [ KIND = truck; ID = t; INITDIRECTION = south; STARTSIGN = light1;\n"
    "  ENDSIGN = (0, -50); CHAIN [ EVENT [ KIND = stop; ] EVENT [ KIND = overtake; ]\n"
    "  EVENT [ KIND = turn_left; ] EVENT [ KIND = turn_right; ] EVENT [ KIND = change_lane_left; "
    "]\n"
    "  critical_event [ KIND = CHANGE_LANE_RIGHT; ] ] ]\n"
    "  VEHICLE [ ID = c; KIND = car; ENDSIGN = oak; ] ]\n"
    "ACCIDENT [ COLLISION [ VICTIM = c, rear; ACTOR = t, front; COORD = (-0.5, +3); ]\n"
    "  COLLISION [ ACTOR = c, rightside; VICTIM = light2, unknown; ] ]\n";

TEST(AccParser, EveryConstructReadsInAnyCaseAndOrder) {
  ParseResult result = parse_text(kEverything);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  const File& file = *result.file;
  EXPECT_EQ(file.road.kind.value, RoadKind::straightroad);
  ASSERT_EQ(file.lights.size(), 2u);
  EXPECT_EQ(file.lights[0].id.text, "light1");
  EXPECT_EQ(file.lights[0].colour.value, Colour::red);
  EXPECT_EQ(file.lights[0].coords.x, -6);
  EXPECT_EQ(file.lights[1].colour.value, Colour::inactive);
  ASSERT_EQ(file.crossings.size(), 1u);
  EXPECT_EQ(file.crossings[0].coords.y, 40.5);
  ASSERT_EQ(file.stop_signs.size(), 2u);
  EXPECT_EQ(file.stop_signs[1].coords.x, 4);
  ASSERT_EQ(file.trees.size(), 1u);
  EXPECT_EQ(file.trees[0].coords.x, 100);
  EXPECT_EQ(file.trees[0].coords.y, -32.5);
  const Vehicle& truck = file.vehicles.at(0);
  EXPECT_EQ(truck.id.text, "t");
  EXPECT_EQ(truck.init_direction->value, Direction::south);
  ASSERT_TRUE(truck.start_sign);
  EXPECT_EQ(truck.start_sign->kind, SignReference::Kind::name);
  EXPECT_EQ(truck.start_sign->name.text, "light1");
  ASSERT_TRUE(truck.end_sign);
  EXPECT_EQ(truck.end_sign->kind, SignReference::Kind::point);
  EXPECT_EQ(truck.end_sign->point.y, -50);
  ASSERT_EQ(truck.chain.size(), 6u);
  EXPECT_EQ(truck.chain[1].kind.value, EventKind::overtake);
  EXPECT_EQ(truck.chain[5].kind.value, EventKind::change_lane_right);
  EXPECT_TRUE(truck.chain[5].critical);
  const Vehicle& car = file.vehicles.at(1);
  EXPECT_FALSE(car.init_direction);
  EXPECT_TRUE(car.chain.empty());
  EXPECT_EQ(car.end_sign->name.text, "oak");
  EXPECT_EQ(file.collisions.at(0).actor.id.text, "t");
  EXPECT_EQ(file.collisions.at(0).coords->y, 3);
  EXPECT_EQ(file.collisions.at(1).victim.id.text, "light2");
  // And it prints back to the same tree.
  const ParseResult back = parse_text(print(file));
  ASSERT_TRUE(back.file) << messages(back.diagnostics) << print(file);
  EXPECT_EQ(*back.file, file);
}

// The parts may come in any order; IDs are names, compared with their case.
TEST(AccParser, PartsInAnyOrderAndIdsKeepTheirCase) {
  const std::string text =
      "ACCIDENT [ COLLISION [ ACTOR = Car1, front; VICTIM = car1, rear; ] ]\n"
      "DYNAMIC [ VEHICLE [ ID = car1; KIND = car; ] VEHICLE [ ID = Car1; KIND = car; ] ]\n"
      "STATIC [ ROAD [ KIND = straightroad; ] ]\n";
  ParseResult result = parse_text(text);
  ASSERT_TRUE(result.file) << messages(result.diagnostics);
  EXPECT_EQ(result.file->collisions[0].actor.id.text, "Car1");
  const ParseResult wrong = parse_text(replaced(text, "ID = Car1", "ID = car2"));
  ASSERT_FALSE(wrong.file);
  EXPECT_THAT(messages(wrong.diagnostics),
              ::testing::HasSubstr("1:32: the ACTOR must name a VEHICLE, and no ID is 'Car1'; "
                                   "did you mean 'car1'?"));
}

// The fuzzer's seed and the corpus: each reads without a mistake and prints back to itself.
TEST(AccParser, TheSeedAndTheCorpusReadWithoutAMistake) {
  std::vector<std::filesystem::path> files =
      scenfuzz::test::files_in(scenfuzz::test::lang_data_dir() / "accident", {".acc"});
  const auto corpus = std::filesystem::path(SCENFUZZ_SOURCE_DIR) / "corpora" / "accident";
  for (const auto& path : scenfuzz::test::files_in(corpus, {".acc"})) files.push_back(path);
  ASSERT_GE(files.size(), 7u);
  for (const auto& path : files) {
    const SourceFile source = scenfuzz::test::load(path);
    ParseResult result = parse(source);
    ASSERT_TRUE(result.file) << path << "\n" << messages(result.diagnostics);
    EXPECT_TRUE(result.diagnostics.all().empty()) << path;
    EXPECT_FALSE(result.file->collisions.empty()) << path;
    const ParseResult back = parse_text(print(*result.file));
    ASSERT_TRUE(back.file) << path;
    EXPECT_EQ(*back.file, *result.file) << path;
  }
}

std::vector<MalformedCase> malformed_cases() {
  const std::string& b = kExample;
  const std::string light =
      "  LIGHT [ ID = light1; COLOR = yellow; COORD = (-6, -6); ]\n";  // becomes line 12
  return {
      {"missing_semicolon", replaced(b, "KIND = crossroad;", "KIND = crossroad"), 7, 3,
       "expected ';' after the road kind, found ']'"},
      {"comma_for_semicolon", replaced(b, "ID = car1;", "ID = car1,"), 16, 14,
       "expected ';' after the ID, found ','"},
      {"misspelt_road_kind", replaced(b, "crossroad;", "crosroad;"), 6, 12,
       "unknown road kind 'crosroad'; did you mean 'crossroad'?"},
      {"unknown_road_kind", replaced(b, "crossroad;", "roundabout;"), 6, 12,
       "unknown road kind 'roundabout': expected crossroad, straightroad, turn_left or "
       "turn_right"},
      {"misspelt_vehicle_kind", replaced(b, "KIND = truck;", "KIND = truk;"), 25, 12,
       "unknown vehicle kind 'truk'; did you mean 'truck'?"},
      {"misspelt_direction", replaced(b, "= north;", "= nord;"), 18, 21,
       "unknown direction 'nord'; did you mean 'north'?"},
      {"misspelt_event_kind", replaced(b, "driving_forward", "driving_foward"), 20, 22,
       "unknown event kind 'driving_foward'; did you mean 'driving_forward'?"},
      {"misspelt_part", replaced(b, "leftside", "left_side"), 36, 20,
       "unknown part 'left_side'; did you mean 'leftside'?"},
      {"colour_not_in_the_list",
       replaced(b, "  ]\n]\n// Dynamic", "  ]\n" + light + "]\n// Dynamic"), 12, 32,
       "unknown colour 'yellow': expected red, orange, green or inactive"},
      {"misspelt_keyword", replaced(b, "INITDIRECTION = north", "INITDIRECTOIN = north"), 18, 5,
       "unknown keyword 'INITDIRECTOIN' in a VEHICLE; did you mean 'INITDIRECTION'?"},
      {"keyword_of_another_bracket", replaced(b, "ID = tree1;", "KIND = tree1;"), 9, 5,
       "KIND does not belong in a TREE, which takes ID or COORD"},
      {"misspelt_part_keyword", replaced(b, "ACCIDENT [", "ACCIDENTS ["), 33, 1,
       "unknown keyword 'ACCIDENTS' in the file; did you mean 'ACCIDENT'?"},
      {"missing_equals", replaced(b, "ID = car1;", "ID car1;"), 16, 8,
       "expected '=' after ID, found 'car1'"},
      {"id_is_a_number", replaced(b, "ID = car1;", "ID = 1;"), 16, 10,
       "expected the ID (a name of letters, digits and '_'), found '1'"},
      {"bad_number", replaced(b, "( 8.5, 9 )", "( 8.5.1, 9 )"), 10, 15, "'8.5.1' is not a number"},
      {"number_with_a_unit", replaced(b, "( 8.5, 9 )", "( 8.5m, 9 )"), 10, 15,
       "'8.5m' is not a number"},
      {"infinite_number", replaced(b, "( 8.5, 9 )", "( 1e999, 9 )"), 10, 15,
       "'1e999' is not a finite number"},
      {"nan_coordinate", replaced(b, "( 8.5, 9 )", "( 8.5, NaN )"), 10, 20,
       "coordinates are finite numbers, not 'NaN'"},
      {"coordinate_out_of_range", replaced(b, "( 1.75, -1.75 )", "( 1.75, -2e6 )"), 37, 21,
       "the y coordinate must be from -100000 to 100000 m, not -2e6"},
      {"inverted_parentheses", replaced(b, "( 8.5, 9 )", ") 8.5, 9 ("), 10, 13,
       "expected '(' to start the coordinates, such as (0, -12.5), found ')'"},
      {"paren_without_comma", replaced(b, "( 8.5, 9 )", "( 8.5 9 )"), 10, 19,
       "expected ',' between the x and y coordinates, found '9'"},
      {"unclosed_paren", replaced(b, "( 8.5, 9 );", "( 8.5, 9 ;"), 10, 22,
       "expected ')' to close the coordinates, found ';'"},
      {"unexpected_character", replaced(b, "KIND = car;", "KIND = car$;"), 17, 15,
       "unexpected character '$'"},
      {"missing_open_bracket", replaced(b, "  TREE [\n", "  TREE\n"), 9, 5,
       "expected '[' after TREE, found 'ID'"},
      {"unclosed_bracket", replaced(b, "    ]\n  ]\n  VEHICLE", "    ]\n  VEHICLE"), 22, 3,
       "expected ']' to close the VEHICLE opened at 15:3, found 'VEHICLE'"},
      {"truncated_file", b.substr(0, b.find("    VICTIM = tree1")), 41, 1,
       "expected ']' to close the COLLISION opened at 39:3, found the end of the file"},
      {"stray_closing_bracket", b + "]\n", 44, 1, "unexpected ']': no bracket is open here"},
      {"duplicate_property", replaced(b, "KIND = car;\n", "KIND = car;\n    KIND = truck;\n"), 18,
       5, "KIND is given twice in this VEHICLE (first at 17:5)"},
      {"part_given_twice", b + "STATIC [ ROAD [ KIND = crossroad; ] ]\n", 44, 1,
       "a second STATIC part (the first is at 4:1)"},
      {"second_road", replaced(b, "  ]\n  TREE", "  ]\n  ROAD [ KIND = straightroad; ]\n  TREE"), 8,
       3, "a second ROAD: a description has one road layout (the first ROAD is at 5:3)"},
      {"duplicate_id", replaced(b, "ID = truck1;", "ID = car1;"), 24, 10,
       "ID 'car1' is already the VEHICLE's at 16:10"},
      {"unknown_collision_victim", replaced(b, "VICTIM = tree1", "VICTIM = tree2"), 41, 14,
       "the VICTIM must name a VEHICLE, a TREE or a LIGHT, and no ID is 'tree2'; did you mean "
       "'tree1'?"},
      {"actor_is_a_tree", replaced(b, "ACTOR = car1", "ACTOR = tree1"), 40, 13,
       "the ACTOR must name a VEHICLE, and 'tree1' is a TREE's ID (at 9:10)"},
      {"actor_is_the_victim", replaced(b, "VICTIM = car1", "VICTIM = truck1"), 36, 14,
       "the VICTIM is the ACTOR, 'truck1': a vehicle does not collide with itself"},
      {"unknown_start_sign", replaced(b, "north;\n", "north;\n    STARTSIGN = light9;\n"), 19, 17,
       "the STARTSIGN must name a LIGHT or a TREE, and no ID is 'light9'"},
      {"end_sign_is_a_vehicle", replaced(b, "north;\n", "north;\n    ENDSIGN = truck1;\n"), 19, 15,
       "the ENDSIGN must name a LIGHT or a TREE, and 'truck1' is a VEHICLE's ID (at 25:10)"},
      {"part_missing_in_actor", replaced(b, "ACTOR = truck1, front;", "ACTOR = truck1;"), 35, 19,
       "expected ',' and the part of the actor that was hit (front, rear, leftside, rightside "
       "or unknown), found ';'"},
      {"empty_file", "", 1, 1,
       "the file describes nothing: a description has a STATIC, a DYNAMIC and an ACCIDENT part"},
      {"only_comments", "// nothing yet\n# still nothing\n", 3, 1, "the file describes nothing"},
      {"missing_accident_part", b.substr(0, b.find("// Collisions")), 32, 1,
       "the file has no ACCIDENT part"},
      {"missing_static_part",
       replaced(b, b.substr(b.find("// Static"), b.find("// Dynamic") - b.find("// Static")), ""),
       34, 1, "the file has no STATIC part"},
      {"static_without_road", replaced(b, "  ROAD [\n    KIND = crossroad;\n  ]\n", ""), 4, 1,
       "the STATIC part has no ROAD"},
      {"tree_without_coord", replaced(b, "    COORD = ( 8.5, 9 );\n", ""), 8, 3,
       "this TREE has no COORD"},
      {"vehicle_without_kind", replaced(b, "    KIND = truck;\n", ""), 23, 3,
       "this VEHICLE has no KIND: add 'KIND = car;' (or truck)"},
      {"event_without_kind", replaced(b, "EVENT [ KIND = driving_forward; ]", "EVENT [ ]"), 20, 7,
       "this EVENT has no KIND"},
      {"empty_chain", replaced(b, "      CRITICAL_EVENT [ KIND = driving_forward; ]\n", ""), 27, 5,
       "this CHAIN lists no EVENT"},
      {"collision_without_victim", replaced(b, "    VICTIM = tree1, unknown;\n", ""), 39, 3,
       "this COLLISION has no VICTIM"},
      {"top_level_object_outside_its_part", "VEHICLE [ ID = car1; KIND = car; ]\n", 1, 1,
       "VEHICLE does not belong in the file, which takes STATIC, DYNAMIC or ACCIDENT"},
  };
}

class AccMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(AccMalformed, FirstErrorIsAtTheMistake) {
  const MalformedCase& c = GetParam();
  ASSERT_TRUE(scenfuzz::test::parse_survives({c.text}, c.name,
                                             [](const std::string& t) { (void)parse_text(t); }));
  ParseResult result = parse_text(c.text);
  EXPECT_FALSE(result.file);
  scenfuzz::test::expect_first_error(c, result.diagnostics, messages(result.diagnostics));
}

INSTANTIATE_TEST_SUITE_P(Acc, AccMalformed, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) {
                           return case_info.param.name;
                         });

// One mistake in each of four brackets: all four are reported, and nothing else.
TEST(AccParser, IndependentMistakesAreAllReported) {
  std::string text = replaced(kExample, "crossroad;", "crosroad;");
  text = replaced(text, "( 8.5, 9 )", "( 8.5 9 )");
  text = replaced(text, "KIND = truck;", "KIND = truk;");
  text = replaced(text, "leftside", "left_side");
  ParseResult result = parse_text(text);
  EXPECT_THAT(error_lines(result.diagnostics), ::testing::ElementsAre(6, 10, 25, 36))
      << messages(result.diagnostics);
}

// A missing `;` and an unclosed bracket do not hide the mistakes after them.
TEST(AccParser, RecoveryGoesOnAfterAMissingSemicolonAndAnUnclosedBracket) {
  std::string text = replaced(kExample, "ID = car1;", "ID = car1");
  text = replaced(text, "    ]\n  ]\n  VEHICLE", "    ]\n  VEHICLE");
  text = replaced(text, "VICTIM = car1, leftside;", "VICTIM = car1, leftsid;");
  ParseResult result = parse_text(text);
  EXPECT_THAT(error_lines(result.diagnostics), ::testing::ElementsAre(17, 22, 35))
      << messages(result.diagnostics);
}

TEST(AccParser, NoTruncationOfTheExampleCrashes) {
  std::vector<std::string> texts;
  for (std::size_t n = 0; n <= kExample.size(); ++n) texts.push_back(kExample.substr(0, n));
  for (std::size_t n = 0; n <= kEverything.size(); ++n) texts.push_back(kEverything.substr(0, n));
  ASSERT_TRUE(scenfuzz::test::parse_survives(texts, "truncations",
                                             [](const std::string& t) { (void)parse_text(t); }));
  // Every cut before the last `]` misses something the file needs, and says so.
  const std::size_t last = kExample.rfind(']');
  for (std::size_t n = 0; n <= last; ++n) {
    ParseResult result = parse_text(kExample.substr(0, n));
    EXPECT_FALSE(result.file) << n;
    EXPECT_TRUE(result.diagnostics.has_errors()) << n;
  }
}

}  // namespace
}  // namespace scenfuzz::accident
