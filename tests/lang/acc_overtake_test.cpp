// What an `overtake` overtakes (docs/accident.md, "The vehicles"): the vehicle ahead, the nearest
// other one starting the same way in the same lane that does not overtake itself. The overtaker
// starts a gap behind it and faster by a difference; with nothing to overtake it is warned of.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/accident/accident.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::accident {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

std::string vehicle(const std::string& id, const std::string& kind, const std::string& heading,
                    const std::string& chain) {
  return "VEHICLE [ ID = " + id + "; KIND = " + kind + "; INITDIRECTION = " + heading +
         "; CHAIN [ " + chain + " ] ]\n";
}

std::string straight_road(const std::string& vehicles) {
  return "STATIC [ ROAD [ KIND = straightroad; ] ]\nDYNAMIC [\n" + vehicles +
         "]\nACCIDENT [ COLLISION [ ACTOR = car1, front; VICTIM = car2, front; ] ]\n";
}

const std::string kOvertaker = vehicle(
    "car1", "car", "east", "EVENT [ KIND = driving_forward; ] CRITICAL_EVENT [ KIND = overtake; ]");
const std::string kOncoming = vehicle("car2", "car", "west", "EVENT [ KIND = driving_forward; ]");
const std::string kTruck = vehicle("truck1", "truck", "east", "EVENT [ KIND = driving_forward; ]");

const Actor& actor_named(const ScenarioTemplate& scenario, const std::string& name) {
  if (scenario.ego.name == name) return scenario.ego;
  for (const Actor& actor : scenario.vehicles)
    if (actor.name == name) return actor;
  ADD_FAILURE() << "no actor " << name;
  return scenario.ego;
}

const Parameter* parameter_named(const ScenarioTemplate& scenario, const std::string& name) {
  for (const Parameter& parameter : scenario.parameters)
    if (parameter.name == name) return &parameter;
  return nullptr;
}

std::vector<std::string> parameter_names(const ScenarioTemplate& scenario) {
  std::vector<std::string> names;
  for (const Parameter& parameter : scenario.parameters) names.push_back(parameter.name);
  return names;
}

// Every parameter at `fraction` of its range.
std::vector<double> at_fraction(const ScenarioTemplate& scenario, double fraction) {
  std::vector<double> values;
  for (const Parameter& p : scenario.parameters)
    values.push_back(p.lower + fraction * (p.upper - p.lower));
  return values;
}

TEST(AccOvertake, TheOvertakerStartsAGapBehindTheVehicleAheadAndFasterThanIt) {
  // The truck is written after the car: its unknowns come first all the same.
  const std::string text = straight_road(kOvertaker + kTruck + kOncoming);
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(SourceFile("test.acc", text), parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  EXPECT_THAT(parameter_names(scenario),
              ElementsAre("truck1.start_distance", "truck1.speed", "car1.gap",
                          "car1.speed_difference", "car1.event2.delay", "car1.event2.pull_out",
                          "car1.event2.pass", "car2.start_distance", "car2.speed"));
  const Parameter* gap = parameter_named(scenario, "car1.gap");
  ASSERT_NE(gap, nullptr);
  EXPECT_EQ(gap->lower, 10);
  EXPECT_EQ(gap->upper, 60);
  EXPECT_EQ(gap->unit, "m");
  const Parameter* difference = parameter_named(scenario, "car1.speed_difference");
  ASSERT_NE(difference, nullptr);
  EXPECT_GT(difference->lower, 0);
  const Actor& car = actor_named(scenario, "car1");
  const Actor& truck = actor_named(scenario, "truck1");
  for (double fraction : {0.0, 0.5, 1.0}) {
    const std::vector<double> values = at_fraction(scenario, fraction);
    // Eastbound: behind is further west, by the gap exactly.
    const double behind =
        evaluate(truck.initial.position.x, values) - evaluate(car.initial.position.x, values);
    EXPECT_DOUBLE_EQ(behind, values[2]) << fraction;
    EXPECT_DOUBLE_EQ(evaluate(car.initial.position.y, values),
                     evaluate(truck.initial.position.y, values));
    EXPECT_GT(evaluate(*car.initial.speed, values), evaluate(*truck.initial.speed, values));
  }
  // It pulls out once close behind the truck, and comes back once past it.
  const std::vector<ManoeuvrePhase>& phases = car.motion.phases;
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[1].manoeuvre, "Overtake");
  ASSERT_TRUE(phases[1].start_when.has_value());
  EXPECT_EQ(phases[1].start_when->kind, FormulaKind::conjunction);
  ASSERT_TRUE(phases[2].start_when.has_value());
  ASSERT_EQ(phases[2].start_when->terms.size(), 2u);
  EXPECT_EQ(phases[2].start_when->terms[0].name, "longitudinal_offset");
  EXPECT_GT(evaluate(phases[2].start_when->terms[1].value, at_fraction(scenario, 0)), 0);
}

TEST(AccOvertake, TheNearestVehicleWrittenThatDoesNotOvertakeIsTheOneAhead) {
  const std::string text =
      straight_road(vehicle("car3", "car", "east", "EVENT [ KIND = driving_forward; ]") +
                    vehicle("car4", "car", "east", "EVENT [ KIND = overtake; ]") + kOvertaker +
                    kOncoming + kTruck);
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok());
  // car1's neighbours are car4 (overtakes) and car2 (westbound): the nearest that qualifies is
  // car3 (two before it) rather than truck1 (three after it); car4 overtakes car3 too.
  EXPECT_NE(parameter_named(parsed.scenario, "car1.gap"), nullptr);
  EXPECT_NE(parameter_named(parsed.scenario, "car4.gap"), nullptr);
  EXPECT_EQ(parameter_named(parsed.scenario, "car3.start_distance")->upper, 60);
  EXPECT_EQ(parameter_named(parsed.scenario, "truck1.start_distance")->upper, 120);
  const std::vector<double> values = at_fraction(parsed.scenario, 0.5);
  EXPECT_DOUBLE_EQ(evaluate(actor_named(parsed.scenario, "car3").initial.position.x, values) -
                       evaluate(actor_named(parsed.scenario, "car1").initial.position.x, values),
                   35);  // the middle of [10, 60]
}

TEST(AccOvertake, WithNothingAheadTheOvertakeIsWarnedOfAndKeepsItsOwnStart) {
  const std::string text = straight_road(kOvertaker + kOncoming);
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok());
  EXPECT_THAT(format_diagnostics(SourceFile("test.acc", text), parsed.diagnostics),
              HasSubstr("test.acc:3:98: warning: car1 overtakes, but no other vehicle starts "
                        "heading east in its lane without overtaking itself: there is nothing to "
                        "overtake"));
  EXPECT_THAT(
      parameter_names(parsed.scenario),
      ElementsAre("car1.start_distance", "car1.speed", "car1.event2.delay", "car1.event2.speed",
                  "car1.event2.pass", "car2.start_distance", "car2.speed"));
  const std::string ahead = straight_road(kOvertaker + kTruck + kOncoming);
  EXPECT_THAT(format_diagnostics(SourceFile("test.acc", ahead),
                                 parse_scenario(SourceFile("test.acc", ahead)).diagnostics),
              Not(HasSubstr("nothing to overtake")));
}

}  // namespace
}  // namespace scenfuzz::accident
