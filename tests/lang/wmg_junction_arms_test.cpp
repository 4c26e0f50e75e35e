// Issue 24: a WMG junction's roads become the generator's arms by the angles the file states
// between them, in whatever order the author wrote the roads and the pairs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::Parts;
using test::road_text;

// A junction of `type` connecting `connected` (written in that order), with "Angles between roads
// [pairs] [angles]", and the ego in R3.L1.
std::string junction_file(const std::string& type, const std::string& connected,
                          const std::string& pairs, const std::string& angles,
                          const std::string& lane_connections = "R3.L1 -> R2.L1",
                          const std::string& car_sector = "FSL") {
  std::string roads;
  for (int r = 1; r <= 3; ++r) {
    const std::string id = "R" + std::to_string(r);
    roads +=
        road_text(id, 1, "Horizontal road geometry [Straight]", "Length [100] AND Lane width [3.5]",
                  r == 1 ? "START" : "START: [J1]", r == 1 ? "END: [J1]" : "END", "48");
  }
  Parts parts;
  parts.scenery = test::scenery_with_roads(
      roads, "\nJ1: Junction type [" + type +
                 "] as [T1]\nwhich has [Give way] connection control and [3] connections with [" +
                 connected + "]\nAngles between roads [" + pairs + "] [" + angles +
                 "]\nRoad lane connections [" + lane_connections +
                 "]\nDimensions [Width: 10, Depth: 10]\n");
  parts.dynamics =
      "DYNAMIC ELEMENTS:\nINITIAL: Vehicle [Ego] in [R3.L1]\nAND Vehicle [Car] in [R1.L1] with a "
      "[Longitudinal] offset of [30] AND at relative position [" +
      car_sector +
      "] with relative heading angle [90] to [Ego]\n"
      "WHEN: [Ego] is [Going Ahead]\nDO: AUTO\nEND\n";
  return parts.text();
}

struct Layout {
  std::string ego_lane, car_lane;
  std::optional<double> angle;  // the map's `angle` at the middle of the space
};

Layout layout_of(const std::string& text) {
  SourceFile file("t.sdl", text);
  const ParseResult result = parse(file);
  EXPECT_TRUE(result.ok()) << format_diagnostics(file, result.diagnostics) << text;
  Layout layout;
  layout.ego_lane = result.scenario.ego.initial.position.lane;
  if (!result.scenario.vehicles.empty())
    layout.car_lane = result.scenario.vehicles[0].initial.position.lane;
  std::vector<double> middle;
  for (const Parameter& p : result.scenario.parameters) middle.push_back((p.lower + p.upper) / 2);
  for (const NamedValue& parameter : result.scenario.map.parameters)
    if (parameter.name == "angle") layout.angle = evaluate(parameter.value, middle);
  return layout;
}

std::string first_error(const std::string& text) {
  SourceFile file("t.sdl", text);
  const ParseResult result = parse(file);
  for (const Diagnostic& d : result.diagnostics.all())
    if (d.severity == Severity::error) return format_diagnostics(file, result.diagnostics);
  return "";
}

TEST(WmgJunctionArmsTest, TheTwoRoadsInLineAreTheThroughRoadAndTheThirdTheStem) {
  // The issue's give-way T: R1 and R2 the major road, R3 the stem at a right angle. It used to
  // stop with "parameter 'angle' = 180 is outside its range": the first pair was taken as the
  // stem's angle.
  const Layout t = layout_of(
      junction_file("T-Junction", "R1, R2, R3", "R1 -> R2, R2 -> R3", "170 to 190, 80 to 100"));
  EXPECT_EQ(t.ego_lane, "south_in_0");  // R3, the stem
  EXPECT_EQ(t.car_lane, "west_in_0");   // R1, one end of the through road
  ASSERT_TRUE(t.angle);
  EXPECT_EQ(*t.angle, 90);
}

TEST(WmgJunctionArmsTest, TheLayoutDoesNotDependOnTheOrderThingsAreWrittenIn) {
  const std::vector<std::string> files = {
      junction_file("T-Junction", "R1, R2, R3", "R2 -> R3, R1 -> R2", "80 to 100, 170 to 190"),
      junction_file("T-Junction", "R3, R1, R2", "R1 -> R2, R3 -> R1", "180, 90"),
      junction_file("T-Junction", "R2, R3, R1", "R3 -> R2, R2 -> R1", "90, 180"),
      junction_file("T-Junction", "R1, R3, R2", "R1 -> R3, R3 -> R2", "90, 90"),
  };
  for (const std::string& text : files) {
    const Layout t = layout_of(text);
    EXPECT_EQ(t.ego_lane, "south_in_0") << text;  // R3 is the stem in every one
    EXPECT_NE(t.car_lane, "south_in_0") << text;
  }
}

TEST(WmgJunctionArmsTest, WhereTheAnglesLeaveAChoiceActorsStandOnTheSideTheirSectorNames) {
  // The issue's car on R1 "at relative position [FSR]" to the ego on the stem R3: R1 is the arm
  // on the ego's right as it drives in (east), R2 the other end of the through road.
  const std::string pairs = "R1 -> R2, R2 -> R3";
  const std::string angles = "170 to 190, 80 to 100";
  const Layout right =
      layout_of(junction_file("T-Junction", "R1, R2, R3", pairs, angles, "R3.L1 -> R2.L1", "FSR"));
  EXPECT_EQ(right.ego_lane, "south_in_0");
  EXPECT_EQ(right.car_lane, "east_in_0");
  const Layout left =
      layout_of(junction_file("T-Junction", "R1, R2, R3", pairs, angles, "R3.L1 -> R2.L1", "SL"));
  EXPECT_EQ(left.car_lane, "west_in_0");
  // The angles come first: a car "ahead" on a road the angles put beside the stem stays there.
  const Layout ahead =
      layout_of(junction_file("T-Junction", "R1, R2, R3", pairs, angles, "R3.L1 -> R2.L1", "F"));
  EXPECT_EQ(ahead.ego_lane, "south_in_0");
  EXPECT_EQ(ahead.car_lane, "west_in_0");
}

TEST(WmgJunctionArmsTest, TheStemsAngleWithEitherEndOfTheThroughRoadSetsTheMap) {
  // R3 meets R2 at 60 degrees: the generator's angle (west arm to the stem) is R1's to the stem,
  // the supplement when the pair names the east arm.
  const Layout a =
      layout_of(junction_file("T-Junction", "R1, R2, R3", "R1 -> R2, R1 -> R3", "180, 60"));
  ASSERT_TRUE(a.angle);
  EXPECT_EQ(*a.angle, 60);
  const Layout b =
      layout_of(junction_file("T-Junction", "R1, R2, R3", "R1 -> R2, R2 -> R3", "180, 60"));
  ASSERT_TRUE(b.angle);
  EXPECT_EQ(*b.angle, 120);
}

TEST(WmgJunctionArmsTest, AnglesNoJunctionCanHaveAreAnErrorAtThem) {
  const std::string text =
      junction_file("T-Junction", "R1, R2, R3", "R1 -> R2, R2 -> R3, R3 -> R1", "90, 90, 90");
  const std::string error = first_error(text);
  EXPECT_NE(error.find("t.sdl:"), std::string::npos) << error;
  EXPECT_NE(error.find("no layout of the t_junction map (two roads in line"), std::string::npos)
      << error;
  EXPECT_NE(error.find("R1 -> R2 90, R2 -> R3 90, R3 -> R1 90"), std::string::npos) << error;
  // Three roads at right angles to each other are no crossroads either.
  EXPECT_NE(first_error(junction_file("Crossroads", "R1, R2, R3", "R1 -> R2, R2 -> R3, R3 -> R1",
                                      "90, 90, 90"))
                .find("no layout of the crossroads map"),
            std::string::npos);
}

TEST(WmgJunctionArmsTest, APairOrConnectionNamingAnotherRoadOrAnUnlistedLaneIsAnErrorAtIt) {
  const std::string pair = junction_file("T-Junction", "R1, R2, R3", "R1 -> R9", "180");
  EXPECT_NE(first_error(pair).find("the angle pair names road 'R9', which junction 'J1' does "
                                   "not connect"),
            std::string::npos)
      << first_error(pair);
  const std::string connection =
      junction_file("T-Junction", "R1, R2, R3", "R1 -> R2", "180", "R3.L1 -> R7.L1");
  EXPECT_NE(first_error(connection).find("the lane connection names road 'R7'"), std::string::npos)
      << first_error(connection);
  // A lane its road does not list.
  const std::string lane =
      junction_file("T-Junction", "R1, R2, R3", "R1 -> R2", "180", "R3.L1 -> R1.L5");
  EXPECT_NE(first_error(lane).find("unknown lane 'R1.L5'"), std::string::npos) << first_error(lane);
}

}  // namespace
}  // namespace scenfuzz::wmg
