// What the constructs real LawBreaker / CausAVFuzzer files use, and the front end once rejected
// (issue 21's parser gaps), mean in the IR: three-component vectors, a frame before a variable
// or a lane position, X with an interval, and scenest's U(state) / u(state) uniform motion.
#include <gtest/gtest.h>

#include <string>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz {
namespace {

using test::parse_text;

const std::string kScenario =
    "ego = AV((\"l\"->0), (\"l\"->100));\n"
    "npc2 = Vehicle((\"l\"->10, , 5));\n"
    "ped = Pedestrian(((1, 2), , 1));\n"
    "s = CreateScenario{load(\"m\"); ego; {npc2}; {ped}; {};};\n"
    "Trace t = EXE(s);\n"
    "pedestrian_truth = t[truth][ped];\n";

avunit::ParseResult parse_ok(const std::string& text) {
  avunit::ParseResult result = parse_text(text);
  EXPECT_TRUE(result.ok()) << format_diagnostics(SourceFile("test.avu", text), result.diagnostics);
  return result;
}

// The vector argument of the first spec's `vel`/`acc` comparison.
const SpecTerm& vector_of_first_spec(const avunit::ParseResult& result) {
  const Formula& comparison = result.scenario.specs.at(0).formula.operands.at(0);
  const SpecTerm& signal = comparison.terms.at(0);
  return signal.operands.at(1);
}

std::vector<double> constants(const SpecTerm& vector) {
  std::vector<double> values;
  for (const SpecTerm& component : vector.operands) values.push_back(evaluate(component.value, {}));
  return values;
}

TEST(ScenestGaps, ThreeComponentVectorsKeepTheirUpComponent) {
  auto result = parse_ok(kScenario + "t |= G (vel(pedestrian_truth, (1, 2, +5)) > 0);\n");
  const SpecTerm& vector = vector_of_first_spec(result);
  EXPECT_EQ(vector.kind, TermKind::vector);
  EXPECT_EQ(constants(vector), (std::vector<double>{1, 2, 5}));
}

TEST(ScenestGaps, SummedCoordinatesAreAVector) {
  auto result =
      parse_ok(kScenario + "v = (1, 1, 1);\nt |= G (acc(t[truth][npc2], (1, 2, -3) + v) > 0);\n");
  const SpecTerm& vector = vector_of_first_spec(result);
  EXPECT_EQ(vector.kind, TermKind::vector);
  EXPECT_EQ(constants(vector), (std::vector<double>{2, 3, -2}));
  // Two components stay two.
  result = parse_ok(kScenario + "t |= G (acc(t[truth][npc2], (1, 2) + (1, 1)) > 0);\n");
  EXPECT_EQ(constants(vector_of_first_spec(result)), (std::vector<double>{2, 3}));
}

TEST(ScenestGaps, AFrameBeforeAVariableGivesItThatFrame) {
  auto result = parse_ok(
      "yyyy = (3, 4);\n"
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "npc1 = Vehicle((IMU yyyy, , 5));\n"
      "npc2 = Vehicle(IMU yyyy + (1, 1));\n"
      "s = CreateScenario{load(\"m\"); ego; {npc1, npc2}; {}; {};};\n");
  const Position& first = result.scenario.vehicles.at(0).initial.position;
  EXPECT_EQ(first.frame, Frame::imu);
  EXPECT_EQ(evaluate(first.x, {}), 3);
  EXPECT_EQ(evaluate(first.y, {}), 4);
  const Position& second = result.scenario.vehicles.at(1).initial.position;
  EXPECT_EQ(second.frame, Frame::imu);
  EXPECT_EQ(evaluate(second.x, {}), 4);
}

TEST(ScenestGaps, AFrameBeforeALanePositionIsIgnoredWithAWarning) {
  auto result = parse_ok(
      "a = \"lane_7\";\nb2 = 5;\n"
      "ego = AV((IMU a -> b2), (ENU \"lane_7\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\n");
  const Position& start = result.scenario.ego.initial.position;
  EXPECT_EQ(start.kind, PositionKind::lane);
  EXPECT_EQ(start.lane, "lane_7");
  EXPECT_EQ(evaluate(start.s, {}), 5);
  ASSERT_EQ(result.diagnostics.all().size(), 2u);
  const Diagnostic& warning = result.diagnostics.all()[0];
  EXPECT_EQ(warning.severity, Severity::warning);
  EXPECT_EQ(warning.location.line, 3u);
  EXPECT_EQ(warning.location.column, 11u);
  EXPECT_NE(warning.message.find("the frame IMU has no effect on a lane position"),
            std::string::npos)
      << warning.message;
}

TEST(ScenestGaps, NextWithAnIntervalIsEventuallyInThatWindow) {
  auto result = parse_ok(kScenario +
                         "t |= X[1, 1.5] (spd(t[ego], 0) > 1);\n"
                         "t |= X[0:2] (spd(t[ego], 0) > 1);\n"
                         "t |= X (spd(t[ego], 0) > 1);\n");
  const auto& specs = result.scenario.specs;
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0].formula.kind, FormulaKind::eventually);
  EXPECT_EQ(specs[0].formula.interval, (TimeInterval{1, 1.5}));
  EXPECT_EQ(specs[1].formula.kind, FormulaKind::eventually);
  EXPECT_EQ(specs[1].formula.interval, (TimeInterval{0, 2}));
  EXPECT_EQ(specs[2].formula.kind, FormulaKind::next);
  EXPECT_FALSE(specs[2].formula.interval);
}

TEST(ScenestGaps, UAndLowerCaseUAreUniformMotionWhereAnOperandStarts) {
  auto result = parse_ok(
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "npc1 = Vehicle((\"l\"->10, , 5), U((\"l\"->30, , 7)));\n"
      "npc2 = Vehicle((\"l\"->10, , 5), u((\"l\"->30, , 8)), (\"l\"->90));\n"
      "s = CreateScenario{load(\"m\"); ego; {npc1, npc2}; {}; {};};\n"
      "Trace t = EXE(s);\n"
      // After an operand, U is until, also right before a parenthesis.
      "t |= (spd(t[ego], 0) > 1) U(spd(t[ego], 0) > 2);\n");
  const auto& vehicles = result.scenario.vehicles;
  ASSERT_EQ(vehicles.size(), 2u);
  EXPECT_EQ(vehicles[0].motion.kind, MotionKind::uniform);
  EXPECT_EQ(evaluate(*vehicles[0].motion.states.at(0).speed, {}), 7);
  EXPECT_EQ(vehicles[1].motion.kind, MotionKind::uniform);
  EXPECT_EQ(evaluate(*vehicles[1].motion.states.at(0).speed, {}), 8);
  EXPECT_EQ(result.scenario.specs.at(0).formula.kind, FormulaKind::until);
}

}  // namespace
}  // namespace scenfuzz
