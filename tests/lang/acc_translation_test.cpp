// The accident formalism's translation (docs/accident.md, "What a description means"): the road
// kind picks a built-in map, each vehicle starts on the way in its INITDIRECTION names with its
// speed, start distance and event timings as the search space, its chain becomes manoeuvre
// phases, the collisions become expected collisions, and what cannot be simulated is said.
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

std::string description(const std::string& road, const std::string& statics,
                        const std::string& vehicles, const std::string& collisions) {
  return "STATIC [ ROAD [ KIND = " + road + "; ] " + statics + " ]\nDYNAMIC [\n" + vehicles +
         "]\nACCIDENT [\n" + collisions + "]\n";
}

std::string vehicle(const std::string& id, const std::string& kind, const std::string& heading,
                    const std::string& chain) {
  return "VEHICLE [ ID = " + id + "; KIND = " + kind + "; " +
         (heading.empty() ? "" : "INITDIRECTION = " + heading + "; ") + "CHAIN [ " + chain +
         " ] ]\n";
}

const std::string kCarsim = description(
    "crossroad", "TREE [ ID = tree1; COORD = (8.5, 9); ]",
    vehicle("car1", "car", "north", "EVENT [ KIND = driving_forward; ]") +
        vehicle("truck1", "truck", "east", "CRITICAL_EVENT [ KIND = driving_forward; ]"),
    "COLLISION [ ACTOR = truck1, front; VICTIM = car1, leftside; COORD = (1.75, "
    "-1.75); ]\nCOLLISION [ ACTOR = car1, front; VICTIM = tree1, unknown; ]\n");

ScenarioParse read(const std::string& text, TranslateOptions options = {}) {
  return parse_scenario(SourceFile("test.acc", text), options);
}

std::string messages(const std::string& text, const Diagnostics& diagnostics) {
  return format_diagnostics(SourceFile("test.acc", text), diagnostics);
}

std::vector<std::string> parameter_names(const ScenarioTemplate& scenario) {
  std::vector<std::string> names;
  for (const Parameter& parameter : scenario.parameters) names.push_back(parameter.name);
  return names;
}

// The value of `value` with every parameter at `fraction` of its range.
double at_fraction(const ScenarioTemplate& scenario, const Value& value, double fraction) {
  std::vector<double> values;
  for (const Parameter& p : scenario.parameters)
    values.push_back(p.lower + fraction * (p.upper - p.lower));
  return evaluate(value, values);
}

TEST(AccTranslation, CarsimExampleIsACrossroadWithTheVictimAsEgoAndTwoExpectedCollisions) {
  const ScenarioParse parsed = read(kCarsim);
  ASSERT_TRUE(parsed.ok()) << messages(kCarsim, parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  EXPECT_EQ(scenario.language, SourceLanguage::accident);
  EXPECT_EQ(scenario.map.name, "crossroads");
  EXPECT_EQ(scenario.ego.name, "car1");  // the first collision's victim
  EXPECT_EQ(scenario.ego.motion.kind, MotionKind::manoeuvres);
  ASSERT_EQ(scenario.vehicles.size(), 1u);
  EXPECT_EQ(scenario.vehicles[0].name, "truck1");
  ASSERT_TRUE(scenario.vehicles[0].type.has_value());
  EXPECT_EQ(scenario.vehicles[0].type->model, "truck");
  EXPECT_EQ(scenario.npc_behaviour, NpcBehaviour::scripted);
  EXPECT_THAT(parameter_names(scenario), ElementsAre("car1.start_distance", "car1.speed",
                                                     "truck1.start_distance", "truck1.speed"));
  ASSERT_EQ(scenario.obstacles.size(), 1u);
  EXPECT_EQ(scenario.obstacles[0].name, "tree1");
  ASSERT_EQ(scenario.expected_collisions.size(), 2u);
  const ExpectedCollision& first = scenario.expected_collisions[0];
  EXPECT_EQ(first.striker, "truck1");
  EXPECT_EQ(first.victim, "car1");
  EXPECT_EQ(first.striker_part, VehiclePart::front);
  EXPECT_EQ(first.victim_part, VehiclePart::left_side);
  ASSERT_TRUE(first.position.has_value());
  EXPECT_DOUBLE_EQ(first.position->x.constant, 1.75);
  EXPECT_DOUBLE_EQ(first.position->y.constant, -1.75);
  EXPECT_EQ(scenario.expected_collisions[1].victim, "tree1");
  EXPECT_FALSE(scenario.expected_collisions[1].position.has_value());
}

TEST(AccTranslation, AVehicleStartsOnItsWayInInTheKerbLaneItsStartDistanceBeforeTheJunction) {
  const ScenarioParse parsed = read(kCarsim);
  ASSERT_TRUE(parsed.ok());
  const ScenarioTemplate& scenario = parsed.scenario;
  // Heading north: up the south arm, x = +1.75; the arm begins 3.5 + 3 m from the centre.
  const Position& car = scenario.ego.initial.position;
  EXPECT_DOUBLE_EQ(at_fraction(scenario, car.x, 0), 1.75);
  EXPECT_DOUBLE_EQ(at_fraction(scenario, car.y, 0), -6.5);
  EXPECT_DOUBLE_EQ(at_fraction(scenario, car.y, 1), -126.5);
  // Heading east: along the west arm, south of its axis.
  const Position& truck = scenario.vehicles[0].initial.position;
  EXPECT_DOUBLE_EQ(at_fraction(scenario, truck.x, 0.5), -66.5);
  EXPECT_DOUBLE_EQ(at_fraction(scenario, truck.y, 0.5), -1.75);
}

TEST(AccTranslation, LaterEventsStartAfterDelaysThatAddUp) {
  const std::string text =
      description("crossroad", "",
                  vehicle("car1", "car", "north",
                          "EVENT [ KIND = driving_forward; ] EVENT [ KIND = stop; ] "
                          "CRITICAL_EVENT [ KIND = driving_forward; ]") +
                      vehicle("truck1", "truck", "north", "EVENT [ KIND = driving_forward; ]"),
                  "COLLISION [ ACTOR = truck1, front; VICTIM = car1, rear; ]\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  EXPECT_THAT(
      parameter_names(scenario),
      ElementsAre("car1.start_distance", "car1.speed", "car1.event2.delay", "car1.event3.delay",
                  "car1.event3.speed", "truck1.start_distance", "truck1.speed"));
  const std::vector<ManoeuvrePhase>& phases = scenario.ego.motion.phases;
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[0].manoeuvre, "Drive");
  EXPECT_FALSE(phases[0].start_when.has_value());
  EXPECT_EQ(phases[1].manoeuvre, "Stop");
  EXPECT_EQ(phases[2].manoeuvre, "Drive");
  EXPECT_TRUE(phases[2].critical);
  ASSERT_TRUE(phases[2].start_when.has_value());
  // The third event starts both delays after the start: 5 + 5 s at the middle of their ranges.
  EXPECT_DOUBLE_EQ(at_fraction(scenario, phases[2].start_when->terms[1].value, 0.5), 10);
  EXPECT_DOUBLE_EQ(at_fraction(scenario, phases[1].start_when->terms[1].value, 0.5), 5);
}

TEST(AccTranslation, OvertakingGoesOutAndComesBackAfterAPassTime) {
  const std::string text =
      description("straightroad", "",
                  vehicle("car1", "car", "east",
                          "EVENT [ KIND = driving_forward; ] CRITICAL_EVENT [ KIND = overtake; ]") +
                      vehicle("car2", "car", "west", "EVENT [ KIND = driving_forward; ]"),
                  "COLLISION [ ACTOR = car1, front; VICTIM = car2, front; COORD = (45, 1.75); ]\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  EXPECT_EQ(scenario.map.name, "straight");
  const std::vector<ManoeuvrePhase>& phases = scenario.vehicles.empty() ? scenario.ego.motion.phases
                                              : scenario.ego.name == "car1"
                                                  ? scenario.ego.motion.phases
                                                  : scenario.vehicles[0].motion.phases;
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[1].manoeuvre, "Overtake");
  EXPECT_EQ(phases[2].manoeuvre, "LaneChangeRight");
  // The straight road's middle is the scene's centre: the collision 45 m east of it.
  ASSERT_TRUE(scenario.expected_collisions[0].position.has_value());
  EXPECT_DOUBLE_EQ(scenario.expected_collisions[0].position->x.constant, 245);
}

TEST(AccTranslation, TwoLanesEachWayWhenAVehicleChangesLanesAndTheLanesAreReadFromTheAccident) {
  const std::string text = description(
      "straightroad", "",
      vehicle("car1", "car", "east",
              "EVENT [ KIND = driving_forward; ] CRITICAL_EVENT [ KIND = change_lane_left; ]") +
          vehicle("car2", "car", "east", "EVENT [ KIND = driving_forward; ]") +
          vehicle("car3", "truck", "east", "EVENT [ KIND = driving_forward; ]"),
      "COLLISION [ ACTOR = car1, leftside; VICTIM = car2, rightside; ]\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  const ScenarioTemplate& scenario = parsed.scenario;
  bool two_lanes = false;
  for (const NamedValue& parameter : scenario.map.parameters)
    if (parameter.name == "lanes") two_lanes = parameter.value.constant == 2;
  EXPECT_TRUE(two_lanes);
  // car1 changes left, so it starts in the kerb lane; car2, which it sideswipes, in the lane it
  // changes to; car3's lane is a choice.
  EXPECT_THAT(
      parameter_names(scenario),
      ElementsAre("car1.start_distance", "car1.speed", "car1.event2.delay", "car2.start_distance",
                  "car2.speed", "car3.start_distance", "car3.lane", "car3.speed"));
  ASSERT_EQ(scenario.ego.name, "car2");
  std::vector<double> values(scenario.parameters.size(), 0);
  EXPECT_DOUBLE_EQ(evaluate(scenario.ego.initial.position.y, values), -1.75);
  ASSERT_EQ(scenario.vehicles.size(), 2u);
  EXPECT_DOUBLE_EQ(evaluate(scenario.vehicles[0].initial.position.y, values), -5.25);
  const Actor& car3 = scenario.vehicles[1];
  EXPECT_DOUBLE_EQ(evaluate(car3.initial.position.y, values), -5.25);
  values[6] = 1;  // beside the kerb lane
  EXPECT_DOUBLE_EQ(evaluate(car3.initial.position.y, values), -1.75);
}

TEST(AccTranslation, EgoCanBeAnyNamedVehicleAndAnUnknownOneIsAnError) {
  const ScenarioParse truck = read(kCarsim, {"truck1"});
  ASSERT_TRUE(truck.ok());
  EXPECT_EQ(truck.scenario.ego.name, "truck1");
  const ScenarioParse unknown = read(kCarsim, {"bus1"});
  EXPECT_FALSE(unknown.ok());
  EXPECT_THAT(messages(kCarsim, unknown.diagnostics),
              HasSubstr("--ego names 'bus1', which is no VEHICLE of this description (car1, "
                        "truck1)"));
}

TEST(AccTranslation, AHeadingTheRoadHasNoWayInIsAnErrorAtTheWord) {
  const std::string valid =
      description("straightroad", "",
                  vehicle("car1", "car", "north", "EVENT [ KIND = stop; ]") +
                      vehicle("car2", "car", "east", "EVENT [ KIND = stop; ]"),
                  "COLLISION [ ACTOR = car1, front; VICTIM = car2, rear; ]\n");
  const ScenarioParse parsed = read(valid);
  EXPECT_FALSE(parsed.ok());
  EXPECT_THAT(messages(valid, parsed.diagnostics),
              HasSubstr("test.acc:3:50: error: car1 cannot start heading north on a straightroad: "
                        "traffic there starts heading east or west"));
}

TEST(AccTranslation, WithoutAnInitialDirectionTheStartSignChoosesTheWayIn) {
  const std::string text =
      description("crossroad", "STOPSIGN [ COORD = (8, 5.5); ]",
                  "VEHICLE [ ID = car1; KIND = car; STARTSIGN = (8, 5.5); CHAIN [ EVENT [ KIND = "
                  "driving_forward; ] ] ]\n" +
                      vehicle("car2", "car", "", "EVENT [ KIND = driving_forward; ]"),
                  "COLLISION [ ACTOR = car1, front; VICTIM = car2, rightside; ]\n");
  const ScenarioParse parsed = read(text);
  EXPECT_FALSE(parsed.ok());
  // car1 comes in on the east arm heading west; car2 says neither.
  EXPECT_THAT(messages(text, parsed.diagnostics),
              HasSubstr("car2 has neither an INITDIRECTION nor a STARTSIGN"));
  ASSERT_EQ(parsed.scenario.vehicles.size(), 1u);
  EXPECT_DOUBLE_EQ(at_fraction(parsed.scenario, parsed.scenario.vehicles[0].initial.position.y, 0),
                   1.75);
  EXPECT_EQ(parsed.scenario.traffic.stop_signs.size(), 1u);
}

TEST(AccTranslation, LightsSetTheCrossroadsSignalOfTheirArmAndAreLeftOutElsewhere) {
  const std::string crossroad = description(
      "crossroad",
      "LIGHT [ ID = l1; COLOR = red; COORD = (5.5, -8); ] LIGHT [ ID = l2; COLOR = "
      "orange; COORD = (-8, -5.5); ] LIGHT [ ID = l3; COLOR = inactive; COORD = (0, 9); ]",
      vehicle("car1", "car", "north", "EVENT [ KIND = stop; ]") +
          vehicle("car2", "truck", "north", "EVENT [ KIND = driving_forward; ]"),
      "COLLISION [ ACTOR = car2, front; VICTIM = car1, rear; ]\n");
  const ScenarioParse parsed = read(crossroad);
  ASSERT_TRUE(parsed.ok()) << messages(crossroad, parsed.diagnostics);
  const auto& lights = parsed.scenario.traffic.lights;
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].id, "light_south");
  EXPECT_EQ(lights[0].color, "red");
  EXPECT_EQ(lights[1].id, "light_west");
  EXPECT_EQ(lights[1].color, "yellow");
  EXPECT_THAT(messages(crossroad, parsed.diagnostics),
              HasSubstr("warning: light 'l3' is inactive, but the crossroad's signals always run"));
  const std::string straight =
      description("straightroad", "LIGHT [ ID = l1; COLOR = red; COORD = (5.5, -8); ]",
                  vehicle("car1", "car", "east", "EVENT [ KIND = stop; ]") +
                      vehicle("car2", "truck", "east", "EVENT [ KIND = driving_forward; ]"),
                  "COLLISION [ ACTOR = car2, front; VICTIM = car1, rear; ]\n");
  const ScenarioParse on_straight = read(straight);
  ASSERT_TRUE(on_straight.ok());
  EXPECT_TRUE(on_straight.scenario.traffic.lights.empty());
  EXPECT_THAT(messages(straight, on_straight.diagnostics),
              HasSubstr("light 'l1' is left out: only a crossroad has traffic lights"));
}

TEST(AccTranslation, ATurnRoadIsTheCurveMapWithItsBendAtTheScenesCentre) {
  const std::string text =
      description("turn_left", "",
                  vehicle("car1", "car", "east", "EVENT [ KIND = driving_forward; ]") +
                      vehicle("car2", "car", "south", "EVENT [ KIND = driving_forward; ]"),
                  "COLLISION [ ACTOR = car1, front; VICTIM = car2, front; ]\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(text, parsed.diagnostics);
  EXPECT_EQ(parsed.scenario.map.name, "curve");
  // car2 comes south down the straight after the bend (x = 30 + 150 on the map, west of its axis).
  const Position& car2 = parsed.scenario.ego.initial.position;
  ASSERT_EQ(parsed.scenario.ego.name, "car2");
  EXPECT_DOUBLE_EQ(at_fraction(parsed.scenario, car2.x, 0), 178.25);
  EXPECT_DOUBLE_EQ(at_fraction(parsed.scenario, car2.y, 0), 30);
}

}  // namespace
}  // namespace scenfuzz::accident
