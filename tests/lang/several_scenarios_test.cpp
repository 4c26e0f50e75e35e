// Files that create and execute several scenarios, as LawBreaker's scenest files may
// (`Trace trace1 = EXE(scenario1);` beside `Trace trace2 = EXE(scenario2);`): the template is the
// one scenario the caller names, with only the specs asserted on its traces (issue 21).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz {
namespace {

// Shared ego, one NPC car in scenario1 and a pedestrian in scenario2, a range in each.
const std::string kTwoScenarios =
    "map_name = \"m\";\n"
    "ego_vehicle = AV((\"l\"->0), (\"l\"->100));\n"
    "npc1 = Vehicle((\"l\"->range(10, 20), , 5));\n"
    "ped1 = Pedestrian(((1, 2), , range(1, 2)));\n"
    "scenario1 = CreateScenario{load(map_name); ego_vehicle; {npc1}; {}; {};};\n"
    "scenario2 = CreateScenario{load(map_name); ego_vehicle; {}; {ped1}; {};};\n"
    "Trace trace1 = EXE(scenario1);\n"
    "Trace trace2 = EXE(scenario2);\n"
    "trace1 |= G (dis(trace1[ego], trace1[truth][npc1]) > 1);\n"
    "trace2 |= G (dis(trace2[ego], trace2[truth][ped1]) > 2);\n"
    "trace2 |= G (dis(trace2[ego], trace2[truth][ped1]) > 3);\n";

avunit::ParseResult parse_choosing(const std::string& text, const std::string& scenario,
                                   bool survey = false) {
  return avunit::parse(SourceFile("test.scenest", text), avunit::ParseOptions{scenario, survey});
}

std::string shown(const std::string& text, const avunit::ParseResult& result) {
  return format_diagnostics(SourceFile("test.scenest", text), result.diagnostics);
}

std::vector<std::string> spec_traces(const ScenarioTemplate& scenario) {
  std::vector<std::string> traces;
  for (const Spec& spec : scenario.specs) traces.push_back(spec.trace);
  return traces;
}

TEST(SeveralScenarios, ChoosingTheFirstGivesItsActorsAndOnlyItsTracesSpecs) {
  const avunit::ParseResult result = parse_choosing(kTwoScenarios, "scenario1");
  ASSERT_TRUE(result.ok()) << shown(kTwoScenarios, result);
  // No warning either: scenario2's range is read by scenario2, so it is no unused range.
  EXPECT_TRUE(result.diagnostics.all().empty()) << shown(kTwoScenarios, result);
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.scenario_name, "scenario1");
  EXPECT_EQ(scenario.trace_name, "trace1");
  ASSERT_EQ(scenario.vehicles.size(), 1u);
  EXPECT_EQ(scenario.vehicles[0].name, "npc1");
  EXPECT_TRUE(scenario.pedestrians.empty());
  EXPECT_EQ(spec_traces(scenario), std::vector<std::string>{"trace1"});
  ASSERT_EQ(scenario.parameters.size(), 1u);
  EXPECT_EQ(scenario.parameters[0].name, "npc1.init.position.s");
  EXPECT_EQ(result.scenarios, (std::vector<std::string>{"scenario1", "scenario2"}));
}

TEST(SeveralScenarios, ChoosingTheSecondGivesItsActorsAndOnlyItsTracesSpecs) {
  const avunit::ParseResult result = parse_choosing(kTwoScenarios, "scenario2");
  ASSERT_TRUE(result.ok()) << shown(kTwoScenarios, result);
  const ScenarioTemplate& scenario = result.scenario;
  EXPECT_EQ(scenario.scenario_name, "scenario2");
  EXPECT_EQ(scenario.trace_name, "trace2");
  EXPECT_TRUE(scenario.vehicles.empty());
  ASSERT_EQ(scenario.pedestrians.size(), 1u);
  EXPECT_EQ(scenario.pedestrians[0].name, "ped1");
  EXPECT_EQ(spec_traces(scenario), (std::vector<std::string>{"trace2", "trace2"}));
  // Specs keep the names they have in the whole file.
  EXPECT_EQ(scenario.specs[0].name, "spec2");
  EXPECT_EQ(scenario.specs[1].name, "spec3");
  ASSERT_EQ(scenario.parameters.size(), 1u);
  EXPECT_EQ(scenario.parameters[0].name, "ped1.init.speed");
}

TEST(SeveralScenarios, WithoutAChoiceIsAnErrorNamingTheOptionAndEveryScenario) {
  const avunit::ParseResult result = avunit::parse(SourceFile("test.scenest", kTwoScenarios));
  ASSERT_FALSE(result.ok());
  const std::string text = shown(kTwoScenarios, result);
  // At trace2's declaration, the second scenario executed.
  EXPECT_NE(text.find("test.scenest:8:7: error: this file executes 2 scenarios: scenario1 "
                      "(trace1), scenario2 (trace2): choose one with --scenario NAME"),
            std::string::npos)
      << text;
  EXPECT_FALSE(result.scenario.has_scenario);
  EXPECT_EQ(result.scenarios, (std::vector<std::string>{"scenario1", "scenario2"}));
}

TEST(SeveralScenarios, AnUnknownNameIsAnErrorListingThoseThatExist) {
  const avunit::ParseResult result = parse_choosing(kTwoScenarios, "scenario3");
  ASSERT_FALSE(result.ok());
  const std::string text = shown(kTwoScenarios, result);
  EXPECT_NE(text.find("error: there is no scenario 'scenario3' (--scenario): this file has "
                      "scenario1 (trace1), scenario2 (trace2)"),
            std::string::npos)
      << text;
}

TEST(SeveralScenarios, ASurveyChecksEveryScenarioAndListsThem) {
  const avunit::ParseResult result = parse_choosing(kTwoScenarios, "", /*survey=*/true);
  ASSERT_TRUE(result.ok()) << shown(kTwoScenarios, result);
  const std::string text = shown(kTwoScenarios, result);
  EXPECT_NE(text.find("note: this file executes 2 scenarios: scenario1 (trace1), scenario2 "
                      "(trace2); `run`, the search and `space` take --scenario NAME"),
            std::string::npos)
      << text;
  // The scenario not chosen is checked as well: its spec reads an actor it does not have.
  const std::string wrong =
      kTwoScenarios + "trace2 |= G (dis(trace2[ego], trace2[truth][npc1]) > 1);\n";
  const avunit::ParseResult checked = parse_choosing(wrong, "scenario1");
  EXPECT_NE(shown(wrong, checked).find("'npc1' is not part of the scenario that 'trace2' executes"),
            std::string::npos)
      << shown(wrong, checked);
}

TEST(SeveralScenarios, OneScenarioNeedsNoChoiceAndItsNameIsChecked) {
  const std::string one =
      "ego_vehicle = AV((\"l\"->0), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego_vehicle; {}; {}; {};};\n"
      "Trace t = EXE(s);\n"
      "Trace t2 = EXE(s);\n"
      "t |= G (speed < 30);\n"
      "t2 |= G (speed < 40);\n";
  const avunit::ParseResult plain = avunit::parse(SourceFile("test.scenest", one));
  ASSERT_TRUE(plain.ok()) << shown(one, plain);
  // Two traces of one scenario: both traces' specs judge it.
  EXPECT_EQ(spec_traces(plain.scenario), (std::vector<std::string>{"t", "t2"}));
  EXPECT_EQ(plain.scenarios, std::vector<std::string>{"s"});
  const avunit::ParseResult named = parse_choosing(one, "s");
  ASSERT_TRUE(named.ok()) << shown(one, named);
  EXPECT_EQ(named.scenario, plain.scenario);
  const avunit::ParseResult wrong = parse_choosing(one, "scenario2");
  EXPECT_NE(shown(one, wrong)
                .find("there is no scenario 'scenario2' (--scenario): this file has "
                      "only s (t, t2)"),
            std::string::npos)
      << shown(one, wrong);
}

TEST(SeveralScenarios, CreatedButNotExecutedScenariosCanBeChosenToo) {
  const std::string created =
      "ego_vehicle = AV((\"l\"->0), (\"l\"->100));\n"
      "a = CreateScenario{load(\"m\"); ego_vehicle; {}; {}; {};};\n"
      "b = CreateScenario{load(\"n\"); ego_vehicle; {}; {}; {};};\n";
  const avunit::ParseResult unchosen = avunit::parse(SourceFile("test.scenest", created));
  EXPECT_NE(shown(created, unchosen)
                .find("this file creates 2 scenarios: a, b: choose one with --scenario NAME or "
                      "with 'Trace trace = EXE(scenario);'"),
            std::string::npos)
      << shown(created, unchosen);
  const avunit::ParseResult chosen = parse_choosing(created, "b");
  ASSERT_TRUE(chosen.ok()) << shown(created, chosen);
  EXPECT_EQ(chosen.scenario.map.name, "n");
}

TEST(SeveralScenarios, AConcreteFindingKeepsTheWholeFileAndFixesOnlyTheChosenScenario) {
  const SourceFile file("test.scenest", kTwoScenarios);
  const avunit::ParseResult result = parse_choosing(kTwoScenarios, "scenario2");
  ASSERT_TRUE(result.ok());
  const std::vector<double> values{1.5};
  const std::string concrete = avunit::print_concrete(file, result.scenario, values);
  // scenario1, its range, its trace and its spec are all still there.
  EXPECT_NE(concrete.find("npc1 = Vehicle((\"l\"->range(10, 20), , 5));"), std::string::npos)
      << concrete;
  EXPECT_NE(concrete.find("ped1 = Pedestrian(((1, 2), , 1.5));"), std::string::npos) << concrete;
  EXPECT_NE(concrete.find("trace1 |= G (dis(trace1[ego], trace1[truth][npc1]) > 1);"),
            std::string::npos);
  const avunit::ParseResult replayed = parse_choosing(concrete, "scenario2");
  ASSERT_TRUE(replayed.ok()) << shown(concrete, replayed);
  EXPECT_TRUE(replayed.scenario.parameters.empty());
  EXPECT_EQ(replayed.scenario.specs.size(), 2u);
  // scenario1 is still the logical scenario it was.
  EXPECT_EQ(parse_choosing(concrete, "scenario1").scenario.parameters.size(), 1u);
}

}  // namespace
}  // namespace scenfuzz
