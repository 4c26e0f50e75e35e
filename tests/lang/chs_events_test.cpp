// CH-Scenario events (docs/ch-scenario.md, "Events"): `when GUARD do ACTION` becomes manoeuvre
// phases of the road user the action moves, started when the guard holds; a probability between 0
// and 1 becomes a search parameter choosing whether the event fires, written back as 1 or 0 with
// the outcomes' probability; what scenfuzz cannot read leaves the event out with a warning.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/chs/chs.hpp"
#include "lang/chs/parser.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::chs {
namespace {

using ::testing::HasSubstr;

// A van parked in the kerb lane 90 m ahead of the car (the ego), a truck ahead in the car's lane,
// and the constraint whose events a test writes.
std::string with_events(const std::string& constraint) {
  return "import from MAP\n  length: 400\n  width: 60\n"
         "RoadNetwork\n  road east_road\n"
         "    left boundary: (0, 37) (400, 37)\n"
         "    center lines: (0, 30) (400, 30)\n"
         "    right boundary: (0, 23) (400, 23)\n"
         "Entity\n"
         "  StaticEntity1\n    name: van\n    overview: a parked van\n    position: (120, 25)\n"
         "  DynamicEntity1\n    name: car\n    speed: 40\n    position: (30, 28)\n"
         "  DynamicEntity2\n    name: truck\n    speed: 36\n    position: (80, 28)\n"
         "ConstraintList\n" +
         constraint;
}

ScenarioParse read(const std::string& text) { return parse_scenario(SourceFile("test.chs", text)); }

std::string messages(const std::string& text, const Diagnostics& diagnostics) {
  return format_diagnostics(SourceFile("test.chs", text), diagnostics);
}

const Actor& vehicle(const ScenarioTemplate& scenario, const std::string& name) {
  for (const Actor& actor : scenario.vehicles)
    if (actor.name == name) return actor;
  ADD_FAILURE() << "no vehicle " << name;
  return scenario.ego;
}

double speed_of(const ManoeuvrePhase& phase) {
  for (const NamedValue& parameter : phase.parameters)
    if (parameter.name == "speed") return parameter.value.constant;
  ADD_FAILURE() << phase.manoeuvre << " has no speed";
  return -1;
}

TEST(ChsEvents, AParkedVanDrivesOffWhenTheEgoComesNearWithItsProbability) {
  const std::string text = with_events(
      "  constraint1 relate with van, car\n"
      "    event: when dist < 40 do parked = false; position++\n"
      "    probability: 0.3\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  EXPECT_TRUE(parsed.diagnostics.all().empty()) << messages(text, parsed.diagnostics);
  // The outcome is a search dimension of its own, at the probability's number.
  ASSERT_EQ(parsed.scenario.parameters.size(), 1u);
  const Parameter& outcome = parsed.scenario.parameters[0];
  EXPECT_EQ(outcome.name, "constraint1.event");
  EXPECT_EQ(outcome.kind, ParameterKind::discrete);
  EXPECT_TRUE(outcome.event_outcome);
  EXPECT_THAT(outcome.choices, ::testing::ElementsAre("does not fire", "fires"));
  EXPECT_EQ(text.substr(outcome.location.offset, outcome.location.length), "0.3");
  // The van drives off at 30 km/h (written without a speed), then changes a lane to the left.
  const Motion& van = vehicle(parsed.scenario, "van").motion;
  ASSERT_EQ(van.kind, MotionKind::manoeuvres);
  ASSERT_EQ(van.phases.size(), 2u);
  EXPECT_EQ(van.phases[0].manoeuvre, "Drive");
  EXPECT_DOUBLE_EQ(speed_of(van.phases[0]), 30 / 3.6);
  EXPECT_EQ(van.phases[1].manoeuvre, "LaneChangeLeft");
  EXPECT_FALSE(van.phases[1].start_when);  // it follows the first
  // Started when the van is less than 40 m ahead of the ego and the outcome is "fires".
  ASSERT_TRUE(van.phases[0].start_when);
  const Formula& when = *van.phases[0].start_when;
  ASSERT_EQ(when.kind, FormulaKind::conjunction);
  const Formula& guard = when.operands[0];
  EXPECT_EQ(guard.compare, CompareOp::less);
  EXPECT_EQ(guard.terms[0].name, "longitudinal_offset");
  ASSERT_EQ(guard.terms[0].operands.size(), 2u);
  EXPECT_EQ(guard.terms[0].operands[0].name, "van");
  EXPECT_EQ(guard.terms[0].operands[1].name, "car");
  EXPECT_DOUBLE_EQ(guard.terms[1].value.constant, 40);
  const Formula& fires = when.operands[1];
  EXPECT_EQ(fires.terms[0].value.op, ValueOp::parameter);
  EXPECT_EQ(fires.terms[0].value.parameter, 0);
  EXPECT_DOUBLE_EQ(fires.terms[1].value.constant, 1);
}

TEST(ChsEvents, GuardsReadTimeSpeedsAndParkedRoadUsersActionsChangeSpeedAndStop) {
  const std::string text = with_events(
      "  constraint1 relate with truck, car\n"
      "    event: when wait > 5 do speed = 20\n"
      "    event: when car_speed >= 50 && not van_parked do speed++\n"
      "    event: when truck_stopped == false do parked = true\n"
      "    probability: 1\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  EXPECT_TRUE(parsed.scenario.parameters.empty());  // a probability of 1 always fires
  // `wait` reads the clock, a timer from the start.
  ASSERT_EQ(parsed.scenario.timers.size(), 1u);
  EXPECT_EQ(parsed.scenario.timers[0].name, "time");
  const Motion& truck = vehicle(parsed.scenario, "truck").motion;
  ASSERT_EQ(truck.phases.size(), 3u);
  EXPECT_EQ(truck.phases[0].manoeuvre, "Drive");
  EXPECT_DOUBLE_EQ(speed_of(truck.phases[0]), 20 / 3.6);
  EXPECT_EQ(truck.phases[0].start_when->terms[0].name, "timer");
  // speed++: 10 km/h above its written 36; the guard compares the ego's speed in km/h.
  EXPECT_DOUBLE_EQ(speed_of(truck.phases[1]), 46 / 3.6);
  const Formula& faster = *truck.phases[1].start_when;
  ASSERT_EQ(faster.kind, FormulaKind::conjunction);
  EXPECT_EQ(faster.operands[0].terms[0].kind, TermKind::multiply);
  EXPECT_EQ(faster.operands[0].terms[0].operands[0].operands[0].name, "car");
  EXPECT_EQ(faster.operands[1].kind, FormulaKind::negation);
  const Formula& parked = faster.operands[1].operands[0];
  EXPECT_EQ(parked.terms[0].name, "manoeuvre");
  EXPECT_EQ(parked.terms[0].operands[0].name, "van");
  EXPECT_EQ(parked.terms[1].name, "Stopped");
  EXPECT_EQ(truck.phases[2].manoeuvre, "Stop");
  EXPECT_EQ(truck.phases[2].start_when->kind, FormulaKind::negation);
}

TEST(ChsEvents, WhatCannotBeReadLeavesTheEventOutWithAWarning) {
  const std::string text = with_events(
      "  constraint1 relate with car, edge\n"
      "    event: when wait > 5 do parked = false\n"
      "  constraint2 relate with truck\n"
      "    event: when first_car_parked == false do speed = 10\n"
      "    event: when wait > 1 do honk = true\n"
      "    event: when wait > 1 do bus_speed = 10\n"
      "    event: when wait > 1 do speed = 10\n"
      "    probability: 0\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  const std::string said = messages(text, parsed.diagnostics);
  EXPECT_THAT(said, HasSubstr("test.chs:24:29: warning: the constraint relates with no road user "
                              "scenfuzz drives"));
  EXPECT_THAT(said, HasSubstr("test.chs:26:17: warning: scenfuzz reads no 'first_car_parked' in "
                              "a guard"));
  EXPECT_THAT(said, HasSubstr("test.chs:27:29: warning: scenfuzz reads the actions parked"));
  EXPECT_THAT(said, HasSubstr("test.chs:28:29: warning: 'bus_speed' names no road user"));
  EXPECT_THAT(said, HasSubstr("warning: this event is left out"));
  // None of them moves anybody; the last never fires (probability 0).
  EXPECT_EQ(vehicle(parsed.scenario, "truck").motion.kind, MotionKind::follow_route);
  EXPECT_TRUE(parsed.scenario.parameters.empty());
}

TEST(ChsEvents, AGuardComparingAConditionWithANumberIsAnError) {
  const std::string text = with_events(
      "  constraint1 relate with truck\n"
      "    event: when truck_parked > 3 do speed = 10\n");
  const ScenarioParse parsed = read(text);
  EXPECT_FALSE(parsed.ok());
  EXPECT_THAT(messages(text, parsed.diagnostics),
              HasSubstr("test.chs:24:17: error: compare a condition with true or false"));
}

TEST(ChsEvents, AFindingWritesTheOutcomeChosenAndItsProbability) {
  const std::string text = with_events(
      "  constraint1 relate with van, car\n"
      "    event: when dist < 40 do parked = false\n"
      "    probability: 0.25\n"
      "    event: when dist < 20 do position++\n"
      "    probability: 0.4\n");
  const SourceFile file("test.chs", text);
  const ScenarioParse parsed = parse_scenario(file);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  ASSERT_EQ(parsed.scenario.parameters.size(), 2u);
  const std::string concrete = print_concrete(file, parsed.scenario, std::vector<double>{1, 0});
  EXPECT_THAT(concrete, HasSubstr("#   constraint1.event1 = fires (probability 0.25)\n"));
  EXPECT_THAT(concrete, HasSubstr("#   constraint1.event2 = does not fire (probability 0.6)\n"));
  EXPECT_THAT(concrete, HasSubstr("# the events' outcomes chosen have probability 0.15 together"));
  // The outcomes are written as certainties: the finding replays them without a search.
  const ParseResult back = parse(SourceFile("concrete.chs", concrete));
  ASSERT_TRUE(back.file);
  EXPECT_DOUBLE_EQ(back.file->constraints[0].events[0].probability.value, 1);
  EXPECT_DOUBLE_EQ(back.file->constraints[0].events[1].probability.value, 0);
  const ScenarioParse replayed = parse_scenario(SourceFile("concrete.chs", concrete));
  ASSERT_TRUE(replayed.ok());
  EXPECT_TRUE(replayed.scenario.parameters.empty());
  EXPECT_EQ(vehicle(replayed.scenario, "van").motion.phases.size(), 1u);
}

}  // namespace
}  // namespace scenfuzz::chs
