// A `stop` aims at its vehicle's ENDSIGN (docs/accident.md, "The vehicles"): it begins when
// braking evenly stops the vehicle's front short of the sign's place, rather than after a delay;
// a stop that cannot aim is warned of.
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

// A car heading north up the crossroad's south arm towards a red light at y = -8, a truck behind.
std::string red_light(const std::string& car_chain, const std::string& end_sign = "light_south") {
  return "STATIC [ ROAD [ KIND = crossroad; ] LIGHT [ ID = light_south; COLOR = red; COORD = "
         "(5.5, -8); ] ]\nDYNAMIC [\nVEHICLE [ ID = car1; KIND = car; INITDIRECTION = north; "
         "ENDSIGN = " +
         end_sign + "; CHAIN [ " + car_chain +
         " ] ]\nVEHICLE [ ID = truck1; KIND = truck; INITDIRECTION = north; CHAIN [ EVENT [ KIND "
         "= driving_forward; ] ] ]\n]\nACCIDENT [ COLLISION [ ACTOR = truck1, front; VICTIM = "
         "car1, rear; ] ]\n";
}

std::vector<std::string> parameter_names(const ScenarioTemplate& scenario) {
  std::vector<std::string> names;
  for (const Parameter& parameter : scenario.parameters) names.push_back(parameter.name);
  return names;
}

double parameter(const ScenarioTemplate& scenario, const std::vector<double>& values,
                 const std::string& name) {
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].name == name) return values[i];
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

TEST(AccEndSignStop, TheStopBeginsWhereEvenBrakingStopsTheFrontShortOfTheSign) {
  const std::string text = red_light("EVENT [ KIND = driving_forward; ] EVENT [ KIND = stop; ]");
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(SourceFile("test.acc", text), parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  EXPECT_THAT(parameter_names(scenario),
              ElementsAre("car1.start_distance", "car1.speed", "car1.event2.short_of_sign",
                          "car1.event2.deceleration", "truck1.start_distance", "truck1.speed"));
  const std::vector<ManoeuvrePhase>& phases = scenario.ego.motion.phases;
  ASSERT_EQ(phases.size(), 2u);
  const ManoeuvrePhase& stop = phases[1];
  EXPECT_EQ(stop.manoeuvre, "Stop");
  ASSERT_TRUE(stop.start_when.has_value());
  ASSERT_EQ(stop.parameters.size(), 1u);
  EXPECT_EQ(stop.parameters[0].name, "duration");
  for (const std::vector<double>& values :
       {std::vector<double>{100, 10, 2, 3, 0, 5}, std::vector<double>{60, 20, 0, 5, 0, 5}}) {
    // Driving on at its speed until the stop begins, then braking evenly over its duration.
    const double speed = parameter(scenario, values, "car1.speed");
    const double begins = evaluate(stop.start_when->terms[1].value, values);
    const double duration = evaluate(stop.parameters[0].value, values);
    EXPECT_DOUBLE_EQ(duration, speed / parameter(scenario, values, "car1.event2.deceleration"));
    const double centre =
        evaluate(scenario.ego.initial.position.y, values) + speed * begins + speed * duration / 2;
    // The car's front (2.35 m ahead of its centre) stops short_of_sign before y = -8.
    EXPECT_NEAR(centre + 2.35, -8 - parameter(scenario, values, "car1.event2.short_of_sign"), 1e-9);
  }
}

TEST(AccEndSignStop, AnEndSignOffItsWayIsWarnedOfAndTheStopStartsAfterItsDelay) {
  const std::string text =
      red_light("EVENT [ KIND = driving_forward; ] EVENT [ KIND = stop; ]", "(100, 100)");
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok());
  EXPECT_THAT(format_diagnostics(SourceFile("test.acc", text), parsed.diagnostics),
              HasSubstr("car1's ENDSIGN lies 100 m from the line of its way in, not beside it"));
  EXPECT_THAT(parameter_names(parsed.scenario),
              ElementsAre("car1.start_distance", "car1.speed", "car1.event2.delay",
                          "truck1.start_distance", "truck1.speed"));
}

TEST(AccEndSignStop, AStopAfterASpeedChangeCannotAimAndIsWarnedOf) {
  const std::string text = red_light(
      "EVENT [ KIND = driving_forward; ] EVENT [ KIND = driving_forward; ] EVENT [ KIND = stop; ]");
  const ScenarioParse parsed = parse_scenario(SourceFile("test.acc", text));
  ASSERT_TRUE(parsed.ok());
  EXPECT_THAT(format_diagnostics(SourceFile("test.acc", text), parsed.diagnostics),
              HasSubstr("warning: car1's stop comes after an event that changes its speed or its "
                        "way: it cannot aim at the ENDSIGN"));
  EXPECT_THAT(
      parameter_names(parsed.scenario),
      ElementsAre("car1.start_distance", "car1.speed", "car1.event2.delay", "car1.event2.speed",
                  "car1.event3.delay", "truck1.start_distance", "truck1.speed"));
}

}  // namespace
}  // namespace scenfuzz::accident
