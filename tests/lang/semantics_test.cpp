// What AVUnit constructs mean in the IR: parameters and their names, coordinate offsets, shared
// ranges, precedence, actor names, concrete printing in the user's layout.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz {
namespace {

using test::parse_text;

const std::string kScenarioTail =
    "s = CreateScenario{load(\"straight\"); ego; {npc1}; {}; {};};\n"
    "Trace t = EXE(s);\n";

avunit::ParseResult parse_ok(const std::string& text) {
  avunit::ParseResult result = parse_text(text);
  EXPECT_TRUE(result.ok()) << format_diagnostics(SourceFile("test.avu", text), result.diagnostics);
  return result;
}

TEST(Semantics, CoordinateRangeOffsetsXAndY) {
  auto result = parse_ok(
      "ego = AV(((553090.1, 4182687.8) range(-10, 10) & (10, 100)), (\"l\"->5));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\n");
  const auto& parameters = result.scenario.parameters;
  ASSERT_EQ(parameters.size(), 2u);
  EXPECT_EQ(parameters[0].name, "ego.init.position.x");
  EXPECT_EQ(parameters[0].lower, -10);
  EXPECT_EQ(parameters[0].upper, 10);
  EXPECT_EQ(parameters[1].name, "ego.init.position.y");
  EXPECT_EQ(parameters[1].unit, "m");
  const Position& start = result.scenario.ego.initial.position;
  std::vector<double> values = {3.0, 50.0};
  EXPECT_DOUBLE_EQ(evaluate(start.x, values), 553093.1);
  EXPECT_DOUBLE_EQ(evaluate(start.y, values), 4182737.8);
}

TEST(Semantics, RangeInAVariableIsOneParameterNamedByItsFirstUse) {
  auto result = parse_ok(
      "v = range(8, 12);\n"
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "npc1 = Vehicle((\"l\"->30, , v), uniform((\"l\"->30, , v)));\n" +
      kScenarioTail);
  ASSERT_EQ(result.scenario.parameters.size(), 1u);
  EXPECT_EQ(result.scenario.parameters[0].name, "npc1.init.speed");
  const Actor& npc = result.scenario.vehicles.at(0);
  EXPECT_EQ(npc.initial.speed->parameter, 0);
  EXPECT_EQ(npc.motion.states.at(0).speed->parameter, 0);
}

TEST(Semantics, ParametersAreNamedAndTypedBySlot) {
  auto result = parse_ok(
      "ego = AV((\"l\"->range(0, 10)), (\"l\"->100));\n"
      "npc1 = Vehicle((\"l\"->30, range(-5, 5) deg), W((\"l\"->40, , 5), (\"l\"->50, , "
      "range(1, 3))));\n"
      "s = CreateScenario{load(\"straight\"); ego; {npc1}; {}; {}; "
      "Environment(range(6:00, 18:00), {fog: range(0, 0.5)});};\n");
  const auto& parameters = result.scenario.parameters;
  ASSERT_EQ(parameters.size(), 5u);
  EXPECT_EQ(parameters[0].name, "ego.init.position.s");
  EXPECT_EQ(parameters[1].name, "npc1.init.heading");
  EXPECT_EQ(parameters[1].kind, ParameterKind::angle);
  EXPECT_EQ(parameters[1].unit, "deg");
  EXPECT_EQ(parameters[2].name, "npc1.waypoint[1].speed");
  EXPECT_EQ(parameters[2].unit, "m/s");
  EXPECT_EQ(parameters[3].name, "environment.time");
  EXPECT_EQ(parameters[3].unit, "time of day");
  EXPECT_EQ(parameters[3].lower, 6 * 3600);
  EXPECT_EQ(parameters[3].upper, 18 * 3600);
  EXPECT_EQ(parameters[4].name, "environment.fog");
  EXPECT_EQ(parameters[4].location.line, 3u);
}

TEST(Semantics, UnusedRangeIsAWarningAndNotADimension) {
  auto result = parse_ok(
      "spare = range(1, 2);\n"
      "ego = AV((\"l\"->0), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {};};\n");
  EXPECT_TRUE(result.scenario.parameters.empty());
  ASSERT_EQ(result.diagnostics.all().size(), 1u);
  EXPECT_EQ(result.diagnostics.all()[0].severity, Severity::warning);
  EXPECT_EQ(result.diagnostics.all()[0].location.line, 1u);
  EXPECT_EQ(result.diagnostics.all()[0].location.column, 9u);
}

TEST(Semantics, AndBindsTighterThanOrAndTemporalOperatorsTakeAComparison) {
  auto result = parse_ok("ego = AV((\"l\"->0), (\"l\"->100));\nnpc1 = Vehicle((\"l\"->30));\n" +
                         kScenarioTail +
                         "d = dis(t[ego], t[truth][npc1]);\n"
                         "t |= d > 1 | d > 2 & d > 3;\n"
                         "t |= G d >= 1;\n"
                         "t |= d > 1 -> d > 2 -> d > 3;\n");
  const auto& specs = result.scenario.specs;
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0].formula.kind, FormulaKind::disjunction);
  EXPECT_EQ(specs[0].formula.operands[1].kind, FormulaKind::conjunction);
  EXPECT_EQ(specs[1].formula.kind, FormulaKind::always);
  EXPECT_EQ(specs[1].formula.operands[0].kind, FormulaKind::comparison);
  EXPECT_EQ(specs[2].formula.kind, FormulaKind::implication);
  EXPECT_EQ(specs[2].formula.operands[0].kind, FormulaKind::implication);
  const SpecTerm& distance = specs[1].formula.operands[0].terms[0];
  EXPECT_EQ(distance.kind, TermKind::signal);
  EXPECT_EQ(distance.name, "dis");
  EXPECT_EQ(distance.operands[1].kind, TermKind::object);
  EXPECT_EQ(distance.operands[1].source, ObjectSource::truth);
  EXPECT_EQ(distance.operands[1].name, "npc1");
}

TEST(Semantics, IntervalsInBothNotationsAndBracedOperands) {
  auto result = parse_ok("ego = AV((\"l\"->0), (\"l\"->100));\nnpc1 = Vehicle((\"l\"->30));\n" +
                         kScenarioTail +
                         "d = dis(t[ego], t[truth][npc1]);\n"
                         "t |= G[0:10] ({d} >= {1.0}) & F[-1, 2.5] (d < 3);\n");
  const Formula& formula = result.scenario.specs.at(0).formula;
  ASSERT_EQ(formula.kind, FormulaKind::conjunction);
  EXPECT_EQ(formula.operands[0].interval, (TimeInterval{0, 10}));
  EXPECT_EQ(formula.operands[1].interval, (TimeInterval{-1, 2.5}));
  EXPECT_EQ(formula.operands[0].operands[0].terms[1].value.constant, 1.0);
}

TEST(Semantics, ProjectionColumnsAndTheBareAcc) {
  auto result = parse_ok("ego = AV((\"l\"->0), (\"l\"->100));\nnpc1 = Vehicle((\"l\"->30));\n" +
                         kScenarioTail +
                         "seen = t[truth][npc1];\n"
                         "t |= G (t[ego].speed < seen.x) & G (acc < 4);\n");
  const Formula& formula = result.scenario.specs.at(0).formula;
  const SpecTerm& speed = formula.operands[0].operands[0].terms[0];
  EXPECT_EQ(speed.kind, TermKind::column);
  EXPECT_EQ(speed.name, "speed");
  ASSERT_EQ(speed.operands.size(), 1u);
  EXPECT_EQ(speed.operands[0].source, ObjectSource::ego);
  const SpecTerm& x = formula.operands[0].operands[0].terms[1];
  EXPECT_EQ(x.kind, TermKind::column);
  EXPECT_EQ(x.operands[0].source, ObjectSource::truth);
  EXPECT_EQ(x.operands[0].name, "npc1");
  const SpecTerm& acc = formula.operands[1].operands[0].terms[0];
  EXPECT_EQ(acc.kind, TermKind::signal);
  EXPECT_EQ(acc.name, "acc");
  EXPECT_TRUE(acc.operands.empty());
  // The printer writes columns back so that they read the same.
  EXPECT_EQ(parse_ok(avunit::print(result.scenario)).scenario, result.scenario);
}

TEST(Semantics, ANegativeLowerBoundBeforeTwoDigitsIsStillTwoBounds) {
  // `-1:10` lexes as a minus and the time 1:10; inside brackets it is the interval -1 to 10.
  for (const char* text : {"G[-1:10](x > 0)", "G[+1:10](x > 0)", "G[-10:10](x > 0)"}) {
    avunit::FormulaParseResult parsed = avunit::parse_formula(SourceFile("--spec", text));
    ASSERT_TRUE(parsed.formula) << text;
    const double lower = text[2] == '-' ? -std::stod(std::string(text).substr(3)) : 1.0;
    EXPECT_EQ(parsed.formula->interval, (TimeInterval{lower, 10})) << text;
  }
}

TEST(Semantics, HeadingsKeepTheirUnitAndReference) {
  auto result = parse_ok(
      "ego = AV((\"l\"->0, -15 deg), (\"l\"->100, 0.5 pi rad related to EGO));\n"
      "npc1 = Vehicle((\"l\"->30, 10 deg related to ego));\n" +
      kScenarioTail);
  const Heading& initial = *result.scenario.ego.initial.heading;
  EXPECT_EQ(initial.angle.constant, -15);
  EXPECT_EQ(initial.unit, AngleUnit::degree);
  const Heading& target = *result.scenario.ego.target->heading;
  EXPECT_DOUBLE_EQ(target.angle.constant, std::numbers::pi / 2);
  EXPECT_EQ(target.unit, AngleUnit::radian);
  EXPECT_EQ(target.relative_to->kind, Direction::Kind::ego);
  const Heading& npc = *result.scenario.vehicles.at(0).initial.heading;
  EXPECT_EQ(npc.relative_to->kind, Direction::Kind::actor);
  EXPECT_EQ(npc.relative_to->actor, "ego");
}

TEST(Semantics, WeatherLevelsAndNumericLaneIds) {
  auto result = parse_ok(
      "ego = AV((1->0.5), (\"l\"->100));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; Environment(7:30, {rain: light, fog: "
      "heavy, snow: 0.3});};\n");
  EXPECT_EQ(result.scenario.ego.initial.position.lane, "1");
  const Environment& environment = *result.scenario.environment;
  EXPECT_EQ(environment.time_of_day->constant, 7 * 3600 + 30 * 60);
  ASSERT_EQ(environment.weather.size(), 3u);
  EXPECT_EQ(environment.weather[0].level, WeatherLevel::light);
  EXPECT_EQ(environment.weather[0].intensity.constant, 0.1);
  EXPECT_EQ(environment.weather[1].intensity.constant, 0.8);
  EXPECT_EQ(environment.weather[2].intensity.constant, 0.3);
}

TEST(Semantics, ActorsAreNamedByTheirFirstVariableOrFreshly) {
  auto result = parse_ok(
      "ego_vehicle = AV((\"l\"->0), (\"l\"->100));\n"
      "lead = Vehicle((\"l\"->30));\nalias = lead;\n"
      "s = CreateScenario{load(\"m\"); ego_vehicle; {alias, Vehicle((\"l\"->60))}; {}; {};};\n");
  EXPECT_EQ(result.scenario.ego.name, "ego_vehicle");
  ASSERT_EQ(result.scenario.vehicles.size(), 2u);
  EXPECT_EQ(result.scenario.vehicles[0].name, "lead");
  EXPECT_EQ(result.scenario.vehicles[1].name, "vehicle1");
}

TEST(Semantics, NamedSpecificationsKeepTheirName) {
  auto result = parse_ok("ego = AV((\"l\"->0), (\"l\"->100));\nnpc1 = Vehicle((\"l\"->30));\n" +
                         kScenarioTail +
                         "safe = G (dis(t[ego], t[truth][npc1]) > 1);\n"
                         "t |= safe;\nt |= safe & F (dis(t[ego], \"l\"->100) < 2);\n");
  ASSERT_EQ(result.scenario.specs.size(), 2u);
  EXPECT_EQ(result.scenario.specs[0].name, "safe");
  EXPECT_EQ(result.scenario.specs[1].name, "spec2");
  EXPECT_EQ(result.scenario.specs[0].trace, "t");
}

TEST(Semantics, AFileWithoutScenarioIsAFragment) {
  auto result = parse_ok("heading1 = range(1 pi, 10 pi) deg related to EGO;\n");
  EXPECT_FALSE(result.scenario.has_scenario);
  EXPECT_TRUE(result.scenario.parameters.empty());
  EXPECT_TRUE(result.diagnostics.all().empty());
}

TEST(Semantics, ConcretePrintReplacesOnlyTheRangesInTheUsersLayout) {
  const std::string text =
      "// my scenario\n"
      "start = (10, 20) range(-1, 1) & (0, 4);\n"
      "ego = AV((start, , range(5, 9)),   (\"l\"->range(50, 60)));\n"
      "s = CreateScenario{load(\"m\"); ego; {}; {}; {}; Environment(range(6:00, 7:00));};\n";
  SourceFile file("mine.avu", text);
  avunit::ParseResult result = avunit::parse(file);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.scenario.parameters.size(), 5u);
  std::string concrete =
      avunit::print_concrete(file, result.scenario, std::vector<double>{0.5, 2, 7.25, 55, 23400});
  EXPECT_NE(concrete.find("start = (10, 20) + (0.5, 2);\n"), std::string::npos) << concrete;
  EXPECT_NE(concrete.find("ego = AV((start, , 7.25),   (\"l\"->55));\n"), std::string::npos)
      << concrete;
  EXPECT_NE(concrete.find("Environment(6:30)"), std::string::npos) << concrete;
  EXPECT_NE(concrete.find("//   ego.init.speed = 7.25 m/s\n"), std::string::npos) << concrete;
  EXPECT_NE(concrete.find("// my scenario\n"), std::string::npos);

  avunit::ParseResult fixed = avunit::parse(SourceFile("mine.avu", concrete));
  ASSERT_TRUE(fixed.ok()) << concrete;
  EXPECT_TRUE(fixed.scenario.parameters.empty());
  EXPECT_EQ(evaluate(fixed.scenario.ego.initial.position.x, {}), 10.5);
  EXPECT_EQ(fixed.scenario.environment->time_of_day->constant, 23400);
}

TEST(Semantics, ParsingIsDeterministic) {
  auto files = test::files_in(test::corpus_dir(), {".avu"});
  ASSERT_FALSE(files.empty());
  SourceFile file = test::load(files.front());
  EXPECT_EQ(avunit::parse(file).scenario, avunit::parse(file).scenario);
  EXPECT_EQ(avunit::print(avunit::parse(file).scenario),
            avunit::print(avunit::parse(file).scenario));
}

}  // namespace
}  // namespace scenfuzz
