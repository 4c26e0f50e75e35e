// scenfuzz's extensions of the AVUnit / scenest traffic slot (docs/avunit.md, "Extensions"):
// NPCBehaviour(...), Flow(...) and TrafficLight(...) as the IR holds them, flows' names and their
// ranges as search parameters, print -> parse round trips, and files without them unchanged. Their
// errors are cases of malformed_test.cpp.
#include <gtest/gtest.h>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz {
namespace {

const std::string kEgo = "ego = AV((\"east_0\"->10), (\"east_0\"->300));\n";

// A scenario whose traffic slot holds `items`, after the `extra` statements.
std::string with_traffic(const std::string& items, const std::string& extra = "") {
  return kEgo + extra + "s = CreateScenario{load(\"straight\"); ego; {}; {}; {}; {}; {" + items +
         "}};\nTrace t = EXE(s);\n";
}

avunit::ParseResult parse_ok(const std::string& text) {
  avunit::ParseResult result = test::parse_text(text);
  EXPECT_TRUE(result.ok()) << format_diagnostics(SourceFile("test.avu", text), result.diagnostics);
  EXPECT_TRUE(result.diagnostics.all().empty())
      << format_diagnostics(SourceFile("test.avu", text), result.diagnostics);
  return result;
}

void expect_round_trip(const std::string& text) {
  SCOPED_TRACE(text);
  avunit::ParseResult parsed = parse_ok(text);
  std::string printed = avunit::print(parsed.scenario);
  avunit::ParseResult reparsed = test::parse_text(printed);
  ASSERT_TRUE(reparsed.ok()) << printed
                             << format_diagnostics(SourceFile("printed", printed),
                                                   reparsed.diagnostics);
  EXPECT_EQ(parsed.scenario, reparsed.scenario) << printed;
}

TEST(NpcBehaviour, EachFormSetsTheSwitch) {
  struct Form {
    std::string items;
    NpcBehaviour expected;
  };
  for (const Form& form :
       {Form{"NPCBehaviour(scripted)", NpcBehaviour::scripted},
        Form{"NPCBehaviour(reactive)", NpcBehaviour::reactive},
        Form{"NPCBehaviour(\"scripted\")", NpcBehaviour::scripted},
        Form{"NPCBehaviour('reactive')", NpcBehaviour::reactive},
        Form{"Intersection(1, 1, 0, 1), NPCBehaviour(scripted)", NpcBehaviour::scripted}}) {
    SCOPED_TRACE(form.items);
    avunit::ParseResult result = parse_ok(with_traffic(form.items));
    EXPECT_EQ(result.scenario.npc_behaviour, form.expected);
  }
}

TEST(NpcBehaviour, AVariableHoldingItAndAScenestFileAreRead) {
  avunit::ParseResult held = parse_ok(with_traffic("{mode}", "mode = NPCBehaviour(scripted);\n"));
  EXPECT_EQ(held.scenario.npc_behaviour, NpcBehaviour::scripted);
  avunit::ParseResult scenest =
      avunit::parse(SourceFile("test.scenest", with_traffic("SpeedLimit(\"east_0\", (0, 20)), "
                                                            "NPCBehaviour(reactive)")));
  ASSERT_TRUE(scenest.ok());
  EXPECT_EQ(scenest.scenario.npc_behaviour, NpcBehaviour::reactive);
  EXPECT_EQ(scenest.scenario.traffic.speed_limits.size(), 1u);
}

TEST(NpcBehaviour, UnsetWithoutIt) {
  EXPECT_EQ(parse_ok(with_traffic("")).scenario.npc_behaviour, std::nullopt);
}

TEST(NpcBehaviour, SurvivesPrintAndParse) {
  expect_round_trip(with_traffic("NPCBehaviour(scripted)"));
  expect_round_trip(with_traffic("NPCBehaviour(\"reactive\")"));
  std::string printed = avunit::print(parse_ok(with_traffic("NPCBehaviour('scripted')")).scenario);
  EXPECT_NE(printed.find("NPCBehaviour(scripted)"), std::string::npos) << printed;
}

TEST(Flow, BothFormsAreReadIntoTheTraffic) {
  avunit::ParseResult result =
      parse_ok(with_traffic("Flow(\"east_1\", 600, 12), Flow(\"west_1\", 300.5, 9.5, \"west_0\")"));
  const std::vector<TrafficFlow>& flows = result.scenario.traffic.flows;
  ASSERT_EQ(flows.size(), 2u);
  EXPECT_EQ(flows[0].name, "flow1");
  EXPECT_EQ(flows[0].source_lane, "east_1");
  EXPECT_EQ(flows[0].destination_lane, "");
  EXPECT_EQ(flows[0].rate, constant_value(600));
  ASSERT_TRUE(flows[0].speed);
  EXPECT_EQ(*flows[0].speed, constant_value(12));
  EXPECT_EQ(flows[0].location.line, 2u);
  EXPECT_EQ(flows[0].location.column, 60u);
  EXPECT_EQ(flows[1].name, "flow2");
  EXPECT_EQ(flows[1].source_lane, "west_1");
  EXPECT_EQ(flows[1].destination_lane, "west_0");
  EXPECT_EQ(flows[1].rate, constant_value(300.5));
  EXPECT_EQ(*flows[1].speed, constant_value(9.5));
  EXPECT_TRUE(result.scenario.parameters.empty());
  // A left-out destination is none; the boundary rate of one vehicle a second is allowed.
  avunit::ParseResult open = parse_ok(with_traffic("Flow(\"east_1\", 3600, 0.5, )"));
  ASSERT_EQ(open.scenario.traffic.flows.size(), 1u);
  EXPECT_EQ(open.scenario.traffic.flows[0].destination_lane, "");
}

TEST(Flow, NamedByItsVariableOrFreshlyBesideTheActors) {
  avunit::ParseResult result = parse_ok(
      kEgo + "flow1 = Vehicle((\"east_0\"->40));\nmain_road = Flow(\"east_1\", 600, 12);\n" +
      "s = CreateScenario{load(\"straight\"); ego; {flow1}; {}; {}; {}; "
      "{main_road, Flow(\"west_1\", 300, 9)}};\n");
  const std::vector<TrafficFlow>& flows = result.scenario.traffic.flows;
  ASSERT_EQ(flows.size(), 2u);
  EXPECT_EQ(flows[0].name, "main_road");
  EXPECT_EQ(flows[1].name, "flow2");  // `flow1` is a vehicle
}

TEST(Flow, RangesAreSearchParametersNamedAfterTheFlow) {
  avunit::ParseResult result =
      parse_ok(with_traffic("Flow(\"east_1\", range(600, 1200), range(8, 14)), busy",
                            "busy = Flow(\"west_1\", 300, range(5, 9), \"west_0\");\n"));
  const std::vector<Parameter>& parameters = result.scenario.parameters;
  ASSERT_EQ(parameters.size(), 3u);
  EXPECT_EQ(parameters[0].name, "flow1.rate");
  EXPECT_EQ(parameters[0].kind, ParameterKind::continuous);
  EXPECT_EQ(parameters[0].lower, 600);
  EXPECT_EQ(parameters[0].upper, 1200);
  EXPECT_EQ(parameters[0].unit, "veh/h");
  EXPECT_EQ(parameters[0].location.line, 3u);
  EXPECT_EQ(parameters[0].location.column, 75u);
  EXPECT_EQ(parameters[1].name, "flow1.speed");
  EXPECT_EQ(parameters[1].lower, 8);
  EXPECT_EQ(parameters[1].upper, 14);
  EXPECT_EQ(parameters[1].unit, "m/s");
  EXPECT_EQ(parameters[2].name, "busy.speed");
  EXPECT_EQ(parameters[2].lower, 5);
  EXPECT_EQ(parameters[2].upper, 9);
  const std::vector<TrafficFlow>& flows = result.scenario.traffic.flows;
  ASSERT_EQ(flows.size(), 2u);
  std::vector<double> values = {900, 10, 7};
  EXPECT_EQ(evaluate(flows[0].rate, values), 900);
  EXPECT_EQ(evaluate(*flows[0].speed, values), 10);
  EXPECT_EQ(evaluate(*flows[1].speed, values), 7);
}

TEST(Flow, ARangeSharedByTwoFlowsIsOneParameter) {
  avunit::ParseResult result = parse_ok(with_traffic(
      "Flow(\"east_1\", rate, 12), Flow(\"west_1\", rate, 12)", "rate = range(200, 800);\n"));
  ASSERT_EQ(result.scenario.parameters.size(), 1u);
  EXPECT_EQ(result.scenario.parameters[0].name, "flow1.rate");
  EXPECT_EQ(result.scenario.traffic.flows[1].rate.parameter, 0);
}

TEST(Flow, SurvivesPrintAndParse) {
  expect_round_trip(with_traffic("Flow(\"east_1\", 600, 12)"));
  expect_round_trip(
      with_traffic("Flow(\"east_1\", range(600, 1200), range(8, 14), \"east_0\"), "
                   "busy, NPCBehaviour(scripted)",
                   "busy = Flow(\"west_1\", 300, range(5, 9), \"west_0\");\n"));
  expect_round_trip(with_traffic("Flow(\"east_1\", rate, 12), Flow(\"west_1\", rate + 100, 12)",
                                 "rate = range(200, 800);\n"));
}

TEST(TrafficExtensions, AFileWithoutThemParsesAsBefore) {
  // The scenest seven-slot golden file: its traffic slot has an intersection and a speed limit.
  SourceFile file = test::load(test::lang_data_dir() / "golden" / "legacy_seven_slot.scenest");
  avunit::ParseResult result = avunit::parse(file);
  ASSERT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics);
  EXPECT_EQ(result.scenario.npc_behaviour, std::nullopt);
  EXPECT_TRUE(result.scenario.traffic.flows.empty());
  EXPECT_EQ(result.scenario.traffic.intersections.size(), 1u);
  std::string printed = avunit::print(result.scenario);
  EXPECT_EQ(printed.find("NPCBehaviour"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("Flow"), std::string::npos) << printed;
}

TEST(TrafficLight, SetsALightsColourAtTheStartAndSurvivesPrintAndParse) {
  avunit::ParseResult result =
      parse_ok(with_traffic("TrafficLight(\"light_west\", red), TrafficLight('light_north', "
                            "\"green\"), NPCBehaviour(scripted)"));
  const std::vector<TrafficLightSetting>& lights = result.scenario.traffic.lights;
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].id, "light_west");
  EXPECT_EQ(lights[0].color, "red");
  EXPECT_EQ(lights[0].location.line, 2u);
  EXPECT_EQ(lights[1].id, "light_north");
  EXPECT_EQ(lights[1].color, "green");
  expect_round_trip(with_traffic("TrafficLight(\"light_west\", yellow)"));
  const std::string printed = avunit::print(result.scenario);
  EXPECT_NE(printed.find("TrafficLight(\"light_west\", red)"), std::string::npos) << printed;
}

}  // namespace
}  // namespace scenfuzz
