// Malformed WMG SDL level 1: each case is a small file with one mistake. The front end must not
// crash, must fail, and must point its first error at the mistake with a message that says what
// it expected (and the closest spelling, for a misspelt word). Then: every truncation of a valid
// file, error recovery (independent mistakes in different sentences are all reported) and
// garbage.
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
#include "lang/wmg/level1_parser.hpp"
#include "lang/wmg/level1_to_level2.hpp"
#include "tests/lang/malformed_harness.hpp"

namespace scenfuzz::wmg {
namespace {

using scenfuzz::test::error_lines;
using scenfuzz::test::errors_of;
using scenfuzz::test::MalformedCase;
using scenfuzz::test::replaced;

// Parses (and converts what parses) every text in a forked child: see malformed_harness.hpp.
bool parse_survives(const std::vector<std::string>& texts, const std::string& label) {
  return scenfuzz::test::parse_survives(texts, label, [](const std::string& text) {
    Level1ParseResult result = parse_level1(SourceFile("t.sdl", text));
    Diagnostics diagnostics;
    if (result.file) (void)level1_to_level2(*result.file, diagnostics);
  });
}

// Lines 1-11: header 1-2, environment 3, junction 4-5, roads 6-7, actors 8-9, SSMS 10-11.
const std::string kBase =
    "VERSION: 1.0\n"
    "AUTHOR: 'a'\n"
    "During the day, there is a light sky, with heavy rain.\n"
    "There is a crossroad, J1, which has connections with R1 and R2.\n"
    "R1 to R2 is straight ahead.\n"
    "R1 and R2 are straight, minor roads with heavy traffic.\n"
    "Also, R1 has traffic lights.\n"
    "There are 2 vehicles, Ego and Car1.\n"
    "Ego is in R1 and Car1 is in R2.\n"
    "When Ego is driving towards J1, Car1 drives across J1 at its front right.\n"
    "Ego operates autonomously.\n";

// ---- one mistake, one first error ------------------------------------------------------------

std::vector<MalformedCase> malformed_cases() {
  const std::string& b = kBase;
  return {
      {"empty_file", "", 1, 1, "the file is empty: expected a level-1 scenario"},
      {"only_comments", "# nothing\n  # here\n", 1, 1, "the file is empty"},
      {"missing_version", replaced(b, "VERSION: 1.0\n", ""), 1, 1,
       "expected 'VERSION: 1.0' at the start of the file, found 'AUTHOR'"},
      {"version_without_minor_part", replaced(b, "VERSION: 1.0", "VERSION: 1"), 1, 10,
       "expected a version number such as 1.0 after 'VERSION:', found number '1'"},
      {"version_as_a_word", replaced(b, "VERSION: 1.0", "VERSION: one"), 1, 10,
       "expected a version number such as 1.0 after 'VERSION:', found 'one'"},
      {"author_without_quotes", replaced(b, "AUTHOR: 'a'", "AUTHOR: a"), 2, 9,
       "expected the author in single quotes after 'AUTHOR:', found 'a'"},
      {"author_in_double_quotes", replaced(b, "AUTHOR: 'a'", "AUTHOR: \"a\""), 2, 9,
       "strings are written in single quotes"},
      {"misspelt_time_of_day", replaced(b, "During the day", "During the dya"), 3, 12,
       "expected 'day' or 'night' after 'During the', found 'dya'; did you mean 'day'?"},
      {"sentence_starts_in_lower_case", replaced(b, "During the day", "during the day"), 3, 1,
       "found 'during'; did you mean 'During the'?"},
      {"comma_missing_after_time_of_day", replaced(b, "day, there", "day there"), 3, 16,
       "expected ',' after 'During the day', found 'there'"},
      {"unknown_light_condition", replaced(b, "a light sky", "a lite sky"), 3, 28,
       "expected 'light', 'bright' or 'dark' after 'there is a', found 'lite'"},
      {"misspelt_weather_feature", replaced(b, "heavy rain.", "heavy rian."), 3, 44,
       "expected a weather feature (rain, snow, a breeze or particulates: "},
      {"misspelt_weather_feature_suggestion", replaced(b, "heavy rain.", "heavy rian."), 3, 44,
       "found 'heavy'; did you mean 'heavy rain'?"},
      {"environment_without_full_stop", replaced(b, "heavy rain.", "heavy rain"), 4, 1,
       "expected ',', 'and' or '.' after the environment sentence's weather features, found "
       "'There'"},
      {"misspelt_junction_type", replaced(b, "crossroad", "crosroad"), 4, 12,
       "found 'crosroad'; did you mean 'crossroad'?"},
      {"junction_named_like_a_road", replaced(b, "crossroad, J1,", "crossroad, R5,"), 4, 23,
       "'R5' has the form of a road id"},
      {"junction_named_with_a_level2_keyword",
       replaced(replaced(replaced(b, "crossroad, J1,", "crossroad, None,"), "towards J1,",
                         "towards None,"),
                "across J1", "across None"),
       4, 23, "'None' cannot name a junction: it is a level-2 keyword"},
      {"connection_in_the_singular",
       replaced(b, "which has connections with", "which has connection with"), 4, 37,
       "expected 'connections with' after 'has', found 'connection'; did you mean 'connections "
       "with'?"},
      {"junction_road_that_is_not_a_road_id", replaced(b, "with R1 and R2.", "with R1 and Road2."),
       4, 57, "expected '.' after the junction's roads, found 'and'"},
      {"unknown_connection_type", replaced(b, "is straight ahead", "is straight on"), 5, 13,
       "expected the connection type ('straight ahead', 'turning right',"},
      {"several_roads_with_is", replaced(b, "R1 and R2 are straight", "R1 and R2 is straight"), 6,
       11, "expected 'are' after the road names, found 'is'"},
      {"misspelt_road_type", replaced(b, "minor roads", "minor raods"), 6, 25,
       "after 'straight,', found 'minor'; did you mean 'minor roads'?"},
      {"misspelt_amount_of_traffic", replaced(b, "with heavy traffic", "with heavvy traffic"), 6,
       42,
       "expected the amount of traffic ('no', 'light', 'some', 'moderate', 'heavy' or 'a lot "
       "of') after 'with', found 'heavvy'; did you mean 'heavy'?"},
      {"traffic_without_its_word", replaced(b, "with heavy traffic.", "with heavy."), 6, 47,
       "expected 'traffic' after 'with heavy', found '.'"},
      {"misspelt_road_feature", replaced(b, "has traffic lights", "has trafic lights"), 7, 14,
       "found 'trafic'; did you mean 'traffic lights'?"},
      {"actor_count_differs_from_names",
       replaced(b, "There are 2 vehicles", "There are 3 vehicles"), 8, 11,
       "the sentence counts 3 but names 2"},
      {"misspelt_actor_type", replaced(b, "2 vehicles", "2 vehicels"), 8, 13,
       "expected the actor type ('vehicle', 'pedestrian', 'cyclist', 'vehicles', 'pedestrians' "
       "or 'cyclists') after '2', found 'vehicels'"},
      {"actor_count_too_large",
       replaced(b, "There are 2 vehicles", "There are 99999999999999999999 vehicles"), 8, 11,
       "is too large"},
      {"actor_named_like_a_lane", replaced(b, "Ego and Car1.", "Ego and L1."), 8, 31,
       "'L1' has the form of a lane id"},
      {"actor_declared_twice", replaced(b, "Ego and Car1.", "Ego and Ego."), 8, 31,
       "actor Ego is declared twice"},
      {"bad_character", replaced(b, "Ego and Car1.", "Ego and Car1 @."), 8, 36,
       "unexpected character '@'"},
      {"actor_without_location", replaced(b, "Ego is in R1 and Car1 is in R2.", "Ego is in R1."), 8,
       31, "actor Car1 has no location: add 'Car1 is in R1'"},
      {"location_that_is_not_in_the_scenery", replaced(b, "Car1 is in R2", "Car1 is in R7"), 9, 29,
       "'R7' is neither a road nor a junction of the scenery; did you mean 'R1'?"},
      {"road_without_road_sentence", replaced(b, "with R1 and R2.", "with R1, R2 and R3."), 4, 65,
       "road R3 connects to J1 but no road sentence describes it"},
      {"junction_road_named_twice", replaced(b, "with R1 and R2.", "with R2 and R2."), 4, 61,
       "road R2 is named twice among the roads of J1"},
      {"connection_to_a_road_of_another_junction", replaced(b, "R1 to R2 is", "R1 to R9 is"), 5, 7,
       "road R9 is not one of the roads of J1"},
      {"missing_junction_part",
       replaced(b,
                "There is a crossroad, J1, which has connections with R1 and R2.\n"
                "R1 to R2 is straight ahead.\n",
                ""),
       4, 1, "expected 'There is no junction present.' or a junction such as"},
      {"unknown_actor_in_a_phase", replaced(b, "Car1 drives across", "Car2 drives across"), 10, 33,
       "unknown actor 'Car2': no 'There is ...' sentence declares it; did you mean 'Car1'?"},
      {"misspelt_manoeuvre", replaced(b, "Car1 drives across", "Car1 drivs across"), 10, 38,
       "after 'Car1', found 'drivs'; did you mean 'drives'?"},
      {"unknown_place", replaced(b, "across J1", "across J9"), 10, 52,
       "'J9' is not an actor, road or junction of the scenario; did you mean 'J1'?"},
      {"misspelt_relative_position", replaced(b, "front right", "front rigth"), 10, 62,
       "did you mean 'front right'?"},
      {"unknown_traffic_light_colour",
       replaced(b, "When Ego is driving towards J1,",
                "When the traffic light ahead of Ego is blue,"),
       10, 40, "expected 'green', 'amber' or 'red' after 'is', found 'blue'"},
      {"phase_without_comma_after_conditions", replaced(b, "towards J1, Car1", "towards J1 Car1"),
       10, 32, "expected ',' after the conditions, found 'Car1'"},
      {"missing_ssms",
       replaced(b,
                "When Ego is driving towards J1, Car1 drives across J1 at its front right.\n"
                "Ego operates autonomously.\n",
                ""),
       10, 1, "expected 'When ...', what the actors do after the actors' locations"},
      {"missing_actor_under_test", replaced(b, "Ego operates autonomously.\n", ""), 11, 1,
       "expected 'Also, when ...', 'Next, ...' or the actor under test ('Ego operates "
       "autonomously.') after the phases, found end of file"},
      {"misspelt_operates", replaced(b, "Ego operates", "Ego operate"), 11, 5,
       "expected 'operates autonomously' after 'Ego', found 'operate'; did you mean 'operates "
       "autonomously'?"},
      {"text_after_the_last_ssms", b + "Extra words.\n", 12, 1,
       "expected the end of the file or another 'When ...' after the last SSMS, found 'Extra'"},
      {"a_level2_file", "VERSION: 1.0\nAUTHOR: 'a'\nSCENERY ELEMENTS:\nDO: 'd' [S] as:\n", 3, 1,
       "expected the environment sentence 'During the day, there is a ... sky.' after the "
       "header, found 'SCENERY'"},
  };
}

class WmgLevel1MalformedInput : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(WmgLevel1MalformedInput, FirstErrorPointsAtTheMistake) {
  const MalformedCase& c = GetParam();
  SCOPED_TRACE(c.name);
  if (!parse_survives({c.text}, c.name)) return;  // do not crash the test binary in-process

  SourceFile file("t.sdl", c.text);
  Level1ParseResult result = parse_level1(file);
  std::string all = format_diagnostics(file, result.diagnostics);
  EXPECT_FALSE(result.file.has_value()) << "accepted:\n" << c.text;
  std::vector<const Diagnostic*> errors = errors_of(result.diagnostics);
  ASSERT_FALSE(errors.empty()) << c.text;
  EXPECT_EQ(errors[0]->location.line, c.line) << all;
  EXPECT_EQ(errors[0]->location.column, c.column) << all;
  EXPECT_THAT(errors[0]->message, ::testing::HasSubstr(c.message)) << all;
}

INSTANTIATE_TEST_SUITE_P(WmgLevel1, WmgLevel1MalformedInput, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& case_info) {
                           return case_info.param.name;
                         });

TEST(WmgLevel1MalformedCases, ThereAreEnoughAndNamesAreUnique) {
  std::vector<MalformedCase> cases = malformed_cases();
  EXPECT_GE(cases.size(), 20u);
  std::set<std::string> names;
  for (const MalformedCase& c : cases) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

TEST(WmgLevel1MalformedCases, TheBaseTextIsValid) {
  SourceFile file("t.sdl", kBase);
  Level1ParseResult result = parse_level1(file);
  EXPECT_TRUE(result.file.has_value()) << format_diagnostics(file, result.diagnostics);
}

// ---- truncation ------------------------------------------------------------------------------

// A valid file whose every sentence is needed at its end, using every sentence form, so that
// every proper prefix is incomplete.
std::string truncation_file() {
  return "VERSION: 1.0\nAUTHOR: 'a'\n"
         "During the night, there is a dark, 'grey' sky, with light snow, mist and fog and with a "
         "light breeze.\n"
         "There is a T-Junction, J1, which has connections with R1, R2 and R3.\n"
         "R1 to R2 is turning left.\n"
         "R1 is a curved, motorway with a lot of traffic.\nR2 and R3 are straight, 'lanes'.\n"
         "Also, R1 has street lights and 'kerbs'.\n"
         "There are 2 vehicles, Ego and Car1.\nThere is 1 pedestrian, Walker.\n"
         "Ego is in R1, Car1 is in J1 and Walker is in R2.\n"
         "When Ego is driving, at constant speed, towards J1, Car1 is stopped and the traffic "
         "light ahead of Ego is red, Car1 cuts in, decelerating, onto R1 in front of Ego at its "
         "front left, and then drives. And Walker walks across R2. Walker then runs away. Next, "
         "as Walker is stopped, Car1 stops.\nEgo operates autonomously.\n";
}

TEST(WmgLevel1Truncation, EveryPrefixIsAnErrorAndNeverACrash) {
  const std::string text = truncation_file();
  {
    SourceFile file("t.sdl", text);
    Level1ParseResult whole = parse_level1(file);
    ASSERT_TRUE(whole.file.has_value()) << format_diagnostics(file, whole.diagnostics);
  }
  // Up to the final full stop: dropping only the line break after it leaves a valid file.
  std::size_t end = text.find_last_of('.');
  std::vector<std::string> prefixes;
  for (std::size_t length = 0; length <= end; ++length) prefixes.push_back(text.substr(0, length));
  if (!parse_survives(prefixes, "a prefix")) return;
  for (const std::string& prefix : prefixes) {
    Level1ParseResult result = parse_level1(SourceFile("t.sdl", prefix));
    EXPECT_FALSE(result.file.has_value()) << "a prefix of " << prefix.size() << " bytes parsed";
    EXPECT_TRUE(result.diagnostics.has_errors()) << prefix.size();
  }
}

// ---- recovery --------------------------------------------------------------------------------

TEST(WmgLevel1Recovery, IndependentMistakesInDifferentSentencesAreAllReportedInOrder) {
  std::string text = replaced(kBase, "a light sky", "a lite sky");   // line 3
  text = replaced(text, "is straight ahead", "is straight on");      // line 5
  text = replaced(text, "has traffic lights", "has trafic lights");  // line 7
  text = replaced(text, "Car1 drives across", "Car1 drivs across");  // line 10
  if (!parse_survives({text}, "independent mistakes")) return;
  SourceFile file("t.sdl", text);
  Level1ParseResult result = parse_level1(file);
  EXPECT_EQ(error_lines(result.diagnostics), (std::vector<std::uint32_t>{3, 5, 7, 10}))
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgLevel1Recovery, AMissingPartIsReportedOnce) {
  // Without the junction part the sentences after it are still where roads go; nothing else is
  // reported.
  std::string text =
      replaced(kBase, "There is a crossroad, J1, which has connections with R1 and R2.\n", "");
  text = replaced(text, "R1 to R2 is straight ahead.\n", "");
  text = replaced(text, "towards J1", "towards R2");
  text = replaced(text, "across J1", "across R2");
  if (!parse_survives({text}, "missing part")) return;
  SourceFile file("t.sdl", text);
  Level1ParseResult result = parse_level1(file);
  EXPECT_EQ(errors_of(result.diagnostics).size(), 1u)
      << format_diagnostics(file, result.diagnostics);
}

TEST(WmgLevel1Recovery, ManyErrorsStopAtTheLimit) {
  std::string roads;
  for (int i = 1; i <= 200; ++i) roads += "R" + std::to_string(i) + " is a straight, motorwya.\n";
  const std::string text =
      replaced(kBase, "R1 and R2 are straight, minor roads with heavy traffic.\n", roads);
  if (!parse_survives({text}, "many errors")) return;
  Level1ParseResult result = parse_level1(SourceFile("t.sdl", text));
  EXPECT_EQ(result.diagnostics.error_count(), Diagnostics::kErrorLimit);
}

TEST(WmgLevel1Recovery, GarbageNeverHangsOrCrashes) {
  std::vector<std::string> texts = {
      std::string(10000, ','),
      std::string(5000, '.'),
      "When When When When , , , .",
      "VERSION: 1.0 During the day, there is a light sky. When Ego drives, Ego drives, and and and",
      "There is a There is a There is a",
      std::string("\0\xff\xfe", 3),
      "[ ] { } -> == < >",
  };
  std::string chained = kBase.substr(0, kBase.find("When"));
  chained += "When Ego is driving";
  for (int i = 0; i < 2000; ++i) chained += ", Car1 is driving";
  chained += " and Car1 is driving, Car1 drives.\nEgo operates autonomously.\n";
  texts.push_back(chained);
  std::string phases = kBase.substr(0, kBase.find("When")) + "When Ego is driving, Car1 drives";
  for (int i = 0; i < 2000; ++i) phases += ", then drives. Car1 stops";
  texts.push_back(phases + ".\nEgo operates autonomously.\n");
  if (!parse_survives(texts, "garbage")) return;
  for (std::size_t i = 0; i + 2 < texts.size(); ++i)
    EXPECT_TRUE(parse_level1(SourceFile("t.sdl", texts[i])).diagnostics.has_errors()) << i;
  // The long lists are valid and must read in reasonable time.
  EXPECT_TRUE(parse_level1(SourceFile("t.sdl", texts[texts.size() - 2])).file.has_value());
  EXPECT_TRUE(parse_level1(SourceFile("t.sdl", texts.back())).file.has_value());
}

// The formatted message shows file:line:column, the line and a caret under the mistake.
TEST(WmgLevel1DiagnosticFormat, CaretUnderTheMistake) {
  const std::string text = replaced(kBase, "During the day", "During the dya");
  SourceFile file("story.sdl", text);
  Level1ParseResult result = parse_level1(file);
  ASSERT_FALSE(result.diagnostics.all().empty());
  std::string formatted = format_diagnostic(file, result.diagnostics.all()[0]);
  EXPECT_THAT(formatted, ::testing::HasSubstr("story.sdl:3:12: error: expected 'day' or 'night'"));
  EXPECT_THAT(formatted, ::testing::HasSubstr("\n  During the dya, there is"));
  EXPECT_THAT(formatted, ::testing::HasSubstr("\n             ^~~"));
}

}  // namespace
}  // namespace scenfuzz::wmg
