// WMG SDL level 1 (natural language) on valid input: every sentence form with its values and
// source locations; the conversion to level 2, field by field, for the qualitative words; the
// defaults table's completeness; level detection; and the bundled level-1 corpus, whose
// conversions must print and parse back as level 2 without diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/level1_defaults.hpp"
#include "lang/wmg/level1_parser.hpp"
#include "lang/wmg/level1_phrases.hpp"
#include "lang/wmg/level1_to_level2.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "tests/lang/test_files.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz::wmg {
namespace {

using test::expect_spans;

// The smallest valid level-1 file, in sentences a test replaces one at a time.
struct Sentences {
  std::string header = "VERSION: 1.0\nAUTHOR: 'Ada'\n";
  std::string environment = "During the day, there is a light sky.\n";
  std::string junctions = "There is no junction present.\n";
  std::string roads = "R1 is a straight, motorway.\n";
  std::string features;
  std::string actors = "There is 1 vehicle, Ego.\n";
  std::string locations = "Ego is in R1.\n";
  std::string ssms = "When Ego is driving, Ego drives.\nEgo operates autonomously.\n";

  std::string text() const {
    return header + environment + junctions + roads + features + actors + locations + ssms;
  }
};

Level1File parse_ok(const std::string& text) {
  SourceFile file("t.sdl", text);
  Level1ParseResult result = parse_level1(file);
  EXPECT_TRUE(result.file.has_value()) << format_diagnostics(file, result.diagnostics) << text;
  EXPECT_TRUE(result.diagnostics.all().empty()) << format_diagnostics(file, result.diagnostics);
  return result.file.value_or(Level1File{});
}

// Converts, and checks that the conversion prints as level 2 that parses back to itself.
Level2File convert_ok(const std::string& text) {
  Level1File level1 = parse_ok(text);
  Diagnostics diagnostics;
  Level2File level2 = level1_to_level2(level1, diagnostics);
  EXPECT_FALSE(diagnostics.has_errors());
  std::string printed = print_level2(level2);
  SourceFile printed_file("printed.sdl", printed);
  Level2ParseResult again = parse_level2(printed_file);
  EXPECT_TRUE(again.file.has_value())
      << format_diagnostics(printed_file, again.diagnostics) << printed;
  EXPECT_TRUE(again.diagnostics.all().empty())
      << format_diagnostics(printed_file, again.diagnostics);
  if (again.file) {
    EXPECT_TRUE(*again.file == level2) << printed;
  }
  return level2;
}

void expect_range(const NumberRange& range, double low, double high) {
  EXPECT_DOUBLE_EQ(range.low, low);
  EXPECT_DOUBLE_EQ(range.high, high);
  EXPECT_EQ(range.is_range, low != high);
}

const ActorClause& actor_clause(const Level1Condition& condition) {
  return std::get<ActorClause>(condition);
}

// ---- sentences -------------------------------------------------------------------------------

TEST(WmgLevel1Parser, HeaderVersionAndAuthor) {
  Sentences sentences;
  sentences.header = "VERSION: 2.10\nAUTHOR: 'Grace Hopper'\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  EXPECT_EQ(file.header.version.major_part.value, 2);
  EXPECT_EQ(file.header.version.minor_part.value, 10);
  ASSERT_TRUE(file.header.author.has_value());
  EXPECT_EQ(file.header.author->text, "Grace Hopper");
  expect_spans(file.header.author->location, text, "'Grace Hopper'");
  expect_spans(file.header.version.location, text, "2.10");
}

TEST(WmgLevel1Parser, TheAuthorIsOptional) {
  Sentences sentences;
  sentences.header = "VERSION: 1.0\n";
  EXPECT_FALSE(parse_ok(sentences.text()).header.author.has_value());
}

TEST(WmgLevel1Parser, EnvironmentSentenceWithCloudAndFeatures) {
  Sentences sentences;
  sentences.environment =
      "During the night, there is a dark, partly cloudy sky, with heavy rain, mist and fog and "
      "with a moderate breeze.\n";
  std::string text = sentences.text();
  const EnvironmentSentence environment = parse_ok(text).environment;
  EXPECT_EQ(environment.time_of_day.text, "night");
  expect_spans(environment.time_of_day.location, text, "night");
  EXPECT_EQ(environment.light.text, "dark");
  ASSERT_TRUE(environment.cloud.has_value());
  EXPECT_EQ(environment.cloud->text, "partly cloudy");
  expect_spans(environment.cloud->location, text, "partly cloudy");
  ASSERT_EQ(environment.features.size(), 3u);
  EXPECT_EQ(environment.features[0].kind, EnvironmentFeatureKind::rainfall);
  EXPECT_EQ(environment.features[0].phrase.text, "heavy rain");
  // "mist and fog" is one phrase although "and" also joins the list.
  EXPECT_EQ(environment.features[1].kind, EnvironmentFeatureKind::particulates);
  EXPECT_EQ(environment.features[1].phrase.text, "mist and fog");
  expect_spans(environment.features[1].location, text, "mist and fog");
  EXPECT_EQ(environment.features[2].kind, EnvironmentFeatureKind::wind);
  EXPECT_EQ(environment.features[2].phrase.text, "a moderate breeze");
  expect_spans(environment.location, text,
               "During the night, there is a dark, partly cloudy sky, with heavy rain, mist and "
               "fog and with a moderate breeze.");
}

TEST(WmgLevel1Parser, SkyWithoutCloudAndAQuotedCloudCondition) {
  Sentences sentences;
  sentences.environment = "During the day, there is a bright sky with light snow.\n";
  Level1File file = parse_ok(sentences.text());
  EXPECT_FALSE(file.environment.cloud.has_value());
  ASSERT_EQ(file.environment.features.size(), 1u);
  EXPECT_EQ(file.environment.features[0].kind, EnvironmentFeatureKind::snowfall);

  sentences.environment = "During the day, there is a light, 'mackerel' sky.\n";
  file = parse_ok(sentences.text());
  ASSERT_TRUE(file.environment.cloud.has_value());
  EXPECT_EQ(file.environment.cloud->text, "mackerel");
  EXPECT_TRUE(file.environment.cloud->is_string);
  EXPECT_TRUE(file.environment.features.empty());
}

TEST(WmgLevel1Parser, NoJunctionPresent) {
  EXPECT_TRUE(parse_ok(Sentences{}.text()).junctions.empty());
}

TEST(WmgLevel1Parser, JunctionWithConnections) {
  Sentences sentences;
  sentences.junctions =
      "There is a T-Junction, J1, which has connections with R1, R2 and R3.\n"
      "R1 to R3 is straight ahead.\nR2 to R1 is turning left.\n";
  sentences.roads = "R1, R2 and R3 are straight, minor roads.\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  ASSERT_EQ(file.junctions.size(), 1u);
  const JunctionSentence& junction = file.junctions[0];
  EXPECT_EQ(junction.type.text, "T-Junction");
  expect_spans(junction.type.location, text, "T-Junction");
  EXPECT_EQ(junction.id.name, "J1");
  ASSERT_EQ(junction.roads.size(), 3u);
  EXPECT_EQ(junction.roads[2].name, "R3");
  ASSERT_EQ(junction.connections.size(), 2u);
  EXPECT_EQ(junction.connections[0].from.name, "R1");
  EXPECT_EQ(junction.connections[0].to.name, "R3");
  EXPECT_EQ(junction.connections[0].connection.text, "straight ahead");
  EXPECT_EQ(junction.connections[1].connection.text, "turning left");
  expect_spans(junction.connections[1].location, text, "R2 to R1 is turning left.");
}

TEST(WmgLevel1Parser, SeveralJunctionsAndAQuotedType) {
  Sentences sentences;
  sentences.junctions =
      "There is a mini roundabout, J1, which has connections with R1 and R2.\n"
      "There is a 'five-way junction', J2, which has connections with R2.\n";
  sentences.roads = "R1 and R2 are curved, 'slip roads'.\n";
  Level1File file = parse_ok(sentences.text());
  ASSERT_EQ(file.junctions.size(), 2u);
  EXPECT_EQ(file.junctions[0].type.text, "mini roundabout");
  EXPECT_TRUE(file.junctions[1].type.is_string);
  EXPECT_EQ(file.junctions[1].type.text, "five-way junction");
  ASSERT_EQ(file.roads.size(), 1u);
  EXPECT_EQ(file.roads[0].road_type.text, "slip roads");
  EXPECT_TRUE(file.roads[0].road_type.is_string);
}

TEST(WmgLevel1Parser, RoadSentencesSingularPluralAndTraffic) {
  Sentences sentences;
  sentences.roads =
      "R1 is a curved, motorway with a lot of traffic.\nR2 and R3 are straight distributor "
      "roads with no traffic.\n";
  sentences.locations = "Ego is in R3.\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  ASSERT_EQ(file.roads.size(), 2u);
  EXPECT_EQ(file.roads[0].roads.at(0).name, "R1");
  EXPECT_EQ(file.roads[0].horizontal_geometry.text, "curved");
  EXPECT_EQ(file.roads[0].road_type.text, "motorway");
  ASSERT_TRUE(file.roads[0].traffic.has_value());
  EXPECT_EQ(file.roads[0].traffic->text, "a lot of");
  expect_spans(file.roads[0].traffic->location, text, "a lot of");
  ASSERT_EQ(file.roads[1].roads.size(), 2u);
  EXPECT_EQ(file.roads[1].road_type.text, "distributor roads");
  EXPECT_EQ(file.roads[1].traffic->text, "no");
}

TEST(WmgLevel1Parser, RoadFeatureSentences) {
  Sentences sentences;
  sentences.roads = "R1 and R2 are straight, minor roads.\n";
  sentences.features =
      "Also, R1 has street lights, trees and 'bus shelters'.\nAlso, R1 and R2 have traffic "
      "lights.\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  ASSERT_EQ(file.road_features.size(), 2u);
  ASSERT_EQ(file.road_features[0].features.size(), 3u);
  EXPECT_EQ(file.road_features[0].features[0].text, "street lights");
  EXPECT_EQ(file.road_features[0].features[1].text, "trees");
  EXPECT_TRUE(file.road_features[0].features[2].is_string);
  EXPECT_EQ(file.road_features[1].roads.size(), 2u);
  EXPECT_EQ(file.road_features[1].features.at(0).text, "traffic lights");
  expect_spans(file.road_features[1].features[0].location, text, "traffic lights");
}

TEST(WmgLevel1Parser, ActorsAndLocations) {
  Sentences sentences;
  sentences.junctions = "There is a crossroad, J1, which has connections with R1 and R2.\n";
  sentences.roads = "R1 and R2 are straight, minor roads.\n";
  sentences.actors =
      "There are 2 vehicles, Ego and Car1.\nThere is 1 pedestrian, Ped1.\n"
      "There are 3 cyclists, Bike1, Bike2 and Bike3.\n";
  sentences.locations =
      "Ego is in R1, Car1 is in J1, Ped1 is in R2, Bike1 is in R1, Bike2 is in R2 and Bike3 is "
      "in R2.\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  ASSERT_EQ(file.actors.size(), 3u);
  EXPECT_EQ(file.actors[0].count.value, 2);
  EXPECT_EQ(file.actors[0].type.value, ActorType::vehicle);
  EXPECT_EQ(file.actors[1].type.value, ActorType::pedestrian);
  EXPECT_EQ(file.actors[2].type.value, ActorType::cyclist);
  EXPECT_EQ(file.actors[2].names.at(2).name, "Bike3");
  expect_spans(file.actors[2].type.location, text, "cyclists");
  ASSERT_EQ(file.locations.size(), 6u);
  EXPECT_EQ(file.locations[1].actor.name, "Car1");
  EXPECT_EQ(file.locations[1].place.name, "J1");
  expect_spans(file.locations[1].location, text, "Car1 is in J1");
}

TEST(WmgLevel1Parser, ConditionsListAndTrafficLight) {
  Sentences sentences;
  sentences.junctions = "There is a crossroad, J1, which has connections with R1 and R2.\n";
  sentences.roads = "R1 and R2 are straight, minor roads.\n";
  sentences.actors = "There are 3 vehicles, Ego, Car1 and Car2.\n";
  sentences.locations = "Ego is in R1, Car1 is in R2 and Car2 is in R2.\n";
  sentences.ssms =
      "When Ego is driving towards J1, Car2 is stopped and the traffic light ahead of Ego is "
      "amber, Car1 cuts in.\nEgo operates autonomously.\n";
  std::string text = sentences.text();
  Level1File file = parse_ok(text);
  ASSERT_EQ(file.sequences.size(), 1u);
  const PhaseGroup& group = file.sequences[0].groups.at(0);
  ASSERT_EQ(group.conditions.size(), 3u);
  EXPECT_EQ(actor_clause(group.conditions[0]).actor.name, "Ego");
  const Level1Manoeuvre& towards = actor_clause(group.conditions[0]).manoeuvre;
  EXPECT_EQ(towards.action.text, "is driving");
  ASSERT_EQ(towards.places.size(), 1u);
  EXPECT_EQ(towards.places[0].relation->text, "towards");
  EXPECT_EQ(towards.places[0].target->name, "J1");
  EXPECT_EQ(actor_clause(group.conditions[1]).manoeuvre.action.text, "is stopped");
  const auto& light = std::get<TrafficLightClause>(group.conditions[2]);
  EXPECT_EQ(light.relation.text, "ahead of");
  EXPECT_EQ(light.reference.name, "Ego");
  EXPECT_EQ(light.colour.value, TrafficLightColour::amber);
  expect_spans(light.location, text, "the traffic light ahead of Ego is amber");
  ASSERT_EQ(group.phases.size(), 1u);
  EXPECT_EQ(group.phases[0].actor.name, "Car1");
  EXPECT_EQ(group.phases[0].manoeuvre.action.text, "cuts in");
  EXPECT_EQ(file.sequences[0].autonomous_actor.name, "Ego");
}

TEST(WmgLevel1Parser, ACommaAfterAConditionCanStartThePhases) {
  // ", Car1 cuts in" reads as another condition up to the full stop, where no "and CONDITION,"
  // has come: it is the first phase.
  Sentences sentences;
  sentences.actors = "There are 2 vehicles, Ego and Car1.\n";
  sentences.locations = "Ego is in R1 and Car1 is in R1.\n";
  sentences.ssms = "When Ego is driving, Car1 cuts in, then drives.\nEgo operates autonomously.\n";
  const PhaseGroup group = parse_ok(sentences.text()).sequences.at(0).groups.at(0);
  EXPECT_EQ(group.conditions.size(), 1u);
  ASSERT_EQ(group.phases.size(), 2u);
  EXPECT_EQ(group.phases[1].actor.name, "Car1");
  EXPECT_FALSE(group.phases[1].actor_written);
  EXPECT_EQ(group.phases[1].manoeuvre.action.text, "drives");
}

TEST(WmgLevel1Parser, EveryFormOfLaterPhase) {
  Sentences sentences;
  sentences.actors = "There are 3 vehicles, Ego, Car1 and Car2.\n";
  sentences.locations = "Ego is in R1, Car1 is in R1 and Car2 is in R1.\n";
  sentences.ssms =
      "When Ego is driving, Car1 cuts in, then drives, and Car2 stops and then reverses. And "
      "Car1 turns left. Car2 then collides with Car1.\nEgo operates autonomously.\n";
  const PhaseGroup group = parse_ok(sentences.text()).sequences.at(0).groups.at(0);
  std::vector<std::string> actors, actions;
  for (const PhaseClause& phase : group.phases) {
    actors.push_back(phase.actor.name);
    actions.push_back(phase.manoeuvre.action.text);
  }
  EXPECT_EQ(actors, (std::vector<std::string>{"Car1", "Car1", "Car2", "Car2", "Car1", "Car2"}));
  EXPECT_EQ(actions, (std::vector<std::string>{"cuts in", "drives", "stops", "reverses",
                                               "turns left", "collides"}));
  EXPECT_EQ(group.phases[5].manoeuvre.places.at(0).relation->text, "with");
  EXPECT_EQ(group.phases[5].manoeuvre.places.at(0).target->name, "Car1");
}

TEST(WmgLevel1Parser, ThenBeforeAManoeuvreStartingWithIsIsNotAnActor) {
  // "then is stopped" once read "is" as an actor, and "and then ..." after a condition once
  // read "then" as the actor of a third condition.
  Sentences sentences;
  sentences.actors = "There are 2 vehicles, Ego and Car1.\n";
  sentences.locations = "Ego is in R1 and Car1 is in R1.\n";
  sentences.ssms =
      "When the traffic light ahead of Ego is red, Car1 stops near Ego and then is stopped, "
      "then is cutting out.\nEgo operates autonomously.\n";
  const PhaseGroup group = parse_ok(sentences.text()).sequences.at(0).groups.at(0);
  EXPECT_EQ(group.conditions.size(), 1u);
  std::vector<std::string> actions;
  for (const PhaseClause& phase : group.phases) {
    EXPECT_EQ(phase.actor.name, "Car1");
    actions.push_back(phase.manoeuvre.action.text);
  }
  EXPECT_EQ(actions, (std::vector<std::string>{"stops", "is stopped", "is cutting out"}));
}

TEST(WmgLevel1Parser, ManoeuvreWithSpeedChangePlacesAndPosition) {
  Sentences sentences;
  sentences.roads = "R1 and R2 are straight, minor roads.\n";
  sentences.actors = "There are 2 vehicles, Ego and Car1.\n";
  sentences.locations = "Ego is in R1 and Car1 is in R1.\n";
  sentences.ssms =
      "When Ego is driving, Car1 turns left, slowing down, onto R2 and in front of Ego at its "
      "front right.\nEgo operates autonomously.\n";
  std::string text = sentences.text();
  const Level1Manoeuvre manoeuvre =
      parse_ok(text).sequences.at(0).groups.at(0).phases.at(0).manoeuvre;
  EXPECT_EQ(manoeuvre.action.text, "turns left");
  ASSERT_TRUE(manoeuvre.speed_change.has_value());
  EXPECT_EQ(manoeuvre.speed_change->text, "slowing down");
  ASSERT_EQ(manoeuvre.places.size(), 2u);
  EXPECT_FALSE(manoeuvre.places[0].relation.has_value());
  EXPECT_EQ(manoeuvre.places[0].preposition->text, "onto");
  EXPECT_EQ(manoeuvre.places[0].target->name, "R2");
  EXPECT_EQ(manoeuvre.places[1].relation->text, "in front of");
  EXPECT_EQ(manoeuvre.places[1].target->name, "Ego");
  ASSERT_TRUE(manoeuvre.position.has_value());
  EXPECT_EQ(manoeuvre.position->text, "front right");
  expect_spans(manoeuvre.location, text,
               "turns left, slowing down, onto R2 and in front of Ego at its front right");
}

TEST(WmgLevel1Parser, TriggersWithAndWithoutConditionsAndSeveralSsms) {
  Sentences sentences;
  sentences.actors = "There are 2 vehicles, Ego and Car1.\n";
  sentences.locations = "Ego is in R1 and Car1 is in R1.\n";
  sentences.ssms =
      "When Ego is driving, Car1 drives away. Also, when Car1 is driving, Car1 stops. Next, "
      "Car1 is stopped. Next, as Ego is stopped, Car1 drives.\nEgo operates autonomously.\n"
      "When Car1 is driving, Car1 stops.\nEgo operates autonomously.\n";
  Level1File file = parse_ok(sentences.text());
  ASSERT_EQ(file.sequences.size(), 2u);
  const std::vector<PhaseGroup>& groups = file.sequences[0].groups;
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_FALSE(groups[0].trigger.has_value());
  EXPECT_EQ(groups[1].trigger->text, "Also");
  EXPECT_EQ(groups[1].trigger_word->text, "when");
  EXPECT_EQ(groups[1].conditions.size(), 1u);
  EXPECT_EQ(groups[2].trigger->text, "Next");
  EXPECT_FALSE(groups[2].trigger_word.has_value());
  EXPECT_TRUE(groups[2].conditions.empty());
  EXPECT_EQ(groups[3].trigger_word->text, "as");
  EXPECT_EQ(groups[0].phases.at(0).manoeuvre.places.at(0).relation->text, "away");
  EXPECT_FALSE(groups[0].phases.at(0).manoeuvre.places.at(0).target.has_value());
}

TEST(WmgLevel1Parser, CommentsAndLineBreaksInsideSentencesAreIgnored) {
  Sentences sentences;
  sentences.environment = "# the weather\nDuring the\nday, there is a\n  light sky. # done\n";
  EXPECT_EQ(parse_ok(sentences.text()).environment.light.text, "light");
}

// ---- conversion: the qualitative words -------------------------------------------------------

TEST(WmgLevel1Conversion, HeavyRainAndTheWeather) {
  Sentences sentences;
  sentences.environment =
      "During the day, there is a bright, overcast sky, with heavy rain, a heavy breeze and "
      "volcanic ash.\n";
  const Level2File file = convert_ok(sentences.text());
  const Environment& environment = file.environment;
  EXPECT_EQ(environment.rainfall.type.text, "Heavy Rain");
  expect_range(environment.rainfall.intensity, 7.6, 50);
  ASSERT_TRUE(environment.wind.has_value());
  expect_range(*environment.wind, 39, 49);
  expect_range(environment.cloudiness, 8, 8);
  ASSERT_TRUE(environment.particulates.has_value());
  EXPECT_EQ(environment.particulates->text, "Volcanic Ash");
  EXPECT_FALSE(environment.snowfall.has_value());
  EXPECT_EQ(file.scenery.roads.at(0).surface_condition->text, "Wet");
}

TEST(WmgLevel1Conversion, DayAndBrightLight) {
  const Level2File file = convert_ok([] {
    Sentences sentences;
    sentences.environment = "During the day, there is a bright, clear sky.\n";
    return sentences.text();
  }());
  const Environment& environment = file.environment;
  ASSERT_TRUE(environment.time_of_day.has_value());
  expect_range(*environment.time_of_day, 9 * 3600, 15 * 3600);
  EXPECT_EQ(environment.illumination.text, "Day");
  EXPECT_EQ(environment.light_source.text, "Sun");
  ASSERT_TRUE(environment.light_source_position.has_value());
  expect_range(environment.light_source_position->elevation, 30, 60);
  expect_range(environment.cloudiness, 0, 1);
  EXPECT_EQ(environment.rainfall.type.text, "Light Rain");
  expect_range(environment.rainfall.intensity, 0, 0);
  EXPECT_EQ(file.scenery.roads.at(0).surface_condition->text, "Dry");
}

TEST(WmgLevel1Conversion, NightDarkAndLight) {
  Sentences sentences;
  sentences.environment = "During the night, there is a dark sky, with moderate snow.\n";
  Level2File file = convert_ok(sentences.text());
  expect_range(*file.environment.time_of_day, 0, 5 * 3600);
  EXPECT_EQ(file.environment.illumination.text, "Night Dark");
  EXPECT_EQ(file.environment.light_source.text, "Headlamp");
  EXPECT_FALSE(file.environment.light_source_position.has_value());
  expect_range(file.environment.cloudiness, 0, 8);  // not said: any sky
  ASSERT_TRUE(file.environment.snowfall.has_value());
  EXPECT_EQ(file.environment.snowfall->type.text, "Moderate Snow");
  expect_range(file.environment.snowfall->visibility, 400, 1000);
  EXPECT_EQ(file.scenery.roads.at(0).surface_condition->text, "Snow");

  sentences.environment = "During the night, there is a light sky.\n";
  file = convert_ok(sentences.text());
  EXPECT_EQ(file.environment.illumination.text, "Night Lit");
  EXPECT_EQ(file.environment.light_source.text, "Street Lighting");
}

TEST(WmgLevel1Conversion, CurvedMotorwayWithALotOfTraffic) {
  Sentences sentences;
  sentences.roads = "R1 is a curved, motorway with a lot of traffic.\n";
  const Level2File file = convert_ok(sentences.text());
  ASSERT_EQ(file.scenery.roads.size(), 1u);
  const Road& road = file.scenery.roads[0];
  EXPECT_EQ(road.road_type.text, "Motorway");
  ASSERT_TRUE(road.speed_limit.has_value());
  expect_range(*road.speed_limit, 112, 112);
  EXPECT_EQ(road.lane_count.value, 3);
  ASSERT_EQ(road.lanes.size(), 3u);
  EXPECT_EQ(road.lanes[2].lane.name, "L3");
  EXPECT_EQ(road.environment.text, "Rural");
  expect_range(*road.lane_width.whole_road, 3.5, 3.75);
  expect_range(road.length, 800, 1500);
  EXPECT_EQ(road.horizontal_geometry.whole_road->text, "Curved");
  ASSERT_TRUE(road.curvature_radius.has_value());
  expect_range(road.curvature_radius->segments.at(0).range.value(), 1000, 4000);
  EXPECT_EQ(road.transverse_geometry.at(0).text, "Divided");
  ASSERT_TRUE(file.traffic.has_value());
  ASSERT_EQ(file.traffic->flows.size(), 1u);
  expect_range(file.traffic->flows[0].first, 1500, 2000);
  expect_range(file.traffic->flows[0].second, 11, 56);  // 0.1 to 0.5 of 112 km/h, rounded
  EXPECT_EQ(file.traffic->centroids.size(), 2u);
  EXPECT_EQ(file.traffic->centroids[0].reference.name, "Ego");
}

TEST(WmgLevel1Conversion, StraightMinorRoadWithoutTraffic) {
  Sentences sentences;
  sentences.roads = "R1 is a straight, minor road with no traffic.\n";
  const Level2File file = convert_ok(sentences.text());
  const Road& road = file.scenery.roads.at(0);
  EXPECT_EQ(road.road_type.text, "Minor road");
  expect_range(*road.speed_limit, 48, 48);
  EXPECT_EQ(road.lane_count.value, 2);
  expect_range(*road.lane_width.whole_road, 2.75, 3.25);
  EXPECT_FALSE(road.curvature_radius.has_value());
  EXPECT_EQ(road.environment.text, "Urban");
  EXPECT_FALSE(file.traffic.has_value());
}

TEST(WmgLevel1Conversion, QuotedRoadTypeKeepsItsNameAndGetsMinorRoadNumbers) {
  Sentences sentences;
  sentences.roads = "R1 is a 'winding', 'slip road'.\n";
  const Road road = convert_ok(sentences.text()).scenery.roads.at(0);
  EXPECT_EQ(road.road_type.text, "slip road");
  EXPECT_TRUE(road.road_type.is_string);
  EXPECT_EQ(road.horizontal_geometry.whole_road->text, "winding");
  EXPECT_TRUE(road.horizontal_geometry.whole_road->is_string);
  expect_range(road.length, 80, 200);
}

TEST(WmgLevel1Conversion, RoadFeatures) {
  Sentences sentences;
  sentences.roads = "R1 is a straight, distributor road.\n";
  sentences.features =
      "Also, R1 has solid lane markings, solid barriers, street lights, trees, pedestrian "
      "crossing and 'bus stop'.\n";
  const Road road = convert_ok(sentences.text()).scenery.roads.at(0);
  EXPECT_EQ(road.lane_markings.text, "Solid line");
  ASSERT_TRUE(road.edge_feature.has_value());
  EXPECT_EQ(road.edge_feature->text, "Solid barriers");
  ASSERT_EQ(road.fixed_structures.size(), 3u);
  ASSERT_TRUE(road.fixed_structures[0].street_lights.has_value());
  expect_range(road.fixed_structures[0].street_lights->spacing, 25, 40);
  expect_range(road.fixed_structures[0].street_lights->height, 8, 12);
  EXPECT_EQ(road.fixed_structures[1].type.text, "Vegetation");
  EXPECT_EQ(road.fixed_structures[2].type.text, "bus stop");
  EXPECT_TRUE(road.fixed_structures[2].type.is_string);
  ASSERT_EQ(road.special_structures.size(), 1u);
  EXPECT_EQ(road.special_structures[0].type.text, "Pedestrian crossing");
  expect_range(road.special_structures[0].distance_from_start, 50, 50);  // half of 100 m
}

TEST(WmgLevel1Conversion, CrossroadWithTrafficLights) {
  Sentences sentences;
  sentences.junctions =
      "There is a crossroad, J1, which has connections with R1, R2, R3 and R4.\n"
      "R1 to R3 is straight ahead.\nR1 to R2 is turning left.\n";
  sentences.roads = "R1, R2, R3 and R4 are straight, minor roads.\n";
  sentences.features = "Also, R1 has traffic lights and pedestrian crossing.\n";
  const Level2File file = convert_ok(sentences.text());
  ASSERT_EQ(file.scenery.junctions.size(), 1u);
  const Junction& junction = file.scenery.junctions[0];
  EXPECT_EQ(junction.type.text, "Crossroads");
  EXPECT_EQ(junction.connection_control.text, "Traffic light");
  EXPECT_EQ(junction.connection_count.value, 4);
  ASSERT_EQ(junction.angle_pairs.size(), 4u);
  EXPECT_EQ(junction.angle_pairs[3].from.name, "R4");
  EXPECT_EQ(junction.angle_pairs[3].to.name, "R1");
  expect_range(junction.angles.at(0), 80, 100);
  ASSERT_EQ(junction.lane_connections.size(), 1u);
  EXPECT_EQ(junction.lane_connections[0].from.road.name, "R1");
  ASSERT_EQ(junction.lane_connections[0].to.size(), 2u);
  EXPECT_EQ(junction.lane_connections[0].to[1].road.name, "R2");
  // Into the junction by L1, out of it by L2 (a minor road is one lane each way).
  EXPECT_EQ(junction.lane_connections[0].from.lane.name, "L1");
  EXPECT_EQ(junction.lane_connections[0].to[0].lane.name, "L2");
  EXPECT_EQ(junction.lane_connections[0].to[1].lane.name, "L2");
  expect_range(*junction.dimensions.width, 15, 25);
  expect_range(*junction.dimensions.depth, 15, 25);
  EXPECT_FALSE(junction.dimensions.diameter.has_value());
  ASSERT_TRUE(junction.traffic_lights.has_value());
  EXPECT_EQ(junction.traffic_lights->type.text, "With pedestrian crossing");
  ASSERT_EQ(junction.traffic_lights->lights.size(), 4u);
  EXPECT_EQ(junction.traffic_lights->lights[1].light.name, "TL2");
  EXPECT_EQ(junction.traffic_lights->lights[1].road.name, "R2");
  EXPECT_EQ(file.scenery.roads.at(0).end_junction->name, "J1");
}

TEST(WmgLevel1Conversion, RoundaboutWithoutLightsGivesWay) {
  Sentences sentences;
  sentences.junctions =
      "There is a compact roundabout, J1, which has connections with R1 and R2.\n";
  sentences.roads = "R1 and R2 are curved, minor roads.\n";
  const Junction junction = convert_ok(sentences.text()).scenery.junctions.at(0);
  EXPECT_EQ(junction.type.text, "Compact roundabout");
  EXPECT_EQ(junction.connection_control.text, "Give way");
  ASSERT_TRUE(junction.dimensions.diameter.has_value());
  expect_range(*junction.dimensions.diameter, 28, 36);
  EXPECT_FALSE(junction.traffic_lights.has_value());
  // Nothing said about the connections: every road leads to every other.
  ASSERT_EQ(junction.lane_connections.size(), 2u);
  EXPECT_EQ(junction.lane_connections[1].from.road.name, "R2");
  EXPECT_EQ(junction.lane_connections[1].to.at(0).road.name, "R1");
  ASSERT_EQ(junction.angle_pairs.size(), 1u);
  expect_range(junction.angles.at(0), 60, 120);
}

TEST(WmgLevel1Conversion, CutInBecomesALaneChangeFromTheNextLane) {
  Sentences sentences;
  sentences.actors = "There are 2 vehicles, Ego and Cutter.\n";
  sentences.locations = "Cutter is in R1 and Ego is in R1.\n";
  sentences.ssms =
      "When Ego is driving, Cutter cuts in, decelerating, in front of Ego.\n"
      "Ego operates autonomously.\n";
  const Level2File file = convert_ok(sentences.text());
  const Initialisation& init = file.dynamics.initialisation;
  EXPECT_EQ(init.first.actor.name, "Ego");  // the actor under test comes first
  EXPECT_EQ(init.first.lane.lane.name, "L1");
  ASSERT_EQ(init.relative.size(), 1u);
  EXPECT_EQ(init.relative[0].actor.name, "Cutter");
  EXPECT_EQ(init.relative[0].lane.lane.name, "L2");
  EXPECT_EQ(init.relative[0].relative_position.value, RelativeLocation::front_side_left);
  expect_range(init.relative[0].offsets.at(0).offset, 10, 40);
  ASSERT_EQ(file.dynamics.sequences.size(), 1u);
  const Ssms& ssms = file.dynamics.sequences[0];
  const auto& condition = std::get<ActorCondition>(ssms.conditions.at(0));
  EXPECT_EQ(condition.observed.text, "Going Ahead");
  EXPECT_EQ(condition.in_lane->lane.name, "L1");
  expect_range(*condition.speed, 56, 112);  // half the limit to the limit
  const ManoeuvrePhase& phase = ssms.sequences.at(0).phases.at(0);
  EXPECT_EQ(phase.type.text, "LaneChangeRight_CutIn");
  expect_range(phase.agent.first, 22, 67);  // decelerating: 0.2 to 0.6 of 112 km/h
  expect_range(phase.agent.second, 1.5, 4);
  EXPECT_EQ(phase.relative.reference.name, "Ego");
  expect_range(phase.relative.distance, 5, 30);
  EXPECT_EQ(phase.relative.relative_location.value, RelativeLocation::front);
  ASSERT_EQ(file.dynamics.end_conditions.size(), 2u);
  expect_range(std::get<TimerConstraint>(file.dynamics.end_conditions[0]).value, 30, 30);
}

TEST(WmgLevel1Conversion, PedestrianWalksAcross) {
  Sentences sentences;
  sentences.actors = "There is 1 vehicle, Ego.\nThere is 1 pedestrian, Walker.\n";
  sentences.locations = "Ego is in R1 and Walker is in R1.\n";
  sentences.ssms =
      "When Ego is driving, Walker walks across R1 at its rear left, then runs away.\n"
      "Ego operates autonomously.\n";
  const Level2File file = convert_ok(sentences.text());
  const RelativeActorInit& walker = file.dynamics.initialisation.relative.at(0);
  EXPECT_EQ(walker.type.value, ActorType::pedestrian);
  EXPECT_EQ(walker.lane.lane.name, "P1");
  ASSERT_EQ(walker.offsets.size(), 2u);
  EXPECT_EQ(walker.offsets[1].relation.value, PositionRelation::lateral);
  // At the ego's left, facing across the road: to the ego's right.
  expect_range(walker.relative_heading, -100, -80);
  const std::vector<ManoeuvrePhase>& phases = file.dynamics.sequences.at(0).sequences.at(0).phases;
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_EQ(phases[0].type.text, "Walk_Cross");
  expect_range(phases[0].agent.first, 3, 6);
  EXPECT_EQ(phases[0].relative.relative_location.value, RelativeLocation::rear_side_left);
  EXPECT_EQ(phases[1].type.text, "Run_Away");
  expect_range(phases[1].agent.first, 8, 15);
  EXPECT_EQ(phases[1].number.value, 2);
}

TEST(WmgLevel1Conversion, StopsTrafficLightConditionsAndGroupsWithoutConditions) {
  Sentences sentences;
  sentences.junctions = "There is a T-Junction, J1, which has connections with R1, R2 and R3.\n";
  sentences.roads = "R1, R2 and R3 are straight, minor roads.\n";
  sentences.actors = "There are 2 vehicles, Ego and Lead.\n";
  sentences.locations = "Ego is in R1 and Lead is in R1.\n";
  sentences.ssms =
      "When the traffic light ahead of Lead is red, Lead stops. Next, Lead is stopped. Also, "
      "when the traffic light ahead of J1 is green, Lead drives.\nEgo operates autonomously.\n";
  const Level2File file = convert_ok(sentences.text());
  // A condition on a light makes the junction signalised.
  EXPECT_EQ(file.scenery.junctions.at(0).connection_control.text, "Traffic light");
  ASSERT_EQ(file.dynamics.sequences.size(), 3u);
  const auto& red = std::get<TrafficLightCondition>(file.dynamics.sequences[0].conditions.at(0));
  EXPECT_EQ(red.colour.value, TrafficLightColour::red);
  ASSERT_EQ(red.lights.size(), 1u);
  EXPECT_EQ(red.lights[0].name, "TL1");
  EXPECT_EQ(file.dynamics.sequences[0].sequences.at(0).phases.at(0).type.text, "Stop");
  expect_range(file.dynamics.sequences[0].sequences.at(0).phases.at(0).agent.first, 0, 0);
  // "Next," without conditions starts when the previous phase is observed.
  const auto& after = std::get<ActorCondition>(file.dynamics.sequences[1].conditions.at(0));
  EXPECT_EQ(after.actor.name, "Lead");
  EXPECT_EQ(after.observed.text, "Stopped");
  EXPECT_FALSE(after.speed.has_value());
  EXPECT_EQ(file.dynamics.sequences[1].sequences.at(0).phases.at(0).type.text, "Stopped");
  // A light "ahead of" a junction: every light of the junction.
  const auto& green = std::get<TrafficLightCondition>(file.dynamics.sequences[2].conditions.at(0));
  EXPECT_EQ(green.lights.size(), 3u);
}

TEST(WmgLevel1Conversion, ConditionInAJunctionAndPositionsOnAnotherRoad) {
  Sentences sentences;
  sentences.junctions = "There is a Y-Junction, J1, which has connections with R1 and R2.\n";
  sentences.roads = "R1 and R2 are straight, radial roads.\n";
  sentences.actors = "There are 2 vehicles, Ego and Other.\n";
  sentences.locations = "Ego is in R1 and Other is in R2.\n";
  sentences.ssms =
      "When Ego is driving towards J1, Other turns right, accelerating, towards Ego.\n"
      "Ego operates autonomously.\n";
  const Level2File file = convert_ok(sentences.text());
  const auto& condition = std::get<ActorCondition>(file.dynamics.sequences.at(0).conditions.at(0));
  ASSERT_TRUE(condition.in_element.has_value());
  EXPECT_EQ(condition.in_element->name, "J1");
  EXPECT_FALSE(condition.in_lane.has_value());
  const RelativeActorInit& other = file.dynamics.initialisation.relative.at(0);
  EXPECT_EQ(other.lane.road.name, "R2");
  EXPECT_EQ(other.relative_position.value, RelativeLocation::front_side_right);
  expect_range(other.relative_heading, -180, 180);
  const ManoeuvrePhase& phase = file.dynamics.sequences.at(0).sequences.at(0).phases.at(0);
  EXPECT_EQ(phase.type.text, "TurnRight_Towards");
  expect_range(phase.agent.first, 45, 64);  // accelerating: 0.7 to 1.0 of 64 km/h
  EXPECT_EQ(phase.relative.relative_location.value, RelativeLocation::front_side_right);
  const Junction& junction = file.scenery.junctions.at(0);
  expect_range(junction.angles.at(0), 30, 60);
}

TEST(WmgLevel1Conversion, CutOutAndHeaderDefaults) {
  Sentences sentences;
  sentences.header = "VERSION: 1.2\n";
  sentences.actors = "There are 2 vehicles, Ego and Lead.\n";
  sentences.locations = "Ego is in R1 and Lead is in R1.\n";
  sentences.ssms = "When Ego is driving, Lead cuts out.\nEgo operates autonomously.\n";
  const Level2File file = convert_ok(sentences.text());
  EXPECT_EQ(file.header.version.minor_part.value, 2);
  ASSERT_EQ(file.header.authors.size(), 1u);
  EXPECT_EQ(file.header.authors[0].text, "level 1");
  EXPECT_EQ(file.dynamics.initialisation.relative.at(0).lane.lane.name, "L1");
  EXPECT_EQ(file.dynamics.sequences.at(0).sequences.at(0).phases.at(0).type.text,
            "LaneChangeLeft_CutOut");
}

// ---- generated stories -----------------------------------------------------------------------

// Writes random valid level-1 files from the word lists: every sentence form, every word, random
// names, lists and joiners. Each must parse cleanly and convert to level 2 that round-trips.
class StoryWriter {
 public:
  explicit StoryWriter(unsigned seed) : random_(seed) {}

  std::string write() {
    roads_.clear();
    junctions_.clear();
    actors_.clear();
    std::string text = "VERSION: 1." + std::to_string(below(10)) + "\n";
    if (chance()) text += "AUTHOR: 'writer " + std::to_string(below(100)) + "'\n";
    text += environment();
    std::size_t road_count = 1 + below(4);
    for (std::size_t i = 1; i <= road_count; ++i) roads_.push_back("R" + std::to_string(i));
    text += junctions();
    text += road_sentences();
    if (chance())
      text += "Also, " + list(some(roads_)) + " " + pick({"has", "have"}) + " " + list(features()) +
              ".\n";
    text += actor_sentences();
    text += locations();
    for (std::size_t i = 0, n = 1 + below(2); i < n; ++i) text += ssms();
    return text;
  }

 private:
  std::size_t below(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }
  bool chance() { return below(2) == 0; }
  std::string pick(const std::vector<std::string>& options) {
    return options[below(options.size())];
  }
  std::string word(const Vocabulary& vocabulary) { return pick(vocabulary.phrases); }

  // A non-empty random selection, in order.
  std::vector<std::string> some(const std::vector<std::string>& all) {
    std::vector<std::string> chosen;
    for (const std::string& item : all)
      if (chance()) chosen.push_back(item);
    if (chosen.empty()) chosen.push_back(pick(all));
    return chosen;
  }

  // "A", "A and B", "A, B and C".
  static std::string list(const std::vector<std::string>& items) {
    std::string text;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i > 0) text += i + 1 == items.size() ? " and " : ", ";
      text += items[i];
    }
    return text;
  }

  std::string environment() {
    namespace phrases = level1_phrases;
    std::string text = "During the " + word(phrases::time_of_day()) + ", there is a " +
                       word(phrases::light_condition());
    if (chance())
      text += (chance() ? ", " : " ") + (chance() ? word(phrases::cloud_condition()) : "'odd'");
    text += " sky";
    std::size_t features = below(4);
    for (std::size_t i = 0; i < features; ++i) {
      const Vocabulary& kind =
          *std::vector<const Vocabulary*>{&phrases::particulates(), &phrases::snowfall(),
                                          &phrases::wind(), &phrases::rainfall()}[below(4)];
      text += (i + 1 == features && i > 0 ? " and " : ", ") + std::string(chance() ? "with " : "") +
              word(kind);
    }
    return text + ".\n";
  }

  std::string junctions() {
    std::size_t count = below(3);
    if (count == 0) return "There is no junction present.\n";
    std::string text;
    for (std::size_t i = 1; i <= count; ++i) {
      std::string name = "J" + std::to_string(i);
      junctions_.push_back(name);
      std::vector<std::string> connected = some(roads_);
      text += "There is a " +
              (chance() ? word(level1_phrases::junction_type()) : std::string("'odd junction'")) +
              ", " + name + ", which has connections with " + list(connected) + ".\n";
      for (std::size_t c = below(3); c > 0; --c)
        text += pick(connected) + " to " + pick(connected) + " is " +
                word(level1_phrases::connection_type()) + ".\n";
    }
    return text;
  }

  std::string road_sentences() {
    std::string text;
    std::size_t i = 0;
    while (i < roads_.size()) {
      std::size_t group = 1 + below(roads_.size() - i);
      std::vector<std::string> roads(roads_.begin() + static_cast<std::ptrdiff_t>(i),
                                     roads_.begin() + static_cast<std::ptrdiff_t>(i + group));
      i += group;
      text += list(roads) + (roads.size() == 1 ? " is a " : " are ") +
              (chance() ? word(level1_phrases::horizontal_geometry()) : std::string("'odd'")) +
              (chance() ? ", " : " ") +
              (below(5) > 0 ? word(level1_phrases::road_type()) : std::string("'lane'"));
      if (chance()) text += " with " + word(level1_phrases::traffic_amount()) + " traffic";
      text += ".\n";
    }
    return text;
  }

  std::vector<std::string> features() {
    std::vector<std::string> chosen;
    for (std::size_t n = 1 + below(3); n > 0; --n)
      chosen.push_back(below(6) > 0 ? word(level1_phrases::road_feature()) : "'kerbs'");
    return chosen;
  }

  std::string actor_sentences() {
    std::string text;
    const std::vector<std::string> singular = {"vehicle", "pedestrian", "cyclist"};
    const std::vector<std::string> plural = {"vehicles", "pedestrians", "cyclists"};
    std::size_t sentences = 1 + below(3);
    for (std::size_t s = 0; s < sentences; ++s) {
      std::size_t count = 1 + below(3);
      std::vector<std::string> names;
      for (std::size_t n = 0; n < count; ++n) {
        names.push_back("Actor" + std::to_string(actors_.size()));
        actors_.push_back(names.back());
      }
      std::size_t type = below(3);
      text += std::string(count == 1 ? "There is 1 " : "There are " + std::to_string(count) + " ") +
              (count == 1 ? singular[type] : plural[type]) + ", " + list(names) + ".\n";
    }
    return text;
  }

  std::string locations() {
    std::vector<std::string> places = roads_;
    places.insert(places.end(), junctions_.begin(), junctions_.end());
    std::vector<std::string> located;
    for (const std::string& actor : actors_) located.push_back(actor + " is in " + pick(places));
    return list(located) + ".\n";
  }

  std::string name() {
    std::vector<std::string> names = actors_;
    names.insert(names.end(), roads_.begin(), roads_.end());
    names.insert(names.end(), junctions_.begin(), junctions_.end());
    return pick(names);
  }

  std::string manoeuvre() {
    namespace phrases = level1_phrases;
    std::string text = word(phrases::action());
    if (below(3) == 0) text += (chance() ? ", " : " ") + word(phrases::speed_change());
    for (std::size_t places = below(3), i = 0; i < places; ++i) {
      text += i > 0 ? pick({" ", ", ", " and "}) : (text.back() == ',' ? "" : " ");
      if (chance()) {
        text += word(phrases::relation());
        if (chance()) text += " " + name();
      } else {
        text += word(phrases::preposition()) + " " + name();
      }
    }
    if (below(3) == 0) text += " at its " + word(phrases::relative_position());
    return text;
  }

  std::string condition() {
    if (below(4) == 0)
      return "the traffic light " + word(level1_phrases::relation()) + " " + name() + " is " +
             word(level1_phrases::traffic_light_colour());
    return pick(actors_) + " " + manoeuvre();
  }

  std::string phases() {
    std::string text = pick(actors_) + " " + manoeuvre();
    for (std::size_t n = below(4); n > 0; --n) {
      switch (below(5)) {
        case 0: text += ", then " + manoeuvre(); break;
        case 1: text += ", and " + pick(actors_) + " " + manoeuvre(); break;
        case 2: text += " and then " + manoeuvre(); break;
        case 3: text += ". And " + pick(actors_) + " " + manoeuvre(); break;
        default: text += ". " + pick(actors_) + " then " + manoeuvre(); break;
      }
    }
    return text + ".\n";
  }

  std::string ssms() {
    std::string text = "When ";
    std::vector<std::string> conditions;
    for (std::size_t n = 1 + below(3); n > 0; --n) conditions.push_back(condition());
    text += list(conditions) + ", " + phases();
    for (std::size_t groups = below(3); groups > 0; --groups) {
      text += pick({"Also", "Next"}) + ", ";
      if (chance()) {
        text += phases();
      } else {
        std::vector<std::string> more;
        for (std::size_t n = 1 + below(2); n > 0; --n) more.push_back(condition());
        text += pick({"when ", "as "}) + list(more) + ", " + phases();
      }
    }
    return text + pick(actors_) + " operates autonomously.\n";
  }

  std::mt19937 random_;
  std::vector<std::string> roads_;
  std::vector<std::string> junctions_;
  std::vector<std::string> actors_;
};

TEST(WmgLevel1Generated, RandomStoriesParseConvertAndRoundTrip) {
  StoryWriter writer(20261121);
  for (int i = 0; i < 400; ++i) {
    std::string text = writer.write();
    SCOPED_TRACE(text);
    SourceFile file("story.sdl", text);
    Level1ParseResult parsed = parse_level1(file);
    ASSERT_TRUE(parsed.file.has_value()) << format_diagnostics(file, parsed.diagnostics);
    Diagnostics diagnostics;
    Level2File converted = level1_to_level2(*parsed.file, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors());
    std::string printed = print_level2(converted);
    SourceFile printed_file("printed.sdl", printed);
    Level2ParseResult again = parse_level2(printed_file);
    ASSERT_TRUE(again.file.has_value())
        << format_diagnostics(printed_file, again.diagnostics) << printed;
    ASSERT_TRUE(again.diagnostics.all().empty());
    ASSERT_TRUE(*again.file == converted) << printed;
  }
}

// ---- the defaults table ----------------------------------------------------------------------

// Every word of every level-1 list that the conversion looks up has its row.
TEST(WmgLevel1Defaults, EveryLevel1WordHasItsRows) {
  namespace phrases = level1_phrases;
  auto expect_rows = [](const Vocabulary& vocabulary, std::initializer_list<Quality> qualities) {
    for (const std::string& phrase : vocabulary.phrases)
      for (Quality quality : qualities)
        EXPECT_NE(find_default(quality, phrase), nullptr)
            << "no row of quality " << static_cast<int>(quality) << " for '" << phrase << "'";
  };
  expect_rows(phrases::time_of_day(), {Quality::time_of_day});
  expect_rows(phrases::light_condition(), {Quality::daylight, Quality::night_light});
  expect_rows(phrases::cloud_condition(), {Quality::cloudiness});
  expect_rows(phrases::particulates(), {Quality::particulates});
  expect_rows(phrases::snowfall(), {Quality::snowfall});
  expect_rows(phrases::wind(), {Quality::wind});
  expect_rows(phrases::rainfall(), {Quality::rainfall});
  expect_rows(phrases::junction_type(),
              {Quality::junction_type, Quality::junction_size, Quality::junction_angle});
  expect_rows(phrases::horizontal_geometry(), {Quality::horizontal_geometry});
  expect_rows(phrases::action(), {Quality::manoeuvre_kind});
  expect_rows(phrases::relation(), {Quality::place_direction});
  expect_rows(phrases::relative_position(), {Quality::relative_position});
  expect_rows(phrases::speed_change(), {Quality::speed_change});
  for (const std::string& amount : phrases::traffic_amount().phrases) {
    if (amount == "no") continue;  // no flow at all
    EXPECT_NE(find_default(Quality::traffic_flow, amount), nullptr) << amount;
    EXPECT_NE(find_default(Quality::traffic_speed, amount), nullptr) << amount;
  }
  // The road types: the five singulars (the plurals share them).
  for (std::size_t i = 0; i < 5; ++i)
    for (Quality quality : {Quality::road_type, Quality::road_environment, Quality::road_division,
                            Quality::speed_limit, Quality::lane_count, Quality::lane_width,
                            Quality::road_length, Quality::curvature_radius})
      EXPECT_NE(find_default(quality, phrases::road_type().phrases[i]), nullptr)
          << phrases::road_type().phrases[i];
  // Every road feature but traffic lights (the junction's control) sets some part of a road.
  for (const std::string& feature : phrases::road_feature().phrases) {
    if (feature == "traffic lights") continue;
    bool found = false;
    for (Quality quality : {Quality::lane_marking_feature, Quality::edge_feature,
                            Quality::fixed_feature, Quality::special_feature})
      found = found || find_default(quality, feature) != nullptr;
    EXPECT_TRUE(found) << feature;
  }
  // Every kind of manoeuvre has its duration and gap; every kind a level-2 type starts with has
  // its observation (cut-ins and cut-outs become LaneChange... or Drive_ types).
  for (const QualitativeDefault& row : qualitative_defaults()) {
    if (row.quality != Quality::manoeuvre_kind) continue;
    EXPECT_NE(find_default(Quality::phase_duration, row.label), nullptr) << row.label;
    EXPECT_NE(find_default(Quality::phase_gap, row.label), nullptr) << row.label;
    if (row.label != "CutIn" && row.label != "CutOut") {
      EXPECT_NE(find_default(Quality::observed_manoeuvre, row.label), nullptr) << row.label;
    }
  }
}

TEST(WmgLevel1Defaults, RangesAreOrderedAndRowsAreUnique) {
  std::span<const QualitativeDefault> table = qualitative_defaults();
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_LE(table[i].low, table[i].high) << table[i].words;
    EXPECT_TRUE(!table[i].label.empty() || table[i].has_range) << table[i].words;
    for (std::size_t j = i + 1; j < table.size(); ++j)
      EXPECT_FALSE(table[i].quality == table[j].quality && table[i].words == table[j].words)
          << "two rows for '" << table[i].words << "'";
  }
}

TEST(WmgLevel1Defaults, AFallbackIsUsedForWordsTheTableDoesNotKnow) {
  const QualitativeDefault& row = default_for(Quality::road_length, "bridleway", "minor road");
  EXPECT_EQ(row.words, "minor road");
  EXPECT_EQ(find_default(Quality::road_length, "bridleway"), nullptr);
  EXPECT_EQ(setting("scenario duration").low, 30);
}

// ---- level detection -------------------------------------------------------------------------

TEST(WmgDetectLevel, SceneryElementsAtALineStartMeansLevelTwo) {
  auto level = [](const std::string& text) { return detect_wmg_level(SourceFile("t.sdl", text)); };
  EXPECT_EQ(level("VERSION: 1.0\nSCENERY ELEMENTS:\n"), 2);
  EXPECT_EQ(level("VERSION: 1.0\r\n  \tSCENERY   ELEMENTS :\r\n"), 2);
  EXPECT_EQ(level("SCENERY ELEMENTS"), 2);
  EXPECT_EQ(level(""), 1);
  EXPECT_EQ(level("During the day, there is a light sky.\n"), 1);
  EXPECT_EQ(level("# SCENERY ELEMENTS:\n"), 1);        // in a comment
  EXPECT_EQ(level("DO: 'x' SCENERY ELEMENTS:\n"), 1);  // not at the line start
  EXPECT_EQ(level("SCENERY ELEMENTSX:\n"), 1);         // another word
  EXPECT_EQ(level("SCENERYELEMENTS:\n"), 1);           // one word
  EXPECT_EQ(level("scenery elements:\n"), 1);          // keywords are case-sensitive
}

TEST(WmgDetectLevel, TheCorpusFilesAreDetectedByTheirNames) {
  for (const auto& path : scenfuzz::test::files_in(test::wmg_corpus_dir(), {".sdl"})) {
    bool level1 = path.filename().string().ends_with("_level1.sdl");
    EXPECT_EQ(detect_wmg_level(scenfuzz::test::load(path)), level1 ? 1 : 2) << path;
  }
}

// ---- corpus ----------------------------------------------------------------------------------

std::vector<std::filesystem::path> level1_corpus() {
  std::vector<std::filesystem::path> files;
  for (const auto& path : scenfuzz::test::files_in(test::wmg_corpus_dir(), {".sdl"}))
    if (path.filename().string().ends_with("_level1.sdl")) files.push_back(path);
  return files;
}

TEST(WmgLevel1Corpus, HasTheScenariosAndEachParsesConvertsAndRoundTrips) {
  std::vector<std::filesystem::path> files = level1_corpus();
  std::vector<std::string> names;
  for (const auto& path : files) names.push_back(path.filename().string());
  for (const char* expected : {"motorway_cut_in_level1.sdl", "junction_crossing_level1.sdl",
                               "pedestrian_crossing_level1.sdl", "lead_vehicle_braking_level1.sdl"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    SourceFile file = scenfuzz::test::load(path);
    EXPECT_EQ(file.text().rfind("# ", 0), 0u) << "starts with a comment header";
    Level1ParseResult parsed = parse_level1(file);
    ASSERT_TRUE(parsed.file.has_value()) << format_diagnostics(file, parsed.diagnostics);
    EXPECT_TRUE(parsed.diagnostics.all().empty()) << format_diagnostics(file, parsed.diagnostics);
    Diagnostics diagnostics;
    Level2File converted = level1_to_level2(*parsed.file, diagnostics);
    EXPECT_TRUE(diagnostics.all().empty()) << format_diagnostics(file, diagnostics);
    std::string printed = print_level2(converted);
    SourceFile printed_file("printed.sdl", printed);
    EXPECT_EQ(detect_wmg_level(printed_file), 2);
    Level2ParseResult again = parse_level2(printed_file);
    ASSERT_TRUE(again.file.has_value())
        << format_diagnostics(printed_file, again.diagnostics) << printed;
    EXPECT_TRUE(again.diagnostics.all().empty());
    EXPECT_TRUE(*again.file == converted) << printed;
    EXPECT_EQ(print_level2(*again.file), printed) << "printing is not stable";
  }
}

TEST(WmgLevel1Corpus, TheFuzzingSeedsParseConvertAndRoundTrip) {
  std::vector<std::filesystem::path> files =
      scenfuzz::test::files_in(scenfuzz::test::lang_data_dir() / "wmg", {".sdl"});
  EXPECT_GE(files.size(), 20u);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    SourceFile file = scenfuzz::test::load(path);
    EXPECT_EQ(detect_wmg_level(file), 1);
    Level1ParseResult parsed = parse_level1(file);
    ASSERT_TRUE(parsed.file.has_value()) << format_diagnostics(file, parsed.diagnostics);
    Diagnostics diagnostics;
    Level2File converted = level1_to_level2(*parsed.file, diagnostics);
    Level2ParseResult again = parse_level2(SourceFile("printed.sdl", print_level2(converted)));
    ASSERT_TRUE(again.file.has_value());
    EXPECT_TRUE(*again.file == converted);
  }
}

TEST(WmgLevel1Corpus, TheMotorwayCutInSearchesHeavyRainTrafficAndTheCutIn) {
  Level1ParseResult parsed =
      parse_level1(scenfuzz::test::load(test::wmg_corpus_dir() / "motorway_cut_in_level1.sdl"));
  ASSERT_TRUE(parsed.file.has_value());
  Diagnostics diagnostics;
  Level2File file = level1_to_level2(*parsed.file, diagnostics);
  EXPECT_EQ(file.environment.rainfall.type.text, "Heavy Rain");
  EXPECT_TRUE(file.environment.rainfall.intensity.is_range);
  ASSERT_TRUE(file.traffic.has_value());
  expect_range(file.traffic->flows.at(0).first, 1500, 2000);
  const ManoeuvrePhase& cut_in = file.dynamics.sequences.at(0).sequences.at(0).phases.at(0);
  EXPECT_EQ(cut_in.type.text, "LaneChangeRight_CutIn");
  EXPECT_TRUE(cut_in.relative.distance.is_range);
}

}  // namespace
}  // namespace scenfuzz::wmg
