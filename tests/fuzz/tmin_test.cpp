// `scenfuzz tmin`: the reduction on fake predicates (which actors go, in which order, rounding,
// the duration cut), and end to end on a scenario whose ego is rammed by one NPC while three
// planted NPCs drive far away: tmin removes them, and its output replays to the same failure.
#include "fuzz/tmin.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "fuzz/significant_digits.hpp"
#include "fuzz/tmin_specs.hpp"
#include "lang/avunit/avunit.hpp"

namespace scenfuzz {
namespace {

using test::Outcome;

Actor actor(ActorKind kind, const std::string& name) {
  Actor result;
  result.kind = kind;
  result.name = name;
  return result;
}

std::set<std::string> actor_names(const ScenarioTemplate& scenario) {
  std::set<std::string> names;
  for (const Actor& a : scenario.vehicles) names.insert(a.name);
  for (const Actor& a : scenario.pedestrians) names.insert(a.name);
  return names;
}

// An ego, eight vehicles and two pedestrians.
TminCandidate crowded() {
  TminCandidate candidate;
  candidate.scenario.has_scenario = true;
  candidate.scenario.ego = actor(ActorKind::ego, "ego");
  for (int i = 1; i <= 8; ++i)
    candidate.scenario.vehicles.push_back(actor(ActorKind::vehicle, "car" + std::to_string(i)));
  candidate.scenario.pedestrians = {actor(ActorKind::pedestrian, "walker1"),
                                    actor(ActorKind::pedestrian, "walker2")};
  return candidate;
}

TminCheck failing(double failure_time = NAN, double end_time = NAN) {
  return TminCheck{true, failure_time, end_time};
}

TEST(TminReduceList, RemovesHalvesFirstThenSingleItems) {
  std::vector<std::vector<bool>> asked;
  // Items 2 and 5 matter.
  const std::vector<bool> kept = reduce_list(8, [&](const std::vector<bool>& trial) {
    asked.push_back(trial);
    return trial[2] && trial[5];
  });
  EXPECT_EQ(kept, (std::vector<bool>{false, false, true, false, false, true, false, false}));
  ASSERT_FALSE(asked.empty());
  // The first candidate lacks the first half.
  EXPECT_EQ(std::count(asked[0].begin(), asked[0].end(), false), 4);
  EXPECT_FALSE(asked[0][0] || asked[0][3]);
  // Never asked without a removal.
  for (const std::vector<bool>& trial : asked)
    EXPECT_NE(std::count(trial.begin(), trial.end(), false), 0);
}

TEST(TminReduceList, AllIrrelevantGoInTwoChecks) {
  int checks = 0;
  const std::vector<bool> kept = reduce_list(8, [&](const std::vector<bool>&) {
    ++checks;
    return true;
  });
  EXPECT_EQ(std::count(kept.begin(), kept.end(), true), 0);
  EXPECT_EQ(checks, 2);
}

TEST(TminReduceList, NothingToReduceAsksNothing) {
  int checks = 0;
  reduce_list(0, [&](const std::vector<bool>&) { return ++checks > 0; });
  EXPECT_EQ(checks, 0);
}

TEST(TminReduce, RemovesExactlyTheIrrelevantActorsAndNeverTheEgo) {
  std::vector<std::size_t> sizes;
  const TminPredicate fails = [&](const TminCandidate& candidate) {
    const std::set<std::string> names = actor_names(candidate.scenario);
    sizes.push_back(names.size());
    EXPECT_EQ(candidate.scenario.ego.name, "ego");
    TminCheck check;
    check.same_failure = names.count("car6") && names.count("walker2");
    return check;
  };
  const TminReduction reduction = reduce_failing_scenario(crowded(), failing(), fails);
  EXPECT_EQ(actor_names(reduction.result.scenario), (std::set<std::string>{"car6", "walker2"}));
  EXPECT_EQ(reduction.actors_removed, 8u);
  EXPECT_EQ(reduction.result.scenario.ego.name, "ego");
  // The first candidate is the first half removed: 10 actors, 5 of them.
  ASSERT_FALSE(sizes.empty());
  EXPECT_EQ(sizes[0], 5u);
  EXPECT_NE(std::find(reduction.changes.begin(), reduction.changes.end(), "removed vehicle car1"),
            reduction.changes.end());
  EXPECT_NE(
      std::find(reduction.changes.begin(), reduction.changes.end(), "removed pedestrian walker1"),
      reduction.changes.end());
  EXPECT_EQ(reduction.changes.size(), 8u);
  EXPECT_EQ(reduction.checks, sizes.size());
}

TEST(TminReduce, KeepsEverythingWhenEveryActorMatters) {
  const TminPredicate fails = [](const TminCandidate& candidate) {
    TminCheck check;
    check.same_failure = actor_names(candidate.scenario).size() == 10;
    return check;
  };
  const TminReduction reduction = reduce_failing_scenario(crowded(), failing(), fails);
  EXPECT_EQ(actor_names(reduction.result.scenario).size(), 10u);
  EXPECT_TRUE(reduction.changes.empty());
}

TEST(SignificantDigits, CountsTheShortestText) {
  EXPECT_EQ(significant_digits(480), 2);
  EXPECT_EQ(significant_digits(0.125), 3);
  EXPECT_EQ(significant_digits(-12.345678), 8);
  EXPECT_EQ(significant_digits(0), 0);
  EXPECT_EQ(significant_digits(0.1), 1);
}

TEST(SignificantDigits, RoundsToTheNearestShorterDecimal) {
  EXPECT_EQ(round_to_significant(12.345678, 3), 12.3);
  EXPECT_EQ(round_to_significant(12.345678, 1), 10);
  EXPECT_EQ(round_to_significant(-0.0456, 2), -0.046);
  EXPECT_EQ(round_to_significant(96.0, 1), 100);
  EXPECT_EQ(round_to_significant(0.5, 4), 0.5);
}

// One vehicle whose speed matters to within 0.05 m/s, and an irrelevant start position.
TminCandidate one_rammer() {
  TminCandidate candidate;
  candidate.scenario.has_scenario = true;
  candidate.scenario.ego = actor(ActorKind::ego, "ego");
  Actor rammer = actor(ActorKind::vehicle, "rammer");
  rammer.initial.position.kind = PositionKind::lane;
  rammer.initial.position.lane = "east_0";
  rammer.initial.position.s = constant_value(10.987654);
  rammer.initial.speed = constant_value(12.345678);
  candidate.scenario.vehicles.push_back(rammer);
  return candidate;
}

TEST(TminReduce, RoundsEachNumberToAsFewDigitsAsKeepTheFailure) {
  const TminPredicate fails = [](const TminCandidate& candidate) {
    TminCheck check;
    if (candidate.scenario.vehicles.empty()) return check;
    const Actor& rammer = candidate.scenario.vehicles[0];
    check.same_failure = std::abs(rammer.initial.speed->constant - 12.345678) < 0.05;
    return check;
  };
  const TminReduction reduction = reduce_failing_scenario(one_rammer(), failing(), fails);
  const Actor& rammer = reduction.result.scenario.vehicles.at(0);
  EXPECT_EQ(rammer.initial.speed->constant, 12.3);
  EXPECT_EQ(rammer.initial.position.s.constant, 10);
  EXPECT_EQ(reduction.numbers_rounded, 2u);
  EXPECT_EQ(reduction.digits_before, 16u);
  EXPECT_EQ(reduction.digits_after, 4u);
}

TEST(TminReduce, NeutralWeatherNoonAndAShorterRun) {
  TminCandidate start = one_rammer();
  Environment environment;
  environment.time_of_day = constant_value(21.5 * 3600);
  environment.weather = {WeatherComponent{"rain", constant_value(0.7), {}, {}},
                         WeatherComponent{"fog", constant_value(0.25), {}, {}}};
  start.scenario.environment = environment;
  std::vector<std::optional<double>> durations;
  // Fog matters; the failure happens at 4.2 s of a 30 s run.
  const TminPredicate fails = [&](const TminCandidate& candidate) {
    durations.push_back(candidate.duration);
    const std::vector<WeatherComponent>& weather = candidate.scenario.environment->weather;
    const bool fog = std::any_of(weather.begin(), weather.end(),
                                 [](const WeatherComponent& c) { return c.kind == "fog"; });
    return TminCheck{fog, 4.2, candidate.duration.value_or(30)};
  };
  const TminReduction reduction = reduce_failing_scenario(start, failing(4.2, 30), fails);
  const Environment& result = *reduction.result.scenario.environment;
  ASSERT_EQ(result.weather.size(), 1u);
  EXPECT_EQ(result.weather[0].kind, "fog");
  EXPECT_EQ(result.time_of_day->constant, kNoonSeconds);
  EXPECT_EQ(reduction.result.duration, 6.0);  // ceil(4.2 + 1)
  const std::vector<std::string>& changes = reduction.changes;
  EXPECT_NE(std::find(changes.begin(), changes.end(), "removed weather rain 0.7"), changes.end());
  EXPECT_NE(std::find(changes.begin(), changes.end(), "time of day 21:30 -> 12:00"), changes.end());
  EXPECT_EQ(changes.back(), "duration cut to 6 s (the run went on to 30 s)");
}

// The ego waits in east_0 and a scripted car (rammer) drives into it from behind; three cars far
// ahead in east_1 and a box by the road have nothing to do with the collision.
// The rammer runs into the ego from behind: not the ego's fault, so it is judged as a finding
// made with --all-collisions is, through its replay line (tmin reads the options there).
constexpr const char* kPlanted = R"(// replay: scenfuzz run planted.avu --all-collisions
ego = AV(("east_0"->60.123456, , 0), ("east_0"->480));
rammer = Vehicle(("east_0"->10.987654, , RAMMER_SPEED),
                 Waypoint(("east_0"->200.4321, , 12.345678), ("east_0"->300.5, , 11.75)),
                 ("east_0"->400));
far1 = Vehicle(("east_1"->300.25, , 5.5), Waypoint(("east_1"->350.75, , 5.5)), ("east_1"->450));
far2 = Vehicle(("east_1"->250.125, , 6.25), Waypoint(("east_1"->320.5, , 6.25)), ("east_1"->440));
far3 = Vehicle(("east_1"->200.0625, , 7.125), Waypoint(("east_1"->300.5, , 7.125)),
               ("east_1"->430));
box = Obstacle("east_1"->470.5, (box, 1.25, 1.0, 0.8));
env = Environment(21:30, {rain: 0.7, fog: 0.25});
scenario = CreateScenario{load("straight"); ego; {rammer, far1, far2, far3}; {}; {box}; env;
                          {NPCBehaviour(scripted)};};
Trace trace = EXE(scenario);
no_rammer_collision = G (dis(trace[ego], trace[truth][rammer]) > 0.5);
trace |= no_rammer_collision;
)";

std::string planted(const std::string& rammer_speed) {
  std::string text = kPlanted;
  text.replace(text.find("RAMMER_SPEED"), 12, rammer_speed);
  return text;
}

// "failure mode: ..." of a file's header or of tmin's output.
std::string mode_line(const std::string& text) {
  const std::size_t at = text.find("failure mode: ");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

class TminCommandTest : public test::CommandTest {
 protected:
  // tmin on `input`, then `run` on its output with the replay's seed: both outcomes.
  void minimise_and_replay(const std::string& input, const std::string& out_path, Outcome& tmin,
                           Outcome& replay) {
    tmin = scenfuzz({"tmin", input, "-o", out_path});
    ASSERT_EQ(tmin.exit_code, 0) << tmin.err;
    const std::string replay_mark = "replay: scenfuzz run " + out_path + " --seed ";
    const std::size_t at = tmin.out.find(replay_mark);
    ASSERT_NE(at, std::string::npos) << tmin.out;
    const std::string seed = tmin.out.substr(
        at + replay_mark.size(),
        tmin.out.find_first_of(" \n", at + replay_mark.size()) - at - replay_mark.size());
    replay = scenfuzz(
        {"run", out_path, "--seed", seed, "--out", (dir_ / "replay").string(), "--all-collisions"});
  }
};

TEST_F(TminCommandTest, RemovesThePlantedActorsAndKeepsTheFailure) {
  const std::string input = write("planted.avu", planted("12.345678"));
  const Outcome before =
      scenfuzz({"run", input, "--out", (dir_ / "before").string(), "--all-collisions"});
  ASSERT_EQ(before.exit_code, 1) << before.out << before.err;
  const std::string out_path = (dir_ / "planted.min.avu").string();
  Outcome tmin, replay;
  minimise_and_replay(input, out_path, tmin, replay);
  for (const char* planted_actor : {"far1", "far2", "far3"})
    EXPECT_NE(tmin.out.find(std::string("removed vehicle ") + planted_actor + "\n"),
              std::string::npos)
        << tmin.out;
  EXPECT_NE(tmin.out.find("removed obstacle box\n"), std::string::npos) << tmin.out;
  EXPECT_NE(tmin.out.find("actors 4 -> 1,"), std::string::npos) << tmin.out;
  const std::string minimised = test::slurp(out_path);
  // The header lists what went; the scenario after it has none of it.
  const std::string body = minimised.substr(minimised.find("// AVUnit printed by scenfuzz"));
  for (const char* gone : {"far1", "far2", "far3", "box", "rain", "fog"})
    EXPECT_EQ(body.find(gone), std::string::npos) << gone << "\n" << minimised;
  EXPECT_NE(minimised.find("rammer"), std::string::npos);
  EXPECT_NE(minimised.find("Environment(12:00)"), std::string::npos) << minimised;
  // The same failure: the mode tmin kept is the one the header records, the output replays
  // violating the spec by a collision with the rammer.
  EXPECT_EQ(mode_line(minimised), mode_line(tmin.out));
  EXPECT_NE(mode_line(tmin.out).find("| collision | rammer | other"), std::string::npos)
      << tmin.out;
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("ego rear / rammer front"), std::string::npos) << replay.out;
  EXPECT_NE(replay.out.find("spec no_rammer_collision: robustness -"), std::string::npos);
  // Minimising the output again changes nothing: it is minimal already, and tmin reads its own
  // header back (the mode and the replay command).
  const Outcome again =
      scenfuzz({"tmin", out_path, "-o", (dir_ / "again.avu").string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("nothing could be removed or changed"), std::string::npos) << again.out;
}

// LawBreaker's style: one spec names every NPC (`G(dis1 >= 0.5 & dis2 >= 0.5 & ...)`). The NPCs
// the failure does not involve still go, and the conjuncts that read them with them.
TEST_F(TminCommandTest, ActorsASpecNamesGoWithTheirAtoms) {
  std::string text = planted("12.345678");
  const std::string spec = "G (dis(trace[ego], trace[truth][rammer]) > 0.5)";
  text.replace(text.find(spec), spec.size(),
               "G (dis(trace[ego], trace[truth][rammer]) > 0.5 & "
               "dis(trace[ego], trace[truth][far1]) > 0.5 & "
               "dis(trace[ego], trace[truth][far2]) > 0.5 & "
               "dis(trace[ego], trace[truth][far3]) > 0.5)");
  const std::string input = write("named.avu", text);
  const std::string out_path = (dir_ / "named.min.avu").string();
  Outcome tmin, replay;
  minimise_and_replay(input, out_path, tmin, replay);
  EXPECT_NE(tmin.out.find("actors 4 -> 1,"), std::string::npos) << tmin.out;
  const std::string minimised = test::slurp(out_path);
  const std::string body = minimised.substr(minimised.find("// AVUnit printed by scenfuzz"));
  for (const char* gone : {"far1", "far2", "far3"})
    EXPECT_EQ(body.find(gone), std::string::npos) << gone << "\n" << minimised;
  EXPECT_NE(body.find("dis(trace[ego], trace[truth][rammer]) > 0.5"), std::string::npos) << body;
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("ego rear / rammer front"), std::string::npos) << replay.out;
}

TEST(TminSpecs, AtomsThatReadARemovedActorGoAndWhatCannotStandWithoutThem) {
  const avunit::ParseResult parse = avunit::parse(SourceFile(
      "specs.avu",
      std::string(kPlanted).replace(std::string(kPlanted).find("RAMMER_SPEED"), 12, "5") +
          "both = G (dis(trace[ego], trace[truth][rammer]) > 0.5 & "
          "dis(trace[ego], trace[truth][far1]) > 0.5);\n"
          "either = F (dis(trace[ego], trace[truth][far1]) < 3 | "
          "dis(trace[ego], trace[truth][far2]) < 3);\n"
          "implied = G (dis(trace[ego], trace[truth][far1]) < 5 -> "
          "dis(trace[ego], trace[truth][rammer]) > 1);\n"
          "trace |= both;\ntrace |= either;\ntrace |= implied;\n"));
  ASSERT_TRUE(parse.ok());
  const std::vector<Spec> kept = specs_without_actors(parse.scenario.specs, {"far1"});
  std::vector<std::string> names;
  for (const Spec& spec : kept) names.push_back(spec.name);
  // `implied` cannot stand without its condition; `either` keeps its far2 side; `both` its rammer
  // side.
  EXPECT_EQ(names, (std::vector<std::string>{"no_rammer_collision", "both", "either"}));
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1].formula.operands.at(0).kind, FormulaKind::comparison);
  EXPECT_EQ(kept[2].formula.operands.at(0).kind, FormulaKind::comparison);
  EXPECT_EQ(specs_without_actors(parse.scenario.specs, {"far1", "far2", "rammer"}).size(), 0u);
  EXPECT_EQ(specs_without_actors(parse.scenario.specs, {}), parse.scenario.specs);
}

TEST_F(TminCommandTest, MinimisesAFindingOfTheSearchWithItsSeed) {
  const std::string input = write("logical.avu", planted("range(11, 14)"));
  const std::string search_dir = (dir_ / "search").string();
  const Outcome search = scenfuzz(
      {"--budget", "4", "--seed", "3", "--out", search_dir, input, "--quiet", "--all-collisions"});
  ASSERT_EQ(search.exit_code, 1) << search.out << search.err;
  std::string finding;
  for (const auto& entry : std::filesystem::directory_iterator(dir_ / "search" / "findings"))
    if (entry.path().extension() == ".avu") finding = entry.path().string();
  ASSERT_FALSE(finding.empty());
  const Outcome tmin = scenfuzz({"tmin", finding});
  ASSERT_EQ(tmin.exit_code, 0) << tmin.err;
  // Beside the finding by default.
  const std::filesystem::path out_path =
      std::filesystem::path(finding).parent_path() /
      (std::filesystem::path(finding).stem().string() + ".min.avu");
  ASSERT_TRUE(std::filesystem::exists(out_path)) << tmin.out;
  EXPECT_EQ(mode_line(test::slurp(finding)), mode_line(tmin.out));
  EXPECT_NE(tmin.out.find("actors 4 -> 1,"), std::string::npos) << tmin.out;
  // Deterministic: the same input gives the same file.
  const std::string first = test::slurp(out_path);
  ASSERT_EQ(scenfuzz({"tmin", finding}).exit_code, 0);
  EXPECT_EQ(test::slurp(out_path), first);
}

// Canonical AVUnit writes named terms out in full ("d" becomes the distance it names), and the
// mode's atom here is a disjunction, " | " inside it: the mode is kept but for the atom's
// spelling, and the output replays to the mode it records.
TEST_F(TminCommandTest, ANamedAtomIsWrittenOutAndTheRestOfTheModeKept) {
  std::string named = planted("12.345678");
  const std::string spec = "G (dis(trace[ego], trace[truth][rammer]) > 0.5)";
  named.replace(named.find(spec), spec.size(), "G ((d > 0.5) | (d > 1000))");
  named.replace(named.find("no_rammer_collision = G"), 0,
                "d = dis(trace[ego], trace[truth][rammer]);\n");
  const std::string input = write("named.avu", named);
  const std::string out_path = (dir_ / "named.min.avu").string();
  Outcome tmin, replay;
  minimise_and_replay(input, out_path, tmin, replay);
  EXPECT_NE(tmin.out.find("actors 4 -> 1,"), std::string::npos) << tmin.out;
  EXPECT_EQ(mode_line(test::slurp(out_path)), mode_line(tmin.out));
  EXPECT_TRUE(mode_line(tmin.out).starts_with(
      "failure mode: no_rammer_collision: dis(trace[ego], trace[truth][rammer]) > 0.5 | "))
      << tmin.out;
  EXPECT_NE(mode_line(tmin.out).find(" | collision | rammer | other | in lane"), std::string::npos)
      << tmin.out;
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("ego rear / rammer front"), std::string::npos) << replay.out;
}

TEST_F(TminCommandTest, BadInputIsExitTwoWithAClearMessage) {
  const Outcome missing = scenfuzz({"tmin", (dir_ / "missing.avu").string()});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos) << missing.err;

  const Outcome logical = scenfuzz({"tmin", write("logical.avu", planted("range(11, 14)"))});
  EXPECT_EQ(logical.exit_code, 2);
  EXPECT_NE(logical.err.find("is a logical scenario with 1 parameters"), std::string::npos)
      << logical.err;

  // A distance is never below -1: nothing fails.
  std::string never_violated = planted("12.345678");
  never_violated.replace(never_violated.find("> 0.5"), 5, "> -1");
  const Outcome passing = scenfuzz({"tmin", write("passing.avu", never_violated)});
  EXPECT_EQ(passing.exit_code, 2) << passing.out;
  EXPECT_NE(passing.err.find("does not fail when replayed with seed 0"), std::string::npos)
      << passing.err;

  // A header whose mode the scenario no longer shows.
  const Outcome stale = scenfuzz(
      {"tmin", write("stale.avu", "// failure mode: something else\n" + planted("12.345678"))});
  EXPECT_EQ(stale.exit_code, 2);
  EXPECT_NE(stale.err.find("no longer fails as its header says"), std::string::npos) << stale.err;

  // A logical WMG SDL file, as a logical AVUnit one (WMG SDL findings: tmin_wmg_test.cpp).
  const Outcome wmg = scenfuzz({"tmin", test::source_file("corpora/wmg/cut_in.sdl")});
  EXPECT_EQ(wmg.exit_code, 2);
  EXPECT_NE(wmg.err.find("cut_in.sdl' is a logical scenario with"), std::string::npos) << wmg.err;

  std::string unknown_map = planted("12.345678");
  unknown_map.replace(unknown_map.find("\"straight\""), 10, "\"no_such_map\"");
  const Outcome no_map = scenfuzz({"tmin", write("no_map.avu", unknown_map)});
  EXPECT_EQ(no_map.exit_code, 2);
  EXPECT_NE(no_map.err.find("cannot be replayed and judged: map 'no_such_map' not found"),
            std::string::npos)
      << no_map.err;

  const Outcome garbage = scenfuzz({"tmin", write("garbage.avu", "this is not AVUnit\n")});
  EXPECT_EQ(garbage.exit_code, 2);
  EXPECT_NE(garbage.err.find("garbage.avu:1:"), std::string::npos) << garbage.err;
}

}  // namespace
}  // namespace scenfuzz
