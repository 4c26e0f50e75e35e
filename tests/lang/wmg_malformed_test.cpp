// Malformed WMG SDL level 2: each case is a small file with one mistake. The front end must not
// crash, must fail, and must point its first error at the mistake with a message that says what
// it expected. Then: every truncation of a valid file, error recovery (independent errors are all
// reported, one mistake gives one error) and the error limit.
//
// Every parse first runs in a forked child (a death test), so a front end that crashes fails the
// one case that crashed instead of taking the whole test binary down.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/parser.hpp"
#include "tests/lang/malformed_harness.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::Parts;
using test::road;
using test::scenery_with_roads;

using scenfuzz::test::error_lines;
using scenfuzz::test::errors_of;
using scenfuzz::test::MalformedCase;
using scenfuzz::test::replaced;

// Parses every text in a forked child: see malformed_harness.hpp.
bool parse_survives(const std::vector<std::string>& texts, const std::string& label) {
  return scenfuzz::test::parse_survives(
      texts, label, [](const std::string& text) { (void)parse_level2(SourceFile("t.sdl", text)); });
}

const Parts kParts;
const std::string kHeader = kParts.header;
const std::string kScenery = kParts.scenery;
const std::string kDynamics = kParts.dynamics;
const std::string kEnvironment = kParts.environment;
// Lines 1-17: header 1-2, scenery 3-6, dynamics 7-11, environment 12-17.
const std::string kBase = kParts.text();
// A road R1 on lines 7-15.
const std::string kRoad = kHeader + scenery_with_roads(road()) + kDynamics + kEnvironment;
const std::string kJunctionText =
    "J1: Junction type [Crossroads] as [X]\n"
    "which has [Traffic light] connection control and [2] connections with [R1, R2]\n"
    "Angles between roads [R1 -> R2] [90]\n"
    "Road lane connections [R1.L1 -> R2.L1]\n"
    "Dimensions [Width: 10, Depth: 10]\n";
// A junction J1 on lines 5-9, then the road.
const std::string kJunction =
    kHeader + scenery_with_roads(road(), kJunctionText) + kDynamics + kEnvironment;
const std::string kPhaseDynamics =
    "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\nWHEN: [Ego] is [Going Ahead]\n"
    "DO: [Npc]\nPHASE 1: [Drive_CutIn] [-, 60 to 80, 1 to 2] [Ego: 10 to 30, FSL]\nEND\n";
// One manoeuvre phase on line 11.
const std::string kPhases = kHeader + kScenery + kPhaseDynamics + kEnvironment;
const std::string kTraffic = kBase +
                             "TRAFFIC ELEMENTS:\nINITIAL: CENTROID [C1] in [R1] at [10] to [J1]\n"
                             "DO: TRAFFIC [F1]: [C1: R1.L1, C1: R1.L1] at [1, 2]\n";

// ---- one mistake, one first error ------------------------------------------------------------

std::vector<MalformedCase> malformed_cases() {
  return {
      {"empty_file", "", 1, 1, "the file is empty: expected a level-2 scenario starting with"},
      {"only_comments", "# nothing\n   # here\n", 1, 1, "the file is empty"},
      {"unterminated_string", replaced(kBase, "AUTHOR: 'a'", "AUTHOR: 'abc"), 2, 9,
       "unterminated string: expected a closing '"},
      {"double_quoted_string", replaced(kBase, "AUTHOR: 'a'", "AUTHOR: \"a\""), 2, 9,
       "strings are written in single quotes: 'text'"},
      {"bad_character", replaced(kBase, "[R1.L1]\n", "[R1.L1] @\n"), 8, 35,
       "unexpected character '@'"},
      {"number_with_exponent", replaced(kBase, "Cloudiness [0]", "Cloudiness [1e5]"), 14, 13,
       "'1e5' is not a number: write plain decimals"},
      {"number_with_unit", replaced(kBase, "Cloudiness [0]", "Cloudiness [5okta]"), 14, 13,
       "'5okta' is not a number"},
      {"decimal_point_without_digits", replaced(kBase, "Cloudiness [0]", "Cloudiness [5.]"), 14, 13,
       "expected digits after the decimal point"},
      {"decimal_point_without_leading_digit", replaced(kBase, "Cloudiness [0]", "Cloudiness [.5]"),
       14, 13, "a number needs a digit before its decimal point (write 0.5)"},
      {"number_out_of_range",
       replaced(kBase, "Cloudiness [0]", "Cloudiness [" + std::string(400, '9') + "]"), 14, 13,
       "is out of range"},
      {"missing_version", replaced(kBase, "VERSION: 1.0\n", ""), 1, 1,
       "expected 'VERSION' at the start of the file, found 'AUTHOR'"},
      {"version_without_minor_part", replaced(kBase, "VERSION: 1.0", "VERSION: 1"), 1, 10,
       "expected a version number such as 1.0 after 'VERSION:', found number '1'"},
      {"missing_author", replaced(kBase, "AUTHOR: 'a'\n", ""), 2, 1,
       "expected 'AUTHOR: 'name'' after the version, found 'SCENERY'"},
      {"two_extension_lines",
       replaced(kBase, "AUTHOR: 'a'\n", "EXTENSION: None\nAUTHOR: 'a'\nEXTENSION: 'x'\n"), 4, 1,
       "the header has two EXTENSION lines"},
      {"npc_behaviour_unknown_value",
       replaced(kBase, "AUTHOR: 'a'\n", "AUTHOR: 'a'\nNPC BEHAVIOUR: Fast\n"), 3, 16,
       "unknown NPC behaviour 'Fast'; expected one of Reactive, Scripted"},
      {"npc_behaviour_in_lower_case",
       replaced(kBase, "AUTHOR: 'a'\n", "AUTHOR: 'a'\nNPC BEHAVIOUR: scripted\n"), 3, 16,
       "unknown NPC behaviour 'scripted'; did you mean 'Scripted'? Expected one of Reactive, "
       "Scripted"},
      {"npc_behaviour_quoted",
       replaced(kBase, "AUTHOR: 'a'\n", "AUTHOR: 'a'\nNPC BEHAVIOUR: 'Scripted'\n"), 3, 16,
       "expected the NPC behaviour (Reactive, Scripted), found string 'Scripted': it takes no "
       "quoted names"},
      {"npc_behaviour_without_colon",
       replaced(kBase, "AUTHOR: 'a'\n", "AUTHOR: 'a'\nNPC BEHAVIOUR Scripted\n"), 3, 15,
       "expected ':' after 'NPC BEHAVIOUR', found 'Scripted'"},
      {"two_npc_behaviour_lines",
       replaced(kBase, "AUTHOR: 'a'\n",
                "NPC BEHAVIOUR: Scripted\nAUTHOR: 'a'\nNPC BEHAVIOUR: Reactive\n"),
       4, 1, "the header has two NPC BEHAVIOUR lines; keep one"},
      {"scenery_without_do", replaced(kBase, "DO: 'd'", "'d'"), 4, 1,
       "expected 'DO' after 'SCENERY ELEMENTS:', found string 'd'"},
      {"empty_junction_list", replaced(kBase, "Junctions: None", "Junctions:"), 6, 1,
       "expected 'None' or a junction (J1: Junction type [...] ...) after 'Junctions:'"},
      {"road_without_colon", replaced(kRoad, "R1: START", "R1 START"), 7, 1,
       "expected 'None' or a road (R1: START ...) after 'Roads:', found 'R1'"},
      {"inverted_range", replaced(kRoad, "Length [100]", "Length [40 to 20]"), 14, 9,
       "inverted range: the lower bound 40 is above the upper bound 20"},
      {"range_without_to", replaced(kRoad, "Length [100]", "Length [20.0 30]"), 14, 14,
       "expected 'to' or ']' after the range's lower bound 20.0, found number '30'"},
      {"nan_as_number", replaced(kBase, "Cloudiness [0]", "Cloudiness [nan]"), 14, 13,
       "'nan' is not a finite number: the cloudiness must be a number such as 20.5"},
      {"inf_as_upper_bound", replaced(kBase, "Cloudiness [0]", "Cloudiness [0 to inf]"), 14, 18,
       "'inf' is not a finite number"},
      {"range_where_one_number_is_expected",
       replaced(kRoad, "speed limit of [100]", "speed limit of [100 to 120]"), 8, 73,
       "the speed limit is a single number, not a range"},
      {"negative_sign_without_number", replaced(kRoad, "Length [100]", "Length [- to 5]"), 14, 11,
       "expected a number after '-' for the road's length, found 'to'"},
      {"unknown_manoeuvre_type", replaced(kPhases, "[Drive_CutIn]", "[Drive_Cutin]"), 11, 11,
       "unknown manoeuvre type 'Drive_Cutin'; did you mean 'Drive_CutIn'? Expected one of "
       "Drive_CutIn, Drive_CutOut,"},
      {"unknown_road_type", replaced(kRoad, "[Motorway]", "[Motorways]"), 8, 12,
       "unknown road type 'Motorways'; did you mean 'Motorway'? Expected one of Motorway, Radial "
       "road"},
      {"unknown_multiword_value", replaced(kRoad, "[Traffic lane]", "[Trafic lane]"), 10, 49,
       "unknown lane type 'Trafic lane'; did you mean 'Traffic lane'?"},
      {"quoted_name_where_none_is_allowed",
       replaced(kRoad, "Road banking angle [Level Plane]", "Road banking angle ['flat']"), 12, 56,
       "found string 'flat': it takes no quoted names"},
      {"road_id_expected", replaced(kJunction, "with [R1, R2]", "with [R1, Road2]"), 6, 76,
       "expected a road id such as R1 for a connected road, found 'Road2'"},
      {"lane_without_lane_id", replaced(kBase, "Vehicle [Ego] in [R1.L1]", "Vehicle [Ego] in [R1]"),
       8, 30, "expected '.' and a lane id after 'R1' (a lane is written R1.L1)"},
      {"bad_lane_id", replaced(kBase, "Vehicle [Ego] in [R1.L1]", "Vehicle [Ego] in [R1.X1]"), 8,
       31, "expected a lane id such as L1 or P1 for the actor's lane, found 'X1'"},
      {"actor_named_like_a_road", replaced(kBase, "Vehicle [Ego]", "Vehicle [R2]"), 8, 19,
       "'R2' has the form of a road id; the actor needs an ID that is not R<n>, L<n> or P<n>"},
      {"missing_close_bracket", replaced(kBase, "DO: [E]", "DO: [E"), 13, 7,
       "expected ']' after the environment, found 'Cloudiness'"},
      {"misspelt_keyword", replaced(kJunction, "Junction type", "Junction typ"), 5, 25,
       "expected 'Junction type' after 'J1:', found 'typ'"},
      {"lane_count_mismatch", replaced(kRoad, "lanes [1] as [R1.L1]", "lanes [2] as [R1.L1]"), 9,
       54, "the count says 2 lanes but the list has 1"},
      {"whole_number_expected", replaced(kRoad, "lanes [1]", "lanes [1.5]"), 9, 48,
       "expected a whole number for the number of lanes, found number '1.5'"},
      {"connection_count_mismatch", replaced(kJunction, "[2] connections", "[3] connections"), 6,
       71, "the count says 3 connections but the list has 2"},
      {"angle_count_mismatch", replaced(kJunction, "[R1 -> R2] [90]", "[R1 -> R2] [90, 80]"), 7, 33,
       "the junction has 1 road pair but 2 angles: give one angle per pair"},
      {"dimensions_without_width_or_diameter",
       replaced(kJunction, "Dimensions [Width: 10, Depth: 10]", "Dimensions [Radius: 5]"), 9, 13,
       "expected 'Width: ..., Depth: ...' or 'Diameter: ...' in the junction's dimensions"},
      {"missing_article", replaced(kRoad, "in a [Rural]", "in [Rural]"), 9, 4,
       "expected 'a' or 'an' after 'in', found '['"},
      {"first_actor_placed_relatively",
       replaced(kBase, "[R1.L1]\nWHEN", "[R1.L1] with a [Lateral] offset of [1]\nWHEN"), 8, 35,
       "the first actor is placed absolutely"},
      {"second_actor_without_placement",
       replaced(kBase, "[R1.L1]\nWHEN", "[R1.L1] AND Vehicle [B] in [R1.L2]\nWHEN"), 9, 1,
       "expected 'AND at relative position' after the lane of 'B'"},
      {"missing_when", replaced(kBase, "WHEN: [Ego] is [Going Ahead]\n", ""), 9, 1,
       "expected 'WHEN:' and the first manoeuvre sequence after the initialisation, found 'DO'"},
      {"unknown_observed_manoeuvre", replaced(kBase, "[Going Ahead]", "[Going ahead]"), 9, 17,
       "unknown observed manoeuvre 'Going ahead'; did you mean 'Going Ahead'?"},
      {"phase_numbered_out_of_order", replaced(kPhases, "PHASE 1", "PHASE 2"), 11, 7,
       "expected PHASE 1: the phases of a sequence are numbered 1, 2, 3, ... in order"},
      {"unknown_relative_location", replaced(kPhases, "10 to 30, FSL]", "10 to 30, FL]"), 11, 62,
       "unknown relative location 'FL'; did you mean"},
      {"agent_parameters_missing_comma", replaced(kPhases, "60 to 80, 1 to 2", "60 to 80 1 to 2"),
       11, 37, "expected ',' after the agent's first parameter, found number '1'"},
      {"while_without_comparison", replaced(kPhases, "FSL]\n", "FSL] WHILE: [Clock] is [3]\n"), 11,
       82,
       "expected a comparison (timer), '[Lateral]' or '[Longitudinal]' (offset) or 'in [R1.L1]' "
       "(lane) after '[Clock]', found 'is'"},
      {"missing_dynamic_end", replaced(kBase, "DO: AUTO\nEND\n", "DO: AUTO\n"), 11, 1,
       "expected 'END' after the manoeuvre sequences, found 'ENVIRONMENT'"},
      {"missing_rainfall", replaced(kBase, "Rainfall [Light Rain: 0]\n", ""), 15, 1,
       "expected 'Rainfall' after the cloudiness and particulates, found 'Time'"},
      {"invalid_time_of_day", replaced(kBase, "[Any]", "[25:00 to 26:00]"), 16, 18,
       "invalid time of day '25:00': expected hours 0-24 and minutes 00-59"},
      {"inverted_time_range", replaced(kBase, "[Any]", "[18:00 to 08:00]"), 16, 18,
       "inverted range: the lower bound 18:00 is above the upper bound 08:00"},
      {"snowfall_without_visibility",
       replaced(kBase, "Time of the day", "Snowfall [Light Snow]\nTime of the day"), 16, 21,
       "expected '(' after the snowfall type (Light Snow (visibility: ...)), found ']'"},
      {"traffic_flow_without_at", replaced(kTraffic, "C1: R1.L1] at [1, 2]", "C1: R1.L1] [1, 2]"),
       20, 42, "expected 'at' after the flow's source and destination, found '['"},
      {"text_after_the_last_section",
       replaced(kBase, "as light source\n", "as light source\nextra\n"), 18, 1,
       "expected the end of the file, found 'extra'"},
      {"sections_out_of_order", std::string(kHeader) + kScenery + kEnvironment + kDynamics, 7, 1,
       "expected 'DYNAMIC ELEMENTS' after the scenery, found 'ENVIRONMENT'"},
  };
}

class WmgMalformedInput : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(WmgMalformedInput, FirstErrorPointsAtTheMistake) {
  const MalformedCase& c = GetParam();
  SCOPED_TRACE(c.name);
  if (!parse_survives({c.text}, c.name)) return;  // do not crash the test binary in-process

  SourceFile file("t.sdl", c.text);
  Level2ParseResult result = parse_level2(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  EXPECT_FALSE(result.file.has_value()) << "accepted:\n" << c.text;
  std::vector<const Diagnostic*> errors = errors_of(result.diagnostics);
  ASSERT_FALSE(errors.empty()) << c.text;
  EXPECT_EQ(errors[0]->location.line, c.line) << all;
  EXPECT_EQ(errors[0]->location.column, c.column) << all;
  EXPECT_THAT(errors[0]->message, ::testing::HasSubstr(c.message)) << all;
}

INSTANTIATE_TEST_SUITE_P(Wmg, WmgMalformedInput, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) {
                           return case_info.param.name;
                         });

TEST(WmgMalformedCases, ThereAreEnoughAndNamesAreUnique) {
  std::vector<MalformedCase> cases = malformed_cases();
  EXPECT_GE(cases.size(), 30u);
  std::set<std::string> names;
  for (const MalformedCase& c : cases) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

TEST(WmgMalformedCases, TheBaseTextsAreValid) {
  for (const std::string* text : {&kBase, &kRoad, &kJunction, &kPhases, &kTraffic}) {
    SourceFile file("t.sdl", *text);
    Level2ParseResult result = parse_level2(file);
    EXPECT_TRUE(result.file.has_value()) << format_diagnostics(file, result.diagnostics) << *text;
  }
}

// ---- truncation ------------------------------------------------------------------------------

// A valid file whose every part is mandatory at its end (no optional trailing section or
// element), so that every proper prefix is incomplete.
std::string truncation_file() {
  return kHeader + scenery_with_roads(road(), kJunctionText) +
         "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1] at [0, 1] at heading angle [0]\n"
         "AND Vehicle [Npc] in [R1.L1] with a [Longitudinal] offset of [10 to 20]\n"
         "AND at relative position [F] with relative heading angle [0] to [Ego]\n"
         "AND Global timer [T] = [0]\n"
         "WHEN: [Ego] is [Going Ahead] at a speed of [10 to 20] AND [TL1] is [Red]\n"
         "DO: [Npc] PHASE 1: [Stop] [-, 0, 1 to 2] [Ego: 10, F] WHILE: [T] < [3]\n"
         "PHASE 2: [Stopped] [Ego, 0, 0] [Ego: 5, F]\n"
         "END: [T] > [20] OR Collision\n"
         "INTERNAL ELEMENTS: 'notes'\n"
         "ENVIRONMENT ELEMENTS:\nDO: [E]\nWind [0 to 5] Cloudiness [1 to 2]\n"
         "Particulates [Marine] Rainfall [Heavy Rain: 5 to 10]\n"
         "Snowfall [Heavy Snow (visibility: 10 to 50)] Time of the day [10:00 to 11:30]\n"
         "Illumination [Night Lit] with [Street Lighting] as light source\n";
}

TEST(WmgTruncation, EveryPrefixIsAnErrorAndNeverACrash) {
  const std::string text = truncation_file();
  {
    SourceFile file("t.sdl", text);
    Level2ParseResult whole = parse_level2(file);
    ASSERT_TRUE(whole.file.has_value()) << format_diagnostics(file, whole.diagnostics);
  }
  // Up to the end of the last word: dropping only the final line break leaves a valid file.
  std::size_t end = text.find_last_not_of('\n') + 1;
  std::vector<std::string> prefixes;
  for (std::size_t length = 0; length < end; ++length) prefixes.push_back(text.substr(0, length));
  if (!parse_survives(prefixes, "a prefix")) return;
  for (const std::string& prefix : prefixes) {
    Level2ParseResult result = parse_level2(SourceFile("t.sdl", prefix));
    EXPECT_FALSE(result.file.has_value()) << "a prefix of " << prefix.size() << " bytes parsed";
    EXPECT_TRUE(result.diagnostics.has_errors()) << prefix.size();
  }
}

// ---- recovery --------------------------------------------------------------------------------

TEST(WmgRecovery, IndependentErrorsInRoadsPhasesAndSectionsAreAllReportedInOrder) {
  std::string bad_road = road("", "Length [40 to 20] AND Lane width [3.5]\n");     // line 14
  std::string second_road = road("", "Length [100] AND Lane width [3.5 3.75]\n");  // line 23
  second_road.replace(0, 2, "R2");
  const std::string text =
      kHeader + scenery_with_roads(bad_road + second_road) +    // roads on lines 7-24
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"  // 25-26
      "WHEN: [Ego] is [Going Ahead]\nDO: [Npc]\n"               // 27-28
      "PHASE 1: [Drive_Cutin] [-, 1, 2] [Ego: 1, F]\n"          // 29
      "PHASE 2: [Stop] [-, 1, 2] [Ego: 1, F]\n"
      "PHASE 3: [Stop] [-, 1 2] [Ego: 1, F]\n"  // 31
      "END\n"
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nCloudiness [0]\nRainfall [Light Rain: x]\n"  // 36
      "Time of the day [Any]\nIllumination [Day] with [Sun] as light source\n";
  if (!parse_survives({text}, "independent errors")) return;
  SourceFile file("t.sdl", text);
  Level2ParseResult result = parse_level2(file);
  EXPECT_EQ(error_lines(result.diagnostics), (std::vector<std::uint32_t>{14, 23, 29, 31, 36}))
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgRecovery, AJunctionErrorStillLetsTheRoadsBeChecked) {
  std::string junction = replaced(kJunctionText, "[Crossroads]", "[Crossroad]");  // line 5
  std::string bad_road = road("", "Length [100] AND Lane width []\n");            // line 18
  const std::string text =
      kHeader + scenery_with_roads(bad_road, junction) + kDynamics + kEnvironment;
  if (!parse_survives({text}, "junction then road")) return;
  SourceFile file("t.sdl", text);
  Level2ParseResult result = parse_level2(file);
  EXPECT_EQ(error_lines(result.diagnostics), (std::vector<std::uint32_t>{5, 18}))
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgRecovery, OneMistakeGivesOneError) {
  // A missing ']' in the first road must not make the second road, the dynamics or the
  // environment report anything.
  std::string second_road = road();
  second_road.replace(0, 2, "R2");
  const std::string text =
      kHeader +
      scenery_with_roads(replaced(road(), "[Level plane]", "[Level plane") + second_road) +
      kDynamics + kEnvironment;
  if (!parse_survives({text}, "one mistake")) return;
  SourceFile file("t.sdl", text);
  Level2ParseResult result = parse_level2(file);
  EXPECT_EQ(errors_of(result.diagnostics).size(), 1u)
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgRecovery, SemanticErrorsDoNotStopTheParse) {
  // An inverted range and a count mismatch leave the text well-formed: both are reported, and so
  // is the syntax error after them.
  const std::string text = replaced(
      replaced(replaced(kRoad, "Length [100]", "Length [9 to 1]"), "lanes [1]", "lanes [3]"),
      "Cloudiness [0]", "Cloudiness [0 1]");
  if (!parse_survives({text}, "semantic errors")) return;
  SourceFile file("t.sdl", text);
  Level2ParseResult result = parse_level2(file);
  EXPECT_EQ(error_lines(result.diagnostics), (std::vector<std::uint32_t>{9, 14, 23}))
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgRecovery, ManyErrorsStopAtTheLimit) {
  std::string phases;
  for (int i = 1; i <= 200; ++i)
    phases += "PHASE " + std::to_string(i) + ": [Drive_Cutin] [-, 1, 2] [Ego: 1, F]\n";
  const std::string text = kHeader + kScenery +
                           "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1]\n"
                           "WHEN: [Ego] is [Going Ahead]\nDO: [Npc]\n" +
                           phases + "END\n" + kEnvironment;
  if (!parse_survives({text}, "many errors")) return;
  Level2ParseResult result = parse_level2(SourceFile("t.sdl", text));
  EXPECT_EQ(result.diagnostics.error_count(), Diagnostics::kErrorLimit);
}

TEST(WmgRecovery, GarbageNeverHangsOrCrashes) {
  std::vector<std::string> texts = {
      std::string(10000, '['),
      std::string(5000, ']'),
      "PHASE PHASE PHASE END END END",
      "VERSION: 1.0 AUTHOR: 'a' SCENERY ELEMENTS: SCENERY ELEMENTS: DYNAMIC ELEMENTS:",
      "R1: START R1: START R1: START",
      "WHEN: WHEN: WHEN: [",
      std::string("\0\xff\xfe", 3)};
  std::string repeated;
  for (int i = 0; i < 2000; ++i) repeated += "AND ";
  texts.push_back(kHeader + kScenery + "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R1.L1] " +
                  repeated);
  if (!parse_survives(texts, "garbage")) return;
  for (const std::string& text : texts)
    EXPECT_TRUE(parse_level2(SourceFile("t.sdl", text)).diagnostics.has_errors());
}

// The formatted message shows file:line:column, the line and a caret under the mistake.
TEST(WmgDiagnosticFormat, CaretUnderTheMistake) {
  const std::string text = replaced(kPhases, "[Drive_CutIn]", "[Drive_Cutin]");
  SourceFile file("cut.sdl", text);
  Level2ParseResult result = parse_level2(file);
  ASSERT_FALSE(result.diagnostics.all().empty());
  std::string formatted = format_diagnostic(file, result.diagnostics.all()[0]);
  EXPECT_THAT(formatted, ::testing::HasSubstr("cut.sdl:11:11: error: unknown manoeuvre type"));
  EXPECT_THAT(formatted, ::testing::HasSubstr("\n  PHASE 1: [Drive_Cutin]"));
  EXPECT_THAT(formatted, ::testing::HasSubstr("\n            ^~~~~~~~~~~"));
}

}  // namespace
}  // namespace scenfuzz::wmg
