// scenfuzz's addition to WMG SDL level 2, the header line `NPC BEHAVIOUR: Reactive | Scripted`
// (docs/wmg-sdl.md: read anywhere after VERSION, printed back, into
// ScenarioTemplate::npc_behaviour), and traffic flows as background traffic: their ranges are
// search parameters, no "not simulated" warning, and the checks on their rate and speed. The
// header line's syntax errors are cases of wmg_malformed_test.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::expect_spans;
using test::Parts;
using test::road;
using test::scenery_with_roads;

// The minimal file with a one-lane road R1 and the traffic model `traffic`.
std::string with_road(const std::string& header, const std::string& traffic = "") {
  Parts parts;
  parts.header = header;
  parts.scenery = scenery_with_roads(road());
  parts.traffic = traffic;
  return parts.text();
}

std::string flow_model(const std::string& rate_and_speed) {
  return "TRAFFIC ELEMENTS:\nINITIAL: CENTROID [C1] in [R1] at [10] to [J1]\n"
         "DO: TRAFFIC [Background]: [C1: R1.L1, C1: R1.L1] at [" +
         rate_and_speed + "]\n";
}

ParseResult parse_ok(const std::string& text) {
  SourceFile file("t.sdl", text);
  ParseResult result = parse(file);
  EXPECT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics) << text;
  EXPECT_TRUE(result.diagnostics.all().empty()) << format_diagnostics(file, result.diagnostics);
  return result;
}

ParseResult parse_text(const std::string& text) { return parse(SourceFile("t.sdl", text)); }

const Diagnostic* first_error(const ParseResult& result) {
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    if (diagnostic.severity == Severity::error) return &diagnostic;
  return nullptr;
}

const Parameter* parameter_named(const ScenarioTemplate& scenario, const std::string& name) {
  for (const Parameter& parameter : scenario.parameters)
    if (parameter.name == name) return &parameter;
  return nullptr;
}

// ---- NPC BEHAVIOUR ---------------------------------------------------------------------------

TEST(WmgNpcBehaviour, ReadAnywhereInTheHeaderAfterTheVersion) {
  for (const std::string header :
       {"VERSION: 1.0\nNPC BEHAVIOUR: Scripted\nAUTHOR: 'a'\n",
        "VERSION: 1.0\nEXTENSION: None\nNPC BEHAVIOUR: Scripted\nAUTHOR: 'a'\n",
        "VERSION: 1.0\nAUTHOR: 'a'\nNPC   BEHAVIOUR :\n  Scripted\nAUTHOR: 'b'\n",
        "VERSION: 1.0\nAUTHOR: 'a'\nEXTENSION: 'x'\nNPC BEHAVIOUR: Scripted\n"}) {
    SCOPED_TRACE(header);
    const std::string text = with_road(header);
    SourceFile file("t.sdl", text);
    Level2ParseResult parsed = parse_level2(file);
    ASSERT_TRUE(parsed.file.has_value()) << format_diagnostics(file, parsed.diagnostics);
    ASSERT_TRUE(parsed.file->header.npc_behaviour.has_value());
    EXPECT_EQ(parsed.file->header.npc_behaviour->value, NpcBehaviourWord::scripted);
    expect_spans(parsed.file->header.npc_behaviour->location, text, "Scripted");
    EXPECT_EQ(parse_ok(text).scenario.npc_behaviour, NpcBehaviour::scripted);
  }
}

TEST(WmgNpcBehaviour, ReactiveAndUnset) {
  EXPECT_EQ(parse_ok(with_road("VERSION: 1.0\nAUTHOR: 'a'\nNPC BEHAVIOUR: Reactive\n"))
                .scenario.npc_behaviour,
            NpcBehaviour::reactive);
  EXPECT_EQ(parse_ok(with_road("VERSION: 1.0\nAUTHOR: 'a'\n")).scenario.npc_behaviour,
            std::nullopt);
}

TEST(WmgNpcBehaviour, SurvivesPrintAndParse) {
  for (const std::string word : {"Scripted", "Reactive"}) {
    const std::string text =
        with_road("VERSION: 1.0\nNPC BEHAVIOUR: " + word + "\nAUTHOR: 'a'\n", flow_model("1, 2"));
    Level2Text canonical = level2_text(SourceFile("t.sdl", text));
    ASSERT_FALSE(canonical.text.empty());
    EXPECT_NE(canonical.text.find("NPC BEHAVIOUR: " + word + "\n"), std::string::npos)
        << canonical.text;
    SourceFile printed("printed.sdl", canonical.text);
    Level2ParseResult again = parse_level2(printed);
    ASSERT_TRUE(again.file.has_value()) << format_diagnostics(printed, again.diagnostics);
    EXPECT_EQ(print_level2(*again.file), canonical.text);
    EXPECT_EQ(parse_ok(canonical.text).scenario, parse_ok(text).scenario);
  }
}

TEST(WmgNpcBehaviour, AConcreteScenarioKeepsIt) {
  const std::string text = with_road("VERSION: 1.0\nAUTHOR: 'a'\nNPC BEHAVIOUR: Scripted\n",
                                     flow_model("100 to 900, 20 to 60"));
  SourceFile file("t.sdl", text);
  ParseResult parsed = parse_ok(text);
  std::vector<double> values;
  for (const Parameter& parameter : parsed.scenario.parameters)
    values.push_back((parameter.lower + parameter.upper) / 2);
  const std::string concrete = print_concrete(file, parsed.scenario, values);
  ParseResult again = parse_ok(concrete);
  EXPECT_EQ(again.scenario.npc_behaviour, NpcBehaviour::scripted);
  ASSERT_EQ(again.scenario.traffic.flows.size(), 1u);
  EXPECT_EQ(evaluate(again.scenario.traffic.flows[0].rate, {}), 500);
}

// ---- traffic flows ---------------------------------------------------------------------------

TEST(WmgFlows, TheirRangesAreSearchParametersAndNothingWarns) {
  const std::string text =
      with_road("VERSION: 1.0\nAUTHOR: 'a'\n", flow_model("200 to 800, 30 to 48"));
  ParseResult result = parse_ok(text);  // no diagnostics at all: no "not simulated" warning
  const ScenarioTemplate& scenario = result.scenario;
  const Parameter* rate = parameter_named(scenario, "traffic.Background.rate");
  const Parameter* speed = parameter_named(scenario, "traffic.Background.speed");
  ASSERT_NE(rate, nullptr);
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(rate->lower, 200);
  EXPECT_EQ(rate->upper, 800);
  EXPECT_EQ(rate->unit, "veh/h");
  expect_spans(rate->location, text, "200 to 800");
  EXPECT_EQ(speed->lower, 30);
  EXPECT_EQ(speed->upper, 48);
  EXPECT_EQ(speed->unit, "km/h");
  expect_spans(speed->location, text, "30 to 48");

  ASSERT_EQ(scenario.traffic.flows.size(), 1u);
  const scenfuzz::TrafficFlow& flow = scenario.traffic.flows[0];
  EXPECT_EQ(flow.name, "Background");
  EXPECT_EQ(flow.source_lane, "east_0");
  EXPECT_EQ(flow.destination_lane, "") << "a flow to its own origin drives on along the lanes";
  std::vector<double> values(scenario.parameters.size(), 0.0);
  values[static_cast<std::size_t>(rate - scenario.parameters.data())] = 500;
  values[static_cast<std::size_t>(speed - scenario.parameters.data())] = 36;
  EXPECT_EQ(evaluate(flow.rate, values), 500);
  ASSERT_TRUE(flow.speed.has_value());
  EXPECT_DOUBLE_EQ(evaluate(*flow.speed, values), 10.0);  // 36 km/h in m/s
}

TEST(WmgFlows, TheCorpusFlowIsSearchedWithoutAWarning) {
  std::optional<SourceFile> read =
      read_source_file((test::wmg_corpus_dir() / "signalised_junction.sdl").string());
  ASSERT_TRUE(read.has_value());
  ParseResult result = parse(*read);
  ASSERT_TRUE(result.ok()) << format_diagnostics(*read, result.diagnostics);
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    EXPECT_EQ(diagnostic.message.find("not simulated"), std::string::npos) << diagnostic.message;
  const Parameter* rate = parameter_named(result.scenario, "traffic.Background.rate");
  ASSERT_NE(rate, nullptr);
  EXPECT_EQ(rate->lower, 200);
  EXPECT_EQ(rate->upper, 800);
  const Parameter* speed = parameter_named(result.scenario, "traffic.Background.speed");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->lower, 30);
  EXPECT_EQ(speed->upper, 48);
  // From R4.L2 (north, into the junction by R4.L2 -> R2.L2) out on R2.L2, the south arm's out
  // lane: one lane each way.
  ASSERT_EQ(result.scenario.traffic.flows.size(), 1u);
  EXPECT_EQ(result.scenario.traffic.flows[0].source_lane, "north_in_0");
  EXPECT_EQ(result.scenario.traffic.flows[0].destination_lane, "south_out_0");
}

TEST(WmgFlows, RateAndSpeedOutsideWhatTheyMeanAreErrorsAtTheirText) {
  struct Case {
    std::string rate_and_speed;
    std::string piece;  // where the error points
    std::string message;
  };
  for (const Case& c :
       {Case{"-100 to 200, 30", "-100 to 200",
             "the rate of traffic flow 'Background' cannot be negative"},
        Case{"1000 to 4000, 30", "1000 to 4000",
             "the rate of traffic flow 'Background' cannot be above 3600 vehicles per hour (one "
             "vehicle per second per lane)"},
        Case{"200, 0 to 30", "0 to 30",
             "the speed of traffic flow 'Background' must be above 0 km/h (its vehicles must "
             "move)"}}) {
    SCOPED_TRACE(c.rate_and_speed);
    const std::string text = with_road("VERSION: 1.0\nAUTHOR: 'a'\n", flow_model(c.rate_and_speed));
    ParseResult result = parse_text(text);
    EXPECT_FALSE(result.ok());
    const Diagnostic* error = first_error(result);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->message, c.message);
    expect_spans(error->location, text, c.piece);
  }
  // One vehicle a second is still traffic.
  parse_ok(with_road("VERSION: 1.0\nAUTHOR: 'a'\n", flow_model("3600, 30")));
}

}  // namespace
}  // namespace scenfuzz::wmg
