// The space derived around a concrete AVUnit scenario: which numbers become parameters, their
// neighbourhoods and bounds, shared literals, and the concrete text printed back.
#include "sampler/mutation_space.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {
namespace {

constexpr const char* kConcrete = R"(speed = 12;
ego_init_state = ("east_0"->50, , speed);
ego_vehicle = AV(ego_init_state, ("east_0"->450), ("Lincoln2017MKZ", white));
cut_start = ("east_1"->2, , speed);
cut_a = ((300, 1.5), 10 deg, 9.5);
cut_b = ((304, 1.5), , 8);
cut_c = ((340, 1.5), , 0.1);
cutter = Vehicle(cut_start, Waypoint(cut_a, cut_b, cut_c), ("east_0"->480));
weather = {rain: 0.9, wetness: 0.1};
env = Environment(22:30, weather);
scenario = CreateScenario{load("straight"); ego_vehicle; {cutter}; {}; {}; env; };
Trace trace = EXE(scenario);
no_collision = G (dis(trace[ego], trace[truth][cutter]) >= 0.5);
trace |= no_collision;
)";

struct Derived {
  SourceFile file{"concrete.avu", kConcrete};
  ScenarioTemplate scenario;
};

Derived derive(const MutationSizes& sizes = {}) {
  Derived derived;
  const avunit::ParseResult parse = avunit::parse(derived.file);
  EXPECT_TRUE(parse.ok());
  EXPECT_TRUE(searched_by_mutation(parse.scenario));
  derived.scenario = derive_mutation_space(parse.scenario, sizes);
  return derived;
}

const Parameter* find(const ScenarioTemplate& scenario, const std::string& name) {
  for (const Parameter& parameter : scenario.parameters)
    if (parameter.name == name) return &parameter;
  return nullptr;
}

TEST(MutationSpace, EveryMutableNumberBecomesAParameterAroundItsValue) {
  const Derived derived = derive();
  std::vector<std::string> names;
  for (const Parameter& parameter : derived.scenario.parameters) names.push_back(parameter.name);
  // The shared `speed` literal is one parameter, named where it is first used; the ego's target,
  // the cutter's destination and the spec's numbers stay as written.
  const std::vector<std::string> expected = {"ego.init.position.s",
                                             "ego.init.speed",
                                             "cutter.init.position.s",
                                             "cutter.waypoint[0].position.x",
                                             "cutter.waypoint[0].position.y",
                                             "cutter.waypoint[0].heading",
                                             "cutter.waypoint[0].speed",
                                             "cutter.waypoint[1].position.x",
                                             "cutter.waypoint[1].position.y",
                                             "cutter.waypoint[1].speed",
                                             "cutter.waypoint[2].position.x",
                                             "cutter.waypoint[2].position.y",
                                             "cutter.waypoint[2].speed",
                                             "environment.time",
                                             "environment.rain",
                                             "environment.wetness"};
  EXPECT_EQ(names, expected);
  const Parameter* ego_s = find(derived.scenario, "ego.init.position.s");
  ASSERT_NE(ego_s, nullptr);
  EXPECT_EQ(ego_s->origin, 50);
  EXPECT_EQ(ego_s->lower, 45);
  EXPECT_EQ(ego_s->upper, 55);
  EXPECT_EQ(ego_s->unit, "m");
  EXPECT_EQ(derived.file.text().substr(ego_s->location.offset, ego_s->location.length), "50");
  const Parameter* heading = find(derived.scenario, "cutter.waypoint[0].heading");
  ASSERT_NE(heading, nullptr);
  EXPECT_EQ(heading->kind, ParameterKind::angle);
  EXPECT_EQ(heading->lower, -5);
  EXPECT_EQ(heading->upper, 25);
}

TEST(MutationSpace, BoundsClipToWhatTheKindAllows) {
  const Derived derived = derive();
  // A lane arc length, a speed and an intensity near their lower or upper limits.
  EXPECT_EQ(find(derived.scenario, "cutter.init.position.s")->lower, 0);
  EXPECT_EQ(find(derived.scenario, "cutter.waypoint[2].speed")->lower, 0);
  EXPECT_EQ(find(derived.scenario, "environment.rain")->upper, 1);
  EXPECT_EQ(find(derived.scenario, "environment.wetness")->lower, 0);
  const Parameter* time = find(derived.scenario, "environment.time");
  EXPECT_EQ(time->unit, "time of day");
  EXPECT_EQ(time->lower, 19.5 * 3600);
  EXPECT_EQ(time->upper, 24 * 3600 - 1);
}

TEST(MutationSpace, DenselyDrawnWaypointsMoveAQuarterOfTheirSpacing) {
  const Derived derived = derive();
  // cut_a and cut_b are 4 m apart: each moves at most 1 m; cut_c, 36 m from cut_b, moves the
  // waypoint size (2 m).
  const Parameter* a = find(derived.scenario, "cutter.waypoint[0].position.x");
  EXPECT_DOUBLE_EQ(a->upper - a->lower, 2);
  const Parameter* b = find(derived.scenario, "cutter.waypoint[1].position.y");
  EXPECT_DOUBLE_EQ(b->upper - b->lower, 2);
  const Parameter* c = find(derived.scenario, "cutter.waypoint[2].position.x");
  EXPECT_DOUBLE_EQ(c->upper - c->lower, 4);
}

TEST(MutationSpace, SizeZeroKeepsAKindAsWritten) {
  MutationSizes sizes;
  ASSERT_FALSE(apply_mutation_option("speed=0", sizes));
  ASSERT_FALSE(apply_mutation_option("weather=0", sizes));
  ASSERT_FALSE(apply_mutation_option("position=1.5", sizes));
  const Derived derived = derive(sizes);
  for (const Parameter& parameter : derived.scenario.parameters) {
    EXPECT_NE(parameter.unit, "m/s") << parameter.name;
    EXPECT_EQ(parameter.name.find("rain"), std::string::npos);
  }
  EXPECT_EQ(find(derived.scenario, "ego.init.position.s")->upper, 51.5);
}

TEST(MutationSpace, BadMutateOptionsAreNamed) {
  MutationSizes sizes;
  EXPECT_NE(apply_mutation_option("speed", sizes), std::nullopt);
  EXPECT_NE(apply_mutation_option("colour=3", sizes), std::nullopt);
  EXPECT_NE(apply_mutation_option("speed=-1", sizes), std::nullopt);
  EXPECT_NE(apply_mutation_option("speed=nan", sizes), std::nullopt);
  EXPECT_NE(apply_mutation_option("speed=3x", sizes), std::nullopt);
  const std::optional<std::string> message = apply_mutation_option("colour=3", sizes);
  ASSERT_TRUE(message);
  EXPECT_NE(message->find("--mutate"), std::string::npos);
  EXPECT_NE(message->find("waypoint"), std::string::npos);
  EXPECT_EQ(mutation_sizes_text(MutationSizes{}),
            "position=5 waypoint=2 lateral=0.5 heading=15 speed=3 weather=0.3 time=3");
}

TEST(MutationSpace, TheConcreteTextIsTheUsersFileWithTheMutatedNumbers) {
  const Derived derived = derive();
  std::vector<double> values;
  for (const Parameter& parameter : derived.scenario.parameters) values.push_back(parameter.upper);
  const std::string text = avunit::print_concrete(derived.file, derived.scenario, values);
  EXPECT_NE(text.find("speed = 15;"), std::string::npos) << text;
  EXPECT_NE(text.find("(\"east_0\"->55, , speed)"), std::string::npos) << text;
  EXPECT_NE(text.find("rain: 1,"), std::string::npos) << text;
  EXPECT_NE(text.find("Environment(23:59:59, weather)"), std::string::npos) << text;
  EXPECT_NE(text.find("((301, 2.5), 25 deg, 12.5)"), std::string::npos) << text;
  // The printed file parses, is concrete, and has the values chosen.
  const avunit::ParseResult reparsed = avunit::parse(SourceFile("finding.avu", text));
  ASSERT_TRUE(reparsed.ok());
  EXPECT_TRUE(reparsed.scenario.parameters.empty());
  const ScenarioTemplate again = derive_mutation_space(reparsed.scenario, MutationSizes{});
  ASSERT_EQ(again.parameters.size(), derived.scenario.parameters.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_DOUBLE_EQ(*again.parameters[i].origin, values[i]) << again.parameters[i].name;
}

TEST(MutationSpace, AScenarioWithRangesIsNotMutated) {
  const SourceFile file("logical.avu",
                        std::string(kConcrete).replace(0, std::string("speed = 12;").size(),
                                                       "speed = range(10, 14);"));
  const avunit::ParseResult parse = avunit::parse(file);
  ASSERT_TRUE(parse.ok());
  EXPECT_FALSE(searched_by_mutation(parse.scenario));
}

// A CH-Scenario event that fires with a probability is a choice of the search's own
// (Parameter::event_outcome): the file is still concrete, its numbers mutated, the choice kept.
TEST(MutationSpace, EventOutcomesStayFirstAndTheRestIsMutated) {
  const avunit::ParseResult parse = avunit::parse(SourceFile("concrete.avu", kConcrete));
  ASSERT_TRUE(parse.ok());
  ScenarioTemplate scenario = parse.scenario;
  Parameter outcome;
  outcome.name = "constraint1.event";
  outcome.kind = ParameterKind::discrete;
  outcome.upper = 1;
  outcome.choices = {"does not fire", "fires"};
  outcome.event_outcome = true;
  scenario.parameters.push_back(outcome);
  ASSERT_TRUE(searched_by_mutation(scenario));
  const ScenarioTemplate derived = derive_mutation_space(scenario, MutationSizes{});
  ASSERT_EQ(derived.parameters.size(), 17u);
  EXPECT_EQ(derived.parameters[0], outcome);
  EXPECT_EQ(derived.parameters[1].name, "ego.init.position.s");
  // Any other parameter of its own makes the file a parameter space, searched as written.
  scenario.parameters.back().event_outcome = false;
  EXPECT_FALSE(searched_by_mutation(scenario));
}

}  // namespace
}  // namespace scenfuzz
