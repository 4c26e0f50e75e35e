// print(parse(f)) parses back to an equal template, including the corner cases the canonical
// printer has to take care of.
#include <gtest/gtest.h>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz {
namespace {

void expect_round_trip(const std::string& text) {
  SCOPED_TRACE(text);
  avunit::ParseResult parsed = test::parse_text(text);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(SourceFile("test.avu", text), parsed.diagnostics);
  std::string printed = avunit::print(parsed.scenario);
  avunit::ParseResult reparsed = test::parse_text(printed);
  ASSERT_TRUE(reparsed.ok()) << printed
                             << format_diagnostics(SourceFile("printed", printed),
                                                   reparsed.diagnostics);
  EXPECT_EQ(parsed.scenario, reparsed.scenario) << printed;
}

// Issue 21's parser gaps, as real LawBreaker files write them.
TEST(RoundTrip, ScenestShortFormsFramesAndThreeComponentVectors) {
  expect_round_trip(
      "a = \"l\"; b2 = 5; yyyy = (1, 2); v = (1, 1, 1);\n"
      "ego = AV((IMU a -> b2), (\"l\"->100));\n"
      "npc2 = Vehicle((IMU yyyy), U((\"l\"->30, , 5)));\n"
      "npc3 = Vehicle((\"l\"->10, , 5), u((\"l\"->30, , 5)));\n"
      "ped = Pedestrian(((1, 2), , 1));\n"
      "s = CreateScenario{load(\"San Francisco\"); ego; {npc2, npc3}; {ped}; {};};\n"
      "Trace t = EXE(s);\n"
      "t |= G (vel(t[truth][ped], (1, 2, +5)) > 0) & G (acc(t[truth][npc2], (1, 2, -3) + v) > 0)"
      " & X[1, 1.5] (spd(t[ego], 0) > 1);\n");
}

TEST(RoundTrip, HeadingRelatedToAnActorPrintedLater) {
  expect_round_trip(
      "npc2 = Vehicle((\"l\"->50));\n"
      "ego = AV((\"l\"->0, 5 deg related to npc2), (\"l\"->100));\n"
      "npc1 = Vehicle((\"l\"->30, 10 deg related to npc2));\n"
      "s = CreateScenario{load(\"m\"); ego; {npc1, npc2}; {}; {};};\n");
}

TEST(RoundTrip, StringsWithQuotesOfTheOtherFamily) {
  expect_round_trip(
      "ego = AV(('lane \"a\"'->0), (“it's”->100), ('say \"hi\"'));\n"
      "s = CreateScenario{load('the \"map\"'); ego; {}; {}; {};};\n");
}

TEST(RoundTrip, TimesThatAreNotWholeSecondsOfADay) {
  expect_round_trip(
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; Environment(12:00 + 0.25);};\n");
  expect_round_trip(
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; Environment(range(0:00 - 60, 1:00));};\n");
}

TEST(RoundTrip, SpecsOnASecondTraceOfTheSameScenario) {
  expect_round_trip(
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\n"
      "Trace a = EXE(s);\nTrace b = EXE(s);\n"
      "b |= G (spd(b[ego], 0) < 30);\na |= F (spd(a[ego], 0) > 1);\n");
}

TEST(RoundTrip, SharedParameterNamesDoNotCollideWithActors) {
  expect_round_trip(
      "v = range(1, 2);\n"
      "parameter_1 = AV((\"l\"->0, , v), (\"l\"->100, , v));\n"
      "s = CreateScenario{load(\"m\"); parameter_1; {}; {}; {};};\n");
}

TEST(RoundTrip, NegativeNumbersAndNestedArithmetic) {
  expect_round_trip(
      "ego = AV((\"l\"->0, -(range(1, 2) - -3) deg, 2 - (range(0, 1) - 1) * -2 ^ 2), "
      "((-1, -2, -3)));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\n"
      "Trace t = EXE(s);\n"
      "t |= G (-spd(t[ego], -5) - (spd(t[ego], 1) - 2) > -(1 + range(0, 1)));\n");
}

}  // namespace
}  // namespace scenfuzz
