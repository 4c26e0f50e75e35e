// CH-Scenario to the scenario IR (docs/ch-scenario.md, "What a file means"): the grammar's worked
// example value by value; which entity is the ego and where each entity starts when its position
// is not written; the track words; weather, disasters and the time of day; safety protocols as
// specs over the ego's signals, and their mistakes; a concrete scenario written back in the file's
// own units.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "lang/chs/chs.hpp"
#include "lang/chs/lane_places.hpp"
#include "lang/chs/parser.hpp"
#include "lang/source_file.hpp"
#include "tests/lang/test_files.hpp"

namespace scenfuzz::chs {
namespace {

using ::testing::HasSubstr;

// A blank 400 m by 60 m map with one road running east, 7 m wide, then `rest`.
std::string on_east_road(const std::string& rest) {
  return "import from MAP\n  length: 400\n  width: 60\n"
         "RoadNetwork\n  road east_road\n"
         "    left boundary: (0, 37) (400, 37)\n"
         "    center lines: (0, 30) (400, 30)\n"
         "    right boundary: (0, 23) (400, 23)\n" +
         rest;
}

ScenarioParse read(const std::string& text) { return parse_scenario(SourceFile("test.chs", text)); }

// The text a located value was written as.
std::string text_at(const std::string& text, SourceLocation at) {
  EXPECT_TRUE(at.known());
  return text.substr(at.offset, at.length);
}

std::string messages(const Diagnostics& diagnostics) {
  return format_diagnostics(SourceFile("test.chs", ""), diagnostics);
}

const WeatherComponent* weather(const ScenarioTemplate& scenario, const std::string& kind) {
  for (const WeatherComponent& component : scenario.environment->weather)
    if (component.kind == kind) return &component;
  return nullptr;
}

TEST(ChsTranslation, TheWorkedExample) {
  const SourceFile file =
      scenfuzz::test::load(scenfuzz::test::lang_data_dir() / "chs" / "typhoon_minibus.chs");
  const ScenarioParse parsed = parse_scenario(file);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  const ScenarioTemplate& s = parsed.scenario;
  EXPECT_EQ(s.language, SourceLanguage::ch_scenario);
  EXPECT_TRUE(s.has_scenario);
  EXPECT_TRUE(s.parameters.empty());
  // The blank map with its one road, every point located at its numbers.
  EXPECT_EQ(s.map.name, "blank");
  ASSERT_EQ(s.map.roads.size(), 1u);
  const RoadOutline& road = s.map.roads[0];
  EXPECT_EQ(road.name, "narrow_road");
  ASSERT_EQ(road.centre_line.size(), 2u);
  EXPECT_EQ(road.centre_line[1].x.constant, 400);
  EXPECT_EQ(text_at(file.text(), road.centre_line[1].y.location), "25.0");
  // The minibus is the ego (the only vehicle), in the forward lane next to the centre line.
  EXPECT_EQ(s.ego.name, "minibus");
  ASSERT_TRUE(s.ego.type);
  EXPECT_EQ(s.ego.type->model, "van");
  EXPECT_EQ(s.ego.initial.position.kind, PositionKind::lane);
  EXPECT_EQ(s.ego.initial.position.lane, "narrow_road_f0");
  EXPECT_EQ(s.ego.initial.position.s.constant, 50);
  ASSERT_TRUE(s.ego.initial.speed);
  EXPECT_DOUBLE_EQ(s.ego.initial.speed->constant, 12.5);  // 45 km/h
  EXPECT_EQ(text_at(file.text(), s.ego.initial.speed->location), "45.0");
  // The little boy stands on the pavement on the ego's right, 60 m ahead.
  ASSERT_EQ(s.pedestrians.size(), 1u);
  const Actor& boy = s.pedestrians[0];
  EXPECT_EQ(boy.name, "pedestrians");
  EXPECT_EQ(boy.initial.position.kind, PositionKind::relative);
  EXPECT_EQ(boy.initial.position.reference, "minibus");
  EXPECT_EQ(boy.initial.position.relative_location, "FSR");
  EXPECT_EQ(boy.initial.position.s.constant, 60);
  EXPECT_EQ(boy.initial.speed->constant, 0);
  // Weather: the written precipitation and visibility beat the typhoon's floors (0.9, 0.5).
  const WeatherComponent* rain = weather(s, "rain");
  ASSERT_NE(rain, nullptr);
  EXPECT_EQ(rain->intensity.constant, 1.0);
  EXPECT_EQ(text_at(file.text(), rain->intensity.location), "1.0");
  const WeatherComponent* fog = weather(s, "fog");
  ASSERT_NE(fog, nullptr);
  EXPECT_DOUBLE_EQ(fog->intensity.constant, 0.6);
  EXPECT_EQ(text_at(file.text(), fog->intensity.location), "0.4");
  // 17:30:42 from the timestamp, located at its time alone.
  ASSERT_TRUE(s.environment->time_of_day);
  EXPECT_EQ(s.environment->time_of_day->constant, 17 * 3600 + 30 * 60 + 42);
  EXPECT_EQ(text_at(file.text(), s.environment->time_of_day->location), "17:30:42");
  // Two safety protocols, each judged throughout the run.
  ASSERT_EQ(s.specs.size(), 2u);
  EXPECT_EQ(s.specs[0].name, "constraint1.safety_protocol");
  EXPECT_EQ(s.specs[1].name, "constraint2.safety_protocol");
  for (const Spec& spec : s.specs) {
    EXPECT_EQ(spec.trace, s.trace_name);
    EXPECT_EQ(spec.formula.kind, FormulaKind::always);
    EXPECT_FALSE(spec.formula.interval);
  }
  // (wiper = true) && (lighton = true) && (hazardlighton = true)
  const Formula& lamps = s.specs[0].formula.operands[0];
  ASSERT_EQ(lamps.kind, FormulaKind::conjunction);
  EXPECT_EQ(lamps.operands[0].kind, FormulaKind::conjunction);
  EXPECT_EQ(lamps.operands[0].operands[0].terms[0].name, "wiperOn");
  EXPECT_EQ(lamps.operands[0].operands[1].kind, FormulaKind::disjunction);
  EXPECT_EQ(lamps.operands[1].terms[0].name, "warningFlashOn");
  // ((dist > safedistance) = true) && (emergencybreak = false)
  const Formula& distance = s.specs[1].formula.operands[0];
  ASSERT_EQ(distance.kind, FormulaKind::conjunction);
  const Formula& gap = distance.operands[0];
  ASSERT_EQ(gap.kind, FormulaKind::comparison);
  EXPECT_EQ(gap.compare, CompareOp::greater);
  EXPECT_EQ(gap.terms[0].name, "NPCAhead");
  EXPECT_EQ(gap.terms[1].kind, TermKind::multiply);
  ASSERT_EQ(distance.operands[1].kind, FormulaKind::negation);
  EXPECT_EQ(distance.operands[1].operands[0].terms[0].name, "brake");
  // What is not simulated is said: the aim, the traffic light, the two events (the example has no
  // road user but the ego for them to move).
  const std::string said = format_diagnostics(file, parsed.diagnostics);
  EXPECT_THAT(said, HasSubstr("the aim 'The First People's Hospital' is no road"));
  EXPECT_THAT(said, HasSubstr("a road network of one road has no junction for a traffic light to "
                              "control: 'traffic_light' is left out"));
  EXPECT_THAT(said, HasSubstr("typhoon_minibus.chs:52:13: warning: the constraint relates with no "
                              "road user scenfuzz drives"));
  EXPECT_THAT(said, HasSubstr("typhoon_minibus.chs:58:13: warning: the constraint relates with no "
                              "road user scenfuzz drives"));
  EXPECT_TRUE(s.parameters.empty());
}

TEST(ChsTranslation, AnEntityNamedTheEgoIsTheEgoElseTheFirstVehicle) {
  const std::string entities =
      "Entity\n  DynamicEntity1\n    name: walker\n    speed: 5\n"
      "  DynamicEntity2\n    name: lorry\n    speed: 50\n"
      "  DynamicEntity3\n    name: ego\n    speed: 40\n";
  ScenarioParse named = read(on_east_road(entities));
  ASSERT_TRUE(named.ok()) << messages(named.diagnostics);
  EXPECT_EQ(named.scenario.ego.name, "ego");
  ASSERT_EQ(named.scenario.vehicles.size(), 1u);
  EXPECT_EQ(named.scenario.vehicles[0].type->model, "truck");
  ASSERT_EQ(named.scenario.pedestrians.size(), 1u);

  ScenarioParse first =
      read(on_east_road("Entity\n  DynamicEntity1\n    name: walker\n    speed: 5\n"
                        "  DynamicEntity2\n    name: current_vehicle\n    speed: 50\n"));
  ASSERT_TRUE(first.ok()) << messages(first.diagnostics);
  EXPECT_EQ(first.scenario.ego.name, "current_vehicle");

  ScenarioParse none =
      read(on_east_road("Entity\n  DynamicEntity1\n    name: pedestrian\n    speed: 5\n"));
  EXPECT_FALSE(none.ok());
  EXPECT_THAT(messages(none.diagnostics), HasSubstr("no dynamic entity that is a vehicle"));
}

TEST(ChsTranslation, DefaultPlacesFollowTheTrackWords) {
  const std::string entities =
      "Entity\n"
      "  DynamicEntity1\n    name: car\n    speed: 36\n    track: heading to the west\n"
      "  DynamicEntity2\n    name: lead_bus\n    speed: 30\n    track: ahead\n"
      "  DynamicEntity3\n    name: van\n    speed: 30\n    track: behind\n"
      "  DynamicEntity4\n    name: truck\n    speed: 60\n    track: oncoming\n"
      "  DynamicEntity5\n    name: boy\n    speed: 4\n    track: crossing the road\n";
  const ScenarioParse parsed = read(on_east_road(entities));
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  const ScenarioTemplate& s = parsed.scenario;
  // West is against the point order: the ego drives the left half.
  EXPECT_EQ(s.ego.initial.position.lane, "east_road_b0");
  EXPECT_EQ(s.ego.initial.position.s.constant, 50);
  ASSERT_EQ(s.vehicles.size(), 3u);
  EXPECT_EQ(s.vehicles[0].initial.position.kind, PositionKind::relative);
  EXPECT_EQ(s.vehicles[0].initial.position.relative_location, "F");
  EXPECT_EQ(s.vehicles[0].initial.position.s.constant, 40);
  EXPECT_EQ(s.vehicles[1].initial.position.relative_location, "R");
  EXPECT_EQ(s.vehicles[1].initial.position.s.constant, -25);
  // Oncoming: the other half, 150 m ahead of the ego (400 - 50 - 150 along its own lane).
  EXPECT_EQ(s.vehicles[2].initial.position.kind, PositionKind::lane);
  EXPECT_EQ(s.vehicles[2].initial.position.lane, "east_road_f0");
  EXPECT_EQ(s.vehicles[2].initial.position.s.constant, 200);
  // The walker crosses from the pavement at its speed.
  ASSERT_EQ(s.pedestrians.size(), 1u);
  const Actor& boy = s.pedestrians[0];
  EXPECT_EQ(boy.initial.position.relative_location, "FSR");
  ASSERT_EQ(boy.motion.kind, MotionKind::manoeuvres);
  ASSERT_EQ(boy.motion.phases.size(), 1u);
  EXPECT_EQ(boy.motion.phases[0].manoeuvre, "Walk_Cross");
  EXPECT_DOUBLE_EQ(boy.motion.phases[0].parameters[0].value.constant, 4 / 3.6);
}

TEST(ChsTranslation, WordsNotReadAreWarnedOf) {
  const ScenarioParse parsed = read(
      on_east_road("Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n"
                   "    track: zigzag merrily to the east\n"
                   "  DynamicEntity2\n    name: bus\n    speed: 36\n    track: change lane left\n"
                   "  StaticEntity1\n    name: thing\n    overview: something odd\n"));
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  const std::string said = messages(parsed.diagnostics);
  EXPECT_THAT(said, HasSubstr("does not read 'zigzag', 'merrily' in a track"));
  EXPECT_THAT(said, HasSubstr("cannot tell what 'thing' is"));
  EXPECT_EQ(parsed.scenario.ego.initial.position.lane, "east_road_f0");
}

// The names a formula's terms give (road users, signals' operands), each once.
void names_in(const SpecTerm& term, std::set<std::string>& names) {
  if (term.kind == TermKind::word) names.insert(term.name);
  for (const SpecTerm& operand : term.operands) names_in(operand, names);
}

std::set<std::string> names_in(const Formula& formula) {
  std::set<std::string> names;
  for (const SpecTerm& term : formula.terms) names_in(term, names);
  for (const Formula& operand : formula.operands) names.merge(names_in(operand));
  return names;
}

// A track's lane change is the vehicle's first manoeuvre, from the start; an overtake pulls out
// when the vehicle is close behind a slower road user and comes back when the lane on its right is
// clear, both judged among the other road users; the ego's own manoeuvres are the system under
// test's to decide.
TEST(ChsTranslation, ATracksManoeuvresAreTheVehiclesPhases) {
  const std::string text = on_east_road(
      "Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n    track: turn left\n"
      "  DynamicEntity2\n    name: bus\n    speed: 36\n    track: ahead, change lane left\n"
      "  DynamicEntity3\n    name: van\n    speed: 54\n    track: overtake the bus\n"
      "  StaticEntity1\n    name: parked truck\n    overview: a parked lorry\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  ASSERT_EQ(parsed.scenario.vehicles.size(), 3u);
  const Motion& bus = parsed.scenario.vehicles[0].motion;
  ASSERT_EQ(bus.kind, MotionKind::manoeuvres);
  ASSERT_EQ(bus.phases.size(), 1u);
  EXPECT_EQ(bus.phases[0].manoeuvre, "LaneChangeLeft");
  EXPECT_FALSE(bus.phases[0].start_when);

  const Motion& van = parsed.scenario.vehicles[1].motion;
  ASSERT_EQ(van.kind, MotionKind::manoeuvres);
  ASSERT_EQ(van.phases.size(), 2u);
  const ManoeuvrePhase& out = van.phases[0];
  EXPECT_EQ(out.manoeuvre, "Overtake");
  EXPECT_EQ(text_at(text, out.location), "overtake the bus");
  ASSERT_EQ(out.parameters.size(), 1u);
  EXPECT_EQ(out.parameters[0].name, "speed");
  EXPECT_DOUBLE_EQ(out.parameters[0].value.constant, 15) << "out at its own speed";
  const ManoeuvrePhase& back = van.phases[1];
  EXPECT_EQ(back.manoeuvre, "LaneChangeRight");
  EXPECT_EQ(back.location, out.location);
  // Both are judged from the van among every other road user, the parked truck included.
  ASSERT_TRUE(out.start_when);
  ASSERT_TRUE(back.start_when);
  const std::set<std::string> everyone{"car", "bus", "van", "parked truck"};
  EXPECT_EQ(names_in(*out.start_when), everyone);
  EXPECT_EQ(names_in(*back.start_when), everyone);
  EXPECT_EQ(back.start_when->kind, FormulaKind::negation) << "when nothing blocks the right";

  const std::string said = messages(parsed.diagnostics);
  EXPECT_THAT(said, HasSubstr("test.chs:13:12: warning: the ego is driven by the system under "
                              "test, which decides itself when to change lanes"));
  EXPECT_THAT(said, ::testing::Not(HasSubstr("not simulated")));
  // Whom it overtakes is not read: the van judges every road user.
  EXPECT_THAT(said, HasSubstr("test.chs:21:12: warning: scenfuzz does not read 'bus' in a track"));
  EXPECT_THAT(said, ::testing::Not(HasSubstr("bus follows its lane")));
}

// A turn is the vehicle's first phase, at the next junction on its way, on a road network (whose
// crossing roads make junctions, outline_map.hpp) as on a named map; a map without a junction is
// the simulation's to warn of. A pedestrian's manoeuvre words are warned of.
TEST(ChsTranslation, ATurnIsTheVehiclesFirstPhaseOnAnyMap) {
  const std::string entities =
      "Entity\n  DynamicEntity1\n    name: ego\n    speed: 36\n    position: (-80, -1.75)\n"
      "  DynamicEntity2\n    name: taxi\n    speed: 30\n    position: (-60, -1.75)\n"
      "    track: turning right\n"
      "  DynamicEntity3\n    name: boy\n    speed: 4\n    track: turn left\n";
  const ScenarioParse network =
      read(on_east_road("Entity\n  DynamicEntity1\n    name: ego\n    speed: 36\n"
                        "  DynamicEntity2\n    name: taxi\n    speed: 30\n    track: turn right\n"
                        "  DynamicEntity3\n    name: boy\n    speed: 4\n    track: turn left\n"));
  ASSERT_TRUE(network.ok()) << messages(network.diagnostics);
  ASSERT_EQ(network.scenario.vehicles.size(), 1u);
  ASSERT_EQ(network.scenario.vehicles[0].motion.kind, MotionKind::manoeuvres);
  EXPECT_EQ(network.scenario.vehicles[0].motion.phases.at(0).manoeuvre, "TurnRight");
  EXPECT_THAT(messages(network.diagnostics), ::testing::Not(HasSubstr("junction")));
  EXPECT_THAT(messages(network.diagnostics), HasSubstr("boy, a pedestrian, crosses the road"));

  const std::string text = "map: t_junction\n" + entities;
  const ScenarioParse named = read(text);
  ASSERT_TRUE(named.ok()) << messages(named.diagnostics);
  ASSERT_EQ(named.scenario.vehicles.size(), 1u);
  const Motion& taxi = named.scenario.vehicles[0].motion;
  ASSERT_EQ(taxi.kind, MotionKind::manoeuvres);
  ASSERT_EQ(taxi.phases.size(), 1u);
  EXPECT_EQ(taxi.phases[0].manoeuvre, "TurnRight");
  EXPECT_FALSE(taxi.phases[0].start_when);
  EXPECT_EQ(text_at(text, taxi.phases[0].location), "turning right");
  const std::string said = messages(named.diagnostics);
  EXPECT_THAT(said, ::testing::Not(HasSubstr("needs a junction")));
  EXPECT_THAT(said, HasSubstr("test.chs:15:12: warning: changing lanes, overtaking and turning are "
                              "a vehicle's manoeuvres: boy, a pedestrian, crosses the road"));
}

// A light on a road network controls the junction nearest its point, else the ego's, and its
// colour is what the ego's road shows at the start; a named map's lights are its own.
TEST(ChsTranslation, ATrafficLightIsASignalOnTheJunctionNearestIt) {
  const std::string crossing =
      "  road north_road\n    left boundary: (196.5, 0) (196.5, 60)\n"
      "    center lines: (200, 0) (200, 60)\n    right boundary: (203.5, 0) (203.5, 60)\n";
  const std::string text = on_east_road(
      crossing +
      "Entity\n  DynamicEntity1\n    name: ego\n    speed: 36\n    position: (120, 26.5)\n"
      "  StaticEntity1\n    name: traffic light\n    overview: the light is red\n"
      "  StaticEntity2\n    name: signal\n    overview: green\n    position: (300, 30)\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  const std::vector<JunctionSignal>& signals = parsed.scenario.map.signals;
  ASSERT_EQ(signals.size(), 2u);
  EXPECT_EQ(signals[0].name, "traffic light");
  EXPECT_EQ(signals[0].road, "east_road");
  EXPECT_EQ(signals[0].colour, "red");
  EXPECT_DOUBLE_EQ(signals[0].x, 120);
  EXPECT_DOUBLE_EQ(signals[0].y, 26.5);
  EXPECT_EQ(text_at(text, signals[0].location).substr(0, 12), "StaticEntity");
  EXPECT_EQ(signals[1].colour, "green");
  EXPECT_DOUBLE_EQ(signals[1].x, 300);

  const ScenarioParse named = read(
      "map: crossroads\nEntity\n  DynamicEntity1\n    name: ego\n    speed: 36\n"
      "    position: (-80, -1.75)\n  StaticEntity1\n    name: traffic light\n");
  ASSERT_TRUE(named.ok()) << messages(named.diagnostics);
  EXPECT_TRUE(named.scenario.map.signals.empty());
  EXPECT_THAT(messages(named.diagnostics),
              HasSubstr("the named map 'crossroads' has its own traffic lights: 'traffic light' "
                        "is left out"));
}

// east_road's halves are 7 m wide: two lanes of 3.5 m each way.
TEST(ChsTranslation, AWrittenVehiclePointIsALanePlaceLocatedAtItsNumbers) {
  const std::string text = on_east_road(
      "Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n    position: (12.5, 27)\n"
      "  DynamicEntity2\n    name: van\n    speed: 36\n    position: (300, 35.5)\n"
      "  DynamicEntity3\n    name: bus\n    speed: 0\n    position: (80, 45)\n"
      "  StaticEntity1\n    name: rock\n    overview: a fallen boulder\n"
      "    position: (150, 28.5)\n");
  const ScenarioParse parsed = read(text);
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  // 3 m right of the centre line: the forward lane next to it, 1.25 m right of its centre.
  const Position& ego = parsed.scenario.ego.initial.position;
  EXPECT_EQ(ego.kind, PositionKind::lane);
  EXPECT_EQ(ego.lane, "east_road_f0");
  EXPECT_DOUBLE_EQ(ego.s.constant, 12.5);
  EXPECT_DOUBLE_EQ(ego.lateral->constant, -1.25);
  EXPECT_EQ(text_at(text, ego.s.location), "12.5");
  EXPECT_EQ(text_at(text, ego.lateral->location), "27");
  // 5.5 m left: the outer lane against the point order, 100 m from its start, 0.25 m right.
  ASSERT_EQ(parsed.scenario.vehicles.size(), 2u);
  const Position& van = parsed.scenario.vehicles[0].initial.position;
  EXPECT_EQ(van.lane, "east_road_b1");
  EXPECT_DOUBLE_EQ(van.s.constant, 100);
  EXPECT_DOUBLE_EQ(van.lateral->constant, -0.25);
  // Beyond the road's boundary a point stays a point; so do obstacles.
  const Position& bus = parsed.scenario.vehicles[1].initial.position;
  EXPECT_EQ(bus.kind, PositionKind::coordinate);
  EXPECT_EQ(text_at(text, bus.y.location), "45");
  ASSERT_EQ(parsed.scenario.obstacles.size(), 1u);
  EXPECT_EQ(parsed.scenario.obstacles[0].position.kind, PositionKind::coordinate);
  EXPECT_EQ(parsed.scenario.obstacles[0].position.x.constant, 150);
  EXPECT_EQ(parsed.scenario.obstacles[0].shape->kind, ShapeKind::box);
}

TEST(ChsTranslation, ANamedMapNeedsTheEgosPosition) {
  const ScenarioParse without =
      read("map: san_francisco\nEntity\n  DynamicEntity1\n    name: car\n    speed: 36\n");
  EXPECT_FALSE(without.ok());
  EXPECT_THAT(messages(without.diagnostics),
              HasSubstr("test.chs:3:3: error: on the named map 'san_francisco', car (the ego) "
                        "needs a 'position: (x, y)'"));
  const ScenarioParse with = read(
      "map: san_francisco\nEntity\n  DynamicEntity1\n    name: car\n    speed: 36\n"
      "    position: (587000, 4141000)\n");
  ASSERT_TRUE(with.ok()) << messages(with.diagnostics);
  EXPECT_EQ(with.scenario.map.name, "san_francisco");
  EXPECT_TRUE(with.scenario.map.roads.empty());
}

TEST(ChsTranslation, ARoadOffTheBlankMapIsAnError) {
  const ScenarioParse parsed = read(
      "import from MAP\n  length: 100\n  width: 50\n"
      "RoadNetwork\n  road r\n    left boundary: (0, 10) (120, 10)\n"
      "    center lines: (0, 5) (100, 5)\n    right boundary: (0, 0) (100, 0)\n"
      "Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n");
  EXPECT_FALSE(parsed.ok());
  EXPECT_THAT(messages(parsed.diagnostics),
              HasSubstr("test.chs:6:28: error: this point of road r lies off the map"));
}

TEST(ChsTranslation, DisastersBlockTheLaneAndDarkenTheSky) {
  const ScenarioParse parsed =
      read(on_east_road("sandstorm: 1\nlandslide: 1\nvisibility: 0.8\n"
                        "Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n"));
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  const ScenarioTemplate& s = parsed.scenario;
  // The sandstorm's fog (0.9) beats the written visibility's (0.2): the number is not mutable.
  const WeatherComponent* fog = weather(s, "fog");
  ASSERT_NE(fog, nullptr);
  EXPECT_EQ(fog->intensity.constant, 0.9);
  EXPECT_FALSE(fog->intensity.location.known());
  ASSERT_EQ(s.obstacles.size(), 1u);
  const Obstacle& landslide = s.obstacles[0];
  EXPECT_EQ(landslide.name, "landslide");
  EXPECT_EQ(landslide.position.kind, PositionKind::relative);
  EXPECT_EQ(landslide.position.reference, "car");
  EXPECT_EQ(landslide.position.s.constant, 120);
  EXPECT_EQ(landslide.shape->dimensions[1].constant, 2.5);
  EXPECT_EQ(landslide.position.lateral->constant, -0.75);
  // A dry road keeps its grip; the speed limit is the law's 30 km/h in a sandstorm.
  EXPECT_FALSE(s.environment->road_friction);
  ASSERT_TRUE(s.map.roads[0].speed_limit);
  EXPECT_DOUBLE_EQ(s.map.roads[0].speed_limit->constant, 30 / 3.6);
}

TEST(ChsTranslation, HighRiskConditionsLowerTheFrictionAndTheSpeedLimit) {
  const auto friction = [](const std::string& conditions) -> double {
    const ScenarioParse parsed =
        read(on_east_road(conditions + "Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n"));
    EXPECT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
    const auto& value = parsed.scenario.environment->road_friction;
    return value ? value->constant : 1.0;
  };
  EXPECT_EQ(friction(""), 1.0);
  EXPECT_DOUBLE_EQ(friction("wetness: 1\n"), 0.7);
  EXPECT_DOUBLE_EQ(friction("wetness: 1\nwade: 1\n"), 0.5);
  EXPECT_DOUBLE_EQ(friction("muddy: 1\nwade: 1\n"), 0.4);
  EXPECT_DOUBLE_EQ(friction("iceroad: 1\nmuddy: 1\n"), 0.2);
  EXPECT_EQ(friction("rough: 1\n"), 1.0);
  const ScenarioParse usual = read(on_east_road("Entity\n  name: car\n  speed: 36\n"));
  ASSERT_TRUE(usual.ok()) << messages(usual.diagnostics);
  EXPECT_DOUBLE_EQ(usual.scenario.map.roads[0].speed_limit->constant, 50 / 3.6);
  const ScenarioParse steep =
      read(on_east_road("steepdescentahead: 1\nEntity\n  name: car\n  speed: 36\n"));
  ASSERT_TRUE(steep.ok()) << messages(steep.diagnostics);
  EXPECT_DOUBLE_EQ(steep.scenario.map.roads[0].speed_limit->constant, 30 / 3.6);
}

struct ProtocolCase {
  const char* protocol;
  const char* error;  // empty: reads
};

TEST(ChsTranslation, SafetyProtocolMistakesAreLocated) {
  const ProtocolCase cases[] = {
      {"not (speed > 60)", ""},
      {"(lighton != false) || (dist >= 10)", ""},
      {"wiper", ""},
      {"(wipers = 1)", "4:21: error: compare a condition with true or false"},
      {"speed", "4:20: error: this is a number, where a condition is expected"},
      {"(speed = true)", "4:21: error: this is a number, where a condition is expected"},
      {"(warp > 3)", "4:21: error: scenfuzz knows no signal 'warp' of a safety protocol"},
      {"true", "4:20: error: a constant true or false here decides nothing"},
      {"(wiper < true)", "4:21: error: true and false are compared with = or != only"},
  };
  for (const ProtocolCase& c : cases) {
    const std::string text = "ConstraintList\n  safety_protocol: " + std::string(c.protocol) + "\n";
    const ScenarioParse parsed =
        read(on_east_road("Entity\n  DynamicEntity1\n    name: car\n    speed: 36\n") + text);
    const std::string said = messages(parsed.diagnostics);
    if (std::string(c.error).empty()) {
      EXPECT_TRUE(parsed.ok()) << c.protocol << "\n" << said;
      ASSERT_EQ(parsed.scenario.specs.size(), 1u) << c.protocol;
      EXPECT_EQ(parsed.scenario.specs[0].name, "safety_protocol");
    } else {
      EXPECT_THAT(said, HasSubstr(std::string("test.chs:1") + c.error)) << c.protocol;
    }
  }
}

TEST(ChsTranslation, AConcreteScenarioIsWrittenInTheFilesOwnUnits) {
  const std::string text = on_east_road(
      "visibility: 0.7\n"
      "Entity\n  DynamicEntity1\n    name: car\n    timestamp: 2022-01-30 17:30:42\n"
      "    speed: 36\n    position: (12.5, 27)\n");
  const SourceFile file("test.chs", text);
  ScenarioParse parsed = parse_scenario(file);
  ASSERT_TRUE(parsed.ok()) << messages(parsed.diagnostics);
  ScenarioTemplate& s = parsed.scenario;
  // Parameters as the mutation space makes them: at the numbers' places, in the IR's units.
  auto parameter = [&](const std::string& name, const std::string& unit, SourceLocation at) {
    Parameter p;
    p.name = name;
    p.unit = unit;
    p.location = at;
    s.parameters.push_back(p);
  };
  parameter("car.init.speed", "m/s", s.ego.initial.speed->location);
  parameter("car.init.position.s", "m", s.ego.initial.position.s.location);
  parameter("car.init.position.lateral", "m", s.ego.initial.position.lateral->location);
  parameter("environment.fog", "", weather(s, "fog")->intensity.location);
  parameter("environment.time", "time of day", s.environment->time_of_day->location);
  s.ego.initial.position.s = parameter_value(1, s.ego.initial.position.s.location);
  s.ego.initial.position.lateral = parameter_value(2, s.ego.initial.position.lateral->location);
  const std::vector<double> values = {15, 20.25, -0.25, 0.5, 6 * 3600 + 5 * 60 + 9};
  const std::string concrete = print_concrete(file, s, values);
  EXPECT_THAT(concrete, HasSubstr("# concrete scenario of test.chs chosen by scenfuzz:\n"));
  EXPECT_THAT(concrete, HasSubstr("#   car.init.speed = 15 m/s\n"));
  // Written back: 15 m/s as 54 km/h, fog 0.5 as visibility 0.5, the time in the timestamp.
  const ParseResult back = parse(SourceFile("concrete.chs", concrete));
  ASSERT_TRUE(back.file) << format_diagnostics(SourceFile("concrete.chs", concrete),
                                               back.diagnostics);
  const DynamicEntity& car = back.file->dynamic_entities[0];
  EXPECT_DOUBLE_EQ(car.speed.value, 54);
  // The lane place chosen (20.25 m along, 0.25 m right of the lane's centre) as a point.
  EXPECT_DOUBLE_EQ(car.position->x, 20.25);
  EXPECT_DOUBLE_EQ(car.position->y, 28);
  EXPECT_EQ(car.timestamp.text, "2022-01-30 06:05:09");
  EXPECT_DOUBLE_EQ(back.file->weather.visibility.value, 0.5);
}

// Any point in a lane of a bent road reads as a place whose point is the one written, so that a
// finding written back replays the place the search chose.
TEST(ChsLanePlaces, APlaceReadsBackAsItsPointOnABentRoad) {
  Road road;
  road.name.text = "bend";
  auto polyline = [](std::vector<std::pair<double, double>> points) {
    std::vector<Point> line;
    for (auto [x, y] : points) line.push_back(Point{x, y, {}, {}, {}});
    return line;
  };
  road.left_boundary = polyline({{0, 8}, {100, 8}, {180, 68}});
  road.centre_lines = polyline({{0, 0}, {100, 0}, {180, 60}});
  road.right_boundary = polyline({{0, -8}, {100, -8}, {180, 52}});
  const std::vector<Road> roads = {road};
  EXPECT_EQ(lane_count(road, true), 2);
  int read = 0;
  for (double x = 5; x < 175; x += 7.3)
    for (double y = -7.5; y < 67; y += 1.9) {
      const std::optional<LanePlace> place = lane_place_at(roads, x, y);
      if (!place) continue;
      ++read;
      const PlanePoint back = point_of(*place);
      EXPECT_NEAR(back.x, x, 1e-9) << x << ", " << y;
      EXPECT_NEAR(back.y, y, 1e-9) << x << ", " << y;
      EXPECT_LT(std::abs(place->lateral), 2.0 + 1e-9) << x << ", " << y;
    }
  EXPECT_GT(read, 150);
  // Off the road: beyond its boundary, before its start.
  EXPECT_FALSE(lane_place_at(roads, 50, 9));
  EXPECT_FALSE(lane_place_at(roads, -1, 2));
}

}  // namespace
}  // namespace scenfuzz::chs
