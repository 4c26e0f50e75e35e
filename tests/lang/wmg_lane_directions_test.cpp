// Issue 24: a junction's lane connections say which way each lane of its roads runs (a lane a
// connection leaves from runs into the junction, one it leads to out of it), so that a two-lane
// road is one lane each way, as its author drew it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::Parts;
using test::road_text;

// A T-junction of R1 (west), R2 (east) and the stem R3 (south), each road `lanes` lanes, with
// "Road lane connections [connections]" and `dynamics`.
std::string t_junction(const std::string& connections, const std::string& dynamics, int lanes = 2) {
  std::string roads;
  for (int r = 1; r <= 3; ++r) {
    const std::string id = "R" + std::to_string(r);
    roads += road_text(id, lanes, "Horizontal road geometry [Straight]",
                       "Length [100] AND Lane width [3.5]", r == 1 ? "START" : "START: [J1]",
                       r == 1 ? "END: [J1]" : "END", "48");
  }
  Parts parts;
  parts.scenery = test::scenery_with_roads(
      roads,
      "\nJ1: Junction type [T-Junction] as [T1]\nwhich has [Give way] connection control and [3] "
      "connections with [R1, R2, R3]\nAngles between roads [R1 -> R2, R2 -> R3] [180, 90]\n"
      "Road lane connections [" +
          connections + "]\nDimensions [Width: 10, Depth: 10]\n");
  parts.dynamics = dynamics;
  return parts.text();
}

const std::string kEgoOnTheStem =
    "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\nWHEN: [Ego] is [Going Ahead]\n"
    "DO: AUTO\nEND\n";

// The issue's give-way T-junction's connections.
const std::string kGiveWay =
    "R3.L1 -> R1.L2 + R2.L1, R1.L1 -> R2.L1 + R3.L2, R2.L2 -> R1.L2 + R3.L2";

ParseResult parse_text(const std::string& text) {
  SourceFile file("t.sdl", text);
  return parse(file);
}

double map_lanes(const ScenarioTemplate& scenario) {
  double lanes = -1;
  for (const NamedValue& parameter : scenario.map.parameters)
    if (parameter.name == "lanes") lanes = evaluate(parameter.value, {});
  return lanes;
}

// `scenfuzz map`'s note on the road: "the west arm (R1.L1 west_in_0, R1.L2 west_out_0)".
std::string road_note(const ScenarioTemplate& scenario, const std::string& road) {
  for (const Attribute& attribute : scenario.map.attributes)
    if (attribute.key == "road " + road) return attribute.value;
  return "";
}

TEST(WmgLaneDirectionsTest, ATwoLaneRoadIsOneLaneEachWayAsTheConnectionsRunThem) {
  const ParseResult result = parse_text(t_junction(kGiveWay, kEgoOnTheStem));
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(map_lanes(result.scenario), 1);
  EXPECT_EQ(road_note(result.scenario, "R1"), "the west arm (R1.L1 west_in_0, R1.L2 west_out_0)");
  EXPECT_EQ(road_note(result.scenario, "R2"), "the east arm (R2.L1 east_out_0, R2.L2 east_in_0)");
  EXPECT_EQ(road_note(result.scenario, "R3"),
            "the south arm (R3.L1 south_in_0, R3.L2 south_out_0)");
  EXPECT_EQ(result.scenario.ego.initial.position.lane, "south_in_0");
  // The ego leaves by R1.L2, the lane the first connection from its lane leads to.
  ASSERT_TRUE(result.scenario.ego.target.has_value());
  EXPECT_EQ(result.scenario.ego.target->position.lane, "west_out_0");
}

TEST(WmgLaneDirectionsTest, AnActorInALaneOutOfTheJunctionStandsOnTheOutLane) {
  const std::string dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\nAND Vehicle [Car] in [R2.L1] with "
      "a [Longitudinal] offset of [30] AND at relative position [FSR] with relative heading "
      "angle [0] to [Ego]\nWHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  const ParseResult result = parse_text(t_junction(kGiveWay, dynamics));
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.scenario.vehicles.size(), 1u);
  EXPECT_EQ(result.scenario.vehicles[0].initial.position.lane, "east_out_0");
}

TEST(WmgLaneDirectionsTest, ALaneNoConnectionNamesRunsTheWayFewerOfItsRoadsLanesRun) {
  // Only R3's lanes are named: R1's and R2's run in, out, in, out by number.
  const ParseResult result = parse_text(t_junction("R3.L1 -> R3.L4", kEgoOnTheStem, 4));
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(map_lanes(result.scenario), 2);
  EXPECT_EQ(road_note(result.scenario, "R1"),
            "the west arm (R1.L1 west_in_0, R1.L2 west_out_0, R1.L3 west_in_1, R1.L4 west_out_1)");
  // R3.L1 in and R3.L4 out leave a tie: the unnamed L2 goes in, then L3 out.
  EXPECT_EQ(road_note(result.scenario, "R3"),
            "the south arm (R3.L1 south_in_0, R3.L2 south_in_1, R3.L3 south_out_0, R3.L4 "
            "south_out_1)");
}

TEST(WmgLaneDirectionsTest, TwoLanesLedTheSameWayMakeTwoLanesEachWay) {
  const ParseResult result = parse_text(t_junction(
      "R3.L1 -> R1.L3 + R2.L4, R3.L2 -> R1.L4, R1.L1 -> R2.L3, R1.L2 -> R2.L4", kEgoOnTheStem, 4));
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(map_lanes(result.scenario), 2);
  EXPECT_EQ(road_note(result.scenario, "R1"),
            "the west arm (R1.L1 west_in_0, R1.L2 west_in_1, R1.L3 west_out_0, R1.L4 west_out_1)");
  ASSERT_TRUE(result.scenario.ego.target.has_value());
  EXPECT_EQ(result.scenario.ego.target->position.lane, "west_out_0");
}

TEST(WmgLaneDirectionsTest, ALaneLedBothIntoAndOutOfTheJunctionIsAnErrorNamingBothPlaces) {
  const std::string text = t_junction("R3.L1 -> R1.L2, R1.L1 -> R3.L1", kEgoOnTheStem);
  SourceFile file("t.sdl", text);
  const ParseResult result = parse(file);
  ASSERT_FALSE(result.ok());
  const std::string message = format_diagnostics(file, result.diagnostics);
  const std::size_t first = text.find("R3.L1 -> R1.L2");
  const std::size_t second = text.find("R3.L1]", first);
  ASSERT_NE(second, std::string::npos);
  // The error is at the second use, and names the first's line and column.
  const Diagnostic* error = nullptr;
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    if (diagnostic.severity == Severity::error) error = &diagnostic;
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(error->location.offset, second) << message;
  EXPECT_NE(error->message.find("lane 'R3.L1' leads out of junction 'J1' here"), std::string::npos)
      << message;
  const std::size_t line_start = text.rfind('\n', first) + 1;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(first), '\n');
  EXPECT_NE(error->message.find("the connection at " + std::to_string(line) + ":" +
                                std::to_string(first - line_start + 1)),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace scenfuzz::wmg
